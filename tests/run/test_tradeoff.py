"""Work-precision measurements, the choice of a method, and `pendcli tradeoff`.

The engine (:mod:`pendcli.run.tradeoff_engine`) is generic, the catalogue
(:mod:`pendcli.run.tradeoff`) collects every paper's families; the families are each paper's
(``pendcli.papers.<paper>.speed``).  References are checked here against other methods
(mpmath quadrature, exact rationals, the defining equation of a zero), never against
themselves.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import matplotlib
import mpmath
import pytest
from helpers.cli import invoke

from pendcli.base.errors import PendcliError
from pendcli.papers.charbonnier import speed as charbonnier_speed
from pendcli.papers.lecornu import speed as lecornu_speed
from pendcli.papers.tisserand import speed as tisserand_speed
from pendcli.run import tradeoff, tradeoff_engine

matplotlib.use("Agg")


@pytest.fixture(scope="module")
def planar_points():
    return tradeoff.measure_family("planar_period", quick=True)


@pytest.fixture(scope="module")
def integral_points():
    return tradeoff.measure_family("integral_pi", quick=True)


# ---------------------------------------------------------------------------------------------
# The families the papers declare


def test_families_are_collected_from_every_paper_in_order():
    declared = [
        fam.name
        for module in (tisserand_speed, lecornu_speed, charbonnier_speed)
        for fam in module.FAMILIES
    ]
    assert tradeoff.family_names() == declared
    assert set(declared) == {
        "conical",
        "planar_period",
        "bessel_zeros",
        "lecornu_elongations",
        "integral_pi",
        "integral_x",
        "charbonnier_loss",
    }
    assert tradeoff.FAMILIES is tradeoff.families()  # one mapping, built once
    for name in declared:  # every family has its published table
        assert tradeoff_engine.table_path(name).exists()


def test_unknown_family_names_the_valid_ones():
    with pytest.raises(PendcliError, match=r"family must be one of conical.*, got 'nope'"):
        tradeoff.family("nope")


def test_lecornu_problem_comes_from_the_table():
    """Lecornu's example as printed (II after (15)): 0,35 m/s from 1 m; g = 9.81 assumed."""
    (problem,) = tradeoff.family("lecornu_elongations").problems
    assert problem == (0.35, 1.0, 9.81)
    assert tradeoff.family("planar_period").problems == [20.0, 90.0]  # III after (38)


# ---------------------------------------------------------------------------------------------
# The references are right (other methods)


@pytest.mark.parametrize("n", [-1, 0, 3, 10, 101])
def test_integral_pi_reference_is_the_wallis_product(n):
    """B(½, (n+2)/2) against the exact product (n-ones)/(n-evens) built here in rationals."""
    q = Fraction(1)
    for k in range(n, 0, -2):
        q *= Fraction(k, k + 1)
    with mpmath.workdps(50):
        exact = mpmath.mpf(q.numerator) / q.denominator * (mpmath.pi if n % 2 else 2)
        assert abs(charbonnier_speed.reference_integral_pi(n) - exact) < mpmath.mpf(10) ** -45


@pytest.mark.parametrize(("n", "x"), [(10, 0.5), (100, 0.3), (1000, 1.4), (100, 2.5), (3, 3.0)])
def test_integral_x_reference_against_the_incomplete_beta(n, x):
    """The hand-written positive series against mpmath.betainc: I = ½ B(sin²x; (n+2)/2, ½)."""
    with mpmath.workdps(50):
        a, half = mpmath.mpf(n + 2) / 2, mpmath.mpf(1) / 2
        part = mpmath.betainc(a, half, 0, mpmath.sin(mpmath.mpf(x)) ** 2) / 2
        expected = part if 2 * x <= math.pi else mpmath.beta(a, half) - part
        ref = charbonnier_speed.reference_integral_x((n, x))
        assert abs(ref - expected) <= mpmath.mpf(10) ** -40 * abs(expected)


