"""Lecornu's equation ledger: every label the text prints has a row. Every row's check is run
and compared with its recorded status once, in tests/data/test_ledger.py (with the other papers)."""

from __future__ import annotations

from collections import Counter

from helpers.ledgers import committed_ledger

from pendcli.data.ledger import CHECKED_STATUSES, labels_in_text


def test_every_printed_label_has_a_row() -> None:
    ledger = committed_ledger("lecornu")
    printed = Counter(labels_in_text(ledger.text.read_text(encoding="utf-8")))
    rows = ledger.labels()
    missing = {label: n for label, n in printed.items() if rows[label] < n}
    assert not missing, f"labels printed more often than the ledger has rows: {missing}"
    assert len(printed) >= 55  # (1)-(52), (17'), (21'), (42')


def test_labels_one_to_fifty_two() -> None:
    rows = committed_ledger("lecornu").labels()
    assert all(rows[f"({n})"] >= 1 for n in range(1, 53))
    assert all(rows[f"({n})"] == 2 for n in (18, 19, 20, 21, 22))  # re-used in section II


def test_most_rows_are_checked() -> None:
    rows = committed_ledger("lecornu").rows
    assert len([r for r in rows if r.status in CHECKED_STATUSES]) >= 0.8 * len(rows)
