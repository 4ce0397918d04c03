"""`pendcli formulas`: derived formulas against direct integration.

Every check is verified three ways: the verdict expected from working the derivation by hand
(one test id per formula, a failure asserted as a failure), the reference solution against a
second, independent method (a closed form, another ODE formulation or a tighter tolerance),
and the corrected terms against their exact values derived by hand.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from helpers.evaluated import committed_formulas

from pendcli.papers.charbonnier import formulas as fch
from pendcli.papers.charbonnier import perturbation as cpt
from pendcli.papers.lecornu import formula_figures as fle_figures
from pendcli.papers.lecornu import formulas as fle
from pendcli.papers.lecornu import formulas_chapter3 as fle3
from pendcli.papers.tisserand import formulas as fti
from pendcli.verify import formula_engine as engine
from pendcli.verify import formula_plots as plots

PI = math.pi
TIGHT = engine.Integrator(rtol=1e-13, atol=1e-15)


@pytest.fixture(scope="module")
def rows():
    # the registry's checks (each paper's formula_checks()), shared with the other files that
    # read them; test_deterministic below computes them again and compares
    return {key: committed_formulas(key) for key in ("lecornu", "tisserand", "charbonnier")}


def by_id(rows) -> dict:
    return {r.id: r for paper in rows.values() for r in paper}


# The verdict each check must reach; failures are worked out by hand in the module notes.
EXPECTED = {
    "lecornu.table26.first_elongation": "holds",
    "lecornu.table26.second_vertical": "holds",
    "lecornu.table26.first_negative_elongation": "holds",
    "lecornu.table26.third_vertical": "holds",
    "lecornu.oscillation_time_increase": "holds",
    "lecornu.quarter_time": "holds",
    "lecornu.amplitude_factor": "holds",
    "lecornu.eq25": "holds",
    "lecornu.eq26": "holds",
    "lecornu.eq28": "holds",
    "lecornu.eq29": "fails",  # −43γ²t² should be +21γ²t²
    "lecornu.period_second_order": "holds",
    "lecornu.mean_pendulum": "fails",  # 7π³/32 should be π³/32
    "lecornu.elongation_ratio": "holds",
    "lecornu.eq52": "fails",  # u cos u / u sin u misprinted
    "lecornu.homothety_ratio": "holds",
    "lecornu.compound_pendulum": "fails",  # the 2bθ' term keeps b
    "lecornu.eq31": "holds",
    "lecornu.eq38": "holds",
    "lecornu.eq41_terms_in_p": "fails",  # sign slip in 2β cos²u
    "lecornu.eq42_terms_in_b": "fails",
    "lecornu.eq42prime_terms_in_b": "fails",
    "lecornu.amplitude_series": "holds",
    "lecornu.k3_neglected": "holds",
    "lecornu.area_small_angle": "holds",
    "lecornu.composed_planes": "holds",  # the motion in space against (48) in two planes
    "lecornu.eq50": "holds",
    "lecornu.inverse_square_length": "holds",
    "lecornu.eq52_as_read": "holds",  # (52) with −u sin u, +u cos u
    "lecornu.trajectory_after_52": "holds",  # as read: arctg(ρ1y/(ρ2x))
    "lecornu.homothety_axes": "holds",  # as read: arctg(ρ1y/(ρ2x))
    "tisserand.k_prime": "holds",
    "tisserand.k_second": "holds",
    "tisserand.eq8_kt_sin2psi": "holds",
    "tisserand.eq8_kt_sin4psi": "holds",
    "tisserand.eq8_phi_psi": "holds",
    "tisserand.eq8_phi_sin2psi": "holds",
    "tisserand.psi_in_psi_sin4psi": "holds",
    "tisserand.II_sin2": "holds",
    "tisserand.II_sin4": "holds",
    "tisserand.V_sin2": "holds",
    "tisserand.eq7_inverse_square": "holds",
    "charbonnier.I_pi.closed_form_even": "holds",
    "charbonnier.I_pi.closed_form_odd": "holds",
    "charbonnier.E_c.closed_form": "fails",  # k^(n+1) should be k^(n−1)
    **{f"charbonnier.eq4_5.{p}": "holds" for p in ("linear_damping", "periodic_force", "friction")},
    **{
        f"charbonnier.eq{n}.{p}": "holds"
        for n in (6, 7, 8)
        for p in ("linear_damping", "periodic_force")
    },
    "charbonnier.eq9.linear_damping": "fails",  # E_c(π/2) should be E_s(π/2)
    "charbonnier.eq9.periodic_force": "fails",
    **{f"charbonnier.delta_alpha.n{n}": "holds" for n in range(6)},
    "charbonnier.delta_T_zero": "holds",
    "charbonnier.delta_T_half": "holds",
    "charbonnier.delta_v_m": "holds",
    "charbonnier.friction_count": "holds",
}


def test_every_check_has_an_expected_verdict(rows):
    assert set(by_id(rows)) == set(EXPECTED)


@pytest.mark.parametrize("row_id", sorted(EXPECTED))
def test_verdict(rows, row_id):
    row = by_id(rows)[row_id]
    assert row.verdict == EXPECTED[row_id], row.note
    paper = row_id.split(".")[0]
    assert row.paper == paper
    assert row.source and row.published and row.recomputed and row.note
    if row.claimed_order is not None:
        assert len(row.residuals) >= 4
        assert all(p > 0 and r >= 0 for p, r in row.residuals)
    if row.verdict == "fails" and row.claimed_order is not None:
        assert row.recomputed != row.published, "a failing formula must say what was found"


def test_observed_orders_near_claims(rows):
    """Holds with an order means the slope is close to (or above) the claim, by rule."""
    for row in by_id(rows).values():
        if row.verdict == "holds" and row.observed_order is not None:
            assert row.observed_order >= row.claimed_order - engine.ORDER_TOLERANCE


def test_deterministic(rows):
    again = fti.formula_checks()
    assert [r.as_dict() for r in again] == [r.as_dict() for r in rows["tisserand"]]
    fle.event_times.cache_clear()
    assert [r.as_dict() for r in fle.formula_checks()] == [r.as_dict() for r in rows["lecornu"]]


# ----------------------------------------------------------------------------- engine
def test_fit_order_and_judge_detect_a_wrong_order():
    ps = (0.04, 0.02, 0.01, 0.005)
    good = engine.Study("p", ps, tuple(3 * p**2 for p in ps), 2, 1e-12)
    bad = engine.Study("p", ps, tuple(3 * p for p in ps), 2, 1e-12)
    noise = engine.Study("p", ps, (1e-14, 2e-14, 1e-14, 3e-14), 2, 1e-12)
    assert engine.study_verdict(good)[0] == "holds"
    assert engine.study_verdict(good)[1] == pytest.approx(2.0)
    assert engine.study_verdict(bad)[0] == "fails"
    assert engine.study_verdict(noise)[0] == "holds" and engine.study_verdict(noise)[1] is None


def test_identify():
    assert engine.identify(35 / 4096) == "35/4096"
    assert engine.identify(3 * PI / 32) == "3/32·π"
    assert engine.identify_combination((PI**3 - 3 * PI) / 32, [(PI**3, "π³"), (PI, "π")]) == (
        "(π³ − 3π)/32"
    )
    assert engine.identify(35 / 4096 * (1 + 1e-3)) is None
    assert engine.identify(math.e / 10) is None


def test_richardson_is_exact_for_a_quadratic_at_uneven_parameters():
    """Neville at 0 through three points recovers f(0) of any quadratic, whatever the spacing
    (the old version assumed halving steps and ignored the parameters)."""
    ps = (Fraction(1, 3), Fraction(1, 7), Fraction(1, 10))
    values = [3 + 5 * p - 7 * p**2 for p in ps]
    assert engine.richardson(values, ps) == 3


@pytest.mark.parametrize(
    "ps",
    [
        (Fraction(1, 2), Fraction(1, 5), Fraction(1, 9)),
        (Fraction(4), Fraction(2), Fraction(1)),
        (Fraction(1, 10), Fraction(3, 10)),
    ],
)
def test_richardson_error_is_the_lagrange_remainder(ps):
    """For f = 1 + p^n with n points, f − P vanishes at every p_i and is monic: f − P =
    Π(p − p_i), so P(0) = 1 − Π(−p_i) = 1 + (−1)^(n+1) Π p_i."""
    n = len(ps)
    product = math.prod(ps)
    expected = 1 + (-1) ** (n + 1) * product
    assert engine.richardson([1 + p**n for p in ps], ps) == expected


def _complete_homogeneous(m: int, xs) -> Fraction:
    """h_m(x1, ..., xn): the sum of every monomial of degree m."""
    from itertools import combinations_with_replacement

    return sum((math.prod(c) for c in combinations_with_replacement(xs, m)), Fraction(0))


def test_richardson_on_a_known_series_in_floats():
    """log(1 + p)/p = Σ c_k p^k with c_k = (−1)^k/(k + 1). Through n points the extrapolation
    of p^k (k ≥ n) is (−1)^(n+1) Π p_i · h_(k−n)(p_i) (divided differences of x^k), so from
    p = 0.004, 0.002, 0.001 the result is 1 + Π Σ_(k≥3) c_k h_(k−3), summed exactly here."""
    ps = (0.004, 0.002, 0.001)
    exact_ps = [Fraction(4, 1000), Fraction(2, 1000), Fraction(1, 1000)]
    product = math.prod(exact_ps)
    expected = 1 + product * sum(
        Fraction((-1) ** k, k + 1) * _complete_homogeneous(k - 3, exact_ps) for k in range(3, 9)
    )
    got = engine.richardson([math.log1p(p) / p for p in ps], ps)
    assert got == pytest.approx(float(expected), abs=2e-15)
    assert abs(got - 1) > 1e-9  # the p³ term is really there: the test sees the parameters


def test_richardson_with_halving_steps_is_the_classical_table():
    """For p, p/2, p/4 the steps are 2 f(p/2) − f(p), then (4 r₂ − r₁)/3: same bits."""
    f1, f2, f3 = 1.2345678901234567, 1.2345001, 1.2344999999
    r1, r2 = 2 * f2 - f1, 2 * f3 - f2
    assert engine.richardson([f1, f2, f3], [0.004, 0.002, 0.001]) == (4 * r2 - r1) / 3


def test_richardson_refuses_repeated_or_missing_parameters():
    with pytest.raises(ValueError, match="distinct"):
        engine.richardson([1.0, 2.0], [0.1, 0.1])
    with pytest.raises(ValueError, match="as many"):
        engine.richardson([1.0, 2.0], [0.1])


def test_leading_coefficient_of_a_known_residual():
    """r = c p² (1 + d p): Richardson on the two smallest p removes d exactly, leaving c."""
    ps = (0.08, 0.04, 0.02, 0.01)
    residuals = [0.7 * p**2 * (1 - 3 * p) for p in ps]
    assert engine.leading_coefficient(ps, residuals, 2) == pytest.approx(0.7, rel=1e-12)


def test_extrapolate_to_zero_of_a_polynomial_in_p_squared():
    ps = (0.4, 0.3, 0.2, 0.1, 0.05)
    values = [2 + 3 * p**2 - p**4 for p in ps]
    assert engine.extrapolate_to_zero(ps, values, step=2) == pytest.approx(2.0, abs=1e-12)


def _row(verdict: str, residuals, claimed=2.0, observed=2.0):
    from pendcli.verify.claims import FormulaRow

    return FormulaRow(
        "demo.eq1", "demo", "(1)", "f", "f", verdict, claimed, observed, "", tuple(residuals)
    )


_LABELS = plots.PanelLabels("demo quantity", "p (rad)", "rad")


def test_draw_study_shows_the_residuals_and_the_claimed_slope():
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt
    from matplotlib.colors import to_rgba

    residuals = [(0.1, 3e-3), (0.05, 4e-4), (0.025, 0.0), (0.0125, 6e-6)]
    fig, ax = plt.subplots()
    try:
        plots.draw_study(ax, _row("fails", residuals, claimed=3.0, observed=2.71), _LABELS)
        data, slope = ax.get_lines()
        # the zero residual cannot sit on a log axis: three points drawn, red for "fails"
        assert list(data.get_xdata()) == [0.1, 0.05, 0.0125]
        assert list(data.get_ydata()) == [3e-3, 4e-4, 6e-6]
        assert to_rgba(data.get_color()) == to_rgba("tab:red")
        # claimed slope 3 through the smallest parameter's residual: 6e-6 · (p/0.0125)³
        expected = [6e-6 * (p / 0.0125) ** 3 for p, _ in residuals]
        np.testing.assert_allclose(slope.get_ydata(), expected, rtol=1e-14)
        assert ax.get_title() == "(1)  demo quantity\nfails: order 2.71 observed, 3 claimed"
        assert ax.get_xlabel() == "p (rad)"
        assert ax.get_ylabel() == "|reference − formula| (rad)"
        assert ax.get_xscale() == ax.get_yscale() == "log"
        # the sweep's ends are labelled ticks (a sweep under two decades may hold no decade)
        ticks = dict(
            zip(ax.get_xticks(), [t.get_text() for t in ax.get_xticklabels()], strict=True)
        )
        assert ticks[0.0125] == "0.0125" and ticks[0.1] == "0.1"
    finally:
        plt.close(fig)


def test_draw_study_of_a_residual_at_the_reference_error_says_so():
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    try:
        row = _row("holds", [(0.1, 2e-12), (0.05, 2e-12)], claimed=2.0, observed=None)
        plots.draw_study(ax, row, _LABELS)
        assert ax.get_title().endswith("holds: residual at the reference's error (claimed order 2)")
    finally:
        plt.close(fig)


def _grid_figure(monkeypatch, rows, labels):
    """Run plot_studies, keeping the figure it draws instead of only its PNG."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    from pendcli.base import plotting

    kept = []
    monkeypatch.setattr(plotting, "save_figure", lambda fig, path: kept.append(fig))
    monkeypatch.setattr(plt, "close", lambda fig: None)
    plots.plot_studies("unused.png", rows, "Demo", labels, ncols=2)
    (fig,) = kept
    return fig


