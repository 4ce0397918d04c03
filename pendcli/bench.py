"""Benchmarks: start-up times and the published work-precision tables.

``python -m pendcli.bench --write docs/benchmarks.md`` measures, in one run and on this machine,

* ``pendcli --help`` against ``python -c "import typer"`` (target: within 1.3x),
* ``pendcli reproduce --format json`` against ``python -c "import scipy.special,
  scipy.integrate"`` (target: within 1.8x),

each as the median wall time of several interleaved runs of a fresh interpreter (the
result cache off); against the import floor B (``python -c "import sympy, scipy.special,
scipy.integrate, matplotlib.pyplot, mpmath"``), cold (``PENDCLI_CACHE=off``) and warm (the
result cache filled by the warm-up run), the CPU and wall time of ``pendcli equations
--format json`` (target: CPU within 2x B) and ``pendcli reproduce --out DIR`` (wall within
4x B; ``reproduce --format json`` is timed once, above, where 7 runs tell its 0.7 s apart
from noise better than the floor table's 3 would); and the
modules that cost most at import (``python -X importtime``); pendcli against its peers in the
same process (``scipy.special.jn_zeros``, ``mpmath.beta``, ``solve_ivp``, ``scipy.special.ellipk``:
time per call, ratio, and the largest relative difference of the two answers); the growth of
cost with size (``lecornu zeros --count`` 1e3..1e7, ``charbonnier table --n-max`` 1e2..1e4:
wall time and peak memory, each run in its own process, stopped at a time and memory limit);
it regenerates the work-precision tables ``tables/tradeoff/<family>.csv``
(:mod:`pendcli.run.tradeoff`, with the date in ``tables/tradeoff/measured.toml``) and rewrites the
README section between ``<!-- bench:start -->`` and ``<!-- bench:end -->`` atomically (or prints
it when the markers are absent).  These are benchmarks, not tests: nothing here fails on a slow
machine.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from pendcli.run.tradeoff_engine import Point

START, END = "<!-- bench:start -->", "<!-- bench:end -->"
HELP_TARGET, REPRODUCE_TARGET = 1.3, 1.8


def _pendcli_command() -> list[str]:
    script = Path(sys.executable).with_name("pendcli")
    if script.exists():
        return [str(script)]
    found = shutil.which("pendcli")
    return [found] if found else [sys.executable, "-m", "pendcli"]


def _commands() -> dict[str, list[str]]:
    py = sys.executable
    cli = _pendcli_command()
    return {
        "import typer": [py, "-c", "import typer"],
        "pendcli --help": [*cli, "--help"],
        "import scipy.special, scipy.integrate": [
            py,
            "-c",
            "import scipy.special, scipy.integrate",
        ],
        "pendcli reproduce --format json": [*cli, "reproduce", "--format", "json", "--quiet"],
    }


def _wall(cmd: list[str]) -> float:
    return _timed(cmd)[0]


def _timed(cmd: list[str], env: dict[str, str] | None = None) -> tuple[float, float]:
    """(wall, CPU) seconds of one run (:func:`pendcli.bench_summary.timed_process`). The
    result cache is off unless ``env`` names one."""
    from pendcli.bench_summary import timed_process

    variables = {**os.environ, "NO_COLOR": "1", "COLUMNS": "100", "PENDCLI_CACHE": "off"}
    variables.update(env or {})
    # As a user runs it: bytecode written and read. Where PYTHONDONTWRITEBYTECODE is set every
    # run would compile sympy and scipy from source again (4 s of B's 6 s on this machine).
    variables.pop("PYTHONDONTWRITEBYTECODE", None)
    return timed_process(cmd, variables)


# The import floor B of the work and what is measured against it:
# label -> (the reference label, the measure the target names, the target ratio)
FLOOR = "B: import sympy, scipy.special, scipy.integrate, matplotlib.pyplot, mpmath"
# What every cold `equations` run pays before its first check: B's imports, then each ledger
# read and its printed formulas parsed. Its ratio to B says how much of the 2x target is left
# for the checks themselves.
LEDGERS = "B, then the three ledgers read (every printed formula parsed)"
# ... then every reference the ledgers cite built, once per name: the author's model done
# exactly, which every verdict on a printed form compares with. Above 2x B, no verdict
# engine that builds these references in sympy can meet the 2x target cold.
REFERENCES = "B, the ledgers read, then every cited reference built (once per name)"
# the rows shown as a share of B's CPU: what a cold `equations` run pays besides its verdicts
PREFIXES = (LEDGERS, REFERENCES)
FLOOR_TARGETS: dict[str, tuple[str, str, float]] = {
    "pendcli equations --format json": (FLOOR, "CPU", 2.0),
    "pendcli reproduce --out DIR": (FLOOR, "wall", 4.0),
}


READ_LEDGERS = (
    "import sympy, scipy.special, scipy.integrate, matplotlib.pyplot, mpmath\n"
    "from pendcli.core.ledger import load_ledger\n"
    "from pendcli.papers.registry import ledger_papers\n"
    "for key in ledger_papers(): load_ledger(key)"
)
BUILD_REFERENCES = (
    "import sympy, scipy.special, scipy.integrate, matplotlib.pyplot, mpmath\n"
    "from pendcli.core.ledger import cited_references\n"
    "from pendcli.papers.registry import ledger_papers, paper\n"
    "for key in ledger_papers(): cited_references(paper(key))"
)


def _floor_commands(folder: Path) -> dict[str, list[str]]:
    py = sys.executable
    cli = _pendcli_command()
    return {
        FLOOR: [
            py,
            "-c",
            "import sympy, scipy.special, scipy.integrate, matplotlib.pyplot, mpmath",
        ],
        LEDGERS: [py, "-c", READ_LEDGERS],
        REFERENCES: [py, "-c", BUILD_REFERENCES],
        "pendcli equations --format json": [*cli, "equations", "--format", "json"],
        "pendcli reproduce --out DIR": [
            *cli,
            "reproduce",
            "--out",
            str(folder / "out"),
            "--quiet",
            "--format",
            "json",
        ],
    }


# (label, "cold" / "warm" / "" for a reference) -> (median wall, median CPU)
FloorTimes = dict[tuple[str, str], tuple[float, float]]


def floor_times(runs: int = 3) -> FloorTimes:
    """Median wall and CPU of each floor command over ``runs`` interleaved runs, after one
    warm-up (which fills the warm runs' result cache, a temporary folder)."""
    import tempfile

    with tempfile.TemporaryDirectory(prefix="pendcli-bench-") as tmp:
        folder = Path(tmp)
        warm = {"PENDCLI_CACHE": str(folder / "cache")}
        cases = []
        for label, cmd in _floor_commands(folder).items():
            modes = ("cold", "warm") if label in FLOOR_TARGETS else ("",)
            cases += [((label, mode), cmd, warm if mode == "warm" else None) for mode in modes]
        samples: dict[tuple[str, str], list[tuple[float, float]]] = {c[0]: [] for c in cases}
        for _, cmd, env in cases:
            _timed(cmd, env)
        for _ in range(runs):
            for key, cmd, env in cases:
                samples[key].append(_timed(cmd, env))
    return {
        key: (statistics.median(w for w, _ in v), statistics.median(c for _, c in v))
        for key, v in samples.items()
    }


def floor_ratio(times: FloorTimes, label: str, mode: str) -> float:
    """A floor command's time over its reference's, in the measure its target names."""
    reference, measure, _ = FLOOR_TARGETS[label]
    which = 0 if measure == "wall" else 1
    return times[label, mode][which] / times[reference, ""][which]


def floor_lines(times: FloorTimes, runs: int) -> list[str]:
    """The floor table: each command cold and warm, its ratio in the measure its target names."""
    lines = [
        'Down to the import floor B, the imports the work needs (`python -c "import sympy, '
        'scipy.special, scipy.integrate, matplotlib.pyplot, mpmath"`): median wall and CPU '
        f"(user + system, workers included) of {runs} interleaved runs; cold: "
        "`PENDCLI_CACHE=off`, everything computed; warm: the result cache filled by a first "
        "run (its key: the code, the tables and the library versions).",
        "",
        "| command | cache | wall (s) | CPU (s) | ratio | target |",
        "|---|---|---:|---:|---:|---|",
    ]
    wall, cpu = times[FLOOR, ""]
    lines.append(f"| `{FLOOR.removeprefix('B: ')}` | | {wall:.2f} | {cpu:.2f} | 1 | |")
    for label in PREFIXES:
        if (label, "") in times:
            wall, cpu = times[label, ""]
            share = cpu / times[FLOOR, ""][1]
            lines.append(f"| {label} | | {wall:.2f} | {cpu:.2f} | CPU {share:.2f}x B | |")
    for label, (reference, measure, target) in FLOOR_TARGETS.items():
        name = "B" if reference == FLOOR else "the scipy import"
        for mode in ("cold", "warm"):
            wall, cpu = times[label, mode]
            ratio = floor_ratio(times, label, mode)
            verdict = "met" if ratio <= target else "missed"
            lines.append(
                f"| `{label}` | {mode} | {wall:.2f} | {cpu:.2f} | {measure} {ratio:.2f}x {name} "
                f"| <= {target}x ({verdict}) |"
            )
    return [*lines, ""]


def startup_times(runs: int = 7) -> dict[str, float]:
    """Median wall time of each command over ``runs`` interleaved runs (after one warm-up)."""
    cmds = _commands()
    samples: dict[str, list[float]] = {k: [] for k in cmds}
    for cmd in cmds.values():  # warm the file cache
        _wall(cmd)
    for _ in range(runs):
        for key, cmd in cmds.items():
            samples[key].append(_wall(cmd))
    return {k: statistics.median(v) for k, v in samples.items()}


def import_costs(args: list[str], top: int = 8) -> list[tuple[str, float]]:
    """The ``top`` packages by import time (s, self time of all their modules), ``pendcli ARGS``."""
    code = (
        "import sys; sys.argv = ['pendcli', *sys.argv[1:]]\n"
        "from pendcli.cli.main import run\n"
        "try:\n    run()\nexcept SystemExit:\n    pass\n"
    )
    proc = subprocess.run(
        [sys.executable, "-X", "importtime", "-c", code, *args],
        capture_output=True,
        text=True,
        env=dict(os.environ, NO_COLOR="1"),
        start_new_session=True,  # a Ctrl-C stops this run, which then kills the child
    )
    costs: dict[str, float] = {}
    for line in proc.stderr.splitlines():
        if not line.startswith("import time:"):
            continue
        parts = line[len("import time:") :].split("|")
        if len(parts) != 3 or not parts[1].strip().isdigit():
            continue  # the header line
        # Self time summed per top-level package: each microsecond is counted once, by the
        # package whose code spent it (cumulative times would count typer inside pendcli).
        root = parts[2].strip().split(".")[0]
        costs[root] = costs.get(root, 0.0) + int(parts[0]) / 1e6
    return sorted(costs.items(), key=lambda kv: -kv[1])[:top]


def machine() -> dict[str, str]:
    model = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.lower().startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {
        "cpus (nproc)": str(os.cpu_count()),
        "cpu": model,
        "python": platform.python_version(),
        "platform": platform.platform(terse=True),
    }


def regenerate_tables(quick: bool = False, root: Path | None = None) -> dict[str, list[Point]]:
    """Measure every family, write ``<root>/tradeoff/<family>.csv`` and the date measured
    (all at once, :func:`table_files`)."""
    from pendcli.core.files import write_set

    measured = measure_tables(quick)
    write_set(table_files(measured, root))
    return measured


def measure_tables(quick: bool = False) -> dict[str, list[Point]]:
    """Every family's work-precision points, measured now (nothing written)."""
    from pendcli.run import tradeoff

    return {name: tradeoff.measure_family(name, quick=quick) for name in tradeoff.family_names()}


def table_files(
    measured: dict[str, list[Point]], root: Path | None = None
) -> dict[Path, str | bytes | None]:
    """The files ``measured`` makes: each family's CSV and ``measured.toml`` with today's date."""
    import datetime

    from pendcli.run import tradeoff_engine as tradeoff

    files: dict[Path, str | bytes | None] = {}
    for name, points in measured.items():
        files[tradeoff.table_path(name, root)] = tradeoff.table_text(points)
    today = datetime.date.today().isoformat()
    files[tradeoff.table_path("measured", root).with_suffix(".toml")] = (
        "# When the work-precision tables beside this file were measured; rewritten by "
        "`make bench`\n# (python -m pendcli.bench). `pendcli reproduce --out DIR` names this "
        f'date in its report.\ndate = "{today}"\nby = "make bench"\n'
    )
    for path in files:
        path.parent.mkdir(parents=True, exist_ok=True)
    return files


# ---------------------------------------------------------------------------------------------
# pendcli against its peers, in one process


def _peer_cases(quick: bool) -> list[tuple[str, str, Callable[[], Any], str, Callable[[], Any]]]:
    """(what, pendcli's call, its function, the peer's call, its function): same answers."""
    import math

    import mpmath
    import numpy as np
    from scipy.special import ellipk, jn_zeros

    from pendcli.numerics.besselzeros import bessel_zeros
    from pendcli.numerics.planar import period_ratio
    from pendcli.numerics.spherical import exact_conical
    from pendcli.papers.charbonnier.model import integral

    count = 100 if quick else 1000
    ns = list(range(0, 400 if quick else 4000, 7))
    amplitudes = np.linspace(1.0, 179.0, 1000 if quick else 100_000)
    angles = (math.radians(20.0), math.radians(10.0))

    def mp_beta() -> list[float]:
        with mpmath.workdps(15):
            return [float(mpmath.beta(0.5, (n + 2) / 2)) for n in ns]

    def conical(method: str) -> tuple[float, float]:
        motion = exact_conical(*angles, method=method, rtol=1e-10)
        return motion.k1, motion.precession

    return [
        (
            f"zeros of J_1, first {count}",
            f"bessel_zeros(1, {count})",
            lambda: bessel_zeros(1, count),
            f"scipy.special.jn_zeros(1, {count})",
            lambda: jn_zeros(1, count),
        ),
        (
            f"I_n(π) for {len(ns)} n up to {ns[-1]}",
            "charbonnier integral(n)",
            lambda: [integral(n) for n in ns],
            "mpmath.beta(1/2, (n+2)/2) at 15 digits",
            mp_beta,
        ),
        (
            "conical pendulum k'/k, Ω at (20°, 10°), rtol 1e-10",
            "exact_conical, quadrature",
            lambda: conical("quad"),
            "solve_ivp DOP853 (exact_conical method ode)",
            lambda: conical("ode"),
        ),
        (
            f"planar period T/T0 for {len(amplitudes)} amplitudes (array)",
            "period_ratio(array), AGM",
            lambda: period_ratio(amplitudes),
            "2/π·scipy.special.ellipk(sin²(θ0/2))",
            lambda: 2 / math.pi * ellipk(np.sin(np.radians(amplitudes) / 2) ** 2),
        ),
    ]


def peer_ratios(quick: bool = False) -> list[dict[str, str]]:
    """Time per call of pendcli and of its peer, measured alternately, and their ratio."""
    import numpy as np

    from pendcli.run.tradeoff_engine import time_per_call

    rows = []
    for what, mine, fn, peer, peer_fn in _peer_cases(quick):
        ours, theirs = [], []
        for _ in range(1 if quick else 3):  # interleaved: both see the same machine load
            ours.append(time_per_call(fn, quick))
            theirs.append(time_per_call(peer_fn, quick))
        a = np.ravel(np.asarray(fn(), dtype=float))
        b = np.ravel(np.asarray(peer_fn(), dtype=float))
        diff = float(np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-300)))
        rows.append(
            {
                "what": what,
                "pendcli": f"{mine}: {min(ours):.3g} s",
                "peer": f"{peer}: {min(theirs):.3g} s",
                "speed-up": f"{min(theirs) / min(ours):.3g}x",
                "largest relative difference": f"{diff:.1e}",
            }
        )
    return rows


