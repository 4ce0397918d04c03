"""Charbonnier (1908), part I, n° 9 (« Points remarquables de la trajectoire »): the
references of the rows of lines 231-287, the turning time, the amplitude and the lowest point
of θ = θ0 + εθ1 and the formulas (6)-(9).

The remarkable points are found from θ = θ0 + εθ1 by one Newton step in ε (never from the
paper's E integrals), θ1 that of the family of :func:`.references_general.exponential_family`
or, for n° 13, of a resistance (:func:`first_order_points`).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from pendcli.papers.charbonnier.references_general import (
    exponential_family,
    free_parameters,
    ledger_symbols,
    principal_motion,
)
from pendcli.verify.printed_check import Reference


def first_order_points(theta1: Any, speed1: Any) -> dict[str, Any]:
    """The turning time t* = π/k + ετ1 (θ' = 0), the lowest point t0 = π/(2k) + εσ1 (θ = 0),
    the amplitude θ(t*) and the speed θ'(t0), to first order in ε, for a given θ1, θ1'."""
    t, k, alpha, eps = ledger_symbols("t", "k", "alpha", "epsilon")
    theta0, speed0 = principal_motion()
    turn, low = sp.pi / k, sp.pi / (2 * k)
    tau = -speed1.subs(t, turn) / sp.diff(speed0, t).subs(t, turn)
    sigma = -theta1.subs(t, low) / speed0.subs(t, low)
    amplitude = theta0.subs(t, turn) + eps * theta1.subs(t, turn)  # θ0'(t*) = 0: no τ term
    speed = speed0.subs(t, low) + eps * speed1.subs(t, low)  # θ0''(t0) = 0: no σ term
    return {
        "turning": turn + eps * tau,
        "lowest": low + eps * sigma,
        "Delta_T": eps * tau,
        "Delta_T_half": eps * sigma,
        "theta_m": amplitude,
        "Delta_alpha": amplitude - alpha,
        "thetap_m": speed,
        "Delta_thetap_m": speed - speed0.subs(t, low),
    }


def _phase(function: Any) -> Any:
    """E of the time -> E of kt, as (6)-(9) write E_c(π), E_c(π/2)."""
    (k,) = ledger_symbols("k")
    u = sp.Symbol("u", real=True)
    return sp.Lambda(u, function(u / k))


def _family_points() -> dict[str, Any]:
    family = exponential_family()
    exact = first_order_points(family["theta_1"], family["dtheta_1_dt"])
    exact.update({"E_s": _phase(family["E_s"]), "E_c": _phase(family["E_c"])})
    return exact


# n° 9, 1°, lines 231-241 (the turning time); 2°, lines 253-257 (repeated) and 259-261 (the
# amplitude θ_m)
def reference_turning_point() -> Reference:
    """n° 9, 1°-2°: t is the turning time t* (θ' = 0 near kt = π), through ε."""
    exact = _family_points()
    exact["t"] = exact["turning"]
    return Reference(exact, what="the turning time of θ0 + εθ1")


# n° 9, 1°, lines 237-241: kt from sin kt = −εE_c(π)/(kα), inverted
def reference_sine_inverted() -> Reference:
    """n° 9, 1°: kt from sin kt = −εE_c(π)/(kα) inverted exactly (kt near π), through ε²."""
    k, alpha, eps = ledger_symbols("k", "alpha", "epsilon")
    exact = _family_points()
    exact["t"] = (sp.pi + sp.asin(eps / (k * alpha) * exact["E_c"](sp.pi))) / k
    return Reference(exact, what="the sine relation inverted, through ε²")


# (6) line 247, (7) line 265, (8) line 283, (9) line 287: ΔT, Δα, ΔT_½, Δθ'_m
def reference_remarkable_points() -> Reference:
    """n° 9: ΔT, θ_m, Δα, ΔT_½, Δθ'_m from θ = θ0 + εθ1, compared through ε."""
    exact = {k: v for k, v in _family_points().items() if k not in ("turning", "lowest")}
    return Reference(exact, what="θ0 + εθ1 at its turning and lowest points")


def _family_constrained(key: str) -> dict[str, Any]:
    """The φ of the family for which the first-order ``key`` (ΔT or Δα) vanishes: p3 solved."""
    (eps,) = ledger_symbols("epsilon")
    p3 = free_parameters(4)[3]
    exact = _family_points()
    first = sp.expand(exact[key] / eps)  # linear in p3
    value = -first.subs(p3, 0) / first.coeff(p3)

    def constrained(v: Any) -> Any:
        if isinstance(v, sp.Lambda):
            return sp.Lambda(v.args[0], v.expr.subs(p3, value))
        return v.subs(p3, value)

    return {k: constrained(v) for k, v in exact.items()}


# n° 9, 1°, lines 249-251: the period is unchanged if and only if E_c(π) = 0
def reference_period_unchanged() -> Reference:
    """n° 9, 1°: the φ of the family whose period is unchanged (ΔT = 0 at first order)."""
    return Reference(_family_constrained("Delta_T"), what="φ with ΔT = 0")


# n° 9, 2°, lines 267-269: the amplitude is unchanged if and only if E_s(π) = 0
def reference_amplitude_unchanged() -> Reference:
    """n° 9, 2°: the φ of the family whose amplitude is unchanged (Δα = 0 at first order)."""
    return Reference(_family_constrained("Delta_alpha"), what="φ with Δα = 0")


# n° 9, 3°, lines 271-279: the time of the lowest point
def reference_lowest_point() -> Reference:
    """n° 9, 3°: t is the time of the lowest point (θ = 0 near kt = π/2), through ε."""
    exact = _family_points()
    exact["t"] = exact["lowest"]
    return Reference(exact, what="the lowest point of θ0 + εθ1")