def test_plot_studies_draws_one_labelled_panel_per_ordered_row(monkeypatch):
    from matplotlib.colors import to_rgba

    rows = [
        _row("holds", [(0.1, 1e-2), (0.05, 2.5e-3), (0.025, 6.25e-4)]),
        _row("fails", [(0.1, 1e-1), (0.05, 5e-2), (0.025, 2.5e-2)]),
        _row("holds", [], claimed=None, observed=None),  # an identity: not drawn
    ]
    fig = _grid_figure(monkeypatch, rows, {"demo.eq1": _LABELS})
    visible = [ax for ax in fig.get_axes() if ax.get_visible()]
    assert len(visible) == 2  # one panel per row with a claimed order
    colours = [to_rgba(ax.get_lines()[0].get_color()) for ax in visible]
    assert colours == [to_rgba("tab:green"), to_rgba("tab:red")]
    for ax in visible:
        assert ax.get_xlabel() == "p (rad)" and "formula|" in ax.get_ylabel()
        texts = [ax.title, ax.xaxis.label, ax.yaxis.label, *ax.get_xticklabels()]
        assert min(t.get_fontsize() for t in texts) >= 8
    assert fig.get_suptitle() == "Demo"
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    assert legend == [
        "|residual|, formula holds",
        "|residual|, formula fails",
        "claimed order (slope)",
    ]


