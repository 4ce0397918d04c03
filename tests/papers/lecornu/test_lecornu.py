"""Lecornu's claims: engine verdicts, confirmed by recomputations that share no code with it.

Every printed number is recomputed a second time here by another method: zeros by mpmath's
findroot on J_ν at 30 digits (the package uses besseljzero and McMahon), the speeds from the
elongation condition d(J_1(z)/z)/dz = 0 (the package uses J_2 = 0), and every time, length
and deviation of the example by integrating eq. (3) with solve_ivp from the values of
solution (10) at l = 1,3 m (the package uses the Bessel zeros and the identity
2J_1/z = J_0). The expected verdict of every claim is asserted, disagreements included.
"""

from __future__ import annotations

import json
import math
import shutil
from dataclasses import replace
from fractions import Fraction
from pathlib import Path

import mpmath
import numpy as np
import pytest
from helpers.cli import invoke
from helpers.evaluated import committed_claims

from pendcli.data.tables import load_paper_table, tables_dir
from pendcli.data.vocabulary import Verdict
from pendcli.papers.lecornu import claims, explore, figures, model
from pendcli.verify.verdict import judge

TABLE = load_paper_table("lecornu")
CLAIMS = {c.id: c for c in TABLE.claims}
G = TABLE.constant("g")
B = TABLE.constant("speed")
L = TABLE.constant("length")

EXPECTED = {
    "lecornu.j2_zeros.count_below_20": "agrees",
    "lecornu.j2_zeros.1": "agrees",
    "lecornu.j2_zeros.2": "truncated",
    "lecornu.j2_zeros.3": "agrees",
    "lecornu.j2_zeros.4": "agrees",
    "lecornu.j2_zeros.5": "agrees",
    **{f"lecornu.speed.{k}": "agrees" for k in range(1, 6)},
    "lecornu.coefficient_b2_4g": "last-digit",
    **{f"lecornu.example.length.{k}": "agrees" for k in range(1, 6)},
    "lecornu.example.time.1": "agrees",
    "lecornu.example.time.2": "discrepant",
    "lecornu.example.time.3": "last-digit",
    "lecornu.example.time.4": "agrees",
    "lecornu.example.time.5": "last-digit",
    "lecornu.example.time_zero_length": "agrees",
    "lecornu.example.interval.1": "discrepant",
    "lecornu.example.interval.2": "discrepant",
    "lecornu.example.interval.3": "agrees",
    "lecornu.example.interval.4": "agrees",
    "lecornu.example.interval.5": "truncated",
    "lecornu.j0_at_j2_zeros.1": "discrepant",
    "lecornu.j0_at_j2_zeros.2": "discrepant",
    "lecornu.j0_at_j2_zeros.3": "agrees",
    "lecornu.j0_at_j2_zeros.4": "truncated",
    "lecornu.j0_at_j2_zeros.5": "agrees",
    **{f"lecornu.deviation.{k}": "discrepant" for k in range(2, 6)},
    "lecornu.deviation.zero_length": "discrepant",
    "lecornu.limit_2j1_over_z": "agrees",
    "lecornu.j1_zeros.1": "truncated",
    "lecornu.j1_zeros.2": "agrees",
    "lecornu.j1_zeros.3": "agrees",
    "lecornu.j1_zeros.4": "agrees",
    "lecornu.j1_zeros.5": "truncated",
    "lecornu.j1_zeros.6": "agrees",
    "lecornu.j1_lengths.1": "last-digit",
    **{f"lecornu.j1_lengths.{k}": "agrees" for k in range(2, 6)},
    "lecornu.j1_lengths.6": "truncated",
    "lecornu.x_bound": "last-digit",
    "lecornu.half_oscillation_coefficient": "agrees",
    "lecornu.mean_pendulum_coefficient": "discrepant",
    "lecornu.k4.theta20": "agrees",
    "lecornu.k4.theta20_below_one_thousandth": "agrees",
    "lecornu.k4.swing180": "agrees",
}

ODE_RTOL = 1e-8  # what the solve_ivp reference (rtol 1e-12) guarantees for event times
MP_RTOL = 1e-12


# --- the independent references ----------------------------------------------------------


