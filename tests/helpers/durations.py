"""List the tests not marked ``slow`` that take over 2 s, from ``--timings-file``.

    python tests/helpers/durations.py TIMINGS [--limit 2] [--recheck 2] [--wall] [--top 20] [--slow]

A test's time is the sum of its phases (setup, call, teardown); a module fixture's work counts
for the first test that asks for it, as it does in a run. By default the time is CPU seconds
(the test process and the children it reaped); ``--wall`` judges wall seconds instead, for a
quiet machine. Exit status 1 when a test not marked ``slow`` is over the limit (each named with
its time), else 0. Nothing here limits a test while it runs. ``--slow`` lists the slow tests'
files and tests instead (where `make test-slow` spends).

CPU seconds still move with the machine's state: the same work costs 1.5-3x the CPU on two
cores crowded by other processes (caches and the shared core's pipeline), and under xdist the
test that first asks for a shared cache (a committed ledger, a reference) pays for it.
``--recheck N`` makes the verdict robust to both: each test over the limit in the run is run
again N times, alone in a fresh process after the suite has finished, each time after its
file's cheapest other test (untimed) has warmed what the file shares; a test is over only if
it is over in the run and in every rerun (its least CPU seconds are reported).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path


def read(path: Path) -> list[dict[str, object]]:
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


def per_test(lines: list[dict[str, object]], key: str) -> dict[str, tuple[float, bool]]:
    """Each test's seconds (summed over its phases) and whether it is marked slow."""
    seconds: dict[str, float] = defaultdict(float)
    slow: dict[str, bool] = {}
    for line in lines:
        if line["phase"] == "collect":
            continue
        test = str(line["test"])
        seconds[test] += float(line[key])  # type: ignore[arg-type]
        slow[test] = bool(line["slow"])
    return {test: (seconds[test], slow[test]) for test in seconds}


def per_file(tests: dict[str, tuple[float, bool]]) -> dict[str, float]:
    files: dict[str, float] = defaultdict(float)
    for test, (seconds, _) in tests.items():
        files[test.split("::")[0]] += seconds
    return files


def show(kind: str, tests: list[tuple[float, str]], key: str, top: int) -> None:
    """The files and the tests of ``kind`` (fast or slow) that took longest."""
    print(f"files by {key} seconds ({kind} tests only):")
    files = per_file({t: (s, False) for s, t in tests})
    for name, seconds in sorted(files.items(), key=lambda kv: -kv[1])[:top]:
        print(f"  {seconds:7.2f}  {name}")
    print(f"slowest {kind} tests by {key} seconds:")
    for seconds, test in sorted(tests, reverse=True)[:top]:
        print(f"  {seconds:7.2f}  {test}")


def warm_up_test(test: str, tests: dict[str, tuple[float, bool]]) -> str | None:
    """The cheapest other fast test of ``test``'s file in the run (its family's first), or
    None: it runs untimed before the rerun, so the rerun pays no more of the file's shared
    work than the run did."""
    file, family = test.split("::")[0], test.partition("[")[0]
    siblings = [
        (not other.startswith(family), seconds, other)
        for other, (seconds, slow) in tests.items()
        if other != test and not slow and other.split("::")[0] == file
    ]
    return min(siblings)[2] if siblings else None


def rerun_seconds(test: str, warm_up: str | None, key: str) -> float:
    """``test``'s seconds (``key``: cpu or wall) run alone in a fresh pytest process; a rerun
    that does not pass (a fixture missing without xdist, say) is no measurement: infinite."""
    with tempfile.TemporaryDirectory() as folder:
        timings = Path(folder) / "timings.jsonl"
        command = [sys.executable, "-m", "pytest", "-q", "-p", "no:xdist"]
        command += ["--timings-file", str(timings), *([warm_up] if warm_up else []), test]
        env = {**os.environ, "PENDCLI_JOBS": "1"}
        done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, check=False)
        if done.returncode != 0 or not timings.exists():
            return float("inf")
        return per_test(read(timings), key).get(test, (float("inf"), False))[0]


