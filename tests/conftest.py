"""Shared test settings: a pinned console width so rendered tables are stable."""

import os

os.environ.setdefault("COLUMNS", "160")
os.environ["NO_COLOR"] = "1"

# No wall-clock limit in any test (issue 23): every hypothesis test, in any file, runs without a
# deadline; its work is bounded by example counts, so a loaded machine is slower, never red.
from hypothesis import settings

settings.register_profile("pendcli", deadline=None)
settings.load_profile("pendcli")

