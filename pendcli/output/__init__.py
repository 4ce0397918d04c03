"""Every output pendcli writes, over plain rows (the ``as_dict()`` mappings of core's rows).

The formats: one module per format (:mod:`~pendcli.output.table`, :mod:`~pendcli.output.json`,
:mod:`~pendcli.output.csv`, :mod:`~pendcli.output.markdown`), each a renderer turning titled
sections of rows (and the whole document, which JSON prints) into text; :class:`OutputFormat`
maps ``--format`` to one. Renderers know columns and values, nothing about pendulums, and are
deterministic: the same rows give the same bytes (no timestamps, fixed key order, floats
written with ``repr`` in JSON and CSV so they round-trip exactly). The number style of each
output is written once (:mod:`~pendcli.output.style`); only :mod:`~pendcli.output.views`
knows what a claim row looks like.

The documents made of those rows: the terminal summary (:mod:`~pendcli.output.summary`),
``out/report.md`` (:mod:`~pendcli.output.report`), what ``pendcli check`` prints
(:mod:`~pendcli.output.check_formats`) and the HTML edition (:mod:`pendcli.output.html`).

May import: ``pendcli.base``, ``pendcli.data``, ``pendcli.verify``, ``pendcli.numerics``, the
registry (``pendcli.papers.registry``, inside functions) and the committed tables' columns
(``pendcli.run.drift``). Never the CLI, a paper's own modules, or the run (``reproduce``,
``regression``), except the report: it takes a ``ReproduceResult`` and the regenerated tables'
names, the one place an output knows the run.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from enum import StrEnum
from typing import TYPE_CHECKING, Protocol

from pendcli.output.columns import Column, Row, Section, fmt_float

if TYPE_CHECKING:
    from rich.console import Console

    from pendcli.output.csv import to_csv
    from pendcli.output.json import to_json
    from pendcli.output.markdown import to_markdown
    from pendcli.output.table import to_rich_table

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
        from pendcli.output.csv import to_csv

        return to_csv
    if name == "to_json":
        from pendcli.output.json import to_json

        return to_json
    if name == "to_markdown":
        from pendcli.output.markdown import to_markdown

        return to_markdown
    if name == "to_rich_table":
        from pendcli.output.table import to_rich_table

        return to_rich_table
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def renderer(fmt: OutputFormat, console: Console | None = None) -> Renderer:
    """The renderer of ``fmt``; ``console`` (width, colour) matters to the table only.
    Each renderer's module loads on first use."""
    if fmt is OutputFormat.table:
        from pendcli.output.table import TableRenderer

        return TableRenderer(console)
    if fmt is OutputFormat.json:
        from pendcli.output.json import JsonRenderer

        return JsonRenderer()
    if fmt is OutputFormat.csv:
        from pendcli.output.csv import CsvRenderer

        return CsvRenderer()
    from pendcli.output.markdown import MarkdownRenderer

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
