"""Bad table files: every one is refused when read, in one line that names
the file (and, for bytes that are not UTF-8, the offset), with exit 2: no hang, no internal
error (exit 3), no empty result, and the committed tables untouched.

The constants of every paper are set to non-finite, negative, zero, tiny, huge and overflowing
values; every kind of table file is replaced by binary junk, non-UTF-8 text, an empty file, a
folder, deep nesting. Most cases run the CLI in-process on a copy of ``tables/``; a
non-finite constant (``value = nan`` under Charbonnier's g), which once hung, runs the
installed CLI for real.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from helpers.cli import assert_clean_error, invoke

from pendcli.base.errors import PendcliError
from pendcli.data.tables import clear_table_cache, load_paper_table
from pendcli.papers.registry import PAPERS

REPO_TABLES = Path(__file__).resolve().parents[2] / "tables"
PENDCLI = Path(sys.executable).with_name("pendcli")


def digest(folder: Path) -> str:
    sha = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file() and not p.name.startswith(".")):
        sha.update(path.relative_to(folder).as_posix().encode() + b"\0" + path.read_bytes())
    return sha.hexdigest()


COMMITTED = digest(REPO_TABLES)


@pytest.fixture(autouse=True, scope="module")
def _committed_tables_untouched() -> Iterator[None]:
    yield
    assert digest(REPO_TABLES) == COMMITTED


def set_constant(tables: Path, key: str, name: str, value: str) -> Path:
    path = tables / "published" / f"{key}.toml"
    text = path.read_text(encoding="utf-8")
    pattern = rf"(\[paper\.constants\.{name}\]\nvalue = )[^\n]+"
    changed, count = re.subn(pattern, lambda m: m.group(1) + value, text)
    assert count == 1, (key, name)
    path.write_text(changed, encoding="utf-8")
    return path


# Every constant of the committed tables, with the range its table declares beside it.
DECLARED = {
    (key, c.name): c.range for key in PAPERS for c in load_paper_table(key, REPO_TABLES).constants
}
CONSTANTS = list(DECLARED)
BAD_VALUES = ["nan", "inf", "-inf", "-9.81", "0", "1e-300", "1e300", "1e999999", "-0.0"]
# One code path checks every constant (tables._constant_value): each paper's first constant
# meets every bad value; each constant meets its own range's edges, and a NaN.
EVERY_BAD_VALUE = {key: name for key, name in reversed(CONSTANTS)}


@pytest.mark.parametrize(("key", "name"), CONSTANTS, ids=[f"{k}.{n}" for k, n in CONSTANTS])
def test_every_constant_out_of_its_range_is_refused_at_load(
    tables: Path, key: str, name: str
) -> None:
    low, high = DECLARED[key, name]
    bad = BAD_VALUES if EVERY_BAD_VALUE[key] == name else ["nan"]
    for value in [*bad, repr(high * 1.01), repr(low * 0.99)]:
        path = set_constant(tables, key, name, value)
        clear_table_cache()
        with pytest.raises(PendcliError) as err:
            load_paper_table(key)
        message = str(err.value)
        assert "\n" not in message and str(path) in message, message
        assert f"[paper.constants.{name}]" in message and "valid range" in message, message
        shutil.copy(REPO_TABLES / "published" / f"{key}.toml", path)
    clear_table_cache()
    assert load_paper_table(key).constant(name) == pytest.approx(
        load_paper_table(key, REPO_TABLES).constant(name)
    )


def test_a_constant_without_a_declared_range_or_with_a_bad_one_is_refused(tables: Path) -> None:
    path = tables / "published" / "charbonnier.toml"
    text = path.read_text(encoding="utf-8")
    extra = '[paper.constants.c]\nvalue = 3e8\nunit = "m/s"\nsource = "assumption: x"\n\n'
    path.write_text(text.replace("[paper.constants.g]", extra + "[paper.constants.g]"), "utf-8")
    with pytest.raises(PendcliError, match=r"constants\.c\]: no declared range for this constant"):
        load_paper_table("charbonnier")
    for bad in ("[100.0, 1.0]", "[1.0]", "[1.0, nan]", '["1", "2"]', "[true, 2]"):
        path.write_text(re.sub(r"range = \[1\.0, 100\.0\]", f"range = {bad}", text, count=1))
        clear_table_cache()
        with pytest.raises(PendcliError, match=r"constants\.g\]: range must be \[low, high\]"):
            load_paper_table("charbonnier")


@pytest.mark.slow
def test_the_nan_constant_that_hung_check_is_one_line_exit_2_in_the_real_process(
    tables: Path,
) -> None:
    path = set_constant(tables, "charbonnier", "g", "nan")
    env = {k: v for k, v in os.environ.items() if k != "PENDCLI_DEBUG"}
    env.update(PENDCLI_TABLES=str(tables), PENDCLI_JOBS="1")
    for command in (["check"], ["reproduce", "-p", "charbonnier"]):
        out = subprocess.run(
            [str(PENDCLI), *command], env=env, capture_output=True, text=True, timeout=600
        )
        assert_clean_error(out.returncode, out.stderr)
        assert str(path) in out.stderr and "value = nan is out of range" in out.stderr


# --- whole files: junk, not UTF-8, empty, a folder, deep nesting -------------------------------

JUNK = {
    "binary": b"\x00\x01\x02\xff\xfe\x80 junk \x9c",
    "latin-1": 'titre = "pendule à longueur variable"\n'.encode("latin-1"),
    "empty": b"",
    "blank": b"\n  \n",
    "deep-array": b"a = " + b"[" * 5000 + b"]" * 5000 + b"\n",
    "deep-table": b"a = " + b"{b = " * 40 + b"1" + b"}" * 40 + b"\n",
}
# the file, and a command that must read it (each fails before any real computation)
FILES = {
    "published/tisserand.toml": ["reproduce", "-p", "tisserand", "--no-formulas"],
    "equations/lecornu.toml": ["equations", "-p", "lecornu"],
    "papers/charbonnier.txt": ["equations", "-p", "charbonnier"],
}


# a text is not parsed: deep nesting means nothing there
DAMAGED = [(n, k) for n in FILES for k in JUNK if not (n.endswith(".txt") and k.startswith("deep"))]


@pytest.mark.parametrize(("name", "kind"), DAMAGED)
def test_a_damaged_table_file_is_one_line_exit_2(tables: Path, name: str, kind: str) -> None:
    path = tables / name
    path.write_bytes(JUNK[kind])
    code, _, err = invoke(*FILES[name])
    assert_clean_error(code, err)
    assert str(path) in err, err
    if kind in ("binary", "latin-1"):
        first = next(i for i, b in enumerate(JUNK[kind]) if b >= 0x80)
        assert f"not UTF-8 text: byte {first} " in err, err
    if kind in ("empty", "blank"):
        assert "is empty" in err, err
    if kind.startswith("deep"):
        assert "nested too deeply" in err, err


@pytest.mark.parametrize("name", list(FILES))
@pytest.mark.parametrize("how", ["deleted", "a folder"])
def test_a_missing_table_file_is_an_error_not_an_empty_result(
    tables: Path, name: str, how: str
) -> None:
    path = tables / name
    path.unlink()
    if how == "a folder":
        path.mkdir()
    code, out, err = invoke(*FILES[name])
    assert_clean_error(code, err)
    assert str(path) in err and ("is missing" if how == "deleted" else "is not a file") in err
    assert out == ""


def test_no_ledger_at_all_fails_equations_and_check(tables: Path) -> None:
    shutil.rmtree(tables / "equations")
    for command in (["equations"], ["check"]):
        code, out, err = invoke(*command)
        assert_clean_error(code, err)
        assert "equation ledger" in err and "is missing" in err and out == ""


TRADEOFF = [("tradeoff/conical.csv", k) for k in ("binary", "latin-1", "empty")]
TRADEOFF += [("tradeoff/measured.toml", k) for k in ("binary", "latin-1", "empty", "deep-array")]


@pytest.mark.parametrize(("name", "kind"), TRADEOFF)
def test_a_damaged_tradeoff_file_fails_the_report_before_it_is_drawn(
    tables: Path, tmp_path: Path, name: str, kind: str
) -> None:
    from pendcli.output.report import write_report
    from pendcli.run.reproduce import ReproduceResult

    path = tables / name
    path.write_bytes(JUNK[kind])
    out = tmp_path / "out"
    with pytest.raises(PendcliError) as err:
        write_report(ReproduceResult(papers=("tisserand",)), out, jobs=1)
    assert "\n" not in str(err.value) and str(path) in str(err.value), err.value
    assert not out.exists() and [p.name for p in tmp_path.iterdir()] == ["tables"]


def test_every_paper_loads_from_the_committed_tables() -> None:
    """The declared ranges hold the committed constants (the refusals above are not all)."""
    clear_table_cache()
    for key in PAPERS:
        table = load_paper_table(key, REPO_TABLES)
        assert all(c.range[0] <= c.value <= c.range[1] for c in table.constants)


def edit_row(tables: Path, key: str, row_id: str, old: str, new: str) -> None:
    """Replace ``old`` by ``new`` in the row ``row_id`` of the paper's ledger (its first
    occurrence after the row's id)."""
    path = tables / "equations" / f"{key}.toml"
    text = path.read_text(encoding="utf-8")
    start = text.index(f'id = "{row_id}"')
    end = text.find("[[", start)
    block = text[start:end]
    assert old in block, (row_id, old)
    path.write_text(text[:start] + block.replace(old, new, 1) + text[end:], encoding="utf-8")


