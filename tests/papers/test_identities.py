"""papers/identities.py's point test against sympy's simplify, the computation it skips."""

from __future__ import annotations

import pytest

sp = pytest.importorskip("sympy")

from pendcli.papers.identities import nonzero_at_a_point, vanishes_identically  # noqa: E402


def _cases() -> list:
    x = sp.Symbol("x", positive=True)
    y, t = sp.symbols("y t")
    n = sp.Symbol("n", integer=True)
    th = sp.Function("theta")(t)
    return [
        sp.sqrt(x**2) - x,  # 0 only because x > 0
        sp.sqrt(y**2) - y,  # not 0 for y < 0, 0 at every positive point
        sp.sin(n * sp.pi) + sp.Abs(y) - y,  # 0 at every positive point, not identically
        sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1,
        th.diff(t, 2) * sp.sin(th) - sp.sin(th) * th.diff(t, 2),
        (th**2).diff(t) - 2 * th * th.diff(t),
        (th**2).diff(t) - th * th.diff(t),  # not 0
        sp.exp(sp.log(x)) - x,
        sp.atan(x) + sp.atan(1 / x) - sp.pi / 2,  # 0 for x > 0 only
        sp.cos(2 * y) - 1 + 2 * sp.sin(y) ** 2,
        sp.cos(2 * y) - 1 + sp.sin(y) ** 2,  # not 0
        x / (x + 1) - 1 + 1 / (x + 1) + y * 10**-25,  # not 0, but a float: no 30 digits
    ]


def test_a_nonzero_value_at_a_point_is_never_a_zero_of_simplify() -> None:
    found = 0
    for case in _cases():
        if nonzero_at_a_point(case):
            found += 1
            assert sp.simplify(case) != 0, case
    assert found == 2  # the two marked "not 0" that are exact


def test_vanishes_identically_agrees_with_simplify() -> None:
    for case in _cases():
        assert vanishes_identically(case) == (sp.simplify(case) == 0), case


def test_an_integral_or_an_integer_symbol_is_left_to_simplify() -> None:
    s, x = sp.symbols("s x", positive=True)
    n = sp.Symbol("n", integer=True)
    assert not nonzero_at_a_point(sp.Integral(s, (s, 0, x)) - x**2)
    assert not nonzero_at_a_point(n + 1)
