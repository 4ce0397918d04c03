"""A paper is one folder plus one registry line: the sample paper under tests/papers/sample_paper/,
registered alone for the test, goes through every output of the CLI.

Its tables are copied into a temporary tables folder (PENDCLI_TABLES); nothing outside
tests/papers/sample_paper/ and this file knows the paper.
"""

from __future__ import annotations

import csv
import io
import json
import shutil
from pathlib import Path

import pytest
import sample_paper
from helpers.cli import invoke

from pendcli.data.tables import clear_table_cache
from pendcli.papers.registry import keys, registered

SAMPLE = Path(sample_paper.__file__).parent


@pytest.fixture
def sample(tmp_path, monkeypatch):
    tables = tmp_path / "tables"
    shutil.copytree(SAMPLE / "tables", tables)
    monkeypatch.setenv("PENDCLI_TABLES", str(tables))
    monkeypatch.setenv("PENDCLI_JOBS", "1")
    clear_table_cache()
    with registered(sample_paper.PAPER, alone=True):
        yield tables
    clear_table_cache()


def _ok(*args: str) -> str:
    code, out, err = invoke(*args)
    assert code == 0, err
    return out


def test_the_registry_holds_the_sample_only_inside_the_block(sample):
    assert keys() == ("sample",)


def test_the_sample_is_gone_after_the_block():
    assert "sample" not in keys()
    assert keys() == ("tisserand", "lecornu", "charbonnier")


def test_list_shows_the_sample_claim(sample):
    rows = json.loads(_ok("list", "-f", "json"))
    assert [r["id"] for r in rows["claims"]] == ["sample.period"]
    assert "sample.period" in _ok("list")


def test_reproduce_json_judges_the_claim_and_the_equation(sample):
    doc = json.loads(_ok("reproduce", "-f", "json", "--equations"))
    (claim,) = doc["claims"]
    assert (claim["id"], claim["published"], claim["verdict"]) == (
        "sample.period",
        "2,006",
        "agrees",
    )
    assert abs(claim["recomputed"] - 2.00606) < 1e-5  # 2π/√9,81, by hand
    assert doc["formulas"] == []  # the sample has no formula checks: an explicit None
    (equation,) = doc["equations"]
    assert (equation["id"], equation["status"]) == ("sample.eq.1", "holds")


@pytest.mark.parametrize("fmt", ["table", "csv", "markdown"])
def test_reproduce_in_every_other_format(sample, fmt):
    out = _ok("reproduce", "-f", fmt, "--equations")
    assert "sample.period" in out or "period" in out
    if fmt == "csv":
        ids = [row["id"] for row in csv.DictReader(io.StringIO(out)) if row.get("id")]
        assert "sample.period" in ids and "sample.eq.1" in ids


def test_equations_lists_the_ledger_row(sample):
    doc = json.loads(_ok("equations", "-f", "json"))
    assert [r["id"] for r in doc["equations"]] == ["sample.eq.1"]
    assert "(1)" in _ok("equations")


def test_check_regenerates_then_passes(sample):
    _ok("check", "--update")
    assert (sample / "regenerated" / "sample-claims.csv").is_file()
    assert "check passed" in _ok("check")


def test_report_and_html_on_the_sample(sample, tmp_path):
    out = tmp_path / "out"
    _ok("reproduce", "--out", str(out), "-f", "json", "--equations")
    report = (out / "report.md").read_text(encoding="utf-8")
    assert "## Sample" in report and "A. Sample" in report
    assert "The small-amplitude period" in report  # the figure's caption, from the paper
    assert (out / "figures" / "sample" / "sample-period.png").is_file()
    page = (out / "papers" / "sample.html").read_text(encoding="utf-8")
    assert 'id="row-sample.period"' in page and 'id="row-sample.eq.1"' in page
    assert 'href="papers/sample.html"' in (out / "report.html").read_text(encoding="utf-8")


def test_the_sample_sub_app(sample):
    assert _ok("sample", "period", "--length", "1").strip() == "2.006067"
    assert "sample" in _ok("--help")


def test_a_paper_cannot_be_registered_twice(sample):
    from pendcli.base.errors import PendcliError

    with pytest.raises(PendcliError, match="already registered"), registered(sample_paper.PAPER):
        pass


def test_a_wrong_printed_value_or_ledger_status_is_caught(sample):
    """The sample's verdicts are computed: a changed printed value is discrepant, and a
    ledger row recording "fails" for an equation that holds is refused."""
    published = sample / "published" / "sample.toml"
    published.write_text(published.read_text("utf-8").replace('"2,006"', '"2,016"'), "utf-8")
    ledger = sample / "equations" / "sample.toml"
    text = ledger.read_text("utf-8").replace('status = "holds"', 'status = "fails"')
    used = 'used_at = [9]\nused = "$T = 2,006$"\n'  # the later line that computes with (1)
    ledger.write_text(text + 'corrected = "none"\n' + used, "utf-8")
    clear_table_cache()
    (claim,) = json.loads(_ok("reproduce", "-f", "json"))["claims"]
    assert claim["verdict"] == "discrepant"
    code, _, err = invoke("equations")
    assert code == 2 and "recorded fails, but the printed form gives holds" in err
