"""Derived formulas of the papers checked against direct numerical solutions.

One module per paper (``pendcli.papers.<paper>``), each exposing
``formula_checks() -> list[FormulaRow]``; :func:`formula_checks` collects them.
:func:`sharing_formula_rows` lets the equation ledger, which re-reads some of those rows,
take the ones a reproduction has just computed instead of integrating everything again.
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Iterator
from contextlib import contextmanager

from pendcli.core.claims import FormulaRow

# Rows computed by the running reproduction, by paper: set only inside sharing_formula_rows.
_SHARED: dict[str, list[FormulaRow]] = {}


def formula_checks(key: str) -> list[FormulaRow]:
    """The formula checks of one paper (empty if it has none yet): the rows a running
    reproduction shares (:func:`sharing_formula_rows`), else computed now."""
    if key in _SHARED:
        return list(_SHARED[key])
    name = f"pendcli.papers.{key}.formulas"
    if importlib.util.find_spec(name) is None:
        return []
    return list(importlib.import_module(name).formula_checks())


@contextmanager
def sharing_formula_rows(key: str, rows: list[FormulaRow]) -> Iterator[None]:
    """Within the block, :func:`formula_checks` of ``key`` returns ``rows`` (never cached
    beyond it, so a later run with other tables computes afresh)."""
    _SHARED[key] = rows
    try:
        yield
    finally:
        _SHARED.pop(key, None)
