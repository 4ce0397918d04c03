"""Forked worker processes that never outlive this one, and whose death never hangs it: the
one way pendcli runs work in parallel (reproduce's steps, the report's figures).

* A worker dies with its parent: on Linux the kernel sends it SIGKILL when the parent ends
  (``PR_SET_PDEATHSIG``), even by ``kill -9``; elsewhere it at least refuses to start once the
  parent is gone. A ``check --update`` killed mid-run used to leave a worker computing, and
  holding its files, for seconds.
* A worker that dies while it holds work (by a signal, the out-of-memory killer's SIGKILL
  included, or by an exit) stops the run: :class:`WorkerDied`, one line naming its pid, the item
  it was computing and how it ended, exit 2. The parent hears of it on SIGCHLD while it
  computes its own share, and from the worker's pipe (its end closes with it; looked at every
  second besides) while it waits. Nothing here waits on a lock a dead worker could hold: the
  items are dealt through a pipe, each taken by one read. (With multiprocessing's Pool, a
  worker killed by ``kill -9`` left its parent blocked in the pool's teardown, deaf to Ctrl-C.)
* Ctrl-C reaches every process of the terminal's group: the workers ignore it and the parent
  alone ends the run (:mod:`pendcli.base.interrupts`: one line, exit 130). TERM and HUP end
  a worker (kill one alone, and the run stops); the run then stops as if they had reached the
  parent, with its line and status (143, 129), whichever process they reached first. Leaving
  the block, however, the parent kills its workers with SIGKILL and reaps them: no orphan, no
  zombie, and no wait on a worker that cannot end.
* :meth:`ForkedWorkers.share` splits work without timings: this process and each worker take
  the next item whenever they are free, so a costly item never waits behind a guess of costs.
  Results are the same whoever computed them (tests/run/test_determinism.py compares the bytes).
"""

from __future__ import annotations

import contextlib
import gc
import mmap
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, NoReturn, TypeVar

from pendcli.base.interrupts import Interrupted, stop, stops_deferred

T = TypeVar("T")
R = TypeVar("R")

_PR_SET_PDEATHSIG = 1  # linux/prctl.h
_INDEX = 4  # bytes of an item's index in the pipe of turns
# Items one share can deal: all their indices fit in the smallest pipe (a page on Linux; 512
# bytes, POSIX's PIPE_BUF, elsewhere), written at once before any process reads.
MOST_ITEMS = 1024 if sys.platform.startswith("linux") else 128
_LOOK_EVERY = 1.0  # seconds: how often a parent waiting for a worker also asks if it lives
_REAP_TRIES = 200  # looks, 10 ms apart, for a worker whose pipe closed to become a zombie
_STOPS = (signal.SIGTERM, signal.SIGHUP)  # the stops a worker dies of, as the parent would
_HANDED_BACK = -1  # a worker's slot once its work is sent back (else: 1 + the item's index)


# Rows done in this run, one 8-byte count per process (this one: 0, worker k: k + 1) in
# memory the forked workers share, so a progress bar moves by rows whoever computes them;
# None outside :func:`counting_rows`.
_rows_done: mmap.mmap | None = None
_row_slot = 0
_ROW_SLOTS = 64


def row_done() -> None:
    """One more row of work done (a ledger row judged): counted when a run counts rows."""
    memory = _rows_done
    if memory is not None:
        at = 8 * _row_slot
        memory[at : at + 8] = (int.from_bytes(memory[at : at + 8], "little") + 1).to_bytes(
            8, "little"
        )


@contextlib.contextmanager
def counting_rows() -> Iterator[Callable[[], int]]:
    """Count :func:`row_done` in this process and the workers forked inside the block; yields
    the count so far (enter before forking: the workers inherit the shared memory)."""
    global _rows_done
    memory = _rows_done = mmap.mmap(-1, 8 * _ROW_SLOTS)

    def done() -> int:
        return sum(int.from_bytes(memory[8 * i : 8 * i + 8], "little") for i in range(_ROW_SLOTS))

    try:
        yield done
    finally:
        _rows_done = None
        memory.close()


class WorkerDied(Interrupted):
    """A forked worker ended before handing back its work: the run stops, exit 2."""

    def __init__(self, pid: int, doing: str, how: str) -> None:
        message = (
            f"worker {pid} ({doing}) {how} before handing back its work; "
            "run again, or with PENDCLI_JOBS=1 to compute in one process"
        )
        super().__init__(signal.SIGCHLD, message, status=2)
        self.pid = pid


