"""Ctrl-C, TERM and HUP end a run with one line and the shell's status (128 + the signal).

:func:`stop_on_signals` turns each of these signals into :class:`Interrupted`, a
``BaseException`` that no ``except Exception`` swallows and that click does not turn into its
own silent abort, so every ``finally`` and cleanup on the way out runs (a half-built output
folder is removed) and the entry point prints one line: 130 for SIGINT, 143 for SIGTERM, 129
for SIGHUP. A forked child leaves at once and silently instead: its parent speaks for the run
(the workers of :mod:`pendcli.base.workers` ignore Ctrl-C; it kills them on its way out).

:func:`stop` raises any :class:`Interrupted` from a signal handler, so that a forked worker's
death (:class:`~pendcli.base.workers.WorkerDied`, noticed on SIGCHLD) stops the run the same
way: deferred within :func:`stops_deferred`, delivered again if lost.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
from collections.abc import Callable, Iterator
from types import FrameType

__all__ = ["Interrupted", "run_entry", "stop", "stop_on_signals", "stops_deferred"]

_SIGNALS = ("SIGINT", "SIGTERM", "SIGHUP")


class Interrupted(BaseException):
    """The run was stopped by ``signum``; ``status`` is what a shell reports (128 + it,
    unless given); ``message`` replaces "interrupted by SIGNAME" (a forked worker's death)."""

    def __init__(self, signum: int, message: str | None = None, status: int | None = None) -> None:
        self.signum = signum
        self.status = 128 + signum if status is None else status
        self.name = signal.Signals(signum).name
        super().__init__(message or f"interrupted by {self.name}")


# Python runs a signal's handler in the main thread, whichever thread the kernel gave the
# signal to (a BLAS or timer thread, which a per-thread signal mask does not cover): so the
# handler itself defers the stop while the main thread is in a section that must not be cut.
_deferring = 0
_deferred: Interrupted | None = None


def stop(exc: Interrupted) -> None:
    """Raise ``exc`` (from a signal handler); within :func:`stops_deferred`, on leaving it. A
    signal to this process replaces a stop noted before; any other stop is noted only first."""
    global _deferred
    if not _deferring:
        raise exc
    if _deferred is None or type(exc) is Interrupted:
        _deferred = exc


def _raise(signum: int, _frame: FrameType | None) -> None:
    stop(Interrupted(signum))


@contextlib.contextmanager
def stops_deferred() -> Iterator[None]:
    """Within the block a stop signal is only noted; it is raised on leaving it."""
    global _deferring, _deferred
    _deferring += 1
    try:
        yield
    finally:
        _deferring -= 1
        if not _deferring and _deferred is not None:
            noted, _deferred = _deferred, None
            raise noted


def _leave(signum: int, _frame: FrameType | None) -> None:
    os._exit(128 + signum)


def _quiet_in_child() -> None:
    for name in _SIGNALS:
        signal.signal(getattr(signal, name), _leave)


# A signal that lands in code whose exceptions Python ignores (an at-fork hook of logging, a
# __del__) would be lost there, printed as "Exception ignored in ...", and the run would go
# on: it is sent again a moment later, from a timer thread (raised or sent at once, it would be
# handled inside this hook, and lost again), to land in ordinary code. Bounded, in case it
# keeps landing there.
_AGAIN_AFTER = 0.05  # seconds: long enough to leave the hook, short beside any run
_REDELIVERIES = 50
_redelivered = 0
_installed = False


def _unraisable(info: sys.UnraisableHookArgs) -> None:
    global _redelivered
    if isinstance(info.exc_value, Interrupted) and _redelivered < _REDELIVERIES:
        import threading

        _redelivered += 1
        again = threading.Timer(_AGAIN_AFTER, os.kill, (os.getpid(), info.exc_value.signum))
        again.daemon = True
        again.start()
        return
    sys.__unraisablehook__(info)


def stop_on_signals() -> None:
    """Raise :class:`Interrupted` on SIGINT, SIGTERM and SIGHUP (in the main thread)."""
    global _installed
    for name in _SIGNALS:
        signal.signal(getattr(signal, name), _raise)
    if not _installed:
        os.register_at_fork(after_in_child=_quiet_in_child)
        sys.unraisablehook = _unraisable
        _installed = True


def run_entry(main: Callable[[], int], prog: str) -> int:
    """Run a module's ``main`` (``python -m tools.docs``...): an interrupt or a
    :class:`~pendcli.base.errors.PendcliError` is one line on stderr, never a traceback."""
    from pendcli.base.errors import PendcliError

    try:
        stop_on_signals()  # inside the block: a signal as soon as its handler is in is caught
        return main()
    except Interrupted as exc:
        print(f"{prog}: {exc}", file=sys.stderr)
        return exc.status
    except PendcliError as exc:
        print(f"{prog}: error: {str(exc).strip().splitlines()[0]}", file=sys.stderr)
        return 2