def confirmed(
    over: list[tuple[float, str]], tests: dict[str, tuple[float, bool]], key: str, runs: int
) -> list[tuple[float, str]]:
    """Of the tests over the limit in the run, those over it in each of ``runs`` reruns too,
    with their least seconds."""
    out = []
    for seconds, test in over:
        least = min([seconds, *(rerun_seconds(test, warm_up_test(test, tests), key)
                                for _ in range(runs))])  # fmt: skip
        print(f"  rechecked {test}: {seconds:.2f} s in the run, least {least:.2f} s")
        out.append((least, test))
    return out


def timeline(lines: list[dict[str, object]]) -> list[str]:
    """Per worker (lines that name one): its CPU and wall seconds in tests, and when its last
    phase ended, in seconds after the first worker's start-up began; the gap between the
    workers' last ends is the time one of them sat idle while the other finished."""
    timed = [line for line in lines if "worker" in line and "end" in line]
    if not timed:
        return []
    begin = min(float(ln["end"]) - float(ln["wall"]) for ln in timed)  # type: ignore[arg-type]
    ends: dict[str, float] = defaultdict(float)
    cpu: dict[str, float] = defaultdict(float)
    wall: dict[str, float] = defaultdict(float)
    for line in timed:
        worker = str(line["worker"])
        ends[worker] = max(ends[worker], float(line["end"]) - begin)  # type: ignore[arg-type]
        if line["phase"] != "collect":
            cpu[worker] += float(line["cpu"])  # type: ignore[arg-type]
            wall[worker] += float(line["wall"])  # type: ignore[arg-type]
    last = max(ends.values())
    return [
        f"  {worker}: tests {cpu[worker]:.1f} s CPU, {wall[worker]:.1f} s wall; done at "
        f"{ends[worker]:.1f} s, idle {last - ends[worker]:.1f} s before the last worker"
        for worker in sorted(ends)
    ]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("timings", type=Path)
    parser.add_argument("--limit", type=float, default=2.0, help="seconds (default 2)")
    parser.add_argument("--wall", action="store_true", help="judge wall, not CPU, seconds")
    parser.add_argument("--top", type=int, default=15, help="files and tests to show")
    parser.add_argument(
        "--slow", action="store_true", help="show the tests marked slow (no limit applies)"
    )
    parser.add_argument(
        "--recheck", type=int, default=0, help="reruns of each test over the limit (default 0)"
    )
    args = parser.parse_args(argv)
    lines = read(args.timings)
    key = "wall" if args.wall else "cpu"
    tests = per_test(lines, key)
    loads = [float(line["load"]) for line in lines]  # type: ignore[arg-type]
    fast = [(s, t) for t, (s, slow) in tests.items() if not slow]
    slow = [(s, t) for t, (s, slow) in tests.items() if slow]
    fast_sum = sum(s for s, _ in fast)
    print(
        f"{len(tests)} tests, {len(slow)} marked slow; {key} seconds: fast {fast_sum:.1f}, "
        f"slow {sum(s for s, _ in slow):.1f}; 1-min load {min(loads, default=0):.1f} to "
        f"{max(loads, default=0):.1f}"
    )
    for line in lines:
        if line["phase"] == "collect":
            print(f"  {line['test']}: start-up and collection {line['cpu']} s CPU, ", end="")
            print(f"{line['wall']} s wall")
    for worker_line in timeline(lines):
        print(worker_line)
    for kind, chosen in (("slow", slow),) if args.slow else (("fast", fast),):
        show(kind, chosen, key, args.top)
    over = sorted(((s, t) for s, t in fast if s > args.limit), reverse=True)
    if args.recheck and over:
        rechecked = confirmed(over, tests, key, args.recheck)
        over = [(s, t) for s, t in rechecked if s > args.limit]
    for seconds, test in over:
        print(f"over {args.limit:g} s and not marked slow: {test} ({seconds:.2f} s {key})")
    if not over:
        print(f"no test over {args.limit:g} s {key} that is not marked slow")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
