"""Issue 6: work-precision measurements, the choice of a method, and `pendcli tradeoff`."""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from typer.testing import CliRunner

from pendcli import tradeoff
from pendcli.cli.main import app
from pendcli.core.errors import PendcliError

runner = CliRunner()


@pytest.fixture(scope="module")
def planar_points():
    return tradeoff.measure_family("planar_period", quick=True)


@pytest.fixture(scope="module")
def integral_points():
    return tradeoff.measure_family("integral_pi", quick=True)


def test_points_have_error_time_and_span_six_decades(planar_points, integral_points):
    for points in (planar_points, integral_points):
        errors = [p.error for p in points if p.error is not None]
        assert max(errors) / max(min(errors), 1e-17) >= 1e6
        for p in points:
            if p.error is not None:
                assert p.seconds > 0 and math.isfinite(p.seconds)


def test_errors_are_measured_against_an_independent_reference(planar_points):
    """Recompute one point's error here: series order 1 at 90° against mpmath's K."""
    from pendcli.numerics.planar import series_period_ratio

    with mpmath.workdps(50):
        worst = max(
            abs(series_period_ratio(a, 1) - exact) / exact
            for a in (20.0, 90.0)
            for exact in [
                2 * mpmath.ellipk(mpmath.sin(mpmath.mpf(a) * mpmath.pi / 360) ** 2) / mpmath.pi
            ]
        )
    (point,) = [p for p in planar_points if p.method == "series" and p.setting == "order=1"]
    assert point.error == pytest.approx(float(worst), rel=1e-6)


def test_naive_forms_fail_visibly(monkeypatch):
    """The printed products as floats overflow at n = 3000: the point records it, no number."""
    fam = tradeoff.FAMILIES["integral_pi"]
    monkeypatch.setitem(
        tradeoff.FAMILIES,
        "products_only",
        tradeoff.Family(
            "products_only",
            "products",
            [100, 3000],
            fam.reference,
            lambda quick: [tradeoff.Candidate("products", "floats", tradeoff._products)],
        ),
    )
    (point,) = tradeoff.measure_family("products_only", quick=True)
    assert point.error is None
    assert "OverflowError" in point.note
    with pytest.raises(PendcliError, match="out of reach"):
        tradeoff.choose("products_only", 1.0, [point])  # a failed point is never chosen


def test_choose_picks_cheapest_meeting_tol(planar_points):
    for tol in (1e-2, 1e-6, 1e-12):
        chosen = tradeoff.choose("planar_period", tol, planar_points)
        assert chosen.error <= tol
        cheaper = [
            p
            for p in planar_points
            if p.error is not None and p.error <= tol and p.seconds < chosen.seconds
        ]
        assert not cheaper
    with pytest.raises(PendcliError, match="out of reach"):
        tradeoff.choose("planar_period", 1e-30, planar_points)
    with pytest.raises(PendcliError):
        tradeoff.choose("planar_period", -1.0, planar_points)


def test_choose_method_reads_published_table(tmp_path, monkeypatch, planar_points):
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path))
    tradeoff.write_table(planar_points, tradeoff.table_path("planar_period"))
    back = tradeoff.read_table(tradeoff.table_path("planar_period"))
    assert [(p.method, p.setting) for p in back] == [(p.method, p.setting) for p in planar_points]
    assert (
        tradeoff.choose_method("planar_period", 1e-6)
        == tradeoff.choose("planar_period", 1e-6, planar_points).method
    )


def test_missing_module_family_is_skipped(monkeypatch):
    fake = tradeoff.Family(
        "ghost", "not yet", [1], lambda p: 1, lambda q: [], module="pendcli.no_such_module"
    )
    monkeypatch.setitem(tradeoff.FAMILIES, "ghost", fake)
    ready, skipped = tradeoff.available_families()
    assert "ghost" not in ready
    assert "not there yet" in skipped["ghost"]
    result = runner.invoke(app, ["tradeoff", "ghost"])
    assert result.exit_code != 0


def test_cli_json_rows_and_plot(tmp_path):
    plot = tmp_path / "wp.png"
    result = runner.invoke(
        app, ["tradeoff", "planar_period", "--quick", "--format", "json", "--plot", str(plot)]
    )
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["rows"]
    for row in doc["rows"]:
        assert {"family", "method", "setting", "seconds", "error", "evaluations"} <= set(row)
    assert plot.exists() and plot.stat().st_size > 1000


def test_cli_unknown_family_is_an_error():
    result = runner.invoke(app, ["tradeoff", "nope"])
    assert result.exit_code != 0


def test_charbonnier_integral_method_and_tol(tmp_path, monkeypatch):
    """--method forces a method; --tol picks one whose value is then within tol of mpmath."""
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path))
    points = tradeoff.measure_family("integral_x", quick=True)
    tradeoff.write_table(points, tradeoff.table_path("integral_x"))
    n, x = 50, 0.7
    with mpmath.workdps(50):
        ref = mpmath.quad(lambda t: mpmath.sin(t) ** (n + 1), [0, 0.35, 0.6, x])
    value, label = tradeoff.integral_with_choice(n, x, tol=1e-8)
    assert "cheapest" in label
    assert abs(value - float(ref)) / float(ref) <= 1e-8
    value, label = tradeoff.integral_with_choice(n, x, method="recurrence")
    assert "forced" in label
    result = runner.invoke(
        app, ["charbonnier", "integral", str(n), "--x", str(x), "--tol", "1e-8", "-f", "json"]
    )
    assert result.exit_code == 0, result.output
    row = json.loads(result.stdout)["integral"]
    assert "cheapest" in row["method"]
    result = runner.invoke(app, ["charbonnier", "integral", "5", "--method", "nope"])
    assert result.exit_code != 0


def test_conical_reference_is_independent_and_agrees_with_the_quadrature():
    """mpmath on the first integrals (tradeoff's reference) against Tisserand's (4)-(5)."""
    import math

    from pendcli.numerics.spherical import exact_conical
    from pendcli.tradeoff import _ref_conical

    for a, b in ((20.0, 10.0), (10.0, 2.0), (60.0, 1.0), (89.0, 45.0)):
        t0, t1 = math.radians(a), math.radians(b)
        k1, omega = _ref_conical((t0, t1))
        motion = exact_conical(t0, t1, method="quad")
        assert abs(motion.k1 - k1) <= 1e-14 * k1
        assert abs(motion.precession - omega) <= 1e-14 * omega
