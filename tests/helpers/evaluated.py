"""The committed papers' claims and formula checks, each computed once per test process: many
files read the same verdicts (Lecornu's claims alone cost 0.6 s a computation, his formula
checks 2.5 s), and a test that only reads them need not pay again. A test of the computation
itself (determinism, an edited table, an assumption changed) calls the registry directly.
The rows are frozen dataclasses, served as tuples: no test can change what another reads.
Under xdist the first worker to ask computes them and leaves them, pickled, in the run's
common temporary folder (:func:`share_across_workers`, set by tests/conftest.py); the other
reads them there, as tests/helpers/regenerated.py shares every table's computation."""

from __future__ import annotations

import fcntl
import os
import pickle
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import TypeVar

from pendcli.data.rows import ClaimRow, FormulaRow
from pendcli.papers.registry import claim_rows, formula_checks


def _committed_tables_only() -> None:
    """Refuse to fill or serve the cache while the tables are a test's copy."""
    if os.environ.get("PENDCLI_TABLES"):
        raise RuntimeError("the shared verdicts are those of the committed tables only")


def committed_claims(key: str) -> tuple[ClaimRow, ...]:
    """``claim_rows(key)`` of the committed tables, computed once per process."""
    _committed_tables_only()
    return _claims(key)


def committed_formulas(key: str) -> tuple[FormulaRow, ...]:
    """``formula_checks(key)`` of the committed tables, computed once per process."""
    _committed_tables_only()
    return _formulas(key)


# the folder every worker of the run shares, once tests/conftest.py has said it
_SHARED: list[Path] = []
T = TypeVar("T")


def share_across_workers(root: Path) -> None:
    """Keep the rows computed here in ``root`` for the run's other workers, and read theirs."""
    _SHARED[:] = [root]


def _once_per_run(name: str, compute: Callable[[], T]) -> T:
    """``compute()``, or what a worker of this run computed and left under ``name``."""
    if not _SHARED:
        return compute()
    path = _SHARED[0] / f"committed-{name}.pickle"
    with open(path.with_name(f"{path.name}.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if path.exists():
            kept: T = pickle.loads(path.read_bytes())
            return kept
        value = compute()
        written = path.with_name(f"{path.name}.tmp")
        written.write_bytes(pickle.dumps(value))
        os.replace(written, path)
        return value


@cache
def _claims(key: str) -> tuple[ClaimRow, ...]:
    return _once_per_run(f"claims-{key}", lambda: tuple(claim_rows(key)))


@cache
def _formulas(key: str) -> tuple[FormulaRow, ...]:
    return _once_per_run(f"formulas-{key}", lambda: tuple(formula_checks(key)))
