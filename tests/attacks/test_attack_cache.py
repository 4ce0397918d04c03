"""The result cache trusts nothing it reads and touches nothing it did not write.

Its folder is used only when it is this user's, writable by no one else and pendcli's (its
CACHEDIR.TAG, or nothing but pendcli's names); pruning and ``pendcli cache clear`` remove only
``pendcli-<sha256>.json`` entries and pendcli's temporaries whose writer is dead. An entry is
read only as a regular file (never a FIFO, never through a link, at most MAX_ENTRY_BYTES), and
only when its digest, its key and every field's type check out: anything else is computed
again. Hashing the tables folder reads regular files in chunks and refuses, in one line, a
FIFO, a device, a file above MAX_HASHED_BYTES or a link out of the folder.

The runs that could hang are real processes of the CLI (a timeout only guards the test run);
the rest run in this process, on the cheapest commands (Tisserand's claims).
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import stat
import subprocess
import sys
import tracemalloc
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from helpers.cli import child_env, invoke

from pendcli.base import cache as cache_module
from pendcli.base.cache import MARKER, ResultCache, cached_json
from pendcli.base.cache_key import MAX_HASHED_BYTES, folders_digest
from pendcli.base.errors import PendcliError
from pendcli.data.tables import tables_dir

PENDCLI = (sys.executable, "-m", "pendcli")
HANG_GUARD = 300  # seconds: only so that a hang fails the test run instead of stopping it
# Charbonnier's claims: the cheapest to compute (0.2 s of CPU for a whole fresh process, where
# Tisserand's take 1.2 s), all agreeing, in an entry of the same kind and shape as any paper's
CLAIMS = ("reproduce", "-p", "charbonnier", "--no-formulas", "-f", "json")
DEAD_PID = 2**22 + 7  # above the default pid_max (4194304): never a live process
HEX = "0123456789abcdef" * 4
# status lines go through rich, which wraps them at $COLUMNS: wide enough for a line naming
# two temporary folders
WIDE = {"COLUMNS": "1000"}


def run_cli(*args: str, env: dict[str, str], **options: Any) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*PENDCLI, *args],
        env=child_env(**{**WIDE, **env}),
        capture_output=True,
        text=True,
        timeout=HANG_GUARD,
        **options,
    )


def status_lines(err: str) -> list[str]:
    return [line for line in err.splitlines() if line.strip()]


def entries_of(folder: Path, kind: str) -> list[Path]:
    """The entries of ``kind`` in ``folder``."""
    found = []
    for path in sorted(folder.glob("pendcli-*.json")):
        body = path.read_bytes().partition(b"\n")[2]
        if json.loads(body)["kind"] == kind:
            found.append(path)
    assert found, f"no {kind} entry in {folder}"
    return found


def forge(path: Path, edit: Callable[[Any], None], sign: bool) -> None:
    """Edit an entry's value in place; ``sign``: with its digest made right again (what only
    someone who can write the folder can do: the user, or anyone when it is shared)."""
    header, _, body = path.read_bytes().partition(b"\n")
    entry = json.loads(body)
    edit(entry["value"])
    body = json.dumps(entry).encode()
    if sign:
        header = header.rsplit(b" ", 1)[0] + b" " + hashlib.sha256(body).hexdigest().encode()
    path.write_bytes(header + b"\n" + body)


def first_claim_is_42(value: Any) -> None:
    value[0].update(recomputed=42.0, verdict="discrepant")


@pytest.fixture(scope="module", autouse=True)
def _installed_signature_read_once() -> Iterator[None]:
    """Each in-process run here keys the cache on the installed libraries' signature, which
    reads the metadata of every distribution they require (10-20 ms a run): read once for
    the module, the same text every run would read (no test here installs anything; the
    signature's own tests are tests/base/test_cache.py's). The folders are hashed each run."""
    signature = cache_module.installed_signature()
    with pytest.MonkeyPatch.context() as monkeypatch:
        monkeypatch.setattr(cache_module, "installed_signature", lambda: signature)
        yield


@pytest.fixture(scope="module")
def uncached() -> str:
    """The output of a run without the cache (``--no-cache``: no folder read or written),
    the same for every test of the module: computed once."""
    fresh = invoke(*CLAIMS, "--no-cache", env=WIDE)
    assert fresh.code == 0, fresh.err
    return fresh.out


@pytest.fixture
def cold(tmp_path: Path, uncached: str) -> tuple[dict[str, str], str]:
    """A cache filled by Charbonnier's claims (in this process), and the output of a run
    without the cache."""
    env = {"PENDCLI_CACHE": str(tmp_path / "cache"), **WIDE}
    first = invoke(*CLAIMS, env=env)
    assert (first.code, first.out) == (0, uncached), first.err
    return env, uncached


# -- the folder: only pendcli's names are ever removed ----------------------------------------


def test_cache_clear_removes_only_pendcli_entries_and_dead_temporaries(tmp_path: Path) -> None:
    folder = tmp_path / "cache"
    cache = ResultCache(folder, tables_dir())
    cache.put("claims", {"paper": "x"}, [1])
    user = {"settings.json": b'{"theme": "dark"}', "dataset.json": b"[1, 2, 3]", "notes": b"x"}
    for name, data in user.items():
        (folder / name).write_bytes(data)
    dead = folder / f".pendcli-{HEX}.json.{DEAD_PID}-abcdefgh.tmp"
    live = folder / f".pendcli-{HEX}.json.{os.getpid()}-abcdefgh.tmp"
    dead.write_bytes(b"half")
    live.write_bytes(b"being written")
    done = invoke("cache", "clear", env={"PENDCLI_CACHE": str(folder), **WIDE})
    assert done.code == 0, done.err
    assert "removed 1 entries" in done.err
    assert sorted(p.name for p in folder.iterdir()) == sorted([*user, MARKER, live.name])
    assert all((folder / name).read_bytes() == data for name, data in user.items())


def test_pruning_removes_only_pendcli_entries(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setattr(cache_module, "KEEP", 2)
    cache = ResultCache(tmp_path, tables_dir())
    cache.put("claims", {"paper": "first"}, [0])
    (tmp_path / "settings.json").write_text("{}", encoding="utf-8")
    os.utime(tmp_path / "settings.json", (0, 0))  # older than every entry
    for i in range(4):
        cache.put("claims", {"paper": f"p{i}"}, [i])
        os.utime(cache.entry_path("claims", {"paper": f"p{i}"}), (i + 1, i + 1))
    assert (tmp_path / "settings.json").read_text(encoding="utf-8") == "{}"
    assert len(list(tmp_path.glob("pendcli-*.json"))) == 2
    assert cache.get("claims", {"paper": "p3"}) == [3]


@pytest.mark.parametrize("name", ["settings.json", MARKER])
def test_a_folder_of_other_files_is_refused_not_adopted(tmp_path: Path, name: str) -> None:
    """A user's file, or another program's cache tag: the folder is not pendcli's."""
    (tmp_path / name).write_text("Signature: 8a477f597d28d172789f06886806bc55\n", "utf-8")
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    cache = ResultCache(tmp_path, tables_dir())
    cache.put("claims", {"paper": "x"}, [1])
    assert cache.get("claims", {"paper": "x"}) is None
    assert cache.problem is not None and f"{name!r}" in cache.problem
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before  # nothing written
    code, _, err = invoke("cache", "clear", env={"PENDCLI_CACHE": str(tmp_path), **WIDE})
    assert code == 2 and len(status_lines(err)) == 1 and name in err
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


