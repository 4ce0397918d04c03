"""The companions of a corrected or read row (pendcli/verify/ledger_companions.py): every later
row and sentence that depends on a misprinted, failing or OCR-read formula is judged against
the changed form (its own record, its computed status, or a ``[[companion]]`` entry saying why
it is independent); one left as printed fails here."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from helpers.ledgers import committed_ledger

from pendcli.base.errors import PendcliError
from pendcli.data.ledger import load_ledger
from pendcli.verify.ledger_blame import row_context
from pendcli.verify.ledger_companions import (
    LEFT,
    companions_of,
    ledger_companions,
    parse_companions,
    unexamined,
)

TABLES = Path(__file__).resolve().parents[2] / "tables"
PAPERS = ("tisserand", "lecornu", "charbonnier")


@pytest.mark.parametrize("paper", PAPERS)
def test_no_companion_is_left_as_printed(paper: str) -> None:
    found = ledger_companions(committed_ledger(paper))
    assert unexamined(found) == [], [c.shown() for c in unexamined(found)]


def _text(paper: str) -> list[str]:
    return (TABLES / "papers" / f"{paper}.txt").read_text(encoding="utf-8").split("\n")


def _prose_lines_citing(paper: str, label: str) -> set[int]:
    """An independent scan: the lines of prose (outside ``$$``) where ``label`` is printed."""
    found, inside = set(), False
    for number, line in enumerate(_text(paper), 1):
        pieces = line.split("$$")
        for index, piece in enumerate(pieces):
            if not inside and label in piece:
                found.add(number)
            if index < len(pieces) - 1:
                inside = not inside
    return found


def test_the_sentences_citing_a_misprinted_label_are_found() -> None:
    """Lecornu's (6) (a misprint, line 80) is cited in prose at lines 114 and 688, neither
    within a row's lines: both are companions, 114 its recorded later use."""
    ledger = committed_ledger("lecornu")
    spans = [r.lines for r in ledger.rows if r.lines is not None]
    by_hand = {n for n in _prose_lines_citing("lecornu", "(6)") if n > 80}
    outside = {n for n in by_hand if not any(a <= n <= b for a, b in spans)}
    found = ledger_companions(ledger)["lecornu.eq.6"]
    assert {c.line for c in found if c.row is None} == outside == {114, 688}
    judged = {c.line: c.judged for c in found}
    assert judged == {114: "used_at", 688: "independent"}


def test_a_citation_of_the_other_printing_of_a_doubled_label_is_no_companion() -> None:
    """The misprinted (19) is the second printing (line 406; the first is line 270). Two
    citations after it, one said to mean line 406 and one line 270, and one unsaid: the
    first and the unsaid are companions, the one meaning the other printing is not."""
    ledger = committed_ledger("lecornu")
    row = "lecornu.eq.19.definite-integral"
    assert 364 in _prose_lines_citing("lecornu", "(19)")  # the real one, before line 406
    assert all(c.line != 364 for c in ledger_companions(ledger)[row])
    citations = [("(19)", 2000, 406), ("(19)", 2001, 270), ("(19)", 2002, None)]
    found = companions_of(ledger, citations, [], _text("lecornu"))[row]
    assert {c.line for c in found if c.row is None} == {2000, 2002}


def test_a_companion_without_an_entry_is_left_as_printed() -> None:
    """Break the record: the same ledger judged without its [[companion]] entries leaves the
    three companions they name as printed."""
    ledger = committed_ledger("lecornu")
    text = _text("lecornu")
    spans = [r.lines for r in ledger.rows if r.lines is not None]
    cited = [(lab, n, None) for lab in ("(6)", "(28)") for n in _prose_lines_citing("lecornu", lab)]
    found = companions_of(ledger, cited, spans, text)
    left = {(c.source, c.row or c.line) for c in unexamined(found)}
    assert left == {
        ("lecornu.eq.6", 688),
        ("lecornu.eq.28", 678),
        ("lecornu.result.quarter_values", "lecornu.result.half_duration"),
    }
    assert all(c.judged == LEFT for c in unexamined(found))


def test_a_restating_row_is_judged_by_its_record() -> None:
    """Tisserand's lines 126 and 154 cite (13) (a misprint) and restate it."""
    found = ledger_companions(committed_ledger("tisserand"))["tisserand.eq.13"]
    assert {(c.row, c.judged) for c in found} == {
        ("tisserand.result.what-gives-the-motion", "restates"),
        ("tisserand.result.axis-and-ellipse-motion", "restates"),
    }


def test_a_name_introduced_by_a_misprint_is_followed_to_its_users() -> None:
    """Charbonnier's (9) introduces Delta_thetap_m (Δθ'_m, by E_c for E_s): the two later rows
    whose formulas use the name are companions, each judged by its computed status."""
    ledger = committed_ledger("charbonnier")
    users = {
        r.id
        for r in ledger.rows
        if r.lines is not None
        and r.lines[0] > 287
        and any(re.search(r"\bDelta_thetap_m\b", getattr(r, f) or "") for f in ("printed",))
    }
    found = ledger_companions(ledger)["charbonnier.eq.9"]
    assert {c.row for c in found} == users
    assert {c.judged for c in found} == {"checked"}


