"""Renderers compared whole against expected strings; they know nothing of pendulums."""

import json

from pendcli.render import Column, OutputFormat, render, to_csv, to_json, to_markdown

ROWS = [
    {"id": "a", "x": 1.5, "verdict": "agrees", "note": "pipe | here"},
    {"id": "b", "x": 0.1, "verdict": "discrepant", "note": None},
]
COLS = [Column("id", "id"), Column("x", "x", justify="right"), Column("verdict", "verdict")]


def test_markdown_whole_output():
    assert to_markdown(ROWS, [*COLS, Column("note", "note")]) == (
        "| id | x | verdict | note |\n"
        "|---|---:|---|---|\n"
        "| a | 1.5 | agrees | pipe \\| here |\n"
        "| b | 0.1 | discrepant |  |\n"
    )


def test_csv_whole_output_round_trips_floats():
    assert to_csv(ROWS, ["id", "x", "note"]) == "id,x,note\na,1.5,pipe | here\nb,0.1,\n"


def test_json_is_deterministic_and_has_no_nan():
    doc = {"claims": [{"v": float("nan"), "w": 0.1 + 0.2}], "formulas": []}
    text = to_json(doc)
    assert text == to_json(doc)
    assert json.loads(text) == {"claims": [{"v": None, "w": 0.30000000000000004}], "formulas": []}


def test_rich_table_renders_all_rows():
    from io import StringIO

    from rich.console import Console

    buf = StringIO()
    render(OutputFormat.table, [("T", ROWS, COLS)], {}, console=Console(file=buf, width=80))
    out = buf.getvalue()
    assert "agrees" in out and "discrepant" in out and "1.5" in out
