"""Derived formulas of the papers checked against direct numerical solutions.

One module per paper (``pendcli.papers.<paper>``), each exposing
``formula_checks() -> list[FormulaRow]``; :func:`formula_checks` collects them.
"""

from __future__ import annotations

import importlib
import importlib.util

from pendcli.core.claims import FormulaRow


def formula_checks(key: str) -> list[FormulaRow]:
    """The formula checks of one paper (empty if it has none yet)."""
    name = f"pendcli.papers.{key}.formulas"
    if importlib.util.find_spec(name) is None:
        return []
    return list(importlib.import_module(name).formula_checks())