# ---------------------------------------------------------------------------------------------
# Cost growth: each size in its own process, wall time and peak memory


GROWTH_TIMEOUT, GROWTH_MEMORY = 60.0, 6 * 2**30  # s; bytes of address space


def growth_cases(quick: bool = False) -> list[tuple[str, list[str]]]:
    """(label, pendcli arguments) for each size of the two growth tables."""
    counts = (1000, 10_000) if quick else (1000, 10_000, 100_000, 1_000_000, 10_000_000)
    n_maxes = (100, 300) if quick else (100, 300, 1000, 3000, 10_000)
    cases = [
        (
            f"lecornu zeros --count {c:.0e} -f csv",
            ["lecornu", "zeros", "--count", str(c), "-f", "csv"],
        )
        for c in counts
    ]
    if not quick:
        cases.append(
            (
                "lecornu zeros --count 1e+06 -f json",
                ["lecornu", "zeros", "--count", "1000000", "-f", "json"],
            )
        )
    cases += [
        (
            f"charbonnier table --n-max {n} -f json",
            ["charbonnier", "table", "--n-max", str(n), "-f", "json"],
        )
        for n in n_maxes
    ]
    return cases


def _limit_memory() -> None:  # pragma: no cover - runs in the child
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (GROWTH_MEMORY, GROWTH_MEMORY))