def test_the_companions_are_on_the_source_row() -> None:
    ledger = committed_ledger("lecornu")
    row = next(r for r in ledger.rows if r.id == "lecornu.result.quarter_values")
    shown = row_context(row, ledger, None, None).companions
    assert len(shown) == 2
    assert any(s.startswith("lecornu.result.half_duration (shares") for s in shown)
    other = next(r for r in ledger.rows if r.id == "lecornu.eq.15")
    assert row_context(other, ledger, None, None).companions == ()


# --- the [[companion]] table: refused when it disagrees -----------------------------------------


def _entry(**changes: object) -> list[dict[str, object]]:
    entry: dict[str, object] = {"of": "lecornu.eq.6", "line": 688, "why": "narration"}
    entry.update(changes)
    return [{k: v for k, v in entry.items() if v is not None}]


SHAPES = [
    ("an unknown key", _entry(note="x"), "unknown key\\(s\\) 'note'"),
    ("both row and line", _entry(row="lecornu.eq.15"), "one of 'row' or 'line'"),
    ("neither row nor line", _entry(line=None), "one of 'row' or 'line'"),
    ("a line as text", _entry(line="688"), "'line' a line number"),
    ("a why of two lines", _entry(why="a\nb"), "one line"),
]


@pytest.mark.parametrize(("what", "entries", "message"), SHAPES, ids=[s[0] for s in SHAPES])
def test_a_malformed_entry_is_refused(what: str, entries: object, message: str) -> None:
    with pytest.raises(PendcliError, match=message) as caught:
        parse_companions("lecornu.toml", entries)
    assert "\n" not in str(caught.value)


def _copy_with(tmp_path: Path, entry: str) -> Path:
    root = tmp_path / "tables"
    for sub in ("papers", "equations", "published"):
        (root / sub).mkdir(parents=True)
    for name in ("lecornu.txt", "lecornu.reading.toml"):
        shutil.copy(TABLES / "papers" / name, root / "papers" / name)
    ledger = (TABLES / "equations" / "lecornu.toml").read_text(encoding="utf-8")
    (root / "equations" / "lecornu.toml").write_text(ledger + entry, encoding="utf-8")
    return root


MATCHES = [
    ("a row that is no companion", 'of = "lecornu.eq.6"\nrow = "lecornu.eq.15"',
     "names no companion"),
    ("a source that is no source", 'of = "lecornu.eq.15"\nline = 688', "names no companion"),
    ("a companion its record judges", 'of = "lecornu.eq.6"\nline = 114', "already judged"),
]  # fmt: skip


@pytest.mark.parametrize(("what", "body", "message"), MATCHES, ids=[m[0] for m in MATCHES])
def test_an_entry_naming_no_unjudged_companion_is_refused(
    tmp_path: Path, what: str, body: str, message: str
) -> None:
    root = _copy_with(tmp_path, f'\n[[companion]]\n{body}\nwhy = "x"\n')
    with pytest.raises(PendcliError, match=message) as caught:
        ledger_companions(load_ledger("lecornu", root))
    assert "lecornu.toml" in str(caught.value) and "\n" not in str(caught.value)


def test_a_flawed_companion_writing_the_wrong_form_again_must_say_it_carries() -> None:
    """Line 565 writes line 561's (π² − 12b)/(16g) again: lecornu.result.largest_length_comparison
    names it (carries). Without that record its computed status (a misprint of its own) does
    not judge it: it is left as printed."""
    from dataclasses import replace

    ledger = committed_ledger("lecornu")
    source = "lecornu.result.vertical_to_elongation"
    companion = "lecornu.result.largest_length_comparison"
    rows = tuple(replace(r, carries=None) if r.id == companion else r for r in ledger.rows)
    spans = [r.lines for r in rows if r.lines is not None]
    found = companions_of(replace(ledger, rows=rows), [], spans, _text("lecornu"))[source]
    assert [(c.row, c.judged) for c in found if c.row == companion] == [(companion, LEFT)]
    judged = {c.row: c.judged for c in ledger_companions(ledger)[source]}
    assert judged[companion] == "carries"
    assert judged["lecornu.result.descending_half_lengthened"] == "restates"


def test_the_shortening_of_line_565_is_the_sign_of_the_printed_form() -> None:
    """« un léger raccourcissement, égal à (π² − 12b)/(16g) »: the printed form is positive for
    every b below π²/12 m/s, the corrected (π² − 12)b/(16g) negative for every b > 0 (the
    ledger's own formulas, evaluated by sympy over b from 0,01 to 0,8 m/s; the integration of
    tests/papers/lecornu/test_prose_lecornu_from_line_462.py finds the half lengthened by 0,133
    b/g)."""
    import sympy as sp

    row = next(
        r
        for r in committed_ledger("lecornu").rows
        if r.id == "lecornu.result.largest_length_comparison"
    )
    assert row.printed is not None and row.reading_formula is not None
    b, g = sp.symbols("b g", positive=True)
    printed = sp.sympify(row.printed.split(";")[1].split("=")[1], {"b": b, "g": g})
    read = sp.sympify(row.reading_formula.split(";")[1].split("=")[1], {"b": b, "g": g})
    for speed in (0.01, 0.2, 0.35, 0.6, 0.8):
        assert printed.subs({b: speed, g: 9.81}) > 0 > read.subs({b: speed, g: 9.81})
