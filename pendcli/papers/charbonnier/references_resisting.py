"""Charbonnier (1908), part II (« Le mouvement du pendule dans un milieu résistant »),
n° 11-13: the references of the rows of lines 311-413, for a resistance of the air cF(v).

θ1 is Duhamel's integral of φ(t) = F(l0 θ0'(t)) (left to quadrature), ε = c/l0 (n° 12), and
the remarkable points come from it as in n° 9 (:func:`.references_points.first_order_points`),
never from the paper's E integrals.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy as sp

from pendcli.papers.charbonnier.references_general import (
    free_parameters,
    integrand_along,
    ledger_symbols,
    principal_motion,
)
from pendcli.papers.charbonnier.references_points import first_order_points
from pendcli.verify.printed_check import Reference


def resisted(force: Any, phase: bool) -> dict[str, Any]:
    """θ1, the E's and the remarkable points for the resistance ``force`` (a Lambda of v),
    φ(t) = F(l0 θ0'(t)), ε = c/l0 (n° 12)."""
    t, k, l0, c, eps = ledger_symbols("t", "k", "l0", "c", "epsilon")
    theta0, speed0 = principal_motion()
    w = sp.Symbol("w_", real=True)
    phi = force(l0 * speed0.subs(t, w))
    theta1 = sp.Integral(-phi * sp.sin(k * (t - w)) / k, (w, 0, t))
    speed1 = sp.Integral(-phi * sp.cos(k * (t - w)), (w, 0, t))
    u = sp.Symbol("u", real=True)
    end = u / k if phase else u
    exact = {k_: v.subs(eps, c / l0) for k_, v in first_order_points(theta1, speed1).items()}
    exact.update(
        {
            "F": force,
            "E_s": sp.Lambda(u, sp.Integral(phi * sp.sin(k * w), (w, 0, end))),
            "E_c": sp.Lambda(u, sp.Integral(phi * sp.cos(k * w), (w, 0, end))),
            "theta": theta0 + c / l0 * theta1,
            "dtheta_dt": speed0 + c / l0 * speed1,
            "g": k**2 * l0,
        }
    )
    return exact


def _air_force() -> Any:
    q0, q1, q2 = free_parameters(3, "q")
    v = sp.Symbol("v_", real=True)
    return sp.Lambda(v, q0 + q1 * v + q2 * v**2)


def _air(phase: bool) -> dict[str, Any]:
    t, k, alpha, l0, c = ledger_symbols("t", "k", "alpha", "l0", "c")
    theta0, speed0 = principal_motion()
    force = _air_force()
    exact = resisted(force, phase)
    v = force.args[0][0]
    w = sp.Symbol("w_", real=True)
    speed = l0 * speed0.subs(t, w)
    exact.update(
        {
            "S": sp.Lambda(v, sp.integrate(force.expr, (v, 0, v))),
            "nu": l0 * speed0,
            "nu_m": l0 * k * alpha,
            "s": l0 * theta0,
            "sigma": l0 * alpha,
            "tau": c * sp.Integral(force(speed) * speed, (w, 0, sp.pi / k)),
        }
    )
    amplitude = exact["Delta_alpha"]
    exact.update(
        {
            "Delta_z": amplitude,
            "Delta_y": l0 / 2 * ((alpha + amplitude) ** 2 - alpha**2),
            "Delta_sigma": l0 * amplitude,
        }
    )
    return exact


def _along_the_arc() -> Callable[[Any], Any]:
    """ν at the arc s of the principal motion: ν² + k²s² = k²σ² (the energy of (2))."""
    k, sigma, nu = ledger_symbols("k", "sigma", "nu")
    # |…| under the root, ≥ 0 on the arc: the quadrature's nodes may round past its ends
    return integrand_along({"s": lambda v: {nu: k * sp.sqrt(sp.Abs(sigma**2 - v**2))}})


# n° 12, 1°, lines 311-313 (θ), 315-317 (E_s, E_c of the time), 319-329 (in the arc, S(ν));
# 3°, lines 349-352 (E_s in the speed)
def reference_air() -> Reference:
    """n° 12: θ, θ' and E_s, E_c (of the time) for F(v) = q0 + q1v + q2v², ε = c/l0."""
    return Reference(_air(phase=False), transform=_along_the_arc(), what="F = q0 + q1v + q2v²")


# n° 12, 3°, lines 356-364 (E_s(π) = 2E_s(π/2)); n° 13, 1°, lines 366-372 (ΔT = 0), 2°,
# lines 378-405 (Δα, the work, the height), 3°, lines 407-413 (the lowest point)
def reference_air_points() -> Reference:
    """n° 13: the remarkable points for F(v) = q0 + q1v + q2v² (E of kt), through c."""
    exact = _air(phase=True)
    return Reference(exact, transform=_along_the_arc(), what="F in the air")


# n° 11, line 309: the sense of the resistance's acceleration along the arc
def reference_resistance_sense() -> Reference:
    """n° 11: on the first simple oscillation (0 < kt < π), the speed v = l0 θ' and the angular
    acceleration θ'' of the equation of line 307 along the principal motion, θ'' = −k²θ0 −
    (c/l0)F(v), F = q0 + q1v + q2v² with positive q's; the resistance's acceleration along the
    arc is −cF(v) in the sense of θ increasing (the term enters that equation as gravity's)."""
    k, l0, c = ledger_symbols("k", "l0", "c")
    theta0, speed0 = principal_motion()
    force = _air_force()
    speed = l0 * speed0
    exact = {"F": force, "v": speed, "d2theta_dt2": -(k**2) * theta0 - c / l0 * force(speed)}
    return Reference(exact, what="the first oscillation in the air")
