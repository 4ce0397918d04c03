"""The equation ledger: coverage computed from the papers' texts, every check consistent with
its recorded status, the extractor and the validation errors."""

from __future__ import annotations

import hashlib
import json
import re
import tomllib
from collections import Counter
from collections.abc import Iterator
from pathlib import Path

import pytest
from helpers.evaluated import committed_formulas
from helpers.ledgers import committed_ledger, committed_row, row_ids

from pendcli.base.errors import PendcliError
from pendcli.data.ledger import CHECKED_STATUSES, OUTPUT_KEYS, labels_in_text, parse_ledger
from pendcli.data.ledger_rows import Ledger, LedgerRow
from pendcli.data.rows import equation_notes
from pendcli.papers.registry import equation_rows, ledger_papers, paper
from pendcli.verify.claims import sharing_formula_rows
from pendcli.verify.ledger_evaluation import coverage, evaluate
from pendcli.verify.ledger_references import printed_problem, reference_table, row_printed_status

ROOT = Path(__file__).resolve().parents[2]
TABLES = ROOT / "tables"
# Papers whose ledger this suite requires.
REQUIRED = ("tisserand", "charbonnier", "lecornu")


def _papers() -> list[str]:
    return list(REQUIRED)


def _hashes() -> dict[str, str]:
    """File -> SHA-256, read from the provenance table in tables/papers/README.md."""
    text = (TABLES / "papers" / "README.md").read_text(encoding="utf-8")
    return dict(re.findall(r"^\| `([a-z]+\.txt)` \| `[^`]+` \| `([0-9a-f]{64})` \|", text, re.M))


def test_the_provenance_table_names_the_three_texts() -> None:
    assert sorted(_hashes()) == ["charbonnier.txt", "lecornu.txt", "tisserand.txt"]


@pytest.mark.parametrize("name", ["tisserand.txt", "lecornu.txt", "charbonnier.txt"])
def test_text_is_byte_for_byte_the_one_recorded(name: str) -> None:
    digest = hashlib.sha256((TABLES / "papers" / name).read_bytes()).hexdigest()
    assert digest == _hashes()[name]


@pytest.mark.parametrize("paper", _papers())
def test_every_printed_label_has_a_row(paper: str) -> None:
    ledger = committed_ledger(paper)
    printed = Counter(labels_in_text(ledger.text.read_text(encoding="utf-8")))
    have = ledger.labels()
    missing = {label: n - have[label] for label, n in printed.items() if have[label] < n}
    assert not missing, f"{paper}: labels printed but not (or not all) in the ledger: {missing}"
    extra = sorted(set(have) - set(printed))
    assert not extra, f"{paper}: ledger labels the text does not print: {extra}"


def _rows() -> list[str]:
    """The row ids of every ledger present (a missing required one fails its own test), read
    with tomllib alone: collecting would otherwise parse every formula of the three ledgers
    (0.9 s in each xdist worker); a test loads its row's validated ledger once per process."""
    present = set(ledger_papers(TABLES))
    return [row_id for paper in _papers() if paper in present for row_id in row_ids(paper)]


# Each row is judged here once (the slow ones are spread over the xdist workers); the tests
# of the whole ledger below read only the statuses, or run evaluate() on a small ledger.
@pytest.mark.parametrize("row_id", _rows())
def test_the_engine_computes_the_recorded_status(row_id: str) -> None:
    row = committed_row(row_id)
    if row.reference is None:
        assert row.status not in CHECKED_STATUSES and row.kind is None, row.id
        return
    symbols = committed_ledger(row.paper).symbols_for(row)
    computed = row_printed_status(row, symbols, reference_table(paper(row.paper)))
    assert printed_problem(row, computed) is None, f"{row.id}: {computed}"
    if row.kind == "digits":  # judged by its printed digits (pendcli/verify/printed_numeric.py)
        assert computed[1].startswith("the printed numbers"), f"{row.id}: {computed}"


