"""Charbonnier's I_n: the printed table, I_n(x), the CLI rows and the figure.

Every expected value comes from a method the code does not use: mpmath's beta function and
quadrature at 40 digits, Wallis' binomial forms of I_n(π) in exact rationals, Bernoulli
numbers from mpmath, the log-gamma function of mpmath.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import mpmath
import numpy as np
import pytest
from helpers.evaluated import committed_claims, committed_formulas

from pendcli.base.errors import PendcliError
from pendcli.data.tables import load_paper_table
from pendcli.papers.charbonnier import claims, explore, figures, model

CLAIMS = load_paper_table("charbonnier").claims


def mp_integral(n: int, x: float) -> mpmath.mpf:
    """∫_0^x sin^(n+1) t dt at 40 digits: mpmath's incomplete beta for x <= π/2 (quadrature
    has an absolute tolerance, useless for tiny values), else quadrature split at kπ/2."""
    with mpmath.workdps(40):
        xm = mpmath.mpf(x)
        if xm <= mpmath.pi / 2:
            return (
                mpmath.betainc(mpmath.mpf(n + 2) / 2, mpmath.mpf(1) / 2, 0, mpmath.sin(xm) ** 2) / 2
            )
        points = [mpmath.mpf(0)]
        k = 1
        while k * mpmath.pi / 2 < xm:
            points.append(k * mpmath.pi / 2)
            k += 1
        points.append(xm)
        return mpmath.quad(lambda t: mpmath.sin(t) ** (n + 1), points)


def mp_beta_pi(n: int) -> mpmath.mpf:
    with mpmath.workdps(40):
        return mpmath.beta(mpmath.mpf(1) / 2, mpmath.mpf(n + 2) / 2)


def wallis(n: int) -> tuple[Fraction, int]:
    """I_n(π) = q·π^p from Wallis' binomial forms (not Charbonnier's recurrence or products):
    n = 2m: 2·4^m/((2m+1)·C(2m, m)); n = 2m - 1: π·C(2m, m)/4^m."""
    if n % 2 == 0:
        m = n // 2
        return Fraction(2 * 4**m, (2 * m + 1) * math.comb(2 * m, m)), 0
    m = (n + 1) // 2
    return Fraction(math.comb(2 * m, m), 4**m), 1


# ----------------------------------------------------------------------------- the claims


@pytest.mark.parametrize("claim", CLAIMS, ids=[c.id for c in CLAIMS])
def test_printed_entry_equals_independent_quadrature(claim):
    n = int(claim.id.rsplit(".n", 1)[1])
    reference = mp_integral(n, math.pi)
    assert float(abs(claim.number.value - reference) / reference) < 1e-15  # the print holds
    rows = {r.id: r for r in committed_claims("charbonnier")}
    assert rows[claim.id].verdict == "agrees"
    assert float(abs(rows[claim.id].recomputed - reference) / reference) < 3e-16


def test_recompute_covers_exactly_the_printed_claims_with_the_exact_value():
    recomputed = claims.recompute()
    assert set(recomputed) == {c.id for c in CLAIMS}
    # n = 3: 3π/8 (Wallis: π·C(4,2)/16 = 6π/16)
    assert recomputed["charbonnier.I_pi.n3"].note == "Exact value 3π/8."
    assert recomputed["charbonnier.I_pi.n4"].note == "Exact value 16/15."


# ----------------------------------------------------------------------------- I_n(π)


@pytest.mark.parametrize("n", [-1, 0, 1, 2, 7, 59, 199, 200, 201, 1837, 10**5, 10**12, 10**15])
def test_integral_pi_against_mpmath_beta(n):
    ref = mp_beta_pi(n)
    assert float(abs(model.integral_pi(n) - ref) / ref) < 1.2e-16  # half an ulp, at most


def ulps_from(value: float, reference: mpmath.mpf) -> float:
    with mpmath.workdps(50):
        return float(abs(mpmath.mpf(value) - reference) / math.ulp(float(reference)))


def wallis_50_digits(n: int) -> mpmath.mpf:
    """I_n(π) from Wallis' binomial forms, π and the division by mpmath at 50 digits."""
    q, p = wallis(n) if n >= 0 else (Fraction(1), 1)
    with mpmath.workdps(50):
        return mpmath.mpf(q.numerator) / q.denominator * (mpmath.pi if p else 1)


