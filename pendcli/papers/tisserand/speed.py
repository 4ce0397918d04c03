"""Tisserand's speed/accuracy family: k'/k and Ω of the exact conical pendulum.

The reference (:func:`reference_conical`) integrates the first integrals in z = cos θ with
mpmath at 30 digits: independent of :mod:`pendcli.numerics.spherical`, whose quadrature and
ODE are measured against it together with Tisserand's series (orders 0 to 6).
"""

from __future__ import annotations

import math
from functools import partial
from typing import Any

from pendcli.run.tradeoff_engine import Candidate, Family

__all__ = ["FAMILIES", "reference_conical"]


def reference_conical(problem: tuple[float, float], dps: int = 30) -> tuple[float, float]:
    """k'/k and Ω from the first integrals in z = cos θ, by mpmath quadrature at ``dps`` digits.

    Independent of pendcli.numerics.spherical: with k = 1, ż² = 2P(z), P = (1 - z²)(e + z) - h²/2 =
    (z - z0)(z1 - z)(z - z3); z = z0 + (z1 - z0) sin² s removes both endpoint singularities.
    k' = π / T_r and Ω = (Δφ - π)/π per radial period T_r.
    """
    import mpmath

    theta0, theta1 = problem
    with mpmath.workdps(dps):
        z0, z1 = mpmath.cos(mpmath.mpf(theta0)), mpmath.cos(mpmath.mpf(theta1))
        # (1 - z²)(e + z) takes the same value h²/2 at both turning points
        e = (z1 * (1 - z1**2) - z0 * (1 - z0**2)) / ((1 - z0**2) - (1 - z1**2))
        h = mpmath.sqrt(2 * (1 - z0**2) * (e + z0))
        z3 = -e - z0 - z1

        def z(s: Any) -> Any:
            return z0 + (z1 - z0) * mpmath.sin(s) ** 2

        half_period = mpmath.quad(lambda s: 2 / mpmath.sqrt(2 * (z(s) - z3)), [0, mpmath.pi / 2])
        half_turn = mpmath.quad(
            lambda s: 2 * h / ((1 - z(s) ** 2) * mpmath.sqrt(2 * (z(s) - z3))),
            [0, mpmath.pi / 2],
        )
        return (
            float(mpmath.pi / (2 * half_period)),
            float((2 * half_turn - mpmath.pi) / mpmath.pi),
        )


def _series(problem: tuple[float, float], order: int) -> tuple[float, float]:
    from pendcli.papers.tisserand.model import series_conical

    motion = series_conical(*problem, order=order)
    return motion.k1, motion.precession


def _exact(problem: tuple[float, float], method: str, rtol: float) -> tuple[float, float]:
    from pendcli.numerics.spherical import exact_conical

    motion = exact_conical(*problem, method=method, rtol=rtol)
    return motion.k1, motion.precession


def _conical_candidates(quick: bool) -> list[Candidate]:
    from pendcli.papers.tisserand.model import SERIES_ORDERS

    orders = (0, 6) if quick else SERIES_ORDERS
    rtols = (1e-4, 1e-10) if quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13)
    out = [Candidate("series", f"order={k}", partial(_series, order=k)) for k in orders]
    for method in ("quad", "ode"):
        out += [
            Candidate(method, f"rtol={r:.0e}", partial(_exact, method=method, rtol=r))
            for r in rtols
        ]
    return out


FAMILIES: list[Family] = [
    Family(
        "conical",
        "exact conical pendulum k'/k and Ω at (θ0, θ1) = (20°, 10°), (10°, 2°) (worst of both)",
        [(math.radians(20.0), math.radians(10.0)), (math.radians(10.0), math.radians(2.0))],
        reference_conical,
        _conical_candidates,
        quick_problems=[(math.radians(20.0), math.radians(10.0))],
    ),
]