def test_plot_studies_refuses_a_row_without_labels(tmp_path):
    rows = [_row("holds", [(0.1, 1e-2), (0.05, 2.5e-3), (0.025, 6.25e-4)])]
    with pytest.raises(ValueError, match=r"no panel labels for demo\.eq1"):
        plots.plot_studies(tmp_path / "x.png", rows, "Demo", {})


@pytest.mark.parametrize("paper", ["tisserand", "lecornu", "charbonnier"])
def test_every_drawn_formula_names_its_parameter_and_unit(paper, rows):
    """Each paper's panel labels cover exactly the rows its grid draws, none generic."""
    module = {"tisserand": fti, "lecornu": fle_figures, "charbonnier": fch}[paper]
    labels = module.panels() if paper == "charbonnier" else module.PANELS
    drawn = {r.id for r in rows[paper] if r.residuals and r.claimed_order is not None}
    assert set(labels) == drawn
    for label in labels.values():
        assert label.name and label.residual
        assert "see note" not in label.parameter
        # the parameter's symbol and its unit (or that it has none)
        assert any(u in label.parameter for u in ("rad", "dimensionless", "δ"))
    caption = module.CAPTIONS[f"formulas_{paper}"]
    assert "|reference − formula|" in caption and "Reference:" in caption


# ----------------------------------------------------------------------------- Lecornu
def _bessel_events(p: float):
    """Vertical passages and elongations of the linearised (3) from a vertical start, exactly.

    θ ∝ C1(z)/z with C_ν(z) = J1(z0)Y_ν(z) − Y1(z0)J_ν(z), z = (2/p)√(1 + pτ) (Lecornu's
    x = z²/4 and (9)); elongations are the zeros of C2, d(C1/z)/dz = −C2/z.
    """
    from scipy.optimize import brentq
    from scipy.special import jv, yv

    z0 = 2 / p

    def c(nu, dz):
        z = z0 + dz
        return jv(1, z0) * yv(nu, z) - yv(1, z0) * jv(nu, z)

    def tau(dz):
        return dz * (2 * z0 + dz) * p / 4

    out = {}
    for key, nu, lo, hi in (
        ("vertical2", 1, 2.6, 3.7),
        ("vertical3", 1, 5.8, 6.8),
        ("elong1", 2, 1.0, 2.1),
        ("elong2", 2, 4.2, 5.3),
    ):
        out[key] = tau(brentq(lambda d, nu=nu: c(nu, d), lo, hi, xtol=1e-15))
    return out


