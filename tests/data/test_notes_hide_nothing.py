"""A note never hides a finding: a `holds` row of any ledger whose note speaks of a slip, a
misprint or something wrong names, by its id, the row (or claim) that carries it, so that the
slip is a row of its own with a computed status, never words in another row's note."""

from __future__ import annotations

import re

import pytest

from pendcli.data.ledger import load_ledger

PAPERS = ("tisserand", "lecornu", "charbonnier")
ADMITS = re.compile(
    r"\b(slip|misprint|wrong|should read|is false|contradict|erroneous|mistake|typo)", re.I
)
NAMES_A_ROW = re.compile(r"\b(tisserand|lecornu|charbonnier)\.[\w.'-]+")


def unnamed_admissions(notes: dict[str, str]) -> list[str]:
    return [i for i, note in notes.items() if ADMITS.search(note) and not NAMES_A_ROW.search(note)]


@pytest.mark.parametrize("paper", PAPERS)
def test_no_holds_row_admits_a_slip_it_does_not_name(paper: str) -> None:
    notes = {r.id: r.note or "" for r in load_ledger(paper).rows if r.status == "holds"}
    assert notes and unnamed_admissions(notes) == []


def test_an_admission_without_a_row_is_caught() -> None:
    notes = {
        "a": "the printed coefficient is a misprint for 3/8",
        "b": "the misprint is lecornu.eq.41's, carried here",
        "c": "holds as printed",
    }
    assert unnamed_admissions(notes) == ["a"]
