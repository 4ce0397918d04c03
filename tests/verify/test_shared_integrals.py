"""Definite integrals in a residual: each quadrature is run once per point and
shared by every residual that holds the same integral; sharing must never lend one point's
or one integral's value to another. The judge is the closed form (erf), not the engine."""

from __future__ import annotations

import pytest
import sympy as sp

from pendcli.data.printed import Formula
from pendcli.verify.printed_check import Reference, formula_passes

x, a, b = sp.symbols("x a b", positive=True)
GAUSS = sp.Integral(sp.exp(-a * x**2), (x, 0, 1))  # = sqrt(pi/a)/2 erf(sqrt(a))
CLOSED = sp.sqrt(sp.pi / a) / 2 * sp.erf(sp.sqrt(a))
NEAR = sp.Rational(10**12 + 1, 10**12)  # one part in 10**12: far above the tolerance


def _passes(lhs: sp.Expr, rhs: sp.Expr) -> bool:
    ok, _ = formula_passes(Formula("printed", ((lhs, rhs),)), Reference(exact={}))
    return ok


@pytest.mark.parametrize("rounds", [1, 2])
def test_a_shared_integral_holds_and_its_near_miss_is_refused(rounds: int) -> None:
    # the second round finds every quadrature remembered from the first
    for _ in range(rounds):
        assert _passes(GAUSS, CLOSED)
        assert not _passes(GAUSS, CLOSED * NEAR)
        assert _passes(2 * GAUSS - CLOSED, CLOSED)  # the same integral in another residual
        assert not _passes(GAUSS + b, CLOSED)


def test_two_integrals_in_one_residual_keep_their_own_values() -> None:
    other = sp.Integral(sp.exp(-b * x**2), (x, 0, 1))
    closed_b = CLOSED.subs(a, b)
    assert _passes(GAUSS + 2 * other, CLOSED + 2 * closed_b)
    assert not _passes(GAUSS + 2 * other, 2 * CLOSED + closed_b)