def run_sized(args: list[str], timeout: float = GROWTH_TIMEOUT) -> tuple[str, str]:
    """(wall time, peak resident memory) of ``pendcli ARGS`` run alone, output discarded."""
    env = dict(os.environ, NO_COLOR="1", COLUMNS="100")
    start = time.perf_counter()
    proc = subprocess.Popen(
        [*_pendcli_command(), *args],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        env=env,
        preexec_fn=_limit_memory,
        start_new_session=True,  # a Ctrl-C stops this run, which then kills the child
    )
    try:
        return _sized_result(proc, start, timeout)
    except BaseException:
        proc.kill()
        proc.wait()
        raise


def _sized_result(proc: subprocess.Popen[bytes], start: float, timeout: float) -> tuple[str, str]:
    status, usage = 0, None
    while True:
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid:
            break
        if time.perf_counter() - start > timeout:
            proc.kill()
            os.wait4(proc.pid, 0)
            proc.returncode = -9
            return f"> {timeout:.0f} (stopped)", "n/a"
        time.sleep(0.01)
    proc.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - start
    peak = f"{usage.ru_maxrss / 1024:.0f}"  # KiB on Linux
    if proc.returncode != 0:
        return f"{wall:.2f} (exit {proc.returncode})", f"{peak} (limit {GROWTH_MEMORY >> 30} GB)"
    return f"{wall:.2f}", peak