LOG_SAMPLE = sorted({int(v) for v in np.logspace(np.log10(3000), 15, 2000)})


def wallis_50_digits_below(n_end: int) -> list[mpmath.mpf]:
    """:func:`wallis_50_digits` of n = -1 .. n_end - 1, Wallis' forms with each central binomial
    C(2m, m) from the one before (C(2m + 2, m + 1) = C(2m, m)(2m + 1)(2m + 2)/(m + 1)², exact):
    math.comb afresh for each n was 60 % of the CPU of the test below."""
    out, central = [], 1  # C(0, 0)
    with mpmath.workdps(50):
        for n in range(-1, n_end):
            m = (n + 1) // 2
            if n > 0 and n % 2 == 1:  # n = 2m - 1 opens a new m
                central = central * (2 * m - 1) * (2 * m) // (m * m)
            if n == -1:
                value = +mpmath.pi
            elif n % 2 == 0:
                value = mpmath.mpf(2 * 4**m) / ((2 * m + 1) * central)
            else:
                value = mpmath.mpf(central) / 4**m * mpmath.pi
            out.append(value)
    return out


def test_the_stepped_wallis_values_are_wallis():
    values = wallis_50_digits_below(400)
    for n in [*range(-1, 40), 199, 200, 398, 399]:
        assert values[n + 1] == wallis_50_digits(n), n


def test_integral_pi_correctly_rounded_for_every_n_below_3000():
    """≤ 0.5 ulp (+1e-3 for the reference's own rounding) against the exact rationals."""
    bad = {}
    for n, reference in zip(range(-1, 3000), wallis_50_digits_below(3000), strict=True):
        err = ulps_from(model.integral_pi(n), reference)
        if err > 0.5 + 1e-3:
            bad[n] = err
    assert not bad, bad


def test_integral_pi_correctly_rounded_log_sample_to_1e15():
    """2,000 n log-spaced from 3000 to 10^15 against mpmath's beta function at 50 digits."""
    bad = {}
    for n in LOG_SAMPLE:
        err = ulps_from(model.integral_pi(n), mp_beta_pi(n))
        if err > 0.5 + 1e-3:
            bad[n] = err
    assert len(LOG_SAMPLE) > 1900 and not bad, bad


def test_integral_pi_array_equals_the_scalar_path():
    ns = np.array([-1, 0, 1, 5, 199, 200, 201, 1837, *LOG_SAMPLE[::20]], dtype=np.int64)
    values = model.integral_pi_array(ns)
    assert values.dtype == np.float64 and values.shape == ns.shape
    assert values.tolist() == [model.integral_pi(int(n)) for n in ns]
    square = model.integral_pi_array(ns[:6].reshape(2, 3))
    assert square.shape == (2, 3) and square.ravel().tolist() == values[:6].tolist()
    assert model.integral_pi_array(np.array([], dtype=int)).size == 0


@pytest.mark.parametrize(
    ("ns", "match"),
    [([1.5, 2.0], "integers"), ([True], "integers"), ([-2, 3], "n must be .*, got -2"),
     ([3, 10**16], "n must be .*, got 10000000000000000")],
)  # fmt: skip
def test_integral_pi_array_refuses_bad_input(ns, match):
    with pytest.raises(PendcliError, match=match) as err:
        model.integral_pi_array(np.array(ns))
    assert "\n" not in str(err.value)