def mp_zero(order: int, s: int) -> mpmath.mpf:
    """j_(order,s) by findroot on besselj from McMahon's first term (30 digits)."""
    with mpmath.workdps(30):
        beta = (s + order / 2 - mpmath.mpf(1) / 4) * mpmath.pi
        return mpmath.findroot(
            lambda x: mpmath.besselj(order, x), beta - (4 * order**2 - 1) / (8 * beta)
        )


def mp_elongation_z(s: int) -> mpmath.mpf:
    """The s-th elongation of solution (10), θ ∝ J_1(z)/z: a zero of its derivative in z."""
    with mpmath.workdps(30):
        guess = (s + mpmath.mpf(3) / 4) * mpmath.pi
        guess -= mpmath.mpf(15) / (8 * guess)
        return mpmath.findroot(lambda z: mpmath.diff(lambda u: mpmath.besselj(1, u) / u, z), guess)


def shortening_rhs(t: float, y: np.ndarray, b: float = B, g: float = G) -> list[float]:
    """Eq. (3) linear, l = L - bt: (L - bt)θ'' - 2bθ' + gθ = 0."""
    return [y[1], (2 * b * y[1] - g * y[0]) / (L - b * t)]


def solution_10_by_ode(l_start: float = 1.3, l_floor: float = 0.02):
    """solve_ivp on eq. (3) from the values of solution (10), θ ∝ J_1(z)/z, at l_start
    (mpmath at 30 digits, derivative numerical): no Bessel zero and no identity used."""
    from scipy.integrate import solve_ivp

    t0, t1 = (L - l_start) / B, (L - l_floor) / B
    with mpmath.workdps(30):

        def theta(t):
            z = 2 * mpmath.sqrt(G * (L - B * t)) / B
            return mpmath.besselj(1, z) / z

        y0 = [float(theta(t0)), float(mpmath.diff(theta, t0))]
    sol = solve_ivp(
        shortening_rhs,
        (t0, t1),
        y0,
        method="DOP853",
        rtol=1e-12,
        atol=1e-14 * abs(y0[0]),
        events=(lambda t, y: y[1], lambda t, y: y[0]),
        dense_output=True,
    )
    assert sol.status == 0
    return sol


def from_rest_by_ode(l_floor: float = 0.05):
    """solve_ivp on eq. (3) from θ = 1, θ' = 0 at t = 0 (l = 1 m): the release from rest."""
    from scipy.integrate import solve_ivp

    sol = solve_ivp(
        shortening_rhs,
        (0.0, (L - l_floor) / B),
        [1.0, 0.0],
        method="DOP853",
        rtol=1e-12,
        atol=1e-14,
        dense_output=True,
    )
    assert sol.status == 0
    return sol


def _example_references() -> dict[str, tuple[float, float]]:
    """Lengths, times, intervals, deviations, J_1 lengths: events of the ODE of solution (10)."""
    sol = solution_10_by_ode()
    te = sol.t_events[0]  # elongations, l from 1,007 m down
    theta_e = sol.y_events[0][:, 0]
    tp = sol.t_events[1]  # vertical passages, l from 1,21 m down
    assert len(te) == 5 and len(tp) == 6
    zero_length = float(Fraction(L) / Fraction(B))  # l = L - bt = 0
    intervals = np.diff(np.append(te, zero_length))
    out: dict[str, tuple[float, float]] = {
        "lecornu.example.time_zero_length": (zero_length, MP_RTOL)
    }
    for k in range(5):
        out[f"lecornu.example.length.{k + 1}"] = (L - B * te[k], ODE_RTOL)
        out[f"lecornu.example.time.{k + 1}"] = (te[k], ODE_RTOL)
        out[f"lecornu.example.interval.{k + 1}"] = (intervals[k], ODE_RTOL)
    for k in range(1, 5):
        out[f"lecornu.deviation.{k + 1}"] = (theta_e[k] / theta_e[0], 1e-7)
    for k in range(6):
        out[f"lecornu.j1_lengths.{k + 1}"] = (L - B * tp[k], ODE_RTOL)
    return out


