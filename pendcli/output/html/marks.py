"""The marks of a paper's annotated page: which stretch of its OCR text each row marks.

:func:`place_marks` places every row of a page: a claim at its printed string, a ledger row
at its wrong terms, its label, the words it quotes, the formula its printed form is, or the
first free formula or sentence of its lines, each mark with the note beside it. Finding the
text is :mod:`~pendcli.output.html.locate`; what a row says, :mod:`~pendcli.output.html.rows`.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from pendcli.output.html.locate import (
    covered_lines,
    find,
    first_free,
    label_place,
    lines_region,
    ocr_pattern,
    paragraph_spans,
    row_regions,
)
from pendcli.output.html.math import balanced, math_segments
from pendcli.output.html.rows import (
    Row,
    claim_note,
    clauses,
    css_of,
    disagrees,
    equation_note,
    id_of,
    printed_terms,
    quoted_in,
    quoted_words,
    quotes_of,
    text_of,
    verdict_of,
)

if TYPE_CHECKING:
    from pendcli.output.html.math import MathSegment


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
    looked for inside its regions (:func:`~pendcli.output.html.locate.row_regions`), then by
    its printed string.
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


def _search(
    page: _Page, forms: Sequence[str], regions: Sequence[tuple[int, int]]
) -> tuple[tuple[int, int] | None, bool]:
    for region in regions:
        span = find(page.text, forms, region[0], region[1], page.taken)
        if span is not None:
            return span, True
    span = find(page.text, forms, page.cursor, len(page.text), page.taken)
    return span or find(page.text, forms, 0, len(page.text), page.taken), False


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
        span = (_standalone(page, forms[0], *region) if bare else None) or find(
            page.text, forms, *region, page.taken
        )
        anchored, how = span is not None, "value"
    else:
        regions = row_regions(page.text, row, page.segments, page.blocks)
        span, anchored = _search(page, forms, regions)
        if not regions and bare:
            span = _standalone(page, forms[0], page.cursor, len(page.text)) or span
        how = "value" if anchored else "string"
    base = {"row_id": id_of(row), "css": css_of(row), "word": verdict_of(row),
            "finding": disagrees(row)}  # fmt: skip
    if span is not None:
        page.cursor = span[0]
        _add(page, span, key=id_of(row), note=claim_note(row), anchored=anchored,
             forms=forms, how=how, **base)  # fmt: skip
    for i, quote in enumerate(quoted_in(text_of(row, "ocr"))):  # the words it reads
        lo, hi = region or (0, len(page.text))
        reading = first_free(page.text, quote, lo, hi, page.taken)
        if reading is not None:
            base.update(css="s-reading wrong", word="reading", finding=True)
            _add(page, reading, key=f"{id_of(row)}~reading{i}",
                 note=clauses(text_of(row, "ocr"), 2), anchored=True, forms=(quote,),
                 how="reading", **base)  # fmt: skip


def _place_equation(page: _Page, row: Row) -> None:
    """The label at its place, the wrong term itself (its note carries the correction), or
    else a note at the passage the row follows."""
    regions = row_regions(page.text, row, page.segments, page.blocks)
    base: dict[str, Any] = {
        "row_id": id_of(row),
        "word": verdict_of(row),
        "finding": disagrees(row),
    }
    note = equation_note(row)
    terms = 0
    for i, printed in enumerate(printed_terms(row)):
        span, anchored = _search(page, [printed], regions)
        if span is not None:
            _add(page, span, key=f"{id_of(row)}~term{i}", css=f"{css_of(row)} wrong", note=note,
                 anchored=anchored, forms=(printed,), how="term", **base)  # fmt: skip
            terms += 1
    label = text_of(row, "equation")
    span = label_place(page.text, label, page.segments) if label else None
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
    base, note = _row_base(row), equation_note(row)
    terms = 0
    for i, printed in enumerate(printed_terms(row)):
        span = find(page.text, [printed], a, b, page.taken) or _around_marks(page, printed, a, b)
        if span is not None:
            _add(page, span, key=f"{id_of(row)}~term{i}", css=f"{css_of(row)} wrong",
                 note=ALSO_WRONG if terms else note, anchored=True, forms=(printed,),
                 how="term", nests=not _free(page, span), **base)  # fmt: skip
            terms += 1
    label = text_of(row, "equation")
    span = label_place(page.text, label, page.segments, region) if label else None
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
    pattern = ocr_pattern(printed)
    for m in pattern.finditer(page.text, a, b) if pattern else ():
        x, y = m.span()
        if all(e <= x or s >= y or (x <= s and e <= y) for s, e in page.taken):
            return x, y
    return None


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
    note = "" if printed_terms(row) else equation_note(row)
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
    for quote in quoted_words(row):
        span = find(page.text, [quote], *region, page.taken)
        if span is not None:
            _add(page, span, key=id_of(row), css=css_of(row), note=equation_note(row),
                 anchored=True, forms=(quote,), how="quote", **_row_base(row))  # fmt: skip
            return True
    return False


# How near a formula's atoms must be to the printed form's to be taken for it (a share of
# atoms in common): the rows' own formulas score 0.5 to 1, their neighbours mostly below.
NEAR = 0.5


def _place_formulas(page: _Page, row: Row, region: tuple[int, int]) -> bool:
    """Each formula of the row's printed form (else of its statement) marked at the piece of
    its lines nearest to it (:func:`pendcli.output.html.match.best_pieces`), if near enough: one
    line or equation of a display where it can be drawn alone, else the whole display. The
    first mark carries the note; a misprint or failure whose wrong term the ledger does not
    record says so beside its reading or correction."""
    from pendcli.output.html.match import best_pieces, formula_parts

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
    note = equation_note(row)
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
    base, note = _row_base(row), equation_note(row)
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
