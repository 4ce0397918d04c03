"""Renderers compared whole against expected text written by hand; they know nothing of
pendulums. Each expectation is a literal (or a structure parsed independently of the renderer),
so a change in any byte of the output fails."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest
from rich.console import Console

from pendcli.output import (
    Column,
    OutputFormat,
    fmt_float,
    render,
    renderer,
    to_csv,
    to_json,
    to_markdown,
)
from pendcli.output.stream import StreamedColumn, StreamedRows, write_stream

ROWS = [
    {"id": "a", "x": 1.5, "verdict": "agrees", "note": "pipe | here"},
    {"id": "b", "x": 0.1, "verdict": "discrepant", "note": None},
]
COLS = [Column("id", "id"), Column("x", "x", justify="right"), Column("verdict", "verdict")]


def _red_when_bad(text: str) -> str | None:
    return "red" if text == "discrepant" else None


def test_markdown_whole_output():
    assert to_markdown(ROWS, [*COLS, Column("note", "note")]) == (
        "| id | x | verdict | note |\n"
        "|---|---:|---|---|\n"
        "| a | 1.5 | agrees | pipe \\| here |\n"
        "| b | 0.1 | discrepant |  |\n"
    )


def test_markdown_sections_have_titles_and_a_blank_line_between():
    text = render(
        OutputFormat.markdown, [("One", ROWS[:1], COLS[:1]), ("", ROWS[1:], COLS[:1])], {}
    )
    assert text == "### One\n\n| id |\n|---|\n| a |\n\n| id |\n|---|\n| b |\n"


def test_csv_whole_output_round_trips_floats():
    assert to_csv(ROWS, ["id", "x", "note"]) == "id,x,note\na,1.5,pipe | here\nb,0.1,\n"


def test_csv_cells_floats_lists_and_non_finite():
    rows = [{"v": 0.1 + 0.2, "w": float("inf"), "pairs": [(0.5, 2.0)], "n": 3, "s": 'say "x"'}]
    text = to_csv(rows)
    assert text == 'v,w,pairs,n,s\n0.30000000000000004,,"[[0.5, 2.0]]",3,"say ""x"""\n'
    parsed = list(csv.reader(io.StringIO(text)))
    assert float(parsed[1][0]) == 0.30000000000000004  # repr round-trips the exact double
    assert json.loads(parsed[1][2]) == [[0.5, 2.0]]


def test_csv_renderer_writes_the_union_of_keys_in_order_of_appearance():
    sections = [("A", [{"id": "a", "x": 1}], COLS), ("B, b", [{"id": "b", "y": 2}], COLS)]
    # several tables: the first column names the table of each row
    assert render(OutputFormat.csv, sections, {}) == 'table,id,x,y\nA,a,1,\n"B, b",b,,2\n'


def test_csv_of_one_table_has_no_table_column():
    assert render(OutputFormat.csv, [("A", [{"id": "a"}], COLS)], {}) == "id\na\n"


def test_numpy_scalars_are_plain_numbers_in_every_format():
    rows = [{"id": np.int64(3), "x": np.float64(1.2178), "pair": (np.float64(9.5), 2)}]
    cols = [Column("id", "id"), Column("x", "x"), Column("pair", "pair")]
    outputs = {
        fmt: render(fmt, [("T", rows, cols)], {"rows": rows}, Console(width=80))
        for fmt in OutputFormat
    }
    assert outputs[OutputFormat.csv] == 'id,x,pair\n3,1.2178,"[9.5, 2]"\n'
    assert json.loads(outputs[OutputFormat.json]) == {
        "rows": [{"id": 3, "x": 1.2178, "pair": [9.5, 2]}]
    }
    assert outputs[OutputFormat.markdown].endswith("| 3 | 1.2178 | [9.5, 2] |\n")
    assert all("np." not in text for text in outputs.values())


def test_json_whole_output():
    doc = {
        "claims": [{"v": float("nan"), "w": 0.1 + 0.2, "angle": "1°7'33''", "pair": (1, -2.5)}],
        "formulas": [],
        "inf": float("-inf"),
    }
    assert to_json(doc) == (
        "{\n"
        '  "claims": [\n'
        "    {\n"
        '      "v": null,\n'
        '      "w": 0.30000000000000004,\n'
        '      "angle": "1°7\'33\'\'",\n'
        '      "pair": [\n'
        "        1,\n"
        "        -2.5\n"
        "      ]\n"
        "    }\n"
        "  ],\n"
        '  "formulas": [],\n'
        '  "inf": null\n'
        "}\n"
    )


