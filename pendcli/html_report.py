"""``out/report.html`` and ``out/papers/<paper>.html``: the report and an annotated edition.

Each paper page is the paper's OCR text (``tables/papers/<paper>.txt``) as an edition: its
TeX rendered as MathML at build time (:mod:`pendcli.html_math`), each printed number,
equation label and stated result marked where it is printed, a misprinted or wrong term
marked itself, and beside each paragraph a numbered note per mark with the verdict and the
reading or the correction. The overview page carries the counts, the propagation graph
(:mod:`pendcli.html_graph`) and one entry per finding. The pages come from the Jinja2
templates in ``pendcli/templates`` (autoescaped; one stylesheet, inlined), figures are data
URIs: nothing is fetched. Everything here works on row dicts (``as_dict()`` of the rows),
read through the small accessors below: it knows the report's keys, not pendulums.
"""

from __future__ import annotations

import base64
import itertools
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.core.vocabulary import (
    CLAIM_VERDICTS,
    STATUSES,
)
from pendcli.html_math import (
    balanced,
    mark_mathml,
    math_segments,
    plain_math,
    to_mathml,
    wrap_marks,
)

if TYPE_CHECKING:
    from jinja2 import Environment
    from markupsafe import Markup

    from pendcli.core.rows import EquationRow
    from pendcli.html_math import MathSegment
    from pendcli.reproduce import ReproduceResult

__all__ = [
    "Figure",
    "Placement",
    "locate",
    "paper_page",
    "place_marks",
    "print_pdfs",
    "propagation_svg",
    "render_stats",
    "report_page",
    "write_for_result",
    "write_html_report",
]

Row = Mapping[str, object]

VERDICT_CLASSES = CLAIM_VERDICTS
STATUS_CLASSES = STATUSES
# The cause of an equation row follows from its status (pendcli.core.causes' vocabulary).
_EQUATION_CAUSE = {"fails": "derivation-error", "misprint": "misprint"}


@dataclass(frozen=True)
class Figure:
    """A figure file and the caption the report prints under it."""

    path: Path
    caption: str


# --- accessors: the only places that know the rows' keys ------------------------------------


def _word(value: object) -> str:
    """A verdict, status or cause as its word (an enum's value, or the string)."""
    value = getattr(value, "value", value)
    return "" if value is None else str(value)


def _id(row: Row) -> str:
    return str(row["id"])


def _verdict(row: Row) -> str:
    return _word(row.get("verdict") or row.get("status"))


def _text(row: Row, key: str) -> str:
    value = row.get(key)
    return "" if value is None else str(value)


def _sources(row: Row) -> list[str]:
    """The ids a propagated row inherits from (its ``from`` key)."""
    value = row.get("from")
    return [str(s) for s in value] if isinstance(value, list | tuple) else []


def _number(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.10g}"
    return "" if value is None else str(value)


def _disagrees(row: Row) -> bool:
    return _verdict(row) in ("truncated", "last-digit", "discrepant", "fails", "misprint")


def _css(row: Row) -> str:
    word = _verdict(row)
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


def _blocks(text: str, segments: Sequence[MathSegment]) -> list[tuple[int, int]]:
    """The paragraphs of ``text``: split at blank lines outside display formulas."""
    inside = [(s.start, s.end) for s in segments if s.display]
    cuts = [m.start() for m in re.finditer(r"\n[ \t]*\n", text)
            if not any(a < m.start() < b for a, b in inside)]  # fmt: skip
    edges = [0, *cuts, len(text)]
    return [(a, b) for a, b in itertools.pairwise(edges) if text[a:b].strip()]


