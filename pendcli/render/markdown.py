"""Markdown: a pipe table per section, headed ``### title`` when the section has one."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from pendcli.render.columns import Column, Row, Section

__all__ = ["MarkdownRenderer", "to_markdown"]


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def to_markdown(rows: Sequence[Row], columns: Sequence[Column]) -> str:
    """One pipe table; right-justified columns are aligned right."""
    lines = [
        "| " + " | ".join(_cell(c.header) for c in columns) + " |",
        "|" + "|".join("---:" if c.justify == "right" else "---" for c in columns) + "|",
    ]
    lines += ["| " + " | ".join(_cell(c.text(r)) for c in columns) + " |" for r in rows]
    return "\n".join(lines) + "\n"


class MarkdownRenderer:
    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        parts = []
        for title, rows, columns in sections:
            if title:
                parts.append(f"### {title}\n")
            parts.append(to_markdown(rows, columns))
        return "\n".join(parts)