def growth_rows(quick: bool = False) -> list[dict[str, str]]:
    rows = []
    for label, args in growth_cases(quick):
        wall, peak = run_sized(args, 10.0 if quick else GROWTH_TIMEOUT)
        rows.append({"command": f"pendcli {label}", "wall (s)": wall, "peak memory (MB)": peak})
    return rows


def _startup_lines(times: dict[str, float], runs: int) -> list[str]:
    """The start-up table: each command's median and its ratio to the bare imports."""
    help_ratio = times["pendcli --help"] / times["import typer"]
    repro_ratio = (
        times["pendcli reproduce --format json"] / times["import scipy.special, scipy.integrate"]
    )
    return [
        "### Start-up and speed against accuracy (generated by `python -m pendcli.bench`)",
        "",
        f"Median wall time of {runs} interleaved runs of a fresh interpreter, measured in the "
        "same run:",
        "",
        "| command | median (s) | ratio | target |",
        "|---|---:|---:|---|",
        f'| `python -c "import typer"` | {times["import typer"]:.3f} | 1 | |',
        f"| `pendcli --help` | {times['pendcli --help']:.3f} | {help_ratio:.2f} | "
        f"<= {HELP_TARGET} ({'met' if help_ratio <= HELP_TARGET else 'missed'}) |",
        '| `python -c "import scipy.special, scipy.integrate"` | '
        f"{times['import scipy.special, scipy.integrate']:.3f} | 1 | |",
        f"| `pendcli reproduce --format json` | {times['pendcli reproduce --format json']:.3f} | "
        f"{repro_ratio:.2f} | <= {REPRODUCE_TARGET} "
        f"({'met' if repro_ratio <= REPRODUCE_TARGET else 'missed'}) |",
        "",
    ]


