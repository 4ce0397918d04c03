"""Forked workers never outlive their parent, and the pool ends with it (issue 23).

Found by an attack run: in 17 of 25 `kill -9` trials of `check --update` a forked worker was
still computing after its parent had died. Each test here starts a parent in a fresh process,
whose workers report their pids, then ends the parent and looks for the workers.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from pendcli.core.workers import ForkedWorkers, job_count

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc and prctl")

# A parent whose two workers and itself each take one item that never ends; each worker writes
# its pid to a file first, and the parent prints "ready" once both have.
PARENT = """
import os, sys, time
from pathlib import Path
from pendcli.core.workers import ForkedWorkers

folder = Path(sys.argv[1])

def forever(item):
    (folder / f"{os.getpid()}.pid").write_text("")
    while True:
        time.sleep(0.05)

def here(item):
    if os.getpid() == parent:
        while len(list(folder.glob("*.pid"))) < 2:
            time.sleep(0.01)
        print("ready", flush=True)
        while True:
            time.sleep(0.05)
    return forever(item)

parent = os.getpid()
with ForkedWorkers(2) as pool:
    pool.share(["a", "b", "c"], here)
"""


def alive(pid: int) -> bool:
    """A process that exists and is not a zombie (a dead child not yet reaped by init)."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except FileNotFoundError:
        return False
    return state != "Z"


def start_parent(folder: Path) -> tuple[subprocess.Popen[str], list[int]]:
    proc = subprocess.Popen(
        [sys.executable, "-c", PARENT, str(folder)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None and proc.stdout.readline().strip() == "ready", proc.stderr
    workers = [int(p.stem) for p in folder.glob("*.pid")]
    assert len(workers) == 2 and all(alive(pid) for pid in workers)
    return proc, workers


def workers_left(workers: list[int]) -> list[int]:
    """The workers still alive after their parent ended (given up to 10 s to go)."""
    for _ in range(1000):
        if not any(alive(pid) for pid in workers):
            return []
        time.sleep(0.01)
    return [pid for pid in workers if alive(pid)]


@pytest.mark.parametrize("how", [signal.SIGKILL, signal.SIGTERM, signal.SIGINT])
def test_no_worker_outlives_its_parent(tmp_path: Path, how: signal.Signals) -> None:
    proc, workers = start_parent(tmp_path)
    proc.send_signal(how)
    code = proc.wait()
    try:
        assert workers_left(workers) == []
    finally:
        for pid in workers:
            if alive(pid):
                os.kill(pid, signal.SIGKILL)
    assert code == {signal.SIGKILL: -9, signal.SIGTERM: 143, signal.SIGINT: -2}[how], proc.stderr
    if how == signal.SIGTERM:  # ended by SystemExit: no traceback from the parent or workers
        assert proc.stderr is not None and "Traceback" not in proc.stderr.read()


def square(x: int) -> int:
    return x * x


def test_share_gives_every_result_in_order_whoever_computed_it() -> None:
    seen: list[int] = []
    with ForkedWorkers(1) as pool:
        out = pool.share(list(range(20)), square, lambda item, result: seen.append(item))
    assert out == [x * x for x in range(20)]
    assert sorted(seen) == list(range(20))


def test_no_workers_runs_everything_here() -> None:
    with ForkedWorkers(0) as pool:
        assert pool.share([1, 2, 3], square) == [1, 4, 9]
        assert pool.submit(square, 7)() == 49


def test_job_count(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PENDCLI_JOBS", "1")
    assert job_count(None, 5) == 1
    monkeypatch.setenv("PENDCLI_JOBS", "8")
    assert job_count(None, 3) == 3  # never more processes than tasks
    assert job_count(2, 5) == 2
    assert job_count(0, 5) == 1
    monkeypatch.setenv("PENDCLI_JOBS", "")
    assert job_count(None, 5) == min(2, os.cpu_count() or 1)  # unset or empty: the default


@pytest.mark.parametrize("value", ["abc", "0", "-1", "2.5"])
def test_a_bad_process_count_is_one_line_naming_the_variable_and_the_range(
    value: str, tmp_path: Path
) -> None:
    """Through the real CLI: one line, exit 2, no traceback (it used to run with the default)."""
    env = {**os.environ, "PENDCLI_JOBS": value, "PENDCLI_CACHE": str(tmp_path)}
    done = subprocess.run(
        [sys.executable, "-m", "pendcli", "equations", "-p", "tisserand", "-f", "json"],
        env=env,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.strip().splitlines() == [
        f"pendcli: error: PENDCLI_JOBS: {value!r} is not valid; expected a whole number of "
        "processes, 1 or more"
    ]


def children(parent: int) -> list[int]:
    """The processes whose parent is ``parent`` (read from /proc)."""
    found = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except (FileNotFoundError, ProcessLookupError):
            continue
        if int(fields[1]) == parent and fields[0] != "Z":
            found.append(int(stat.parent.name))
    return found


@pytest.mark.slow
def test_killing_reproduce_leaves_no_worker(tmp_path: Path) -> None:
    """The CLI itself: `reproduce --equations` with two processes, killed by SIGKILL."""
    env = {**os.environ, "PENDCLI_JOBS": "2"}
    proc = subprocess.Popen(
        [sys.executable, "-m", "pendcli", "reproduce", "-f", "json", "--equations"],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    workers: list[int] = []
    for _ in range(6000):  # the worker is forked once the imports are done (up to 60 s)
        workers = children(proc.pid)
        if workers or proc.poll() is not None:
            break
        time.sleep(0.01)
    assert workers, "no worker was forked"
    proc.kill()
    proc.wait()
    try:
        assert workers_left(workers) == []
    finally:
        for pid in workers:
            if alive(pid):
                os.kill(pid, signal.SIGKILL)


def test_equations_shares_each_ledger_s_parts_and_gives_them_back_in_ledger_order(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """`pendcli equations` (reproduce.ledger_rows): each ledger cut in LEDGER_PARTS parts,
    taken by this process and a forked worker; the rows come back paper by paper, part by
    part, whichever process computed them, and in one process the same list."""
    from pendcli.papers import registry
    from pendcli.reproduce import LEDGER_PARTS, ledger_rows

    parent, taken = os.getpid(), tmp_path / "a worker took a part"
    # this process waits for the worker to take a part, however loaded the machine; a hang
    # guard of 60 s in all: with no worker the assertion below then fails
    wait_until = time.monotonic() + 60

    def fake_rows(keys: list[str], part: tuple[int, int] = (0, 1)) -> list[object]:
        if os.getpid() != parent:
            taken.touch()
        while os.getpid() == parent and not taken.exists() and time.monotonic() < wait_until:
            time.sleep(0.01)
        return [(keys[0], part, os.getpid())]

    monkeypatch.setattr(registry, "equation_rows", fake_rows)
    keys = ("tisserand", "lecornu")
    shared = ledger_rows(keys, jobs=2)
    assert [(k, p) for k, p, _ in shared] == [
        (k, (i, LEDGER_PARTS)) for k in keys for i in range(LEDGER_PARTS)
    ]
    assert {pid for *_, pid in shared} - {os.getpid()}  # a part computed by the worker
    alone = ledger_rows(keys, jobs=1)
    assert [(k, p) for k, p, _ in alone] == [(k, p) for k, p, _ in shared]
    assert {pid for *_, pid in alone} == {os.getpid()}
