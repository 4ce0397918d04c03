"""Lecornu: what the reference builders of lines 420-1135 share (references_asymptotic,
references_finite, references_perturbed, references_conical, references_conical_planes,
and references_slow's solver): the ledger's symbols as sympy symbols, a Reference, the chain
rule along given rates, a forced oscillator started at rest, and a reference another module
keeps, looked up in the paper's table.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.data.printed import ledger_symbols as real_symbols
from pendcli.verify.printed_check import Reference

__all__ = ["cited", "derivative_along", "make_reference", "real_symbols", "zero_start_forced"]


def make_reference(exact: dict[str, Any], what: str, **kw: Any) -> Any:
    """A :class:`~pendcli.verify.printed_check.Reference` (its options passed through)."""
    return Reference(exact, what=what, **kw)


def derivative_along(rates: dict[Any, Any]) -> Any:
    """The derivative along a motion: f -> Σ ∂f/∂s · rate(s), over the symbols of ``rates``."""

    def derivative(f: Any) -> Any:
        return sp.Add(*(sp.diff(f, s) * v for s, v in rates.items()))

    return derivative


@cache
def zero_start_forced(rhs: Any, tau: Any, degree: int, frequencies: tuple[int, ...] = (1,)) -> Any:
    """The solution of y'' + y = rhs(τ) with y(0) = y'(0) = 0, rhs a sum of polynomials in τ
    times cos mτ and sin mτ (m in ``frequencies``; products of them turned into sums, TR8):
    undetermined coefficients (a polynomial of ``degree`` on each), solved by sympy's linear
    solver (the solution is unique: no free oscillation starts at rest)."""
    from sympy.simplify.fu import TR8

    unknowns, trial, waves = [], sp.Integer(0), []
    for m in frequencies:
        for wave in (sp.cos(m * tau), sp.sin(m * tau)):
            coefficients = sp.symbols(f"c{len(waves)}_0:{degree + 1}")
            unknowns += coefficients
            trial += sum(c * tau**k for k, c in enumerate(coefficients)) * wave
            waves.append(wave)
    residual = sp.expand(TR8(sp.expand(trial.diff(tau, 2) + trial - rhs)))
    equations = [trial.subs(tau, 0), trial.diff(tau).subs(tau, 0)]
    for wave in waves:
        equations.extend(sp.Poly(residual.coeff(wave), tau).all_coeffs())
    (solution,) = sp.linsolve(equations, unknowns)
    return sp.expand(trial.subs(dict(zip(unknowns, solution, strict=True))))


def cited(name: str) -> Any:
    """The reference ``name`` of Lecornu's table (built when asked: a builder of another
    module, found by the name the ledger cites rather than by its file)."""
    from pendcli.papers.lecornu import PAPER

    assert PAPER.references is not None
    return PAPER.references()[name]()
