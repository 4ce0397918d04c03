"""The shortcuts of pendcli/papers/taylor.py against sympy's own computations."""

from __future__ import annotations

import pytest

sp = pytest.importorskip("sympy")

from pendcli.papers.taylor import degree_in  # noqa: E402


def _terms() -> list:
    """Expanded terms of the kind the Tisserand series truncation meets: rational
    coefficients, other letters, sines of another variable, powers of the scale s."""
    s, u, tau = sp.symbols("s u tau", positive=True)
    series = sp.series(sp.sqrt(1 + s * u * sp.sin(tau)) / (1 - s**2 * u), s, 0, 7).removeO()
    return list(sp.Add.make_args(sp.expand(series * (3 + sp.cos(2 * tau)) + sp.Rational(5, 7))))


def test_degree_in_agrees_with_sympy_degree_on_a_series_terms() -> None:
    s = sp.Symbol("s", positive=True)
    terms = _terms()
    assert len(terms) > 20
    degrees = {degree_in(t, s) for t in terms}
    assert degrees == set(range(7))  # the constant term up to s**6
    for term in terms:
        assert degree_in(term, s) == sp.degree(term, s), term


def test_degree_in_of_the_tisserand_motion_terms() -> None:
    from pendcli.papers.tisserand.references_series import motion_series, series_symbols

    s = series_symbols()[0]
    for term in sp.Add.make_args(sp.expand(motion_series(5)["kt"])):
        assert degree_in(term, s) == sp.degree(term, s), term


def test_degree_in_leaves_a_non_plain_power_to_sympy() -> None:
    s, x = sp.symbols("s x")
    assert degree_in(x * s ** sp.Integer(3), s) == 3
    assert degree_in(sp.Integer(4), s) == 0
    with pytest.raises(sp.PolynomialError):  # s inside a function is no polynomial term
        degree_in(s * sp.sin(s), s)
