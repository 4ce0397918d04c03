"""Where each row is printed in a paper's OCR text, and the marks of its annotated page.

The accessors below are the only places that know the rows' keys (row dicts, ``as_dict()``
of the rows); :mod:`pendcli.html_paper` and :mod:`pendcli.html_report` read rows through
them. A row is located by its printed string, tolerant of the OCR's TeX spacing, inside the
stretches of text its quoted words, its label or "after (N)" point to.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from pendcli.core.vocabulary import (
    CLAIM_VERDICTS,
    STATUSES,
)
from pendcli.html_math import balanced, math_segments

if TYPE_CHECKING:
    from pendcli.html_math import MathSegment

Row = Mapping[str, object]

VERDICT_CLASSES = CLAIM_VERDICTS
STATUS_CLASSES = STATUSES
# The cause of an equation row follows from its status (pendcli.core.causes' vocabulary).
EQUATION_CAUSE = {"fails": "derivation-error", "misprint": "misprint"}


# --- accessors: the only places that know the rows' keys ------------------------------------


def word_of(value: object) -> str:
    """A verdict, status or cause as its word (an enum's value, or the string)."""
    value = getattr(value, "value", value)
    return "" if value is None else str(value)


def id_of(row: Row) -> str:
    return str(row["id"])


def verdict_of(row: Row) -> str:
    return word_of(row.get("verdict") or row.get("status"))


def text_of(row: Row, key: str) -> str:
    value = row.get(key)
    return "" if value is None else str(value)


def sources_of(row: Row) -> list[str]:
    """The ids a propagated row inherits from (its ``from`` key)."""
    value = row.get("from")
    return [str(s) for s in value] if isinstance(value, list | tuple) else []


def own_of(row: Row) -> str:
    """A claim against the author's procedure on his printed inputs, and his value."""
    from pendcli.core.numbers import edition_number

    verdict, his = word_of(row.get("procedure_verdict")), row.get("procedure_value")
    if not verdict or not isinstance(his, float | int):
        return "no procedure known"
    return f"{verdict}: {text_of(row, 'procedure')} = {edition_number(his, 6)}"


def number_text(value: object) -> str:
    """A recomputed number as the papers write theirs (decimal comma): the edition is French."""
    from pendcli.core.numbers import edition_number

    return edition_number(value)


def disagrees(row: Row) -> bool:
    return verdict_of(row) in ("truncated", "last-digit", "discrepant", "fails", "misprint")


def css_of(row: Row) -> str:
    word = verdict_of(row)
    return f"v-{word}" if word in VERDICT_CLASSES else f"s-{word}"


# --- locating what the paper prints in its OCR text -----------------------------------------

# How the OCR's TeX writes symbols that the tables keep in plain notation.
_OCR_FORMS = {
    "°": r"(?:°|\^\{\\circ\})",
    "·": r"(?:·|\\cdot(?![A-Za-z]))",
    "²": r"(?:²|\^\{?2\}?)",
    "√": r"(?:√|\\sqrt(?![A-Za-z]))",
    "−": r"(?:−|-)",
    **{
        c: rf"(?:{c}|\\{name}(?![A-Za-z]))"
        for c, name in zip(
            "πθφψωαβγλρε",
            [
                "pi",
                "theta",
                "varphi",
                "psi",
                "omega",
                "alpha",
                "beta",
                "gamma",
                "lambda",
                "rho",
                "varepsilon",
            ],
            strict=True,
        )
    },
}
_SPACE = r"(?:\s|\\q?quad\b|\\[,;!])*"


def _pattern(printed: str) -> re.Pattern[str] | None:
    """A regex for ``printed`` that tolerates the OCR's spacing (``0^m,68`` ~ ``0^m, 68``)."""
    chars = [c for c in printed if not c.isspace()]
    if not chars:
        return None
    body = _SPACE.join(_OCR_FORMS.get(c, re.escape(c)) for c in chars)
    # A bare number must not match inside a longer one ("5" inside "0,35").
    before = r"(?<![\d,.])" if chars[0].isdigit() else ""
    after = r"(?![\d])" if chars[-1].isdigit() else ""
    return re.compile(before + body + after)


def locate(text: str, candidates: Sequence[Sequence[str]]) -> list[tuple[int, int] | None]:
    """Where each item's printed form first occurs in ``text``, in reading order.

    ``candidates[i]`` are the forms of item i, widest first: the OCR's own text (which may be
    a whole formula), then the value alone. An item is looked for after the previous item's
    place first, since tables list claims in the paper's order, then anywhere; spans already
    taken are skipped.
    """
    taken: list[tuple[int, int]] = []
    spans: list[tuple[int, int] | None] = []
    cursor = 0
    for forms in candidates:
        span = _find(text, forms, cursor, len(text), taken) or _find(
            text, forms, 0, len(text), taken
        )
        spans.append(span)
        if span is not None:
            taken.append(span)
            cursor = span[0]
    return spans


def _find(
    text: str, forms: Sequence[str], start: int, end: int, taken: list[tuple[int, int]]
) -> tuple[int, int] | None:
    """The first free match of the widest form, narrowed to a later form found inside it."""
    for i, form in enumerate(forms):
        span = _first_free(text, form, start, end, taken)
        if span is not None:
            for narrower in forms[i + 1 :]:
                inner = _first_free(text, narrower, span[0], span[1], taken)
                if inner is not None:
                    return inner
            return span
    return None


def _first_free(
    text: str, form: str, start: int, end: int, taken: list[tuple[int, int]]
) -> tuple[int, int] | None:
    pattern = _pattern(form)
    if pattern is None:
        return None
    for m in pattern.finditer(text, start, end):
        if all(m.end() <= a or m.start() >= b for a, b in taken):
            return m.span()
    return None


# --- where a row belongs: its quoted words, its label, "after (N)" --------------------------

_QUOTE = re.compile(r"«\s*(.+?)\s*»")
_WORDS = re.compile(r"[A-Za-zÀ-ÿ'’]+(?:[ ,][A-Za-zÀ-ÿ'’]+){2,}")
_AFTER = re.compile(r"\b(after|before|footnote to|table after) (\([0-9IVX]+'?\))")


def paragraph_spans(text: str, segments: Sequence[MathSegment]) -> list[tuple[int, int]]:
    """The paragraphs of ``text``: split at blank lines outside display formulas."""
    inside = [(s.start, s.end) for s in segments if s.display]
    cuts = [m.start() for m in re.finditer(r"\n[ \t]*\n", text)
            if not any(a < m.start() < b for a, b in inside)]  # fmt: skip
    edges = [0, *cuts, len(text)]
    return [(a, b) for a, b in itertools.pairwise(edges) if text[a:b].strip()]


def _label_place(
    text: str,
    label: str,
    segments: Sequence[MathSegment],
    within: tuple[int, int] = (0, 1 << 62),
) -> tuple[int, int] | None:
    """Where ``label`` is printed as a label (in a display formula starting ``within``): at a
    line's start (after $$, \\\\ or \\begin{…}) or in the margin after a \\quad; else
    anywhere in a display."""
    token = re.escape(label)
    at_start = re.compile(rf"(?:^\s*|\\\\\s*|\\begin\{{\w+\*?\}}\s*|\\left\\{{\s*){token}")
    in_margin = re.compile(rf"\\q?quad\s*{token}")
    displays = [s for s in segments if s.display and within[0] <= s.start < within[1]]
    for pattern in (at_start, in_margin, re.compile(token)):
        for s in displays:
            m = pattern.search(text, s.tex_start, s.tex_end)
            if m is not None:
                return m.end() - len(label), m.end()
    return None


def _quotes(row: Row) -> list[str]:
    keys = ("source", "section", "ocr", "statement", "reading_note", "corrected_note", "note")
    return [q for key in keys for q in _QUOTE.findall(text_of(row, key))]


def _quote_place(text: str, quote: str) -> tuple[int, int] | None:
    """The quote found whole (TeX-tolerant), or its longest run of plain words."""
    whole = _pattern(quote)
    m = whole.search(text) if whole else None
    if m is not None:
        return m.span()
    for words in sorted(_WORDS.findall(quote), key=len, reverse=True):
        at = text.find(words)
        if at >= 0 and len(words) >= 12:
            return at, at + len(words)
    return None


def _regions(
    text: str, row: Row, segments: Sequence[MathSegment], blocks: Sequence[tuple[int, int]]
) -> list[tuple[int, int]]:
    """The stretches of text where the row may be printed, surest first: the paragraph of
    its quoted words and the two after it (a number follows its sentence); its label's
    paragraph; the text after (N) up to the next numbered equation, or before (N); the
    equation its source names, "eq. (15)", and the text up to the next numbered one; its
    numbered section, "n° 15"."""
    out = []
    for quote in _quotes(row):
        span = _quote_place(text, quote)
        if span is not None:
            out.append(_paragraphs(blocks, span[0], 0, 2))
    label = text_of(row, "equation")
    span = _label_place(text, label, segments) if label else None
    if span is not None:
        out.append(_paragraphs(blocks, span[0], 0, 0))
    where = text_of(row, "section") + " " + text_of(row, "source")
    m = _AFTER.search(where)
    span = _label_place(text, m.group(2), segments) if m else None
    if m and span is not None:
        before = m.group(1) == "before"
        out.append(_paragraphs(blocks, span[0], -3, 0) if before else
                   (span[1], _next_label(text, span[1], segments)))  # fmt: skip
    m = _IN_LABEL.search(text_of(row, "source"))
    span = _label_place(text, m.group(1), segments) if m else None
    if span is not None:
        out.append((span[0], _next_label(text, span[1], segments)))
    m = re.search(r"n° (\d+)", where)
    heading = re.search(rf"(?:^|\n\n){m.group(1)}\. ", text) if m else None
    if heading is not None:
        end = re.compile(r"\n\n\d+\. ").search(text, heading.end())
        out.append((heading.start(), end.start() if end else len(text)))
    return out


_ANY_LABEL = re.compile(r"^\s*\(\d{1,3}[a-z]?'?\)|\\q?quad\s*\(\d{1,3}[a-z]?'?\)\s*[.,;]?\s*$")


def _next_label(text: str, after: int, segments: Sequence[MathSegment]) -> int:
    """Where the next display formula carrying an equation label starts (or the text's end)."""
    for s in segments:
        if s.display and s.start >= after and _ANY_LABEL.search(text[s.tex_start : s.tex_end]):
            return s.start
    return len(text)


_IN_LABEL = re.compile(r"(?:^|[\s,])(?:eq\.\s*)?(\(\d{1,3}[a-z]?'?\))")


def _paragraphs(
    blocks: Sequence[tuple[int, int]], at: int, first: int, last: int
) -> tuple[int, int]:
    i = next(k for k, (a, b) in enumerate(blocks) if a <= at < b or k == len(blocks) - 1)
    lo, hi = max(0, i + first), min(len(blocks) - 1, i + last)
    return blocks[lo][0], blocks[max(lo, hi)][1]


# --- the marks of a page --------------------------------------------------------------------


@dataclass(frozen=True)
class Placement:
    """One mark: the text it covers, the row it stands for and how it was placed."""

    start: int
    end: int
    row_id: str
    key: str  # the element's id: at-<key>
    css: str
    word: str  # the verdict or status shown in the note
    note: str  # the note beside the text (reading, correction, recomputed value)
    finding: bool
    anchored: bool  # found at the row's own place (its lines, quoted words, label, "after (N)")
    forms: tuple[str, ...] = ()  # the printed strings it was looked for by
    lines: tuple[int, int] = (0, 0)  # the 1-based lines of the text it covers
    generic: bool = False  # the first free formula or sentence of the row's lines
    # how it was placed: "value" (a claim's printed string), "reading" (the words an OCR
    # note reads), "term" (a wrong term), "label", "formula" (the formula its printed form
    # or statement is), "quote" (its quoted words), "first" (the first free formula or
    # sentence of its lines), "string" (its printed string, searched outside any lines)
    how: str = ""
    whole: bool = False  # drawn around a whole formula, which may hold other marks
    nests: bool = False  # drawn around other marks that it holds whole (a wrong table entry)
    # the key of the mark whose note it shares: a later piece of one quote or formula, which
    # gets no note call or margin entry of its own
    continues: str = ""


@dataclass
class _Page:
    text: str
    segments: list[MathSegment]
    blocks: list[tuple[int, int]]
    taken: list[tuple[int, int]] = field(default_factory=list)
    marks: list[Placement] = field(default_factory=list)
    passages: list[tuple[int, Placement]] = field(default_factory=list)  # notes without a mark
    cursor: int = 0


def place_marks(
    text: str, claims: Sequence[Row], equations: Sequence[Row]
) -> tuple[list[Placement], list[tuple[int, Placement]]]:
    """Every mark of the page, and the notes placed at a passage without a mark of their own.

    A row with ``lines`` is marked inside them: a claim by its printed string; a ledger row
    by its wrong terms (a misprint or a failure) or its label, and by the words of the text
    it rests on (its ``quote``); else at the formula of those lines that its printed form (or
    statement) is, else by its quoted words, else at their first free formula or sentence.
    Wrong terms and labels go first for every row, then quotes, so that one row's whole
    formula does not take another row's label or sentence. A row without ``lines`` is
    looked for inside its regions (:func:`_regions`), then by its printed string.
    """
    segments = math_segments(text)
    page = _Page(text, segments, paragraph_spans(text, segments))
    for row in claims:
        _place_claim(page, row)
    bounded = [(row, span) for row in equations if (span := lines_region(text, row))]
    specific = [_place_specific(page, row, span) for row, span in bounded]
    quoted = [_place_own_quotes(page, row, span) for row, span in bounded]
    unmarked = [rs for rs, a, b in zip(bounded, specific, quoted, strict=True) if not (a or b)]
    for row, span in unmarked:
        if not _place_formulas(page, row, span) and not _place_quote(page, row, span):
            _place_generic(page, row, span)
    for row in equations:
        if lines_region(text, row) is None:
            _place_equation(page, row)
    # in reading order; of marks starting together, the outer first
    order = sorted(page.marks, key=lambda m: (m.start, not m.whole, -m.end, not m.nests))
    return order, page.passages


def lines_of(row: Row) -> tuple[int, int] | None:
    """The row's ``lines = [first, last]`` (1-based lines of the paper's text), if recorded."""
    value = row.get("lines")
    if isinstance(value, list | tuple) and len(value) == 2:
        return int(value[0]), int(value[1])
    return None


def lines_region(text: str, row: Row) -> tuple[int, int] | None:
    """The offsets of the row's lines in ``text``: from its first line's start to its last
    line's end."""
    lines = lines_of(row)
    if lines is None:
        return None
    starts = _line_starts(text)
    first, last = lines
    end = starts[last] - 1 if last < len(starts) else len(text)
    return starts[first - 1], end


@lru_cache(maxsize=8)  # a page asks for each of its rows' lines in the same text
def _line_starts(text: str) -> tuple[int, ...]:
    """The offset of each line's start in ``text``."""
    return (0, *(m.end() for m in re.finditer("\n", text)))


def _search(
    page: _Page, forms: Sequence[str], regions: Sequence[tuple[int, int]]
) -> tuple[tuple[int, int] | None, bool]:
    for region in regions:
        span = _find(page.text, forms, region[0], region[1], page.taken)
        if span is not None:
            return span, True
    span = _find(page.text, forms, page.cursor, len(page.text), page.taken)
    return span or _find(page.text, forms, 0, len(page.text), page.taken), False


_BARE = re.compile(r"^[\d,.]+$")


def _standalone(page: _Page, number: str, start: int, end: int) -> tuple[int, int] | None:
    """A bare number printed alone (a table's cell, between blanks, outside any formula)
    in text[start:end]: "2" is the table's entry, not the factor 2 of a formula."""
    pattern = re.compile(rf"(?<=\s){re.escape(number)}(?=\s)")
    for m in pattern.finditer(page.text, start, end):
        free = all(m.end() <= a or m.start() >= b for a, b in page.taken)
        if free and not any(s.start <= m.start() < s.end for s in page.segments):
            return m.span()
    return None


def line_of(text: str, at: int) -> int:
    """The 1-based line of ``text`` that offset ``at`` is on."""
    return text.count("\n", 0, at) + 1


def covered_lines(text: str, start: int, end: int) -> tuple[int, int]:
    """The first and last line of text[start:end] (its start's line when empty)."""
    return line_of(text, start), line_of(text, max(start, end - 1))


def _add(page: _Page, span: tuple[int, int], **kw: Any) -> None:
    if not kw.get("whole"):  # a mark around a whole formula leaves its inside free
        page.taken.append(span)
    lines = covered_lines(page.text, *span)
    page.marks.append(Placement(span[0], span[1], lines=lines, **kw))


def _place_claim(page: _Page, row: Row) -> None:
    """The claim's printed string inside its lines (a bare number standing alone there
    first: "2" is the table's entry, not the factor 2 of a formula), and the words its OCR
    note reads; a claim without lines by its regions, then by its printed string."""
    forms = tuple(f for f in (text_of(row, "as_printed"), text_of(row, "published")) if f)
    region = lines_region(page.text, row)
    bare = all(_BARE.match(f) for f in forms)
    if region is not None:
        span = (_standalone(page, forms[0], *region) if bare else None) or _find(
            page.text, forms, *region, page.taken
        )
        anchored, how = span is not None, "value"
    else:
        regions = _regions(page.text, row, page.segments, page.blocks)
        span, anchored = _search(page, forms, regions)
        if not regions and bare:
            span = _standalone(page, forms[0], page.cursor, len(page.text)) or span
        how = "value" if anchored else "string"
    base = {"row_id": id_of(row), "css": css_of(row), "word": verdict_of(row),
            "finding": disagrees(row)}  # fmt: skip
    if span is not None:
        page.cursor = span[0]
        _add(page, span, key=id_of(row), note=_claim_note(row), anchored=anchored,
             forms=forms, how=how, **base)  # fmt: skip
    for i, quote in enumerate(_QUOTE.findall(text_of(row, "ocr"))):  # the words it reads
        lo, hi = region or (0, len(page.text))
        reading = _first_free(page.text, quote, lo, hi, page.taken)
        if reading is not None:
            base.update(css="s-reading wrong", word="reading", finding=True)
            _add(page, reading, key=f"{id_of(row)}~reading{i}",
                 note=_clauses(text_of(row, "ocr"), 2), anchored=True, forms=(quote,),
                 how="reading", **base)  # fmt: skip


def _place_equation(page: _Page, row: Row) -> None:
    """The label at its place, the wrong term itself (its note carries the correction), or
    else a note at the passage the row follows."""
    regions = _regions(page.text, row, page.segments, page.blocks)
    base: dict[str, Any] = {
        "row_id": id_of(row),
        "word": verdict_of(row),
        "finding": disagrees(row),
    }
    note = _equation_note(row)
    terms = 0
    for i, printed in enumerate(_printed_terms(row)):
        span, anchored = _search(page, [printed], regions)
        if span is not None:
            _add(page, span, key=f"{id_of(row)}~term{i}", css=f"{css_of(row)} wrong", note=note,
                 anchored=anchored, forms=(printed,), how="term", **base)  # fmt: skip
            terms += 1
    label = text_of(row, "equation")
    span = _label_place(page.text, label, page.segments) if label else None
    if span is not None and all(span[1] <= a or span[0] >= b for a, b in page.taken):
        label_note = "the wrong term is marked in the formula" if terms else note
        _add(page, span, key=id_of(row), css=css_of(row), note=label_note, anchored=True,
             forms=(label,), how="label", **base)  # fmt: skip
    elif not terms and regions:
        at = regions[0][0]
        mark = Placement(at, at, key=id_of(row), css=css_of(row), note=note, anchored=True, **base)
        page.passages.append((at, mark))


def _row_base(row: Row) -> dict[str, Any]:
    return {"row_id": id_of(row), "word": verdict_of(row), "finding": disagrees(row)}


# The note of a row's second and later wrong terms: the reading or correction is shown once.
ALSO_WRONG = "also wrong; the reading or correction is in this row's note on its main wrong term"


def _place_specific(page: _Page, row: Row, region: tuple[int, int]) -> bool:
    """Inside the row's lines: its wrong terms (the first carries the reading or correction,
    the others say where it is) and its label. Whether anything was marked."""
    a, b = region
    base, note = _row_base(row), _equation_note(row)
    terms = 0
    for i, printed in enumerate(_printed_terms(row)):
        span = _find(page.text, [printed], a, b, page.taken) or _around_marks(page, printed, a, b)
        if span is not None:
            _add(page, span, key=f"{id_of(row)}~term{i}", css=f"{css_of(row)} wrong",
                 note=ALSO_WRONG if terms else note, anchored=True, forms=(printed,),
                 how="term", nests=not _free(page, span), **base)  # fmt: skip
            terms += 1
    label = text_of(row, "equation")
    span = _label_place(page.text, label, page.segments, region) if label else None
    if span is not None and _free(page, span):
        label_note = "the wrong term is marked in the formula" if terms else note
        if not terms and note and verdict_of(row) in ("misprint", "fails"):
            label_note += " (the ledger records no wrong term: the label is marked)"
        _add(page, span, key=id_of(row), css=css_of(row), note=label_note, anchored=True,
             forms=(label,), how="label", **base)  # fmt: skip
        return True
    return terms > 0


def _around_marks(page: _Page, printed: str, a: int, b: int) -> tuple[int, int] | None:
    """The first occurrence of ``printed`` in text[a:b] that holds whole the marks it meets:
    a wrong table entry is drawn around its claim's mark (0^{sec}, 94 is both the claim's
    printed number and the ledger row's wrong term), never across part of one."""
    pattern = _pattern(printed)
    for m in pattern.finditer(page.text, a, b) if pattern else ():
        x, y = m.span()
        if all(e <= x or s >= y or (x <= s and e <= y) for s, e in page.taken):
            return x, y
    return None


def quotes_of(row: Row) -> list[str]:
    """The words of the text the row rests on (its ``quote``: a string or a list)."""
    value = row.get("quote")
    if isinstance(value, str):
        return [value] if value else []
    return [str(v) for v in value] if isinstance(value, list | tuple) else []


def _place_own_quotes(page: _Page, row: Row, region: tuple[int, int]) -> bool:
    """Each of the row's ``quote``s, found verbatim inside its lines, marked as it is printed:
    its prose, and the formulas it runs through, each a piece of the mark (a prose mark
    cannot reach into a formula). A quote may hold a claim's mark whole (the claim's number
    in the sentence). The first piece carries the note. Whether every quote was marked."""
    pieces: list[tuple[tuple[int, int], bool, str]] = []
    for quote in quotes_of(row):
        span = _verbatim(page, quote, *region)
        if span is None:
            return False
        pieces += [(piece, whole, quote) for piece, whole in _quote_pieces(page, *span)]
    # a row with wrong terms shows its reading or correction at the first of them, once
    note = "" if _printed_terms(row) else _equation_note(row)
    for i, (span, whole, quote) in enumerate(pieces):
        base = {**_row_base(row), "finding": disagrees(row) and i == 0}  # its note, once
        _add(page, span, key=id_of(row) if i == 0 else f"{id_of(row)}~quote{i}",
             css=css_of(row), note="" if i else note, anchored=True,
             forms=(quote,), how="quote", whole=whole, nests=not whole and not _free(page, span),
             continues=id_of(row) if i else "", **base)  # fmt: skip
    return bool(pieces)


def _verbatim(page: _Page, quote: str, a: int, b: int) -> tuple[int, int] | None:
    """The first occurrence of ``quote`` in text[a:b] that meets only marks it holds whole."""
    at = page.text.find(quote, a, b)
    while at >= 0:
        x, y = at, at + len(quote)
        if all(e <= x or s >= y or (x <= s and e <= y) for s, e in page.taken):
            return x, y
        at = page.text.find(quote, at + 1, b)
    return None


def _quote_pieces(page: _Page, a: int, b: int) -> list[tuple[tuple[int, int], bool]]:
    """text[a:b] cut where formulas begin and end: its prose stretches and, of each formula
    it meets, the TeX it covers (the whole formula where that part does not balance). Each
    piece with whether it is drawn around a whole formula."""
    out: list[tuple[tuple[int, int], bool]] = []
    pos = a
    for s in (s for s in page.segments if s.start < b and a < s.end):
        if pos < s.start:
            out.append((_strip(page.text, pos, s.start), False))
        x, y = _strip(page.text, max(a, s.tex_start), min(b, s.tex_end))
        if not balanced(page.text[x:y]):
            x, y = _strip(page.text, s.tex_start, s.tex_end)
        out.append(((x, y), (x, y) == _strip(page.text, s.tex_start, s.tex_end) and s.display))
        pos = s.end
    if pos < b:
        out.append((_strip(page.text, pos, b), False))
    return [(span, whole) for span, whole in out if re.search(r"\w", page.text[slice(*span)])]


def _place_quote(page: _Page, row: Row, region: tuple[int, int]) -> bool:
    """The row's quoted words inside its lines, where it has any."""
    for quote in _quotes(row):
        span = _find(page.text, [quote], *region, page.taken)
        if span is not None:
            _add(page, span, key=id_of(row), css=css_of(row), note=_equation_note(row),
                 anchored=True, forms=(quote,), how="quote", **_row_base(row))  # fmt: skip
            return True
    return False


# How near a formula's atoms must be to the printed form's to be taken for it (a share of
# atoms in common): the rows' own formulas score 0.5 to 1, their neighbours mostly below.
NEAR = 0.5


def _place_formulas(page: _Page, row: Row, region: tuple[int, int]) -> bool:
    """Each formula of the row's printed form (else of its statement) marked at the piece of
    its lines nearest to it (:func:`pendcli.html_match.best_pieces`), if near enough: one
    line or equation of a display where it can be drawn alone, else the whole display. The
    first mark carries the note; a misprint or failure whose wrong term the ledger does not
    record says so beside its reading or correction."""
    from pendcli.html_match import best_pieces, formula_parts

    source = text_of(row, "printed") or text_of(row, "statement")
    parts = formula_parts(source)
    spans: list[tuple[tuple[int, int], bool, str]] = []
    for piece, score, number in best_pieces(page.text, page.segments, region, source):
        span, whole = (piece.start, piece.end), piece.whole
        if not whole and not (balanced(page.text[span[0] : span[1]]) and _free(page, span)):
            span, whole = (piece.segment.tex_start, piece.segment.tex_end), True
        if whole:
            span = _strip(page.text, *span)
        if score >= NEAR and span not in [s for s, _, _ in spans]:
            spans.append((span, whole, parts[number]))
            spans += [(c, True, parts[number]) for c in _continuations(page, piece.segment, region)]
    note = _equation_note(row)
    if note and verdict_of(row) in ("misprint", "fails"):
        note += " (the ledger records no wrong term: the formula is marked)"
    for i, (span, whole, part) in enumerate(spans):
        base = {**_row_base(row), "finding": disagrees(row) and i == 0}  # its note, once
        _add(page, span, key=id_of(row) if i == 0 else f"{id_of(row)}~formula{i}",
             css=css_of(row), note="" if i else note, anchored=True, forms=(part,),
             how="formula", whole=whole, continues=id_of(row) if i else "", **base)  # fmt: skip
    return bool(spans)


def _free(page: _Page, span: tuple[int, int]) -> bool:
    return all(span[1] <= a or span[0] >= b for a, b in page.taken)


def _continuations(
    page: _Page, segment: MathSegment, region: tuple[int, int]
) -> list[tuple[int, int]]:
    """The display formulas right after ``segment`` in the region that go on with it (they
    begin with + or −: one formula printed over several displays)."""
    out = []
    following = [s for s in page.segments if s.start >= segment.end and s.tex_end <= region[1]]
    for s in following:
        if not (s.display and re.match(r"\s*[+\-−]", page.text[s.tex_start : s.tex_end])):
            break
        out.append(_strip(page.text, s.tex_start, s.tex_end))
    return out


def _place_generic(page: _Page, row: Row, region: tuple[int, int]) -> None:
    """The first free display formula of the row's lines as its place (what a stated result
    states), else their first free sentence; a note at their first line where every piece of
    them is taken already."""
    span = next((s for s in _pieces(page, region) if _free(page, s)), None)
    base, note = _row_base(row), _equation_note(row)
    if span is None:
        at = region[0]
        mark = Placement(at, at, key=id_of(row), css=css_of(row), note=note, anchored=True,
                         lines=covered_lines(page.text, at, at), **base)  # fmt: skip
        page.passages.append((at, mark))
        return
    _add(page, span, key=id_of(row), css=css_of(row), note=note, anchored=True,
         forms=(page.text[span[0] : span[1]],), generic=True, how="first", **base)  # fmt: skip


_SENTENCE_END = re.compile(r"(?<=[.;:!?])\s|\n")


def _pieces(page: _Page, region: tuple[int, int]) -> list[tuple[int, int]]:
    """The row's lines cut into markable pieces: each display formula inside them (its TeX,
    or its longest free stretch between marks already there), then each sentence of prose
    (cut at a formula, which a prose mark cannot cross), each in reading order."""
    a, b = region
    formulas: list[tuple[int, int]] = []
    sentences: list[tuple[int, int]] = []
    pos = a
    for s in [s for s in page.segments if s.end > a and s.start < b]:
        sentences.extend(_sentences(page.text, pos, max(pos, s.start)))
        if s.display and a <= s.tex_start and s.tex_end <= b:
            formulas.extend(_free_stretches(page, s.tex_start, s.tex_end))
        pos = max(pos, s.end)
    sentences.extend(_sentences(page.text, pos, b))
    return formulas + sentences


def _sentences(text: str, a: int, b: int) -> list[tuple[int, int]]:
    out: list[tuple[int, int]] = []
    for piece in re.finditer(r"[^\n]+", text[a:b]):
        start = a + piece.start()
        cuts = [start, *(start + m.end() for m in _SENTENCE_END.finditer(piece.group(0))),
                a + piece.end()]  # fmt: skip
        out.extend(_strip(text, x, y) for x, y in itertools.pairwise(cuts))
    return [s for s in out if re.search(r"\w", text[s[0] : s[1]])]


def _strip(text: str, a: int, b: int) -> tuple[int, int]:
    while a < b and text[a].isspace():
        a += 1
    while b > a and text[b - 1].isspace():
        b -= 1
    return a, b


def _free_stretches(page: _Page, a: int, b: int) -> list[tuple[int, int]]:
    """A formula's TeX, whole when free (a mark that does not balance is drawn around the
    whole formula), else its longest balanced stretch between marks."""
    taken = sorted((max(a, x), min(b, y)) for x, y in page.taken if x < b and y > a)
    if not taken:
        return [_strip(page.text, a, b)]
    edges = [a, *(e for x, y in taken for e in (x, y)), b]
    stretches = [_strip(page.text, x, y) for x, y in zip(edges[::2], edges[1::2], strict=True)]
    ok = [(x, y) for x, y in stretches if re.search(r"\w", page.text[x:y])
          and balanced(page.text[x:y])]  # fmt: skip
    return sorted(ok, key=lambda s: s[0] - s[1])[:1]


def _clauses(text: str, count: int) -> str:
    """The first ``count`` clauses of a note (split at "; "): what fits in the margin."""
    parts = text.split("; ")
    return "; ".join(parts[:count]) + (" …" if len(parts) > count else "")


def _printed_terms(row: Row) -> list[str]:
    """The wrong term as the OCR prints it (the ledger's ``wrong_term``), when recorded."""
    value = row.get("wrong_term")
    if isinstance(value, str):
        return [value] if value else []
    return [str(v) for v in value] if isinstance(value, list | tuple) else []


def printed_form(published: str) -> str:
    """A printed number as the paper sets it, not as TeX: ``0^{sec},94`` is 0ˢᵉᶜ,94, and
    ``-1,27`` is −1,27 (the typeset minus of the page)."""
    from pendcli.core.numbers import edition_minus
    from pendcli.core.reader_text import UNIT_FORMS, UNIT_TEX

    return edition_minus(UNIT_TEX.sub(lambda m: UNIT_FORMS[m.group(1)], published))


def _claim_note(row: Row) -> str:
    recomputed = number_text(row.get("recomputed"))
    unit = text_of(row, "unit")
    printed = printed_form(text_of(row, "published"))
    text = f"printed {printed}, recomputed {recomputed} {unit}".rstrip()
    cause = word_of(row.get("cause"))
    own = f"; against his procedure, {own_of(row)}" if row.get("procedure_verdict") else ""
    # a verdict that turns on an unstated assumption names each side, as the ledger's rows do
    condition = f"; {text_of(row, 'condition')}" if row.get("condition") else ""
    return f"{text}{own}{condition}; {cause}" if cause and disagrees(row) else text + condition


def _equation_note(row: Row) -> str:
    correction = correction_of(row)
    if correction:
        return correction
    readings = text_of(row, "readings")  # the OCR's substitutions the row is read through
    return f"OCR, read: {readings}" if readings else ""


def correction_of(row: Row) -> str:
    """The reading of a misprint or the correction of a failure, once."""
    if text_of(row, "reading"):
        return f"read {text_of(row, 'reading')}"
    if text_of(row, "corrected"):
        return f"corrected: {text_of(row, 'corrected')}"
    return ""
