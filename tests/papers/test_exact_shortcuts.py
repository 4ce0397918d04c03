"""The exact shortcuts the equation checks take before sympy's costly general routines:
``vanishes_identically`` (cancel, then sin² + cos² = 1, then simplify) and
``taylor`` (Taylor polynomials by exact derivatives instead of ``sp.series``).

Each is compared with an independent computation: numeric evaluation at random points (a
claimed zero must vanish there, a claimed non-zero must not) and ``sp.series`` itself.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pendcli.papers.identities import simplified, vanishes_identically
from pendcli.papers.taylor import taylor

FEW = settings(
    max_examples=25, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow]
)
x, y, t = sp.symbols("x y t", real=True)
f = sp.Function("f")


def _numerically_zero(expr: sp.Expr, trials: int = 4) -> bool:
    """expr at random points of [0.3, 1.7]ⁿ, 30 digits: the independent check."""
    rng = random.Random(23)
    expr = expr.replace(f, lambda arg: sp.exp(arg) / 3 + arg)  # any f: one concrete f
    free = sorted(expr.free_symbols, key=str)
    for _ in range(trials):
        point = {s: sp.Rational(rng.randint(3, 17), 10) for s in free}
        if abs(sp.N(expr.subs(point), 30)) > 1e-20:
            return False
    return True


ZEROS = [
    (x**2 - 1) / (x - 1) - (x + 1),  # rational: cancel
    sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1,  # sin² + cos² = 1
    sp.sin(2 * x) - 2 * sp.sin(x) * sp.cos(x),  # multiple angles, expand_trig
    sp.sin(x - y) * sp.cos(y) + sp.cos(x - y) * sp.sin(y) - sp.sin(x),  # sums of angles
    sp.sin(x) ** 4 - sp.cos(x) ** 4 + sp.cos(2 * x),
    (f(t) * sp.sin(t) ** 2 + f(t) * sp.cos(t) ** 2 - f(t)) / (1 + t**2),  # a generic f
    sp.cosh(x) ** 2 - sp.sinh(x) ** 2 - 1,  # neither shortcut: simplify decides
]
NONZEROS = [
    sp.sin(x) ** 2 - sp.cos(x) ** 2,
    sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1 + x / 10**6,
    sp.sin(2 * x) - sp.sin(x) * sp.cos(x),
    x / (x + 1) - 1,
    sp.cosh(x) ** 2 + sp.sinh(x) ** 2 - 1,
]


@pytest.mark.parametrize("expr", ZEROS, ids=str)
def test_zeros_are_found(expr: sp.Expr) -> None:
    assert _numerically_zero(expr)  # the example itself is right
    assert vanishes_identically(expr)
    assert vanishes_identically(expr, expand_first=True)
    assert simplified(expr) == 0


@pytest.mark.parametrize("expr", NONZEROS, ids=str)
def test_non_zeros_are_not(expr: sp.Expr) -> None:
    assert not _numerically_zero(expr)
    assert not vanishes_identically(expr)
    assert not vanishes_identically(expr, expand_first=True)
    assert simplified(expr) == sp.simplify(expr) != 0


# a random polynomial in sin x, cos x, sin 2x, cos(x − y): zero differences are that
# polynomial against itself times sin²x + cos²x and with 2 sin x cos x for sin 2x; a
# perturbed one is zero only when the bump is 0
TERMS = [sp.sin(x), sp.cos(x), sp.sin(2 * x), sp.cos(x - y), sp.Integer(1)]
monomials = st.tuples(*(st.integers(0, 2) for _ in TERMS), st.integers(-3, 3))


def _polynomial(parts: list[tuple[int, ...]]) -> sp.Expr:
    total = sp.Integer(0)
    for *powers, coefficient in parts:
        total += coefficient * sp.Mul(*(b**e for b, e in zip(TERMS, powers, strict=True)))
    return total


@pytest.mark.slow  # 2.3 s: five random polynomials, some through simplify
@settings(FEW, max_examples=5)
@given(st.lists(monomials, min_size=1, max_size=2), st.integers(0, 2))
def test_random_trig_polynomials(parts: list[tuple[int, ...]], bump: int) -> None:
    poly = _polynomial(parts)
    pythagoras = poly * (sp.sin(x) ** 2 + sp.cos(x) ** 2) - poly
    double = poly - poly.subs(sp.sin(2 * x), 2 * sp.sin(x) * sp.cos(x))
    assert vanishes_identically(pythagoras) and vanishes_identically(double)
    perturbed = pythagoras + double + bump * sp.sin(x) ** 2 * sp.cos(x - y)
    assert vanishes_identically(perturbed) == _numerically_zero(perturbed) == (bump == 0)


ANALYTIC = [
    (sp.cos(2 * y * sp.cos(x) + y**3 * sp.sin(x)), y, 3),
    (sp.exp(-y * x / 2) * sp.sin(sp.sqrt(4 + y) * x), y, 3),
    (1 / sp.sqrt(1 - y**2 * sp.sin(x) ** 2), y, 5),
    (x / (1 + y * x), y, 4),
]
NOT_ANALYTIC = [
    (sp.sqrt(y) + y, y, 3),  # infinite derivative at 0
    (sp.sin(y) / y, y, 3),  # 0/0 at 0: analytic, but not by substitution
    (sp.Abs(y) + y**2, y, 3),  # no derivative at 0
    (sp.log(1 + y) / y**2, y, 2),  # a pole
]


@pytest.mark.parametrize(("expr", "var", "n"), ANALYTIC + NOT_ANALYTIC, ids=str)
def test_taylor_is_the_series(expr: sp.Expr, var: sp.Symbol, n: int) -> None:
    expected = sp.series(expr, var, 0, n).removeO()
    assert sp.simplify(sp.expand(taylor(expr, var, n) - expected)) == 0
