"""Output formats over plain rows (mappings): rich table, JSON, CSV, Markdown.

One module per format (:mod:`~pendcli.render.table`, :mod:`~pendcli.render.json`,
:mod:`~pendcli.render.csv`, :mod:`~pendcli.render.markdown`), each a renderer turning titled
sections of rows (and the whole document, which JSON prints) into text; :class:`OutputFormat`
maps ``--format`` to one. Renderers know columns and values, nothing about pendulums, and are
deterministic: the same rows give the same bytes (no timestamps, fixed key order, floats
written with ``repr`` in JSON and CSV so they round-trip exactly).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from enum import StrEnum
from typing import TYPE_CHECKING, Protocol

from pendcli.render.columns import Column, Row, Section, fmt_float

if TYPE_CHECKING:
    from rich.console import Console

    from pendcli.render.csv import to_csv
    from pendcli.render.json import to_json
    from pendcli.render.markdown import to_markdown
    from pendcli.render.table import to_rich_table

__all__ = [
    "Column",
    "OutputFormat",
    "Renderer",
    "Row",
    "Section",
    "fmt_float",
    "render",
    "renderer",
    "to_csv",
    "to_json",
    "to_markdown",
    "to_rich_table",
]


class Renderer(Protocol):
    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str: ...


class OutputFormat(StrEnum):
    table = "table"
    json = "json"
    csv = "csv"
    markdown = "markdown"


def __getattr__(name: str) -> object:
    # the renderers' functions, loaded on first use: `pendcli --help` needs only the enum
    if name == "to_csv":
        from pendcli.render.csv import to_csv

        return to_csv
    if name == "to_json":
        from pendcli.render.json import to_json

        return to_json
    if name == "to_markdown":
        from pendcli.render.markdown import to_markdown

        return to_markdown
    if name == "to_rich_table":
        from pendcli.render.table import to_rich_table

        return to_rich_table
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def renderer(fmt: OutputFormat, console: Console | None = None) -> Renderer:
    """The renderer of ``fmt``; ``console`` (width, colour) matters to the table only.
    Each renderer's module loads on first use."""
    if fmt is OutputFormat.table:
        from pendcli.render.table import TableRenderer

        return TableRenderer(console)
    if fmt is OutputFormat.json:
        from pendcli.render.json import JsonRenderer

        return JsonRenderer()
    if fmt is OutputFormat.csv:
        from pendcli.render.csv import CsvRenderer

        return CsvRenderer()
    from pendcli.render.markdown import MarkdownRenderer

    return MarkdownRenderer()


def render(
    fmt: OutputFormat,
    sections: Sequence[Section],
    document: Mapping[str, object],
    console: Console | None = None,
) -> str:
    """Titled sections of rows as text in format ``fmt``.

    JSON prints ``document`` whole; CSV writes every row of every section under the union of
    their keys; Markdown and the table show each section under its title.
    """
    return renderer(fmt, console)(sections, document)
