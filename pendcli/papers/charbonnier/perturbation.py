"""Charbonnier's perturbed pendulum (nos. 4-9, 11, 14) and its direct integration.

The equation is θ'' + k²θ + ε φ(θ, θ', t) = 0, θ(0) = −α, θ'(0) = 0 (no. 4), the principal
motion being linear (sin θ → θ, no. 3).  The integrals E_s, E_c of no. 7 are computed by
Gauss-Legendre quadrature of φ(−α cos kt, kα sin kt, t), independent of the ODE, which
:func:`measure` integrates with a :class:`~pendcli.verify.formula_engine.Integrator` to find the
events the first-order formulas (6)-(9) predict.

The pendulum of these checks (g, l0, α) is read from ``[paper.constants]`` of
``tables/published/charbonnier.toml``: Charbonnier prints no numbers for them.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from pendcli.data.tables import load_paper_table
from pendcli.verify.formula_engine import crossings

if TYPE_CHECKING:
    from pendcli.verify.formula_engine import Integrator

__all__ = [
    "GL_NODES",
    "CheckPendulum",
    "Perturbation",
    "Phi",
    "check_pendulum",
    "e_integrals",
    "measure",
    "monomial",
    "perturbations",
]

# φ(θ, θ', t), vectorised over numpy arrays: ε φ is the perturbing acceleration
Phi = Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]
GL_NODES = 60  # Gauss-Legendre nodes of e_integrals: exact to rounding for these smooth φ


@dataclass(frozen=True)
class CheckPendulum:
    """The principal motion θ = −α cos kt, k = √(g/l0), of the checks (no. 3)."""

    g: float  # m/s²
    l0: float  # m
    alpha: float  # rad

    @property
    def k(self) -> float:
        return math.sqrt(self.g / self.l0)

    @property
    def half(self) -> float:
        """T = π/k, the principal half-swing (no. 3)."""
        return math.pi / self.k


def check_pendulum() -> CheckPendulum:
    """g, l0 and α of the checks, from ``[paper.constants]`` (assumptions: see the table).

    Not cached here: the table loader caches, and its cache can be cleared.
    """
    table = load_paper_table("charbonnier")
    return CheckPendulum(table.constant("g"), table.constant("l0"), table.constant("alpha"))


class Perturbation(NamedTuple):
    description: str
    phi: Phi
    scale: float  # ε = δ·scale for the dimensionless size δ


def perturbations(p: CheckPendulum) -> dict[str, Perturbation]:
    """The three perturbations of the general formulas' checks (names are the row ids)."""
    k, alpha = p.k, p.alpha
    omega = 0.6 * k
    return {
        "linear_damping": Perturbation(
            "linear resistance εφ = ε θ' (ε = δk)",
            lambda th, om, t: om,
            k,
        ),
        "periodic_force": Perturbation(
            "periodic force εφ = ε k²α cos(0.6kt) (ε = δ)",
            lambda th, om, t: k**2 * alpha * np.cos(omega * t),
            1.0,
        ),
        "friction": Perturbation(
            "constant friction εφ = ε k²α on the half-swing θ' > 0 (ε = δ)",
            lambda th, om, t: k**2 * alpha * np.ones_like(np.asarray(t * 1.0 + 0 * th)),
            1.0,
        ),
    }


def monomial(p: CheckPendulum, n: int) -> tuple[Phi, float]:
    """Resistance b_n v^n (no. 14), v = l0 θ' >= 0 on the half-swing: εφ = b_n l0^(n−1) θ'^n.

    ε = b_n = δ / (k^(n−2) α^(n−1) l0^(n−1)), so that Δα/α = −δ I_n(π).
    """
    k, alpha, l0 = p.k, p.alpha, p.l0
    scale = 1.0 / (k ** (n - 2) * alpha ** (n - 1) * l0 ** (n - 1))
    if n == 0:
        return lambda th, om, t: np.ones_like(np.asarray(om * 0.0 + 0.0 * th)) / l0, scale
    return lambda th, om, t: l0 ** (n - 1) * np.sign(om) * np.abs(om) ** n, scale


@cache
def _gauss_legendre() -> tuple[np.ndarray, np.ndarray]:
    nodes, weights = np.polynomial.legendre.leggauss(GL_NODES)
    return nodes, weights


def e_integrals(p: CheckPendulum, phi: Phi, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """E_s(t), E_c(t) of no. 7 on the principal motion, by Gauss-Legendre on [0, t]."""
    k, alpha = p.k, p.alpha
    gl_nodes, gl_weights = _gauss_legendre()
    t = np.atleast_1d(np.asarray(t, dtype=float))
    nodes = np.outer(t, (gl_nodes + 1) / 2)  # shape (len(t), GL_NODES)
    weights = np.outer(t, gl_weights / 2)
    f = phi(-alpha * np.cos(k * nodes), k * alpha * np.sin(k * nodes), nodes)
    return (
        np.sum(weights * f * np.sin(k * nodes), axis=1),
        np.sum(weights * f * np.cos(k * nodes), axis=1),
    )


def _solve(p: CheckPendulum, phi: Phi, epsilons: np.ndarray, ref: Integrator):
    """θ'' + k²θ + εφ = 0 for every ε at once, θ(0) = −α, θ'(0) = 0, to 1.25 half-swings."""
    m = len(epsilons)
    k2 = p.k**2

    def rhs(t, y):
        th, om = y[:m], y[m:]
        return np.concatenate((om, -k2 * th - epsilons * phi(th, om, t)))

    y0 = [-p.alpha] * m + [0.0] * m
    return ref.solve(rhs, 1.25 * p.half, y0)


def measure(p: CheckPendulum, phi: Phi, epsilons: np.ndarray, ref: Integrator):
    """End of the half-swing (θ' = 0), amplitude there, lowest point (θ = 0) and its speed.

    Returns ({"t_end", "theta_end", "t_low", "omega_low"} -> array over ε, dense solution).
    """
    sol = _solve(p, phi, epsilons, ref)
    m = len(epsilons)
    window = 1.25 * p.half
    out: dict[str, list[float]] = {k: [] for k in ("t_end", "theta_end", "t_low", "omega_low")}
    for j in range(m):
        (t_end,) = crossings(sol, m + j, 0.0, window, 1)
        (t_low,) = crossings(sol, j, 0.0, window, 1)
        out["t_end"].append(t_end)
        out["theta_end"].append(sol(t_end)[j])
        out["t_low"].append(t_low)
        out["omega_low"].append(sol(t_low)[m + j])
    return {k: np.array(v) for k, v in out.items()}, sol
