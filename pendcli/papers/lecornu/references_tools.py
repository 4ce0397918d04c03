"""Lecornu: what the reference builders of lines 420-1135 share (references_asymptotic,
references_finite, references_perturbed, references_conical, references_conical_planes):
the ledger's symbols as sympy symbols, a Reference, the chain rule along given rates, and a
reference another module keeps, looked up in the paper's table.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from pendcli.data.printed import ledger_symbols as real_symbols
from pendcli.verify.printed_check import Reference

__all__ = ["cited", "derivative_along", "make_reference", "real_symbols"]


def make_reference(exact: dict[str, Any], what: str, **kw: Any) -> Any:
    """A :class:`~pendcli.verify.printed_check.Reference` (its options passed through)."""
    return Reference(exact, what=what, **kw)


def derivative_along(rates: dict[Any, Any]) -> Any:
    """The derivative along a motion: f -> Σ ∂f/∂s · rate(s), over the symbols of ``rates``."""

    def derivative(f: Any) -> Any:
        return sp.Add(*(sp.diff(f, s) * v for s, v in rates.items()))

    return derivative


def cited(name: str) -> Any:
    """The reference ``name`` of Lecornu's table (built when asked: a builder of another
    module, found by the name the ledger cites rather than by its file)."""
    from pendcli.papers.lecornu import PAPER

    assert PAPER.references is not None
    return PAPER.references()[name]()
