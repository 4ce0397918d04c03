"""Kills and signals at several moments of a write: the target is the old version or the new
one, byte for byte; Ctrl-C and TERM end with one line and status 130 or 143, no traceback, no
leftover and no orphan process.

Each moment is an event the test waits for (a temporary folder appears, a file in it), polled
a bounded number of times, never a clock. The CLI runs are subprocesses of the installed
``pendcli`` with ``PENDCLI_JOBS=1`` and one small paper.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import signal
import subprocess
import sys
import textwrap
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from helpers.cli import child_env

from pendcli.base.files import remove_stale
from pendcli.base.owned_folders import MANIFEST, manifest_text

PENDCLI = Path(sys.executable).with_name("pendcli")
CHEAP = ("reproduce", "-p", "tisserand", "--no-formulas", "--no-equations", "--no-stability")
CHEAP += ("-q", "-f", "json")
POLLS = 400_000  # at most this many looks for a moment (each ~1 ms asleep)


def tree(folder: Path) -> dict[str, bytes] | None:
    if not folder.is_dir():
        return None
    return {
        p.relative_to(folder).as_posix(): p.read_bytes()
        for p in sorted(folder.rglob("*"))
        if p.is_file()
    }


def wait_for(proc: subprocess.Popen[bytes], moment: Callable[[], bool]) -> bool:
    """Poll until ``moment()`` holds or the process ends (at most POLLS looks)."""
    for _ in range(POLLS):
        if proc.poll() is not None:
            return False
        if moment():
            return True
        time.sleep(0.001)
    return False


def session_processes(pid: int) -> list[str]:
    """Processes still alive in the child's session (its forked workers, were any left)."""
    out = subprocess.run(["ps", "-o", "pid=,stat=", "-s", str(pid)], capture_output=True)
    return [line for line in out.stdout.decode().splitlines() if "Z" not in line.split()[-1]]


def new_folders(parent: Path, name: str) -> list[Path]:
    return [p for p in parent.glob(f".{name}.new-*") if p.is_dir()]


def old_pendcli_folder(folder: Path) -> dict[str, bytes]:
    """An earlier pendcli report (tiny, with its manifest): what 'old' means here."""
    folder.mkdir()
    (folder / "report.md").write_text("# the old report\n", encoding="utf-8")
    (folder / MANIFEST).write_text(manifest_text(["report.md"]), encoding="utf-8")
    snapshot = tree(folder)
    assert snapshot is not None
    return snapshot


def assert_whole_new(folder: Path) -> None:
    files = tree(folder)
    assert files is not None
    listed = [n for n in files[MANIFEST].decode().splitlines() if not n.startswith("#")]
    assert sorted(listed) == sorted(n for n in files if n != MANIFEST)
    assert {"report.md", "claims.json", "report.html", "tables/tisserand-claims.csv"} <= set(files)


def in_new_folder(parent: Path, name: str, inside: str) -> Callable[[], bool]:
    return lambda: any((p / inside).exists() for p in new_folders(parent, name))


# (signal, moment): early in the fill, in the middle, near its end (the HTML pages)
MOMENTS = [
    (signal.SIGINT, "folder"),
    (signal.SIGTERM, "tables"),
    (signal.SIGKILL, "papers"),
]