@pytest.mark.parametrize("amplitude", [1.0, 20.0, 90.0, 179.0])
def test_period_reference_against_quadrature(amplitude):
    """(2/π)∫_0^(π/2) dφ/√(1 - k² sin²φ), k = sin(θ0/2), by mpmath quadrature."""
    with mpmath.workdps(40):
        k2 = mpmath.sin(mpmath.radians(amplitude) / 2) ** 2
        quad = (
            2
            / mpmath.pi
            * mpmath.quad(
                lambda p: 1 / mpmath.sqrt(1 - k2 * mpmath.sin(p) ** 2), [0, mpmath.pi / 2]
            )
        )
        ref = lecornu_speed.reference_period_ratio(amplitude)
        assert abs(ref - quad) <= mpmath.mpf(10) ** -30


@pytest.mark.parametrize(("order", "s"), [(1, 1), (2, 1), (1, 6), (2, 6)])
def test_bessel_reference_is_a_zero(order, s):
    """J_ν vanishes there and changes sign; McMahon's estimate puts it at index s."""
    z = lecornu_speed.reference_bessel_zero((order, s))
    with mpmath.workdps(50):
        assert abs(mpmath.besselj(order, z)) < mpmath.mpf(10) ** -45
        d = mpmath.mpf(10) ** -20
        assert mpmath.besselj(order, z - d) * mpmath.besselj(order, z + d) < 0
    mcmahon = (s + order / 2 - 0.25) * math.pi
    assert abs(float(z) - mcmahon) < 0.5


def test_conical_reference_is_independent_and_agrees_with_the_quadrature():
    """mpmath on the first integrals against Tisserand's (4)-(5) in pendcli.numerics."""
    from pendcli.numerics.spherical import exact_conical

    for a, b in ((20.0, 10.0), (10.0, 2.0), (60.0, 1.0), (89.0, 45.0)):
        t0, t1 = math.radians(a), math.radians(b)
        k1, omega = tisserand_speed.reference_conical((t0, t1))
        motion = exact_conical(t0, t1, method="quad")
        assert abs(motion.k1 - k1) <= 1e-14 * k1
        assert abs(motion.precession - omega) <= 1e-14 * omega


def test_lecornu_reference_agrees_with_the_ode():
    """The Bessel-function elongation times against solve_ivp on eq. (3) at rtol 1e-12."""
    problem = lecornu_speed.example_problem()
    from pendcli.papers.lecornu.model import elongation_times

    exact = lecornu_speed.reference_elongations(problem)
    ode = [float(t) for t in elongation_times(*problem, method="ode", rtol=1e-12)]
    n = min(len(exact), len(ode))
    assert n >= 5
    assert ode[:n] == pytest.approx(exact[:n], rel=1e-8)


# ---------------------------------------------------------------------------------------------
# Measuring and choosing


def test_relative_error_and_timing():
    assert tradeoff_engine.relative_error(1.5, 1) == 0.5
    assert tradeoff_engine.relative_error(1e-300, 0) == 1e-300  # absolute when the reference is 0
    calls = []
    seconds = tradeoff_engine.time_per_call(lambda: calls.append(1), quick=True)
    assert 0 < seconds < 1e-3 and len(calls) >= 2  # warm-up, then a batch


def test_points_have_error_time_and_span_six_decades(planar_points, integral_points):
    for points in (planar_points, integral_points):
        errors = [p.error for p in points if p.error is not None]
        assert max(errors) / max(min(errors), 1e-17) >= 1e6
        for p in points:
            if p.error is not None:
                assert p.seconds > 0 and math.isfinite(p.seconds)


def test_errors_are_measured_against_an_independent_reference(planar_points):
    """Recompute one point's error here: series order 1 is (1 + k²/4); quadrature for T."""
    worst = 0.0
    with mpmath.workdps(40):
        for a in (20.0, 90.0):
            k2 = mpmath.sin(mpmath.radians(a) / 2) ** 2
            exact = (
                2
                / mpmath.pi
                * mpmath.quad(
                    lambda p, k2=k2: 1 / mpmath.sqrt(1 - k2 * mpmath.sin(p) ** 2),
                    [0, mpmath.pi / 2],
                )
            )
            series = 1 + float(k2) / 4
            worst = max(worst, float(abs(series - exact) / exact))
    (point,) = [p for p in planar_points if p.method == "series" and p.setting == "order=1"]
    assert point.error == pytest.approx(worst, rel=1e-6)


