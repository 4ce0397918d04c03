"""A citation of a label the text prints twice says which printing it means
(``[[citation]]`` of tables/papers/<paper>.reading.toml): every one is said, and an entry
that disagrees with the text is refused."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from pendcli.base.errors import PendcliError
from pendcli.data.ledger_labels import label_lines
from pendcli.data.reading import load_reading
from pendcli.data.reading_citations import parse_citations, unsaid_citations

TABLES = Path(__file__).resolve().parents[2] / "tables"


def _text(paper: str) -> str:
    return (TABLES / "papers" / f"{paper}.txt").read_text(encoding="utf-8")


def _cited_by_hand(text: str, labels: list[str]) -> set[tuple[str, int]]:
    """An independent scan: split the text on ``$$`` (even pieces are prose) and find each
    label's number in brackets, counting the lines before it."""
    found = set()
    offset = 0
    for index, piece in enumerate(text.split("$$")):
        if index % 2 == 0:
            for label in labels:
                number = label.strip("()")
                for match in re.finditer(rf"\({number}\)", piece):
                    found.add((label, text.count("\n", 0, offset + match.start()) + 1))
        offset += len(piece) + 2
    return found


@pytest.mark.parametrize("paper", ["tisserand", "lecornu", "charbonnier"])
def test_every_citation_of_a_label_printed_twice_says_which_printing(paper: str) -> None:
    text = _text(paper)
    twice = sorted(k for k, v in label_lines(text).items() if len(v) > 1)
    reading = load_reading(paper, TABLES)
    assert reading is not None
    said = {(c.label, c.line) for c in reading.citations}
    assert _cited_by_hand(text, twice) == said
    assert reading.unsaid == ()
    if paper == "lecornu":
        assert len(said) == 14 and {c.label for c in reading.citations} == set(twice)


def test_lecornus_section_two_citations_mean_section_two() -> None:
    """§ II begins with the second (18) (line 384): a citation after it of (18)-(22) means the
    printing of § II, one before it the printing of § I (no citation looks forward)."""
    reading = load_reading("lecornu", TABLES)
    assert reading is not None
    lines = label_lines(_text("lecornu"))
    for citation in reading.citations:
        first, second = lines[citation.label]
        assert citation.printing == (second if citation.line > second else first), citation


def test_a_citation_left_unsaid_is_listed() -> None:
    text = _text("lecornu")
    twice = {k: v for k, v in label_lines(text).items() if len(v) > 1}
    raw = tomllib.loads((TABLES / "papers" / "lecornu.reading.toml").read_text("utf-8"))
    kept = [e for e in raw["citation"] if e["line"] != 533]
    citations = parse_citations("lecornu.reading.toml", kept, text, twice)
    assert unsaid_citations(text, twice, citations) == (("(22)", 533),)


def _entry(**changes: object) -> list[dict[str, object]]:
    entry: dict[str, object] = {"label": "(22)", "line": 533, "printing": 509, "why": "θ in l"}
    entry.update(changes)
    return [{k: v for k, v in entry.items() if v is not None}]


REFUSED = [
    ("an unknown key", _entry(note="x"), r"unknown: 'note'"),
    ("a missing key", _entry(why=None), "keys must be exactly"),
    ("a label printed once", _entry(label="(24)"), "not one the text prints twice"),
    ("a line citing nothing", _entry(line=534), "line 534 cites no \\(22\\)"),
    ("a printing of another label", _entry(printing=505), "printing 505 is not a line printing"),
    ("a why of two lines", _entry(why="a\nb"), "one line"),
]


@pytest.mark.parametrize(("what", "entries", "message"), REFUSED, ids=[r[0] for r in REFUSED])
def test_a_citation_that_disagrees_with_the_text_is_refused(
    what: str, entries: list[dict[str, object]], message: str
) -> None:
    text = _text("lecornu")
    twice = {k: v for k, v in label_lines(text).items() if len(v) > 1}
    with pytest.raises(PendcliError, match=message) as caught:
        parse_citations("lecornu.reading.toml", entries, text, twice)
    assert "\n" not in str(caught.value)


def test_a_citation_listed_twice_is_refused() -> None:
    text = _text("lecornu")
    twice = {k: v for k, v in label_lines(text).items() if len(v) > 1}
    with pytest.raises(PendcliError, match="listed twice"):
        parse_citations("lecornu.reading.toml", _entry() + _entry(), text, twice)