def _choice_cell(name: str, tol: float, points: list[Point]) -> str:
    from pendcli.core.errors import PendcliError
    from pendcli.run.tradeoff_engine import choose

    try:
        p = choose(name, tol, points)
    except PendcliError:  # out of reach: say so in the cell
        return "out of reach"
    return f"{p.method} ({p.setting}), {p.seconds:.1e} s"


def _choice_lines(tables: dict[str, list[Point]]) -> list[str]:
    """The cheapest measured method of each family at three tolerances."""
    lines = [
        "Work-precision tables (`tables/tradeoff/<family>.csv`, worst relative error over "
        "each family's problems against an independent reference; `pendcli tradeoff` "
        "measures them again). Cheapest measured method per tolerance:",
        "",
        "| family | tol 1e-6 | tol 1e-10 | tol 1e-14 |",
        "|---|---|---|---|",
    ]
    for name, points in tables.items():
        cells = [_choice_cell(name, tol, points) for tol in (1e-6, 1e-10, 1e-14)]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return [*lines, ""]


def _table(rows: list[dict[str, str]]) -> list[str]:
    if not rows:
        return []
    keys = list(rows[0])
    lines = ["| " + " | ".join(keys) + " |", "|" + "---|" * len(keys)]
    lines += ["| " + " | ".join(str(r[k]) for k in keys) + " |" for r in rows]
    return [*lines, ""]