def _bessel_references() -> dict[str, tuple[float, float]]:
    """Zeros, speeds, J_0, the limits and the bound: mpmath at 30 digits."""
    out: dict[str, tuple[float, float]] = {}
    with mpmath.workdps(30):
        out["lecornu.j2_zeros.count_below_20"] = (
            float(sum(1 for s in range(1, 10) if mp_zero(2, s) < 20)),
            0.0,
        )
        for k in range(1, 6):
            out[f"lecornu.j2_zeros.{k}"] = (float(mp_zero(2, k)), MP_RTOL)
            speed = 2 * mpmath.sqrt(mpmath.mpf(G) * L) / mp_elongation_z(k)
            out[f"lecornu.speed.{k}"] = (float(speed), 1e-10)
            out[f"lecornu.j0_at_j2_zeros.{k}"] = (float(mpmath.besselj(0, mp_zero(2, k))), 1e-10)
        for k in range(1, 7):
            out[f"lecornu.j1_zeros.{k}"] = (float(mp_zero(1, 7 - k)), MP_RTOL)
        limit = mpmath.limit(lambda z: 2 * mpmath.besselj(1, z) / z, 0)
        out["lecornu.limit_2j1_over_z"] = (float(limit), MP_RTOL)
        # θ/θ0 at zero length: J_1(z)/z as z → 0 over its value at the first elongation
        ze = mp_elongation_z(5)
        tiny = mpmath.mpf("1e-12")
        ratio = (mpmath.besselj(1, tiny) / tiny) / (mpmath.besselj(1, ze) / ze)
        out["lecornu.deviation.zero_length"] = (float(ratio), 1e-10)
        # the smallest nonzero zero of φ(x) = √x J_1(2√x)
        x1 = mpmath.findroot(lambda x: mpmath.sqrt(x) * mpmath.besselj(1, 2 * mpmath.sqrt(x)), 3.6)
        out["lecornu.x_bound"] = (float(x1), MP_RTOL)
        # these two rows recompute the printed expressions (their exact column is tested below)
        pi = mpmath.pi
        out["lecornu.half_oscillation_coefficient"] = (float((pi**2 - 12) / 16), MP_RTOL)
        out["lecornu.mean_pendulum_coefficient"] = (float(pi * (7 * pi**2 - 3) / 32), MP_RTOL)
        k4_20 = float(mpmath.sin(mpmath.pi / 18) ** 4)  # k = sin(θ0/2), θ0 = 20°
    out["lecornu.k4.theta20"] = (k4_20, MP_RTOL)
    out["lecornu.k4.theta20_below_one_thousandth"] = (k4_20, MP_RTOL)
    out["lecornu.k4.swing180"] = (0.25, MP_RTOL)  # sin⁴(45°) = (1/√2)⁴
    # b²/(4g) in exact rationals of the table's decimals
    coefficient = Fraction(str(B)) ** 2 / (4 * Fraction(str(G)))
    out["lecornu.coefficient_b2_4g"] = (float(coefficient), MP_RTOL)
    return out


@pytest.fixture(scope="module")
def references() -> dict[str, tuple[float, float]]:
    return {**_bessel_references(), **_example_references()}


@pytest.fixture(scope="module")
def rows():
    return {r.id: r for r in committed_claims("lecornu")}


# --- every claim --------------------------------------------------------------------------


def test_every_claim_has_an_expected_verdict_and_a_reference(references):
    assert set(EXPECTED) == set(CLAIMS)
    assert set(references) == set(CLAIMS)


@pytest.mark.parametrize("cid", list(CLAIMS))
def test_claim(rows, references, cid):
    row = rows[cid]
    ref, rtol = references[cid]
    assert row.recomputed == pytest.approx(ref, rel=rtol, abs=1e-14)
    assert row.verdict == EXPECTED[cid]
    # the independent value lands on the same side of the printed precision
    assert judge(CLAIMS[cid].number, ref, CLAIMS[cid].comparison).verdict.value == EXPECTED[cid]


def test_exact_half_oscillation_coefficient_is_the_printed_formula(rows):
    # Lecornu's (π² - 12)/16 is right: the exact solution extrapolated to b → 0 gives it.
    assert rows["lecornu.half_oscillation_coefficient"].exact == pytest.approx(
        (math.pi**2 - 12) / 16, abs=1e-6
    )


def test_exact_mean_pendulum_coefficient_is_not_the_printed_formula(rows):
    exact = rows["lecornu.mean_pendulum_coefficient"].exact
    # π√((a + bt/2)/g) expanded by hand has π³/32 in the b² term: the difference is π(π²-3)/32
    assert exact == pytest.approx(math.pi * (math.pi**2 - 3) / 32, abs=1e-5)
    assert judge(CLAIMS["lecornu.mean_pendulum_coefficient"].number, exact).verdict.value == (
        "discrepant"
    )


