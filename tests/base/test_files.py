"""Atomic files and folders: a crash leaves the old content or the new, never a mix."""

from __future__ import annotations

import os
import resource
import signal
import subprocess
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from helpers.forked import in_a_child

from pendcli.base.errors import PendcliError
from pendcli.base.files import atomic_write, locked, remove_stale, replace_directory


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def test_atomic_write_replaces_whole_file(tmp_path: Path) -> None:
    target = tmp_path / "t.csv"
    target.write_text("old\n")
    atomic_write(target, "new\n")
    assert target.read_text() == "new\n"
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]  # no temporary left behind


def test_atomic_write_names_path_and_cause(tmp_path: Path) -> None:
    with pytest.raises(PendcliError, match=r"cannot write .*missing/x\.csv: No such file"):
        atomic_write(tmp_path / "missing" / "x.csv", "a")


def test_replace_directory_drops_stale_files(tmp_path: Path) -> None:
    target = tmp_path / "tables"
    target.mkdir()
    (target / "a.csv").write_text("old a")
    (target / "stale.csv").write_text("stale")

    def fill(tmp: Path) -> None:
        (tmp / "a.csv").write_text("new a")
        (tmp / "b.csv").write_text("new b")

    replace_directory(target, fill)
    assert _snapshot(target) == {"a.csv": b"new a", "b.csv": b"new b"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tables"]


def test_replace_directory_keeps_old_when_fill_fails(tmp_path: Path) -> None:
    target = tmp_path / "tables"
    target.mkdir()
    (target / "a.csv").write_text("old a")

    def fill(tmp: Path) -> None:
        (tmp / "a.csv").write_text("half")
        raise PendcliError("boom")

    with pytest.raises(PendcliError, match="boom"):
        replace_directory(target, fill)
    assert _snapshot(target) == {"a.csv": b"old a"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tables"]


def _fill_slowly(tmp: Path) -> None:
    for i in range(6):
        with open(tmp / f"t{i}.csv", "w") as fh:
            for _ in range(200):
                fh.write("new," * 50 + "\n")
                fh.flush()
            time.sleep(0.002)


def _replacing_until_killed(target: Path) -> int:
    """A child forked from this process that replaces ``target`` again and again until it is
    killed (a real process, without a fresh interpreter's start-up); its pid."""
    child = os.fork()
    if child == 0:
        try:
            while True:
                replace_directory(target, _fill_slowly)
        finally:
            os._exit(1)
    return child


@pytest.mark.parametrize("delay", [0.01, 0.03, 0.05, 0.08, 0.13, 0.21])
def test_kill_during_replace_leaves_old_or_new(tmp_path: Path, delay: float) -> None:
    target = tmp_path / "tables"
    target.mkdir()
    for i in range(6):
        (target / f"t{i}.csv").write_text("old\n")
    old = _snapshot(target)
    new = {f"t{i}.csv": ("new," * 50 + "\n").encode() * 200 for i in range(6)}
    child = _replacing_until_killed(target)
    time.sleep(delay)
    os.kill(child, signal.SIGKILL)
    os.waitpid(child, 0)
    assert _snapshot(target) in (old, new)
    remove_stale(tmp_path, "tables")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tables"]


def _limited_fill(tmp: Path) -> None:
    (tmp / "big.csv").write_bytes(b"x" * 20_000)


def test_file_size_limit_leaves_old_content(tmp_path: Path) -> None:
    target = tmp_path / "tables"
    target.mkdir()
    (target / "a.csv").write_text("old")

    def limited() -> str:
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, resource.RLIM_INFINITY))
        try:
            replace_directory(target, _limited_fill)
        except PendcliError as exc:
            return str(exc)
        return "no error"

    said = in_a_child(limited)  # a real process under the limit (the test's is not)
    assert "File too large" in said and str(target) in said, said
    assert _snapshot(target) == {"a.csv": b"old"}


def _holding(lock: Path, until: Callable[[], object]) -> tuple[int, int]:
    """A child forked from this process that takes ``lock`` whole, says so (one byte on the
    pipe whose reading end is returned), and keeps it until ``until()`` returns: its pid
    and that reading end."""
    read, write = os.pipe()
    child = os.fork()
    if child == 0:
        try:
            os.close(read)
            with locked(lock):
                os.write(write, b"h")
                until()
        finally:
            os._exit(0)
    os.close(write)
    assert os.read(read, 1) == b"h"
    return child, read


def test_exclusive_lock_blocks_a_second_writer(tmp_path: Path) -> None:
    lock = tmp_path / ".lock"
    holder, said = _holding(lock, lambda: time.sleep(0.6))
    start = time.perf_counter()
    with locked(lock, shared=True):
        waited = time.perf_counter() - start
    os.waitpid(holder, 0)
    os.close(said)
    assert waited > 0.2  # the reader waited for the writer to finish


def _unshare_user_namespace() -> None:
    # Root in a new user namespace loses CAP_DAC_OVERRIDE over the files outside: modes apply.
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    if libc.unshare(0x10000000) != 0:  # CLONE_NEWUSER
        raise OSError(ctypes.get_errno(), "unshare(CLONE_NEWUSER) refused")


