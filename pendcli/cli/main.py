"""`pendcli`: the console-script entry. It runs the app (:mod:`pendcli.cli.app`) and turns
every way a run can end into an exit code and at most one line on stderr, never a traceback:
a user error or an OS error exits 2, a bug 3 (the trace under ``PENDCLI_DEBUG``)."""

from __future__ import annotations

import atexit
import contextlib
import gc
import os
import sys

import typer

from pendcli.base.errors import PendcliError
from pendcli.cli.app import app
from pendcli.cli.messages import named_as_typed, usage_message

__all__ = ["refuse_blank", "run"]


def run() -> None:
    """Console-script entry: every user error and OS error one line and exit 2, no traceback."""
    if sys.stdout is None:  # started with `>&-`: Python leaves no stdout at all
        _write_error("cannot write standard output: it is closed")
        sys.exit(2)
    from pendcli.base.console import protect_streams, set_quiet

    # At exit, skip the collector's last pass over every object scipy made (~0.06 s of CPU
    # measured): the OS frees them anyway. Other atexit handlers and the flushes still run.
    atexit.unregister(gc.freeze)
    atexit.register(gc.freeze)
    # The collector's first generation every 50,000 allocations, not 700: a cold judgement
    # builds millions of short-lived sympy and numpy objects, and the default thresholds
    # collect thousands of times (0.25-0.4 s of a cold `equations`' 4.5 s of CPU, measured in
    # pairs); the peak memory stays the same (156 MB both). Forked workers inherit it.
    gc.set_threshold(50_000, 20, 20)
    set_quiet(False)
    from pendcli.base.interrupts import Interrupted, stop_on_signals

    try:  # a stop that lands outside _invoke (as the handlers go in, at the flush): one line
        stop_on_signals()  # Ctrl-C, TERM, HUP: one line, status 128 + the signal (_invoke)
        original = protect_streams()
        try:
            code = _invoke(sys.argv[1:])
            code = _flush_standard_output(code)
        finally:
            sys.stdout = original
    except Interrupted as exc:
        code = _fail(str(exc), exc.status)
    sys.exit(code)


def refuse_blank(args: list[str]) -> None:
    """No option or argument of pendcli takes an empty or blank value: one is a slip of the
    shell (an unset variable, stray quotes), refused in one line where typer would read ''
    as the current folder (`formulas --plot ''`) or as no claim at all (`explain ''`)."""
    for index, arg in enumerate(args):
        name, equals, value = arg.partition("=") if arg.startswith("--") else ("", "", arg)
        if (equals and not value.strip()) or (not equals and not arg.strip()):
            before = args[index - 1] if index and args[index - 1].startswith("-") else ""
            after = f", after {args[index - 1]!r}," if index else ""
            where = name or before or f"argument {index + 1}{after}"
            raise PendcliError(f"{where} must not be empty or blank, got {value or arg!r}")


def _invoke(args: list[str]) -> int:
    """Run the app; turn every way it can end into an exit code and at most one stderr line."""
    from pendcli.base.interrupts import Interrupted

    try:
        refuse_blank(args)
        # prog_name fixed: the usage line and the completion variable (_PENDCLI_COMPLETE)
        # must not depend on how Python was started (`python -m pendcli`, a test runner).
        code = app(args=args, prog_name="pendcli", standalone_mode=False)
    except PendcliError as exc:
        return _fail(named_as_typed(exc, args), 2)
    except typer.TyperException as exc:  # click's usage errors: rephrased, one line
        if _is_bare_group_help(exc):  # a bare group: its help, as typer does
            _write_error(exc.format_message(), prefix="")
            return 2
        return _fail(usage_message(exc, args), 2)
    except Interrupted as exc:
        return _fail(str(exc), exc.status)
    except (typer.Abort, KeyboardInterrupt):
        return _fail("aborted", 130)
    except typer.Exit as exc:
        return exc.exit_code
    except OSError as exc:
        from pendcli.base.files import describe_os_error  # not on the start-up path

        return _fail(describe_os_error(exc), 2)
    except Exception as exc:  # a bug: still one line, unless PENDCLI_DEBUG asks for the trace
        from pendcli.base.errors import out_of_memory

        if (memory := out_of_memory(exc)) is not None:  # a limit reached, no bug: exit 2
            return _fail(memory, 2)
        if os.environ.get("PENDCLI_DEBUG"):
            raise
        return _fail(f"internal error: {type(exc).__name__}: {exc} (set PENDCLI_DEBUG=1)", 3)
    return code if isinstance(code, int) else 0


def _is_bare_group_help(exc: typer.TyperException) -> bool:
    """A group named without a subcommand (``no_args_is_help``): the error's text is its help."""
    ctx = getattr(exc, "ctx", None)
    return (
        ctx is not None
        and not isinstance(exc, typer.BadParameter)
        and exc.format_message() == ctx.get_help()
    )


def _flush_standard_output(code: int) -> int:
    """Flush stdout now, so a full disk or a closed pipe is reported here, not at shutdown."""
    from pendcli.base.errors import PendcliError

    try:
        sys.stdout.flush()
    except PendcliError as exc:  # base.console names the stream (standard output)
        # Python flushes stdout again at exit and would print "Exception ignored ...".
        with contextlib.suppress(OSError, ValueError):
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            os.close(devnull)
        return code if code >= 2 else _fail(str(exc), 2)  # an earlier error already spoke
    return code


def _write_error(message: str, prefix: str = "pendcli: error: ") -> None:
    if sys.stderr is None:
        return
    with contextlib.suppress(OSError, ValueError):
        sys.stderr.write(f"{prefix}{message.rstrip()}\n")
        sys.stderr.flush()


def _fail(message: str, code: int) -> int:
    """One line on stderr, whole: a newline in it (a path's) is shown escaped."""
    from pendcli.base.errors import one_line

    _write_error(one_line(message.strip()) or "error")
    return code