def section(
    times: dict[str, float],
    costs: dict[str, list[tuple[str, float]]],
    tables: dict[str, list[Point]],
    runs: int,
    peers: list[dict[str, str]] | None = None,
    growth: list[dict[str, str]] | None = None,
    floor: FloorTimes | None = None,
    floor_runs: int = 3,
) -> str:
    """The README section as Markdown (no timestamps: the same measurements give the same text)."""
    lines = _startup_lines(times, runs)
    if floor:
        lines += floor_lines(floor, floor_runs)
    lines += ["Largest imports (`python -X importtime`, self time summed per package):", ""]
    for label, items in costs.items():
        lines.append(f"- `pendcli {label}`: " + ", ".join(f"{n} {t:.3f} s" for n, t in items))
    lines += ["", "Machine: " + "; ".join(f"{k} {v}" for k, v in machine().items()) + ".", ""]
    if peers:
        lines += [
            "Against the peers, in the same process, alternately (best of the batches; the "
            "largest relative difference compares the two answers):",
            "",
            *_table(peers),
        ]
    if growth:
        lines += [
            "Cost growth: each command alone in a fresh process, output discarded; wall time "
            f"and peak resident memory (stopped after {GROWTH_TIMEOUT:.0f} s or "
            f"{GROWTH_MEMORY >> 30} GB of address space):",
            "",
            *_table(growth),
        ]
    if tables:
        lines += _choice_lines(tables)
    return "\n".join(lines)


def with_section(readme: Path, text: str) -> str | None:
    """The README with ``text`` between the markers (None if the file or markers are absent)."""
    if not readme.exists():
        return None
    return spliced(readme.read_text(encoding="utf-8"), text)


def spliced(content: str, text: str) -> str | None:
    """``content`` with ``text`` between the markers (None if they are absent)."""
    if START not in content or END not in content:
        return None
    head, rest = content.split(START, 1)
    _old, tail = rest.split(END, 1)
    return f"{head}{START}\n{text}\n{END}{tail}"


def write_section(readme: Path, text: str) -> bool:
    """Replace the text between the markers; False (nothing written) if they are absent."""
    new = with_section(readme, text)
    if new is None:
        return False
    from pendcli.core.files import atomic_write

    atomic_write(readme, new)
    return True


