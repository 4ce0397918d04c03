"""Large results streamed: numeric columns written chunk by chunk, memory bounded.

A :class:`StreamedRows` is a result too large to hold as a list of dicts (millions of rows):
named columns that arrive as numpy arrays, one chunk at a time. :func:`write_stream` writes it
in any :class:`~pendcli.output.OutputFormat` as each chunk arrives, so memory stays that of
one chunk whatever the count. The bytes are those the list renderers would give for the same
rows: JSON in the document's key layout (two-space indent), floats as ``repr`` (exact round
trip) everywhere, non-finite floats as ``null`` in JSON and empty elsewhere. The table format
is plain aligned text (a rich table of millions of rows would hold them all). On a terminal a
progress bar on stderr appears once the writing is expected to take over ~2 s.
"""

from __future__ import annotations

import json
import sys
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal, TextIO

from pendcli.output.json import to_json

if TYPE_CHECKING:
    import numpy as np
    from rich.progress import Progress, TaskID

    from pendcli.output import OutputFormat

__all__ = ["StreamedColumn", "StreamedRows", "write_stream"]

_SENTINEL = "\x00streamed rows\x00"
_PROGRESS_AFTER = 2.0  # seconds: a shorter job gets no bar


@dataclass(frozen=True)
class StreamedColumn:
    key: str
    header: str
    width: int | None = None  # plain-text width; None: measured on the first chunk
    justify: Literal["left", "right"] = "right"


@dataclass(frozen=True)
class StreamedRows:
    """``length`` rows under ``columns``; ``chunks()`` yields, per chunk, one array per column."""

    title: str
    columns: Sequence[StreamedColumn]
    length: int
    chunks: Callable[[], Iterable[Sequence[np.ndarray]]]


def _cells(values: np.ndarray, non_finite: str) -> list[str]:
    """Each value as text: integers in decimal, floats as their repr (shortest exact)."""
    import numpy as np

    if values.dtype.kind in "iu":
        return list(map(str, values.tolist()))
    floats = values.astype(float, copy=False)
    cells = list(map(float.__repr__, floats.tolist()))
    if not np.isfinite(floats).all():
        for i in np.flatnonzero(~np.isfinite(floats)).tolist():
            cells[i] = non_finite
    return cells


def _text_chunks(
    rows: StreamedRows, template: str, non_finite: str, separator: str
) -> Iterator[str]:
    """The rows as text, a chunk at a time: ``template % cells`` joined by ``separator``."""
    first = True
    for arrays in _with_progress(rows):
        cells = [_cells(a, non_finite) for a in arrays]
        text = separator.join(map(template.__mod__, zip(*cells, strict=True)))
        yield text if first else separator + text
        first = False


def _json(rows: StreamedRows, document: Mapping[str, object], key: str) -> Iterator[str]:
    """``document`` as :func:`to_json` prints it, the list under ``key`` being ``rows``."""
    head, tail = to_json({**document, key: _SENTINEL}).split(json.dumps(_SENTINEL), 1)
    indent = head[head.rfind("\n") + 1 :].split('"', 1)[0]
    if rows.length == 0:
        yield head + "[]" + tail
        return
    inner = indent + "    "
    fields = ",\n".join(f"{inner}{json.dumps(c.key)}: %s" for c in rows.columns)
    yield head + "[\n"
    yield from _text_chunks(rows, f"{indent}  {{\n{fields}\n{indent}  }}", "null", ",\n")
    yield f"\n{indent}]" + tail


def _csv(rows: StreamedRows) -> Iterator[str]:
    yield ",".join(c.key for c in rows.columns) + "\n"
    yield from _text_chunks(rows, ",".join(["%s"] * len(rows.columns)), "", "\n")
    yield "\n" if rows.length else ""


def _markdown(rows: StreamedRows) -> Iterator[str]:
    cols = rows.columns
    if rows.title:
        yield f"### {rows.title}\n\n"
    yield "| " + " | ".join(c.header for c in cols) + " |\n"
    yield "|" + "|".join("---:" if c.justify == "right" else "---" for c in cols) + "|\n"
    yield from _text_chunks(rows, "| " + " | ".join(["%s"] * len(cols)) + " |", "", "\n")
    yield "\n" if rows.length else ""


def _plain(rows: StreamedRows) -> Iterator[str]:
    """Aligned columns, two spaces apart; widths given or measured on the first chunk."""
    first = next(iter(rows.chunks()), None) if any(c.width is None for c in rows.columns) else None
    widths = []
    for i, c in enumerate(rows.columns):
        measured = max(map(len, _cells(first[i], ""))) if first is not None else 0
        widths.append(max(len(c.header), c.width or measured))
    marks = [">" if c.justify == "right" else "<" for c in rows.columns]
    if rows.title:
        yield rows.title + "\n"
    pairs = zip(rows.columns, marks, widths, strict=True)
    yield "  ".join(f"{c.header:{m}{w}}" for c, m, w in pairs) + "\n"
    yield "  ".join("-" * w for w in widths) + "\n"
    # %*s right-aligns, %-*s left-aligns: the widths are baked into the template
    template = "  ".join(
        f"%{'' if m == '>' else '-'}{w}s" for m, w in zip(marks, widths, strict=True)
    )
    yield from _text_chunks(rows, template, "", "\n")
    yield "\n" if rows.length else ""


def _with_progress(rows: StreamedRows) -> Iterator[Sequence[np.ndarray]]:
    """The chunks, with a bar on stderr (terminals only) once the whole looks longer than 2 s."""
    if not sys.stderr.isatty():
        yield from rows.chunks()
        return
    start, done, bar = time.perf_counter(), 0, None
    try:
        for arrays in rows.chunks():
            yield arrays
            done += len(arrays[0]) if arrays else 0
            elapsed = time.perf_counter() - start
            if bar is None and done and elapsed * rows.length / done > _PROGRESS_AFTER:
                bar = _start_bar(rows.length, rows.title or "rows")
            if bar is not None:
                bar[0].update(bar[1], completed=done)
    finally:
        if bar is not None:
            bar[0].stop()


def _start_bar(total: int, description: str) -> tuple[Progress, TaskID]:
    from rich.console import Console
    from rich.progress import Progress

    progress = Progress(console=Console(stderr=True), transient=True)
    task = progress.add_task(description, total=total)
    progress.start()
    return progress, task


def write_stream(
    fmt: OutputFormat,
    rows: StreamedRows,
    document: Mapping[str, object],
    key: str,
    out: TextIO | None = None,
) -> None:
    """Write ``rows`` to ``out`` (default stdout) in ``fmt`` as they are produced.

    JSON prints ``document`` with ``rows`` as the list under ``key``; CSV one header line and
    a line per row; Markdown a pipe table under ``### title``; the table plain aligned text.
    """
    from pendcli.output import OutputFormat

    out = sys.stdout if out is None else out
    parts = {
        OutputFormat.json: lambda: _json(rows, document, key),
        OutputFormat.csv: lambda: _csv(rows),
        OutputFormat.markdown: lambda: _markdown(rows),
        OutputFormat.table: lambda: _plain(rows),
    }[fmt]()
    for text in parts:
        out.write(text)
