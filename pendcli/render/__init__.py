"""Output formats over plain rows (dicts): rich table, JSON, CSV, Markdown.

A renderer knows columns and values, nothing about pendulums. Every renderer is
deterministic: the same rows give the same bytes (no timestamps, fixed key order,
floats written with ``repr`` in JSON and CSV so they round-trip exactly).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import StrEnum

__all__ = ["Column", "OutputFormat", "fmt_float", "render"]


class OutputFormat(StrEnum):
    table = "table"
    json = "json"
    csv = "csv"
    markdown = "markdown"


@dataclass(frozen=True)
class Column:
    key: str
    header: str
    fmt: Callable[[dict], str] | None = None  # text for table/markdown; default str(value)
    justify: str = "left"
    table_max: int | None = None  # in the terminal table only, cut longer text with "…"

    def text(self, row: dict) -> str:
        if self.fmt is not None:
            return self.fmt(row)
        value = row.get(self.key)
        if value is None:
            return ""
        if isinstance(value, float):
            return fmt_float(value)
        return str(value)


def fmt_float(value: float | None, sig: int = 10) -> str:
    """A float for human eyes: ``sig`` significant digits, no trailing noise."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, float) and math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if value == 0:
        return "0"
    return f"{value:.{sig}g}"


VERDICT_STYLES = {
    "agrees": "green",
    "holds": "green",
    "truncated": "yellow",
    "last-digit": "yellow",
    "discrepant": "bold red",
    "fails": "bold red",
}


def _plain(value: object) -> object:
    if isinstance(value, float):
        if not math.isfinite(value):
            return None
        return value
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    if isinstance(value, list):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return value


def to_json(document: dict) -> str:
    """Deterministic JSON (NaN/inf become null: JSON has no such numbers)."""
    import json

    return json.dumps(_plain(document), indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def to_csv(rows: Sequence[dict], keys: Sequence[str] | None = None) -> str:
    import csv
    import io

    keys = list(keys or (rows[0].keys() if rows else []))
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(keys)
    for row in rows:
        writer.writerow(["" if row.get(k) is None else _csv_cell(row.get(k)) for k in keys])
    return buf.getvalue()


def _csv_cell(value: object) -> str:
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else ""
    if isinstance(value, (list, tuple)):
        import json

        return json.dumps(_plain(value))
    return str(value)


def to_markdown(rows: Sequence[dict], columns: Sequence[Column]) -> str:
    def cell(text: str) -> str:
        return text.replace("|", "\\|").replace("\n", " ")

    lines = [
        "| " + " | ".join(cell(c.header) for c in columns) + " |",
        "|" + "|".join("---:" if c.justify == "right" else "---" for c in columns) + "|",
    ]
    lines += ["| " + " | ".join(cell(c.text(r)) for c in columns) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def to_rich_table(rows: Sequence[dict], columns: Sequence[Column], title: str | None = None):
    from rich.table import Table

    table = Table(title=title, show_lines=False, header_style="bold")
    for c in columns:
        table.add_column(c.header, justify=c.justify, overflow="fold")
    for r in rows:
        cells = []
        for c in columns:
            text = c.text(r)
            if c.table_max is not None and len(text) > c.table_max:
                text = text[: c.table_max - 1].rstrip() + "…"
            style = VERDICT_STYLES.get(text) if c.key == "verdict" else None
            cells.append(f"[{style}]{text}[/]" if style else _escape(text))
        table.add_row(*cells)
    return table


def _escape(text: str) -> str:
    from rich.markup import escape

    return escape(text)


def render(
    fmt: OutputFormat,
    sections: Sequence[tuple[str, Sequence[dict], Sequence[Column]]],
    document: dict,
    console=None,
) -> str | None:
    """Render titled sections of rows.

    ``document`` is what JSON prints whole; CSV writes every row of every section with the
    union of their keys; table prints to ``console`` (returns None); Markdown returns text.
    """
    if fmt is OutputFormat.json:
        return to_json(document)
    if fmt is OutputFormat.csv:
        all_rows = [r for _, rows, _ in sections for r in rows]
        keys: list[str] = []
        for r in all_rows:
            keys.extend(k for k in r if k not in keys)
        return to_csv(all_rows, keys)
    if fmt is OutputFormat.markdown:
        parts = []
        for title, rows, columns in sections:
            if title:
                parts.append(f"### {title}\n")
            parts.append(to_markdown(rows, columns))
        return "\n".join(parts)
    for title, rows, columns in sections:
        console.print(to_rich_table(rows, columns, title=title))
    return None