def run(
    runs: int = 7,
    quick: bool = False,
    tables: bool = True,
    root: Path | None = None,
    growth: bool | None = None,
    readme: Path | None = None,
    floor: bool | None = None,
    floor_runs: int = 3,
    summary: Path | None = None,
    checkout: bool | None = None,
) -> str:
    """Every measurement, one after the other (never two at once), as the README section.

    The measured tables, their date, (``readme``, when it has the markers) docs/benchmarks.md
    and (``summary``) the README's timings block are written together at the end
    (:func:`pendcli.core.files.write_set`): a run stopped before leaves all of them as they
    were. The cost-growth table (minutes) is left out of a ``quick`` run unless ``growth``
    asks, and so are the floor table (minutes: every equation checked ``floor_runs`` + 1
    times) unless ``floor`` asks, and the suite and install timings unless ``checkout`` asks.
    """
    from pendcli import bench_summary

    growth = not quick if growth is None else growth
    floor = not quick if floor is None else floor
    checkout = not quick if checkout is None else checkout
    load_before = os.getloadavg()[0]
    times = startup_times(runs)
    floored = floor_times(floor_runs) if floor else None
    root_dir = bench_summary.checkout_root() if checkout else None
    suite = bench_summary.suite_time(root_dir) if root_dir else None
    install = bench_summary.install_time(root_dir) if root_dir else None
    costs = {
        "--help": import_costs(["--help"]),
        "reproduce --format json": import_costs(["reproduce", "--format", "json", "--quiet"]),
    }
    peers = peer_ratios(quick)
    sized = growth_rows(quick) if growth else []
    measured = measure_tables(quick) if tables else committed_tables(root)
    load = (load_before, os.getloadavg()[0])
    text = section(times, costs, measured, runs, peers, sized, floored, floor_runs)
    heads = headlines(times, floored, suite, install)
    tag = bench_summary.measurement_tag([text, *map(str, heads)])
    text = _tagged(text, tag, load, heads)
    files: dict[Path, str | bytes | None] = {**table_files(measured, root)} if tables else {}
    block = bench_summary.summary_lines(heads, tag, load)
    splices = [
        (readme, lambda old: spliced(old, text)),
        (summary, lambda old: bench_summary.with_summary(old, block)),
    ]
    write_results(files, splices)
    return text


Splice = tuple[Path | None, Callable[[str], str | None]]


def write_results(files: dict[Path, str | bytes | None], splices: list[Splice]) -> None:
    """Write ``files`` (the measured tables) and each README of ``splices`` ((path, its new
    text from the old or None to leave it)) as one set (:func:`pendcli.core.files.write_set`).

    Each README is read here, at the end of the run, and must still hold what was read when
    the set is renamed: an edit made in between is refused in one line, nothing written.
    """
    from pendcli.core.files import content_digest, write_set

    read: dict[Path, str | None] = {}
    for path, splice in splices:
        if path is None or not path.is_file():
            continue
        pending = files.get(path)  # a second splice of the same file builds on the first
        old = pending if isinstance(pending, str) else path.read_text(encoding="utf-8")
        new = splice(old)
        if new is not None:
            read.setdefault(path, content_digest(old))
            files[path] = new
    write_set(files, read)


def _tagged(text: str, tag: str, load: tuple[float, float], heads: list[Any]) -> str:
    """The section with its measurement tag, the machine's load, and the suite and install."""
    from pendcli import bench_summary

    extra = [h for h in heads if h.what.startswith(("`make test`", "install"))]
    lines = [
        f"Measurement `{tag}` (the timings block of docs/install.md carries the same tag); "
        f"one-minute load average {load[0]:.2f} at the start, {load[1]:.2f} at the end "
        "(2 cores: a load above 1 slows every figure).",
        "",
    ]
    if extra:
        lines += [*bench_summary.summary_lines(extra, tag)[2:], ""]
    head, _, rest = text.partition("\n\n")
    return "\n".join([head, "", *lines, rest])