def test_a_former_cache_is_adopted_and_its_entries_removed(tmp_path: Path) -> None:
    """A folder holding only the entries of the first layout (``<sha256>.json``) and their
    temporaries is pendcli's: it gets the marker; those entries, never read again, go."""
    (tmp_path / f"{HEX}.json").write_text("{}", encoding="utf-8")
    (tmp_path / f".{HEX}.json.{DEAD_PID}-abcdefgh.tmp").write_text("{", encoding="utf-8")
    cache = ResultCache(tmp_path, tables_dir())
    cache.put("claims", {"paper": "x"}, [1])
    assert cache.problem is None and cache.get("claims", {"paper": "x"}) == [1]
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == [MARKER, cache.entry_path("claims", {"paper": "x"}).name]


# -- entries: none is trusted ----------------------------------------------------------------


def test_an_edited_entry_is_recomputed_in_a_real_run(cold: tuple[dict[str, str], str]) -> None:
    env, fresh = cold
    (entry,) = entries_of(Path(env["PENDCLI_CACHE"]), "claims")
    forge(entry, first_claim_is_42, sign=False)
    warm = run_cli(*CLAIMS, "--fail-on", "discrepant", env=env)
    assert (warm.returncode, warm.stdout) == (0, fresh), warm.stderr
    assert b'"recomputed": 42.0' not in entry.read_bytes()  # rewritten


