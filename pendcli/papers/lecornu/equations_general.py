"""Lecornu, II: the general integral (17)-(22). What remains here is the sympy helper the
checks of § IV (:mod:`pendcli.papers.lecornu.equations_conical`) import.

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

from typing import Any


def substitute_all(expr: Any, rules: dict[Any, Any]) -> Any:
    """``expr`` with each rule old -> new applied in turn (sympy subs)."""
    for old, new in rules.items():
        expr = expr.subs(old, new)
    return expr
