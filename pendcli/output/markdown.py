"""Markdown: a pipe table per section, headed ``### title`` when the section has one.

Every cell is text, never markup: :func:`markdown_text` escapes what would make raw HTML, a
link or an image of a table's string (``report.md`` uses it, :func:`code_span` and
:func:`fence` too, for each string it takes from the tables).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

from pendcli.output.columns import Column, Row, Section
from pendcli.output.style import MARKDOWN, using

__all__ = ["MarkdownRenderer", "code_span", "fence", "markdown_text", "to_markdown"]

# What CommonMark could read as markup in a line of text: a backslash (it would escape what
# follows it: the escapes below), an entity, a `<` that may open a tag, comment or autolink
# (one before a space, or in « <= », cannot), and a `]` that may close a link's or image's
# text into a destination `](`, a label `][` or a definition `]:` (a string's last `]` is
# followed by the report's own text: never `(` or `[`, and a definition must start its line).
# Emphasis changes how text looks, never what it is, and stays. A code span stays too, its
# content as it is: CommonMark reads no escape, entity, tag or link inside one, so an escape
# there would be shown (`a\\b` for `a\b`).
_MARKUP = re.compile(r"\\|&|<(?!\s|=\s)|\](?=[(\[:])")
_REPLACEMENT = {"\\": "\\\\", "&": "&amp;", "<": "&lt;", "]": "\\]"}
_TICKS = re.compile(r"`+")


def markdown_text(text: str) -> str:
    """``text`` as Markdown that shows it as text, on one line: see :data:`_MARKUP`."""
    one_line = re.sub(r"\r\n?|\n", " ", text)
    out, start = [], 0
    for opened, closed in _code_spans(one_line):
        out += [_escaped(one_line[start:opened]), one_line[opened:closed]]
        start = closed
    return "".join([*out, _escaped(one_line[start:])])


def _escaped(text: str) -> str:
    return _MARKUP.sub(lambda m: _REPLACEMENT[m.group(0)], text)


def _code_spans(text: str) -> list[tuple[int, int]]:
    """Where CommonMark reads a code span in ``text`` once its backslashes outside code spans
    are escaped (so none escapes a backtick): a run of backticks up to the next run of the
    same length; a run that nothing closes is text."""
    runs = list(_TICKS.finditer(text))
    spans, i = [], 0
    while i < len(runs):
        closer = next(
            (j for j in range(i + 1, len(runs)) if len(runs[j][0]) == len(runs[i][0])), None
        )
        if closer is None:
            i += 1
            continue
        spans.append((runs[i].start(), runs[closer].end()))
        i = closer + 1
    return spans


def code_span(text: str) -> str:
    """``text`` in a code span whose backticks outnumber any run of them inside it (padded
    with a space where a backtick or a space at both ends would be read otherwise)."""
    one_line = re.sub(r"\r\n?|\n", " ", text)
    ticks = "`" * (max(map(len, re.findall("`+", one_line)), default=0) + 1)
    edges = one_line[:1] + one_line[-1:]
    pad = " " if "`" in edges or (edges == "  " and one_line.strip(" ")) else ""
    return f"{ticks}{pad}{one_line}{pad}{ticks}"


def fence(lines: Sequence[str]) -> str:
    """The backticks of a code block around ``lines`` that no line of it can close."""
    longest = max((len(run) for line in lines for run in re.findall("`+", line)), default=0)
    return "`" * max(3, longest + 1)


def _cell(text: str) -> str:
    return markdown_text(text).replace("|", "\\|")


def to_markdown(rows: Sequence[Row], columns: Sequence[Column]) -> str:
    """One pipe table; right-justified columns are aligned right."""
    lines = [
        "| " + " | ".join(_cell(c.header) for c in columns) + " |",
        "|" + "|".join("---:" if c.justify == "right" else "---" for c in columns) + "|",
    ]
    with using(MARKDOWN):
        texts = [c.texts(rows) for c in columns]
    lines += [
        "| " + " | ".join(_cell(texts[j][i].strip()) for j in range(len(columns))) + " |"
        for i in range(len(rows))
    ]
    return "\n".join(lines) + "\n"


class MarkdownRenderer:
    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        parts = []
        for title, rows, columns in sections:
            if title:
                parts.append(f"### {title}\n")
            parts.append(to_markdown(rows, columns))
        return "\n".join(parts)
