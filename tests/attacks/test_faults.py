"""Fault injection on the committed tables: each fault ends in the old or the new
set of tables, never a mix or a cut file, and in one named line with the right exit code.

Process-level faults (kill -9, a file-size limit, a read-only folder) run `pendcli check
--update` in a child process on a copy of ``tables/``, made to differ from what the code
regenerates so that "unchanged" and "rewritten" can be told apart byte for byte. The faults
are in the writing, so the child is served the tables' computation, done once for the run
(tests/helpers/regenerated.py), and reaches its lock and writer as the real command does
with the same files (tests/run/test_determinism.py runs the whole command). Faults in
the data (a renamed claim id, a non-finite or cut committed table, a bad tradeoff table) run
the CLI in-process, where the recomputation is cached across tests.
"""

from __future__ import annotations

import contextlib
import csv
import ctypes
import io
import os
import re
import resource
import shutil
import signal
import subprocess
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from helpers.cli import NO_BYTECODE, assert_clean_error, invoke
from helpers.regenerated import SERVED_CLI, served

from pendcli.base.errors import PendcliError
from pendcli.data.tables import clear_table_cache
from pendcli.papers.registry import PAPERS, claim_rows
from pendcli.run.drift import CLAIM_COLUMNS

REPO_TABLES = Path(__file__).resolve().parents[2] / "tables"
CLONE_NEWUSER = 0x10000000  # linux/sched.h


def copy_tables(dest: Path) -> Path:
    shutil.copytree(
        REPO_TABLES, dest, ignore=shutil.ignore_patterns(".*"), copy_function=shutil.copy
    )
    return dest


def snapshot(folder: Path) -> dict[str, bytes] | None:
    """Every file under ``folder`` with its bytes; None when the folder is gone."""
    if not folder.is_dir():
        return None
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))}


def make_stale(tables: Path) -> None:
    """Edit a committed verdict, so that `check --update` has something to rewrite."""
    path = tables / "regenerated" / "lecornu-claims.csv"
    path.write_text(path.read_text(encoding="utf-8").replace("agrees", "discrepant", 1), "utf-8")


def leftovers(tables: Path) -> list[str]:
    """Temporary folders of an interrupted swap (``.regenerated.new-*``, ``.old-*``)."""
    return sorted(p.name for p in tables.glob(".regenerated.*") if p.is_dir())


def write_signature(tables: Path) -> list[tuple[str, int, int]]:
    """What a writer of the set changes first: a temporary folder beside, or a table's stat.
    Polled every half millisecond while a whole `check --update` runs: one listing of each
    folder and one stat per file (a quarter of the CPU of globbing and stating each twice)."""
    stats = []
    for entry in _entries(tables / "regenerated"):
        try:
            stat = entry.stat()
        except FileNotFoundError:  # removed since the listing
            continue
        stats.append((entry.name, stat.st_mtime_ns, stat.st_size))
    beside = [e.name for e in _entries(tables) if e.name.startswith(".regenerated.") and e.is_dir()]
    return [(name, 0, 0) for name in sorted(beside)] + sorted(stats)


def _entries(folder: Path) -> list[os.DirEntry[str]]:
    try:
        with os.scandir(folder) as found:
            return list(found)
    except FileNotFoundError:
        return []


def cli_command(computed: Path, *args: str) -> list[str]:
    """`pendcli ARGS` in a fresh process, its tables' computation served from ``computed``."""
    return [*SERVED_CLI, str(computed), *args]


def tables_env(tables: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "PENDCLI_DEBUG"}
    return {**env, "PENDCLI_TABLES": str(tables), "COLUMNS": "200"}


def run_cli(
    tables: Path, computed: Path, *args: str, preexec: Callable[[], None] | None = None
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        cli_command(computed, *args),
        env={**tables_env(tables), **(NO_BYTECODE if preexec is _limit_file_size else {})},
        capture_output=True,
        text=True,
        preexec_fn=preexec,
        timeout=300,
        cwd=tables.parent,
    )


def assert_one_line_error(out: subprocess.CompletedProcess[str], path: Path) -> None:
    lines = [line for line in out.stderr.splitlines() if line.strip()]
    assert out.returncode == 2, out.stderr
    assert len(lines) == 1 and lines[0].startswith("pendcli: error: "), out.stderr
    assert str(path) in lines[0], lines[0]


# ---------------------------------------------------------------------------------------------
# Process-level faults during `pendcli check --update`


