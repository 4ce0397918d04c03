"""Lecornu's slow-variation studies read each printed form from the tables in use
($PENDCLI_TABLES), row by row, not from the committed ledger."""

from __future__ import annotations

from pathlib import Path

from pendcli.papers.lecornu.formulas_slow import slow_row

OLD = "- 3*b/(4*g) + pi**2*b/(16*g)'"  # line 555 as printed
NEW = "- 5*b/(4*g) + pi**2*b/(16*g)'"  # a changed coefficient: the residual is then O(b)


def test_an_edit_of_the_tables_in_use_reaches_the_quarter_time(tables: Path) -> None:
    ledger = tables / "equations" / "lecornu.toml"
    text = ledger.read_text(encoding="utf-8")
    assert text.count(OLD) == 1
    ledger.write_text(text.replace(OLD, NEW), encoding="utf-8")
    row = slow_row("quarter_time")  # the tables in use, the other two studies not measured
    assert row.verdict == "fails", row.note
    assert row.observed_order is not None and row.observed_order < 1.5
