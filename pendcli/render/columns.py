"""Columns: which key of a row a renderer shows, under which header, formatted how.

Shared by every renderer; knows nothing of what the rows describe.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal

from pendcli.render.values import plain

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


# A titled group of rows with the columns to show them in (title "" for none).
Section = tuple[str, Sequence[Row], Sequence[Column]]


def fmt_float(value: float | None, sig: int = 10) -> str:
    """A float for human eyes: ``sig`` significant digits, no trailing noise."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, float) and math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if value == 0:
        return "0"
    return f"{value:.{sig}g}"
