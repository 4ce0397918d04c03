"""Where tests/conftest.py records how it split the suite, for
tests/suite/test_suite_split.py: each long family's (fast cases, all cases), and every node id
collected before ``-m`` deselected the slow ones."""

from __future__ import annotations

import pytest

# family pattern -> (cases `make test` runs, cases in all)
FAMILY_SPLIT = pytest.StashKey[dict[str, tuple[int, int]]]()
# the node ids of the session, slow ones included
COLLECTED = pytest.StashKey[list[str]]()
