"""Each piece of an equation row is a field of its own: the ledger's words (``note``,
``reading_note``, ``corrected_note``), the status the engine computed from the printed form
(``against``, ``computed``, ``evidence``), the dimension check's reason and the check's
corrected form; the table, Markdown and report join them into one note column."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import pytest
from helpers.cli import invoke
from helpers.evaluated import committed_formulas
from helpers.ledgers import committed_ledger

from pendcli.base.cache import rows_from_json, rows_to_json
from pendcli.data.rows import EquationRow, equation_notes
from pendcli.output import schema
from pendcli.output.json import to_json
from pendcli.papers.registry import ledger_papers, paper
from pendcli.verify.claims import sharing_formula_rows
from pendcli.verify.ledger_evaluation import Evaluated, evaluate

TABLES = Path(__file__).resolve().parents[2] / "tables"
ENGINE = ("against", "computed", "evidence")


def _toml(key: str) -> dict[str, dict[str, object]]:
    """The committed ledger's entries by id, read with tomllib alone."""
    text = (TABLES / "equations" / f"{key}.toml").read_text(encoding="utf-8")
    return {str(e["id"]): e for e in tomllib.loads(text)["equation"]}


def _json_row(key: str, row_id: str) -> dict[str, object]:
    """Row ``row_id`` evaluated alone (a slice of one row of its ledger), as JSON prints it.
    The paper's formula checks (which its measured rows cite) are lent as a reproduction
    lends them to its ledger's parts, computed once per process (tests/helpers/evaluated.py)."""
    rows = committed_ledger(key).rows
    index = [r.id for r in rows].index(row_id)
    with sharing_formula_rows(key, list(committed_formulas(key))):
        (item,) = evaluate(paper(key), part=(index, len(rows)))
    assert item.problem is None
    document = json.loads(to_json({"equations": [item.output_row().as_dict()]}))
    assert schema.check_row(schema.DOCUMENT["equations"], document["equations"][0]) == []
    return dict(document["equations"][0])


@pytest.mark.parametrize("key", ledger_papers())
def test_the_ledgers_words_are_their_own_fields(key: str) -> None:
    """For every committed row: ``note`` is exactly the ledger's note, the reading's and the
    correction's prose are fields, and ``against`` names the row's reference."""
    entries = _toml(key)
    for row in committed_ledger(key).rows:
        out = Evaluated(row, None, None).output_row()
        entry = entries[row.id]
        assert out.note == entry.get("note", ""), row.id
        assert (out.reading_note, out.corrected_note) == (
            entry.get("reading"),
            entry.get("corrected"),
        ), row.id
        assert out.against == entry.get("reference"), row.id


def test_a_failing_printed_form_carries_its_evidence() -> None:
    """Lecornu's (16) prints 0,00313 for b²/(4g) = 0,0031218: the engine computes, from the
    printed digits, a misprint (its 0,00312 reading holds; no later length carries the digit)
    and says why in ``evidence``, not in ``note``."""
    row = _json_row("lecornu", "lecornu.eq.16")
    entry = _toml("lecornu")["lecornu.eq.16"]
    assert (row["status"], row["against"], row["computed"]) == (
        "misprint",
        "numbers_eq16",
        "misprint",
    )
    evidence = str(row["evidence"])
    assert evidence.startswith("the printed numbers fail (1 of 1 off: #1 0.00313"), evidence
    assert row["note"] == entry["note"] and "computed from the printed form" not in row["note"]
    assert row["reading_note"] == entry["reading"] and row["kind"] == "digits"
    assert row["inconsistency"] is None
    joined = equation_notes(row)
    assert f"computed from the printed form: misprint: {evidence}" in joined
    # its verdict turns with g, which the paper does not print: the note says so first
    assert joined.startswith("conditional: holds for g <= 9.80, misprint for g > 9.80 ")
    assert f"; reading: {entry['reading']}; " in joined


def test_a_row_without_a_reference_has_no_computed_status() -> None:
    row = _json_row("lecornu", "lecornu.result.uniform_lengthening")
    assert row["status"] == "definition"
    assert [row[k] for k in ENGINE] == [None, None, None]
    assert "computed from the printed form" not in equation_notes(row)


def test_the_note_column_joins_the_fields_in_order() -> None:
    """The table's, Markdown's and the report's note column: each piece, in a fixed order."""
    row = {"reading_note": "R", "corrected_note": "C", "note": "N", "against": "ref",
           "computed": None, "evidence": "E", "measured": "M", "dimensions": "inconsistent",
           "dimensions_detail": "D", "inconsistency": "I"}  # fmt: skip
    assert equation_notes(row) == (
        "reading: R; corrected: C; N; computed from the printed form: no status "
        "the ledger may record: E; measured: M; dimensions: D; LEDGER INCONSISTENT: I"
    )
    consistent = {**row, "dimensions": "consistent", "against": None, "measured": None}
    assert equation_notes(consistent) == "reading: R; corrected: C; N; LEDGER INCONSISTENT: I"
    assert equation_notes({"note": "N", "against": None}) == "N"


def test_a_cached_row_of_the_old_shape_is_not_read() -> None:
    """A cache entry written before the fields existed is a miss (read back, it raises)."""
    row = EquationRow("a.eq.1", "a", "(1)", "I", "s", "holds", "", None, "n", against="ref",
                      computed="holds", evidence="why")  # fmt: skip
    (stored,) = rows_to_json([row])
    assert rows_from_json(EquationRow, [stored]) == [row]
    old = {k: v for k, v in stored.items() if k not in (*ENGINE, "dimensions_detail")}
    with pytest.raises(TypeError, match="not the fields of a EquationRow"):
        rows_from_json(EquationRow, [old])


def test_every_json_row_carries_the_engines_verdict(
    monkeypatch, shared_result_cache, reproduce_computed_once
) -> None:
    """`pendcli equations -f json`, every paper: a row with a reference carries the status
    computed from its printed form (the recorded one) and why; a row without none; every
    ``note`` is the ledger's own. The ledgers are the run's one computation of every table
    (tests/helpers/regenerated.py), made by the same engine in a fresh process."""
    monkeypatch.setenv("PENDCLI_CACHE", shared_result_cache)
    code, out, err = invoke("equations", "-f", "json")
    assert code == 0, err
    rows = json.loads(out)["equations"]
    entries = {i: e for key in ledger_papers() for i, e in _toml(key).items()}
    assert sorted(r["id"] for r in rows) == sorted(entries)
    for row in rows:
        entry = entries[row["id"]]
        assert row["note"] == entry.get("note", ""), row["id"]
        assert row["against"] == entry.get("reference"), row["id"]
        if row["against"] is None:
            assert (row["computed"], row["evidence"]) == (None, None), row["id"]
        else:
            assert row["computed"] == row["status"] and row["evidence"], row["id"]
    failing = [r for r in rows if r["computed"] == "fails"]
    assert failing and all(str(r["evidence"]).strip() for r in failing)