def test_kill_during_check_update_leaves_the_old_or_the_new_set(
    tmp_path: Path, computed_tables: Path
) -> None:
    tables = copy_tables(tmp_path / "tables")
    make_stale(tables)
    old = snapshot(tables / "regenerated")
    proc = subprocess.Popen(
        cli_command(computed_tables, "check", "--update", "--quiet"),
        env=tables_env(tables),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        cwd=tmp_path,
    )
    # Kill at the dangerous moment: as soon as the new set starts being written (beside the
    # folder, or, were it written in place, into it).
    untouched = write_signature(tables)
    deadline = time.monotonic() + 300
    while (
        proc.poll() is None and write_signature(tables) == untouched and time.monotonic() < deadline
    ):
        time.sleep(0.0005)
    proc.kill()
    proc.wait()
    killed = snapshot(tables / "regenerated")
    finished = run_cli(
        tables, computed_tables, "check", "--update"
    )  # the next run recovers and completes
    assert finished.returncode == 0, finished.stderr
    new = snapshot(tables / "regenerated")
    assert new is not None and new != old
    assert killed in (old, new)
    assert leftovers(tables) == []


@pytest.mark.slow
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_or_term_during_check_update_is_one_line_and_old_or_new(
    tmp_path: Path, signum: signal.Signals, computed_tables: Path
) -> None:
    """Stopped once the write has begun (its lock taken): the old set or the new, status 130
    or 143, one line, no temporary folder, no lock file, no traceback."""
    tables = copy_tables(tmp_path / "tables")
    make_stale(tables)
    old = snapshot(tables / "regenerated")
    proc = subprocess.Popen(
        cli_command(computed_tables, "check", "--update", "--quiet"),
        env={**tables_env(tables), "PENDCLI_JOBS": "1"},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        cwd=tmp_path,
        start_new_session=True,
    )
    lock = tables / ".regenerated.lock"
    for _ in range(400_000):  # bounded by count: until the writer holds its lock
        if proc.poll() is not None or lock.exists():
            break
        time.sleep(0.0005)
    if proc.poll() is None:
        os.killpg(proc.pid, signum)
    _, err = proc.communicate()
    after = snapshot(tables / "regenerated")
    assert "Traceback" not in err, err
    assert sorted(p.name for p in tables.iterdir() if p.name.startswith(".")) == []
    if proc.returncode == 0:  # it finished first: the new set
        assert after != old
        return
    assert proc.returncode == 128 + signum, err
    assert err == f"pendcli: error: interrupted by {signum.name}\n"
    if after != old:  # the swap came first: the whole new set
        assert after is not None and run_cli(tables, computed_tables, "check").returncode == 0


def _limit_file_size() -> None:
    # Below the size of lecornu-claims.csv (about 6 kB), above the small tables written first.
    resource.setrlimit(resource.RLIMIT_FSIZE, (2048, resource.getrlimit(resource.RLIMIT_FSIZE)[1]))


def test_full_disk_during_check_update_is_a_named_error_and_changes_nothing(
    tmp_path: Path, computed_tables: Path
) -> None:
    tables = copy_tables(tmp_path / "tables")
    make_stale(tables)
    before = snapshot(tables / "regenerated")
    out = run_cli(tables, computed_tables, "check", "--update", preexec=_limit_file_size)
    assert_one_line_error(out, tables)
    assert "File too large" in out.stderr
    assert snapshot(tables / "regenerated") == before
    assert leftovers(tables) == []


def _without_root_privileges() -> None:
    # In a new user namespace, root keeps its uid but loses CAP_DAC_OVERRIDE over files of
    # the parent namespace: a folder's mode bits apply to it as to anyone.
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.unshare(CLONE_NEWUSER) != 0:
        raise OSError(ctypes.get_errno(), "unshare(CLONE_NEWUSER) refused")


@contextlib.contextmanager
def read_only(*folders: Path) -> Iterator[None]:
    for folder in folders:
        folder.chmod(0o555)
    try:
        yield
    finally:
        for folder in folders:
            folder.chmod(0o755)


def test_read_only_tables_folder_is_a_named_error_and_changes_nothing(
    tmp_path: Path, computed_tables: Path
) -> None:
    tables = copy_tables(tmp_path / "tables")
    make_stale(tables)
    before = snapshot(tables / "regenerated")
    preexec = _without_root_privileges if os.geteuid() == 0 else None
    with read_only(tables, tables / "regenerated"):
        try:
            out = run_cli(tables, computed_tables, "check", "--update", preexec=preexec)
        except subprocess.SubprocessError as exc:  # no user namespaces here: root ignores modes
            pytest.skip(f"cannot drop root's file permissions: {exc}")
    assert_one_line_error(out, tables)
    assert "Permission denied" in out.stderr
    assert snapshot(tables / "regenerated") == before
    assert leftovers(tables) == []


# ---------------------------------------------------------------------------------------------
# Faults in the data


