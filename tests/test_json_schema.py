"""`pendcli reproduce --format json` against the schema documented in the README."""

from __future__ import annotations

import json

from cli_helpers import invoke

from pendcli.core.claims import PAPERS

NUMBER, TEXT, OPTIONAL_NUMBER = (int, float), str, (int, float, type(None))
CLAIM_SCHEMA = {
    "id": TEXT,
    "paper": TEXT,
    "source": TEXT,
    "quantity": TEXT,
    "unit": TEXT,
    "published": TEXT,
    "published_value": NUMBER,
    "recomputed": NUMBER,
    "verdict": TEXT,
    "abs_diff": NUMBER,
    "rel_diff": OPTIONAL_NUMBER,
    "digits": NUMBER,
    "exact": OPTIONAL_NUMBER,
    "method": TEXT,
    "note": TEXT,
}
FORMULA_SCHEMA = {
    "id": TEXT,
    "paper": TEXT,
    "source": TEXT,
    "published": TEXT,
    "recomputed": TEXT,
    "verdict": TEXT,
    "claimed_order": OPTIONAL_NUMBER,
    "observed_order": OPTIONAL_NUMBER,
    "note": TEXT,
    "residuals": list,
}


def test_reproduce_json_matches_the_documented_schema():
    code, out, err = invoke("reproduce", "--format", "json", "--stability")
    assert code == 0, err
    doc = json.loads(out)
    assert set(doc) == {"claims", "formulas", "stability"}
    ids = [row["id"] for row in doc["claims"]]
    assert len(ids) == len(set(ids))
    for row in doc["claims"]:
        assert set(row) == set(CLAIM_SCHEMA), row["id"]
        for key, kind in CLAIM_SCHEMA.items():
            assert isinstance(row[key], kind), (row["id"], key, row[key])
        assert row["paper"] in PAPERS
        assert row["id"].startswith(row["paper"] + ".")
        assert row["verdict"] in {"agrees", "truncated", "last-digit", "discrepant"}
    for row in doc["formulas"]:
        assert set(row) == set(FORMULA_SCHEMA), row["id"]
        for key, kind in FORMULA_SCHEMA.items():
            assert isinstance(row[key], kind), (row["id"], key, row[key])
        assert row["verdict"] in {"holds", "fails"}
        assert all(
            len(pair) == 2 and all(isinstance(v, NUMBER) for v in pair) for pair in row["residuals"]
        )
    for row in doc["stability"]:
        assert set(row) == {"family", "method", "accurate_range", "fails_beyond", "measured"}
    assert {row["paper"] for row in doc["claims"]} == set(PAPERS)


def test_every_disagreement_is_explained():
    """A verdict other than `agrees` carries a note; a failing formula says what is right."""
    from pendcli.reproduce import reproduce_all

    result = reproduce_all(PAPERS, formulas=True)
    for row in result.claim_dicts():
        if row["verdict"] != "agrees":
            assert len(row["note"]) > 20, row["id"]
    for row in result.formula_dicts():
        if row["verdict"] == "fails":
            assert row["recomputed"] != row["published"], row["id"]
            assert len(row["note"]) > 20, row["id"]