def job_count(requested: int | None, tasks: int) -> int:
    """Processes to use for ``tasks`` items: ``requested``, else ``$PENDCLI_JOBS`` (a whole
    number, 1 or more; anything else is refused), else up to 2 (this project's machines have
    two cores); 1 where ``fork`` is not available."""
    import multiprocessing

    if "fork" not in multiprocessing.get_all_start_methods():
        return 1
    if requested is None:
        env = os.environ.get("PENDCLI_JOBS", "").strip()
        if env and not (env.isdigit() and int(env) >= 1):
            # a typo here used to be ignored silently: the run took the default instead
            from pendcli.base.errors import invalid_value

            raise invalid_value("PENDCLI_JOBS", env, "a whole number of processes, 1 or more")
        requested = int(env) if env else min(2, os.cpu_count() or 1)
    return max(1, min(requested, tasks))


def how_it_ended(status: int) -> str:
    """``"was killed by SIGKILL"``, ``"exited with status 3"``: a wait status in words."""
    if os.WIFSIGNALED(status):
        number = os.WTERMSIG(status)
        try:
            return f"was killed by {signal.Signals(number).name}"
        except ValueError:
            return f"was killed by signal {number}"
    return f"exited with status {os.waitstatus_to_exitcode(status)}"


class _Turns:
    """The indices of the items not yet taken, in a pipe every forked process reads: each
    takes the next with one read of 4 bytes, done whole under the kernel's own lock, so a
    process killed at any moment leaves no lock held (a multiprocessing.Lock would stay
    taken). The read end does not block: an empty pipe means every item is taken."""

    def __init__(self) -> None:
        self.read, self.write = os.pipe()
        os.set_blocking(self.read, False)

    def deal(self, count: int) -> None:
        if count > MOST_ITEMS:
            raise ValueError(f"{count} items to share; at most {MOST_ITEMS}")
        os.write(self.write, b"".join(i.to_bytes(_INDEX, "little") for i in range(count)))

    def take(self) -> int | None:
        try:
            return int.from_bytes(os.read(self.read, _INDEX), "little")
        except BlockingIOError:
            return None

    def close(self) -> None:
        os.close(self.read)
        os.close(self.write)


class _Slots:
    """What each worker is doing, in memory shared with it (one 8-byte number per worker):
    0 nothing yet, 1 + i computing item i, _HANDED_BACK its work sent. Read by the parent
    only, and only to name what a dead worker was computing (no pipe is read in a handler)."""

    def __init__(self, count: int) -> None:
        self.memory = mmap.mmap(-1, 8 * count)

    def set(self, slot: int, value: int) -> None:
        self.memory[8 * slot : 8 * slot + 8] = value.to_bytes(8, "little", signed=True)

    def get(self, slot: int) -> int:
        return int.from_bytes(self.memory[8 * slot : 8 * slot + 8], "little", signed=True)


@dataclass
class _Worker:
    pid: int
    slot: int
    conn: Any  # multiprocessing.connection.Connection: work in, results out
    status: int | None = None  # its wait status, once reaped
    busy: bool = False  # it holds work not yet handed back
    results: dict[int, Any] | None = None  # what it handed back

    def ended(self) -> int | None:
        """Its wait status if it has ended (reaped now, if not already), else None."""
        if self.status is None:
            try:
                pid, status = os.waitpid(self.pid, os.WNOHANG)
            except ChildProcessError:  # being reaped by the code this handler interrupted
                return None
            if pid:
                self.status = status
        return self.status


def _reaped(worker: _Worker) -> int | None:
    """The wait status of a worker whose pipe has closed: it is ending, so a zombie in a
    moment (bounded; one that closed its pipe yet lives on is of no use: it is killed)."""
    for _ in range(_REAP_TRIES):
        if worker.ended() is not None:
            return worker.status
        time.sleep(0.01)
    with contextlib.suppress(ProcessLookupError, ChildProcessError):
        os.kill(worker.pid, signal.SIGKILL)
        worker.status = os.waitpid(worker.pid, 0)[1]
    return worker.status


