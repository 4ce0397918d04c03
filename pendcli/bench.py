"""Benchmarks: start-up times and the published work-precision tables (issue 6).

``python -m pendcli.bench --write README.md`` measures, in one run and on this machine,

* ``pendcli --help`` against ``python -c "import typer"`` (target: within 1.3x),
* ``pendcli reproduce --format json`` against ``python -c "import scipy.special,
  scipy.integrate"`` (target: within 3x),

each as the median wall time of several interleaved runs of a fresh interpreter, and the
modules that cost most at import (``python -X importtime``); it regenerates the work-precision
tables ``tables/tradeoff/<family>.csv`` (:mod:`pendcli.tradeoff`) and rewrites the README
section between ``<!-- bench:start -->`` and ``<!-- bench:end -->`` (or prints it when the
markers are absent).  These are benchmarks, not tests: nothing here fails on a slow machine.
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
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from pendcli.tradeoff import Point

START, END = "<!-- bench:start -->", "<!-- bench:end -->"
HELP_TARGET, REPRODUCE_TARGET = 1.3, 3.0


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
    env = dict(os.environ, NO_COLOR="1", COLUMNS="100")
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env, check=True)
    return time.perf_counter() - start


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
    """Measure every family and write ``<root>/tradeoff/<family>.csv``."""
    from pendcli import tradeoff

    out = {}
    for name in tradeoff.family_names():
        points = tradeoff.measure_family(name, quick=quick)
        tradeoff.write_table(points, tradeoff.table_path(name, root))
        out[name] = points
    return out


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
    from pendcli.tradeoff import choose

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


def section(
    times: dict[str, float],
    costs: dict[str, list[tuple[str, float]]],
    tables: dict[str, list[Point]],
    runs: int,
) -> str:
    """The README section as Markdown (no timestamps: the same measurements give the same text)."""
    lines = _startup_lines(times, runs)
    lines += ["Largest imports (`python -X importtime`, self time summed per package):", ""]
    for label, items in costs.items():
        lines.append(f"- `pendcli {label}`: " + ", ".join(f"{n} {t:.3f} s" for n, t in items))
    lines += ["", "Machine: " + "; ".join(f"{k} {v}" for k, v in machine().items()) + ".", ""]
    if tables:
        lines += _choice_lines(tables)
    return "\n".join(lines)


def write_section(readme: Path, text: str) -> bool:
    """Replace the text between the markers; False (nothing written) if they are absent."""
    if not readme.exists():
        return False
    content = readme.read_text(encoding="utf-8")
    if START not in content or END not in content:
        return False
    head, rest = content.split(START, 1)
    _old, tail = rest.split(END, 1)
    readme.write_text(f"{head}{START}\n{text}\n{END}{tail}", encoding="utf-8")
    return True


def run(runs: int = 7, quick: bool = False, tables: bool = True, root: Path | None = None) -> str:
    times = startup_times(runs)
    costs = {
        "--help": import_costs(["--help"]),
        "reproduce --format json": import_costs(["reproduce", "--format", "json", "--quiet"]),
    }
    measured = regenerate_tables(quick=quick, root=root) if tables else {}
    return section(times, costs, measured, runs)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pendcli.bench", description=__doc__)
    parser.add_argument("--write", type=Path, help="README to update between the markers")
    parser.add_argument("--runs", type=int, default=7, help="runs per command (median)")
    parser.add_argument("--quick", action="store_true", help="tiny configuration (smoke test)")
    parser.add_argument(
        "--no-tables", action="store_true", help="do not regenerate tables/tradeoff"
    )
    parser.add_argument("--tables-root", type=Path, help="tables folder (default: the package's)")
    args = parser.parse_args(argv)
    text = run(args.runs, args.quick, not args.no_tables, args.tables_root)
    if args.write is not None and write_section(args.write, text):
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
    sys.exit(main())
