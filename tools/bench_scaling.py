"""``make bench``: pendcli against its peers, and how its cost grows with size.

Peers: the same answers from pendcli and from scipy or mpmath in one process, time per
call and the ratio (:func:`peer_ratios`). Growth: ``lecornu zeros --count`` and
``charbonnier table --n-max`` at growing sizes, each in its own process stopped at a time
and memory limit (:func:`growth_rows`).
"""

from __future__ import annotations

import os
import subprocess
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    pass

from tools.bench_startup import pendcli_command


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
        [*pendcli_command(), *args],
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