def test_undecided_rounding_falls_back_to_mpmath(monkeypatch):
    """With Ziv's bound made huge every series value is undecided: mpmath then decides."""
    from pendcli.papers.charbonnier import wallis

    monkeypatch.setattr(wallis, "DD_BOUND", 1e-3)
    ns = [200, 1001, 1837, 10**9]
    values = [wallis.integral_pi(n) for n in ns]
    assert values == wallis.integral_pi_array(np.array(ns)).tolist()
    for n, v in zip(ns, values, strict=True):
        assert ulps_from(v, mp_beta_pi(n)) <= 0.5 + 1e-3


def test_double_double_series_far_below_its_bound():
    """The double-double value itself (before rounding) is within 2^-78, the bound is 2^-72."""
    from pendcli.papers.charbonnier import wallis

    ns = np.array([200, 201, 210, 300, 1837, 10**4, 10**7, 10**12, 10**15])
    hi, lo = wallis.series_dd((ns + 2) / 2.0, np.sqrt)
    for n, h, low in zip(ns, hi, lo, strict=True):
        with mpmath.workdps(50):
            ref = mp_beta_pi(int(n))
            assert abs((mpmath.mpf(h) + mpmath.mpf(low) - ref) / ref) < 2.0**-78
    assert wallis.DD_BOUND == 2.0**-72


def test_pi_bounds_enclose_mpmath_pi():
    from pendcli.papers.charbonnier import wallis

    lo, hi = wallis.pi_bounds()
    with mpmath.workdps(100):
        pi = mpmath.pi
        assert (
            mpmath.mpf(lo.numerator) / lo.denominator
            < pi
            < mpmath.mpf(hi.numerator) / hi.denominator
        )
    assert hi - lo < Fraction(1, 2**250)


def test_exact_rationals_equal_wallis():
    """The recurrence (cached and uncached) and the printed products against Wallis."""
    assert model.integral_pi_rational(-1) == (Fraction(1), 1)
    for n in range(0, 400):
        expected = wallis(n)
        assert model.integral_pi_rational(n) == expected, n
        assert model.integral_pi_exact(n) == expected, n
        assert model.printed_closed_form(n) == expected, n


def test_row_by_row_sequences_equal_the_restarting_forms():
    """One step per row gives what restarting from n = 0 gives, exactly (floats bit for bit)."""
    exact = list(model.integral_pi_sequence(400))
    closed = list(model.printed_closed_form_sequence(400))
    assert [n for n, _, _ in exact] == list(range(-1, 401))
    assert exact[0] == (-1, Fraction(1), 1)
    for (n, q, p), (m, num, den, cp) in zip(exact[1:], closed[1:], strict=True):
        assert n == m and (q, p) == wallis(n), n
        assert (Fraction(num, den), cp) == model.printed_closed_form(n), n
    for x in (math.pi, 0.7, 2.5, -1.0):
        seq = model.integral_recurrence_sequence(300, x)
        assert seq == [model.integral_recurrence(n, x) for n in range(-1, 301)]
    assert model.integral_recurrence_sequence(-1) == [math.pi]


def test_integral_pi_rational_is_uncached_and_exact_cached():
    model.integral_pi_exact.cache_clear()
    model.integral_pi_exact(301)
    model.integral_pi_exact(301)
    assert model.integral_pi_exact.cache_info().hits == 1
    assert not hasattr(model.integral_pi_rational, "cache_info")
    with pytest.raises(PendcliError, match="limited to n <= 100000"):
        model.integral_pi_rational(model.MAX_EXACT_N + 1)


def test_bernoulli_numbers_against_mpmath():
    ours = model.bernoulli(30)
    for k, value in enumerate(ours):
        p, q = mpmath.bernfrac(k)
        assert value == Fraction(int(p), int(q)), k