def test_read_only_folder_is_a_named_error(tmp_path: Path) -> None:
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o555)

    def write() -> str:  # in a child: the namespace is left with it
        if os.geteuid() == 0:
            try:
                _unshare_user_namespace()
            except OSError as exc:
                return f"no namespace: {exc}"
        try:
            atomic_write(folder / "x.csv", "a")
        except PendcliError as exc:
            return str(exc)
        return "written"

    try:
        said = in_a_child(write)
    finally:
        folder.chmod(0o755)
    if said.startswith("no namespace: "):
        pytest.skip(f"root ignores folder modes here and cannot drop that: {said}")
    assert "Permission denied" in said and str(folder / "x.csv") in said, said
    assert list(folder.iterdir()) == []


def test_check_update_swaps_the_whole_set(tmp_path: Path, computed_tables: Path) -> None:
    """A retired table removed, a cut one replaced, no temporary folder left: the real
    command in a process, its computation served (tests/helpers/regenerated.py)."""
    import shutil

    from helpers.regenerated import SERVED_CLI

    root = Path(__file__).resolve().parents[2] / "tables"
    copy = tmp_path / "tables"
    shutil.copytree(root, copy)
    (copy / "regenerated" / "retired-claims.csv").write_text("id\n")
    (copy / "regenerated" / "lecornu-claims.csv").write_text("id\ncut mid-r")  # a cut table
    env = {**os.environ, "PENDCLI_TABLES": str(copy)}
    cmd = [*SERVED_CLI, str(computed_tables), "check", "--update"]
    out = subprocess.run(cmd, capture_output=True, text=True, env=env)
    assert out.returncode == 0, out.stderr
    assert "removed 1 table(s) no longer produced: retired-claims.csv" in out.stdout
    names = sorted(p.name for p in (copy / "regenerated").iterdir())
    assert names == sorted(p.name for p in (root / "regenerated").iterdir())
    assert (copy / "regenerated" / "lecornu-claims.csv").read_text().startswith("id,published")
    assert not [p for p in copy.iterdir() if p.name.startswith(".regenerated.") and p.is_dir()]


def test_an_exclusive_holder_removes_its_lock_file_and_a_busy_lock_is_refused(
    tmp_path: Path,
) -> None:
    lock = tmp_path / ".out.lock"
    with locked(lock):
        assert lock.exists()
        with (
            pytest.raises(PendcliError, match=r"^busy: another run$"),
            locked(lock, busy="busy: another run"),
        ):
            pass
    assert list(tmp_path.iterdir()) == []


def test_a_waiter_on_a_removed_lock_file_locks_the_current_one(tmp_path: Path) -> None:
    """A writer that waited on a lock file its holder then removed must not believe it holds
    the lock: it locks the file now at that path (else two writers would run at once)."""
    lock = tmp_path / ".out.lock"
    release, released = os.pipe()
    holder, said = _holding(lock, lambda: os.read(release, 1))
    stale_fd = os.open(lock, os.O_RDWR)  # what a waiter opened before the holder finished
    os.write(released, b"\n")
    os.waitpid(holder, 0)
    for fd in (release, released, said):
        os.close(fd)
    assert not lock.exists()
    with locked(lock):  # locks a new file at the path, not the removed one
        assert lock.exists() and os.fstat(stale_fd).st_ino != lock.stat().st_ino
    os.close(stale_fd)


def test_write_set_failing_before_its_renames_changes_nothing(tmp_path: Path) -> None:
    from pendcli.base.files import write_set

    (tmp_path / "a.csv").write_text("old a")
    (tmp_path / "b.csv").write_text("old b")
    changes: dict[Path, str | bytes | None] = {
        tmp_path / "a.csv": "new a",
        tmp_path / "missing" / "c.csv": "new c",  # its folder does not exist
        tmp_path / "b.csv": None,
    }
    with pytest.raises(PendcliError, match=r"cannot write .*missing/c\.csv"):
        write_set(changes)
    assert _snapshot(tmp_path) == {"a.csv": b"old a", "b.csv": b"old b"}
    del changes[tmp_path / "missing" / "c.csv"]
    write_set(changes)
    assert _snapshot(tmp_path) == {"a.csv": b"new a"}


def test_write_set_refuses_a_file_changed_since_it_was_read(tmp_path: Path) -> None:
    from pendcli.base.files import content_digest, file_digest, write_set

    readme, table = tmp_path / "README.md", tmp_path / "t.csv"
    readme.write_text("old readme\n")
    read = {readme: content_digest(readme.read_text())}
    with readme.open("a") as fh:  # someone's edit, after the read, before the write
        fh.write("my edit\n")
    changes: dict[Path, str | bytes | None] = {readme: "regenerated\n", table: "new table\n"}
    with pytest.raises(PendcliError, match=r"'.*README\.md' changed since this run read it"):
        write_set(changes, read)
    assert _snapshot(tmp_path) == {"README.md": b"old readme\nmy edit\n"}  # nothing written
    read[readme] = file_digest(readme)
    write_set(changes, read)  # read again: written
    assert _snapshot(tmp_path) == {"README.md": b"regenerated\n", "t.csv": b"new table\n"}


