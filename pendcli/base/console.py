"""The rich console used for tables and progress: colour only on a terminal, never with NO_COLOR.

Also the standard streams made safe for any locale and any destination: a character the
stream's encoding lacks is written as a ``\\uXXXX`` escape (still valid inside JSON strings),
and a failed write to standard output names it, so the CLI can say which "file" failed.
"""

from __future__ import annotations

import codecs
import errno
import os
import signal
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any, TextIO

if TYPE_CHECKING:
    from rich.console import Console

__all__ = [
    "ESCAPE_ERRORS",
    "NamedStream",
    "console",
    "for_display",
    "is_quiet",
    "progress_bar",
    "protect_streams",
    "set_quiet",
    "status_line",
]

STANDARD_OUTPUT = "standard output"
ESCAPE_ERRORS = "pendcli-escape"
_quiet = False


def set_quiet(value: bool) -> None:
    """Silence status lines (``say``) for the rest of this invocation (``--quiet``)."""
    global _quiet
    _quiet = value


def is_quiet() -> bool:
    return _quiet


def _pipe_width() -> int:
    """Width of tables written to a file or pipe: $COLUMNS when set, else 160."""
    columns = os.environ.get("COLUMNS", "")
    return int(columns) if columns.isdigit() and int(columns) >= 40 else 160


def wants_colour(is_tty: bool) -> bool:
    """Colour on a terminal, or anywhere FORCE_COLOR is set (CI logs render it); never when
    NO_COLOR is set (https://no-color.org; it wins over FORCE_COLOR)."""
    if os.environ.get("NO_COLOR"):
        return False
    return is_tty or bool(os.environ.get("FORCE_COLOR"))


def console(stderr: bool = False) -> Console:
    """A rich console: colour only on a terminal or with FORCE_COLOR, never with NO_COLOR."""
    from rich.console import Console

    stream = sys.stderr if stderr else sys.stdout
    is_tty = stream.isatty()
    colour = wants_colour(is_tty)
    made = Console(
        file=stream,
        force_terminal=colour or is_tty,  # (rich would read FORCE_COLOR even under NO_COLOR)
        no_color=not colour,
        highlight=False,
        width=None if is_tty else _pipe_width(),
        soft_wrap=False,
    )
    if stderr:  # (stdout's own broken pipe is NamedStream's: a quiet exit, 141)
        made.on_broken_pipe = lambda: _status_unread(made)  # type: ignore[method-assign]
    return made


def _status_unread(made: Console) -> None:
    """Standard error's reader stopped (``2>&1 >out.json | head -1``): status lines are only
    advice, so the run goes on without them. rich's own answer was exit 1 with standard
    *output* sent to /dev/null, the result lost."""
    made.quiet = True
    set_quiet(True)
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)  # Python's last flush of stderr goes there
        os.dup2(devnull, sys.stderr.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass


def _escape_unencodable(exc: UnicodeError) -> tuple[str, int]:
    """``\\uXXXX`` (UTF-16 pairs beyond the BMP): readable, lossless and valid JSON."""
    if not isinstance(exc, UnicodeEncodeError):
        raise exc
    escaped = []
    for char in exc.object[exc.start : exc.end]:
        code = ord(char)
        if code > 0xFFFF:
            code -= 0x10000
            escaped += [f"\\u{0xD800 + (code >> 10):04x}", f"\\u{0xDC00 + (code & 0x3FF):04x}"]
        else:
            escaped.append(f"\\u{code:04x}")
    return "".join(escaped), exc.end


codecs.register_error(ESCAPE_ERRORS, _escape_unencodable)


class NamedStream:
    """A text stream whose OS errors become one PendcliError naming it (``standard output``)."""

    def __init__(self, stream: TextIO, name: str) -> None:
        self._stream = stream
        self._name = name

    def _error(self, exc: OSError) -> BaseException:
        # A reader that stops early (`pendcli reproduce | head`) is no fault: leave quietly
        # with the status a shell gives a process killed by SIGPIPE, as other tools do.
        if exc.errno == errno.EPIPE:
            os.dup2(os.open(os.devnull, os.O_WRONLY), self._stream.fileno())
            return SystemExit(128 + signal.SIGPIPE)
        # A PendcliError, not an OSError: typer swallows EPIPE (exit 1) before pendcli sees it.
        from pendcli.base.errors import PendcliError
        from pendcli.base.files import describe_os_error

        return PendcliError(describe_os_error(exc, self._name))

    def write(self, text: str) -> int:
        try:
            return self._stream.write(text)
        except OSError as exc:
            raise self._error(exc) from None

    def flush(self) -> None:
        try:
            self._stream.flush()
        except OSError as exc:
            raise self._error(exc) from None

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)


def _encodes_unicode(stream: TextIO) -> bool:
    try:
        return codecs.lookup(stream.encoding or "ascii").name.startswith("utf")
    except LookupError:
        return False


def for_display(text: str, stream: TextIO | None = None) -> str:
    """Text for a human on ``stream``: ``?`` for what its encoding lacks, so columns still align."""
    stream = sys.stdout if stream is None else stream
    if _encodes_unicode(stream):
        return text
    encoding = stream.encoding or "ascii"
    return text.encode(encoding, "replace").decode(encoding)


def protect_streams() -> TextIO:
    """Make stdout/stderr safe on any locale; wrap stdout; return the stdout to restore."""
    original = sys.stdout
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is not None and not _encodes_unicode(stream):
            reconfigure(errors=ESCAPE_ERRORS)
    if not isinstance(original, NamedStream):
        sys.stdout = NamedStream(original, STANDARD_OUTPUT)
    return original


@contextmanager
def progress_bar(
    quiet: bool,
    total: int,
    title: str,
    rows: tuple[int, Callable[[], int]] | None = None,
) -> Iterator[Callable[[str, int], None]]:
    """A progress bar of ``total`` steps on stderr, only on a terminal and when not quiet
    (rich loads only then); yields ``advance(description, steps)``. ``rows``: (rows to do,
    rows done so far), shown live beside the steps: read at each refresh, in rich's own
    thread, so the count moves while this process computes (``37/112 ledger rows``)."""
    if quiet or not sys.stderr.isatty():
        yield lambda _description, _steps: None
        return
    from rich.progress import Progress, ProgressColumn
    from rich.text import Text

    columns: list[Any] = [*Progress.get_default_columns()]
    if rows is not None:
        count, done = rows

        class RowsDone(ProgressColumn):
            def render(self, task: Any) -> Text:
                return Text(f"{min(done(), count)}/{count} ledger rows")

        columns.append(RowsDone())
    with Progress(*columns, console=console(stderr=True), transient=True) as progress:
        task = progress.add_task(title, total=total)
        yield lambda description, steps: progress.update(
            task, description=description, advance=steps
        )


def status_line(text: str) -> None:
    """``text`` as the one status line on a terminal's stderr, replacing the previous one
    (``""`` clears it); nothing in a pipe or under --quiet. No thread: safe across a fork,
    for the seconds before a progress bar can start (loading the libraries, the ledgers)."""
    if _quiet or not sys.stderr.isatty():
        return
    import shutil

    width = shutil.get_terminal_size().columns - 1
    try:
        sys.stderr.write(f"\r\033[K{text[:width]}")
        sys.stderr.flush()
    except (OSError, ValueError):
        pass
