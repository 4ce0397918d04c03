"""A series row's quick numerical proof (issue 23): the Taylor and pole coefficients of the
residual in the scale, by Cauchy's integral about 0, prove what sympy's series would and
never a residual that sympy's series keeps; sympy's series is the independent judge here."""

from __future__ import annotations

import pytest
import sympy as sp

from pendcli.core.printed import Formula
from pendcli.core.printed_check import Reference, formula_passes

s, a = sp.symbols("s a", real=True)

# (residual, order): the truncated series of each vanishes, or does not, as sympy says
CASES = [
    ((sp.cos(a * s) - 1) / s**2 + a**2 / 2 - a**4 * s**2 / 24, 4),  # removable at 0
    ((sp.cos(a * s) - 1) / s**2 + a**2 / 2 - a**4 * s**2 / 25, 4),  # one coefficient off
    ((sp.cos(a * s) - 1) / s**2 + a**2 / 2 - a**4 * s**2 / 25, 2),  # off beyond the order
    (sp.sqrt(1 + a * s) - 1 - a * s / 2 + a**2 * s**2 / 8 - a**3 * s**3 / 16, 4),
    (sp.sqrt(1 + a * s) - 1 - a * s / 2 + a**2 * s**2 / 8 - a**3 * s**3 / 16, 5),
    (sp.besselj(0, a * s) - 1 + a**2 * s**2 / 4, 4),
    (sp.besselj(0, a * s) - 1 + a**2 * s**2 / 5, 4),
    (1 / (a - s) - 1 / a - s / a**2, 2),
    (1 / (a - s) - 1 / a - s / a**2, 3),
    (2 / s**2 - 1 / s**2 + 5, 0),  # a pole's term: kept by sympy's series below order 0
    (1 / sp.sin(s) ** 2 - 1 / s**2 - sp.Rational(1, 3), 1),
    (1 / sp.sin(s) ** 2 - 2 / s**2 - sp.Rational(1, 3), 1),
    (sp.sqrt(s) ** 3 * a, 2),  # s**(3/2): not a Taylor series; sympy's series keeps it
    (s * sp.log(s) * a, 1),  # no Taylor series at 0 either (log(s) is left to sympy)
]


def _series_vanishes(residual: sp.Expr, order: int) -> bool:
    return sp.simplify(sp.series(residual, s, 0, order).removeO()) == 0


@pytest.mark.parametrize(("residual", "order"), CASES)
def test_a_series_row_passes_exactly_when_sympys_series_vanishes(
    residual: sp.Expr, order: int
) -> None:
    formula = Formula("residual = 0", ((residual, sp.Integer(0)),))
    reference = Reference(exact={}, scale=s, order=order)
    ok, why = formula_passes(formula, reference)
    assert ok is _series_vanishes(residual, order), why
