"""The committed papers' claims and formula checks, each computed once per test process: many
files read the same verdicts (Lecornu's claims alone cost 0.6 s a computation, his formula
checks 2.5 s), and a test that only reads them need not pay again. A test of the computation
itself (determinism, an edited table, an assumption changed) calls the registry directly.
The rows are frozen dataclasses, served as tuples: no test can change what another reads."""

from __future__ import annotations

import os
from functools import cache

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


@cache
def _claims(key: str) -> tuple[ClaimRow, ...]:
    return tuple(claim_rows(key))


@cache
def _formulas(key: str) -> tuple[FormulaRow, ...]:
    return tuple(formula_checks(key))
