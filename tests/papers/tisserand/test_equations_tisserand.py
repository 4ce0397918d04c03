"""Tisserand's references can fail: each is compared with an independent computation (exact
values at a point, Newton's equations integrated, mpmath quadrature), and the ledger cites
exactly the references its table lists."""

from __future__ import annotations

import math

import mpmath
import pytest
import sympy as sp
from helpers.ledgers import committed_ledger

from pendcli.papers.registry import paper
from pendcli.papers.tisserand.references import REFERENCES
from pendcli.papers.tisserand.references_series import motion_in_kpt, motion_series, series_symbols
from pendcli.verify.ledger_formulas import row_formula
from pendcli.verify.ledger_references import cited_reference


def test_every_cited_reference_is_in_the_table_and_every_entry_is_cited() -> None:
    cited = {r.reference for r in committed_ledger("tisserand").rows if r.reference}
    assert sorted(cited - set(REFERENCES)) == []  # a row citing a reference nobody builds
    assert sorted(set(REFERENCES) - cited) == []  # a dead reference
    assert paper("tisserand").references() is REFERENCES


def _real(*names: str) -> list[sp.Symbol]:
    return [sp.Symbol(n, real=True) for n in names]


def _sides_at(row_id: str, field: str, point: dict[sp.Symbol, object]) -> tuple[object, object]:
    """The two sides of a row's formula (its printed form, or ``read``: that form read
    through the OCR's reading table) at an exact point."""
    ledger = committed_ledger("tisserand")
    (row,) = [r for r in ledger.rows if r.id == row_id]
    text = row.read("printed") if field == "read" else getattr(row, field)
    ((lhs, rhs),) = row_formula(row.id, text, ledger.symbols_for(row)).equations
    return lhs.subs(point), rhs.subs(point)


def test_the_ellipse_reference_gives_10_and_refutes_the_flattened_tan_sq_phi1() -> None:
    """At ψ = π/4 (tan ψ = 1) (10) gives tan²φ1 = u1²/u0² exactly: the reference (9) does, the
    reading of lines 136-138 does, the fraction as the OCR flattens it does not."""
    u0, u1, psi, phi1, u = _real("u0", "u1", "psi", "phi1", "u")
    exact = cited_reference(paper("tisserand"), "reference_ellipse").exact
    point = {u0: sp.Rational(1, 2), u1: sp.Rational(1, 3), psi: sp.pi / 4}
    tan_sq = sp.simplify(sp.tan(exact["phi1"].subs(point)) ** 2)
    assert tan_sq == sp.Rational(4, 9)  # (u1/u0)²
    at = {**point, u: exact["u"].subs(point), phi1: exact["phi1"].subs(point)}
    lhs, rhs = _sides_at("tisserand.result.tan-sq-phi1", "read", at)
    assert sp.simplify(lhs - tan_sq) == 0 and sp.simplify(rhs - tan_sq) == 0
    lhs, rhs = _sides_at("tisserand.result.tan-sq-phi1", "printed", at)
    assert sp.simplify(rhs - tan_sq) != 0


def _from_newton(k: float, theta0: float, theta1: float, h: float) -> tuple[float, list]:
    """Newton's equations of the spherical pendulum in θ, φ (θ'' = sin θ cos θ φ'² − k² sin θ,
    φ'' = −2 θ' φ' cot θ) from θ0 at rest in θ, sin²θ0 φ' = h: the smallest angle reached,
    and (θ, θ'²) along the way down."""
    from scipy.integrate import solve_ivp

    def rhs(_t: float, y: list[float]) -> list[float]:
        theta, dtheta, dphi = y
        ddtheta = math.sin(theta) * math.cos(theta) * dphi**2 - k**2 * math.sin(theta)
        return [dtheta, ddtheta, -2 * dtheta * dphi / math.tan(theta)]

    def at_the_bottom(_t: float, y: list[float]) -> float:
        return y[1]

    at_the_bottom.direction = 1  # type: ignore[attr-defined]  # θ' from − to +: the least θ
    at_the_bottom.terminal = True  # type: ignore[attr-defined]  # the first is all it reads
    start = [theta0, 0.0, h / math.sin(theta0) ** 2]
    run = solve_ivp(rhs, (0, 100 / k), start, events=at_the_bottom, rtol=1e-12, atol=1e-14,
                    dense_output=True)  # fmt: skip
    bottom = run.t_events[0][0]
    along = [run.sol(bottom * f) for f in (0.25, 0.5, 0.75)]
    return float(run.y_events[0][0][0]), [(y[0], y[1] ** 2) for y in along]


