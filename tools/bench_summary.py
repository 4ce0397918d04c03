"""The suite and the install, timed by ``make bench``, and the README's summary of the run.

The project asks that every timing the project states comes from one measurement. ``python -m
tools.bench`` measures everything in one run; this module adds what only a checkout can
measure (the fast test suite as ``make test`` runs it; installing the runtime from the lock
into a new venv with empty download caches: "from nothing") and writes the few headline
figures into the README between ``<!-- timings:start -->`` and ``<!-- timings:end -->``. Both
the README block and docs/benchmarks.md carry the same measurement tag, a digest of the
figures, so a test can tell that they were written together.
"""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

__all__ = [
    "INSTALL_TARGET",
    "SUITE_TARGET",
    "SUMMARY_END",
    "SUMMARY_START",
    "Headline",
    "checkout_root",
    "install_time",
    "measurement_tag",
    "suite_time",
    "summary_lines",
    "timed_process",
    "with_summary",
]

SUMMARY_START, SUMMARY_END = "<!-- timings:start -->", "<!-- timings:end -->"
SUITE_TARGET = 25.0  # s wall, quiet
INSTALL_TARGET = 15.0  # s wall, from nothing
# the fast suite exactly as `make test` runs it (Makefile: PYTEST and XDIST)
SUITE_ARGS = ["-m", "pytest", "-q", "-n", "2", "--dist", "worksteal", "-p", "no:randomly"]
SUITE_MARKS = ["-m", "not slow and not browser"]


@dataclass(frozen=True)
class Headline:
    """One figure of the summary: what, its wall and CPU seconds, and its ratio to a reference
    in the measure its target names (``None`` where there is no target)."""

    what: str
    wall: float
    cpu: float | None
    ratio: str = ""
    target: str = ""


def checkout_root() -> Path | None:
    """The checkout pendcli runs from (with its tests, Makefile and lock), or None (installed)."""
    root = Path(__file__).resolve().parent.parent
    needed = ("Makefile", "tests", "requirements.lock", "pyproject.toml")
    return root if all((root / name).exists() for name in needed) else None


def timed_process(
    cmd: list[str],
    env: dict[str, str],
    cwd: Path | None = None,
    allowed: tuple[int, ...] = (0,),
) -> tuple[float, float]:
    """(wall, CPU) seconds of one run: CPU is user + system of the process and every child it
    waited for (a forked worker's too), as the kernel accounts them. Output is discarded;
    another exit status than ``allowed`` raises, with the run's stderr."""
    with tempfile.TemporaryFile() as err:
        start = time.perf_counter()
        # A session of its own: a Ctrl-C stops this run (which then kills the child), not the
        # child first, whose failure would read as a broken command.
        proc = subprocess.Popen(
            cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=err,
            start_new_session=True,
        )  # fmt: skip
        try:
            _, status, usage = os.wait4(proc.pid, 0)
        except BaseException:
            proc.kill()
            raise
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        if proc.returncode not in allowed:
            err.seek(0)
            raise subprocess.CalledProcessError(
                proc.returncode, cmd, stderr=err.read().decode(errors="replace")
            )
    return wall, usage.ru_utime + usage.ru_stime


def suite_time(root: Path) -> tuple[float, float]:
    """Wall and CPU seconds of the fast suite, run as ``make test`` runs it (bytecode kept in
    the venv's pycache, reproduce's own forks off: PENDCLI_JOBS=1). A failing test still
    leaves a time (exit 1; the test of this block's own tag fails until it is written once);
    an error of pytest itself raises."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(
        PENDCLI_JOBS="1", NO_COLOR="1", PYTHONPYCACHEPREFIX=str(Path(sys.prefix) / "pycache")
    )
    return timed_process([sys.executable, *SUITE_ARGS, *SUITE_MARKS], env, root, allowed=(0, 1))


def install_time(root: Path) -> tuple[float, float]:
    """Wall and CPU seconds of ``make reproduce``'s install step into a new venv, with empty
    pip and uv caches (every wheel downloaded from the registry): the Makefile's own recipe."""
    with tempfile.TemporaryDirectory(prefix="pendcli-install-") as tmp:
        env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "UV_CACHE_DIR")}
        env.update(UV_CACHE_DIR=str(Path(tmp) / "uv-cache"), PIP_NO_CACHE_DIR="1")
        venv = Path(tmp) / "venv"
        python = _base_python()
        cmd = ["make", "-s", f"VENV={venv}", f"PYTHON={python}", f"{venv}/.runtime"]
        return timed_process(cmd, env, root)


def _base_python() -> str:
    """The interpreter the venv was made from (``make`` makes the new venv with it)."""
    base = Path(sys.base_prefix) / "bin" / f"python{sys.version_info[0]}.{sys.version_info[1]}"
    return str(base) if base.exists() else "python3"


def measurement_tag(lines: list[str]) -> str:
    """A short digest of a measurement's text: the same in every file it was written to."""
    return hashlib.sha256("\n".join(lines).encode()).hexdigest()[:12]


def summary_lines(
    headlines: list[Headline], tag: str, load: tuple[float, float] | None = None
) -> list[str]:
    """The README's block: the headline figures of one ``make bench`` run, as ratios."""
    at = f", at a load average of {load[0]:.1f} to {load[1]:.1f} on 2 cores" if load else ""
    lines = [
        f"Measured by one `make bench` run{at} (measurement `{tag}`, the same tag as in "
        "[benchmarks.md](benchmarks.md), which has every figure and how it was taken):",
        "",
        "| what | wall (s) | CPU (s) | ratio | target |",
        "|---|---:|---:|---:|---|",
    ]
    for h in headlines:
        cpu = "" if h.cpu is None else f"{h.cpu:.2f}"
        lines.append(f"| {h.what} | {h.wall:.2f} | {cpu} | {h.ratio} | {h.target} |")
    return lines


def with_summary(readme_text: str, block: list[str]) -> str | None:
    """The README with ``block`` between the timings markers (None where they are absent)."""
    if SUMMARY_START not in readme_text or SUMMARY_END not in readme_text:
        return None
    head, rest = readme_text.split(SUMMARY_START, 1)
    _old, tail = rest.split(SUMMARY_END, 1)
    return f"{head}{SUMMARY_START}\n" + "\n".join(block) + f"\n{SUMMARY_END}{tail}"