def test_period_b2_coefficient_3pi_over_32_holds():
    assert model.period_b2_coefficient_exact() == pytest.approx(3 * math.pi / 32, abs=1e-5)


def test_extrapolation_to_b_zero_uses_the_given_ps():
    # any three small p give the same limit (the old Richardson step assumed p, p/2, p/4)
    half = (math.pi**2 - 12) / 16
    assert model.half_oscillation_coefficient_exact((0.003, 0.0015, 0.001)) == pytest.approx(
        half, abs=1e-6
    )
    assert model.period_b2_coefficient_exact((0.005, 0.003, 0.001)) == pytest.approx(
        3 * math.pi / 32, abs=1e-5
    )


def test_time_slip_is_not_explained_by_his_own_lengths():
    # (1 - 0,68)/0,35 from his own printed numbers: 0,91, not 0,94
    own = (L - CLAIMS["lecornu.example.length.2"].number.value) / B
    assert judge(CLAIMS["lecornu.example.time.2"].number, own).verdict.value == "discrepant"
    # ... while the printed interval 0,72 is 1,66 - 0,94 (the slip propagated)
    t2 = CLAIMS["lecornu.example.time.2"].number.value
    t3 = CLAIMS["lecornu.example.time.3"].number.value
    assert judge(CLAIMS["lecornu.example.interval.2"].number, t3 - t2).verdict.value == "agrees"


def test_coefficient_needs_g_at_most_9_80():
    number = CLAIMS["lecornu.coefficient_b2_4g"].number
    assert judge(number, B * B / (4 * 9.80)).verdict.value == "agrees"
    assert judge(number, B * B / (4 * 9.8005)).verdict.value != "agrees"


def test_notes_use_the_printed_intermediates(rows):
    # the author's procedure, from his printed (rounded) values: 0,00313·8,41² and 3,83²/4,
    # written with the memoir's decimal comma as the table's notes beside them
    assert "0,2214" in rows["lecornu.example.length.4"].note  # 0,00313 × 8,41²
    assert f"{3.83**2 / 4:.5f}".replace(".", ",") in rows["lecornu.x_bound"].note
    assert "g <= 9,800" in rows["lecornu.coefficient_b2_4g"].note


# --- the numbers come from the table, not from the code -----------------------------------


@pytest.fixture
def edited_tables(tmp_path, monkeypatch):
    """A copy of the tables whose edits the code must follow (PENDCLI_TABLES)."""

    def edit(old: str, new: str) -> Path:
        root = tmp_path / "tables"
        if not root.exists():
            shutil.copytree(tables_dir(), root)
        path = root / "published" / "lecornu.toml"
        text = path.read_text(encoding="utf-8")
        assert text.count(old) == 1
        path.write_text(text.replace(old, new), encoding="utf-8")
        monkeypatch.setenv("PENDCLI_TABLES", str(root))
        return root

    return edit


def test_g_and_printed_intermediates_are_read_from_the_table(edited_tables):
    edited_tables("[paper.constants.g]\nvalue = 9.81", "[paper.constants.g]\nvalue = 9.8")
    edited_tables('published = "3,83"', 'published = "3,85"')
    out = claims.recompute()
    assert out["lecornu.coefficient_b2_4g"].value == pytest.approx(B * B / (4 * 9.8), rel=1e-15)
    assert "3,85²/4" in out["lecornu.x_bound"].note


def test_cli_defaults_come_from_the_table(edited_tables):
    edited_tables("[paper.constants.speed]\nvalue = 0.35", "[paper.constants.speed]\nvalue = 0.42")
    result = invoke("lecornu", "example", "--format", "json")
    assert result.code == 0, result.out
    summary = {r["quantity"]: r["value"] for r in json.loads(result.out)["summary"]}
    assert summary["b²/(4g), eq. (16)"] == pytest.approx(0.42**2 / (4 * G), rel=1e-15)


# --- the example against direct integration of eq. (3) -----------------------------------


def test_elongation_times_bessel_against_ode():
    bessel = model.elongation_times(B, L, G, "bessel", floor_fraction=0.02)
    ode = model.elongation_times(B, L, G, "ode", rtol=1e-11, floor_fraction=0.02)
    assert len(bessel) == len(ode) == 5
    np.testing.assert_allclose(ode, bessel, rtol=0, atol=1e-8)


