"""CSV: one header line, one line per row; floats written with ``repr`` so they round-trip."""

from __future__ import annotations

import csv
import io
import json
import math
from collections.abc import Mapping, Sequence

from pendcli.render.columns import Row, Section
from pendcli.render.json import plain

__all__ = ["CsvRenderer", "to_csv"]


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
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else ""
    if isinstance(value, list | tuple):
        return json.dumps(plain(value))
    return str(value)


class CsvRenderer:
    """Every row of every section, under the union of their keys in order of appearance."""

    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        rows = [r for _, section_rows, _ in sections for r in section_rows]
        keys: list[str] = []
        for r in rows:
            keys.extend(k for k in r if k not in keys)
        return to_csv(rows, keys)
