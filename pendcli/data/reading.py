"""The reading record of a paper's prose: ``tables/papers/<paper>.reading.toml``.

Every paragraph of prose of ``tables/papers/<paper>.txt`` (a maximal run of non-blank lines
once the ``$$`` display formulas are blanked out, :func:`prose_paragraphs`) is accounted for
by one ``[[paragraph]]``: ``lines = [first, last]`` exactly the paragraph's, and either
``rows``, the ledger rows (``tables/equations/<paper>.toml``) whose ``quote`` gives, within
those lines, the exact words of each checkable claim the paragraph makes, or ``none``, a
one-line reason why it makes none (a title, narration, a definition already a row, a
citation of a work). The claims are judged by the ledger's engine like the formulas; this
module only checks that the record and the text agree. It also lists where each equation
label is printed (:func:`~pendcli.data.ledger_labels.label_lines`): a label printed twice is
one the reader must tell apart.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pendcli.base.errors import PendcliError
from pendcli.data.ledger_labels import label_lines
from pendcli.data.reading_citations import (
    Citation,
    parse_citations,
    reading_path,
    unsaid_citations,
)
from pendcli.data.text_blocks import Span

__all__ = [
    "Paragraph",
    "ReadingCoverage",
    "ReadingRecord",
    "load_reading",
    "parse_reading",
    "prose_paragraphs",
    "reading_coverage",
]

READING_KEYS = ("paper", "text")
PARAGRAPH_KEYS = ("lines", "rows", "none")
# a reason is one line, a paragraph names at most this many rows
MAX_REASON = 300
MAX_ROWS = 40
_DISPLAY = re.compile(r"\$\$.*?\$\$", re.DOTALL)


def prose_paragraphs(text: str) -> tuple[Span, ...]:
    """The text's paragraphs of prose, as 1-based inclusive line spans: maximal runs of lines
    with something on them once every ``$$ … $$`` block is blanked (its line breaks kept)."""
    masked = _DISPLAY.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    spans: list[Span] = []
    first: int | None = None
    lines = masked.split("\n")
    for number, line in enumerate(lines, 1):
        if line.strip() and first is None:
            first = number
        elif not line.strip() and first is not None:
            spans.append((first, number - 1))
            first = None
    if first is not None:
        spans.append((first, len(lines)))
    return tuple(spans)


@dataclass(frozen=True)
class Paragraph:
    """One paragraph of prose: its lines, and the rows holding its claims or why it has none."""

    lines: Span
    rows: tuple[str, ...] = ()
    none: str | None = None


@dataclass(frozen=True)
class ReadingRecord:
    paper: str
    path: Path
    paragraphs: tuple[Paragraph, ...]
    # every paragraph of the text, read or not
    text_paragraphs: tuple[Span, ...]
    # which printing each citation of a label printed twice means (data/reading_citations)
    citations: tuple[Citation, ...] = ()
    # the (label, line) citations of a label printed twice that no citation entry says
    unsaid: tuple[tuple[str, int], ...] = ()

    @property
    def missing(self) -> tuple[Span, ...]:
        """The text's paragraphs the record does not account for."""
        read = {p.lines for p in self.paragraphs}
        return tuple(span for span in self.text_paragraphs if span not in read)


def load_reading(paper: str, root: Path | None = None) -> ReadingRecord | None:
    """The paper's reading record, validated against its text and ledger (None: it has none)."""
    from pendcli.data.ledger import load_ledger
    from pendcli.data.tables import read_table_text, read_toml

    path = reading_path(paper, root)
    if not path.exists():
        return None
    ledger = load_ledger(paper, root)
    text = read_table_text(ledger.text, "paper text")
    quotes = {row.id: row.quotes for row in ledger.rows}
    header = f"tables/{ledger.text.relative_to(ledger.path.parent.parent).as_posix()}"
    return parse_reading(read_toml(path, "reading record"), paper, path, text, quotes, header)


def parse_reading(
    raw: dict[str, Any],
    paper: str,
    path: Path,
    text: str,
    quotes: Mapping[str, tuple[str, ...]],
    text_name: str,
) -> ReadingRecord:
    """Validate a parsed record against the text (its paragraphs) and the ledger's rows by id
    with their quotes; ``text_name`` is the ledger's ``[ledger] text``, which the record's
    ``[reading] text`` must repeat. Every problem is one line naming the file."""
    _refuse_unknown(f"{path}", "top-level key(s)", raw, ("reading", "paragraph", "citation"))
    head = raw.get("reading")
    if not isinstance(head, dict) or head.get("paper") != paper:
        raise PendcliError(f"{path}: [reading] must be a table with paper = {paper!r}")
    _refuse_unknown(f"{path}: [reading]", "key(s)", head, READING_KEYS)
    if head.get("text") != text_name:
        raise PendcliError(f"{path}: [reading] text must be {text_name!r} (the ledger's text)")
    entries = raw.get("paragraph")
    if not isinstance(entries, list) or not entries:
        raise PendcliError(f"{path}: no [[paragraph]] entries")
    spans = prose_paragraphs(text)
    lines = text.split("\n")
    paragraphs: list[Paragraph] = []
    for index, entry in enumerate(entries):
        paragraph = _paragraph(f"{path}: [[paragraph]] #{index + 1}", entry, spans)
        if paragraphs and paragraph.lines[0] <= paragraphs[-1].lines[1]:
            previous = list(paragraphs[-1].lines)
            raise PendcliError(
                f"{path}: paragraph {list(paragraph.lines)} is listed again or out of order "
                f"(after {previous})"
            )
        _check_rows(f"{path}: paragraph {list(paragraph.lines)}", paragraph, lines, quotes)
        paragraphs.append(paragraph)
    twice = {k: v for k, v in label_lines(text).items() if len(v) > 1}
    citations = parse_citations(f"{path}", raw.get("citation"), text, twice)
    unsaid = unsaid_citations(text, twice, citations)
    return ReadingRecord(paper, path, tuple(paragraphs), spans, citations, unsaid)


