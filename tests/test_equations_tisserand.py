"""Tisserand's equation checks can fail: the printed slips and altered coefficients are refuted."""

from __future__ import annotations

import math

import mpmath
import pytest
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


# --- the exact series the computed statuses rest on, against independent methods -----------


def _series_value(expr: object, theta0: float, theta1: float, **more: float) -> float:
    s, _, _, _, u0, u1, *_ = eq.series_symbols()
    point = {s: 1, u0: math.sin(theta0), u1: math.sin(theta1)}
    point.update({sp.Symbol(k, real=True): v for k, v in more.items()})
    return float(sp.sympify(expr).subs(point))


def _quadrature_means(theta0: float, theta1: float) -> tuple[float, float]:
    """The means over ψ of k dt/dψ (4) and of (dφ/dψ − u0u1/u²)/(u0u1) (5), by mpmath."""
    u0, u1 = mpmath.sin(theta0), mpmath.sin(theta1)
    c0, c1 = mpmath.cos(theta0), mpmath.cos(theta1)

    def parts(psi: object) -> tuple[object, object]:
        u2 = u0**2 * mpmath.cos(psi) ** 2 + u1**2 * mpmath.sin(psi) ** 2
        c = mpmath.sqrt(1 - u2)
        big = 1 + c * c0 + c * c1 + c0 * c1
        kdt = mpmath.sqrt((c + c0) * (c + c1) * (c0 + c1) / (2 * big)) / c
        dphi = mpmath.sqrt((c + c0) * (c + c1) / big) / (u2 * c)  # (5) over u0u1
        return kdt, dphi - 1 / u2

    with mpmath.workdps(30):
        a = mpmath.quad(lambda p: parts(p)[0], [0, mpmath.pi]) / mpmath.pi
        b = mpmath.quad(lambda p: parts(p)[1], [0, mpmath.pi]) / mpmath.pi
    return float(a), float(b)


def test_the_secular_coefficients_agree_with_quadrature_to_their_order() -> None:
    """A (kt = Aψ + …) and P (φ' = Pψ + …) through the sixth order against mpmath quadrature
    of (4), (5): the error falls as the eighth power of the angles (halving them: ÷ 2⁸)."""
    series = eq.motion_series(7)
    errors = []
    for theta0 in (0.2, 0.1):
        a, b = _quadrature_means(theta0, theta0 / 2)
        u0u1 = math.sin(theta0) * math.sin(theta0 / 2)
        errors.append(
            (
                abs(_series_value(series["A"], theta0, theta0 / 2) - a),
                abs(_series_value(series["P"], theta0, theta0 / 2) / u0u1 - b),
            )
        )
    for big, small in zip(errors[0], errors[1], strict=True):
        assert small < 1e-9 and big / small > 2**7, errors


def test_psi_in_kpt_agrees_with_the_fourier_inversion() -> None:
    """ψ(τ), τ = k't, from the series inversion against formulas.py's Fourier analysis and
    Newton inversion of the exact (4): the gap falls as the sixth power (order 4 kept)."""
    from pendcli.papers.tisserand.formulas import series_coefficients

    psi_of_tau = eq.motion_in_kpt(5)["psi"]
    gaps = []
    for theta0 in (0.2, 0.1):
        d = series_coefficients(theta0, theta0 / 2)["d"]
        gap = 0.0
        for tau in (0.3, 0.9, 1.4):
            numeric = tau + sum(d[m] * math.sin(2 * m * tau) for m in range(1, len(d)))
            gap = max(gap, abs(_series_value(psi_of_tau, theta0, theta0 / 2, tau=tau) - numeric))
        gaps.append(gap)
    assert gaps[1] < 1e-7 and gaps[0] / gaps[1] > 2**5, gaps


def _apsidal_rate(k: float, theta0: float, theta1: float) -> float:
    """The mean angular velocity of the apsides, by a direct integration of the spherical
    pendulum (θ'' = sin θ cos θ φ'² − k² sin θ, sin²θ φ' = h) over one period of θ."""
    from scipy.integrate import solve_ivp

    c0, c1 = math.cos(theta0), math.cos(theta1)
    h = k * math.sqrt(2 * (1 - c0**2) * (1 - c1**2) / (c0 + c1))  # θ' = 0 at θ0 and θ1

    def rhs(_t: float, y: list[float]) -> list[float]:
        theta, dtheta, _phi = y
        dphi = h / math.sin(theta) ** 2
        return [dtheta, math.sin(theta) * math.cos(theta) * dphi**2 - k**2 * math.sin(theta), dphi]

    def back_at_theta0(_t: float, y: list[float]) -> float:
        return y[1]

    back_at_theta0.direction = 1  # type: ignore[attr-defined]  # θ' from − to +: at θ1
    low = solve_ivp(rhs, (0, 100 / k), [theta0, 0, 0], events=back_at_theta0, rtol=1e-12,
                    atol=1e-14)  # fmt: skip
    half_period, (_, _, phi_half) = low.t_events[0][0], low.y_events[0][0]
    return (2 * phi_half - math.pi) / (2 * half_period)  # φ1 turns by π per period of θ


def test_resals_rate_is_a_rate_proportional_to_k() -> None:
    """Line 180, « k'' diffère peu de l'unité »: the axis's angular velocity, by direct ODE
    integration, is (3/8)u0u1k'' with k'' = k'(1 + 9(u0²+u1²)/32 + …), so it scales with k:
    (3/8)u0u1 is its value per unit of k't, not an angular velocity."""
    theta0, theta1 = 0.1, 0.05
    u0, u1 = math.sin(theta0), math.sin(theta1)
    series = eq.motion_series(5)
    kp_over_k = 1 / _series_value(series["A"], theta0, theta1)
    kpp_over_kp = _series_value(series["P"], theta0, theta1) / (3 / 8 * u0 * u1)
    rates = {k: _apsidal_rate(k, theta0, theta1) for k in (1.0, 3.0)}
    assert rates[3.0] / rates[1.0] == pytest.approx(3, rel=1e-8)
    for k, rate in rates.items():
        assert rate / (3 / 8 * u0 * u1 * k * kp_over_k) == pytest.approx(kpp_over_kp, rel=1e-5)
    assert abs(rates[3.0] / (3 / 8 * u0 * u1) - 1) > 1  # not (3/8)u0u1 as an angular velocity