def test_naive_forms_fail_visibly(monkeypatch):
    """The printed products as floats overflow at n = 3000: the point records it, no number."""
    fam = tradeoff.family("integral_pi")
    monkeypatch.setitem(
        tradeoff.FAMILIES,
        "products_only",
        tradeoff_engine.Family(
            "products_only",
            "products",
            [100, 3000],
            fam.reference,
            lambda quick: [
                tradeoff_engine.Candidate("products", "floats", charbonnier_speed.printed_products)
            ],
        ),
    )
    (point,) = tradeoff.measure_family("products_only", quick=True)
    assert point.error is None
    assert math.isnan(point.seconds)
    assert "OverflowError" in point.note
    with pytest.raises(PendcliError, match="out of reach"):
        tradeoff_engine.choose("products_only", 1.0, [point])  # a failed point is never chosen


def test_choose_picks_cheapest_meeting_tol(planar_points):
    for tol in (1e-2, 1e-6, 1e-12):
        chosen = tradeoff_engine.choose("planar_period", tol, planar_points)
        assert chosen.error <= tol
        cheaper = [
            p
            for p in planar_points
            if p.error is not None and p.error <= tol and p.seconds < chosen.seconds
        ]
        assert not cheaper
    with pytest.raises(PendcliError, match="out of reach"):
        tradeoff_engine.choose("planar_period", 1e-30, planar_points)
    with pytest.raises(PendcliError):
        tradeoff_engine.choose("planar_period", -1.0, planar_points)


def test_choose_on_hand_made_points():
    points = [
        tradeoff_engine.Point("f", "slow-exact", "", 1e-3, 1e-16),
        tradeoff_engine.Point("f", "fast-rough", "", 1e-6, 1e-4),
        tradeoff_engine.Point("f", "middle", "", 1e-5, 1e-9),
        tradeoff_engine.Point("f", "broken", "", math.nan, None, note="fails"),
    ]
    assert tradeoff_engine.choose("f", 1e-3, points).method == "fast-rough"
    assert tradeoff_engine.choose("f", 1e-8, points).method == "middle"
    assert tradeoff_engine.choose("f", 1e-15, points).method == "slow-exact"


def test_choose_method_reads_published_table(tmp_path, monkeypatch, planar_points):
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path))
    tradeoff_engine.write_table(planar_points, tradeoff_engine.table_path("planar_period"))
    back = tradeoff_engine.read_points(tradeoff_engine.table_path("planar_period"))
    assert [(p.method, p.setting) for p in back] == [(p.method, p.setting) for p in planar_points]
    for a, b in zip(back, planar_points, strict=True):  # three significant digits kept
        assert (a.error is None) == (b.error is None)
        if b.error is not None:
            assert a.error == pytest.approx(b.error, rel=5e-3, abs=1e-300)
    assert (
        tradeoff_engine.choose(
            "planar_period", 1e-6, tradeoff_engine.measured_points(tradeoff.family("planar_period"))
        ).method
        == tradeoff_engine.choose("planar_period", 1e-6, planar_points).method
    )


# ---------------------------------------------------------------------------------------------
# The work-precision diagram


def _hand_points():
    return [
        tradeoff_engine.Point("a", "m1", "s=1", 1e-6, 1e-3),
        tradeoff_engine.Point("a", "m1", "s=2", 1e-5, 1e-9),
        tradeoff_engine.Point("a", "m2", "", 1e-4, 0.0),  # exact: drawn on the bottom edge
        tradeoff_engine.Point("a", "m3", "", math.nan, None, note="fails"),  # not drawn
        tradeoff_engine.Point("a", "m5", "n=1", 3e-6, 1e-2),
        tradeoff_engine.Point("a", "m5", "n=2", 4e-6, 1e37),  # diverges: drawn on the top edge
        tradeoff_engine.Point("b", "m4", "", 2e-6, 1e-12),
    ]