# The definition rule (tables/README.md): a row records `definition` only when nothing in it
# can be derived, and its note says which: it defines a name, imposes a condition the author
# chooses, or repeats another row (then `restates` names that row). Every other row is
# checked (or, rarely, `not-checkable` with its reason).
DEFINING = ("defines", "imposes", "repeats")


def _definition_fault(row: LedgerRow) -> str | None:
    """How the row breaks the definition rule (None: it keeps it)."""
    if row.status != "definition":
        kept = row.status == "not-checkable" or row.kind
        return None if kept else f"{row.id}: {row.status} without a kind"
    first = row.note.split()[0] if row.note else ""
    if first not in DEFINING:
        return f"{row.id}: a definition's note starts with one of {DEFINING}"
    if (first == "repeats") != (row.restates is not None):
        return f"{row.id}: a repeated formula names the row it restates, and only then"
    return None


# One case per ledger, naming every row that breaks the rule: one case per row (378) cost
# about 1 ms of pytest (2 ms under xdist) apiece, twenty times the check.
@pytest.mark.parametrize("paper", _papers())
def test_the_definition_rule(paper: str) -> None:
    faults = [_definition_fault(row) for row in committed_ledger(paper).rows]
    assert [f for f in faults if f] == []


def test_required_ledgers_are_present() -> None:
    assert set(REQUIRED) <= set(ledger_papers(TABLES))


# --- evaluate / equation_rows on a small ledger: four real rows, one of each kind ----------

SMALL = (
    "charbonnier.eq.3",  # holds
    "charbonnier.eq.p",  # definition
    "charbonnier.eq.5",  # holds, read through the OCR's x for α
    "charbonnier.result.ec-monomial",  # misprint: n° 17 uses the right exponent
)


def _toml(value: object) -> str:
    """A value as TOML writes it (a table inline: a row's domain)."""
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_toml(v)}" for k, v in value.items()) + " }"
    return json.dumps(value, ensure_ascii=False)


def _small_ledger(root: Path, change: dict[str, dict[str, object]] | None = None) -> None:
    """The SMALL rows of the real Charbonnier ledger (and its reading table), as
    tables/equations/charbonnier.toml; ``change`` alters a row's fields (None removes one)."""
    raw = tomllib.loads((TABLES / "equations" / "charbonnier.toml").read_text(encoding="utf-8"))
    parts = [f'[ledger]\npaper = "charbonnier"\ntext = {json.dumps(raw["ledger"]["text"])}']
    symbols = "\n".join(f"{json.dumps(k)} = {json.dumps(v)}" for k, v in raw["symbols"].items())
    parts.append(f"[symbols]\n{symbols}")
    for entry in raw["reading"]:
        body = "\n".join(f"{k} = {json.dumps(v, ensure_ascii=False)}" for k, v in entry.items())
        parts.append(f"[[reading]]\n{body}")
    for entry in raw["equation"]:
        if entry["id"] in SMALL:
            altered = {**entry, **(change or {}).get(entry["id"], {})}
            entry = {k: v for k, v in altered.items() if v is not None}
            body = "\n".join(f"{k} = {_toml(v)}" for k, v in entry.items())
            parts.append(f"[[equation]]\n{body}")
    (root / "equations").mkdir()
    (root / "equations" / "charbonnier.toml").write_text("\n\n".join(parts) + "\n", "utf-8")
    (root / "papers").mkdir()  # the text the ledger names must exist (and not be empty)
    text = raw["ledger"]["text"].removeprefix("tables/")
    (root / text).write_bytes((TABLES / text).read_bytes())


@pytest.fixture
def charbonnier_formulas_lent() -> Iterator[None]:
    """Charbonnier's formula checks, which the small ledger's measured rows cite, lent to
    each judgement as a reproduction lends them to its ledger: computed once per run from the
    committed tables (tests/helpers/evaluated.py), as every judgement here would compute them
    (the small ledgers change no table they read), not once per call (0.1-0.3 s each)."""
    with sharing_formula_rows("charbonnier", list(committed_formulas("charbonnier"))):
        yield


