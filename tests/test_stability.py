"""Issue 7: the stability summary is generated from measurements made at run time."""

from __future__ import annotations

import re

import pytest

from pendcli import stability

pytestmark = pytest.mark.extremes

KEYS = {"family", "method", "accurate_range", "fails_beyond", "measured"}


@pytest.fixture(scope="module")
def rows():
    return stability.stability_rows()


def test_rows_have_keys_and_text(rows):
    assert rows
    for row in rows:
        assert set(row) >= KEYS
        assert all(isinstance(row[k], str) and row[k] for k in KEYS)


def test_families_covered(rows):
    families = {r["family"] for r in rows}
    assert {"I_n = ∫ sin^(n+1)", "planar period T/T0", "Charbonnier Δα, b_n v^n"} <= families
    methods = " ".join(r["method"] for r in rows)
    for name in ("integral_pi", "recurrence", "products", "scipy.special.beta", "gammaln"):
        assert name in methods
    for name in ("agm", "ellipkm1", "ellipk", "quad"):
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
    assert (
        "OverflowError" in by_method["printed products 2·4…n / 1·3…(n+1) as floats"]["fails_beyond"]
    )


def test_rows_change_when_a_method_breaks(monkeypatch):
    """Generated, not typed in: make agm wrong and its row says so."""
    from pendcli.numerics import planar

    real = planar.period_ratio

    def broken(amplitude, method="agm", **kw):
        value = real(amplitude, method, **kw)
        return value * (1 + 1e-6) if method == "agm" else value

    monkeypatch.setattr(planar, "period_ratio", broken)
    (agm,) = [r for r in stability._planar_rows() if r["method"] == "agm"]
    assert "none measured" not in agm["fails_beyond"]
