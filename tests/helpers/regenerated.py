"""Every table's computation (what `pendcli check` regenerates: ``reproduce_all`` of every
paper with its formulas and ledger), done once per test run and shared by the tests that need
its result but test something else: the writer of `check --update` under a kill, a signal, a
full disk or a read-only folder, and the comparison of damaged committed cells. xdist workers
share one computation through a file lock in the run's common temporary folder.

:data:`SERVED_CLI` runs `pendcli ARGS` in a fresh process as ``python -m pendcli`` does, with
``reproduce_all`` answering from that file: the process, its signal handlers, its lock and its
writer are the real ones; only the computation before them is skipped. The tests of the
computation itself (tests/run/test_determinism.py, tests/run/test_regression.py) compute it.
"""

from __future__ import annotations

import fcntl
import os
import pickle
import sys
from pathlib import Path

import pytest

from pendcli.data.tables import clear_table_cache

SERVED_CLI = (sys.executable, str(Path(__file__).with_name("served_cli.py")))
NAME = "reproduce-all.pickle"


def shared_root(factory: pytest.TempPathFactory, worker: str) -> Path:
    """The folder every worker of this run shares (the run's own folder without xdist)."""
    base = factory.getbasetemp()
    return base if worker == "master" else base.parent


def computed_once(root: Path) -> Path:
    """The file holding every table's computation from the committed tables, computed by
    the first worker to ask (the others wait on the lock, then read it)."""
    path = root / NAME
    with open(root / f"{NAME}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not path.exists():
            tmp = path.with_name(f"{NAME}.tmp")
            tmp.write_bytes(pickle.dumps(_compute()))
            os.replace(tmp, path)
    return path


def _compute() -> object:
    from pendcli.papers.registry import keys
    from pendcli.run.reproduce import reproduce_all

    saved = os.environ.pop("PENDCLI_TABLES", None)  # the committed tables, not a test's copy
    clear_table_cache()
    try:
        return reproduce_all(keys(), formulas=True, equations=True, quiet=True, jobs=1)
    finally:
        if saved is not None:
            os.environ["PENDCLI_TABLES"] = saved
        clear_table_cache()


def served(path: Path) -> object:
    """A stand-in for ``reproduce_all`` that answers with the stored computation."""

    def reproduce_all(*args: object, **kwargs: object) -> object:
        return pickle.loads(path.read_bytes())

    return reproduce_all
