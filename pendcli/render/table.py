"""The terminal table (rich): one table per section, long cells cut, styles from the columns.

rich is imported inside the functions: ``pendcli --help`` loads this module's package but
never draws a table.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from pendcli.render.columns import Column, Row, Section

if TYPE_CHECKING:
    from rich.console import Console
    from rich.table import Table

__all__ = ["TableRenderer", "to_rich_table"]


def _cell(column: Column, row: Row) -> str:
    """The cell as rich markup: text cut to ``table_max``, styled or escaped."""
    from rich.markup import escape

    text = column.text(row)
    if column.table_max is not None and len(text) > column.table_max:
        text = text[: column.table_max - 1].rstrip() + "…"
    style = column.style(text) if column.style is not None else None
    return f"[{style}]{text}[/]" if style else escape(text)


def to_rich_table(
    rows: Sequence[Row], columns: Sequence[Column], title: str | None = None
) -> Table:
    from rich import box
    from rich.table import Table

    # No vertical rules: two spaces between columns leave the width to the data.
    table = Table(
        title=title,
        show_lines=False,
        header_style="bold",
        box=box.SIMPLE_HEAD,
        show_edge=False,
        padding=(0, 1, 0, 0),
    )
    for c in columns:
        table.add_column(c.header, justify=c.justify, overflow="fold")
    for r in rows:
        table.add_row(*(_cell(c, r) for c in columns))
    return table


class TableRenderer:
    """The sections as rich tables, drawn for ``console`` (its width, colour, terminal)."""

    def __init__(self, console: Console | None = None) -> None:
        self.console = console

    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        if self.console is None:
            from pendcli.core.console import console

            self.console = console()
        with self.console.capture() as captured:
            for title, rows, columns in sections:
                self.console.print(to_rich_table(rows, columns, title=title))
        return captured.get()
