"""Characters that would act on a reader's terminal or reorder what a reader sees: a control
character (ESC, CR, NUL...) or a bidirectional override in a table or a paper's text, raw or
as a TOML escape, is refused when the file is read, in one line that names the file, the line
and the code point, exit 2; a table file too large to be one is refused before it is read;
rich markup in a table's string is shown as its text, never applied."""

from __future__ import annotations

import io
import os
import shutil
from pathlib import Path

import pytest
from helpers.cli import assert_clean_error, invoke, run_cli

from pendcli.base.errors import PendcliError
from pendcli.data.tables import MAX_TABLE_BYTES, clear_table_cache, load_paper_table

REPO_TABLES = Path(__file__).resolve().parents[2] / "tables"
# every character the rule refuses, by class: C0 controls, DEL and C1, the bidi controls
REFUSED = ["\x00", "\x1b", "\r", "\x0b", "\x7f", "\x9b", "\u202e", "\u2066", "\u2069"]
KEPT = ["\t", "é", "θ", "\u00a0", "—", "½"]


def _with_note(tables: Path, note_toml: str) -> Path:
    """Charbonnier's first claim with ``note = <note_toml>`` (TOML source) after its id."""
    path = tables / "published" / "charbonnier.toml"
    text = path.read_text(encoding="utf-8")
    first = 'id = "charbonnier.I_pi.n0"'
    assert first in text
    path.write_text(text.replace(first, f"{first}\nnote = {note_toml}", 1), encoding="utf-8")
    return path


@pytest.mark.parametrize("char", REFUSED, ids=[f"U+{ord(c):04X}" for c in REFUSED])
def test_a_hidden_character_in_a_table_raw_or_escaped_is_refused(tables: Path, char: str) -> None:
    escaped = f'"see \\u{ord(char):04x}[31m red"'
    for note in (escaped, f'"see {char} here"' if char not in "\x00\r" else escaped):
        path = _with_note(tables, note)
        clear_table_cache()
        with pytest.raises(PendcliError) as err:
            load_paper_table("charbonnier")
        message = str(err.value)
        assert str(path) in message and f"U+{ord(char):04X}" in message, message
        assert "\n" not in message and char not in message, message
        shutil.copy(REPO_TABLES / "published" / "charbonnier.toml", path)


@pytest.mark.parametrize("char", KEPT)
def test_printable_text_is_kept(tables: Path, char: str) -> None:
    _with_note(tables, f'"a {char} b"')
    claim = next(c for c in load_paper_table("charbonnier").claims if c.id.endswith("n0"))
    assert claim.note == f"a {char} b"


def test_escape_codes_in_a_paper_text_are_one_line_naming_the_line(tables: Path) -> None:
    path = tables / "papers" / "tisserand.txt"
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    lines[9] = "\x1b]8;;https://x\x1b\\link\x1b]8;;\x1b\\\n"  # an OSC 8 terminal hyperlink
    path.write_text("".join(lines), encoding="utf-8")
    result = invoke("equations", "-p", "tisserand", "-f", "json")
    assert_clean_error(result.code, result.err)
    assert f"{path}: line 10, column 1: U+001B" in result.err, result.err
    assert "\x1b" not in result.err + result.out


def test_a_table_file_over_the_size_limit_is_refused_unread(tables: Path) -> None:
    path = tables / "published" / "charbonnier.toml"
    with path.open("ab") as stream:  # sparse: no disk or memory is spent on the hole
        stream.truncate(MAX_TABLE_BYTES + 1)
    clear_table_cache()
    with pytest.raises(PendcliError, match="over 16,000,000 bytes, the limit of a table"):
        load_paper_table("charbonnier")


def test_rich_markup_in_a_styled_cell_is_shown_as_text() -> None:
    from rich.console import Console

    from pendcli.output.columns import Column
    from pendcli.output.table import to_rich_table

    text = "[link=https://example.invalid]x[/link] [bold]y[/]"
    column = Column("v", "v", style=lambda _: "red")
    out = io.StringIO()
    Console(file=out, width=200, color_system=None).print(to_rich_table([{"v": text}], [column]))
    assert text in out.getvalue()


@pytest.mark.slow
def test_a_control_character_through_the_installed_cli_is_one_line(tables: Path) -> None:
    _with_note(tables, '"\\u001b[2J cleared"')
    env = {"PENDCLI_TABLES": str(tables), "PENDCLI_JOBS": "1", "PENDCLI_CACHE": "off"}
    for command in (["reproduce", "-p", "charbonnier"], ["check"]):
        out = run_cli(*command, env={**os.environ, **env})
        assert_clean_error(out.returncode, out.stderr)
        assert "U+001B" in out.stderr and "\x1b" not in out.stdout + out.stderr
