"""The stability summary is generated from measurements made at run time.

The helpers (:mod:`pendcli.run.stability`) are checked against values worked out by hand; the
rows are each paper's (``pendcli.papers.<paper>.stability``), collected in paper order.
"""

from __future__ import annotations

import math
import re

import pytest

from pendcli.base.errors import PendcliError
from pendcli.papers import registry
from pendcli.papers.charbonnier import stability as charbonnier_stability
from pendcli.papers.lecornu import stability as lecornu_stability
from pendcli.papers.registry import PAPERS
from pendcli.papers.tisserand import stability as tisserand_stability
from pendcli.run import stability

# each paper's own module, named here, so the collected rows are checked against them
STABILITY_MODULES = {
    "tisserand": tisserand_stability,
    "lecornu": lecornu_stability,
    "charbonnier": charbonnier_stability,
}

pytestmark = pytest.mark.extremes

KEYS = {"family", "method", "accurate_range", "fails_beyond", "measured"}
PAPER_FAMILIES = {
    "tisserand": {"exact conical pendulum"},
    "lecornu": {"planar period T/T0", "zeros of J1, J2"},
    "charbonnier": {"I_n = ∫ sin^(n+1)", "Charbonnier Δα, b_n v^n"},
}


@pytest.fixture(scope="module")
def paper_rows() -> dict[str, list[dict[str, str]]]:
    """Each paper's own module's rows, measured once for this file (0.1-0.2 s a paper)."""
    return {key: module.stability_rows() for key, module in STABILITY_MODULES.items()}


@pytest.fixture(scope="module")
def rows(paper_rows):
    """The registry's collection, its papers' functions answering with the rows measured
    above (a copy each): what is checked of it is that it collects them, in paper order."""
    with pytest.MonkeyPatch.context() as patch:
        for key, module in STABILITY_MODULES.items():
            patch.setattr(module, "stability_rows", lambda key=key: list(paper_rows[key]))
        return registry.stability_rows()


# ---------------------------------------------------------------------------------------------
# The helpers


def test_ulps_counts_units_in_the_last_place():
    assert stability.ulps(1.0, 1) == 0.0
    assert stability.ulps(1.0 + 2**-52, 1) == 1.0  # the next double after 1
    assert stability.ulps(1.0 + 3 * 2**-52, 1) == 3.0
    assert stability.ulps(0.75, 0.5) == 2.0**51  # |0.25| / ulp(0.5) = 2^-2 / 2^-53
    assert stability.ulps(math.inf, 1) == math.inf
    assert stability.ulps(1.0, 0) == math.inf


def test_rel_and_short():
    assert stability.rel(1.5, 2) == 0.25
    assert stability.rel(None, 2) == math.inf
    assert stability.rel(math.nan, 2) == math.inf
    text = "word " * 30 + "; detail"
    cut = stability.short(PendcliError(text), limit=22)
    assert cut == "word word word word …"
    assert stability.short(ValueError("short; and more")) == "short"


def test_worst_skips_underflow_and_counts_failures_as_infinite():
    def fn(n):
        if n == 3:
            raise OverflowError("too big")
        return 1.0 + n * 2**-52

    points = [(0,), (1,), (2,)]
    assert stability.worst(points, fn, lambda n: 1) == (2.0, (2,))
    assert stability.worst([*points, (3,)], fn, lambda n: 1) == (math.inf, (3,))
    # a reference below 1e-290 says nothing about ulps: skipped
    assert stability.worst([(0,), (5,)], fn, lambda n: 1e-300 if n == 5 else 1) == (0.0, (0,))


def test_row_keys_in_order():
    assert list(stability.row("f", "m", "a", "b", "c")) == list(stability.KEYS)


# ---------------------------------------------------------------------------------------------
# The rows


def test_rows_have_keys_and_text(rows):
    assert rows
    for row in rows:
        assert set(row) >= KEYS
        assert all(isinstance(row[k], str) and row[k] for k in KEYS)


def test_rows_come_from_each_paper_in_paper_order(rows, paper_rows):
    expected = []
    for key in PAPERS:
        assert {r["family"] for r in paper_rows[key]} == PAPER_FAMILIES[key]
        expected += [(r["family"], r["method"]) for r in paper_rows[key]]
    assert [(r["family"], r["method"]) for r in rows] == expected


def test_families_covered(rows):
    methods = " ".join(r["method"] for r in rows)
    for name in ("integral_pi", "recurrence", "products", "scipy.special.beta", "gammaln"):
        assert name in methods
    for name in ("agm", "ellipkm1", "ellipk", "quad", "mcmahon", "series"):
        assert any(r["method"] == name for r in rows)


def test_measured_numbers_reflect_the_methods(rows):
    by_method = {r["method"]: r for r in rows}
    ulp = float(
        re.search(
            r"max ([0-9.]+) ulp", by_method["integral (40-digit incomplete beta)"]["measured"]
        ).group(1)
    )
    assert ulp <= 1.0
    naive = by_method["scipy betainc with sin²x rounded (naive)"]
    assert float(re.search(r"max ([0-9.]+) ulp", naive["measured"]).group(1)) > 1000
    assert "none measured" in by_method["agm"]["fails_beyond"]
    assert "inf" in by_method["ellipk"]["fails_beyond"]
    products = by_method["printed products 2·4…n / 1·3…(n+1) as floats"]
    assert "OverflowError" in products["fails_beyond"]
    # the odd product 1·3…(n+1) exceeds the largest double first (at n = 300): found in ints
    first = next(n for n in range(2, 400, 2) if math.prod(range(1, n + 2, 2)) > 2**1024)
    assert products["accurate_range"] in (f"n < {first}", f"n <= {first - 1}")
    # Lecornu's k⁴ at 20°: sin⁴(10°) = 0.00091 (he prints « inférieur à 1/1000 »)
    series = by_method["series in k², order 1 (Lecornu keeps k², neglects k⁴)"]
    assert f"k⁴ = {math.sin(math.radians(10)) ** 4:.5f} at 20°" in series["fails_beyond"]


def test_planar_row_changes_when_a_method_breaks(monkeypatch):
    """Generated, not typed in: make agm wrong and its row says so."""
    from pendcli.numerics import planar
    from pendcli.papers.lecornu.stability import planar_rows

    real = planar.period_ratio

    def broken(amplitude, method="agm", **kw):
        value = real(amplitude, method, **kw)
        return value * (1 + 1e-6) if method == "agm" else value

    monkeypatch.setattr(planar, "period_ratio", broken)
    (agm,) = [r for r in planar_rows() if r["method"] == "agm"]
    assert "none measured" not in agm["fails_beyond"]


def test_integral_row_changes_when_a_method_breaks(monkeypatch):
    from pendcli.papers.charbonnier import model
    from pendcli.papers.charbonnier.stability import integral_rows

    real = model.integral_pi
    monkeypatch.setattr(model, "integral_pi", lambda n: real(n) * (1 + 1e-12))
    (row,) = [r for r in integral_rows() if r["method"].startswith("integral_pi (")]
    ulps = float(re.search(r"max ([0-9.]+) ulp", row["measured"]).group(1))
    assert ulps > 1000  # 1e-12 relative is ~4500 ulp


def test_conical_rows_measure_the_series_error():
    """Tisserand's series at order 6 is good at small amplitudes and poor at 80°/40°."""
    from pendcli.papers.tisserand.stability import conical_rows

    (series,) = [r for r in conical_rows() if r["method"].startswith("series_conical")]
    assert "5°/2°" in series["accurate_range"]
    assert "80°/40°" in series["fails_beyond"]