@pytest.mark.usefixtures("charbonnier_formulas_lent")
def test_evaluate_runs_each_check_and_renders_the_output_rows(tmp_path: Path) -> None:
    _small_ledger(tmp_path)
    items = evaluate(paper("charbonnier"), tmp_path)
    assert sorted(i.row.id for i in items) == sorted(SMALL)
    assert [i.problem for i in items] == [None] * len(SMALL)
    assert [i.computed is None for i in items] == [i.row.status == "definition" for i in items]
    with pytest.raises(PendcliError, match=r"equation ledger .*tisserand\.toml is missing"):
        equation_rows(["tisserand", "charbonnier"], tmp_path)  # no tisserand ledger here
    rows = equation_rows(["charbonnier"], tmp_path)
    assert all(tuple(r.as_dict()) == OUTPUT_KEYS for r in rows)
    misprint = next(r for r in rows if r.status == "misprint")
    assert misprint.kind and misprint.computed == "misprint" and misprint.evidence
    notes = equation_notes(misprint.as_dict())
    assert f"computed from the printed form: misprint: {misprint.evidence}" in notes
    assert "blame: not carried: the right form is used at line 530" in notes
    read = next(r for r in rows if r.id == "charbonnier.eq.5")
    assert read.status == "holds" and "α printed as x" in (read.readings or "")
    definition = next(r for r in rows if r.status == "definition")
    assert (definition.against, definition.computed, definition.evidence) == (None, None, None)
    counts = coverage(rows)["charbonnier"]
    assert (counts["total"], counts["checked"], counts["misprint"], counts["findings"]) == (
        4,
        3,
        1,
        1,
    )


@pytest.mark.parametrize(
    ("row_id", "change"),
    [
        ("charbonnier.eq.3", {"status": "misprint", "reading": "θ = α cos kt", "unused": "-"}),
        (
            "charbonnier.result.ec-monomial",
            {"status": "holds", "reading": None, "reading_formula": None, "used_at": None,
             "used": None},
        ),
    ],
)  # fmt: skip
@pytest.mark.usefixtures("charbonnier_formulas_lent")
def test_a_check_contradicting_its_status_is_reported(
    tmp_path: Path, row_id: str, change: dict[str, object]
) -> None:
    _small_ledger(tmp_path, {row_id: change})
    problems = {i.row.id: i.problem for i in evaluate(paper("charbonnier"), tmp_path) if i.problem}
    assert list(problems) == [row_id]
    with pytest.raises(PendcliError, match=f"equation ledger inconsistent: {re.escape(row_id)}"):
        equation_rows(["charbonnier"], tmp_path)


# --- the extractor ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "labels"),
    [
        ("$$(1) \\quad a = b,$$", ["(1)"]),
        ("$$(42') \\quad T = 1$$", ["(42')"]),
        ("$$(II) \\left\\{ x \\right.$$", ["(II)"]),
        ("$$\\begin{aligned} a &= b; \\\\ (3) \\quad u^2 = v \\end{aligned}$$", ["(3)"]),
        ("$$x = y \\tag{7}$$", ["(7)"]),
        ("$$x = y. \\qquad (12)$$", ["(12)"]),
        ("$$(p) \\quad \\frac{dM}{dt} = 0.$$", ["(p)"]),
        ("$$(18) \\quad u$$ text $$(18) \\quad v$$", ["(18)", "(18)"]),
    ],
)
def test_labels_found(text: str, labels: list[str]) -> None:
    assert labels_in_text(text) == labels


@pytest.mark.parametrize(
    "text",
    [
        "la formule (5) donnera ensuite",
        "tome 5, n° 1 (1881), p. 448-454",
        "(n° 12, 2°) et (Avril 1908.) 10",
        "$$\\frac{3x^3}{(1 \\cdot 2 \\cdot 3)^2} + (u_0^2 - u_1^2)$$",
        "$$k = f(2) + g(x)$$",
        "On a (3) $$\\nu = k$$",
    ],
)
def test_no_label_in_prose_years_or_formulas(text: str) -> None:
    assert labels_in_text(text) == []


