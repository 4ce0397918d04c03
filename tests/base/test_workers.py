"""Forked workers never outlive their parent, and the pool ends with it.

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
from helpers.cli import invoke

from pendcli.base.workers import ForkedWorkers, WorkerDied, job_count

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc and prctl")

# A parent whose two workers and itself each take one item that never ends; each worker writes
# its pid to a file first, and the parent prints "ready" once both have.
PARENT = """
import os, sys, time
from pathlib import Path
from pendcli.base.workers import ForkedWorkers

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


def reaped(pid: int) -> bool:
    """Whether ``pid``, a child of this process, is gone and reaped (no zombie left)."""
    try:
        os.waitpid(pid, os.WNOHANG)
    except ChildProcessError:
        return not Path(f"/proc/{pid}").exists()
    return False


# A parent of one worker, each taking one of two items: the parent leaves a sign as it starts
# its own; the worker waits for that sign, leaves one of its own, then is killed ("kill"),
# exits with status 3 ("exit", SIGCHLD blocked: the wait for its results must notice), raises
# ("error") or returns ("none"); the parent's item waits for the worker's sign (up to 60 s;
# "kill": all that time, but for the worker's death), counting its looks. Printed: what was
# raised or returned, then the worker's pid, the looks and whether the worker was reaped once
# the block is left. Each wait is a hang guard of 6,000 looks.
DYING = """
import os, signal, sys, time
from pathlib import Path
from pendcli.base.errors import PendcliError
from pendcli.base.workers import ForkedWorkers, WorkerDied

how, sign, started = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[2] + "-parent")
parent, looks, taken = os.getpid(), [], []

def item(name):
    if os.getpid() != parent:
        for _ in range(6000):
            if started.exists():
                break
            time.sleep(0.01)
        sign.touch()
        if how == "kill":
            os.kill(os.getpid(), signal.SIGKILL)
        if how == "exit":
            os._exit(3)
        if how == "error":
            raise PendcliError("tables/x.csv: row 3: not a number")
        return name
    taken.append(name)  # before the sign: the worker may die, and SIGCHLD stop this item, at once
    started.touch()
    for _ in range(6000):
        looks.append(name)
        if how != "kill" and sign.exists():
            break
        time.sleep(0.01)
    return name

if how == "exit":
    signal.pthread_sigmask(signal.SIG_BLOCK, [signal.SIGCHLD])
with ForkedWorkers(1) as pool:
    (pid,) = [worker.pid for worker in pool.workers]
    try:
        print("returned", *pool.share(["a", "b"], item, name=lambda name: f"the item {name}"),
              sep="|")
    except (WorkerDied, PendcliError) as exc:
        print(type(exc).__name__, getattr(exc, "status", ""), exc, sep="|")
try:
    os.waitpid(pid, os.WNOHANG)
    reaped = "not reaped"
except ChildProcessError:
    reaped = "reaped"
print(pid, len(looks), taken[0], reaped, sep="|")
"""