@pytest.mark.parametrize(
    ("field", "value"),
    [("recomputed", "abc"), ("verdict", "nonsense"), ("digits", None), ("cause_from", "ab")],
)
def test_a_value_of_the_wrong_type_is_a_miss_not_an_internal_error(
    cold: tuple[dict[str, str], str], field: str, value: object
) -> None:
    env, fresh = cold
    (entry,) = entries_of(Path(env["PENDCLI_CACHE"]), "claims")
    forge(entry, lambda rows: rows[0].update({field: value}), sign=True)
    markdown = invoke(*CLAIMS[:-1], "markdown", env=env)
    assert markdown.code == 0, markdown.err
    assert invoke(*CLAIMS, env=env).out == fresh


def first_row(entry: Path) -> dict[str, Any]:
    row: dict[str, Any] = json.loads(entry.read_bytes().partition(b"\n")[2])["value"][0]
    return row


@pytest.mark.parametrize("field", ["cause", "as_printed", "cause_from"])
def test_a_missing_or_unknown_field_is_a_miss(cold: tuple[dict[str, str], str], field: str) -> None:
    """A field left out (one with a default, which the row would take silently) or one no
    row has: the entry is computed again and rewritten whole."""
    env, fresh = cold
    (entry,) = entries_of(Path(env["PENDCLI_CACHE"]), "claims")
    forge(entry, lambda rows: rows[0].pop(field), sign=True)
    assert invoke(*CLAIMS, env=env).out == fresh
    assert field in first_row(entry)
    forge(entry, lambda rows: rows[0].update(extra=1), sign=True)
    assert invoke(*CLAIMS, env=env).out == fresh
    assert "extra" not in first_row(entry)


@pytest.mark.parametrize("mode", [0o1777, 0o777, 0o770])
def test_a_folder_others_can_write_is_refused_with_one_line(
    cold: tuple[dict[str, str], str], mode: int
) -> None:
    env, fresh = cold
    folder = Path(env["PENDCLI_CACHE"])
    (entry,) = entries_of(folder, "claims")
    forge(entry, first_claim_is_42, sign=True)  # planted by someone who could write there
    folder.chmod(mode)
    result = invoke(*CLAIMS, "--fail-on", "discrepant", env=env)
    assert (result.code, result.out) == (0, fresh), result.err
    (line,) = status_lines(result.err)
    assert line.startswith("result cache off:") and "writable by others" in line
    assert f"{mode:04o}" in line


@pytest.mark.skipif(os.geteuid() != 0, reason="giving a folder to another user needs root")
def test_a_folder_of_another_user_is_refused_with_one_line(
    cold: tuple[dict[str, str], str],
) -> None:
    env, fresh = cold
    folder = Path(env["PENDCLI_CACHE"])
    (entry,) = entries_of(folder, "claims")
    forge(entry, first_claim_is_42, sign=True)
    os.chown(folder, 65534, -1)
    result = invoke(*CLAIMS, "--fail-on", "discrepant", env=env)
    assert (result.code, result.out) == (0, fresh), result.err
    (line,) = status_lines(result.err)
    assert "owned by uid 65534" in line


def test_an_entry_of_another_user_is_a_miss(cold: tuple[dict[str, str], str]) -> None:
    if os.geteuid() != 0:
        pytest.skip("giving a file to another user needs root")
    env, fresh = cold
    (entry,) = entries_of(Path(env["PENDCLI_CACHE"]), "claims")
    forge(entry, first_claim_is_42, sign=True)
    os.chown(entry, 65534, -1)
    assert invoke(*CLAIMS, env=env).out == fresh


@pytest.mark.parametrize("kind", ["fifo", "dev-zero", "folder", "huge"])
def test_an_entry_that_is_not_a_small_regular_file_is_a_miss_in_a_real_run(
    cold: tuple[dict[str, str], str], kind: str
) -> None:
    """A FIFO hung the run, a link to /dev/zero grew its memory without bound (a limit on
    the address space makes that a failure, not a swapping machine)."""
    env, fresh = cold
    (entry,) = entries_of(Path(env["PENDCLI_CACHE"]), "claims")
    entry.unlink()
    if kind == "fifo":
        os.mkfifo(entry)
    elif kind == "dev-zero":
        entry.symlink_to("/dev/zero")
    elif kind == "folder":
        entry.mkdir()
    else:  # larger than the address space the run may use: read whole, it would fail
        with entry.open("wb") as file:  # sparse: no disk used
            file.truncate(2 * MEMORY_LIMIT)
    if kind == "folder":  # nothing about the process: the run in this one reads the same
        result = invoke(*CLAIMS, env=env)
        assert (result.code, result.out) == (0, fresh), result.err
    else:  # a hang or unbounded memory: a real process, under a limit
        warm = run_cli(*CLAIMS, env=env, preexec_fn=_limit_memory)
        assert (warm.returncode, warm.stdout) == (0, fresh), warm.stderr
    if kind != "folder":  # rewritten as a regular file
        assert stat.S_ISREG(entry.lstat().st_mode) and entry.stat().st_size < 10**6