def test_from_rest_amplitudes_against_ode():
    m = model.from_rest_model(B, L, G, floor_fraction=0.02)
    run = model.integrate_shortening(B, L, G, 1e-4, rtol=1e-11, floor_fraction=0.02)
    np.testing.assert_allclose(
        run.elongation_angles / run.elongation_angles[0], m.amplitude_ratios, rtol=1e-7
    )
    # vertical passages, too
    np.testing.assert_allclose(run.passage_times, m.passage_times, atol=1e-8)


def test_at_lecornus_speed_the_release_is_solution_10():
    b5 = 2 * math.sqrt(G) / float(mp_zero(2, 5))
    rest = model.from_rest_model(b5, L, G, floor_fraction=0.02)
    particular = model.example_model(b5, L, G)
    assert abs(rest.singular_weight) < 1e-12
    np.testing.assert_allclose(rest.elongation_times, particular.elongation_times, atol=1e-9)
    np.testing.assert_allclose(rest.amplitude_ratios, particular.amplitude_ratios, rtol=1e-8)


def test_small_angle_cost():
    rows = explore.ode_check(B, L, G, (1.0, 5.0), floor_fraction=0.02)
    assert all(abs(r["linear_minus_bessel_s"]) < 1e-8 for r in rows)
    shifts1 = np.array([r["sin_shift_1deg_s"] for r in rows[1:]])
    shifts5 = np.array([r["sin_shift_5deg_s"] for r in rows[1:]])
    assert np.all(shifts1 > 0) and np.all(shifts1 < 5e-4)  # sin θ < θ: later elongations
    assert np.all(shifts5 < 1e-2)
    # the shift is a finite-amplitude effect ∝ θ0²: 5° costs 25 times 1°
    np.testing.assert_allclose(shifts5 / shifts1, 25.0, rtol=0.06)


def test_exact_solution_constants_against_mpmath_roots():
    """The double-precision roots behind -0,13, 3π/32 and 6,47 against mpmath at 30 digits."""
    for p in (0.004, 0.001):
        with mpmath.workdps(30):
            z0 = 2 / mpmath.mpf(p)
            j1, y1 = mpmath.besselj(1, z0), mpmath.bessely(1, z0)
            ze = mpmath.findroot(
                lambda z, j1=j1, y1=y1: mpmath.besselj(2, z) * y1 - mpmath.bessely(2, z) * j1,
                z0 + mpmath.pi / 2,
            )
            z1 = mpmath.findroot(
                lambda z, j1=j1, y1=y1: mpmath.besselj(1, z) * y1 - mpmath.bessely(1, z) * j1,
                z0 + mpmath.pi,
            )
            ref = (p * (ze**2 - z0**2) / 4, p * (z1**2 - z0**2) / 4)
        got = model.lengthening_from_vertical(p)
        assert abs(got[0] - float(ref[0])) < 1e-12
        assert abs(got[1] - float(ref[1])) < 1e-12


# --- g ------------------------------------------------------------------------------------


def test_g_sensitivity_derivative_is_analytic():
    rows = {r["id"]: r for r in explore.g_sensitivity(gs=(9.80, 9.81))}
    speed = 2 * math.sqrt(G) / float(mp_zero(2, 5))
    assert rows["lecornu.speed.5"]["d_value_dg"] == pytest.approx(speed / (2 * G), rel=1e-6)
    coef = B * B / (4 * G)
    assert rows["lecornu.coefficient_b2_4g"]["d_value_dg"] == pytest.approx(-coef / G, rel=1e-6)
    assert rows["lecornu.coefficient_b2_4g"]["verdict g=9.8000"] == "agrees"


def test_best_g_is_consistent_with_the_verdicts(rows):
    best = explore.best_g(lo=9.78, hi=9.84, step=0.002)
    ids = explore.g_dependent_ids()
    agreeing = best[f"agreeing_at_{G:g}"]
    assert agreeing == sum(rows[i].verdict == "agrees" for i in ids)
    assert best["most_agreeing"] >= agreeing
    assert 9.78 <= best["best_g_least_squares"] <= 9.84


# --- CLI ------------------------------------------------------------------------------------


def _lecornu(*args):
    return invoke("lecornu", *args)