def test_json_renderer_prints_the_document_not_the_sections():
    assert render(OutputFormat.json, [("A", ROWS, COLS)], {"k": 1}) == '{\n  "k": 1\n}\n'


def test_rich_table_whole_output():
    cols = [*COLS[:2], Column("verdict", "verdict", style=_red_when_bad), Column("note", "n")]
    console = Console(file=io.StringIO(), width=60)
    text = render(OutputFormat.table, [("T", ROWS, cols)], {}, console=console)
    assert text == (
        "                T                \n"  # centred over the 33 columns
        "id    x  verdict     n           \n"  # no vertical rules: two spaces part columns
        "─────────────────────────────────\n"
        "a   1.5  agrees      pipe | here \n"
        "b   0.1  discrepant              \n"
    )


def test_rich_table_cuts_long_cells_styles_and_escapes(monkeypatch):
    monkeypatch.delenv("NO_COLOR", raising=False)  # conftest sets it; colour is tested here
    rows = [{"verdict": "discrepant", "note": "[b]not markup[/b] and more"}]
    cols = [Column("verdict", "v", style=_red_when_bad), Column("note", "note", table_max=12)]
    console = Console(file=io.StringIO(), width=40, force_terminal=True, color_system="standard")
    text = render(OutputFormat.table, [("", rows, cols)], {}, console=console)
    assert "\x1b[31mdiscrepant\x1b[0m  [b]not mark…" in text  # red; markup shown as text
    plain = render(OutputFormat.table, [("", rows, cols)], {}, console=Console(width=40))
    assert "\x1b" not in plain


@pytest.mark.parametrize("fmt", list(OutputFormat))
def test_every_format_has_a_renderer_returning_text(fmt):
    text = renderer(fmt, Console(file=io.StringIO(), width=80))([("T", ROWS, COLS)], {"a": 1})
    assert isinstance(text, str) and text.endswith("\n")


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (None, ""),
        (float("nan"), ""),
        (float("inf"), "inf"),
        (-float("inf"), "-inf"),
        (0.0, "0"),
        (1 / 3, "0.3333333333"),
        (123456789012.0, "1.23456789e+11"),
        (2.5, "2.5"),
    ],
)
def test_fmt_float(value, text):
    assert fmt_float(value) == text


# --- streamed rows: the same bytes as the list renderers, a chunk at a time ----------------

STREAM_KEYS = ("k", "v")


def _streamed(chunks: list[tuple[list[int], list[float]]]) -> StreamedRows:
    columns = (StreamedColumn("k", "k"), StreamedColumn("v", "value"))
    length = sum(len(k) for k, _ in chunks)
    return StreamedRows(
        "T", columns, length, lambda: [(np.array(k), np.array(v, dtype=float)) for k, v in chunks]
    )


STREAM_CHUNKS = [([1, 2], [0.1 + 0.2, float("nan")]), ([3], [-1e-300]), ([4, 5], [2.5, 1 / 3])]


@pytest.mark.parametrize("fmt", [OutputFormat.json, OutputFormat.csv, OutputFormat.markdown])
def test_stream_writes_what_the_list_renderer_writes(fmt):
    rows = [{"k": k, "v": v} for ks, vs in STREAM_CHUNKS for k, v in zip(ks, vs, strict=True)]
    cols = [
        Column("k", "k", justify="right"),
        Column("v", "value", fmt=lambda r: _repr(r["v"]), justify="right"),
    ]
    document = {"head": 1, "rows": rows, "tail": "z"}
    out = io.StringIO()
    write_stream(fmt, _streamed(STREAM_CHUNKS), {"head": 1, "rows": None, "tail": "z"}, "rows", out)
    assert out.getvalue() == render(fmt, [("T", rows, cols)], document)


def _repr(value: float) -> str:
    return repr(value) if value == value else ""


def test_stream_json_floats_round_trip():
    out = io.StringIO()
    write_stream(OutputFormat.json, _streamed(STREAM_CHUNKS), {"rows": []}, "rows", out)
    values = [r["v"] for r in json.loads(out.getvalue())["rows"]]
    assert values[0] == 0.1 + 0.2 and values[1] is None and values[2] == -1e-300


def test_stream_plain_table_whole_output():
    out = io.StringIO()
    write_stream(OutputFormat.table, _streamed(STREAM_CHUNKS), {}, "rows", out)
    assert out.getvalue() == (
        "T\n"
        "k                value\n"
        "-  -------------------\n"
        "1  0.30000000000000004\n"
        "2                     \n"
        "3              -1e-300\n"
        "4                  2.5\n"
        "5   0.3333333333333333\n"
    )