def _start_worker(parent: int) -> None:
    """In each forked worker, before any work: die with the parent, leave it the stops."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C reaches the group: the parent's
    for name in ("SIGTERM", "SIGHUP", "SIGCHLD"):  # (the others, from interrupts' at-fork hook)
        signal.signal(getattr(signal, name), signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() != parent:  # the parent died before prctl took effect
        os._exit(1)


def _serve(
    conn: Any, turns: _Turns, slots: _Slots, slot: int, parent: int, others: list[Any]
) -> NoReturn:
    """A forked worker's life: each piece of work read from ``conn`` done and sent back,
    until the pipe closes or the parent kills it; it never returns, nor runs exit handlers."""
    global _row_slot
    code = 1
    _row_slot = min(slot + 1, _ROW_SLOTS - 1)
    try:
        _start_worker(parent)
        for other in others:  # the parent's ends: this worker's death must close its own
            other.close()
        while True:
            try:
                items, run = conn.recv()
            except EOFError:
                break
            _hand_back(conn, _work(items, run, turns, slots, slot))
            slots.set(slot, _HANDED_BACK)
        code = 0
    finally:
        os._exit(code)


def _work(
    items: Sequence[Any], run: Callable[[Any], Any], turns: _Turns, slots: _Slots, slot: int
) -> tuple[str, Any]:
    """In a worker: the items not yet taken, one at a time; ("results", {index: result}), or
    ("failed", the exception) at the first that raised."""
    done: dict[int, Any] = {}
    try:
        while (index := turns.take()) is not None:
            slots.set(slot, 1 + index)
            done[index] = run(items[index])
    except Exception as exc:
        return ("failed", exc)
    return ("results", done)


def _hand_back(conn: Any, message: tuple[str, Any]) -> None:
    try:
        conn.send(message)
    except Exception as exc:  # a result or an exception that pickle cannot carry
        what = f"{type(message[1]).__name__}: {message[1]}" if message[0] == "failed" else "results"
        conn.send(("failed", RuntimeError(f"a worker's {what} could not be sent back: {exc}")))


def _ended_by_sigterm(signum: int, frame: object) -> None:
    raise SystemExit(128 + signum)


class ForkedWorkers:
    """``processes`` forked workers beside this process (none: everything runs here)."""

    def __init__(self, processes: int) -> None:
        self.processes = processes
        self.workers: list[_Worker] = []
        self.turns: _Turns | None = None
        self.slots: _Slots | None = None
        self.previous_sigterm: Any = None
        self.label: Callable[[int], str] = str
        self.frozen = False

    def __enter__(self) -> ForkedWorkers:
        if self.processes > 0:
            main = threading.current_thread() is threading.main_thread()
            if main and signal.getsignal(signal.SIGTERM) is signal.SIG_DFL:  # no handler yet
                self.previous_sigterm = signal.signal(signal.SIGTERM, _ended_by_sigterm)
            try:
                self._start()
            except BaseException:
                self.__exit__(*sys.exc_info())
                raise
        return self

    def _start(self) -> None:
        from multiprocessing.connection import Pipe

        parent, self.turns, self.slots = os.getpid(), _Turns(), _Slots(self.processes)
        # What exists now is shared with the workers: frozen, the collector of neither process
        # walks it (writing to every page of it, which the fork then copies), until _end
        gc.freeze()
        self.frozen = True
        for slot in range(self.processes):
            here, there = Pipe()
            try:
                pid = os.fork()
            except BaseException:
                here.close()
                there.close()
                raise
            if pid == 0:
                others = [here, *(worker.conn for worker in self.workers)]
                _serve(there, self.turns, self.slots, slot, parent, others)
            there.close()
            self.workers.append(_Worker(pid, slot, here))

    def share(
        self,
        items: Sequence[T],
        run: Callable[[T], R],
        done: Callable[[T, R], None] = lambda item, result: None,
        name: Callable[[T], str] | None = None,
        first: Callable[[], object] | None = None,
    ) -> list[R]:
        """``run`` over ``items``, shared by this process and the workers, each taking the
        next item when free (put the costliest first); results in the order of ``items``.
        ``done`` is called here for each item, as soon as its result is here; ``name`` says
        what an item is, should a worker die computing it; ``first`` is done here while the
        workers take their first items (with no worker, not at all: nothing runs beside it)."""
        if not self.workers:
            return [_done(done, item, run(item)) for item in items]
        self.label = (lambda i: name(items[i])) if name else (lambda i: f"item {i + 1}")
        results: dict[int, R] = {}
        with self._watching():
            self._deal(items, run)
            if first is not None:
                first()
            assert self.turns is not None
            while (index := self.turns.take()) is not None:
                results[index] = _done(done, items[index], run(items[index]))
                self._look()
            for worker in self.workers:
                for index, value in self._collect(worker).items():
                    results[index] = _done(done, items[index], value)
        return [results[i] for i in range(len(items))]

    def _deal(self, items: Sequence[Any], run: Callable[[Any], Any]) -> None:
        assert self.turns is not None and self.slots is not None
        self.turns.deal(len(items))
        for worker in self.workers:
            self.slots.set(worker.slot, 0)
            worker.busy, worker.results = True, None
            try:
                worker.conn.send((items, run))
            except (BrokenPipeError, ConnectionResetError):
                raise self._death(worker) from None

    def _look(self) -> None:
        """Between this process's items: take what the workers handed back, and stop the run
        if one died holding work."""
        for worker in self.workers:
            if worker.busy and worker.conn.poll():
                self._receive(worker)
            if self._lost(worker):
                raise self._death(worker)

    def _collect(self, worker: _Worker) -> dict[int, Any]:
        """Wait for what ``worker`` hands back, looking every second whether it still lives
        (its pipe's end tells at once; this, even should something else hold it open)."""
        while worker.busy:
            if worker.conn.poll(_LOOK_EVERY):
                self._receive(worker)
            elif self._lost(worker):
                raise self._death(worker)
        assert worker.results is not None
        return worker.results

    def _receive(self, worker: _Worker) -> None:
        try:
            kind, value = worker.conn.recv()
        except (EOFError, OSError):  # its end closed, maybe in the middle of a message
            raise self._death(worker) from None
        worker.busy = False
        if kind == "failed":
            raise value
        worker.results = value

    def _lost(self, worker: _Worker) -> bool:
        """Whether ``worker`` has ended holding work it had not sent back."""
        assert self.slots is not None
        if not worker.busy or worker.ended() is None:
            return False
        return self.slots.get(worker.slot) != _HANDED_BACK

    def _death(self, worker: _Worker) -> Interrupted:
        """How the run stops for ``worker``'s death: killed by TERM or HUP (a stop sent to
        the run's group, say), as if this process had been, with the same line; else
        :class:`WorkerDied`."""
        assert self.slots is not None
        status = _reaped(worker)
        if status is not None and os.WIFSIGNALED(status) and os.WTERMSIG(status) in _STOPS:
            return Interrupted(os.WTERMSIG(status))
        doing = self.slots.get(worker.slot)
        what = f"computing {self.label(doing - 1)}" if doing > 0 else "before its first item"
        return WorkerDied(worker.pid, what, how_it_ended(status) if status is not None else "ended")

    @contextlib.contextmanager
    def _watching(self) -> Iterator[None]:
        """SIGCHLD stops the run as soon as a worker holding work dies, whatever this process
        is computing (in the main thread only, where handlers run; elsewhere the looks and
        waits above notice it)."""
        if threading.current_thread() is not threading.main_thread():
            yield
            return
        previous = signal.signal(signal.SIGCHLD, self._on_child)
        try:
            yield
        finally:
            signal.signal(signal.SIGCHLD, previous if previous is not None else signal.SIG_DFL)

    def _on_child(self, signum: int, frame: object) -> None:
        for worker in self.workers:
            if self._lost(worker):
                stop(self._death(worker))

    def __exit__(self, *exc: object) -> None:
        try:
            with stops_deferred():  # a second Ctrl-C waits for the workers' end: bounded
                self._end()
        finally:
            if self.previous_sigterm is not None:
                signal.signal(signal.SIGTERM, self.previous_sigterm)
                self.previous_sigterm = None

    def _end(self) -> None:
        """Kill and reap every worker, whatever it is doing: its work is handed back or no
        longer wanted (SIGKILL cannot be ignored, so the wait is bounded)."""
        for worker in self.workers:
            if worker.status is None:
                with contextlib.suppress(ProcessLookupError):
                    os.kill(worker.pid, signal.SIGKILL)
        for worker in self.workers:
            if worker.status is None:
                with contextlib.suppress(ChildProcessError):
                    worker.status = os.waitpid(worker.pid, 0)[1]
            worker.conn.close()
        self.workers = []
        if self.turns is not None and self.slots is not None:
            self.turns.close()
            self.slots.memory.close()
        self.turns = self.slots = None
        if self.frozen:
            gc.unfreeze()
            self.frozen = False


def _done(done: Callable[[T, R], None], item: T, result: R) -> R:
    done(item, result)
    return result
