"""Every table's computation (what `pendcli check` regenerates: ``reproduce_all`` of every
paper with its formulas and ledger), done once per test run in a fresh process with one job,
and shared by the tests that need its result but test something else: the writer of `check
--update` under a kill, a signal, a full disk or a read-only folder, the comparison of damaged
committed cells, and the one-job side of the determinism tests. xdist workers share one
computation through a file lock in the run's common temporary folder.

:data:`SERVED_CLI` runs `pendcli ARGS` in a fresh process as ``python -m pendcli`` does, with
``reproduce_all`` answering from that file: the process, its signal handlers, its lock, its
writer and its output are the real ones; only the computation before them is served.
"""

from __future__ import annotations

import fcntl
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from helpers.served_cli import stand_in

SERVED_CLI = (sys.executable, str(Path(__file__).with_name("served_cli.py")))
NAME = "reproduce-all.pickle"
COMPUTE = """
import pickle, sys
from pendcli.papers.registry import keys
from pendcli.run.reproduce import reproduce_all
asked = {"keys": tuple(keys()), "formulas": True, "equations": True, "stability": False}
result = reproduce_all(keys(), formulas=True, equations=True, stability=False, quiet=True, jobs=1)
sys.stdout.buffer.write(pickle.dumps((asked, result)))
"""


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
            env = {k: v for k, v in os.environ.items() if k != "PENDCLI_TABLES"}
            done = subprocess.run(
                [sys.executable, "-c", COMPUTE],
                env={**env, "PENDCLI_JOBS": "1"},
                capture_output=True,
                check=False,
            )
            assert done.returncode == 0, done.stderr.decode()
            tmp = path.with_name(f"{NAME}.tmp")
            tmp.write_bytes(done.stdout)
            os.replace(tmp, path)
    return path


def served(path: Path) -> Callable[..., Any]:
    """A stand-in for ``reproduce_all`` in this process, answering from ``path``."""
    return stand_in(path)
