"""A series row's quick numerical proof: the Taylor and pole coefficients of the
residual in the scale, by Cauchy's integral about 0, prove what sympy's series would and
never a residual that sympy's series keeps; sympy's series is the independent judge here."""

from __future__ import annotations

from functools import cache

import pytest
import sympy as sp

from pendcli.data.printed import Formula
from pendcli.verify.printed_check import Reference, formula_passes

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


@cache  # four residuals are judged in both families below: sympy's series once each
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


# Residuals the Cauchy proof alone must prove (sympy's series not called): real ones, whose
# lower half circle is mirrored from the upper, and complex ones (an I, or a real-looking
# square root of a negative number), whose whole circle is evaluated.
PROVED_WITHOUT_SERIES = [
    ((sp.cos(a * s) - 1) / s**2 + a**2 / 2 - a**4 * s**2 / 24, 4),
    (sp.sqrt(1 + a * s) - 1 - a * s / 2 + a**2 * s**2 / 8 - a**3 * s**3 / 16, 4),
    (sp.besselj(0, a * s) - 1 + a**2 * s**2 / 4, 4),
    (1 / sp.sin(s) ** 2 - 1 / s**2 - sp.Rational(1, 3), 1),
    (sp.exp(sp.I * a * s) - 1 - sp.I * a * s + a**2 * s**2 / 2, 3),
    (sp.sqrt(a - 1) * (sp.sin(s) - s), 3),  # a < 1: an imaginary factor with no I in it
    (sp.sqrt(a - 1) * (sp.sin(s) - s + s**3 / 6) + sp.I * s**5, 5),
]


@pytest.mark.parametrize(("residual", "order"), PROVED_WITHOUT_SERIES)
def test_the_cauchy_proof_decides_an_analytic_residual_alone(
    residual: sp.Expr, order: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert _series_vanishes(residual, order)  # the independent judge, before it is barred

    def barred(*args: object, **kwargs: object) -> None:
        pytest.fail("sympy's series was needed: the Cauchy proof did not go through")

    monkeypatch.setattr(sp, "series", barred)
    formula = Formula("residual = 0", ((residual, sp.Integer(0)),))
    ok, why = formula_passes(formula, Reference(exact={}, scale=s, order=order))
    assert ok, why


@pytest.mark.parametrize(
    "residual",
    [
        sp.cos(a * s) - 1 + a**2 * s**2 / 2 - a**3 * s**3 / 1000,  # real, one odd term
        sp.sqrt(a - 1) * (sp.sin(s) - s) + sp.I * s**2,  # complex, even term imaginary
    ],
)
def test_a_coefficient_off_by_little_is_still_refused(residual: sp.Expr) -> None:
    assert not _series_vanishes(residual, 4)
    formula = Formula("residual = 0", ((residual, sp.Integer(0)),))
    ok, why = formula_passes(formula, Reference(exact={}, scale=s, order=4))
    assert not ok, why