@pytest.mark.slow
@pytest.mark.parametrize(("signum", "inside"), MOMENTS, ids=[f"{s.name}-{m}" for s, m in MOMENTS])
def test_a_signal_during_reproduce_out_leaves_the_old_report_or_the_new(
    tmp_path: Path, signum: signal.Signals, inside: str
) -> None:
    from helpers.undrawn_figures import UNDRAWN_CLI

    target = tmp_path / "o"
    old = old_pendcli_folder(target)
    # the pages come after the figures are drawn: for that moment they are plotted but not
    # rendered (tests/helpers/undrawn_figures.py), which leaves the time after it as it is;
    # at the earlier moments the figures are being drawn, and drawn in full
    cli = UNDRAWN_CLI if inside == "papers" else (str(PENDCLI),)
    proc = subprocess.Popen(
        [*cli, *CHEAP, "--out", "o"],
        cwd=tmp_path,
        env=child_env(),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    moment = (
        (lambda: bool(new_folders(tmp_path, "o")))
        if inside == "folder"
        else in_new_folder(tmp_path, "o", inside)
    )
    wait_for(proc, moment)
    if proc.poll() is None:
        os.killpg(proc.pid, signum)  # as a terminal does: the whole process group
    _, err = proc.communicate()
    stderr = err.decode()
    assert "Traceback" not in stderr, stderr
    if tree(target) != old:
        assert_whole_new(target)
    assert session_processes(proc.pid) == []
    if proc.returncode == 0:  # finished before the signal came
        return
    if signum == signal.SIGKILL:  # nothing runs on the way out: the next run cleans up
        assert proc.returncode == -signal.SIGKILL
        remove_stale(tmp_path, "o")  # the writer is dead: its temporary folder goes
        assert sorted(p.name for p in tmp_path.iterdir() if p.is_dir()) == ["o"]
        return
    assert proc.returncode == 128 + signum, stderr
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert lines == [f"pendcli: error: interrupted by {signum.name}"], stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o"]  # no temporary, no lock


def test_a_signal_lost_where_python_ignores_exceptions_is_delivered_again() -> None:
    # A TERM handled inside __del__ (or logging's at-fork hook, where a forking run met it)
    # is printed as "Exception ignored" and lost: the run went on and exited 0.
    script = textwrap.dedent(
        """
        import os, signal, sys
        from pendcli.base.interrupts import run_entry

        class Trap:
            def __del__(self):
                os.kill(os.getpid(), signal.SIGTERM)

        def main():
            Trap()
            for _ in range(10**7):
                pass
            print("went on")
            return 0

        sys.exit(run_entry(main, "demo"))
        """
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert (out.returncode, out.stdout) == (143, ""), out.stderr
    assert out.stderr == "demo: interrupted by SIGTERM\n"


_SET_WRITER = textwrap.dedent(
    """
    import sys
    from pathlib import Path
    from pendcli.base.files import write_set
    from pendcli.base.interrupts import run_entry

    def main():
        root = Path(sys.argv[1])
        names = [root / "a" / "t.csv", root / "b" / "u.csv", root / "README.md"]
        print("go", flush=True)
        for i in range(1, 10**6):
            write_set({p: f"{i}\\n" * 20_000 for p in names})
        return 0

    sys.exit(run_entry(main, "writer"))
    """
)


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
@pytest.mark.parametrize("writes", [1, 7, 30])
def test_a_set_interrupted_is_all_old_or_all_new(
    tmp_path: Path, signum: signal.Signals, writes: int
) -> None:
    """``make bench`` and ``make regen`` write their set with write_set: tables in one folder,
    the README in another. Stopped after ``writes`` renames of the README, every file of the
    set holds the same generation."""
    for sub in ("a", "b"):
        (tmp_path / sub).mkdir()
    paths = [tmp_path / "a" / "t.csv", tmp_path / "b" / "u.csv", tmp_path / "README.md"]
    for path in paths:
        path.write_text("0\n" * 20_000, encoding="utf-8")
    proc = subprocess.Popen(
        [sys.executable, "-c", _SET_WRITER, str(tmp_path)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None and proc.stdout.readline() == "go\n"
    readme = tmp_path / "README.md"
    seen, last = 0, readme.stat().st_ino
    for _ in range(POLLS):  # count the README's renames (a new inode each time)
        inode = readme.stat().st_ino
        seen, last = seen + (inode != last), inode
        if seen >= writes:
            break
    proc.send_signal(signum)
    _, err = proc.communicate()
    assert proc.returncode == 128 + signum and err == f"writer: interrupted by {signum.name}\n"
    generations = {p.read_text(encoding="utf-8") for p in paths}
    assert len(generations) == 1, [p.read_text(encoding="utf-8")[:8] for p in paths]
    (text,) = generations
    first = text.splitlines()[0]
    assert text == f"{first}\n" * 20_000  # whole, not cut
    leftovers = [p.name for sub in ("a", "b", ".") for p in (tmp_path / sub).glob(".*.tmp")]
    assert leftovers == []


@pytest.mark.slow
@pytest.mark.parametrize("signum", [signal.SIGKILL])
def test_a_signal_while_a_plot_is_written_leaves_no_cut_file_and_no_lasting_leftover(
    tmp_path: Path, signum: signal.Signals
) -> None:
    """Stopped while its temporary exists: no ``p.png`` or a whole one; TERM removes the
    temporary on the way out, and a SIGKILL's is removed by the next write of that file."""
    from pendcli.base.files import atomic_write

    proc = subprocess.Popen(
        [str(PENDCLI), "tisserand", "example", "--plot", "p.png", "-q"],
        cwd=tmp_path,
        env=child_env(),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    wait_for(proc, lambda: any(p.suffix == ".tmp" for p in tmp_path.iterdir()))
    if proc.poll() is None:
        os.killpg(proc.pid, signum)
    _, err = proc.communicate()
    assert "Traceback" not in err.decode(), err
    plot = tmp_path / "p.png"
    assert not plot.exists() or plot.read_bytes().startswith(b"\x89PNG")
    if proc.returncode == 128 + signal.SIGTERM:
        assert err.decode() == "pendcli: error: interrupted by SIGTERM\n"
        assert [p.name for p in tmp_path.iterdir() if p.name != "p.png"] == []
    atomic_write(plot, b"\x89PNG next")  # the next write of the plot
    assert [p.name for p in tmp_path.iterdir()] == ["p.png"]


def handles(pid: int, signum: int) -> bool:
    """Whether process ``pid`` has installed a handler for ``signum`` (/proc's SigCgt)."""
    status = Path(f"/proc/{pid}/status").read_text(encoding="ascii")
    caught = int(re.search(r"^SigCgt:\s*([0-9a-f]+)$", status, re.M).group(1), 16)  # type: ignore[union-attr]
    return bool(caught >> (signum - 1) & 1)


@pytest.mark.parametrize("module", ["tools.docs", "tools.bench"])
def test_ctrl_c_in_make_regen_or_make_bench_is_one_line_130_and_changes_nothing(
    tmp_path: Path, module: str
) -> None:
    """Stopped during their (long) computation, before anything is written: status 130, one
    line, every file of the set as it was."""
    readme = tmp_path / "README.md"
    readme.write_text("# x\n<!-- bench:start -->\nold\n<!-- bench:end -->\n", encoding="utf-8")
    args = ["--tables", "--readme", str(readme)] if module == "tools.docs" else []
    if module == "tools.bench":
        args = ["--write", str(readme), "--runs", "1", "--quick", "--tables-root", str(tmp_path)]
    proc = subprocess.Popen(
        [sys.executable, "-m", module, *args],
        cwd=tmp_path,
        env={**child_env(), "PYTHONPATH": str(Path(__file__).resolve().parents[2])},  # tools/
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    wait_for(proc, lambda: handles(proc.pid, signal.SIGTERM))  # pendcli's handler is in place
    os.killpg(proc.pid, signal.SIGINT)
    _, err = proc.communicate()
    assert proc.returncode == 130, err
    assert err.decode() == f"python -m {module}: interrupted by SIGINT\n"
    assert readme.read_text(encoding="utf-8").count("old") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["README.md"]


def cpu_ticks(pid: int) -> int:
    """The CPU time process ``pid`` has used (user and system), in clock ticks (/proc)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return int(fields[11]) + int(fields[12])


def children(pid: int) -> list[int]:
    found: list[int] = []
    for task in Path(f"/proc/{pid}/task").glob("*/children"):
        with contextlib.suppress(FileNotFoundError, ProcessLookupError):
            found += [int(child) for child in task.read_text().split()]
    return found


def computing_worker(proc: subprocess.Popen[bytes]) -> int:
    """The forked worker of ``proc`` once it is computing: it has used 0.2 s of CPU (20
    ticks; a fork starts from none), well inside its half of a ledger (seconds)."""
    found: list[int] = []

    def busy() -> bool:
        with contextlib.suppress(FileNotFoundError, ProcessLookupError):
            found[:] = [pid for pid in children(proc.pid) if cpu_ticks(pid) >= 20]
        return bool(found)

    assert wait_for(proc, busy), "no worker computed"
    return found[0]


def start_equations_with_a_worker(tmp_path: Path) -> tuple[subprocess.Popen[bytes], int]:
    """`pendcli equations` of one paper in two processes: each takes half of its ledger. The
    ledger is edited (a comment added), so it is derived afresh (seconds of CPU for each half)
    rather than judged from the stored derivations, which a worker can finish before it is
    seen computing; no result cache."""
    from pendcli.data.tables import tables_dir

    shutil.copytree(tables_dir(), tmp_path / "tables")
    ledger = tmp_path / "tables" / "equations" / "tisserand.toml"
    ledger.write_text(ledger.read_text("utf-8") + "# edited\n", "utf-8")
    proc = subprocess.Popen(
        [str(PENDCLI), "equations", "-p", "tisserand", "-f", "json"],
        cwd=tmp_path,
        env={
            **child_env(),
            "PENDCLI_JOBS": "2",
            "PENDCLI_TABLES": str(tmp_path / "tables"),
            "PENDCLI_CACHE": "off",
        },
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    return proc, computing_worker(proc)


def ended(proc: subprocess.Popen[bytes]) -> str:
    """Its stderr once it has ended; a hang guard of 120 s (a run blocked for ever, as one
    whose worker was killed used to be, fails here, and its processes are killed)."""
    try:
        _, err = proc.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        raise AssertionError("the run did not end") from None
    return err.decode()


def test_a_worker_killed_stops_the_run_in_one_line_naming_it_and_its_signal(
    tmp_path: Path,
) -> None:
    """kill -9 of the worker (as the out-of-memory killer does): the parent used to wait for
    ever, deaf to Ctrl-C; now one line, exit 2, and nothing left running."""
    proc, worker = start_equations_with_a_worker(tmp_path)
    os.kill(worker, signal.SIGKILL)
    stderr = ended(proc)
    assert proc.returncode == 2, stderr
    assert re.fullmatch(
        rf"pendcli: error: worker {worker} \(computing tisserand: equations [01]/2\) was killed "
        r"by SIGKILL before handing back its work; run again, or with PENDCLI_JOBS=1 to "
        r"compute in one process\n",
        stderr,
    ), stderr
    assert session_processes(proc.pid) == []


TO_WORKERS = [
    (signal.SIGTERM, "parent"),
    (signal.SIGTERM, "group"),
    (signal.SIGTERM, "worker"),
    (signal.SIGINT, "group"),
]


@pytest.mark.parametrize(
    ("signum", "to"), TO_WORKERS, ids=[f"{s.name}-{to}" for s, to in TO_WORKERS]
)
def test_a_stop_while_a_worker_computes_ends_the_run_with_its_line(
    tmp_path: Path, signum: signal.Signals, to: str
) -> None:
    """TERM to the parent, to the whole group (as systemd does) or to the worker alone, and
    Ctrl-C: the one-process run's line and status, the worker killed and reaped. TERM used to
    end two processes with status 143 and no line (or, to the worker, hang the parent)."""
    proc, worker = start_equations_with_a_worker(tmp_path)
    if to == "parent":
        os.kill(proc.pid, signum)
    elif to == "group":
        os.killpg(proc.pid, signum)
    else:
        os.kill(worker, signum)
    stderr = ended(proc)
    assert proc.returncode == 128 + signum, stderr
    assert stderr == f"pendcli: error: interrupted by {signum.name}\n"
    assert session_processes(proc.pid) == []


# A signal that lands the moment the handlers are in place, before the entry point has begun
# its work: the stop is the entry point's one line and status, not a traceback (it was a
# traceback and status 1 when the signal came between the handlers' installation and the
# block that catches the stop: a `make bench` stopped early, once in a few runs).
_SIGNAL_AT_ONCE = """
import os, signal, sys
from pendcli.base import interrupts

installed = interrupts.stop_on_signals

def installed_then_signalled():
    installed()
    os.kill(os.getpid(), signal.SIGINT)  # its handler raises here, at once

interrupts.stop_on_signals = installed_then_signalled
{call}
"""


@pytest.mark.parametrize(
    ("call", "line"),
    [
        ("sys.exit(interrupts.run_entry(lambda: 0, 'python -m tools.x'))", "python -m tools.x"),
        ("sys.argv[1:] = ['--version']\nfrom pendcli.cli.main import run\nrun()", "pendcli: error"),
    ],
    ids=["tools", "pendcli"],
)
def test_a_signal_as_the_handlers_are_installed_is_one_line_130(call: str, line: str) -> None:
    proc = subprocess.run(
        [sys.executable, "-c", _SIGNAL_AT_ONCE.format(call=call)],
        env=child_env(),
        capture_output=True,
        text=True,
    )
    assert (proc.returncode, proc.stdout) == (130, ""), proc.stderr
    assert proc.stderr == f"{line}: interrupted by SIGINT\n"