def _refuse_unknown(where: str, what: str, entry: dict[str, Any], valid: tuple[str, ...]) -> None:
    unknown = sorted(set(entry) - set(valid))
    if unknown:
        raise PendcliError(
            f"{where}: unknown {what} {', '.join(map(repr, unknown))}; valid: {', '.join(valid)}"
        )


def _paragraph(where: str, entry: object, spans: tuple[Span, ...]) -> Paragraph:
    """One ``[[paragraph]]``: its lines a paragraph of the text, and rows or none, not both."""
    if not isinstance(entry, dict):
        raise PendcliError(f"{where} is not a table")
    _refuse_unknown(where, "key(s)", entry, PARAGRAPH_KEYS)
    value = entry.get("lines")
    if not (isinstance(value, list) and len(value) == 2 and all(type(v) is int for v in value)):
        raise PendcliError(f"{where}: 'lines' must be [first, last], two line numbers")
    span = (value[0], value[1])
    if span not in spans:
        near = [list(s) for s in spans if s[0] <= span[1] and span[0] <= s[1]]
        which = f"it overlaps {near}" if near else "no paragraph lies there"
        raise PendcliError(f"{where}: lines {value} are not a paragraph of the text ({which})")
    where = f"{where} (lines {value})"
    rows, none = entry.get("rows"), entry.get("none")
    if (rows is None) == (none is None):
        raise PendcliError(f"{where}: give either 'rows' or 'none', not both or neither")
    if none is not None:
        if not isinstance(none, str) or not none.strip() or "\n" in none or len(none) > MAX_REASON:
            raise PendcliError(
                f"{where}: 'none' must be one line of at most {MAX_REASON} characters"
            )
        return Paragraph(span, none=none)
    if not isinstance(rows, list) or not 0 < len(rows) <= MAX_ROWS:
        raise PendcliError(f"{where}: 'rows' must be a list of 1 to {MAX_ROWS} row ids")
    if not all(isinstance(r, str) and r for r in rows):
        raise PendcliError(f"{where}: 'rows' must be a list of 1 to {MAX_ROWS} row ids")
    if len(set(rows)) != len(rows):
        raise PendcliError(f"{where}: a row is named twice in 'rows'")
    return Paragraph(span, rows=tuple(str(r) for r in rows))


def _check_rows(
    where: str, paragraph: Paragraph, lines: list[str], quotes: Mapping[str, tuple[str, ...]]
) -> None:
    """Each row named exists and has a quote printed within the paragraph's lines."""
    first, last = paragraph.lines
    words = "\n".join(lines[first - 1 : last])
    for row in paragraph.rows:
        if row not in quotes:
            raise PendcliError(f"{where}: row {row!r} is not in the ledger")
        if not any(quote in words for quote in quotes[row]):
            raise PendcliError(f"{where}: row {row!r} has no quote within these lines")


@dataclass(frozen=True)
class ReadingCoverage:
    """How many of a paper's paragraphs of prose its reading record accounts for."""

    paper: str
    paragraphs: int
    read: int
    unread: tuple[Span, ...]
    # each label the text prints more than once, with the line of each printing
    printed_twice: Mapping[str, tuple[int, ...]]

    def as_dict(self) -> dict[str, object]:
        """The keys ``pendcli equations`` adds to a paper's coverage."""
        return {
            "paragraphs": self.paragraphs,
            "paragraphs_read": self.read,
            "unread_paragraphs": [list(span) for span in self.unread],
            "labels_printed_twice": {k: list(v) for k, v in self.printed_twice.items()},
        }


def reading_coverage(paper: str, root: Path | None = None) -> ReadingCoverage:
    """The paper's paragraphs accounted for by its reading record (none without a record),
    and the labels its text prints more than once."""
    from pendcli.data.ledger import load_ledger
    from pendcli.data.tables import read_table_text

    text = read_table_text(load_ledger(paper, root).text, "paper text")
    twice = {k: v for k, v in label_lines(text).items() if len(v) > 1}
    reading = load_reading(paper, root)
    if reading is None:
        spans = prose_paragraphs(text)
        return ReadingCoverage(paper, len(spans), 0, spans, twice)
    unread = reading.missing
    total = len(reading.text_paragraphs)
    return ReadingCoverage(paper, total, total - len(unread), unread, twice)
