"""Tisserand's equation checks can fail: the printed slips and altered coefficients are refuted."""

from __future__ import annotations

import sympy as sp

from pendcli.papers.tisserand import equations as eq


def test_the_tan_sq_phi1_as_the_ocr_prints_it_is_not_the_squared_10() -> None:
    *_, w, a, b, psi = eq.symbols()
    printed = (b * a - w) / (a * w - b)  # the flattened fraction
    exact = b / a * sp.tan(psi) ** 2
    u2 = a * sp.cos(psi) ** 2 + b * sp.sin(psi) ** 2
    # One exact point where the two differ refutes the identity (ψ = π/4: all rational).
    point = {a: sp.Rational(1, 4), b: sp.Rational(1, 9), psi: sp.pi / 4}
    difference = (printed.subs(w, u2) - exact).subs(point)
    assert difference.is_Rational and difference != 0


def test_formula_5_alone_has_no_dt_so_the_cross_reference_needs_4() -> None:
    x, w = eq.symbols()[3:5]
    # (5) squared, times u⁴: not the series printed after « La formule (5) donnera ».
    from_5 = (eq.dphi_over_u0u1() * x * w) ** 2
    s, q, _ = eq.sum_q_r()
    assert sp.simplify(eq.series_in_x(from_5) - (1 - s / 4 - q / 16)) != 0


def test_an_altered_coefficient_of_6_is_refuted() -> None:
    _, _, _, x, w, a, b, _ = eq.symbols()
    c, _, _ = eq.cosines()
    exact = sp.sqrt(eq.square_from_4()) / c
    altered = 1 - x * (a + b) / 8 + sp.Rational(3, 8) * x * w + sp.Rational(36, 128) * x**2 * w**2
    assert not eq.identity_check(eq.series_in_x(exact) - altered, "altered").holds


def test_the_first_integrals_match_a_direct_spherical_pendulum() -> None:
    """θ'² of (1) at the apsides is zero and positive between (k = 1)."""
    c, c0, c1, *_ = eq.symbols()
    v = eq.energy_theta_dot_sq()
    values = {c0: sp.Rational(7, 10), c1: sp.Rational(9, 10)}
    assert v.subs({**values, c: values[c0]}) == 0
    assert sp.simplify(v.subs({**values, c: values[c1]})) == 0
    assert v.subs({**values, c: sp.Rational(8, 10)}) > 0


def test_every_check_named_in_the_ledger_exists() -> None:
    from pendcli.core.ledger import load_ledger

    for row in load_ledger("tisserand").rows:
        if row.check is not None:
            assert callable(getattr(eq, row.check)), row.id