MEMORY_LIMIT = 6 * 2**30  # address space of a run: several times what one uses


def _limit_memory() -> None:
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


# -- the report's entry ----------------------------------------------------------------------

BAD_NAMES = {
    "dot": {".": "aGk="},
    "empty": {"": "aGk="},
    "file-and-folder": {"zz": "aGk=", "zz/b": "aGk="},
    "too-long": {"x" * 300: "aGk="},
    "nul": {"a\0b": "aGk="},
    "absolute": {"/tmp/x": "aGk="},
    "parent": {"../x": "aGk="},
    "inner-parent": {"a/../../x": "aGk="},
    "double-slash": {"a//b": "aGk="},
    "hidden": {".x": "aGk="},
    "manifest": {"pendcli-manifest.txt": "aGk="},
    "not-base64": {"report.md": "not base64!"},
    "not-text": {"report.md": 3},
    "no-files": {},
}


@pytest.fixture(scope="module")
def code_and_tables_key() -> str:
    """The part of every key the code, the tables and the versions make (``ResultCache.base``,
    12 ms of hashing), the same for every cache of the module's committed tables: computed
    once, for the tests of what an entry holds (the key's own tests hash afresh)."""
    return ResultCache(None, tables_dir()).base


def report_cache(folder: Path, base: str) -> ResultCache:
    """A cache in ``folder`` of the committed tables, its key's base given."""
    cache = ResultCache(folder, tables_dir())
    cache.base = base  # what the cached property computes, computed once
    return cache


@pytest.mark.parametrize("files", list(BAD_NAMES.values()), ids=list(BAD_NAMES))
def test_a_damaged_report_entry_is_recomputed(
    tmp_path: Path, monkeypatch, files: dict[str, Any], code_and_tables_key: str
) -> None:
    """Each such entry (its digest made right) failed every run (exit 2 or 3) until the
    cache was cleared; now it is a miss: the report is written afresh and stored again."""
    from pendcli.output.report import write_report
    from pendcli.run.reproduce import ReproduceResult

    written = []

    def fill(_result: object, folder: Path, *_args: object) -> list[Path]:
        written.append(folder)
        (folder / "report.md").write_text("fresh", encoding="utf-8")
        return [Path("report.md")]

    monkeypatch.setattr("pendcli.output.report._fill", fill)
    cache = report_cache(tmp_path / "cache", code_and_tables_key)
    result = ReproduceResult(papers=("tisserand",))
    write_report(result, tmp_path / "first", cache=cache)
    (entry,) = entries_of(tmp_path / "cache", "report")
    forge(entry, lambda value: value.update(files=files), sign=True)
    write_report(result, tmp_path / "out", cache=report_cache(tmp_path / "cache", cache.base))
    assert len(written) == 2  # computed again
    assert (tmp_path / "out" / "report.md").read_text(encoding="utf-8") == "fresh"
    assert json.loads(entry.read_bytes().partition(b"\n")[2])["value"]["files"] != files


def test_an_edited_report_entry_is_not_copied_into_the_report(tmp_path: Path, monkeypatch) -> None:
    from pendcli.output.report import write_report
    from pendcli.run.reproduce import ReproduceResult

    def fill(_result: object, folder: Path, *_args: object) -> list[Path]:
        (folder / "report.md").write_text("fresh", encoding="utf-8")
        return [Path("report.md")]

    monkeypatch.setattr("pendcli.output.report._fill", fill)
    result = ReproduceResult(papers=("tisserand",))
    write_report(result, tmp_path / "first", cache=ResultCache(tmp_path / "c", tables_dir()))
    (entry,) = entries_of(tmp_path / "c", "report")
    script = "PHNjcmlwdD5hbGVydCgxKTwvc2NyaXB0Pg=="  # <script>alert(1)</script>
    forge(entry, lambda value: value["files"].update({"report.md": script}), sign=False)
    write_report(result, tmp_path / "out", cache=ResultCache(tmp_path / "c", tables_dir()))
    assert (tmp_path / "out" / "report.md").read_text(encoding="utf-8") == "fresh"