def test_draw_family_shows_one_line_per_method_within_the_error_range():
    import matplotlib.pyplot as plt

    low, high = tradeoff.ERROR_RANGE
    fig, ax = plt.subplots()
    try:
        tradeoff.draw_family(ax, "a", _hand_points())
        lines = {line.get_label(): line for line in ax.get_lines() if line.get_label()[0] != "_"}
        assert set(lines) == {"m1", "m2", "m5"}
        assert list(lines["m1"].get_xdata()) == [1e-6, 1e-5]
        assert list(lines["m1"].get_ydata()) == [1e-3, 1e-9]
        # off-scale errors sit on the range's edges, with ▼ / ▲ markers there, not dots
        assert list(lines["m2"].get_ydata()) == [low]
        assert list(lines["m5"].get_ydata()) == [1e-2, high]
        assert list(lines["m5"].get_markevery()) == [0]
        edges = {
            line.get_marker(): line for line in ax.get_lines() if "off scale" in line.get_label()
        }
        assert list(edges["^"].get_ydata()) == [high] and list(edges["^"].get_xdata()) == [4e-6]
        assert edges["^"].get_color() == lines["m5"].get_color()
        assert list(edges["v"].get_ydata()) == [low]
        # the axis stays readable: the diverging 1e37 does not stretch it
        bottom, top = ax.get_ylim()
        assert low / 10 < bottom < low and high < top < high * 10
        assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
        assert ax.get_title() == "a"  # not a declared family: its name
        assert ax.get_xlabel() == "seconds per evaluation"
        assert ax.get_ylabel() == "worst relative error"
        legend = ax.get_legend()
        assert [t.get_text() for t in legend.get_texts()] == [
            "m1",
            "m2",
            "m5",
            "error > 1, off scale",
            "error < 1e-17, off scale",
        ]
        # the legend sits right of the panel, over no data
        fig.canvas.draw()
        box, panel = legend.get_window_extent(), ax.get_window_extent()
        assert box.x0 >= panel.x1
    finally:
        plt.close(fig)


def test_draw_family_titles_a_declared_family_by_its_title():
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    try:
        points = [tradeoff_engine.Point("integral_pi", "m", "", 1e-6, 1e-10)]
        tradeoff.draw_family(ax, "integral_pi", points)
        title = ax.get_title()
        declared = tradeoff.family("integral_pi").title  # I_n(π), the subscript set: Iₙ(π)
        assert title.replace("\n", " ") == declared.replace("I_n(π)", "Iₙ(π)")
        assert "Iₙ(π)" in title and all(len(line) <= 56 for line in title.split("\n"))
    finally:
        plt.close(fig)


def test_plot_tradeoff_draws_one_panel_per_family(tmp_path, monkeypatch):
    """Two families side by side, each panel with its family's lines."""
    import matplotlib.pyplot as plt

    from pendcli.base import plotting

    kept = []
    monkeypatch.setattr(plotting, "save_figure", lambda fig, path: kept.append(fig))
    monkeypatch.setattr(plt, "close", lambda fig: None)
    tradeoff.plot_tradeoff(_hand_points(), tmp_path / "wp.png")
    (fig,) = kept
    left, right = fig.get_axes()
    assert (left.get_title(), right.get_title()) == ("a", "b")
    assert [line.get_label() for line in right.get_lines() if line.get_label()[0] != "_"] == ["m4"]
    assert fig.get_size_inches()[0] > 2 * fig.get_size_inches()[1]  # two panels wide
    plt.close(fig)


def test_caption_names_the_error_range():
    assert "[1e-17, 1]" in tradeoff.CAPTION and "▲" in tradeoff.CAPTION


# ---------------------------------------------------------------------------------------------
# The CLI