@pytest.mark.parametrize("j", range(len(fle.P_SWEEP)))
def test_lecornu_events_against_bessel_closed_form(j):
    ode = fle.event_times(engine.DEFAULT_INTEGRATOR)
    exact = _bessel_events(fle.P_SWEEP[j])
    for key, value in exact.items():
        assert ode[key][j] == pytest.approx(value, abs=engine.DEFAULT_INTEGRATOR.error_bound)


def _same_residuals(a, b, bound):
    assert [r.id for r in a] == [r.id for r in b]
    for ra, rb in zip(a, b, strict=True):
        for (pa, xa), (pb, xb) in zip(ra.residuals, rb.residuals, strict=True):
            assert pa == pb
            assert abs(xa - xb) <= bound, (ra.id, pa, xa, xb)


def test_lecornu_reference_second_tolerance():
    """DOP853 at rtol 1e-13 moves no residual by more than the stated error bound."""
    fle.event_times.cache_clear()
    _same_residuals(
        committed_formulas("lecornu"),  # the default integrator's, computed once per process
        fle.formula_checks(TIGHT),
        engine.DEFAULT_INTEGRATOR.error_bound,
    )


def test_lecornu_reference_second_method_radau():
    radau = engine.Integrator(method="Radau", rtol=1e-12, atol=1e-14)
    _same_residuals(fle3.finite_rows(), fle3.finite_rows(radau), 3 * radau.error_bound)


