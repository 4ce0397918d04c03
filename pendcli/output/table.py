"""The terminal table (rich): one table per section, long cells cut, styles from the columns.

rich is imported inside the functions: ``pendcli --help`` loads this module's package but
never draws a table.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from pendcli.output.columns import Column, Row, Section
from pendcli.output.style import TERMINAL, using

if TYPE_CHECKING:
    from collections.abc import Iterator

    from rich.console import Console, RenderableType
    from rich.table import Table
    from rich.text import Text

__all__ = ["TERMINAL_DIGITS", "TableRenderer", "to_rich_table"]

# Significant digits of a float the terminal shows (the terminal style's: JSON and CSV keep all).
TERMINAL_DIGITS = TERMINAL.digits

# A number and the unit after it wrap together (« 7.6e-07 s/evaluation », « 0.1966 mm »): a
# number, then one word of letters (a unit, « s/evaluation », « m/s² »), kept on one line.
_NUMBER = r"[-+−]?\d[\d.,]*(?:e[-+]?\d+)?[°'″′%]*"
_GLUED = re.compile(rf"(?:(?<=\s)|^){_NUMBER}\s(?=[^\W\d_][\w/²³⁻¹·]{{0,13}}(?:[\s,;:.)]|$))")


def _cell(column: Column, text: str) -> str:
    """The cell as rich markup: text cut to ``table_max``, styled or escaped."""
    from rich.markup import escape

    if column.table_max is not None and len(text) > column.table_max:
        text = text[: column.table_max - 1].rstrip() + "…"
    style = column.style(text) if column.style is not None else None
    return f"[{style}]{escape(text)}[/]" if style else escape(text)


def _words(plain: str) -> list[tuple[int, int]]:
    """The spans of the words of one line of ``plain`` that may not be broken: each word, a
    number and its unit taken as one."""
    spans = [(m.start(), m.end()) for m in re.finditer(r"\S+", plain)]
    glued = {m.end() for m in _GLUED.finditer(plain)}  # where a unit starts after its number
    merged: list[tuple[int, int]] = []
    for start, end in spans:
        if merged and start in glued:
            merged[-1] = (merged[-1][0], end)
        else:
            merged.append((start, end))
    return merged


def _longest_token(text: str) -> int:
    from rich.cells import cell_len
    from rich.text import Text

    plain = Text.from_markup(text).plain
    return max(
        (cell_len(line[a:b]) for line in plain.splitlines() for a, b in _words(line)), default=0
    )


def wrapped(text: Text, width: int) -> Text:
    """``text`` with its lines broken at spaces to fit ``width`` cells, a number never apart
    from its unit (rich would break « 7.6e-07 / s/evaluation »); a word longer than ``width``
    stays whole on its own line."""
    from rich.cells import cell_len
    from rich.text import Text

    lines: list[Text] = []
    offset = 0
    for line in text.plain.split("\n"):
        if cell_len(line) <= width:  # as it is: its indent, its alignment padding
            lines.append(text[offset : offset + len(line)])
            offset += len(line) + 1
            continue
        start: int | None = 0  # the first piece keeps the line's indent
        end = 0
        for a, b in _words(line):
            if start is not None and end and cell_len(line[start:b]) > width:
                lines.append(text[offset + start : offset + end])
                start = None
            start = a if start is None else start
            end = b
        lines.append(text[offset + (start or 0) : offset + end])
        offset += len(line) + 1
    return Text("\n").join(lines)


def _longest_line(text: str) -> int:
    from rich.cells import cell_len
    from rich.text import Text

    return max((cell_len(t) for t in Text.from_markup(text).plain.splitlines()), default=0)


def fitted_widths(lower: Sequence[int], upper: Sequence[int], room: int) -> list[int] | None:
    """Column widths that fit ``room`` cells and never cut a token: each column at least its
    longest word (``lower``), the rest of the room shared in proportion to what each column
    would still use (``upper - lower``). None when everything fits unwrapped; when even the
    longest words do not fit, ``lower`` (the table is wider than the room: nothing is cut)."""
    if sum(upper) <= room:
        return None
    spare = room - sum(lower)
    if spare <= 0:
        return list(lower)
    want = [u - lo for lo, u in zip(lower, upper, strict=True)]
    share = [lo + (spare * w) // sum(want) for lo, w in zip(lower, want, strict=True)]
    left = room - sum(share)
    for i in sorted(range(len(share)), key=lambda i: share[i] - upper[i])[:left]:
        share[i] += 1
    return share


def _records(table: Table, headers: list[str], width: int) -> Iterator[RenderableType]:
    """The rows one under another, ``header  value`` per line, for a terminal too narrow for
    the columns side by side: every word and number stays whole, prose wraps at spaces, and a
    header wraps only when the values would not fit beside it."""
    from rich.table import Table
    from rich.text import Text

    if table.title:
        yield Text(str(table.title), style="italic")
    cells: list[list[str]] = getattr(table, "cells", [])
    values = max((_longest_token(c) for col in cells[1:] for c in col), default=0)
    label = min(max(len(h) for h in headers[1:] or [""]), max(width - 4 - values, width // 3))
    for i in range(table.row_count):
        grid = Table.grid(padding=(0, 2, 0, 2))
        grid.add_column(width=label, overflow="fold")
        grid.add_column(overflow="fold", max_width=width - label - 4)
        first = cells[0][i] if cells else ""
        for header, column in zip(headers[1:], cells[1:], strict=True):
            if Text.from_markup(column[i]).plain.strip():
                value = wrapped(Text.from_markup(column[i]), width - label - 4)
                grid.add_row(wrapped(Text(header, style="dim"), label), value)
        yield Text.from_markup(f"[bold]{first}[/]" if first else "")
        yield grid


def _fitting_table_class() -> type[Table]:
    from rich.cells import cell_len
    from rich.table import Table
    from rich.text import Text

    class FittingTable(Table):
        """A table whose columns shrink by wrapping prose at spaces, never inside a word or
        a number nor between a number and its unit (rich alone folds the widest columns,
        cutting `-1.000e-04` into two lines); a title wider than the table is written on its
        own line rather than wrapped to the table's width."""

        cells: list[list[str]]

        def __rich_console__(self, console, options):
            headers = [str(c.header) for c in self.columns]
            cells = [[str(h), *col] for h, col in zip(headers, self.cells, strict=True)]
            lower = [max(_longest_token(t) for t in col) for col in cells]
            upper = [max(_longest_line(t) for t in col) for col in cells]
            # Per column: one cell of right padding, and the box's blank rule between columns;
            # where the words do not fit so, the blank rule alone (one space between columns).
            padding = 2 * len(self.columns) - 1
            if sum(lower) + padding > options.max_width:
                padding = len(self.columns) - 1
                self.padding = (0, 0, 0, 0)
            widths = fitted_widths(lower, upper, options.max_width - padding)
            if widths is not None and sum(widths) + padding > options.max_width:
                yield from _records(self, headers, options.max_width)
                return
            sizes: list[int | None] = list(widths) if widths else [None] * len(lower)
            for column, width, col in zip(self.columns, sizes, self.cells, strict=True):
                column.width = width  # None: rich sizes the column (everything fits)
                if width is not None:  # the cells wrapped here, not by rich (rich's own list)
                    column._cells = [wrapped(Text.from_markup(c), width) for c in col]
            drawn = sum(widths) if widths else sum(upper)
            if self.title and cell_len(str(self.title)) > drawn + padding:
                yield Text(str(self.title), style="italic")
                self.title = None
            yield from super().__rich_console__(console, options)

    return FittingTable