def headlines(
    times: dict[str, float],
    floor: FloorTimes | None,
    suite: tuple[float, float] | None,
    install: tuple[float, float] | None,
) -> list[Any]:
    """The figures the README states, each with its ratio and target, from this run."""
    from pendcli.bench_summary import INSTALL_TARGET, SUITE_TARGET, Headline

    def met(value: float, target: float, unit: str = "x") -> str:
        return f"<= {target:g}{unit} ({'met' if value <= target else 'missed'})"

    help_r = times["pendcli --help"] / times["import typer"]
    scipy = times["import scipy.special, scipy.integrate"]
    repro_r = times["pendcli reproduce --format json"] / scipy
    heads = [
        Headline("`pendcli --help`", times["pendcli --help"], None,
                 f"wall {help_r:.2f}x `import typer`", met(help_r, HELP_TARGET)),
        Headline("`pendcli reproduce --format json`", times["pendcli reproduce --format json"],
                 None, f"wall {repro_r:.2f}x the scipy import", met(repro_r, REPRODUCE_TARGET)),
    ]  # fmt: skip
    if floor is not None and (REFERENCES, "") in floor:
        # what a cold `equations` pays besides its verdicts, against its 2x target
        wall, cpu = floor[REFERENCES, ""]
        share = cpu / floor[FLOOR, ""][1]
        heads.append(Headline(REFERENCES, wall, cpu, f"CPU {share:.2f}x B", ""))
    for label, (reference, measure, target) in FLOOR_TARGETS.items() if floor else ():
        assert floor is not None
        if reference != FLOOR:
            continue
        for mode in ("cold", "warm"):
            wall, cpu = floor[label, mode]
            ratio = floor_ratio(floor, label, mode)
            heads.append(Headline(f"`{label}`, {mode}", wall, cpu,
                                  f"{measure} {ratio:.2f}x B", met(ratio, target)))  # fmt: skip
    if suite is not None:
        what = "`make test` (the fast suite)"
        heads.append(Headline(what, *suite, "", met(suite[0], SUITE_TARGET, " s wall")))
    if install is not None:
        what = "install from nothing (`make reproduce`'s venv)"
        heads.append(Headline(what, *install, "", met(install[0], INSTALL_TARGET, " s wall")))
    return heads


def committed_tables(root: Path | None = None) -> dict[str, list[Point]]:
    """The work-precision tables as committed (``--no-tables``: choices from them, unchanged)."""
    from pendcli.run import tradeoff, tradeoff_engine

    paths = {name: tradeoff_engine.table_path(name, root) for name in tradeoff.family_names()}
    return {name: tradeoff_engine.read_table(p) for name, p in paths.items() if p.is_file()}


def _has_timings_block(path: Path) -> bool:
    from pendcli.bench_summary import with_summary

    try:
        return with_summary(path.read_text("utf-8"), []) is not None
    except (OSError, UnicodeDecodeError):
        return False


def _positive(text: str) -> int:
    """A count of runs: a whole number, 1 or more (argparse prints the one-line error)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number; expected >= 1") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{value} is out of range; expected >= 1")
    return value


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pendcli.bench", description=__doc__)
    parser.add_argument("--write", type=Path, help="README to update between the markers")
    parser.add_argument("--runs", type=_positive, default=7, help="runs per command (median)")
    parser.add_argument("--quick", action="store_true", help="tiny configuration (smoke test)")
    parser.add_argument(
        "--no-tables",
        action="store_true",
        help="keep tables/tradeoff as committed (the README's choices are read from them)",
    )
    parser.add_argument("--tables-root", type=Path, help="tables folder (default: the package's)")
    parser.add_argument("--no-growth", action="store_true", help="skip the cost-growth table")
    parser.add_argument("--no-floor", action="store_true", help="skip the import-floor table")
    parser.add_argument(
        "--floor-runs", type=_positive, default=3, help="runs per import-floor command (median)"
    )
    parser.add_argument("--summary", type=Path, help="README whose timings block to update")
    parser.add_argument(
        "--no-checkout", action="store_true", help="skip timing the test suite and the install"
    )
    args = parser.parse_args(argv)
    if args.summary is not None and not _has_timings_block(args.summary):
        from pendcli.bench_summary import SUMMARY_END, SUMMARY_START

        parser.error(
            f"--summary {args.summary}: no such file, or no {SUMMARY_START} ... {SUMMARY_END} "
            "markers; give the README that has them"
        )
    growth = False if args.no_growth else None
    floor = False if args.no_floor else None
    text = run(
        args.runs,
        args.quick,
        not args.no_tables,
        args.tables_root,
        growth,
        args.write,
        floor,
        args.floor_runs,
        args.summary,
        False if args.no_checkout else None,
    )
    if args.write is not None and with_section(args.write, text) is not None:
        print(f"bench: updated {args.write}", file=sys.stderr)
    else:
        if args.write is not None:
            print(
                f"bench: {args.write} has no {START} ... {END} markers; printing the section "
                "instead (add the markers to let bench update it)",
                file=sys.stderr,
            )
        print(text)
    return 0


if __name__ == "__main__":
    from pendcli.core.interrupts import run_entry

    sys.exit(run_entry(main, "python -m pendcli.bench"))