@pytest.mark.parametrize("m", [30.5, 100.0, 5000.0])
def test_log_gamma_ratio_series_against_mpmath_loggamma(m):
    """Σ c_k m^-k = log Γ(m+½) - log Γ(m) - ½ log m, within the first omitted term."""
    coeffs = model.log_gamma_ratio_coefficients()
    series = sum(c * m ** -(2 * i + 1) for i, c in enumerate(coeffs))
    with mpmath.workdps(50):
        mm = mpmath.mpf(m)
        exact = mpmath.loggamma(mm + 0.5) - mpmath.loggamma(mm) - mpmath.log(mm) / 2
    assert float(abs(series - exact)) <= 4e-16 * abs(float(exact)) + 1e-300
    assert coeffs[0] == pytest.approx(-1 / 8, rel=1e-15)  # Γ(m+½)/Γ(m) = √m (1 - 1/(8m) ...)


@pytest.fixture(scope="module")
def formula_rows():
    return committed_formulas("charbonnier")


def test_closed_form_formula_rows_hold(formula_rows):
    rows = {r.id: r for r in formula_rows}
    assert rows["charbonnier.I_pi.closed_form_even"].verdict == "holds"
    assert rows["charbonnier.I_pi.closed_form_odd"].verdict == "holds"


@pytest.mark.parametrize(
    ("q", "p", "text"),
    [(Fraction(1), 1, "π"), (Fraction(2), 0, "2"), (Fraction(1, 2), 1, "π/2"),
     (Fraction(3, 8), 1, "3π/8"), (Fraction(16, 15), 0, "16/15")],
)  # fmt: skip
def test_exact_text(q, p, text):
    assert model.exact_text(q, p) == text


# ----------------------------------------------------------------------------- I_n(x)


@pytest.mark.parametrize("n", [-1, 0, 1, 2, 3, 6, 11, 40])
@pytest.mark.parametrize(
    "x", [1e-3, 0.3, 1.0, math.pi / 2, 2.0, 3.0, math.pi - 1e-6, 5.0, 10.0, -2.5]
)
def test_integral_general_x_against_quadrature(n, x):
    ref = mp_integral(n, x) if x >= 0 else (-1) ** n * mp_integral(n, -x)
    got = model.integral(n, x)
    assert float(abs(got - ref)) <= 1e-13 * float(abs(ref)) + 1e-300


def test_recurrence_in_floating_point_is_exact_at_pi_but_not_at_small_x():
    for n in range(0, 30):
        assert model.integral_recurrence(n, math.pi) == pytest.approx(
            float(mp_beta_pi(n)), rel=1e-14
        )
    # At x = 0.01 the printed recurrence subtracts nearly equal terms: digits vanish.
    ref = mp_integral(12, 0.01)
    rel = abs(model.integral_recurrence(12, 0.01) - ref) / ref
    assert rel > 1e-3


@pytest.mark.parametrize(
    ("n", "x", "branch"),
    [(-1, 2.0, "I_(-1)(x) = x"), (0, 2.0, "I_0(x) = 2 sin²(x/2)"),
     (5, math.pi, "I_n(π): exact Wallis rational"), (199, math.pi, "exact Wallis rational"),
     (200, math.pi, "asymptotic series"),
     (5, 2.0, "incomplete beta"), (5, 10.0, "exact reduction to [0, π], then incomplete")],
)  # fmt: skip
def test_integral_method_names_the_branch(n, x, branch):
    assert branch in model.integral_method(n, x)


@pytest.mark.parametrize(
    ("n", "x"), [(-2, 1.0), (10**15 + 1, 1.0), (1.5, 1.0), (3, math.nan), (3, math.inf), (3, 2e6)]
)
def test_bad_inputs_raise_clear_errors(n, x):
    with pytest.raises(PendcliError) as err:
        model.integral(n, x)
    assert "range" in str(err.value) or "must be" in str(err.value)
    assert "\n" not in str(err.value)


# ----------------------------------------------------------------------------- CLI rows


