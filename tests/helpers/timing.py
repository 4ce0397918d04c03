"""Per-test timings for the 2 s rule, without any limit inside a test.

``pytest --timings-file PATH`` writes one JSON line per test phase (setup, call, teardown):
its node id, whether it is marked ``slow``, wall seconds, and CPU seconds of the test process
plus the children it reaped (a test that runs the CLI in a subprocess spends its time there).
``python tests/helpers/durations.py PATH`` then lists the tests not marked ``slow`` over 2 s,
and each worker's timeline (a line carries its worker and the epoch second its phase ended).
CPU seconds hardly move with the machine's load, wall seconds do; the list can use either.

The hooks are imported by conftest.py; under xdist they run in each worker, which appends its
own lines (one ``write`` of one line each, so workers do not interleave within a line).
"""

from __future__ import annotations

import json
import os
import resource
import time
from collections.abc import Iterator

import pytest


def _cpu_seconds() -> float:
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--timings-file",
        default=None,
        type=os.path.abspath,  # a test may change the working directory
        help="append each test phase's wall and CPU seconds (JSON lines) to this file",
    )


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_setup(item: pytest.Item) -> Iterator[None]:
    yield from _timed(item, "setup")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_call(item: pytest.Item) -> Iterator[None]:
    yield from _timed(item, "call")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_teardown(item: pytest.Item) -> Iterator[None]:
    yield from _timed(item, "teardown")


def pytest_collection_finish(session: pytest.Session) -> None:
    """One line for this process's start-up and collection: CPU since the process began
    (interpreter, imports of every test module and what they import) and its wall time."""
    path = session.config.getoption("--timings-file")
    if path is not None:
        worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
        wall = time.time() - _process_start()
        _append(
            path,
            {
                "test": f"<collection {worker}>",
                "phase": "collect",
                "slow": False,
                "wall": round(wall, 4),
                "cpu": round(time.process_time(), 4),
                "load": round(os.getloadavg()[0], 2),
                "worker": worker,
                "end": round(time.time(), 3),
            },
        )


def _process_start() -> float:
    """When this process started, from /proc (Linux); now elsewhere."""
    try:
        with open("/proc/self/stat") as stat:
            ticks = int(stat.read().rsplit(")", 1)[1].split()[19])
        with open("/proc/uptime") as uptime:
            booted = time.time() - float(uptime.read().split()[0])
        return booted + ticks / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return time.time()


def _timed(item: pytest.Item, phase: str) -> Iterator[None]:
    path = item.config.getoption("--timings-file")
    if path is None:
        yield
        return
    wall, cpu = time.perf_counter(), _cpu_seconds()
    yield
    line = {
        "test": item.nodeid,
        "phase": phase,
        "slow": item.get_closest_marker("slow") is not None,
        "wall": round(time.perf_counter() - wall, 4),
        "cpu": round(_cpu_seconds() - cpu, 4),
        "load": round(os.getloadavg()[0], 2),
        # the worker's timeline: which worker ran the phase and when it ended (epoch seconds)
        "worker": os.environ.get("PYTEST_XDIST_WORKER", "main"),
        "end": round(time.time(), 3),
    }
    _append(path, line)


def _append(path: str, line: dict[str, object]) -> None:
    fd = os.open(path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
    try:
        os.write(fd, (json.dumps(line) + "\n").encode())
    finally:
        os.close(fd)
