"""Columns: which key of a row a renderer shows, under which header, formatted how.

Shared by every renderer; knows nothing of what the rows describe.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal

from pendcli.output.style import current
from pendcli.output.values import plain

__all__ = ["Column", "Row", "Section", "fmt_float"]

# A row is a flat mapping from column key to a plain value (str, int, float, None, list).
Row = Mapping[str, Any]


@dataclass(frozen=True)
class Column:
    key: str
    header: str
    fmt: Callable[[Row], str] | None = None  # text for table/markdown; default str(value)
    justify: Literal["left", "right"] = "left"
    table_max: int | None = None  # in the terminal table only, cut longer text with "…"
    style: Callable[[str], str | None] | None = None  # rich style of a cell, from its text
    # A numeric column: its floats written together (one notation, decimal points aligned,
    # trailing zeros kept) with this many significant digits, within the output's style.
    digits: int | None = None

    def text(self, row: Row) -> str:
        if self.fmt is not None:
            return self.fmt(row)
        value = row.get(self.key)
        if value is None:
            return ""
        if isinstance(value, float):
            return fmt_float(value)
        if isinstance(value, list | tuple):
            return str(plain(value))
        return str(value)

    def texts(self, rows: Sequence[Row]) -> list[str]:
        """The column's cells, in the style of the output being drawn: a numeric column (one
        with ``digits``, or no format of its own and only floats) in one notation."""
        values = [plain(r.get(self.key)) for r in rows]
        numeric = self.fmt is None and any(isinstance(v, float) for v in values)
        if (self.digits is not None or numeric) and all(
            v is None or (isinstance(v, int | float) and not isinstance(v, bool)) for v in values
        ):
            floats = [None if v is None else float(v) for v in values]  # type: ignore[arg-type]
            return current().column(floats, self.digits, trim=self.digits is None)
        return [self.text(r) for r in rows]


# A titled group of rows with the columns to show them in (title "" for none).
Section = tuple[str, Sequence[Row], Sequence[Column]]


def fmt_float(value: float | None, sig: int = 10) -> str:
    """A float for human eyes: ``sig`` significant digits, no trailing noise, and never more
    than the output being drawn shows (7 in the terminal: :mod:`pendcli.output.style`)."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    return current().number(value, sig)
