"""Output formats over plain rows (mappings): rich table, JSON, CSV, Markdown.

One module per format (:mod:`~pendcli.render.table`, :mod:`~pendcli.render.json`,
:mod:`~pendcli.render.csv`, :mod:`~pendcli.render.markdown`), each a renderer turning titled
sections of rows (and the whole document, which JSON prints) into text; :class:`OutputFormat`
maps ``--format`` to one. Renderers know columns and values, nothing about pendulums, and are
deterministic: the same rows give the same bytes (no timestamps, fixed key order, floats
written with ``repr`` in JSON and CSV so they round-trip exactly).
"""

from __future__ import annotations

import importlib
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


# --format -> (module, renderer class). Modules load on first use: `pendcli --help` needs
# only the enum.
_RENDERERS: dict[OutputFormat, tuple[str, str]] = {
    OutputFormat.table: ("pendcli.render.table", "TableRenderer"),
    OutputFormat.json: ("pendcli.render.json", "JsonRenderer"),
    OutputFormat.csv: ("pendcli.render.csv", "CsvRenderer"),
    OutputFormat.markdown: ("pendcli.render.markdown", "MarkdownRenderer"),
}
_FUNCTIONS = {
    "to_csv": "pendcli.render.csv",
    "to_json": "pendcli.render.json",
    "to_markdown": "pendcli.render.markdown",
    "to_rich_table": "pendcli.render.table",
}


def __getattr__(name: str) -> object:
    if name in _FUNCTIONS:
        return getattr(importlib.import_module(_FUNCTIONS[name]), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def renderer(fmt: OutputFormat, console: Console | None = None) -> Renderer:
    """The renderer of ``fmt``; ``console`` (width, colour) matters to the table only."""
    module, name = _RENDERERS[fmt]
    cls = getattr(importlib.import_module(module), name)
    return cls(console) if fmt is OutputFormat.table else cls()


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