def to_rich_table(
    rows: Sequence[Row], columns: Sequence[Column], title: str | None = None
) -> Table:
    from rich import box

    # No vertical rules: two spaces between columns leave the width to the data.
    table = _fitting_table_class()(
        title=title,
        show_lines=False,
        header_style="bold",
        box=box.SIMPLE_HEAD,
        show_edge=False,
        padding=(0, 1, 0, 0),
    )
    for c in columns:
        table.add_column(c.header, justify=c.justify, overflow="fold")
    with using(TERMINAL):
        texts = [c.texts(rows) for c in columns]
    cells = [[_cell(c, texts[j][i]) for j, c in enumerate(columns)] for i in range(len(rows))]
    for row_cells in cells:
        table.add_row(*row_cells)
    table.cells = [list(col) for col in zip(*cells, strict=True)] or [[] for _ in columns]  # type: ignore[attr-defined]
    return table


class TableRenderer:
    """The sections as rich tables, drawn for ``console`` (its width, colour, terminal)."""

    def __init__(self, console: Console | None = None) -> None:
        self.console = console

    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        if self.console is None:
            from pendcli.base.console import console

            self.console = console()
        with self.console.capture() as captured:
            for title, rows, columns in sections:
                self.console.print(to_rich_table(rows, columns, title=title))
        return captured.get()
