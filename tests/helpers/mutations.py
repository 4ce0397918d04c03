"""One edit of a committed ledger, judged again: the shared part of the mutation tests of
tests/**/test_printed*.py (a changed coefficient, or a misprint set to its reading, must be
refused).

The edit is made to the committed ledger's text in memory and validated by the loader's own
``parse_ledger`` under the committed path. A formula's parse is cached on its text and symbol
table (``pendcli.data.printed.parse_formula``), so the rows the edit leaves alone are served
from the cache and only the edited one is parsed again; a reference is cached on its name and
the tables folder, so one row's reference is built once per process, not once per case. A
copy of tables/ (``altered_tables``) is made only where the judgement reads the edited file
through $PENDCLI_TABLES (the published tables a numeric reference compares with). The edited
text is read as TOML once per ledger: an edit inside one ``[[equation]]`` block replaces that
entry of the committed ledger's parse by the block's own parse (tomllib reads an entry the same
alone or among the others; 18 ms a read of Lecornu's 168 kB saved on each of ~90 edits).
"""

from __future__ import annotations

import copy
import shutil
import tomllib
from functools import cache
from pathlib import Path
from typing import Any

from pendcli.data.ledger import ledger_path, parse_ledger
from pendcli.data.ledger_rows import Ledger, LedgerRow
from pendcli.verify.ledger_references import References, verify_printed

TABLES = Path(__file__).resolve().parents[2] / "tables"


def edit_once(text: str, old: str, new: str, within: str | None = None) -> str:
    """``text`` with ``old`` replaced by ``new``; ``old`` must occur exactly once (in the
    [[equation]] block of row ``within`` when given), so an edit never lands elsewhere."""
    start, end = 0, len(text)
    if within is not None:
        start = text.index(f'id = "{within}"')
        following = text.find("[[equation]]", start)
        end = len(text) if following < 0 else following
    block = text[start:end]
    assert block.count(old) == 1, (within, old)
    return text[:start] + block.replace(old, new) + text[end:]


def altered_ledger(paper: str, old: str, new: str, within: str | None = None) -> Ledger:
    """The committed ledger of ``paper`` with one edit, validated as ``load_ledger`` would."""
    path = ledger_path(paper, TABLES)
    text = path.read_text(encoding="utf-8")
    edited = edit_once(text, old, new, within)
    start = text.index(f'id = "{within}"') if within is not None else 0
    at = text.index(old, start)
    return parse_ledger(_edited_toml(paper, edited, (at, at + len(old), new)), paper, path, TABLES)


@cache
def _committed_toml(paper: str) -> tuple[str, dict[str, Any]]:
    text = ledger_path(paper, TABLES).read_text(encoding="utf-8")
    return text, tomllib.loads(text)


_ENTRY = "\n[[equation]]\n"


def _edited_toml(paper: str, edited: str, edit: tuple[int, int, str]) -> dict[str, Any]:
    """``tomllib.loads(edited)``, the committed ledger with ``text[at:end]`` replaced by ``new``:
    where the edit lies inside one ``[[equation]]`` entry (from its header to the next table
    header), the committed parse with that entry read again alone; else the whole text read."""
    text, parsed = _committed_toml(paper)
    at, end, new = edit
    start = text.rfind(_ENTRY, 0, at) + 1
    stop = text.find("\n[", at)
    stop = len(text) if stop < 0 else stop + 1
    if start == 0 or end > stop or text.find("\n[", start, at) >= 0:
        return tomllib.loads(edited)  # not inside one entry
    index = text.count(_ENTRY, 0, start)
    entries = parsed["equation"]
    try:
        alone = tomllib.loads(text[start:stop])
        read = tomllib.loads(text[start:at] + new + text[end:stop])
    except tomllib.TOMLDecodeError:
        return tomllib.loads(edited)  # the whole text's error, with its line
    if alone != {"equation": [entries[index]]} or list(read) != ["equation"]:
        return tomllib.loads(edited)
    if len(read["equation"]) != 1:
        return tomllib.loads(edited)
    out = copy.deepcopy(parsed)
    out["equation"][index] = read["equation"][0]
    return out


def altered_row(
    paper: str, row_id: str, old: str, new: str, within: str | None = None
) -> tuple[LedgerRow, dict[str, str]]:
    """Row ``row_id`` of the edited ledger and the symbols of its place in the text."""
    ledger = altered_ledger(paper, old, new, within)
    row = next(r for r in ledger.rows if r.id == row_id)
    return row, ledger.symbols_for(row)


def judged_after_edit(
    references: References, row_id: str, old: str, new: str, within: str | None = None
) -> tuple[str | None, str | None]:
    """``verify_printed`` of the edited row: (its computed status and why, the problem)."""
    row, symbols = altered_row(row_id.split(".")[0], row_id, old, new, within)
    return verify_printed(row, symbols, references)


def printed_line(ledger: Ledger, row_id: str, value_of: str = "printed") -> str:
    """The TOML line ``printed = '…'`` of a row, holding its printed form, or the formula of
    another of its fields (``reading_formula``: the misprint set to its reading)."""
    row = next(r for r in ledger.rows if r.id == row_id)
    return f"printed = '{getattr(row, value_of)}'"


def field_line(row: LedgerRow, field: str) -> str:
    """The TOML line ``field = '…'`` (or ``"…"``) of a committed row's formula field
    (``printed``, ``reading_formula``, ``corrected_formula``): the ``old`` of an edit of it."""
    text = ledger_path(row.paper, TABLES).read_text(encoding="utf-8")
    value = getattr(row, field)
    single, double = f"{field} = '{value}'", f'{field} = "{value}"'
    return single if single in text else double


def altered_field(row: LedgerRow, field: str, text: str) -> tuple[LedgerRow, dict[str, str]]:
    """Row ``row`` of its committed ledger with the formula ``field`` set to ``text`` (the
    TOML edited and validated as :func:`altered_row` does), and the symbols of its place."""
    old = field_line(row, field)
    quote = old[len(field) + 3]
    new = f"{field} = {quote}{text}{quote}"
    return altered_row(row.paper, row.id, old, new, within=row.id)


def altered_tables(tmp_path: Path, *edits: tuple[str, str, str]) -> Path:
    """A copy of tables/ with ``(file under tables/, old, new)`` edits, each applied once."""
    root = tmp_path / "tables"
    shutil.copytree(TABLES, root)
    for name, old, new in edits:
        path = root / name
        path.write_text(edit_once(path.read_text(encoding="utf-8"), old, new), encoding="utf-8")
    return root