@pytest.fixture
def tables_copy(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A copy of ``tables/`` that the in-process CLI reads (``$PENDCLI_TABLES``)."""
    tables = copy_tables(tmp_path / "tables")
    monkeypatch.setenv("PENDCLI_TABLES", str(tables))
    clear_table_cache()
    yield tables
    clear_table_cache()


def claim_ids(key: str) -> list[str]:
    text = (REPO_TABLES / "published" / f"{key}.toml").read_text(encoding="utf-8")
    return re.findall(r'^id = "([^"]+)"', text, re.M)


def rename_claim(tables: Path, key: str, claim_id: str) -> Path:
    path = tables / "published" / f"{key}.toml"
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace(f'id = "{claim_id}"', f'id = "{claim_id}_renamed"'), "utf-8")
    return path


@pytest.mark.parametrize("key", PAPERS)
def test_every_renamed_claim_id_is_a_named_error(tables_copy: Path, key: str) -> None:
    """Every renamed claim id is one named error (24 of 69 once crashed: KeyError, exit 3)."""
    pristine = (tables_copy / "published" / f"{key}.toml").read_text(encoding="utf-8")
    for claim_id in claim_ids(key):
        path = rename_claim(tables_copy, key, claim_id)
        clear_table_cache()
        with pytest.raises(PendcliError) as err:
            claim_rows(key)
        message = str(err.value)
        assert str(path) in message and repr(claim_id) in message and "renamed" in message
        path.write_text(pristine, "utf-8")


@pytest.mark.parametrize(
    ("claim_id", "command"),
    [
        # the fast suite keeps the first and the third (conftest.REPRESENTATIVES): two
        # commands; `check` of Charbonnier (0.6 s: the other papers' claims computed first)
        # runs in the slow suite with the rest
        ("tisserand.resal.rate", ["check"]),
        ("charbonnier.I_pi.n2", ["check"]),
        ("lecornu.k4.swing180", ["reproduce"]),
        ("lecornu.speed.1", ["lecornu", "g-sensitivity"]),
    ],
)
def test_renamed_id_through_the_cli_is_one_line_exit_2(
    tables_copy: Path, claim_id: str, command: list[str]
) -> None:
    path = rename_claim(tables_copy, claim_id.split(".")[0], claim_id)
    code, _, err = invoke(*command)
    assert_clean_error(code, err)
    assert str(path) in err and repr(claim_id) in err


def _set_cells(path: Path, column: str, values: dict[int, str]) -> None:
    """Edit a committed CSV: row index (0 = first data row) -> new text of ``column``."""
    rows = list(csv.reader(io.StringIO(path.read_text(encoding="utf-8"), newline="")))
    at = rows[0].index(column)
    for index, text in values.items():
        rows[index + 1][at] = text
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(rows)
    path.write_text(buf.getvalue(), "utf-8")


def test_non_finite_committed_values_fail_the_check(
    tables_copy: Path, computed_tables: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Damaged committed cells against the computation (served: the cells are the fault)."""
    from pendcli.run import reproduce

    monkeypatch.setattr(reproduce, "reproduce_all", served(computed_tables))
    tokens = {0: "inf", 1: "-1e400", 2: "nan", 3: "1e400"}
    _set_cells(tables_copy / "regenerated" / "lecornu-claims.csv", "recomputed", tokens)
    code, out, _ = invoke("check")
    assert code == 1
    assert out.count("non-finite") == len(tokens)
    for token in tokens.values():
        assert f" {token} " in out


@pytest.mark.parametrize(
    ("damage", "message"),
    [
        (lambda text: "", "empty table; expected the header line"),
        (lambda text: text[: len(text) // 2], "cut short"),  # cut mid-row
        (lambda text: text[: text.index("\n", 500)], "cut short"),  # cut at a row's end
        (lambda text: text.replace(",agrees,", ",", 1), f"fields; expected {len(CLAIM_COLUMNS)}"),
        (lambda text: text.replace("recomputed", "recomputd"), "line 1: header"),
    ],
)
def test_a_cut_or_damaged_committed_table_is_a_named_error(
    tables_copy: Path, damage: Callable[[str], str], message: str
) -> None:
    path = tables_copy / "regenerated" / "lecornu-claims.csv"
    path.write_text(damage(path.read_text(encoding="utf-8")), "utf-8")
    code, _, err = invoke("check")
    assert_clean_error(code, err)
    assert str(path) in err and message in err


@pytest.mark.parametrize(
    ("family", "command"),
    [
        ("integral_x", ["charbonnier", "integral", "5", "--x", "1", "--tol", "1e-10"]),
        ("bessel_zeros", ["lecornu", "zeros", "--tol", "1e-10"]),
    ],
)
def test_a_bad_tradeoff_table_is_a_named_error_for_tol(
    tables_copy: Path, family: str, command: list[str]
) -> None:
    path = tables_copy / "tradeoff" / f"{family}.csv"
    _set_cells(path, "seconds", {1: "inf"})
    code, _, err = invoke(*command)
    assert_clean_error(code, err)
    assert f"{path}: line 3: seconds = 'inf'" in err