def test_table_rows_against_independent_values():
    rows = explore.table_rows(8)
    assert [r["n"] for r in rows] == list(range(-1, 9))
    printed = {int(c.id.rsplit(".n", 1)[1]): c.published for c in CLAIMS}
    for r in rows:
        n = r["n"]
        q, p = wallis(n) if n >= 0 else (Fraction(1), 1)
        assert r["exact"] == model.exact_text(q, p)
        assert r["published"] == printed.get(n, "")
        assert r["closed_form_matches_recurrence"] is True
        ref = float(mp_beta_pi(n))
        assert r["beta"] == ref  # correctly rounded
        assert r["recurrence_float"] == pytest.approx(ref, rel=1e-14)


def test_table_rows_linear_form_against_wallis_at_large_n():
    rows = explore.table_rows(2500)
    assert [r["n"] for r in rows] == list(range(-1, 2501))
    for r in rows[1::97] + rows[-3:]:
        n = r["n"]
        assert r["exact"] == model.exact_text(*wallis(n))
        assert r["closed_form_matches_recurrence"] is True
        assert ulps_from(r["beta"], wallis_50_digits(n)) <= 0.5 + 1e-3
        assert r["recurrence_float"] == model.integral_recurrence(n, math.pi)


@pytest.mark.parametrize("wrong", ["numerator", "twos", "parity"])
def test_table_column_says_no_when_the_closed_form_differs(monkeypatch, wrong):
    """The cross-multiplied comparison can fail: one altered row of the products shows NO."""
    real = model.printed_closed_form_sequence

    def altered(n_max):
        for n, num, den, p in real(n_max):
            if n == 40:
                num, p = {"numerator": (num + 2, p), "twos": (2 * num, p), "parity": (num, 1)}[
                    wrong
                ]
            yield n, num, den, p

    monkeypatch.setattr(explore, "printed_closed_form_sequence", altered)
    flags = {r["n"]: r["closed_form_matches_recurrence"] for r in explore.table_rows(60)}
    assert [n for n, ok in flags.items() if not ok] == [40]


@pytest.mark.parametrize("n_max", [-2, 10_001, True, 2.0])
def test_table_rows_refuses_bad_n_max(n_max):
    with pytest.raises(PendcliError, match=r"n_max must be in \[-1, \d+\], got ") as err:
        explore.table_rows(n_max)
    assert "\n" not in str(err.value)


def test_integral_row_value_and_exact():
    row = explore.integral_row(5, math.pi)
    assert row["value"] == pytest.approx(float(mp_beta_pi(5)), rel=3e-16)
    assert row["exact"] == "5π/16"  # π·1·3·5/(2·4·6), Wallis: π·C(6,3)/64 = 20π/64
    row = explore.integral_row(5, 1.0)
    assert "exact" not in row
    assert row["value"] == pytest.approx(float(mp_integral(5, 1.0)), rel=1e-15)
    assert "exact" not in explore.integral_row(explore.TABLE_N_MAX + 1, math.pi)
    assert "exact" in explore.integral_row(explore.TABLE_N_MAX, math.pi)


# ----------------------------------------------------------------------------- the figure


@pytest.fixture(scope="module")
def table_axes():
    from matplotlib.figure import Figure

    ax = Figure().subplots()
    figures.draw_table(ax, n_max=60)
    return ax


def test_figure_curve_is_i_n_pi(table_axes):
    curve, _points, _asymptote = table_axes.get_lines()
    xs, ys = curve.get_xdata(), curve.get_ydata()
    assert list(xs) == [n + 2 for n in range(-1, 61)]
    for x, y in zip(xs, ys, strict=True):
        assert y == pytest.approx(float(mp_beta_pi(int(x) - 2)), rel=1e-15)