@pytest.mark.parametrize("inside", ["the-folder", "below-it"])
def test_a_cache_inside_the_out_folder_is_turned_off_before_the_run(
    tmp_path: Path, monkeypatch, inside: str
) -> None:
    def fill(_result: object, folder: Path, *_args: object) -> list[Path]:
        (folder / "report.md").write_text("fresh", encoding="utf-8")
        return [Path("report.md")]

    monkeypatch.setattr("pendcli.output.report._fill", fill)
    out = tmp_path / "out"
    cache = out if inside == "the-folder" else out / "cache"
    # Charbonnier: the cheapest claims to compute (the cache is off: they are computed)
    args = ("reproduce", "-p", "charbonnier", "--no-formulas", "--no-equations", "--no-stability")
    env = {"PENDCLI_CACHE": str(cache), **WIDE}
    result = invoke(*args, "-f", "json", "--out", str(out), env=env)
    assert result.code == 0, result.err
    lines = [line for line in status_lines(result.err) if "result cache" in line]
    assert len(lines) == 1 and "inside --out" in lines[0]
    assert sorted(p.name for p in out.iterdir()) == ["pendcli-manifest.txt", "report.md"]


# -- hashing the tables folder ---------------------------------------------------------------


def _tables_copy(tmp_path: Path) -> Path:
    copy = tmp_path / "tables"
    shutil.copytree(tables_dir(), copy, ignore=shutil.ignore_patterns(".*"))
    return copy


@pytest.mark.parametrize("command", [CLAIMS, ("equations", "-p", "tisserand", "-f", "json")])
def test_a_fifo_in_the_tables_is_one_line_not_a_hang(tmp_path: Path, command) -> None:
    tables = _tables_copy(tmp_path)
    os.mkfifo(tables / "papers" / "pipe")
    env = {"PENDCLI_CACHE": str(tmp_path / "cache"), "PENDCLI_TABLES": str(tables)}
    done = run_cli(*command, env=env)
    (line,) = status_lines(done.stderr)
    assert done.returncode == 2 and done.stdout == ""
    assert line.startswith("pendcli: error: ") and "pipe is a FIFO" in line


def test_a_file_above_the_bound_is_refused_without_reading_it(tmp_path: Path) -> None:
    (tmp_path / "huge.bin").touch()
    os.truncate(tmp_path / "huge.bin", MAX_HASHED_BYTES + 1)  # sparse: no disk used
    with pytest.raises(PendcliError, match=f"huge.bin is {MAX_HASHED_BYTES + 1} bytes"):
        folders_digest([("tables", tmp_path)])


def test_a_file_is_hashed_in_chunks(tmp_path: Path) -> None:
    """The old digest read each file whole: a 1.5 GB table cost 1.5 GB of memory. 8 MB, twice
    the peak allowed: read whole, it would be over; read in 1 MB chunks, far below."""
    size = 8 * 2**20
    (tmp_path / "big.bin").touch()
    os.truncate(tmp_path / "big.bin", size)
    tracemalloc.start()
    try:
        folders_digest([("tables", tmp_path)])
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 4 * 2**20
    expected = hashlib.sha256(f"tables:big.bin:{size}\0".encode() + bytes(size))
    assert folders_digest([("tables", tmp_path)]) == expected.hexdigest()


def test_links_are_followed_only_inside_the_folder(tmp_path: Path) -> None:
    root = tmp_path / "tables"
    root.mkdir()
    (root / "a.txt").write_text("one", encoding="utf-8")
    (root / "link.txt").symlink_to("a.txt")
    before = folders_digest([("tables", root)])
    (root / "a.txt").write_text("two", encoding="utf-8")  # seen through the link too
    assert folders_digest([("tables", root)]) != before
    (tmp_path / "secret").write_text("s", encoding="utf-8")
    for name, target in (("out.txt", tmp_path / "secret"), ("zero", Path("/dev/zero"))):
        (root / name).symlink_to(target)
        with pytest.raises(PendcliError, match="is a link out of"):
            folders_digest([("tables", root)])
        (root / name).unlink()
    (root / "folder").symlink_to(tmp_path, target_is_directory=True)
    with pytest.raises(PendcliError, match="is a link out of"):
        folders_digest([("tables", root)])


def test_a_stored_json_value_is_checked_before_it_is_used(tmp_path: Path) -> None:
    cache = ResultCache(tmp_path, tables_dir())
    cache.put("text-coverage", {"paper": "x"}, {"blocks": "many"})
    computed = []

    def compute() -> dict[str, int]:
        computed.append(1)
        return {"blocks": 3}

    def valid(value: Any) -> bool:
        return isinstance(value, dict) and type(value.get("blocks")) is int

    assert cached_json(cache, "text-coverage", {"paper": "x"}, compute, valid) == {"blocks": 3}
    assert cached_json(cache, "text-coverage", {"paper": "x"}, compute, valid) == {"blocks": 3}
    assert computed == [1]  # the bad value recomputed and rewritten, the good one read
