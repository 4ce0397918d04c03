"""Shared test settings: a pinned console width so rendered tables are stable."""

import os

os.environ.setdefault("COLUMNS", "160")
os.environ["NO_COLOR"] = "1"
