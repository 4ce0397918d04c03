"""What a command asks for several times is computed once per content: a ledger per (TOML,
paper text), a formula per (text, symbol table); a changed file is read again, and a failure
is never kept."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from pendcli.base.errors import PendcliError
from pendcli.data import printed
from pendcli.data.ledger import ledger_path, load_ledger
from pendcli.data.printed import parse_formula
from pendcli.data.tables import read_toml

QUOTE = "La formule (5) donnera ensuite"  # a quote of tisserand's ledger, in its text


def test_a_ledger_is_loaded_once_per_content(tables: Path) -> None:
    first = load_ledger("tisserand", tables)
    assert load_ledger("tisserand", tables) is first
    path = ledger_path("tisserand", tables)
    statement = 'statement = "k = √(g/l)"'
    source = path.read_text(encoding="utf-8")
    assert source.count(statement) == 1
    path.write_text(source.replace(statement, 'statement = "k, a rate"'), encoding="utf-8")
    edited = load_ledger("tisserand", tables)
    assert edited is not first
    assert [r.statement for r in edited.rows].count("k, a rate") == 1


def test_a_changed_paper_text_is_read_again(tables: Path) -> None:
    ledger = load_ledger("tisserand", tables)
    text = ledger.text.read_text(encoding="utf-8")
    assert text.count(QUOTE) == 1
    ledger.text.write_text(text.replace(QUOTE, "La formule (5) donne"), encoding="utf-8")
    with pytest.raises(PendcliError, match="is not in its lines"):
        load_ledger("tisserand", tables)
    ledger.text.unlink()
    with pytest.raises(PendcliError, match=r"paper text .* is missing"):
        load_ledger("tisserand", tables)


def _counting(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The sides the grammar builds from now on."""
    built: list[str] = []
    parse_side = printed.parse_side

    def counted(where: str, text: str, *rest: object) -> object:
        built.append(text)
        return parse_side(where, text, *rest)  # type: ignore[arg-type]

    monkeypatch.setattr(printed, "parse_side", counted)
    return built


def test_a_formula_is_parsed_once_per_text_and_symbol_table(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    built = _counting(monkeypatch)
    symbols = {"q_once": "L", "w_once": "T"}
    text = "q_once = 3*w_once**2 + q_once/7"
    first = parse_formula("row a: printed", text, symbols)
    again = parse_formula("row b: reading_formula", text, dict(reversed(symbols.items())))
    assert again is first and built == ["q_once", "3*w_once**2 + q_once/7"]
    other = parse_formula("row c: printed", text, {**symbols, "w_once": "1"})
    assert other is not first and other == first and len(built) == 4


def test_a_formula_that_fails_is_not_kept(monkeypatch: pytest.MonkeyPatch) -> None:
    for where in ("row a: printed", "row b: printed"):
        with pytest.raises(PendcliError, match=f"^{where}: .*undeclared_once"):
            parse_formula(where, "x_once = undeclared_once", {"x_once": "L"})


def test_a_table_is_parsed_once_and_each_reader_gets_its_own_copy(tmp_path: Path) -> None:
    path = tmp_path / "record.toml"
    path.write_text('[[row]]\nid = "a"\nlines = [1, 2]\n', encoding="utf-8")
    first = read_toml(path, "record")
    first["row"][0]["lines"].append(3)  # a reader that edits what it got
    assert read_toml(path, "record") == tomllib.loads(path.read_text(encoding="utf-8"))
    path.write_text('[[row]]\nid = "b"\n', encoding="utf-8")
    assert read_toml(path, "record") == {"row": [{"id": "b"}]}
    for name in ("bad.toml", "worse.toml"):  # a failure is not kept: each names its file
        (tmp_path / name).write_text('[[row]]\nid = "b"\nid = "c"\n', encoding="utf-8")
        with pytest.raises(PendcliError, match=f"record {tmp_path / name} is not valid TOML"):
            read_toml(tmp_path / name, "record")
