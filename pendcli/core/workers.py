"""Forked worker processes that never outlive this one: the one way pendcli runs work in
parallel (reproduce's steps, the report's figures).

* A worker dies with its parent: on Linux the kernel sends it SIGKILL when the parent ends
  (``PR_SET_PDEATHSIG``), even by ``kill -9``; elsewhere it at least refuses to start once the
  parent is gone. A ``check --update`` killed mid-run used to leave a worker computing, and
  holding its files, for seconds.
* Ctrl-C reaches every process of the terminal's group: the workers ignore it and the parent
  alone ends the run (one line, exit 130, no traceback per worker). SIGTERM in the parent ends
  the block with ``SystemExit(143)``; either way the pool is terminated, not waited for.
* :meth:`ForkedWorkers.share` splits work without timings: this process and each worker take
  the next item whenever they are free, so a costly item never waits behind a guess of costs.
  Results are the same whoever computed them (tests/test_determinism.py compares the bytes).
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

T = TypeVar("T")
R = TypeVar("R")

_PR_SET_PDEATHSIG = 1  # linux/prctl.h
_NEXT: Any = None  # in a worker: the _Counter of the next item to take (see share)


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
            from pendcli.core.errors import invalid_value

            raise invalid_value("PENDCLI_JOBS", env, "a whole number of processes, 1 or more")
        requested = int(env) if env else min(2, os.cpu_count() or 1)
    return max(1, min(requested, tasks))


def _start_worker(parent: int, next_item: Any) -> None:
    """In each forked worker, before any task: die with the parent, leave Ctrl-C to it."""
    global _NEXT
    _NEXT = next_item
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() != parent:  # the parent died before prctl took effect
        os._exit(1)


def _ended_by_sigterm(signum: int, frame: object) -> None:
    raise SystemExit(128 + signum)


class _Counter:
    """The index of the next item, shared by forked processes: an anonymous shared mapping
    (no file: multiprocessing.Value would make a 4 kB temporary one, refused where the file
    size is limited) and a lock."""

    def __init__(self, context: Any) -> None:
        import mmap

        self.memory = mmap.mmap(-1, 8)
        self.lock = context.Lock()

    def take(self) -> int:
        with self.lock:
            index = int.from_bytes(self.memory[:8], "little")
            self.memory[:8] = (index + 1).to_bytes(8, "little")
        return index


def _take_turns(items: Sequence[T], run: Callable[[T], R], next_item: _Counter) -> dict[int, R]:
    """Run the items not yet taken by another process, one at a time: {index: result}."""
    done: dict[int, R] = {}
    while (index := next_item.take()) < len(items):
        done[index] = run(items[index])
    return done


def _worker_turns(items: Sequence[T], run: Callable[[T], R]) -> dict[int, R]:
    return _take_turns(items, run, _NEXT)


class ForkedWorkers:
    """``processes`` forked workers beside this process (none: everything runs here)."""

    def __init__(self, processes: int) -> None:
        self.processes = processes
        self.pool: Any = None
        self.next_item: Any = None
        self.previous_sigterm: Any = None

    def __enter__(self) -> ForkedWorkers:
        if self.processes > 0:
            import multiprocessing

            context = multiprocessing.get_context("fork")
            self.next_item = _Counter(context)
            if threading.current_thread() is threading.main_thread():
                self.previous_sigterm = signal.signal(signal.SIGTERM, _ended_by_sigterm)
            args = (os.getpid(), self.next_item)
            self.pool = context.Pool(self.processes, initializer=_start_worker, initargs=args)
        return self

    def submit(self, run: Callable[..., R], *args: Any) -> Callable[[], R]:
        """Start ``run(*args)`` in a worker (or, with none, here when asked): its result."""
        if self.pool is None:
            return lambda: run(*args)
        return self.pool.apply_async(run, args).get

    def share(
        self,
        items: Sequence[T],
        run: Callable[[T], R],
        done: Callable[[T, R], None] = lambda item, result: None,
    ) -> list[R]:
        """``run`` over ``items``, shared by this process and the workers, each taking the
        next item when free (put the costliest first); results in the order of ``items``.
        ``done`` is called here for each item, as soon as its result is here. Once per pool."""
        if self.pool is None:
            return [_done(done, item, run(item)) for item in items]
        theirs = [self.submit(_worker_turns, items, run) for _ in range(self.processes)]
        results: dict[int, R] = {}
        mine = _take_turns(items, lambda item: _done(done, item, run(item)), self.next_item)
        results.update(mine)
        for collect in theirs:
            for index, result in collect().items():
                results[index] = _done(done, items[index], result)
        return [results[i] for i in range(len(items))]

    def __exit__(self, exc_type: object, *exc: object) -> None:
        if self.pool is not None:
            if exc_type is None:
                self.pool.close()
            else:  # an error, Ctrl-C or SIGTERM: the workers' work is not wanted any more
                self.pool.terminate()
            self.pool.join()
            self.pool = None
        if self.previous_sigterm is not None:
            signal.signal(signal.SIGTERM, self.previous_sigterm)
            self.previous_sigterm = None


def _done(done: Callable[[T, R], None], item: T, result: R) -> R:
    done(item, result)
    return result