LIMIT_ROW = "lecornu.result.small_x_asymptotics"  # kind limit: scale eps_, bounded
SERIES_ROW = "lecornu.eq.25"  # kind series: scale p, order 2
# a row's kind parameters made wrong: (row, old, new, what the one line must say)
BAD_PARAMETERS = {
    "unknown key for the kind": (
        SERIES_ROW,
        "order = 2",
        "order = 2\nbounded = true",
        "kind 'series' takes no 'bounded'",
    ),
    "bounded without scale": (LIMIT_ROW, 'scale = "eps_"\n', "", "'bounded' needs a 'scale'"),
    "order without scale": (SERIES_ROW, 'scale = "p"\n', "", "'order' needs a 'scale'"),
    "domain reversed": (
        LIMIT_ROW,
        "alpha = [0.3, 1.2]",
        "alpha = [1.2, 0.3]",
        "bounds reversed",
    ),
    "domain not a number": (
        LIMIT_ROW,
        "alpha = [0.3, 1.2]",
        'alpha = ["x", 1.2]',
        "of 'alpha': is not a number",
    ),
    "domain bound with a huge exponent": (
        LIMIT_ROW,
        "alpha = [0.3, 1.2]",
        'alpha = ["1e99999999", 1.2]',
        "of 'alpha': is not a number of at most 30 digits",
    ),
    "order not an integer": (
        SERIES_ROW,
        "order = 2",
        "order = 2.5",
        "'order' must be",
    ),
    "a scale without order": (SERIES_ROW, "order = 2\n", "", "'scale' needs an 'order'"),
}


@pytest.mark.parametrize("case", list(BAD_PARAMETERS))
def test_a_row_with_meaningless_kind_parameters_is_one_line_exit_2(tables: Path, case: str) -> None:
    row_id, old, new, says = BAD_PARAMETERS[case]
    edit_row(tables, "lecornu", row_id, old, new)
    code, out, err = invoke("equations", "-p", "lecornu")
    assert_clean_error(code, err)
    assert f"{row_id}: " in err and says in err and out == "", err