def test_figure_marks_every_printed_entry(table_axes):
    _curve, points, _asymptote = table_axes.get_lines()
    xs, ys = points.get_xdata(), points.get_ydata()
    assert sorted(int(x) - 2 for x in xs) == list(range(-1, 6))  # n = -1..5, as printed
    for x, y in zip(xs, ys, strict=True):
        assert y == pytest.approx(float(mp_beta_pi(int(x) - 2)), rel=1e-15)
    assert "printed" in points.get_label()


def test_figure_asymptote_approaches_from_below(table_axes):
    """√(2π/(n+2)) undershoots I_n(π) by 1/(4(n+2)) + O(n^-2) (Γ(m+½)/Γ(m) ~ √m(1 - 1/(8m)))."""
    _curve, _points, asymptote = table_axes.get_lines()
    for x, y in zip(asymptote.get_xdata(), asymptote.get_ydata(), strict=True):
        if x >= 10:
            gap = 1 - y / float(mp_beta_pi(int(x) - 2))
            assert 0 < gap < 1.1 / (4 * x)


def test_figure_axes_and_labels(table_axes):
    assert table_axes.get_xscale() == "log" and table_axes.get_yscale() == "log"
    assert table_axes.get_xlabel() == "n + 2"
    assert "Iₙ(π)" in table_axes.get_ylabel() and "_" not in table_axes.get_ylabel()
    assert [t.get_text() for t in table_axes.get_legend().get_texts()] == [
        "recomputed Iₙ(π)",
        "printed (Charbonnier 1908, no. 15)",
        "asymptote √(2π/(n+2))",
    ]


def test_report_figure_shows_the_red_printed_marks(tmp_path):
    """The written PNG: red pixels (the printed marks) and blue ones (the curve)."""
    import matplotlib.image

    (path,) = figures.figures(tmp_path)
    assert path.name == "charbonnier-In-pi.png"
    rgb = matplotlib.image.imread(path)[..., :3]

    def near(color: tuple[int, int, int]) -> int:
        return int(np.sum(np.all(np.abs(rgb - np.array(color) / 255) < 0.08, axis=-1)))

    assert near((214, 39, 40)) > 150  # tab:red circles: 7 marks + the legend's (~40 px each)
    assert near((31, 119, 180)) > 200  # tab:blue curve


def test_formulas_figure_colours_each_panel_by_its_verdict(tmp_path, formula_rows):
    """One panel per δ-sweep row, green if it holds, red if not: the share of red pixels
    follows the share of failing rows (two: (9) with E_c, on two perturbations)."""
    import matplotlib.image

    from pendcli.papers.charbonnier import formulas

    (path,) = formulas.figures(tmp_path, formula_rows)
    rgb = matplotlib.image.imread(path)[..., :3]

    def near(color: tuple[int, int, int]) -> int:
        return int(np.sum(np.all(np.abs(rgb - np.array(color) / 255) < 0.08, axis=-1)))

    drawn = [r for r in formula_rows if r.claimed_order is not None and r.residuals]
    failing = sum(r.verdict != "holds" for r in drawn)
    assert failing == 2  # eq9.linear_damping, eq9.periodic_force
    red, green = near((214, 39, 40)), near((44, 160, 44))
    share = red / (red + green)
    assert 0.5 * failing / len(drawn) < share < 2 * failing / len(drawn)


# ----------------------------------------------------------------------------- the checks' pendulum


def test_check_pendulum_is_read_from_the_table():
    from pendcli.papers.charbonnier.perturbation import check_pendulum

    table = load_paper_table("charbonnier")
    p = check_pendulum()
    for name in ("g", "l0", "alpha"):
        (constant,) = [c for c in table.constants if c.name == name]
        assert constant.source.startswith("assumption")  # Charbonnier prints none of them
        assert getattr(p, name) == constant.value
    assert p.k == pytest.approx(math.sqrt(9.81 / 1.5), rel=1e-15)
    assert p.half * p.k == pytest.approx(math.pi, rel=1e-15)


# ----------------------------------------------------------------------------- the CLI's domains