def test_cli_claims_json():
    result = _lecornu("claims", "--format", "json")
    assert result.code == 0, result.out
    doc = json.loads(result.out)
    assert doc["g"] == G
    assert {r["id"]: r["verdict"] for r in doc["claims"]} == EXPECTED


# --- figures: what is drawn ---------------------------------------------------------------


@pytest.fixture
def axes():
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    yield ax
    plt.close(fig)


def _line(ax, label: str):
    found = [line for line in ax.lines if line.get_label() == label]
    assert len(found) == 1, [line.get_label() for line in ax.lines]
    return found[0]


def test_example_figure_curves_are_the_solutions_of_eq_3(axes, rows):
    m = model.example_model()
    figures.draw_example_claims(axes, m, rows)
    sol10, rest = solution_10_by_ode(), from_rest_by_ode()
    g = f"{G:g}".replace(".", ",")  # the paper's decimal comma, in every label
    curve = _line(axes, f"solution (10), b = 0,35 m/s, g = {g} m/s²")
    t, y = curve.get_xdata(), curve.get_ydata()
    keep = (L - B * t) >= 0.02
    theta = sol10.sol(t[keep])[0] / sol10.y_events[0][0, 0]  # θ0 at the first elongation
    np.testing.assert_allclose(y[keep], theta, rtol=0, atol=1e-7 * np.max(np.abs(theta)))
    curve = _line(axes, "released from rest at 1 m (exact column)")
    t, y = curve.get_xdata(), curve.get_ydata()
    assert np.all(np.isnan(y[t < 0]))
    keep = (t >= 0) & ((L - B * t) >= 0.05)
    theta = rest.sol(t[keep])[0]
    np.testing.assert_allclose(y[keep], theta, rtol=0, atol=1e-7 * np.max(np.abs(theta)))


def test_example_figure_draws_the_printed_points(axes, rows):
    figures.draw_example_claims(axes, model.example_model(), rows)
    printed = _line(axes, "elongations, printed")
    times = [CLAIMS[f"lecornu.example.time.{k}"].number.value for k in range(1, 6)]
    deviations = [1.0] + [CLAIMS[f"lecornu.deviation.{k}"].number.value for k in range(2, 6)]
    assert list(printed.get_xdata()) == times
    assert list(printed.get_ydata()) == deviations
    passages = _line(axes, "vertical passages from printed lengths")
    lengths = np.array([CLAIMS[f"lecornu.j1_lengths.{k}"].number.value for k in range(1, 7)])
    np.testing.assert_allclose(passages.get_xdata(), (L - lengths) / B)
    # asinh: smooth through ±1, where symlog's corner drew kinks into the curves
    assert axes.get_yscale() == "asinh"
    assert axes.get_ylabel() == "θ/θ0 (asinh scale)"
    # the from-rest curve (to -1e4 as L -> 0) is clipped, and the axis says so
    assert -100 < axes.get_ylim()[0] < -47
    assert any("clipped" in t.get_text() for t in axes.texts)
    assert "1 m long at t = 0, shortening at 0,35 m/s" in axes.get_xlabel()


def test_difference_figure_bars(axes, rows, references):
    from matplotlib.colors import to_rgba

    figures.draw_printed_minus_recomputed(axes, rows, G)
    ids = [cid for _, group in figures.GROUPS for cid in group]
    bars = [bar for container in axes.containers for bar in container]
    assert len(bars) == len(ids)
    colours = {"agrees": "C2", "truncated": "C1", "last-digit": "C1", "discrepant": "C3"}
    for bar, cid in zip(bars, ids, strict=True):
        number = CLAIMS[cid].number
        expected = (number.value - references[cid][0]) / number.resolution
        assert bar.get_height() == pytest.approx(expected, abs=1e-5), cid
        assert bar.get_facecolor() == to_rgba(colours[EXPECTED[cid]]), cid
    labels = [t.get_text() for t in axes.get_xticklabels()]
    assert labels == [f"{CLAIMS[c].number.value:.{CLAIMS[c].number.decimals}f}" for c in ids]
    assert f"(g = {G:g})" in axes.get_title()


def _png_pixels(path: Path) -> np.ndarray:
    from matplotlib.image import imread

    return imread(path)


def _share_of(pixels: np.ndarray, colour: str, tol: float = 0.08) -> float:
    from matplotlib.colors import to_rgb

    rgb = np.array(to_rgb(colour), dtype=pixels.dtype)  # float32 as read: not widened
    return float(np.mean(np.all(np.abs(pixels[..., :3] - rgb) < tol, axis=-1)))