def test_the_first_integrals_reference_follows_newtons_equations() -> None:
    """(1), (2): the reference's dt/dθ and dφ/dt, at θ0 = 0.7, θ1 = 0.3, k = 1.3: launched
    from θ0 with its h = sin²θ dφ/dt, Newton's equations turn back at its θ1, and θ'² along
    the way is its (dθ/dt)²."""
    theta, dtheta, theta0, theta1, k = _real("theta", "dtheta", "theta0", "theta1", "k")
    exact = cited_reference(paper("tisserand"), "reference_first_integrals").exact
    given = {theta0: 0.7, theta1: 0.3, k: 1.3, dtheta: -1}
    dt = sp.lambdify(theta, exact["dt"].subs(given))
    h = sp.lambdify(theta, (sp.sin(theta) ** 2 * exact["dphi"] / exact["dt"]).subs(given))
    assert h(0.4) == pytest.approx(h(0.6), rel=1e-12)  # the areal constant
    lowest, along = _from_newton(1.3, 0.7, 0.3, float(h(0.5)))
    assert lowest == pytest.approx(0.3, abs=1e-8)
    for angle, dtheta_sq in along:
        assert 1 / float(dt(angle)) ** 2 == pytest.approx(dtheta_sq, rel=1e-8)


def test_the_differential_4_reference_is_the_first_integrals_through_3() -> None:
    """(4) solved for dt (lines 70-72), at u = sin θ of (3), against dθ/θ' by mpmath: θ'²
    from the energy and areal integrals (their constants solved numerically from θ' = 0 at
    θ0, θ1), dθ the numerical derivative of (3)."""
    u, u0, u1, k, dpsi = _real("u", "u0", "u1", "k", "dpsi")
    x = sp.Symbol("x", positive=True)
    dt = cited_reference(paper("tisserand"), "reference_differential_4").exact["dt"]
    with mpmath.workdps(30):
        a, b, kk, psi = mpmath.mpf("0.6"), mpmath.mpf("0.25"), mpmath.mpf("1.3"), mpmath.mpf("0.8")
        theta0, theta1 = mpmath.asin(a), mpmath.asin(b)
        rows = [[1, -1 / (2 * mpmath.sin(t) ** 2)] for t in (theta0, theta1)]
        energy, h2 = mpmath.lu_solve(rows, [-(kk**2) * mpmath.cos(t) for t in (theta0, theta1)])

        def theta(p: object) -> object:
            return mpmath.asin(mpmath.sqrt(a**2 * mpmath.cos(p) ** 2 + b**2 * mpmath.sin(p) ** 2))

        at = theta(psi)
        theta_dot = -mpmath.sqrt(2 * energy + 2 * kk**2 * mpmath.cos(at) - h2 / mpmath.sin(at) ** 2)
        expected = mpmath.diff(theta, psi) / theta_dot
        point = {x: 1, u: mpmath.sin(at), u0: a, u1: b, k: kk, dpsi: 1}
        found = sp.N(dt.subs(point), 30)
        assert abs(found - expected) < mpmath.mpf(10) ** -25 * abs(expected)


# --- the exact series the computed statuses rest on, against independent methods -----------


def _series_value(expr: object, theta0: float, theta1: float, **more: float) -> float:
    s, _, _, _, u0, u1, *_ = series_symbols()
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
    series = motion_series(7)
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

    psi_of_tau = motion_in_kpt(5)["psi"]
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
    series = motion_series(5)
    kp_over_k = 1 / _series_value(series["A"], theta0, theta1)
    kpp_over_kp = _series_value(series["P"], theta0, theta1) / (3 / 8 * u0 * u1)
    rates = {k: _apsidal_rate(k, theta0, theta1) for k in (1.0, 3.0)}
    assert rates[3.0] / rates[1.0] == pytest.approx(3, rel=1e-8)
    for k, rate in rates.items():
        assert rate / (3 / 8 * u0 * u1 * k * kp_over_k) == pytest.approx(kpp_over_kp, rel=1e-5)
    assert abs(rates[3.0] / (3 / 8 * u0 * u1) - 1) > 1  # not (3/8)u0u1 as an angular velocity
    # the row's reference, dφ'/dt = k'·P (k' through the second order, P through the fourth:
    # the axis's rate agrees to the fourth order in the angles, 1.5e-5 here)
    g, length = sp.Symbol("g", real=True), sp.Symbol("l", real=True)
    rate_of = cited_reference(paper("tisserand"), "reference_resal").exact["dphip_dt"]
    for k, rate in rates.items():
        found = _series_value(rate_of.subs({g: k**2, length: 1}), theta0, theta1)
        assert found == pytest.approx(rate, rel=5e-5)