def test_write_set_refuses_a_file_created_or_removed_since_it_was_read(tmp_path: Path) -> None:
    from pendcli.base.files import file_digest, write_set

    absent, present = tmp_path / "new.csv", tmp_path / "old.csv"
    present.write_text("x\n")
    read = {absent: file_digest(absent), present: file_digest(present)}
    assert read[absent] is None
    absent.write_text("made meanwhile\n")
    with pytest.raises(PendcliError, match=r"new\.csv' was created since"):
        write_set({absent: "mine\n"}, read)
    absent.unlink()
    present.unlink()
    with pytest.raises(PendcliError, match=r"old\.csv' was removed since"):
        write_set({absent: "mine\n"}, read)
    assert not absent.exists()


def _docs_set(tmp_path: Path) -> Path:
    """A README and the docs pages holding the generated sections' markers (docs/findings.md,
    verdicts.md, schema.md, ENGINE.md: tools.docs.SECTION_FILES), and no tables. Returns
    docs/verdicts.md, the page of the ledger's section."""
    (tmp_path / "README.md").write_text("# readme\n")

    def marks(*names: str) -> str:
        return "".join(f"<!-- {n}:start -->\nold {n}\n<!-- {n}:end -->\n" for n in names)

    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "findings.md").write_text(marks("sample", "causes", "findings"))
    (tmp_path / "docs" / "verdicts.md").write_text(f"# verdicts\n{marks('ledger')}")
    (tmp_path / "docs" / "schema.md").write_text(marks("schema"))
    (tmp_path / "docs" / "ENGINE.md").write_text(marks("kinds"))
    return tmp_path / "docs" / "verdicts.md"


@pytest.mark.parametrize("tables", [True, False], ids=["regen", "sections"])
def test_regen_refuses_to_write_over_an_edit_made_while_it_computed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, tables: bool
) -> None:
    """`make regen` reads the README, computes for most of a minute, then writes: an edit made
    in between (here by the compute step itself) is refused, nothing written, the edit kept."""
    from pendcli.run import regression, reproduce
    from tools import docs

    page = _docs_set(tmp_path)
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path / "tables"))
    monkeypatch.setattr(
        reproduce, "reproduce_all", lambda *a, **k: reproduce.ReproduceResult(papers=())
    )
    monkeypatch.setattr(docs, "sample_section", lambda result=None: "new sample")
    monkeypatch.setattr(regression, "regenerated_tables", lambda result: {"x-claims.csv": "id\n"})
    monkeypatch.setitem(docs.SECTIONS, "schema", lambda: "new schema")
    monkeypatch.setitem(docs.SECTIONS, "kinds", lambda: "new kinds")
    monkeypatch.setitem(docs.SECTIONS, "findings", lambda: "new findings")

    def ledger_while_someone_edits() -> str:
        with page.open("a") as fh:
            fh.write("my edit\n")
        return "new ledger"

    monkeypatch.setitem(docs.SECTIONS, "ledger", ledger_while_someone_edits)
    before = page.read_text()
    argv = ["--readme", str(tmp_path / "README.md"), *(["--tables"] if tables else [])]
    with pytest.raises(PendcliError, match=r"verdicts\.md' changed since this run read it"):
        docs.main(argv)
    assert page.read_text() == before + "my edit\n"
    assert "old" in (tmp_path / "docs" / "schema.md").read_text()
    assert not list((tmp_path / "tables").rglob("*.csv"))
    monkeypatch.setitem(docs.SECTIONS, "ledger", lambda: "new ledger")
    assert docs.main(argv) == 0  # nothing edited meanwhile: written, the edit kept
    assert "new ledger" in page.read_text() and "my edit" in page.read_text()
    assert (tmp_path / "tables" / "regenerated" / "x-claims.csv").exists() == tables


def test_bench_refuses_to_write_over_an_edit_made_after_it_read(tmp_path: Path) -> None:
    from tools import bench

    page, table = tmp_path / "benchmarks.md", tmp_path / "family.csv"
    page.write_text(f"# b\n{bench.START}\nold\n{bench.END}\n")
    table.write_text("old table\n")

    def splice_while_someone_edits(old: str) -> str | None:
        with page.open("a") as fh:
            fh.write("my edit\n")
        return bench.spliced(old, "new figures")

    files: dict[Path, str | bytes | None] = {table: "new table\n"}
    with pytest.raises(PendcliError, match=r"benchmarks\.md' changed since this run read it"):
        bench.write_results(files, [(page, splice_while_someone_edits), (None, str)])
    assert page.read_text().endswith("old\n<!-- bench:end -->\nmy edit\n")
    assert table.read_text() == "old table\n"
    bench.write_results({table: "new table\n"}, [(page, lambda old: bench.spliced(old, "new"))])
    assert "\nnew\n" in page.read_text() and page.read_text().endswith("my edit\n")
    assert table.read_text() == "new table\n"
