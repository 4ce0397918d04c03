"""A ``bounded`` row's limit as the scale tends to 0+: proved finite by Cauchy's
integral, the logarithms of the scale split off (P + Q log s), without sympy's limit; sympy's
own limit, computed before it is barred, is the judge, and a growing residual is refused."""

from __future__ import annotations

import pytest
import sympy as sp

from pendcli.data.printed import Formula
from pendcli.verify.printed_check import Reference, formula_passes

s = sp.Symbol("s", positive=True)
a = sp.Symbol("a", real=True)

FINITE = [
    (1 + a * s) / s - 1 / s - a + s * sp.log(s),
    sp.log(a * s) - sp.log(s) + sp.exp(sp.sqrt(s)),
    sp.sqrt(s) * sp.log(s) + a,
    (sp.exp(-2 * a * sp.sqrt(s)) * (1 + 2 * a * sp.sqrt(s)) - 1) / s,
    sp.log(1 + s) / s,
    sp.log(s**2 / a) / 2 - sp.log(s) + a**2 / s - a**2 / s,
    (sp.log(s * a) - 1 / (a * s)) * s**2 + (1 - sp.cos(sp.sqrt(s))) / s,
]
GROWING = [
    1 / s + sp.log(s),
    sp.log(s),
    sp.log(s**2 * a) / 2 - 1 / sp.sqrt(s),
    (1 - sp.cos(sp.sqrt(s))) / s**2,
    a / s - (a + s**2) / s,  # finite: sympy and the proof agree without a log
]


def _judged(residual: sp.Expr) -> tuple[bool, str]:
    formula = Formula("residual = 0", ((residual, sp.Integer(0)),))
    return formula_passes(formula, Reference(exact={}, scale=s, bounded=True))


def _barred(*args: object, **kwargs: object) -> None:
    pytest.fail("sympy's limit was needed: the Cauchy proof did not decide")


@pytest.mark.parametrize("residual", FINITE + GROWING)
def test_a_bounded_row_passes_exactly_when_sympys_limit_is_finite(
    residual: sp.Expr, monkeypatch: pytest.MonkeyPatch
) -> None:
    """And each of FINITE, whose limit sympy finds finite, is proved so without sympy's
    limit: it is barred, once it has judged, while the engine judges those."""
    finite = sp.limit(residual.subs(a, sp.Rational(1, 3)), s, 0, "+").is_finite
    if residual in FINITE:
        assert finite
        monkeypatch.setattr(sp, "limit", _barred)
    ok, why = _judged(residual)
    assert ok is bool(finite), why