def test_figures_written(tmp_path, monkeypatch):
    """Without rows given, the figures judge Lecornu's claims themselves (evaluate_paper with
    his recomputation and procedures: the rows it returns are the shared committed ones, not a
    second computation of them) and draw them."""
    from pendcli.verify import claims as claims_engine

    judged = list(committed_claims("lecornu"))  # before the patch: they are computed by it
    asked = []

    def evaluated(key, recompute, procedures):
        asked.append((key, recompute, sorted(procedures)))
        return judged

    monkeypatch.setattr(claims_engine, "evaluate_paper", evaluated)
    paths = figures.figures(tmp_path)
    assert asked == [("lecornu", claims.recompute, sorted(claims.author_procedures()))]
    assert [p.name for p in paths] == [
        "lecornu_example_theta.png",
        "lecornu_printed_minus_recomputed.png",
    ]
    theta, bars = (_png_pixels(p) for p in paths)
    assert theta.shape[:2] == (576, 960)  # 8 × 4.8 in at 120 dpi
    assert _share_of(theta, "C3") > 1e-4  # the printed crosses (red)
    assert _share_of(theta, "0.3") > 1e-3  # the solution (10) curve
    assert _share_of(bars, "C2") > 1e-3  # agreeing bars (green)
    assert _share_of(bars, "C3") > 1e-3  # discrepant bars (red)


def test_figures_draw_the_claim_rows_given(tmp_path, monkeypatch):
    """The report's judged rows are drawn as given (not judged again): every row made to
    agree, no bar is red. (The example's curves, read by test_figures_written, are not drawn.)"""
    monkeypatch.setattr(figures, "draw_example_claims", lambda *_: None)
    rows = [replace(r, verdict=Verdict.AGREES) for r in committed_claims("lecornu")]
    _theta, bars = (_png_pixels(p) for p in figures.figures(tmp_path, rows))
    assert _share_of(bars, "C2") > 1e-2  # every bar green
    assert _share_of(bars, "C3") < 1e-3  # only the legend's patch red (the judged rows: 0.027)


def test_cli_example_csv_and_plot(tmp_path):
    plot = tmp_path / "ex.png"
    result = _lecornu(
        "example", "--speed", "0.5", "--length", "2", "--format", "csv", "--plot", str(plot)
    )
    assert result.code == 0, result.out
    # several tables in one CSV: the first column names the table of each row
    assert result.out.splitlines()[0].startswith("table,k,z,length_m,time_s")
    pixels = _png_pixels(plot)
    assert pixels.shape[:2] == (576, 960)
    assert _share_of(pixels, "0.3") > 1e-3  # solution (10) drawn
    assert _share_of(pixels, "C0") > 1e-4  # elongations and passages marked


def test_example_plot_curve_for_other_inputs(axes):
    # speed 0.5 m/s from 2 m at g = 9.8: the drawn solution (10) against mpmath's J_1
    m = model.example_model(0.5, 2.0, 9.8)
    figures.draw_example(axes, m)
    curve = _line(axes, "solution (10)")
    t, y = curve.get_xdata()[::97], curve.get_ydata()[::97]
    with mpmath.workdps(30):
        ze = mp_elongation_z(len(m.elongation_z))
        theta0 = mpmath.besselj(1, ze) / ze

        def theta(time):
            z = 2 * mpmath.sqrt(mpmath.mpf(9.8) * (2.0 - 0.5 * time)) / 0.5
            return float(mpmath.besselj(1, z) / z / theta0)

        expected = np.array([theta(float(ti)) for ti in t])
    np.testing.assert_allclose(y, expected, rtol=0, atol=1e-10 * np.max(np.abs(expected)))
    assert axes.get_xlabel() == "t (s), L = 2 m at t = 0, shortening at 0,5 m/s, g = 9,8 m/s²"


def test_difference_figure_draws_every_discrepant_claim(rows):
    """The printed-minus-recomputed bars include every discrepant claim (the deviations off
    by up to ~40 units too: the axis is symmetric-log beyond ±1)."""
    drawn = {cid for _, ids in figures.GROUPS for cid in ids}
    discrepant = {cid for cid, r in rows.items() if r.verdict == "discrepant"}
    assert discrepant <= drawn, sorted(discrepant - drawn)
