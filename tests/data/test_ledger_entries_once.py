"""A ledger's entries validated once per content: a ledger edited in one entry validates that
entry alone again, and a changed entry, or an unchanged one in a changed context (the paper's
text, the symbols, the reading table), is never served the validation of what it was."""

from __future__ import annotations

import copy
import tomllib
from pathlib import Path
from typing import Any

import pytest

from pendcli.base.errors import PendcliError
from pendcli.data.ledger import ledger_path, parse_ledger
from pendcli.data.ledger_rows import Ledger
from pendcli.verify import ledger_formulas

TABLES = Path(__file__).resolve().parents[2] / "tables"
ROW = "tisserand.result.square-from-formula-5"
QUOTE = "La formule (5) donnera ensuite"  # the row's quote, printed within its lines


def _raw() -> dict[str, Any]:
    return tomllib.loads(ledger_path("tisserand", TABLES).read_text(encoding="utf-8"))


def _parsed(raw: dict[str, Any], root: Path = TABLES) -> Ledger:
    return parse_ledger(copy.deepcopy(raw), "tisserand", ledger_path("tisserand", root), root)


def _edited(**changes: Any) -> dict[str, Any]:
    """The committed ledger with the entry ``ROW`` changed (a value None: the key removed)."""
    raw = _raw()
    entry = next(e for e in raw["equation"] if e["id"] == ROW)
    entry.update(changes)
    for key in [k for k, v in entry.items() if v is None]:
        del entry[key]
    return raw


@pytest.mark.parametrize(
    ("change", "refused"),
    [
        ({"quote": "La formule (6) donnera ensuite"}, "is not in its lines"),
        ({"lines": [68, 10**6]}, "lines"),
        ({"printed": "(k*dt/dpsi)**2 = undeclared_name"}, "'undeclared_name' is not a declared"),
        ({"reading_formula": "k = undeclared_name"}, "'undeclared_name' is not a declared"),
        ({"status": "proved"}, "unknown status"),
        ({"status": "holds"}, "'reading' is required for, and only for, misprint"),
        ({"reference": None}, "needs a reference"),
    ],
)
def test_a_changed_entry_is_validated_again(change: dict[str, Any], refused: str) -> None:
    """The committed entry is valid (and kept as such); each edit of it is refused as a
    fresh load refuses it."""
    assert any(r.id == ROW for r in _parsed(_raw()).rows)
    with pytest.raises(PendcliError, match=refused):
        _parsed(_edited(**change))
    with pytest.raises(PendcliError, match=refused):  # a refusal is not kept either
        _parsed(_edited(**change))


def test_an_unchanged_entry_is_validated_again_in_a_changed_text(tables: Path) -> None:
    raw = _raw()
    _parsed(raw, tables)
    text = tables / "papers" / "tisserand.txt"
    committed = text.read_text(encoding="utf-8")
    assert committed.count(QUOTE) == 1
    text.write_text(committed.replace(QUOTE, "La formule (5) donne"), encoding="utf-8")
    with pytest.raises(PendcliError, match=f"{ROW}: (quote|wrong_term) .* is not in its lines"):
        _parsed(raw, tables)
    text.write_text(committed, encoding="utf-8")
    assert any(r.id == ROW for r in _parsed(raw, tables).rows)


def test_an_unchanged_entry_is_validated_again_in_changed_symbols() -> None:
    _parsed(_raw())
    raw = _raw()
    del raw["symbols"]["dpsi"]  # a symbol the row's printed form is written in
    with pytest.raises(PendcliError, match="'dpsi' is not a declared"):
        _parsed(raw)
    raw = _raw()
    raw["symbols"]["dpsi"] = "L^x"  # a dimension that is none
    with pytest.raises(PendcliError, match=r"\[symbols\] dpsi"):
        _parsed(raw)


def test_an_unchanged_entry_is_read_through_the_reading_table_it_is_loaded_with() -> None:
    """The rows a reading applies to carry it; loaded without that reading, the same
    entries carry none (and are not served the rows read through it)."""
    raw = _raw()
    read = {r.id: r.readings for r in _parsed(raw).rows if r.readings}
    assert read, "a reading of the committed ledger applies to some row"
    reading = raw["reading"][0]["id"]
    citing = {i for i, rs in read.items() if any(name == reading for name, _ in rs)}
    assert citing
    raw["reading"] = raw["reading"][1:]
    without = {r.id: r.readings for r in _parsed(raw).rows}
    for row_id in citing:
        assert all(name != reading for name, _ in without[row_id]), row_id


def test_a_ledger_edited_in_one_entry_checks_that_entry_alone(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    _parsed(_raw())
    named: list[str] = []
    check = ledger_formulas.check_formula

    def counted(where: str, text: str, symbols: Any) -> None:
        named.append(where)
        check(where, text, symbols)

    monkeypatch.setattr(ledger_formulas, "check_formula", counted)
    entry = next(e for e in _raw()["equation"] if e["id"] == ROW)
    ledger = _parsed(_edited(printed=entry["printed"].replace("/16", "/17")))
    assert "/17" in next(r for r in ledger.rows if r.id == ROW).printed  # type: ignore[operator]
    assert named and all(f": {ROW}: " in where for where in named), named
