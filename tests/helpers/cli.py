"""Run the CLI in tests: in this process as a user would (:func:`invoke`), or in a fresh
process where a real one is needed (:func:`run_cli`: exit codes on a closed or full stdout,
start-up imports, signals, shell completion); and check its one-line errors."""

from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys
from collections.abc import Iterator, Mapping
from typing import Any, NamedTuple

from pendcli.cli.main import run

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


def invoke(*args: str, env: Mapping[str, str] | None = None, utf8: bool = False) -> CliResult:
    """Run `pendcli ARGS` in-process (``env``: variables set for the call; ``utf8``: stdout
    declares UTF-8, as a terminal does); return (exit code, stdout, stderr)."""
    out = _Utf8Capture() if utf8 else io.StringIO()
    err = io.StringIO()
    argv = sys.argv
    sys.argv = ["pendcli", *args]
    code = 0
    try:
        with _environment(env), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            run()
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    finally:
        sys.argv = argv
    return CliResult(code, out.getvalue(), err.getvalue())


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


def assert_clean_error(code: int, err: str) -> None:
    assert code == 2, err
    assert "Traceback" not in err
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert lines[0].startswith("pendcli: error: ")
