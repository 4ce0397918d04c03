"""Lecornu's speed/accuracy families: the planar period (his k⁴ remark), the zeros of J1 and
J2 (his Bessel tables), and the elongation times of his shortening pendulum.

References: mpmath's complete elliptic integral and Bessel zeros at 50 digits; for the
elongation times, the exact Bessel-function solution (its zeros are checked against mpmath
in the bessel_zeros family).  The example's speed, length and g and the two amplitudes of the
k⁴ remark are read from ``tables/published/lecornu.toml`` ``[paper.constants]``.
"""

from __future__ import annotations

import math
from functools import partial
from typing import Any

from pendcli.data.tables import load_paper_table
from pendcli.run.tradeoff_engine import Candidate, Family

__all__ = [
    "FAMILIES",
    "example_problem",
    "reference_bessel_zero",
    "reference_elongations",
    "reference_period_ratio",
]


def example_problem() -> tuple[float, float, float]:
    """Lecornu's example (speed m/s, length at t = 0 m, g m/s²) from the paper's table."""
    table = load_paper_table("lecornu")
    return table.constant("speed"), table.constant("length"), table.constant("g")


def _k4_amplitudes() -> list[float]:
    """θ0 (degrees) of the k⁴ remark: 20° and the swing of 180° (θ0 = 90°)."""
    table = load_paper_table("lecornu")
    return [table.constant("k4_amplitude"), table.constant("horizontal_amplitude")]


# ---------------------------------------------------------------------------------------------
# Planar pendulum period


def reference_period_ratio(amplitude: float) -> Any:
    """T/T0 = (2/π) K(sin²(θ0/2)) by mpmath at 50 digits (θ0 in degrees)."""
    import mpmath

    with mpmath.workdps(50):
        m = mpmath.sin(mpmath.mpf(amplitude) * mpmath.pi / 360) ** 2
        return 2 * mpmath.ellipk(m) / mpmath.pi


def _agm_fixed(amplitude: float, iterations: int) -> float:
    from pendcli.numerics import planar

    value, _used = planar.agm_ellipk(planar.complementary_modulus(amplitude), iterations)
    return 2 * value / math.pi


def _planar_candidates(quick: bool) -> list[Candidate]:
    from pendcli.numerics import planar

    orders = (1, 4, 16) if quick else (1, 2, 4, 8, 16, 32, 48)
    iters = (1, 3) if quick else (1, 2, 3, 4, 5)
    epsrels = (1e-3, 1e-10) if quick else (1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
    out = [
        Candidate(
            m,
            "scipy.special" if m.startswith("ellip") else "default",
            partial(planar.period_ratio, method=m),
        )
        for m in ("agm", "ellipkm1", "ellipk")
    ]
    out += [
        Candidate("series", f"order={k}", partial(planar.series_period_ratio, order=k))
        for k in orders
    ]
    out += [
        Candidate("agm-fixed", f"iterations={k}", partial(_agm_fixed, iterations=k)) for k in iters
    ]
    out += [
        Candidate("quad", f"epsrel={e:.0e}", partial(planar.period_ratio, method="quad", epsrel=e))
        for e in epsrels
    ]
    return out


# ---------------------------------------------------------------------------------------------
# Zeros of J1 and J2


def reference_bessel_zero(problem: tuple[int, int]) -> Any:
    """j_(ν,s) by mpmath.besseljzero at 50 digits; problem = (ν, s)."""
    import mpmath

    order, s = problem
    with mpmath.workdps(50):
        return mpmath.besseljzero(order, s)


def _zero(problem: tuple[int, int], method: str) -> float:
    """j_(ν,s) by one method of bessel_zeros (which returns the first s zeros)."""
    from pendcli.numerics.besselzeros import bessel_zeros

    order, s = problem
    return float(bessel_zeros(order, s, method)[s - 1])


def _bessel_candidates(quick: bool) -> list[Candidate]:
    from pendcli.numerics import besselzeros as bz

    return [
        Candidate(method, "first zeros up to j_(ν,s)", partial(_zero, method=method))
        for method in bz.METHODS
    ]


# ---------------------------------------------------------------------------------------------
# Elongation times of the shortening pendulum


def reference_elongations(problem: tuple[float, float, float]) -> tuple[float, ...]:
    """The exact Bessel-function solution (its zeros are checked against mpmath elsewhere)."""
    from pendcli.papers.lecornu.model import elongation_times

    return tuple(float(t) for t in elongation_times(*problem, method="bessel"))


def _lecornu_candidates(quick: bool) -> list[Candidate]:
    from pendcli.papers.lecornu.model import elongation_times

    reference = reference_elongations(example_problem())
    rtols = (1e-3, 1e-9) if quick else (1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12)

    def times(problem: tuple[float, float, float], method: str, rtol: float) -> tuple[float, ...]:
        out = [float(t) for t in elongation_times(*problem, method=method, rtol=rtol)]
        # compare the elongations both methods find (the last may fall on either side of the
        # length floor where the integration stops)
        return tuple(out[: len(reference)]) + tuple(reference[len(out) :])

    out = [Candidate("bessel", "exact (reference)", partial(times, method="bessel", rtol=1e-10))]
    out += [Candidate("ode", f"rtol={r:.0e}", partial(times, method="ode", rtol=r)) for r in rtols]
    return out


def _families() -> list[Family]:
    k4 = _k4_amplitudes()
    k4_printed = load_paper_table("lecornu").claim("lecornu.k4.swing180").number.value
    speed, length, _g = problem = example_problem()
    return [
        Family(
            "planar_period",
            f"planar pendulum T/T0 = (2/π) K(sin²(θ0/2)) at θ0 = {k4[0]:g}°, {k4[1]:g}° "
            f"(Lecornu's k⁴ = {k4_printed:g})",
            k4,
            reference_period_ratio,
            _planar_candidates,
        ),
        Family(
            "bessel_zeros",
            "zeros j_(ν,s) of J1 and J2: the 1st and the 6th (below 23, Lecornu's series range)",
            [(1, 1), (2, 1), (1, 6), (2, 6)],
            reference_bessel_zero,
            _bessel_candidates,
            quick_problems=[(1, 1), (2, 6)],
        ),
        Family(
            "lecornu_elongations",
            "elongation times of the shortening pendulum, "
            f"{speed:g} m/s from {length:g} m (Lecornu's example)",
            [problem],
            reference_elongations,
            _lecornu_candidates,
        ),
    ]


FAMILIES: list[Family] = _families()