def dying(how: str, tmp_path: Path) -> tuple[list[str], int, int, str, str]:
    """Run DYING: (what was raised or returned, split), the worker's pid, the parent's
    looks, the item it took, and whether the worker was reaped (a hang guard of 120 s)."""
    done = subprocess.run(
        [sys.executable, "-c", DYING, how, str(tmp_path / "sign")],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0 and done.stderr == "", done.stderr
    raised, worker = done.stdout.splitlines()
    pid, looks, mine, reaped = worker.split("|")
    return raised.split("|"), int(pid), int(looks), mine, reaped


def test_a_worker_killed_while_this_process_computes_stops_it_at_once(tmp_path: Path) -> None:
    """A worker killed mid-item (as the out-of-memory killer does): the parent, busy with an
    item of its own, is stopped by SIGCHLD, in one line naming the worker, its item and the
    signal (multiprocessing's Pool waited for ever); the worker is reaped."""
    raised, pid, looks, mine, reaped = dying("kill", tmp_path)
    theirs = {"a": "b", "b": "a"}[mine]
    assert raised == [
        "WorkerDied",
        "2",
        f"worker {pid} (computing the item {theirs}) was killed by SIGKILL before handing back "
        "its work; run again, or with PENDCLI_JOBS=1 to compute in one process",
    ]
    assert looks < 6000  # cut short, not waited out
    assert reaped == "reaped"


def test_a_worker_that_exits_while_this_process_waits_is_named_with_its_status(
    tmp_path: Path,
) -> None:
    """SIGCHLD blocked: the wait for the worker's results notices its death by itself."""
    raised, pid, _, mine, reaped = dying("exit", tmp_path)
    theirs = {"a": "b", "b": "a"}[mine]
    assert raised[:2] == ["WorkerDied", "2"]
    assert raised[2].startswith(
        f"worker {pid} (computing the item {theirs}) exited with status 3 before handing back"
    )
    assert reaped == "reaped"


def test_an_error_in_a_worker_is_raised_here_and_the_worker_is_reaped(tmp_path: Path) -> None:
    raised, _, _, _, reaped = dying("error", tmp_path)
    assert raised == ["PendcliError", "", "tables/x.csv: row 3: not a number"]
    assert reaped == "reaped"


def test_leaving_the_block_kills_and_reaps_the_worker(tmp_path: Path) -> None:
    raised, _, _, _, reaped = dying("none", tmp_path)
    assert raised == ["returned", "a", "b"]
    assert reaped == "reaped"


def test_more_items_than_a_pipe_surely_holds_are_refused_not_left_to_block() -> None:
    from pendcli.base.workers import MOST_ITEMS

    with ForkedWorkers(1) as pool:
        assert pool.share(list(range(MOST_ITEMS)), square)[-1] == (MOST_ITEMS - 1) ** 2
        with pytest.raises(ValueError, match=f"at most {MOST_ITEMS}"):
            pool.share(list(range(MOST_ITEMS + 1)), square)


def test_a_worker_s_death_waits_for_the_end_of_a_section_that_defers_stops() -> None:
    """Noticed inside stops_deferred (an atomic write), it stops the run on leaving it; a
    signal to this process noted there takes its place."""
    from pendcli.base.interrupts import Interrupted, stop, stops_deferred

    finished: list[int] = []

    def section(*stops: Interrupted) -> None:
        with stops_deferred():
            for each in stops:
                stop(each)
            finished.append(len(stops))

    death = WorkerDied(1234, "computing x", "was killed by SIGKILL")
    with pytest.raises(WorkerDied):
        section(death)
    later = WorkerDied(5678, "computing y", "was killed by SIGKILL")
    with pytest.raises(Interrupted) as stopped:
        section(death, Interrupted(signal.SIGTERM), later)
    assert finished == [1, 3]  # each section ran to its end
    assert type(stopped.value) is Interrupted and stopped.value.status == 143


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
    """One line, exit 2, no traceback (it used to run with the default), through the entry
    point in this process: the variable is read when a command asks for its workers, not when
    a module is imported (a fresh process's exit code on a one-line error is the attacks')."""
    env = {"PENDCLI_JOBS": value, "PENDCLI_CACHE": str(tmp_path)}
    code, out, err = invoke("equations", "-p", "tisserand", "-f", "json", env=env)
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        "pendcli: error: PENDCLI_JOBS must be a whole number of processes, 1 or more, "
        f"got {value!r}"
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
    from pendcli.run.reproduce import LEDGER_PARTS, ledger_rows

    parent, taken = os.getpid(), tmp_path / "a worker took a part"
    # this process waits for the worker to take a part, however loaded the machine; a hang
    # guard of 60 s in all: with no worker the assertion below then fails
    wait_until = time.monotonic() + 60

    def fake_rows(
        keys: list[str], part: tuple[int, int] = (0, 1), measure: bool = True
    ) -> list[object]:
        if os.getpid() != parent:
            taken.touch()
        while os.getpid() == parent and not taken.exists() and time.monotonic() < wait_until:
            time.sleep(0.01)
        return [(keys[0], part, os.getpid())]

    monkeypatch.setattr(registry, "equation_rows", fake_rows)
    # the formula rows lent to the ledger's measured rows: the fake rows read none (Lecornu's
    # checks would be integrated for each of the two runs, 0.5 s each)
    monkeypatch.setattr("pendcli.run.reproduce.formula_checks", lambda key: [])
    monkeypatch.setattr(
        "pendcli.verify.ledger_evaluation.with_measured", lambda rows, ledger, formulas: rows
    )
    keys = ("tisserand", "lecornu")
    shared = ledger_rows(keys, jobs=2)
    assert [(k, p) for k, p, _ in shared] == [
        (k, (i, LEDGER_PARTS)) for k in keys for i in range(LEDGER_PARTS)
    ]
    assert {pid for *_, pid in shared} - {os.getpid()}  # a part computed by the worker
    alone = ledger_rows(keys, jobs=1)
    assert [(k, p) for k, p, _ in alone] == [(k, p) for k, p, _ in shared]
    assert {pid for *_, pid in alone} == {os.getpid()}
