"""Real JSON output against the one schema (pendcli.output.schema) behind docs/schema.md."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest
from helpers.cli import invoke
from helpers.evaluated import committed_claims, committed_formulas

from pendcli.output import schema
from pendcli.papers.registry import PAPERS
from pendcli.verify.claims import ClaimRow, FormulaRow

SCHEMA_DOC = Path(__file__).resolve().parents[2] / "docs" / "schema.md"


def _problems(kind: schema.RowKind, rows: list) -> list[str]:
    return [
        f"{row.get('id', i)}: {p}"
        for i, row in enumerate(rows)
        for p in schema.check_row(kind, row)
    ]


def test_reproduce_json_matches_the_schema():
    code, out, err = invoke("reproduce", "--format", "json", "--stability")
    assert code == 0, err
    doc = json.loads(out)
    assert set(doc) == {"claims", "formulas", "stability"}
    for key in ("claims", "formulas", "stability"):
        assert doc[key], key
        assert _problems(schema.DOCUMENT[key], doc[key]) == []
    ids = [row["id"] for row in doc["claims"] + doc["formulas"]]
    assert len(ids) == len(set(ids))
    for row in doc["claims"] + doc["formulas"]:
        assert row["id"].startswith(row["paper"] + ".")
    for row in doc["formulas"]:
        pairs = row["residuals"]
        assert all(len(p) == 2 and all(isinstance(v, int | float) for v in p) for p in pairs)
    assert {row["paper"] for row in doc["claims"]} == set(PAPERS)


def test_tradeoff_json_rows_match_the_schema():
    code, out, err = invoke("tradeoff", "planar_period", "--quick", "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert set(doc) == {"rows", "skipped"}
    assert doc["rows"]
    assert _problems(schema.DOCUMENT["rows"], doc["rows"]) == []


def test_the_schema_names_every_field_of_the_rows():
    """The dataclasses behind claims and formulas and the schema list the same keys."""
    # The field cause_from is the JSON key "from" (a Python keyword); as_printed (the OCR's
    # text of the value) is the HTML's, which marks it in the paper's text.
    claim_keys = [
        f.name.replace("cause_from", "from")
        for f in dataclasses.fields(ClaimRow)
        if f.name != "as_printed"
    ]
    formula_keys = [f.name.replace("cause_from", "from") for f in dataclasses.fields(FormulaRow)]
    assert sorted(schema.DOCUMENT["claims"].names) == sorted(claim_keys)
    # in the order a row prints them: the verdict against his procedure beside the truth's
    row = ClaimRow("p.a", "p", "", "", "", "1", 1.0, 1.0, "agrees", 0.0, 0.0, 17.0, None, "", "")
    assert list(schema.DOCUMENT["claims"].names) == list(row.as_dict())
    assert list(schema.DOCUMENT["formulas"].names) == formula_keys


@pytest.mark.parametrize(
    ("row", "problem"),
    [
        ({"family": "f", "method": "m", "setting": "s", "seconds": 1e-3, "error": None,
          "evaluations": 7, "note": ""}, None),
        ({"family": "f", "method": "m", "setting": "s", "seconds": "fast", "error": None,
          "evaluations": 7, "note": ""}, "seconds: 'fast' is not number"),
        ({"family": "f", "method": "m", "setting": "s", "seconds": 1.0, "error": None,
          "evaluations": 7.5, "note": ""}, "evaluations: 7.5 is not integer or null"),
        ({"family": "f", "method": "m", "setting": "s", "seconds": True, "error": None,
          "evaluations": 7, "note": ""}, "seconds: True is not number"),
        ({"family": "f", "method": "m", "setting": "s", "seconds": 1.0, "error": None,
          "note": ""}, "missing key 'evaluations'"),
        ({"family": "f", "method": "m", "setting": "s", "seconds": 1.0, "error": None,
          "evaluations": None, "note": "", "extra": 1}, "unexpected key 'extra'"),
    ],
)  # fmt: skip
def test_check_row_catches_each_kind_of_departure(row, problem):
    problems = schema.check_row(schema.DOCUMENT["rows"], row)
    assert problems == ([] if problem is None else [problem])


def test_check_row_refuses_a_verdict_outside_the_list():
    row = {f.name: "" for f in schema.DOCUMENT["stability"].fields}
    assert schema.check_row(schema.DOCUMENT["stability"], row) == []
    claim = schema.DOCUMENT["claims"]
    verdict = next(f for f in claim.fields if f.name == "verdict")
    assert verdict.problems("agrees") == []
    assert verdict.problems("roughly") == [
        "verdict: 'roughly' is not one of agrees, truncated, last-digit, discrepant"
    ]


def test_docs_schema_section_is_generated_from_the_schema():
    from tools.docs import schema_section

    text = SCHEMA_DOC.read_text(encoding="utf-8")
    between = text.split("<!-- schema:start -->\n", 1)[1].split("\n<!-- schema:end -->", 1)[0]
    assert between == schema_section()
    for kind in schema.DOCUMENT.values():
        for name in kind.names:
            assert f"| `{name}` |" in between


def test_every_disagreement_is_explained():
    """A verdict other than `agrees` carries a note; a failing formula says what is right.
    The rows `reproduce` computes (the registry's claim_rows and formula_checks), computed once
    per process for the tests that read them (tests/helpers/evaluated.py)."""
    for row in (r.as_dict() for key in PAPERS for r in committed_claims(key)):
        if row["verdict"] != "agrees":
            assert len(str(row["note"])) > 20, row["id"]
    for row in (r.as_dict() for key in PAPERS for r in committed_formulas(key)):
        if row["verdict"] == "fails":
            assert row["recomputed"] != row["published"], row["id"]
            assert len(str(row["note"])) > 20, row["id"]


def test_reproduce_equations_json_matches_the_schema(monkeypatch, shared_result_cache):
    # Charbonnier's ledger is the cheapest to run; the keys are the same.
    monkeypatch.setenv("PENDCLI_CACHE", shared_result_cache)  # a test of the form, not values
    code, out, err = invoke("reproduce", "-f", "json", "--equations", "--paper", "charbonnier")
    assert code == 0, err
    doc = json.loads(out)
    assert set(doc) == {"claims", "formulas", "equations"}
    assert doc["equations"] and _problems(schema.DOCUMENT["equations"], doc["equations"]) == []
    labels = {row["equation"] for row in doc["equations"]}
    assert {f"({n})" for n in range(1, 10)} <= labels
