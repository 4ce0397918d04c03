"""A ledger row's ``quote`` (the words of the text it rests on) and its list of
wrong terms: validated against the paper's text when the ledger is read, and marked there."""

from __future__ import annotations

import dataclasses
import shutil
from pathlib import Path

import pytest
from helpers.edition import edition_rows, misplaced, quote_is_printed

from pendcli.base.errors import PendcliError
from pendcli.data.ledger import load_ledger
from pendcli.data.tables import tables_dir
from pendcli.output.html.marks import ALSO_WRONG, place_marks


def _altered(tmp_path: Path, paper: str, old: str, new: str) -> Path:
    root = tmp_path / "tables"
    shutil.copytree(tables_dir(), root)
    path = root / "equations" / f"{paper}.toml"
    text = path.read_text("utf-8")
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new), "utf-8")
    return root


RISE = "quote = \"L'arc de remontée est égal à l'arc de descente\""


@pytest.mark.parametrize(
    ("new", "message"),
    [
        # one letter off the text: not a transcription
        (RISE.replace("égal", "egal"), "quote \"L'arc de remontée est egal à l'arc de descente\""
         " is not in its lines [107, 107] of charbonnier.txt"),
        # printed in the text, but not within the row's lines
        ('quote = "Le sinus pourra"', "is not in its lines [107, 107]"),
        ("quote = []", "'quote' must be a non-empty string or list of strings"),
        ('quote = ["L\'arc", 3]', "'quote' must be a non-empty string or list of strings"),
    ],
)  # fmt: skip
def test_a_quote_not_printed_within_its_lines_is_one_line_error(
    tmp_path: Path, new: str, message: str
) -> None:
    root = _altered(tmp_path, "charbonnier", RISE, new)
    with pytest.raises(PendcliError) as error:
        load_ledger("charbonnier", root)
    assert message in str(error.value) and "\n" not in str(error.value)


def test_a_wrong_term_of_a_list_not_printed_within_its_lines_is_an_error(tmp_path: Path) -> None:
    old = 'wrong_term = ["+ \\\\frac{5}{8} u \\\\cos u", "+ \\\\frac{3}{8} u \\\\cos 3u"]'
    root = _altered(tmp_path, "lecornu", old, old.replace("{3}{8}", "{9}{8}"))
    with pytest.raises(PendcliError, match=r"wrong_term .*\{9\}\{8\}.* is not in its lines"):
        load_ledger("lecornu", root)


def test_the_rows_with_two_wrong_terms_read_as_lists() -> None:
    rows = {r.id: r for r in load_ledger("lecornu").rows}
    counts = {i: len(rows[f"lecornu.result.{i}"].wrong_terms) for i in (
        "delta_rhs", "u_at_roots", "largest_length_comparison", "general_constants",
        "constant_a_prime", "quarter_values")}  # fmt: skip
    assert counts == {"delta_rhs": 2, "u_at_roots": 2, "largest_length_comparison": 2,
                      "general_constants": 3, "constant_a_prime": 2,
                      "quarter_values": 2}  # fmt: skip
    assert rows["lecornu.eq.52"].wrong_terms == (rows["lecornu.eq.52"].wrong_term,)


def test_each_wrong_term_is_marked_and_only_the_first_carries_the_correction() -> None:
    text = (tables_dir() / "papers" / "lecornu.txt").read_text("utf-8")
    marks = {m.key: m for m in place_marks(text, *edition_rows("lecornu"))[0]}
    first = marks["lecornu.result.largest_length_comparison~term0"]
    second = marks["lecornu.result.largest_length_comparison~term1"]
    assert text[first.start : first.end] == "\\frac{3\\pi^2 + 12b}{16g}"
    assert text[second.start : second.end] == "\\frac{\\pi^2 - 12b}{16g}"
    assert first.note.startswith("read (3π² + 12)b/(16g)") and second.note == ALSO_WRONG


def test_a_quote_runs_through_a_formula_as_pieces() -> None:
    """« $\\cos kt$ ne diffère de -1 »: the formula's TeX and the prose, two pieces."""
    text = (tables_dir() / "papers" / "charbonnier.txt").read_text("utf-8")
    marks = [m for m in place_marks(text, *edition_rows("charbonnier"))[0]
             if m.row_id == "charbonnier.result.amplitude"]  # fmt: skip
    assert [text[m.start : m.end] for m in marks][:2] == [
        "\\cos kt", "ne diffère de -1 que par un terme en ε^2"]  # fmt: skip
    assert all(m.how == "quote" for m in marks)


def test_the_quote_check_sees_a_piece_moved_or_missing() -> None:
    """Broken on purpose: a quote's piece shifted by three characters, or one piece of two
    dropped, is not the quote as printed."""
    text = (tables_dir() / "papers" / "charbonnier.txt").read_text("utf-8")
    claims, equations = edition_rows("charbonnier")
    row = next(r for r in equations if r["id"] == "charbonnier.result.amplitude")
    marks = [m for m in place_marks(text, claims, equations)[0] if m.row_id == row["id"]]
    pieces = [m for m in marks if m.forms == marks[0].forms]
    assert len(pieces) == 2 and quote_is_printed(text, row, pieces[0], pieces)
    moved = dataclasses.replace(pieces[1], start=pieces[1].start + 3, end=pieces[1].end + 3)
    assert not quote_is_printed(text, row, pieces[0], [pieces[0], moved])
    assert not quote_is_printed(text, row, pieces[0], [pieces[0]])


def test_a_quote_outside_its_lines_falls_back_and_is_caught() -> None:
    """Broken on purpose: rise-equals-descent's lines moved off its sentence, onto line 72
    (sine-to-arc's sentence, marked already): its quote is not found there, so it has no
    mark of its own, and the check says so."""
    text = (tables_dir() / "papers" / "charbonnier.txt").read_text("utf-8")
    claims, equations = edition_rows("charbonnier")
    moved = [{**r, "lines": [72, 72]} if r["id"] == "charbonnier.result.rise-equals-descent"
             else r for r in equations]  # fmt: skip
    bad = misplaced("charbonnier", text, claims, moved)
    assert bad == ["charbonnier.result.rise-equals-descent not marked"]