# --- validation ------------------------------------------------------------------------

_GOOD = {
    "id": "demo.eq.1",
    "equation": "(1)",
    "section": "§ 1",
    "statement": "a = b",
    "status": "definition",
    "note": "defines a",
}


def _parse(rows: list[dict[str, object]], header: dict[str, object] | None = None) -> Ledger:
    raw = {"ledger": header or {"paper": "demo", "text": "tables/papers/demo.txt"}}
    raw["equation"] = rows  # type: ignore[assignment]
    return parse_ledger(raw, "demo", Path("demo.toml"), TABLES)


def test_a_good_row_parses() -> None:
    ledger = _parse([_GOOD])
    assert ledger.rows[0].equation == "(1)"


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"typo": "x"}, "unknown key(s) 'typo'"),
        ({"status": "ok"}, "unknown status 'ok'"),
        ({"status": "holds"}, "needs a kind"),
        ({"status": "holds", "kind": "identity"}, "needs a reference"),
        ({"status": "holds", "kind": "proof", "reference": "r"}, "unknown kind 'proof'; valid:"),
        ({"check": "eq_1"}, "unknown key(s) 'check'"),
        ({"kind": "identity"}, "takes no kind"),
        ({"reference": "r"}, "takes no reference"),
        ({"measured": ["eq1"]}, "takes no measured"),
        ({"status": "holds", "kind": "series", "reference": "r", "measured": []}, "non-empty"),
        ({"equation": "1"}, "label as printed"),
        ({"equation": "(2)"}, "does not match the label"),
        ({"id": "other.eq.1"}, "id must read"),
        ({"status": "fails", "kind": "identity", "reference": "r"}, "'corrected' is required"),
        ({"status": "misprint", "kind": "identity", "reference": "r"}, "'reading' is required"),
        ({"reading": "x"}, "'reading' is required"),
        ({"note": None}, "needs a note"),
        ({"section": ""}, "non-empty string"),
    ],
)
def test_a_bad_row_is_refused_naming_file_and_id(change: dict[str, object], message: str) -> None:
    row = {k: v for k, v in {**_GOOD, **change}.items() if v is not None}
    with pytest.raises(PendcliError, match=re.escape(message)) as info:
        _parse([row])
    assert "demo.toml" in str(info.value)
    assert str(row.get("id", "")) in str(info.value)


def test_duplicate_ids_and_unknown_header_keys_are_refused() -> None:
    with pytest.raises(PendcliError, match="duplicate id"):
        _parse([_GOOD, _GOOD])
    with pytest.raises(PendcliError, match="unknown key"):
        _parse([_GOOD], {"paper": "demo", "text": "tables/papers/demo.txt", "year": 1})
    with pytest.raises(PendcliError, match="paper = 'demo'"):
        _parse([_GOOD], {"paper": "other", "text": "tables/papers/demo.txt"})


def test_a_stated_result_has_no_label() -> None:
    row = {**_GOOD, "id": "demo.result.sum", "equation": ""}
    assert _parse([row]).rows[0].equation == ""
    with pytest.raises(PendcliError, match="stated result"):
        _parse([{**row, "equation": "(1)"}])


def test_checked_statuses_are_the_three() -> None:
    assert CHECKED_STATUSES == ("holds", "fails", "misprint")


def test_the_cited_references_are_the_ledger_s_reference_names_each_built_once() -> None:
    """The names read from the TOML with tomllib; a second call returns the same objects
    (shared, not built again)."""
    from pendcli.verify.ledger_references import cited_references
    from pendcli.verify.printed_check import Reference

    raw = tomllib.loads((TABLES / "equations" / "charbonnier.toml").read_text("utf-8"))
    names = {e["reference"] for e in raw["equation"] if "reference" in e}
    built = cited_references(paper("charbonnier"), TABLES)
    assert set(built) == names and len(names) > 5
    assert all(isinstance(r, Reference) for r in built.values())
    again = cited_references(paper("charbonnier"), TABLES)
    assert all(again[name] is built[name] for name in names)
