"""CSV: one header line, one line per row; floats written with ``repr`` so they round-trip.

Cells are plain text: numbers as numbers (a numpy scalar as the Python number it holds, never
``np.float64(...)``), lists as JSON. A command printing several tables writes them under one
header, the first column ``table`` naming the table (section title) each row belongs to; a
command with a single table has no such column.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Mapping, Sequence

from pendcli.output.columns import Row, Section
from pendcli.output.json import plain

__all__ = ["TABLE_KEY", "CsvRenderer", "to_csv"]


def to_csv(rows: Sequence[Row], keys: Sequence[str] | None = None) -> str:
    """Rows under ``keys`` (default: the first row's keys); a missing value is empty."""
    keys = list(keys or (rows[0].keys() if rows else []))
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(keys)
    for row in rows:
        writer.writerow([_cell(row.get(k)) for k in keys])
    return buf.getvalue()


def _cell(value: object) -> str:
    value = plain(value)
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, list):
        return json.dumps(value)
    return str(value)


TABLE_KEY = "table"  # the first column when several tables share one CSV


class CsvRenderer:
    """Every row of every section, under the union of their keys in order of appearance;
    with several sections, a first column ``table`` holds each row's section title."""

    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        several = len(sections) > 1
        rows: list[Row] = []
        for title, section_rows, _ in sections:
            rows.extend({TABLE_KEY: title, **r} if several else r for r in section_rows)
        keys: list[str] = []
        for r in rows:
            keys.extend(k for k in r if k not in keys)
        return to_csv(rows, keys)
