"""Shared test settings: a pinned console width so rendered tables are stable."""

import os

os.environ.setdefault("COLUMNS", "160")
os.environ["NO_COLOR"] = "1"

# No wall-clock limit in any test (issue 23): every hypothesis test, in any file, runs without a
# deadline; its work is bounded by example counts, so a loaded machine is slower, never red.
from hypothesis import settings

settings.register_profile("pendcli", deadline=None)
settings.load_profile("pendcli")


# The result cache (pendcli/core/cache.py) is off in every test and every process a test
# starts: no test is served a result stored outside it (the user's ~/.cache/pendcli), nor one
# an earlier test stored, which would make a test of determinism, of the forked workers or of
# an interrupt compare a computation with a copy of itself. tests/test_cache.py gives each of
# its tests a folder of its own.
os.environ["PENDCLI_CACHE"] = "off"
