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


C = TypeVar("C")
S = TypeVar("S")


def judged_once(
    factory: pytest.TempPathFactory,
    name: str,
    cases: dict[str, list[C]],
    judge: Callable[[C], S],
    label: Callable[[C], str],
) -> dict[str, list[tuple[C, S]]]:
    """Each case of ``cases`` (made by every worker alike) with ``judge(case)``, judged once
    for the run: a worker reading the verdicts pairs them with its own cases by ``label``."""
    verdicts = once_per_run(
        factory,
        name,
        lambda: {k: [(label(c), judge(c)) for c in made] for k, made in cases.items()},
    )
    paired = {k: list(zip(made, verdicts[k], strict=True)) for k, made in cases.items()}
    assert all(label(c) == kept for pairs in paired.values() for c, (kept, _) in pairs)
    return {k: [(c, verdict) for c, (_, verdict) in pairs] for k, pairs in paired.items()}
