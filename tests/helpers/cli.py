"""Run the CLI in tests: in this process as a user would (:func:`invoke`), or in a fresh
process where a real one is needed (:func:`run_cli`: exit codes on a closed or full stdout,
start-up imports, signals, shell completion); and check its one-line errors."""

from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any, NamedTuple, TextIO

import typer

from pendcli.cli.app import app
from pendcli.cli.main import run
from pendcli.papers.registry import all_papers

# `pendcli` as a fresh interpreter runs it (the installed script may be absent in a checkout)
PENDCLI = (sys.executable, "-m", "pendcli")
# For a child under a file-size limit (RLIMIT_FSIZE): Python writes a module's byte-code with
# one write() that the limit cuts short, and renames the cut file into the shared cache, where
# every later import of that module fails ("marshal data too short"). No byte-code written.
NO_BYTECODE = {"PYTHONDONTWRITEBYTECODE": "1"}


class _Utf8Capture(io.StringIO):
    """Captured output that declares UTF-8, as a terminal would (a plain StringIO declares
    none, so a table shows ``?`` for every non-ASCII character)."""

    @property
    def encoding(self) -> str:  # type: ignore[override]
        return "utf-8"


class CliResult(NamedTuple):
    code: int
    out: str
    err: str


@contextlib.contextmanager
def _environment(env: Mapping[str, str] | None) -> Iterator[None]:
    if not env:
        yield
        return
    saved = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        yield
    finally:
        for key, value in saved.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value


# The click group typer makes of the app, per set of registered papers (their sub-commands
# are the group's): a process runs one command line, so it builds the group once, reading the
# annotations of every command's parameters (3 ms, and 1-3 ms for the sub-command named);
# the tests run a thousand in one process, each served the group the first one built.
# Click makes a fresh context for every run: the group holds no state of a run.
_GROUPS: dict[tuple[int, ...], Any] = {}


@contextlib.contextmanager
def _group_built_once() -> Iterator[None]:
    build = typer.main.get_command

    def built(typer_instance: typer.Typer) -> Any:
        if typer_instance is not app:
            return build(typer_instance)
        papers = all_papers()
        key = tuple(id(p) for p in papers)
        if key not in _GROUPS:
            _GROUPS[key] = (build(typer_instance), papers)  # the papers kept: ids not reused
        return _GROUPS[key][0]

    typer.main.get_command = built
    try:
        yield
    finally:
        typer.main.get_command = build


def invoke(
    *args: str,
    env: Mapping[str, str] | None = None,
    utf8: bool = False,
    terminal: TextIO | None = None,
) -> CliResult:
    """Run `pendcli ARGS` in-process (``env``: variables set for the call; ``utf8``: stdout
    declares UTF-8, as a terminal does; ``terminal``: a stream both stdout and stderr write
    to instead, such as a pseudo-terminal's, and then the result's are empty); return (exit
    code, stdout, stderr). The app's click group is built once per set of registered papers
    and served again."""
    out: TextIO = _Utf8Capture() if utf8 else io.StringIO()
    err: TextIO = io.StringIO()
    if terminal is not None:
        out = err = terminal
    argv = sys.argv
    sys.argv = ["pendcli", *args]
    code = 0
    try:
        with (
            _environment(env),
            _group_built_once(),
            contextlib.redirect_stdout(out),
            contextlib.redirect_stderr(err),
        ):
            run()
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    finally:
        sys.argv = argv
    if terminal is not None:
        return CliResult(code, "", "")
    return CliResult(code, out.getvalue(), err.getvalue())  # type: ignore[attr-defined]


def invoke_in_a_child(
    *args: str, limit: Callable[[], None], env: Mapping[str, str] | None = None
) -> CliResult:
    """:func:`invoke` in a child forked from this process (helpers/forked.py), after
    ``limit()`` (a resource limit, say, that must not bind this process)."""
    from helpers.forked import in_a_child

    def limited() -> CliResult:
        limit()
        return invoke(*args, env=env)

    return in_a_child(limited)


def child_env(**extra: str) -> dict[str, str]:
    """This process's environment for a `pendcli` child, without what would change its run
    (PENDCLI_DEBUG's tracebacks, a PENDCLI_TABLES folder), in one process (PENDCLI_JOBS=1)
    unless ``extra`` says otherwise."""
    env = {k: v for k, v in os.environ.items() if k not in ("PENDCLI_DEBUG", "PENDCLI_TABLES")}
    return {**env, "PENDCLI_JOBS": "1", **extra}


def run_cli(
    *args: str, env: Mapping[str, str] | None = None, **kwargs: Any
) -> subprocess.CompletedProcess[str]:
    """Run `pendcli ARGS` in a fresh process, output captured as text unless ``kwargs`` say
    otherwise (``stdout=``, ``preexec_fn=``...); ``env`` is added to this process's
    environment. Never raises on a non-zero exit."""
    options: dict[str, Any] = {"text": True, "check": False, "timeout": 300}
    if "stdout" not in kwargs and "stderr" not in kwargs:
        options["capture_output"] = True
    options.update(kwargs)
    return subprocess.run([*PENDCLI, *args], env={**os.environ, **(env or {})}, **options)


# One interpreter imports what `python -m pendcli` imports before it reads its arguments, then
# runs the real entry point (pendcli/__main__.py, through runpy as `-m` does) in a child forked
# for each command line: its standard output the file named, its standard error a file of its
# own; the child ends as the fresh process would (SystemExit, then the interpreter's shutdown
# with its last flush). The parent prints each child's exit code.
_FORKED_ENTRY = """
import os
import runpy
import sys

import pendcli.cli.main

for index, args in enumerate({arg_lists!r}):
    sys.stdout.flush()
    sys.stderr.flush()
    child = os.fork()
    if child == 0:
        os.dup2(os.open({stdout!r}, os.O_WRONLY), 1)
        os.dup2(os.open(f"{{{errors!r}}}.{{index}}", os.O_WRONLY | os.O_CREAT, 0o600), 2)
        sys.argv = ["pendcli", *args]
        runpy.run_module("pendcli", run_name="__main__", alter_sys=True)
        sys.exit(0)
    print(index, os.waitstatus_to_exitcode(os.waitpid(child, 0)[1]))
"""


def run_cli_forked(
    arg_lists: Sequence[Sequence[str]], stdout: str, errors: str
) -> list[tuple[int, str]]:
    """Per command line of ``arg_lists``: (exit code, stderr) of `pendcli ARGS` with its
    standard output opened from the path ``stdout`` (such as /dev/full), each run as a fresh
    process runs it but forked from one interpreter (``errors``: a path prefix for their
    standard errors). For behaviours of the real entry point that do not depend on how the
    interpreter started (its locale, its closed streams: those need :func:`run_cli`)."""
    code = _FORKED_ENTRY.format(
        arg_lists=[list(a) for a in arg_lists], stdout=stdout, errors=errors
    )
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=300
    )
    codes = dict(line.split() for line in done.stdout.splitlines())
    assert len(codes) == len(arg_lists), done.stderr
    return [
        (int(codes[str(i)]), Path(f"{errors}.{i}").read_text(encoding="utf-8"))
        for i in range(len(arg_lists))
    ]


def assert_clean_error(code: int, err: str) -> None:
    assert code == 2, err
    assert "Traceback" not in err
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert lines[0].startswith("pendcli: error: ")
