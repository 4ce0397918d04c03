"""The committed ledgers (tables/equations/*.toml), each loaded and validated once per test
process: a load parses every formula of the ledger, and a test of one row would otherwise pay
for all of them. A test of an edited copy of tables/ loads that copy itself (load_ledger)."""

from __future__ import annotations

from functools import cache
from pathlib import Path

from pendcli.core.ledger import Ledger, load_ledger

TABLES = Path(__file__).resolve().parent.parent / "tables"


@cache
def committed_ledger(paper: str) -> Ledger:
    """``load_ledger(paper, TABLES)``, shared (a Ledger is frozen: its rows, symbols and
    scopes are tuples, and ``symbols_for`` returns a new dict each call)."""
    return load_ledger(paper, TABLES)
