"""Tisserand's model: his summary series (I)-(VI), the example's data, and the exact motion.

The series are evaluated exactly as printed (:func:`series_conical`); the exact spherical
pendulum they approximate is :func:`pendcli.numerics.spherical.exact_conical`, re-exported
here with :class:`ConicalMotion` so that one module holds both sides of every comparison.
The example's amplitudes and length are read from ``[paper.constants]`` of
``tables/published/tisserand.toml``, never typed in.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from pendcli.base.errors import PendcliError
from pendcli.data.tables import load_paper_table
from pendcli.numerics.spherical import (
    ConicalMotion,
    check_amplitudes,
    exact_conical,
    integrands,
)
from pendcli.papers.tisserand.units import amplitudes

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import ArrayLike

__all__ = [
    "DEGREES",
    "PRINTED_UNIT",
    "SERIES_ORDERS",
    "ConicalMotion",
    "displacement_mm",
    "exact_conical",
    "example_angles",
    "example_length_m",
    "example_ratio",
    "example_reading",
    "periodic_excursion_mm",
    "resal_rate_limit",
    "series_conical",
    "series_path",
]

PAPER = "tisserand"
SERIES_ORDERS = (0, 2, 4, 6)
PRINTED_UNIT = "'"  # the example's amplitudes as the OCR (and perhaps the print) has them
DEGREES = "°"  # the reading the printed coefficients support (see the package docstring)


# ---------------------------------------------------------------- the example's data


def example_reading(unit: str = DEGREES) -> tuple[str, str]:
    """The example's θ0, θ1 as text in ``unit``: ("30°", "15°"), or ("30'", "15'") as printed."""
    table = load_paper_table(PAPER)
    return f"{table.constant('theta0'):g}{unit}", f"{table.constant('theta1'):g}{unit}"


def example_angles(unit: str = DEGREES) -> tuple[float, float]:
    """The example's θ0, θ1 in radians under the reading ``unit`` (degrees by default)."""
    return amplitudes(*example_reading(unit))


def example_length_m() -> float:
    """l of the remark after the example (« En supposant l = 0^m,5 »), in metres."""
    return load_paper_table(PAPER).constant("length")


def example_ratio() -> float:
    """θ1/θ0 of the example."""
    table = load_paper_table(PAPER)
    return table.constant("theta1") / table.constant("theta0")


# ---------------------------------------------------------------- Tisserand's series


def _check_order(order: int) -> int:
    if order not in SERIES_ORDERS:
        raise PendcliError(
            f"order: {order!r} is not available; choose one of {', '.join(map(str, SERIES_ORDERS))}"
        )
    return order


def series_conical(theta0_rad: float, theta1_rad: float, order: int = 6) -> ConicalMotion:
    """k', k'', Ω and the coefficients of ψ and φ' from Tisserand's summary (I), (II), (V).

    ``order`` n in (0, 2, 4, 6) keeps in every printed series the terms of degree <= n in
    (u0, u1); terms Tisserand did not print are absent (so n = 6 only adds the sixth-order
    term of k'). Ω = (3/8) u0 u1 k''/k' per unit k't, as (V) writes it.
    (I)   k' = k / [1 + (u0²+u1²)/16 + (25(u0⁴+u1⁴) - 26u0²u1²)/1024
                    + (225(u0⁶+u1⁶) - 313u0²u1²(u0²+u1²))/16384]
          k'' = k' [1 + 9(u0²+u1²)/32 + (151(u0⁴+u1⁴) + 58u0²u1²)/1024]
    (II)  ψ = k't - (u0²-u1²)(3/32 + 11(u0²+u1²)/256) sin 2k't + (u0²-u1²)²/4096 sin 4k't
    (V)   φ' = (3/8) u0 u1 k'' t + u0 u1 (u0²-u1²)(17/512) sin 2k't
    """
    theta0, theta1 = check_amplitudes(theta0_rad, theta1_rad)
    _check_order(order)
    u0, u1 = math.sin(theta0), math.sin(theta1)
    p0, p1 = u0 * u0, u1 * u1
    s, e, prod = p0 + p1, (u0 - u1) * (u0 + u1), p0 * p1

    def upto(*terms: tuple[int, float]) -> float:
        return sum(value for degree, value in terms if degree <= order)

    k_over_k1 = 1.0 + upto(
        (2, s / 16),
        (4, (25 * (p0 * p0 + p1 * p1) - 26 * prod) / 1024),
        (6, (225 * (p0**3 + p1**3) - 313 * prod * s) / 16384),
    )
    k2_over_k1 = 1.0 + upto((2, 9 * s / 32), (4, (151 * (p0 * p0 + p1 * p1) + 58 * prod) / 1024))
    k1 = 1.0 / k_over_k1
    return ConicalMotion(
        theta0=theta0,
        theta1=theta1,
        k1=k1,
        k2=k1 * k2_over_k1,
        precession=0.375 * u0 * u1 * k2_over_k1,
        psi_coeffs=(-upto((2, e * 3 / 32), (4, e * 11 * s / 256)), upto((4, e * e / 4096))),
        phi_coeffs=(upto((4, u0 * u1 * e * 17 / 512)),),
        method=f"Tisserand (I), (II), (V) to order {order}",
    )


def series_path(theta0: float, theta1: float, kt: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(x, y)/l from (II)-(VI): the point (u0 cos ψ, u1 sin ψ) of the ellipse turned by φ'."""
    import numpy as np

    s = series_conical(theta0, theta1, order=6)
    u0, u1 = math.sin(theta0), math.sin(theta1)
    tau = s.k1 * np.asarray(kt, dtype=float)
    psi = tau + s.psi_coeffs[0] * np.sin(2 * tau) + s.psi_coeffs[1] * np.sin(4 * tau)
    phi_prime = s.precession * tau + s.phi_coeffs[0] * np.sin(2 * tau)
    ex, ey = u0 * np.cos(psi), u1 * np.sin(psi)
    return (
        ex * np.cos(phi_prime) - ey * np.sin(phi_prime),
        ex * np.sin(phi_prime) + ey * np.cos(phi_prime),
    )


# ---------------------------------------------------------------- derived quantities


def displacement_mm(motion: ConicalMotion, length_m: float) -> float:
    """Largest shift of the bob along the circle through the ends of the major axis (radius
    l sin θ0) due to the periodic term c_1 sin 2k't of φ': l sin θ0 |c_1|, in millimetres."""
    return 1000.0 * length_m * math.sin(motion.theta0) * abs(motion.phi_coeffs[0])


def periodic_excursion_mm(theta0: float, theta1: float, length_m: float) -> float:
    """max over t of |φ' - Ω k't| (exact motion, 8 harmonics) times l sin θ0, in mm."""
    import numpy as np

    motion = exact_conical(theta0, theta1, harmonics=8)
    tau = np.linspace(0.0, 0.5 * math.pi, 2001)
    periodic = sum(c * np.sin(2 * (n + 1) * tau) for n, c in enumerate(motion.phi_coeffs))
    return 1000.0 * length_m * math.sin(theta0) * float(np.max(np.abs(periodic)))


def resal_rate_limit() -> float:
    """Ω/(u0 u1) of the exact motion at zero amplitude: eq. (5) minus dφ1/dψ, per u0 u1,
    averaged over ψ (the integrand is regular there, see :mod:`pendcli.numerics.spherical`)."""
    import numpy as np

    psi = np.arange(64) * (math.pi / 64)
    _, q = integrands(0.0, 0.0, psi)
    return float(q.mean())