def test_lecornu_corrections_match_hand_derivation(rows):
    found = by_id(rows)
    assert "(3 + 21γ²t² − γ⁴t⁴)" in found["lecornu.eq29"].recomputed
    assert "(π³ − 3π)/32" in found["lecornu.mean_pendulum"].recomputed
    assert "(48 − π²)/64" in found["lecornu.eq42_terms_in_b"].recomputed
    # 64δ solved by hand from δ'' + δ = (3/4)u² sin u − (31/8)u cos u + ½ sin u
    # + ¼u² sin 3u − (9/8)u cos 3u + ½ sin 3u, δ(0) = δ'(0) = 0.
    assert (
        "(k³/64)(−8u³ cos u − 50u² sin u − 2u² sin 3u − 66u cos u + 6u cos 3u + 87 sin u "
        "− 9 sin 3u)" in found["lecornu.eq41_terms_in_p"].recomputed
    )
    assert "holds" in found["lecornu.eq41_terms_in_p"].note


def test_lecornu_delta_by_hand_satisfies_its_equation():
    """The hand value of 64δ solves the corrected equation (finite differences)."""
    u = np.linspace(0.1, 6.0, 2001)
    h = u[1] - u[0]

    def delta(x):
        s, c, s3, c3 = np.sin(x), np.cos(x), np.sin(3 * x), np.cos(3 * x)
        return (
            -8 * x**3 * c
            - 50 * x**2 * s
            - 2 * x**2 * s3
            - 66 * x * c
            + 6 * x * c3
            + 87 * s
            - 9 * s3
        ) / 64

    second = (delta(u + h) - 2 * delta(u) + delta(u - h)) / h**2
    rhs = (
        0.75 * u**2 * np.sin(u)
        - 31 / 8 * u * np.cos(u)
        + 0.5 * np.sin(u)
        + 0.25 * u**2 * np.sin(3 * u)
        - 9 / 8 * u * np.cos(3 * u)
        + 0.5 * np.sin(3 * u)
    )
    assert np.max(np.abs(second + delta(u) - rhs)) < 1e-3  # FD truncation ~1e-4 at u = 6
    assert abs(delta(np.array([0.0]))[0]) < 1e-15


