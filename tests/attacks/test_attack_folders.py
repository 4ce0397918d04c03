"""Output folders never cost a user a file.

``reproduce --out`` replaces a folder as a whole, so it must only ever replace one pendcli
made (its manifest lists every file in it), touch nothing beside it but its own temporary
names, keep to one writer at a time, write through a symlink, follow the umask, and accept
every legal name. The library calls run in this process (cheap), and so does a refusal before
the run; the other CLI runs are subprocesses of the installed ``pendcli``, with
``PENDCLI_JOBS=1`` and one small paper.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from helpers.cli import assert_clean_error, child_env, invoke

from pendcli.base.errors import PendcliError
from pendcli.base.files import atomic_write, lock_file, locked, remove_stale
from pendcli.base.owned_folders import MANIFEST, manifest_text, replace_owned_folder

PENDCLI = Path(sys.executable).with_name("pendcli")
CHEAP = ("reproduce", "-p", "tisserand", "--no-formulas", "--no-equations", "--no-stability")
CHEAP += ("-q", "-f", "json")
DEAD_PID = 2**22 + 7  # above the default pid_max (4194304): never a live process


def run_cli(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(PENDCLI), *args],
        cwd=cwd,
        env=child_env(),
        capture_output=True,
        text=True,
        timeout=600,
    )


def tree(folder: Path) -> dict[str, bytes]:
    return {
        p.relative_to(folder).as_posix(): p.read_bytes()
        for p in sorted(folder.rglob("*"))
        if p.is_file()
    }


def assert_one_line(out: subprocess.CompletedProcess[str], *words: str) -> None:
    lines = [line for line in out.stderr.splitlines() if line.strip()]
    assert out.returncode == 2, out.stderr
    assert len(lines) == 1 and lines[0].startswith("pendcli: error: "), out.stderr
    assert all(w in lines[0] for w in words), lines[0]


def assert_complete(folder: Path) -> None:
    """A whole pendcli folder: its manifest lists exactly the files in it."""
    listed = (folder / MANIFEST).read_text(encoding="utf-8").splitlines()
    files = sorted(n for n in tree(folder) if n != MANIFEST)
    assert sorted(n for n in listed if not n.startswith("#")) == files
    assert {"report.md", "claims.json", "report.html"} <= set(files)


def fill_with(names: dict[str, str]):  # type: ignore[no-untyped-def]
    def fill(tmp: Path) -> None:
        for name, text in names.items():
            (tmp / name).parent.mkdir(parents=True, exist_ok=True)
            (tmp / name).write_text(text, encoding="utf-8")

    return fill


# --- the CLI: hidden folders beside the target, "*", a folder pendcli did not make ----------


def test_a_folder_pendcli_did_not_make_is_refused_before_the_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """In this process (a refusal before the run needs no real one): --out relative to the
    working folder, as typed."""
    thesis = tmp_path / "thesis"
    (thesis / "chapters").mkdir(parents=True)
    for name, text in {"report.md": "# mine", "results.csv": "a,b\n"}.items():
        (thesis / name).write_text(text, encoding="utf-8")
    (thesis / "chapters" / "main.tex").write_text("\\chapter{}", encoding="utf-8")
    before = tree(thesis)
    monkeypatch.chdir(tmp_path)
    code, out, err = invoke(*CHEAP, "--out", "thesis")
    assert_clean_error(code, err)
    assert all(w in err for w in ("'thesis'", "did not make", "new or empty folder")), err
    assert out == ""  # refused before the run
    assert tree(thesis) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["thesis"]


def test_a_file_added_to_a_pendcli_folder_is_never_deleted(tmp_path: Path) -> None:
    out_dir = tmp_path / "out"
    replace_owned_folder(out_dir, fill_with({"report.md": "old"}), "--out")
    (out_dir / "notes.txt").write_text("mine", encoding="utf-8")
    with pytest.raises(PendcliError, match=r"holds 1 file\(s\) pendcli did not write \('notes"):
        replace_owned_folder(out_dir, fill_with({"report.md": "new"}), "--out")
    assert tree(out_dir)["notes.txt"] == b"mine" and tree(out_dir)["report.md"] == b"old"
    (out_dir / "notes.txt").unlink()
    replace_owned_folder(out_dir, fill_with({"report.md": "new"}), "--out")
    assert tree(out_dir) == {MANIFEST: manifest_text(["report.md"]).encode(), "report.md": b"new"}


# --- stale removal: only pendcli's own names, glob-escaped, of dead writers -------------------


@pytest.mark.parametrize("name", ["R9", "*", "a[b]", "?x"])
def test_remove_stale_touches_only_its_own_dead_temporaries(tmp_path: Path, name: str) -> None:
    others = [f".{name}.keep-me", f".{name}.new-{DEAD_PID}", f".{name}.new-1-abcdefgh", ".x.y-z"]
    others += [f".{name}x.new-{DEAD_PID}-abcdefgh", f".{name}.new-{DEAD_PID}-abcdefgh-more"]
    ours = [f".{name}.new-{DEAD_PID}-abcdefgh", f".{name}.old-{DEAD_PID}-a1b2_c3d"]
    for entry in (*others, *ours):
        (tmp_path / entry).mkdir()
        (tmp_path / entry / "f").write_text("x", encoding="utf-8")
    remove_stale(tmp_path, name)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(others)


def test_atomic_write_cleans_its_dead_temporaries_and_keeps_a_live_ones(tmp_path: Path) -> None:
    target = tmp_path / "p.png"
    dead = tmp_path / f".p.png.{DEAD_PID}-abcdefgh.tmp"
    live = tmp_path / ".p.png.1-abcdefgh.tmp"
    other = tmp_path / ".p.png.notes.tmp"
    for path in (dead, live, other):
        path.write_text("x", encoding="utf-8")
    atomic_write(target, b"png")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([other.name, live.name, "p.png"])


def test_kill_9_during_atomic_write_leaves_a_leftover_the_next_write_removes(
    tmp_path: Path,
) -> None:
    target = tmp_path / "p.png"
    writer = textwrap.dedent(
        f"""
        from pendcli.base.files import atomic_write
        print("go", flush=True)
        while True:
            atomic_write({str(target)!r}, b"x" * 4_000_000)
        """
    )
    proc = subprocess.Popen([sys.executable, "-c", writer], stdout=subprocess.PIPE, text=True)
    assert proc.stdout is not None and proc.stdout.readline() == "go\n"
    for _ in range(200_000):  # until a temporary exists (bounded by count)
        if any(p.suffix == ".tmp" for p in tmp_path.iterdir()):
            break
    proc.kill()
    proc.wait()
    atomic_write(target, b"new")
    assert [p.name for p in tmp_path.iterdir()] == ["p.png"] and target.read_bytes() == b"new"


# --- one writer at a time ---------------------------------------------------------------------


def test_a_second_writer_is_refused_in_one_line_while_the_first_holds_the_lock(
    tmp_path: Path,
) -> None:
    out_dir = tmp_path / "RR"
    replace_owned_folder(out_dir, fill_with({"report.md": "old"}), "--out")
    before = tree(out_dir)
    with locked(lock_file(out_dir)):  # another run, writing
        out = run_cli(tmp_path, *CHEAP, "--out", "RR")
        with pytest.raises(PendcliError, match="being written by another pendcli run"):
            replace_owned_folder(out_dir, fill_with({"report.md": "new"}), "--out")
    assert_one_line(out, "'RR'", "being written by another pendcli run")
    assert tree(out_dir) == before


@pytest.mark.slow
def test_two_concurrent_runs_on_out_star_keep_every_folder_beside_it_and_leave_a_whole_report(
    tmp_path: Path,
) -> None:
    """Two runs at once on ``--out '*'``: each ends 0 or refused in one line, the folder is a
    whole report; the hidden folders beside it (matched by an unescaped glob ``.*.*-*``) are
    all kept, pendcli's own names of a live writer too; a dead writer's is removed. The
    figures are plotted but not rendered to pixels (tests/helpers/undrawn_figures.py): the
    folders are what is read."""
    from helpers.undrawn_figures import UNDRAWN_CLI

    keep = [".R9.keep-me", ".my.notes-2024", ".config.bak-1", ".*.new-1-abcdefgh"]
    for name in keep:  # the last: pendcli's own name, but pid 1 is alive
        (tmp_path / name).mkdir()
        (tmp_path / name / "notes.txt").write_text("mine", encoding="utf-8")
    dead = tmp_path / f".*.new-{DEAD_PID}-abcdefgh"
    dead.mkdir()
    env = child_env()
    runs = [
        subprocess.Popen(
            [*UNDRAWN_CLI, *CHEAP, "--out", "*"],
            cwd=tmp_path,
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
        )
        for _ in range(2)
    ]
    results = [(p.wait(), p.stderr.read() if p.stderr else "") for p in runs]
    for code, err in results:
        assert code in (0, 2) and "Traceback" not in err, err
        if code == 2:
            assert "being written by another pendcli run" in err, err
    assert 0 in [code for code, _ in results]
    assert_complete(tmp_path / "*")
    for name in keep:
        assert (tmp_path / name / "notes.txt").read_text(encoding="utf-8") == "mine", name
    assert not dead.exists()  # pendcli's, from a run that died: cleaned
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([*keep, "*"])  # no lock left


# --- symlinks, names, modes ---------------------------------------------------------------------


def test_a_symlinked_target_is_written_through_and_the_link_kept(tmp_path: Path) -> None:
    real = tmp_path / "real"
    replace_owned_folder(real, fill_with({"report.md": "old"}), "--out")
    link = tmp_path / "link"
    link.symlink_to("real")
    replace_owned_folder(link, fill_with({"report.md": "new"}), "--out")
    assert link.is_symlink() and os.readlink(link) == "real"
    assert (real / "report.md").read_text(encoding="utf-8") == "new"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link", "real"]
    dangling = tmp_path / "dangling"
    dangling.symlink_to("nowhere")
    with pytest.raises(PendcliError, match="is a link to nothing"):
        replace_owned_folder(dangling, fill_with({"a": "b"}), "--out")


def test_a_255_byte_target_name_has_temporary_names_that_fit(tmp_path: Path) -> None:
    name = "é" * 127 + "n"  # 255 bytes in UTF-8
    assert len(name.encode()) == 255
    replace_owned_folder(tmp_path / name, fill_with({"report.md": "one"}), "--out")
    replace_owned_folder(tmp_path / name, fill_with({"report.md": "two"}), "--out")
    atomic_write(tmp_path / name / "report.md", "three")
    assert [p.name for p in tmp_path.iterdir()] == [name]
    assert (tmp_path / name / "report.md").read_text(encoding="utf-8") == "three"


def test_modes_follow_the_umask_and_a_replaced_file_keeps_its_own(tmp_path: Path) -> None:
    old = os.umask(0o077)
    try:
        replace_owned_folder(tmp_path / "out", fill_with({"a/b.txt": "x"}), "--out")
        atomic_write(tmp_path / "plot.png", b"png")
        (tmp_path / "kept.png").write_bytes(b"old")
        (tmp_path / "kept.png").chmod(0o640)
        atomic_write(tmp_path / "kept.png", b"new")
    finally:
        os.umask(old)

    def mode(path: Path) -> int:
        return stat.S_IMODE(path.stat().st_mode)

    assert mode(tmp_path / "out") == 0o700 and mode(tmp_path / "out" / "a") == 0o700
    assert mode(tmp_path / "out" / "a" / "b.txt") == 0o600
    assert mode(tmp_path / "out" / MANIFEST) == 0o600
    assert mode(tmp_path / "plot.png") == 0o600
    assert mode(tmp_path / "kept.png") == 0o640
