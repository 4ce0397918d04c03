"""A value computed once for a whole test run, however many xdist workers ask: the first
worker to ask computes it and leaves it, pickled, in the run's common temporary folder (under
a file lock, as tests/helpers/evaluated.py shares the committed verdicts); the others wait on
the lock, then read it. For what is plain data (ids, statuses), not objects a worker must
build itself (a reference holding local functions does not pickle)."""

from __future__ import annotations

import fcntl
import os
import pickle
from collections.abc import Callable
from typing import TypeVar

import pytest

from helpers.regenerated import shared_root

T = TypeVar("T")


def once_per_run(factory: pytest.TempPathFactory, name: str, compute: Callable[[], T]) -> T:
    """``compute()``, or what a worker of this run computed under ``name``."""
    root = shared_root(factory, os.environ.get("PYTEST_XDIST_WORKER", "master"))
    path = root / f"{name}.pickle"
    with open(root / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if path.exists():
            kept: T = pickle.loads(path.read_bytes())
            return kept
        value = compute()
        written = root / f"{name}.tmp"
        written.write_bytes(pickle.dumps(value))
        os.replace(written, path)
        return value