# ----------------------------------------------------------------------------- Tisserand
@pytest.mark.parametrize("theta0", [0.4, 0.2, 1.0])
def test_tisserand_quadrature_against_spherical_pendulum_ode(theta0):
    """(4)-(5) by Fourier quadrature against solve_ivp on the spherical pendulum (k = 1)."""
    from scipy.integrate import solve_ivp

    theta1 = theta0 / 2
    u0, u1 = math.sin(theta0), math.sin(theta1)
    c0, c1 = math.cos(theta0), math.cos(theta1)
    h = math.sqrt(2 * (c1 - c0) * u0**2 * u1**2 / (u0**2 - u1**2))  # area constant

    def rhs2(t, y):
        th, om, _phi = y
        phidot = h / math.sin(th) ** 2
        return [om, math.sin(th) * math.cos(th) * phidot**2 - math.sin(th), phidot]

    def turn(t, y):
        return y[1]

    turn.direction = 1.0
    sol = solve_ivp(
        rhs2, (0, 20), [theta0, 0.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-15, events=turn
    )
    t_half, phi_half = sol.t_events[0][0], sol.y_events[0][0][2]
    assert sol.y_events[0][0][0] == pytest.approx(theta1, abs=1e-10)
    co = fti.series_coefficients(theta0, theta1, fti.QuadratureReference(nodes=128))
    assert co["a"][0] * PI / 2 == pytest.approx(t_half, rel=1e-11)
    assert PI / 2 + u0 * u1 * co["b"][0] * PI / 2 == pytest.approx(phi_half, rel=1e-11)


def test_tisserand_nodes_converged():
    coarse = fti.formula_checks(fti.QuadratureReference(nodes=64))
    fine = fti.formula_checks(fti.QuadratureReference(nodes=128))
    _same_residuals(coarse, fine, 1e-14)


def test_tisserand_sin4_coefficient_is_one_over_4096(rows):
    row = by_id(rows)["tisserand.II_sin4"]
    assert row.recomputed.endswith("1/4096")
    assert "With 35/4096 the residual is O(θ0^3.9" in row.note


# ----------------------------------------------------------------------------- Charbonnier
def test_charbonnier_damped_oscillator_closed_form():
    """Linear damping εθ': the half-swing ends at π/ω with θ = α exp(−επ/(2ω)) exactly."""
    p = cpt.check_pendulum()
    text, phi, scale = cpt.perturbations(p)["linear_damping"]
    eps = np.array(fch.DELTA_SWEEP) * scale
    ev, _ = cpt.measure(p, phi, eps, engine.DEFAULT_INTEGRATOR)
    omega = np.sqrt(p.k**2 - eps**2 / 4)
    np.testing.assert_allclose(ev["t_end"], PI / omega, rtol=0, atol=1e-10)
    np.testing.assert_allclose(
        ev["theta_end"], p.alpha * np.exp(-eps * PI / (2 * omega)), rtol=0, atol=1e-11
    )
    assert "linear" in text


def test_charbonnier_e_integrals_closed_form():
    """E_s, E_c of the monomial resistance by quadrature against B_n k^(n−1)(αl0)^n I_n."""
    from pendcli.papers.charbonnier.model import integral

    p = cpt.check_pendulum()
    for n in range(6):
        phi = lambda th, om, t, n=n: (p.l0 * om) ** n  # noqa: E731
        t = np.array([p.half / 3, p.half / 2, p.half])
        es, ec = cpt.e_integrals(p, phi, t)
        scale = p.k ** (n - 1) * (p.alpha * p.l0) ** n
        for j, x in enumerate(p.k * t):
            assert es[j] == pytest.approx(scale * integral(n, float(x)), rel=1e-13, abs=1e-15)
            assert ec[j] == pytest.approx(scale * math.sin(x) ** (n + 1) / (n + 1), abs=1e-13)


def test_charbonnier_reference_second_tolerance():
    _same_residuals(
        [*fch.general_rows(), *fch.monomial_rows()],
        [*fch.general_rows(TIGHT), *fch.monomial_rows(TIGHT)],
        engine.DEFAULT_INTEGRATOR.error_bound,
    )


def test_charbonnier_friction_count_exact_by_simulation():
    """The exact count rule against stepping the half-swings one by one."""
    g, alpha = cpt.check_pendulum().g, cpt.check_pendulum().alpha
    for p_nominal in (3.3, 7.9, 12.5):
        b0 = alpha * g / (2 * p_nominal)
        amp, count = alpha, 0
        while amp > b0 / g:  # the pendulum moves again from this extremity
            amp = amp - 2 * b0 / g
            count += 1
            if amp < 0:
                break
        assert count == max(0, math.ceil((alpha - b0 / g) / (2 * b0 / g)))


# ----------------------------------------------------------------------------- CLI
from helpers.cli import assert_clean_error, invoke  # noqa: E402

from pendcli.verify.claims import sharing_formula_rows  # noqa: E402


def test_cli_formulas_json_and_plot(tmp_path):
    import json

    # the rows as computed once per process (their computation is tested above: here, what
    # the command writes of them)
    with sharing_formula_rows("tisserand", list(committed_formulas("tisserand"))):
        code, out, err = invoke("formulas", "--paper", "tisserand", "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert {r["id"] for r in doc["formulas"]} == {k for k in EXPECTED if k.startswith("tiss")}
    # what the panels show is tested on the Axes above; here: the command writes the PNG of
    # its grid, drawn of two of the paper's rows (its ten panels cost 0.4 s more to draw)
    drawn = [r for r in committed_formulas("tisserand") if r.claimed_order is not None]
    with sharing_formula_rows("tisserand", drawn[:2]):
        code, out, err = invoke("formulas", "-p", "tisserand", "--plot", str(tmp_path / "figs"))
    assert code == 0, err
    png = (tmp_path / "figs" / "formulas_tisserand.png").read_bytes()
    assert png.startswith(b"\x89PNG")


def test_cli_formulas_bad_input(tmp_path):
    code, _, err = invoke("formulas", "--paper", "newton")
    assert_clean_error(code, err)
    target = tmp_path / "a_file.png"
    target.write_text("x")
    code, _, err = invoke("formulas", "-p", "tisserand", "--plot", str(target))
    assert_clean_error(code, err)