def _label_place(text: str, label: str, segments: Sequence[MathSegment]) -> tuple[int, int] | None:
    """Where ``label`` is printed as a label: in display mathematics, at a line's start (after
    $$, \\\\ or \\begin{…}) or in the margin after a \\quad; else anywhere in a display."""
    token = re.escape(label)
    at_start = re.compile(rf"(?:^\s*|\\\\\s*|\\begin\{{\w+\*?\}}\s*|\\left\\{{\s*){token}")
    in_margin = re.compile(rf"\\q?quad\s*{token}")
    displays = [s for s in segments if s.display]
    for pattern in (at_start, in_margin, re.compile(token)):
        for s in displays:
            m = pattern.search(text, s.tex_start, s.tex_end)
            if m is not None:
                return m.end() - len(label), m.end()
    return None


def _quotes(row: Row) -> list[str]:
    return [q for key in ("source", "section", "ocr", "statement", "note")
            for q in _QUOTE.findall(_text(row, key))]  # fmt: skip


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
    label = _text(row, "equation")
    span = _label_place(text, label, segments) if label else None
    if span is not None:
        out.append(_paragraphs(blocks, span[0], 0, 0))
    where = _text(row, "section") + " " + _text(row, "source")
    m = _AFTER.search(where)
    span = _label_place(text, m.group(2), segments) if m else None
    if m and span is not None:
        before = m.group(1) == "before"
        out.append(_paragraphs(blocks, span[0], -3, 0) if before else
                   (span[1], _next_label(text, span[1], segments)))  # fmt: skip
    m = _IN_LABEL.search(_text(row, "source"))
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
    anchored: bool  # found at the row's own place (its quoted words, label or "after (N)")
    forms: tuple[str, ...] = ()  # the printed strings it was looked for by


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

    A row is looked for inside its regions (:func:`_regions`) first; found there it is
    *anchored*. A row with no region is looked for by its printed string in reading order.
    """
    segments = math_segments(text)
    page = _Page(text, segments, _blocks(text, segments))
    for row in claims:
        _place_claim(page, row)
    for row in equations:
        _place_equation(page, row)
    return sorted(page.marks, key=lambda m: m.start), page.passages


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


def _standalone(page: _Page, number: str) -> tuple[int, int] | None:
    """A bare number printed alone (a table's cell, between blanks, outside any formula),
    after the previous claim: "2" is the table's entry, not the factor 2 of a formula."""
    pattern = re.compile(rf"(?<=\s){re.escape(number)}(?=\s)")
    for m in pattern.finditer(page.text, page.cursor):
        free = all(m.end() <= a or m.start() >= b for a, b in page.taken)
        if free and not any(s.start <= m.start() < s.end for s in page.segments):
            return m.span()
    return None


def _add(page: _Page, span: tuple[int, int], **kw: Any) -> None:
    page.taken.append(span)
    page.marks.append(Placement(span[0], span[1], **kw))


def _place_claim(page: _Page, row: Row) -> None:
    forms = tuple(f for f in (_text(row, "as_printed"), _text(row, "published")) if f)
    regions = _regions(page.text, row, page.segments, page.blocks)
    span, anchored = _search(page, forms, regions)
    if not regions and all(_BARE.match(f) for f in forms):
        span = _standalone(page, forms[0]) or span
    base = {"row_id": _id(row), "css": _css(row), "word": _verdict(row), "finding": _disagrees(row)}
    if span is not None:
        page.cursor = span[0]
        _add(
            page, span, key=_id(row), note=_claim_note(row), anchored=anchored, forms=forms, **base
        )
    for i, quote in enumerate(_QUOTE.findall(_text(row, "ocr"))):  # the words it reads
        reading = _first_free(page.text, quote, 0, len(page.text), page.taken)
        if reading is not None:
            base.update(css="s-reading wrong", word="reading", finding=True)
            _add(page, reading, key=f"{_id(row)}~reading{i}", note=_clauses(_text(row, "ocr"), 2),
                 anchored=True, forms=(quote,), **base)  # fmt: skip


def _place_equation(page: _Page, row: Row) -> None:
    """The label at its place, the wrong term itself (its note carries the correction), or
    else a note at the passage the row follows."""
    regions = _regions(page.text, row, page.segments, page.blocks)
    base: dict[str, Any] = {"row_id": _id(row), "word": _verdict(row), "finding": _disagrees(row)}
    note = _equation_note(row)
    terms = 0
    for i, printed in enumerate(_printed_terms(row)):
        span, anchored = _search(page, [printed], regions)
        if span is not None:
            _add(page, span, key=f"{_id(row)}~term{i}", css=f"{_css(row)} wrong", note=note,
                 anchored=anchored, forms=(printed,), **base)  # fmt: skip
            terms += 1
    label = _text(row, "equation")
    span = _label_place(page.text, label, page.segments) if label else None
    if span is not None and all(span[1] <= a or span[0] >= b for a, b in page.taken):
        label_note = "the wrong term is marked in the formula" if terms else note
        _add(page, span, key=_id(row), css=_css(row), note=label_note, anchored=True,
             forms=(label,), **base)  # fmt: skip
    elif not terms and regions:
        at = regions[0][0]
        mark = Placement(at, at, key=_id(row), css=_css(row), note=note, anchored=True, **base)
        page.passages.append((at, mark))


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


def _claim_note(row: Row) -> str:
    recomputed = _number(row.get("recomputed"))
    unit = _text(row, "unit")
    text = f"printed {_text(row, 'published')}, recomputed {recomputed} {unit}".rstrip()
    cause = _word(row.get("cause"))
    return f"{text}; {cause}" if cause and _disagrees(row) else text


def _equation_note(row: Row) -> str:
    correction = _correction(row)
    if correction:
        return correction
    return ""


def _correction(row: Row) -> str:
    """The reading of a misprint or the correction of a failure, once."""
    if _text(row, "reading"):
        return f"read {_text(row, 'reading')}"
    if _text(row, "corrected"):
        return f"corrected: {_text(row, 'corrected')}"
    return ""


# --- the text rendered: prose escaped, formulas as MathML, marks inside both ----------------


@dataclass
class RenderStats:
    """How the page's formulas were rendered: MathML, or the plain reading where it failed."""

    formulas: int = 0
    mathml: int = 0
    plain: int = 0
    widened: int = 0  # marks drawn around their whole formula (their TeX did not balance)


def render_stats(text: str) -> RenderStats:
    """The conversion rate over every formula of ``text`` (no marks)."""
    stats = RenderStats()
    for s in math_segments(text):
        stats.formulas += 1
        ok = to_mathml(text[s.tex_start : s.tex_end], s.display) is not None
        stats.mathml += ok
        stats.plain += not ok
    return stats


_STRAY_TEX = re.compile(r"\\[A-Za-z]+(?:\{[^{}]*\})?(?:_\{?\w+\}?)?|\b\w_\{[^{}]*\}")


def _prose(piece: str) -> str:
    """Prose escaped, its stray TeX (``\\mathbf{E}_c`` outside dollars) read plainly, its
    Markdown emphasis kept."""
    from markupsafe import escape

    piece = _STRAY_TEX.sub(lambda m: plain_math(m.group(0)), piece)
    piece = re.sub(r"(?<=[^\W\d_])_([0-9])(?!\d)", lambda m: plain_math("_" + m.group(1)), piece)
    piece = re.sub(r"(?<=\d)\^e\b", "ᵉ", piece).replace("\t", "\u2003\u2003")
    out = str(
        escape(re.sub(r"(?<=\w)\^([0-9])(?!\d)", lambda m: plain_math("^" + m.group(1)), piece))
    )
    out = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", out)
    return re.sub(r"(?<![\w*])\*(?!\s)(.+?)(?<!\s)\*(?![\w*])", r"<i>\1</i>", out)


def _call(mark: Placement, number: int) -> str:
    return f'<sup class="call"><a href="#note-{_attr(mark.key)}">{number}</a></sup>'


def _attr(value: str) -> str:
    from markupsafe import escape

    return str(escape(value))


def _open(mark: Placement) -> str:
    return (
        f'class="hl {_attr(mark.css)}" id="at-{_attr(mark.key)}" '
        f'title="{_attr(mark.row_id)}: {_attr(mark.word)}"'
    )


def _render_span(page_text: str, a: int, b: int, marks: Sequence[Placement],
                 segments: Sequence[MathSegment], numbers: Mapping[str, int],
                 stats: RenderStats) -> str:  # fmt: skip
    """Text [a, b): formulas and prose in order, each mark at its place."""
    out: list[str] = []
    pos = a
    for s in [s for s in segments if a <= s.start and s.end <= b]:
        out.append(_render_prose(page_text, pos, s.start, marks, numbers))
        inner = [m for m in marks if m.start < s.end and s.start < m.end and m.end > m.start]
        out.append(_render_formula(page_text, s, inner, numbers, stats))
        pos = s.end
    out.append(_render_prose(page_text, pos, b, marks, numbers))
    return "".join(out)


def _render_prose(text: str, a: int, b: int, marks: Sequence[Placement],
                  numbers: Mapping[str, int]) -> str:  # fmt: skip
    out, pos = [], a
    for m in (m for m in marks if a <= m.start and m.end <= b and m.end > m.start):
        out.append(_prose(text[pos : m.start]))
        href = f"#row-{_attr(m.row_id)}"
        out.append(f'<a {_open(m)} href="{href}">{_prose(text[m.start : m.end])}</a>')
        out.append(_call(m, numbers[m.key]))
        pos = m.end
    out.append(_prose(text[pos:b]))
    return "".join(out)


def _render_formula(text: str, s: MathSegment, marks: Sequence[Placement],
                    numbers: Mapping[str, int], stats: RenderStats) -> str:  # fmt: skip
    """One formula as MathML with its marks as ``<mrow class="hl">`` and their calls."""
    tex = text[s.tex_start : s.tex_end]
    inside = [m for m in marks if s.tex_start <= m.start and m.end <= s.tex_end
              and balanced(text[m.start : m.end])]  # fmt: skip
    around = [m for m in marks if m not in inside]
    spans = [(m.start - s.tex_start, m.end - s.tex_start, i) for i, m in enumerate(inside)]
    mathml = to_mathml(wrap_marks(tex, spans), s.display) if inside else None
    if mathml is None:
        around, inside = [*around, *inside], []
        mathml = to_mathml(tex, s.display)
    if mathml is None:  # not converted: the plain reading, marks around it
        stats.plain += 1
        body = f'<span class="plain-math">{_attr(plain_math(tex))}</span>'
    else:
        stats.mathml += 1
        body = mark_mathml(
            mathml,
            lambda i: f"<msup><mrow {_open(inside[i])}>",
            lambda i: (
                f'<mtext class="call"><a href="#note-{_attr(inside[i].key)}">'
                f"{numbers[inside[i].key]}</a></mtext></msup>"
            ),
        )
    stats.formulas += 1
    stats.widened += len(around)
    for m in around:
        body = f"<span {_open(m)}>{body}</span>{_call(m, numbers[m.key])}"
    return f'<div class="display">{body}</div>' if s.display else body


# --- the pages ------------------------------------------------------------------------------


@cache
def _environment() -> Environment:
    from jinja2 import Environment, PackageLoader, StrictUndefined

    return Environment(
        loader=PackageLoader("pendcli", "templates"),
        autoescape=True,
        undefined=StrictUndefined,
        keep_trailing_newline=True,
    )


def _render(template: str, **context: object) -> str:
    return _environment().get_template(template).render(**context)


def _markup(html: str) -> Markup:
    from markupsafe import Markup

    return Markup(html)


def _legend() -> list[dict[str, str]]:
    words = [*VERDICT_CLASSES, *STATUS_CLASSES]
    return [{"css": f"v-{w}" if w in VERDICT_CLASSES else f"s-{w}", "word": w} for w in words]


def _figures(figures: Sequence[Figure]) -> list[dict[str, str]]:
    return [
        {"stem": f.path.stem, "caption": f.caption,
         "data": base64.b64encode(f.path.read_bytes()).decode("ascii")}
        for f in figures
    ]  # fmt: skip


def cited_formulas(equations: Sequence[Row], formulas: Sequence[Row]) -> dict[str, list[Row]]:
    """The formula rows each equation row's check cites: one entry for both checks."""
    out: dict[str, list[Row]] = {}
    for formula in formulas:
        pattern = re.compile(rf"(?<![\w.]){re.escape(_id(formula))}(?![\w.])")
        named = [eq for eq in equations if _same_equation(_id(formula), eq)]
        for eq in named or equations:
            if named or pattern.search(_text(eq, "check") + " " + _text(eq, "corrected")):
                out.setdefault(_id(eq), []).append(formula)
    return out


def _same_equation(formula_id: str, equation: Row) -> bool:
    """A formula check named after the equation's label: ``lecornu.eq52`` is (52)."""
    label = _text(equation, "equation").strip("()").replace("'", "prime")
    paper = _id(equation).split(".", 1)[0]
    return (
        bool(label)
        and re.fullmatch(rf"{paper}\.eq{re.escape(label)}(?:[._].*)?", formula_id) is not None
    )


def _text_blocks(text: str, marks: Sequence[Placement], passages: Sequence[tuple[int, Placement]],
                 stats: RenderStats) -> list[dict[str, object]]:  # fmt: skip
    segments = math_segments(text)
    numbers = {m.key: i for i, m in enumerate(sorted([*marks, *(p for _, p in passages)],
                                                     key=lambda m: m.start), 1)}  # fmt: skip
    blocks = []
    for a, b in _blocks(text, segments):
        inside = [m for m in marks if a <= m.start < b]
        notes = sorted([*inside, *(p for at, p in passages if a <= at < b)],
                       key=lambda m: numbers[m.key])  # fmt: skip
        html = _render_span(text, a, b, inside, segments, numbers, stats)
        blocks.append({
            "html": _markup(html.strip().replace("\n", "<br>")),
            "heading": text[a:b].lstrip().startswith("#"),
            "notes": [_note(m, numbers[m.key]) for m in notes],
        })  # fmt: skip
    return blocks


def _note(mark: Placement, number: int) -> dict[str, object]:
    return {"n": number, "key": mark.key, "row": mark.row_id, "css": mark.css.split()[0],
            "word": mark.word, "text": mark.note, "finding": mark.finding}  # fmt: skip


def _claim_rows(claims: Sequence[Row], at: Mapping[str, str]) -> list[dict[str, object]]:
    return [
        {"id": _id(r), "at": at.get(_id(r), ""), "css": _css(r), "word": _verdict(r),
         "source": _text(r, "source"), "published": _text(r, "published"),
         "unit": _text(r, "unit"), "recomputed": _number(r.get("recomputed")),
         "exact": _number(r.get("exact")), "cause": _word(r.get("cause")),
         "sources": _sources(r), "note": _text(r, "note")}
        for r in claims
    ]  # fmt: skip


def _formula_cell(r: Row) -> dict[str, object]:
    order = r.get("observed_order")
    return {"id": _id(r), "css": _css(r), "word": _verdict(r),
            "order": f"{order:.2f}" if isinstance(order, float) else ""}  # fmt: skip


def _equation_rows(equations: Sequence[Row], cited: Mapping[str, Sequence[Row]],
                   at: Mapping[str, str]) -> list[dict[str, object]]:  # fmt: skip
    return [
        {"id": _id(r), "at": at.get(_id(r), ""), "css": _css(r), "word": _verdict(r),
         "label": _text(r, "equation"), "section": _text(r, "section"),
         "statement": _text(r, "statement"), "cause": _EQUATION_CAUSE.get(_verdict(r), ""),
         "correction": _correction(r), "check": _text(r, "check"),
         "formulas": [_formula_cell(f) for f in cited.get(_id(r), [])],
         "note": _text(r, "ledger_note") if "ledger_note" in r else _text(r, "note")}
        for r in equations
    ]  # fmt: skip


def _formula_rows(formulas: Sequence[Row]) -> list[dict[str, object]]:
    return [
        {"id": _id(r), "at": "", "css": _css(r), "word": _verdict(r),
         "source": _text(r, "source"), "published": _text(r, "published"),
         "recomputed": _text(r, "recomputed"), "claimed_order": _number(r.get("claimed_order")),
         "observed_order": _number(r.get("observed_order")), "cause": _word(r.get("cause")),
         "sources": _sources(r), "note": _text(r, "note")}
        for r in formulas
    ]  # fmt: skip


def paper_page(
    paper: str,
    citation: str,
    text: str,
    claims: Sequence[Row],
    formulas: Sequence[Row] = (),
    equations: Sequence[Row] = (),
    figures: Sequence[Figure] = (),
    stats: RenderStats | None = None,
) -> str:
    """One paper as an annotated edition, then its claims, equations, formulas and figures."""
    stats = stats if stats is not None else RenderStats()
    marks, passages = place_marks(text, claims, equations)
    at: dict[str, str] = {}
    for m in [*marks, *(p for _, p in passages)]:
        at.setdefault(m.row_id, f"at-{m.key}" if m.end > m.start else f"note-{m.key}")
    cited = cited_formulas(equations, formulas)
    merged = {_id(f) for fs in cited.values() for f in fs}
    alone = [f for f in formulas if _id(f) not in merged]
    findings = [_id(r) for r in [*claims, *equations, *alone] if _disagrees(r)]
    blocks = _text_blocks(text, marks, passages, stats)
    return _render(
        "paper.html.j2",
        title=f"pendcli: {paper}", lang="fr", paper=paper, citation=citation, legend=_legend(),
        placed=_placed_text(claims, equations, marks, passages, stats), findings=findings,
        blocks=blocks, claims=_claim_rows(claims, at),
        equations=_equation_rows(equations, cited, at), formulas=_formula_rows(alone),
        figs=_figures(figures),
    )  # fmt: skip


def _placed_text(claims: Sequence[Row], equations: Sequence[Row], marks: Sequence[Placement],
                 passages: Sequence[tuple[int, Placement]], stats: RenderStats) -> str:  # fmt: skip
    anchored = {m.row_id for m in marks if m.anchored} | {p.row_id for _, p in passages}
    by_string = {m.row_id for m in marks} - anchored
    rows = [_id(r) for r in [*claims, *equations]]
    n_anchored = sum(r in anchored for r in rows)
    n_string = sum(r in by_string for r in rows)
    wrong = sum(m.key.split("~")[-1].startswith(("term", "reading")) for m in marks)
    return (
        f"{n_anchored} of {len(rows)} rows placed at their own place in the text (by their "
        f"label, their quoted words, or the equation or numbered section they belong to), "
        f"{n_string} found by their printed string alone (place not verified), "
        f"{len(rows) - n_anchored - n_string} not placed; {wrong} wrong terms or misread words "
        f"marked. Formulas: {stats.mathml} of {stats.formulas} rendered as MathML, "
        f"{stats.plain} as a plain reading."
    )


# --- the overview page ----------------------------------------------------------------------


def propagation_svg(rows: Sequence[Row]) -> str:
    """The layered graph of the slips: each root on the left, what inherits it to its right."""
    from pendcli.html_graph import layered_graph

    ids = {_id(r) for r in rows}
    edges = [(s, _id(r)) for r in rows for s in _sources(r) if s in ids]
    if not edges:
        return "<p>No row inherits a slip from another.</p>"
    nodes = sorted({n for e in edges for n in e})
    propagated = {_id(r) for r in rows if _word(r.get("cause")) == "propagated"}
    svg, _, _ = layered_graph(
        nodes, edges, lambda n: f"{_page_of(n)}#row-{n}", lambda n: n not in propagated
    )
    return svg


def _page_of(row_id: str) -> str:
    return f"papers/{row_id.split('.', 1)[0]}.html"


def _tally(rows: Iterable[Row], word: Any) -> dict[str, int]:
    out: dict[str, int] = {}
    for r in rows:
        out[word(r)] = out.get(word(r), 0) + 1
    return out


def _findings(
    papers: Sequence[str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
) -> list[dict[str, object]]:
    """One entry per finding: claims, equations (citing their formula checks), and the
    formula checks no equation row cites."""
    out: list[dict[str, object]] = []
    for p in papers:
        cited = cited_formulas(equations.get(p, []), formulas.get(p, []))
        merged = {_id(f) for fs in cited.values() for f in fs}
        for r in claims.get(p, []):
            out.append(_entry(p, r, _word(r.get("cause")), "", _text(r, "note")))
        for r in equations.get(p, []):
            note = _text(r, "ledger_note") if "ledger_note" in r else ""
            entry = _entry(p, r, _EQUATION_CAUSE.get(_verdict(r), ""), _correction(r), note)
            entry["formulas"] = [_formula_cell(f) for f in cited.get(_id(r), [])]
            out.append(entry)
        for r in formulas.get(p, []):
            if _id(r) not in merged:
                correction = _text(r, "recomputed")
                out.append(_entry(p, r, _word(r.get("cause")), correction, _text(r, "note")))
    return [e for e in out if e.pop("disagrees")]


def _entry(paper: str, row: Row, cause: str, correction: str, note: str) -> dict[str, object]:
    return {
        "paper": paper,
        "id": _id(row),
        "word": _verdict(row),
        "formulas": [],
        "cause": cause,
        "sources": _sources(row),
        "correction": correction,
        "note": note,
        "disagrees": _disagrees(row),
    }


def report_page(
    papers: Sequence[str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
    figures: Sequence[Figure] = (),
    intro: str = "",
) -> str:
    """The overview: counts, root slips and their propagation, the findings, figures."""
    every_claim = [r for p in papers for r in claims.get(p, [])]
    causes = {
        p: _tally((r for r in claims.get(p, []) if r.get("cause") and _disagrees(r)),
                  lambda r: _word(r.get("cause")))
        for p in papers
    }  # fmt: skip
    ledger = {p: _tally(equations.get(p, []), _verdict) for p in papers if equations.get(p)}
    return _render(
        "report.html.j2",
        title="pendcli reproduction report", intro=intro, papers=papers,
        verdicts={p: _tally(claims.get(p, []), _verdict) for p in papers},
        verdict_keys=VERDICT_CLASSES, causes=causes,
        cause_keys=sorted({c for t in causes.values() for c in t}),
        graph=_markup(propagation_svg(every_claim)), ledger=ledger, status_keys=STATUS_CLASSES,
        findings=_findings(papers, claims, formulas, equations), figs=_figures(figures),
    )  # fmt: skip


def write_html_report(
    out: Path,
    papers: Sequence[str],
    citations: Mapping[str, str],
    texts: Mapping[str, str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
    figures: Mapping[str, Sequence[Figure]],
) -> list[Path]:
    """Write ``out/report.html`` and ``out/papers/<paper>.html`` (atomically); return them."""
    from pendcli.core.files import atomic_write

    (out / "papers").mkdir(parents=True, exist_ok=True)
    written = []
    for p in papers:
        page = paper_page(
            p,
            citations.get(p, ""),
            texts.get(p, ""),
            claims.get(p, []),
            formulas.get(p, []),
            equations.get(p, []),
            figures.get(p, []),
        )
        written.append(atomic_write(out / "papers" / f"{p}.html", page))
    page = report_page(papers, claims, formulas, equations, figures.get("", []))
    written.append(atomic_write(out / "report.html", page))
    return written


def _ledger_fields(paper: str, rows: Sequence[Row]) -> list[Row]:
    """The equation rows with the ledger's own reading, correction, printed term and note
    (the row's ``note`` joins them into one string)."""
    from pendcli.core.ledger import load_ledger
    from pendcli.papers.registry import ledger_papers

    if paper not in ledger_papers():
        return list(rows)
    recorded = {r.id: r for r in load_ledger(paper).rows}
    keys = ("reading", "corrected", "wrong_term", "note")
    return [
        {**row, **{("ledger_note" if k == "note" else k): getattr(recorded[_id(row)], k, None)
                   for k in keys}} if _id(row) in recorded else row
        for row in rows
    ]  # fmt: skip


def write_for_result(
    result: ReproduceResult,
    out: Path,
    figures: Mapping[str, Sequence[Figure]],
    equations: Mapping[str, Sequence[EquationRow]] | None = None,
) -> list[Path]:
    """The HTML pages of a reproduction: rows from ``result``, texts from tables/papers/."""
    from pendcli.core.tables import load_paper_table, tables_dir
    from pendcli.papers.registry import paper

    claims: dict[str, list[Row]] = {}
    for key in result.papers:
        printed = {c.id: c for c in load_paper_table(key).claims}
        claims[key] = [
            {**row.as_dict(), "as_printed": getattr(printed.get(row.id), "as_printed", ""),
             "ocr": getattr(printed.get(row.id), "ocr", "")}
            for row in result.claims.get(key, [])
        ]  # fmt: skip
    return write_html_report(
        out,
        result.papers,
        {key: paper(key).citation() for key in result.papers},
        {key: paper(key).tables(tables_dir()).text.read_text("utf-8") for key in result.papers},
        claims,
        {key: [f.as_dict() for f in result.formulas.get(key, [])] for key in result.papers},
        {
            key: _ledger_fields(key, [r.as_dict() for r in rows])
            for key, rows in (equations or {}).items()
        },
        figures,
    )


# --- printing -------------------------------------------------------------------------------

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")


def chromium() -> str | None:
    """The headless browser that prints the pages, where one is installed."""
    import shutil

    return next((p for p in map(shutil.which, CHROMIUM_NAMES) if p), None)


def require_chromium() -> str:
    """The headless browser that prints the pages; one line naming the package where absent."""
    from pendcli.core.errors import PendcliError

    browser = chromium()
    if browser is None:
        raise PendcliError("--pdf needs Chromium (apt-get install chromium); nothing was written")
    return browser


def print_pdfs(out: Path) -> list[Path]:
    """Print ``out/report.html`` and each paper page to PDF beside it (the print stylesheet
    makes a paper page an annotated edition on A4), with headless Chromium."""
    browser = require_chromium()
    pages = [out / "report.html", *sorted((out / "papers").glob("*.html"))]
    return [_print_pdf(browser, page) for page in pages if page.is_file()]


def _print_pdf(browser: str, page: Path) -> Path:
    """One page to PDF, written beside it atomically (printed to a temporary name first)."""
    import os
    import subprocess
    import tempfile

    from pendcli.core.errors import PendcliError

    target = page.with_suffix(".pdf")
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".pdf", dir=page.parent)
    os.close(fd)
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run(
            [browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={profile}", "--no-pdf-header-footer", f"--print-to-pdf={tmp}",
             page.resolve().as_uri()],
            capture_output=True, text=True, timeout=300, check=False,
        )  # fmt: skip
    if done.returncode != 0 or os.path.getsize(tmp) == 0:
        os.unlink(tmp)
        raise PendcliError(f"Chromium could not print {page.name} (exit {done.returncode})")
    os.chmod(tmp, 0o644)
    os.replace(tmp, target)
    return target
