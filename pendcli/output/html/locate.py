"""Where a paper's OCR text prints what a row records.

A printed string is found tolerant of the OCR's TeX spacing and symbols (:func:`ocr_pattern`,
:func:`find`); a row without recorded lines is looked for in the stretches of text its
quoted words, its label or "after (N)" point to (:func:`row_regions`). Offsets and lines of the
text both ways (:func:`lines_region`, :func:`covered_lines`). Plain text and row dicts only:
the marks themselves are :mod:`~pendcli.output.html.marks`.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence
from functools import lru_cache
from typing import TYPE_CHECKING

from pendcli.output.html.rows import Row, lines_of, quoted_words, text_of

if TYPE_CHECKING:
    from pendcli.output.html.math import MathSegment

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


def ocr_pattern(printed: str) -> re.Pattern[str] | None:
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
        span = find(text, forms, cursor, len(text), taken) or find(text, forms, 0, len(text), taken)
        spans.append(span)
        if span is not None:
            taken.append(span)
            cursor = span[0]
    return spans


def find(
    text: str, forms: Sequence[str], start: int, end: int, taken: list[tuple[int, int]]
) -> tuple[int, int] | None:
    """The first free match of the widest form, narrowed to a later form found inside it."""
    for i, form in enumerate(forms):
        span = first_free(text, form, start, end, taken)
        if span is not None:
            for narrower in forms[i + 1 :]:
                inner = first_free(text, narrower, span[0], span[1], taken)
                if inner is not None:
                    return inner
            return span
    return None


def first_free(
    text: str, form: str, start: int, end: int, taken: list[tuple[int, int]]
) -> tuple[int, int] | None:
    pattern = ocr_pattern(form)
    if pattern is None:
        return None
    for m in pattern.finditer(text, start, end):
        if all(m.end() <= a or m.start() >= b for a, b in taken):
            return m.span()
    return None


# --- where a row belongs: its quoted words, its label, "after (N)" --------------------------

_WORDS = re.compile(r"[A-Za-zÀ-ÿ'’]+(?:[ ,][A-Za-zÀ-ÿ'’]+){2,}")
_AFTER = re.compile(r"\b(after|before|footnote to|table after) (\([0-9IVX]+'?\))")


def paragraph_spans(text: str, segments: Sequence[MathSegment]) -> list[tuple[int, int]]:
    """The paragraphs of ``text``: split at blank lines outside display formulas."""
    inside = [(s.start, s.end) for s in segments if s.display]
    cuts = [m.start() for m in re.finditer(r"\n[ \t]*\n", text)
            if not any(a < m.start() < b for a, b in inside)]  # fmt: skip
    edges = [0, *cuts, len(text)]
    return [(a, b) for a, b in itertools.pairwise(edges) if text[a:b].strip()]


def label_place(
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


def _quote_place(text: str, quote: str) -> tuple[int, int] | None:
    """The quote found whole (TeX-tolerant), or its longest run of plain words."""
    whole = ocr_pattern(quote)
    m = whole.search(text) if whole else None
    if m is not None:
        return m.span()
    for words in sorted(_WORDS.findall(quote), key=len, reverse=True):
        at = text.find(words)
        if at >= 0 and len(words) >= 12:
            return at, at + len(words)
    return None


def row_regions(
    text: str, row: Row, segments: Sequence[MathSegment], blocks: Sequence[tuple[int, int]]
) -> list[tuple[int, int]]:
    """The stretches of text where the row may be printed, surest first: the paragraph of
    its quoted words and the two after it (a number follows its sentence); its label's
    paragraph; the text after (N) up to the next numbered equation, or before (N); the
    equation its source names, "eq. (15)", and the text up to the next numbered one; its
    numbered section, "n° 15"."""
    out = []
    for quote in quoted_words(row):
        span = _quote_place(text, quote)
        if span is not None:
            out.append(_paragraphs(blocks, span[0], 0, 2))
    label = text_of(row, "equation")
    span = label_place(text, label, segments) if label else None
    if span is not None:
        out.append(_paragraphs(blocks, span[0], 0, 0))
    where = text_of(row, "section") + " " + text_of(row, "source")
    m = _AFTER.search(where)
    span = label_place(text, m.group(2), segments) if m else None
    if m and span is not None:
        before = m.group(1) == "before"
        out.append(_paragraphs(blocks, span[0], -3, 0) if before else
                   (span[1], _next_label(text, span[1], segments)))  # fmt: skip
    m = _IN_LABEL.search(text_of(row, "source"))
    span = label_place(text, m.group(1), segments) if m else None
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


def line_of(text: str, at: int) -> int:
    """The 1-based line of ``text`` that offset ``at`` is on."""
    return text.count("\n", 0, at) + 1


def covered_lines(text: str, start: int, end: int) -> tuple[int, int]:
    """The first and last line of text[start:end] (its start's line when empty)."""
    return line_of(text, start), line_of(text, max(start, end - 1))
