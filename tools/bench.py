"""Benchmarks: start-up times and the published work-precision tables.

``python -m tools.bench --write docs/benchmarks.md`` measures, in one run and on this machine,

* ``pendcli --help`` against ``python -c "import typer"`` (target: within 1.3x),
* ``pendcli reproduce --format json`` against ``python -c "import scipy.special,
  scipy.integrate"`` (target: within 1.8x),

each as the median wall time of several interleaved runs of a fresh interpreter (the
result cache off); against the import floor B (``python -c "import sympy, scipy.special,
scipy.integrate, matplotlib.pyplot, mpmath"``), cold (``PENDCLI_CACHE=off``) and warm (the
result cache filled by the warm-up run), the CPU and wall time of ``pendcli equations
--format json`` (target: CPU within 4x B) and ``pendcli reproduce --out DIR`` (wall within
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

This module runs them all and writes the results; the start-up and floor timings are
:mod:`tools.bench_startup`, the peers and the growth :mod:`tools.bench_scaling`, the suite and
install timings :mod:`tools.bench_summary`.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from tools.bench_scaling import GROWTH_MEMORY, GROWTH_TIMEOUT, growth_rows, peer_ratios
from tools.bench_startup import (
    FloorTimes,
    floor_lines,
    floor_times,
    headlines,
    import_costs,
    machine,
    startup_lines,
    startup_times,
)

if TYPE_CHECKING:
    from pendcli.run.tradeoff_engine import Point

START, END = "<!-- bench:start -->", "<!-- bench:end -->"


def regenerate_tables(quick: bool = False, root: Path | None = None) -> dict[str, list[Point]]:
    """Measure every family, write ``<root>/tradeoff/<family>.csv`` and the date measured
    (all at once, :func:`table_files`)."""
    from pendcli.base.files import write_set

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
        "`make bench`\n# (python -m tools.bench). `pendcli reproduce --out DIR` names this "
        f'date in its report.\ndate = "{today}"\nby = "make bench"\n'
    )
    for path in files:
        path.parent.mkdir(parents=True, exist_ok=True)
    return files


def _choice_cell(name: str, tol: float, points: list[Point]) -> str:
    from pendcli.base.errors import PendcliError
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
    lines = startup_lines(times, runs)
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
    from pendcli.base.files import atomic_write

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
    (:func:`pendcli.base.files.write_set`): a run stopped before leaves all of them as they
    were. The cost-growth table (minutes) is left out of a ``quick`` run unless ``growth``
    asks, and so are the floor table (minutes: every equation checked ``floor_runs`` + 1
    times) unless ``floor`` asks, and the suite and install timings unless ``checkout`` asks.
    """
    from tools import bench_summary

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
    text from the old or None to leave it)) as one set (:func:`pendcli.base.files.write_set`).

    Each README is read here, at the end of the run, and must still hold what was read when
    the set is renamed: an edit made in between is refused in one line, nothing written.
    """
    from pendcli.base.files import content_digest, write_set

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
    from tools import bench_summary

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


def committed_tables(root: Path | None = None) -> dict[str, list[Point]]:
    """The work-precision tables as committed (``--no-tables``: choices from them, unchanged)."""
    from pendcli.run import tradeoff, tradeoff_engine

    paths = {name: tradeoff_engine.table_path(name, root) for name in tradeoff.family_names()}
    return {name: tradeoff_engine.read_points(p) for name, p in paths.items() if p.is_file()}


def _has_timings_block(path: Path) -> bool:
    from tools.bench_summary import with_summary

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
    parser = argparse.ArgumentParser(prog="python -m tools.bench", description=__doc__)
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
        from tools.bench_summary import SUMMARY_END, SUMMARY_START

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
    from pendcli.base.interrupts import run_entry

    sys.exit(run_entry(main, "python -m tools.bench"))