def test_cli_json_rows_and_plot(tmp_path):
    plot = tmp_path / "wp.png"
    result = invoke("tradeoff", "planar_period", "--quick", "--format", "json", "--plot", str(plot))
    assert result.code == 0, result.out
    doc = json.loads(result.out)
    assert doc["rows"] and doc["skipped"] == {}
    for row in doc["rows"]:
        assert {"family", "method", "setting", "seconds", "error", "evaluations"} <= set(row)
        assert row["family"] == "planar_period"
    methods = {r["method"] for r in doc["rows"]}
    assert {"agm", "series", "quad", "agm-fixed"} <= methods
    assert plot.exists()


def test_cli_write_tables(tmp_path):
    result = invoke(
        "tradeoff", "bessel_zeros", "--quick", "-f", "csv", "--write-tables", str(tmp_path)
    )
    assert result.code == 0, result.out
    back = tradeoff_engine.read_points(tmp_path / "bessel_zeros.csv")
    assert {p.method for p in back} >= {"mpmath", "scipy", "mcmahon"}


def test_cli_unknown_family_is_an_error():
    result = invoke("tradeoff", "nope")
    assert result.code != 0


def test_charbonnier_integral_method_and_tol(tmp_path, monkeypatch):
    """--method forces a method; --tol picks one whose value is then within tol of mpmath."""
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path))
    points = tradeoff.measure_family("integral_x", quick=True)
    tradeoff_engine.write_table(points, tradeoff_engine.table_path("integral_x"))
    n, x = 50, 0.7
    with mpmath.workdps(50):
        ref = mpmath.quad(lambda t: mpmath.sin(t) ** (n + 1), [0, 0.35, 0.6, x])
    value, label = charbonnier_speed.integral_with_choice(n, x, tol=1e-8)
    assert "cheapest" in label
    assert abs(value - float(ref)) / float(ref) <= 1e-8
    value, label = charbonnier_speed.integral_with_choice(n, x, method="recurrence")
    assert "forced" in label
    result = invoke("charbonnier", "integral", str(n), "--x", str(x), "--tol", "1e-8", "-f", "json")
    assert result.code == 0, result.out
    row = json.loads(result.out)["integral"]
    assert "cheapest" in row["method"]
    result = invoke("charbonnier", "integral", "5", "--method", "nope")
    assert result.code != 0


@pytest.mark.parametrize("method", charbonnier_speed.INTEGRAL_METHODS)
def test_every_integral_method_at_pi(method):
    """Each --method at (n, x) = (20, π) against the exact Wallis product 2·(20!!)/(21!!)."""
    q = Fraction(2)
    for k in range(20, 0, -2):
        q *= Fraction(k, k + 1)
    value = charbonnier_speed.integral_by_method(20, math.pi, method)
    tol = {"asymptotic": 1e-12, "quad": 1e-9}.get(method, 4e-16)
    assert abs(value - float(q)) <= tol * float(q)


def test_pi_only_methods_refuse_other_x():
    with pytest.raises(PendcliError, match="computes I_n"):
        charbonnier_speed.integral_by_method(5, 1.0, "products")
    with pytest.raises(PendcliError, match=r"must be one of .*, got 'nope'"):
        charbonnier_speed.integral_by_method(5, 1.0, "nope")


def test_bench_growth_runs_each_size_alone_and_stops_at_the_time_limit():
    from tools import bench_scaling

    wall, peak = bench_scaling.run_sized(["--version"])
    assert float(wall) > 0 and float(peak) > 1  # MB: a Python interpreter at least
    wall, peak = bench_scaling.run_sized(
        ["lecornu", "zeros", "--count", "10000000", "-f", "json"], 0.05
    )
    assert wall == "> 0 (stopped)" and peak == "n/a"
    labels = [label for label, _ in bench_scaling.growth_cases(quick=False)]
    assert "lecornu zeros --count 1e+07 -f csv" in labels
    assert "charbonnier table --n-max 10000 -f json" in labels


def test_bench_peers_give_the_same_answers():
    from tools import bench_scaling

    rows = bench_scaling.peer_ratios(quick=True)
    assert [r["what"].split()[0] for r in rows] == ["zeros", "I_n(π)", "conical", "planar"]
    for row in rows:  # the comparison is fair only if both compute the same numbers
        assert float(row["largest relative difference"]) < 1e-8, row
        assert row["speed-up"].endswith("x")
