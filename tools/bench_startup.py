"""``make bench``: how long pendcli takes to start and to judge, against what it imports.

Start-up: ``pendcli --help`` and ``pendcli reproduce --format json`` against the bare imports
they need (:func:`startup_times`), and the modules that cost most at import
(:func:`import_costs`). The floor: ``pendcli equations`` and ``reproduce --out`` cold and warm
against the import floor B, and what a cold ``equations`` pays before its verdicts
(:func:`floor_times`). The headlines the README states come from these (:func:`headlines`).
"""

from __future__ import annotations

import os
import platform
import shutil
import statistics
import subprocess
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    pass

HELP_TARGET, REPRODUCE_TARGET = 1.3, 1.8


def pendcli_command() -> list[str]:
    script = Path(sys.executable).with_name("pendcli")
    if script.exists():
        return [str(script)]
    found = shutil.which("pendcli")
    return [found] if found else [sys.executable, "-m", "pendcli"]


def _commands() -> dict[str, list[str]]:
    py = sys.executable
    cli = pendcli_command()
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
    """(wall, CPU) seconds of one run (:func:`tools.bench_summary.timed_process`). The
    result cache is off unless ``env`` names one."""
    from tools.bench_summary import timed_process

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
# read and its printed formulas parsed. Its ratio to B says how much of the target is left
# for the checks themselves.
LEDGERS = "B, then the three ledgers read (every printed formula parsed)"


# ... then every stored derivation read back through the closed grammar: the references'
# exact work, derived by `make regen` and judged from on a cold run instead of built again.
DERIVATIONS = "B, the ledgers read, then every stored derivation read back"


# the rows shown as a share of B's CPU: what a cold `equations` run pays besides its verdicts
PREFIXES = (LEDGERS, DERIVATIONS)


FLOOR_TARGETS: dict[str, tuple[str, str, float]] = {
    "pendcli equations --format json": (FLOOR, "CPU", 4.0),
    "pendcli reproduce --out DIR": (FLOOR, "wall", 4.0),
}


READ_LEDGERS = (
    "import sympy, scipy.special, scipy.integrate, matplotlib.pyplot, mpmath\n"
    "from pendcli.data.ledger import load_ledger\n"
    "from pendcli.papers.registry import ledger_papers\n"
    "for key in ledger_papers(): load_ledger(key)"
)


READ_DERIVATIONS = (
    "import sympy, scipy.special, scipy.integrate, matplotlib.pyplot, mpmath\n"
    "from pendcli.data.ledger import load_ledger\n"
    "from pendcli.verify.derivation_store import row_record, stored_nodes, stored_rows\n"
    "from pendcli.verify.ledger_references import paper_digest\n"
    "from pendcli.papers.registry import ledger_papers\n"
    "for key in ledger_papers():\n"
    "    load_ledger(key)\n"
    "    for name, (_, record) in stored_rows(key, paper_digest(key)).items():\n"
    "        if 'live' not in record: row_record(name, record, stored_nodes(key))"
)


def _floor_commands(folder: Path) -> dict[str, list[str]]:
    py = sys.executable
    cli = pendcli_command()
    return {
        FLOOR: [
            py,
            "-c",
            "import sympy, scipy.special, scipy.integrate, matplotlib.pyplot, mpmath",
        ],
        LEDGERS: [py, "-c", READ_LEDGERS],
        DERIVATIONS: [py, "-c", READ_DERIVATIONS],
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


def startup_lines(times: dict[str, float], runs: int) -> list[str]:
    """The start-up table: each command's median and its ratio to the bare imports."""
    help_ratio = times["pendcli --help"] / times["import typer"]
    repro_ratio = (
        times["pendcli reproduce --format json"] / times["import scipy.special, scipy.integrate"]
    )
    return [
        "### Start-up and speed against accuracy (generated by `python -m tools.bench`)",
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


def headlines(
    times: dict[str, float],
    floor: FloorTimes | None,
    suite: tuple[float, float] | None,
    install: tuple[float, float] | None,
) -> list[Any]:
    """The figures the README states, each with its ratio and target, from this run."""
    from tools.bench_summary import INSTALL_TARGET, SUITE_TARGET, Headline

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
    if floor is not None and (DERIVATIONS, "") in floor:
        # what a cold `equations` pays besides its verdicts, against its target
        wall, cpu = floor[DERIVATIONS, ""]
        share = cpu / floor[FLOOR, ""][1]
        heads.append(Headline(DERIVATIONS, wall, cpu, f"CPU {share:.2f}x B", ""))
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