def _run_cli(*args: str) -> tuple[int, str, str, float]:
    """`pendcli ARGS` in a fresh process: (code, stdout, stderr, CPU seconds of the child).

    CPU, not wall time, so a loaded machine cannot fail the test.
    """
    import resource

    from helpers.cli import run_cli

    def children_cpu() -> float:
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        return usage.ru_utime + usage.ru_stime

    start = children_cpu()
    done = run_cli(*args)
    return done.returncode, done.stdout, done.stderr, children_cpu() - start


def _invoked(*args: str) -> tuple[int, str, str, float]:
    """`pendcli ARGS` in this process: (code, stdout, stderr, CPU seconds of the call)."""
    import time

    from helpers.cli import invoke

    start = time.process_time()
    code, out, err = invoke(*args)
    return code, out, err, time.process_time() - start


# One refusal through the real entry point in a process of its own (its exit code and the
# child's CPU); the other domains' refusals are the same code path, run in-process.
@pytest.mark.parametrize(
    ("args", "valid", "in_a_process"),
    [(("300", "--method", "products"), "[-1, 299]", False),
     (("1000000000000", "--method", "products"), "[-1, 299]", False),
     (("100000", "--method", "quad"), "[-1, 3e+04]", False),
     (("1000000000000000000", "--method", "pendcli"), "[-1, 1e+15]", True)],
)  # fmt: skip
def test_methods_refuse_inputs_outside_their_measured_domain(args, valid, in_a_process):
    run = _run_cli if in_a_process else _invoked
    code, out, err, seconds = run("charbonnier", "integral", *args)
    assert code == 2 and not out, err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    assert err.startswith("pendcli: error: ") and valid in err
    assert "measured" in err or "1e+15" in err
    assert seconds < 20  # refused before any computation (once: never ended)


@pytest.mark.parametrize(
    ("args", "warned"),
    [(("100", "-x", "0.5", "--method", "recurrence"), "not even the sign"),
     (("10", "-x", "0.1", "--method", "recurrence"), "estimated relative error"),
     (("1000000000000", "--method", "gammaln"), "gammaln(m) - gammaln(m+½) cancels"),
     (("0", "--method", "asymptotic"), "truncated too early"),
     (("100", "-x", "2.0", "--method", "recurrence"), None),
     (("300", "--method", "gammaln"), None)],
)  # fmt: skip
def test_unstable_methods_warn_on_stderr_and_still_answer(args, warned):
    from helpers.cli import invoke

    code, out, err = invoke("charbonnier", "integral", *args, "-f", "json")
    assert code == 0 and "Traceback" not in err
    row = json.loads(out)["integral"]
    if warned is None:
        assert not err and "warning" not in row
        return
    assert err.startswith("pendcli: warning: method ") and warned in err
    assert len(err.strip().splitlines()) == 1 and row["warning"] in err


def test_recurrence_warning_is_right_about_the_value():
    """The warned value really is wrong: I_100(0.5) > 0, the recurrence returns < 0 there."""
    from pendcli.papers.charbonnier.speed import integral_by_method_checked

    value, warning = integral_by_method_checked(100, 0.5, "recurrence")
    assert mp_integral(100, 0.5) > 0 and value < 0 and warning is not None


def test_short_option_x_is_accepted():
    """`charbonnier integral 3 -x 1` was refused as an unexpected extra argument."""
    from helpers.cli import invoke

    code, out, err = invoke("charbonnier", "integral", "3", "-x", "1", "-f", "json")
    assert code == 0, err
    row = json.loads(out)["integral"]
    assert row["x"] == 1.0 and row["value"] == pytest.approx(float(mp_integral(3, 1.0)), rel=1e-15)
    code, out, err = invoke("charbonnier", "integral", "-1", "-x", "-2", "-f", "json")
    assert code == 0 and json.loads(out)["integral"]["value"] == -2.0, err
