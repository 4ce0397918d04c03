"""The series engine's shortcuts: a branch point at 0 (s**(1/2), s**(3/2)) proved
in the root t = s**(1/q), and a coefficient far from 0 refused, both by Cauchy's integral and
without sympy's series; sympy's own series, computed before it is barred, is the judge."""

from __future__ import annotations

import re

import pytest
import sympy as sp

from pendcli.data.printed import Formula
from pendcli.verify.printed_check import Reference, formula_passes

s = sp.Symbol("s", positive=True)
a = sp.Symbol("a", real=True)
x = sp.sqrt(s)

# (residual, order): Puiseux series in s, each judged where sympy's series is cheap
BRANCHED = [
    (sp.sqrt(1 + x) - 1 - x / 2 + s / 8 - x**3 / 16, 2),  # next term -5 s**2/128
    (sp.sqrt(1 + x) - 1 - x / 2 + s / 8 - x**3 / 16, 3),
    (sp.sqrt(1 + x) - 1 - x / 2 + s / 8 - x**3 / 15, 2),  # the s**(3/2) coefficient off
    (a * x**3, 1),  # s**(3/2) lies above order 1
    (a * x**3, 2),
    ((sp.sin(a * x) - a * x) / x + a**3 * s / 6, 2),  # next a**5 s**2/120
    ((sp.sin(a * x) - a * x) / x + a**3 * s / 6, 3),
    (sp.exp(sp.cbrt(s)) - 1 - sp.cbrt(s) - sp.cbrt(s) ** 2 / 2 - s / 6, 1),  # q = 3
    (sp.exp(sp.cbrt(s)) - 1 - sp.cbrt(s) - sp.cbrt(s) ** 2 / 2 - s / 6, 2),
    (a / x + 1 / s - 1 / s, 0),  # a pole s**(-1/2): kept below order 0
    # a root whose base is 0 * zoo at s = 0 as written, 1 + a s expanded
    (x * (sp.sqrt(s**2 * (a + 1 / s) ** 2 + s) - sp.sqrt(1 + (2 * a + 1) * s) - s), 2),
]


def _series_vanishes(residual: sp.Expr, order: int) -> bool:
    return sp.simplify(sp.series(residual, s, 0, order).removeO()) == 0


def _barred(*args: object, **kwargs: object) -> None:
    pytest.fail("sympy's series was needed: the Cauchy proof did not decide")


@pytest.mark.parametrize(("residual", "order"), BRANCHED)
def test_a_branch_point_is_judged_in_its_root_as_sympys_series_judges_it(
    residual: sp.Expr, order: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    expected = _series_vanishes(residual, order)  # the independent judge, before it is barred
    monkeypatch.setattr(sp, "series", _barred)
    formula = Formula("residual = 0", ((residual, sp.Integer(0)),))
    ok, why = formula_passes(formula, Reference(exact={}, scale=s, order=order))
    assert ok is expected, why


# (residual, order, power): the lowest power whose coefficient is not 0
REFUSED = [
    ((sp.cos(a * s) - 1) / s**2 + a**2 / 2 - a**4 * s**2 / 25, 4, 2),
    (sp.besselj(0, a * s) - 1 + a**2 * s**2 / 5, 4, 2),
    (1 / (a - s) - 1 / a - s / a**2, 3, 2),
    (sp.sqrt(1 + x) - 1 - x / 2 + s / 8 - x**3 / 15, 2, sp.Rational(3, 2)),
]


@pytest.mark.parametrize(("residual", "order", "power"), REFUSED)
def test_a_refused_series_names_sympys_lowest_coefficient(
    residual: sp.Expr, order: int, power: sp.Rational, monkeypatch: pytest.MonkeyPatch
) -> None:
    series = sp.expand(sp.series(residual, s, 0, order).removeO())
    monkeypatch.setattr(sp, "series", _barred)
    formula = Formula("residual = 0", ((residual, sp.Integer(0)),))
    ok, why = formula_passes(formula, Reference(exact={}, scale=s, order=order))
    assert not ok
    found = re.search(r"the coefficient of s\*\*(\S+) is (\S+)(?: at a=(\d+/\d+))?", why)
    assert found, why
    assert sp.Rational(found.group(1)) == power
    at = {a: sp.Rational(found.group(3))} if found.group(3) else {}
    coefficient = series.coeff(s**power).subs(at)
    assert float(found.group(2)) == pytest.approx(float(coefficient), rel=1e-5)


def test_a_decimals_rounding_is_not_a_refused_coefficient() -> None:
    """A 20-digit decimal leaves a coefficient of 1e-21, far above the Cauchy proof's
    tolerance, that the points forgive (relative 1e-15): the proof must decide nothing."""
    third = sp.Float("0.33333333333333333333", 20)
    assert abs(sp.Rational(third) - sp.Rational(1, 3)) > 1e-22  # the noise is there
    residual = sp.exp(s) * s**2 * (third - (sp.cos(a) ** 2 + sp.sin(a) ** 2) / 3)
    formula = Formula("residual = 0", ((residual, sp.Integer(0)),))
    ok, why = formula_passes(formula, Reference(exact={}, scale=s, order=4))
    assert ok, why
