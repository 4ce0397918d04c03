"""The committed ledgers (tables/equations/*.toml), each loaded and validated once per test
process: a load parses every formula of the ledger, and a test of one row would otherwise pay
for all of them. A test of an edited copy of tables/ loads that copy itself (load_ledger)."""

from __future__ import annotations

import tomllib
from collections.abc import Callable
from functools import cache
from pathlib import Path

from pendcli.data.ledger import load_ledger
from pendcli.data.ledger_rows import Ledger, LedgerRow

TABLES = Path(__file__).resolve().parents[2] / "tables"


@cache
def committed_ledger(paper: str) -> Ledger:
    """``load_ledger(paper, TABLES)``, shared (a Ledger is frozen: its rows, symbols and
    scopes are tuples, and ``symbols_for`` returns a new dict each call)."""
    return load_ledger(paper, TABLES)


@cache
def _raw_rows(paper: str) -> tuple[dict[str, object], ...]:
    with (TABLES / "equations" / f"{paper}.toml").open("rb") as file:
        return tuple(tomllib.load(file)["equation"])


def row_ids(
    paper: str, keep: Callable[[dict[str, object]], bool] = lambda entry: True
) -> list[str]:
    """The ids of the committed rows whose TOML entry ``keep`` accepts, in ledger order, read
    with tomllib alone: for a parametrize list, so that collecting the tests does not parse
    every formula of the ledger (``committed_row`` loads and validates it at the first test)."""
    return [str(entry["id"]) for entry in _raw_rows(paper) if keep(entry)]


def first_line(entry: dict[str, object]) -> int:
    """The first line of a raw entry's ``lines`` (0 without)."""
    lines = entry.get("lines")
    return int(lines[0]) if isinstance(lines, list) and lines else 0


def committed_row(row_id: str) -> LedgerRow:
    """Row ``row_id`` of its paper's committed (validated) ledger."""
    ledger = committed_ledger(row_id.split(".")[0])
    return next(r for r in ledger.rows if r.id == row_id)


def paragraphs_by_hand(text: str) -> list[tuple[int, int]]:
    """The text's paragraphs of prose counted by hand, independently of
    pendcli.data.reading.prose_paragraphs: a line is prose unless it lies in a $$ block (the
    blocks of the committed texts begin and end on lines of their own)."""
    spans: list[tuple[int, int]] = []
    inside, first = False, None
    for number, line in enumerate(text.split("\n"), 1):
        opens = line.count("$$") % 2 == 1
        prose = bool(line.strip()) and not inside and not line.strip().startswith("$$")
        if opens:
            inside = not inside
        if prose and first is None:
            first = number
        if not prose and first is not None:
            spans.append((first, number - 1))
            first = None
    last = len(text.split("\n"))
    return spans if first is None else [*spans, (first, last)]
