"""Tisserand (1881), p. 448-450, lines 32-88: the references of the motion's differentials.

The first integrals of the spherical pendulum and (1), (2); the substitution (3) and the
differentials (4), (5) it gives; the developments in the small angles before (6), (6), (7) and
the integrals in ψ. Each builder maps ledger symbols (tables/equations/tisserand.toml
[symbols]) to exact expressions taken from what the printed formula rests on: the energy and
areal integrals (their constants solved from θ' = 0 at θ0 and θ1), the definition (3),
u = sin θ, the differentials (4) and (5) themselves; never a copy of the formula the row
prints.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.data.printed import ledger_symbols
from pendcli.verify.printed_check import Reference


def scale() -> Any:
    """s, the scale of the angles' order: the series references multiply u, u0, u1 by it."""
    return sp.Symbol("s", positive=True)


# --- the first integrals: (1), (2), lines 36-38 ---------------------------------------------


def _first_integrals(theta: Any, k: Any) -> tuple[Any, Any]:
    """θ'² and h (the areal constant sin²θ φ') of the spherical pendulum with apsides θ0, θ1:
    energy θ'² + sin²θ φ'² = 2E + 2k² cos θ and sin²θ φ' = h, E and h² fixed by θ' = 0 at θ0
    and at θ1 (solved here, not typed)."""
    energy, h2 = sp.symbols("E h2")
    fixed = dict(zip((energy, h2), _apsidal_constants(k), strict=True))
    theta_dot_sq = 2 * energy + 2 * k**2 * sp.cos(theta) - h2 / sp.sin(theta) ** 2
    return theta_dot_sq.subs(fixed), sp.sqrt(fixed[h2])


@cache
def _apsidal_constants(k: Any) -> tuple[Any, Any]:
    """E and h² of :func:`_first_integrals`, solved from θ' = 0 at θ0 and at θ1."""
    theta0, theta1 = ledger_symbols("theta0", "theta1")
    energy, h2 = sp.symbols("E h2")

    def theta_dot_sq(angle: Any) -> Any:
        return 2 * energy + 2 * k**2 * sp.cos(angle) - h2 / sp.sin(angle) ** 2

    fixed = sp.solve([theta_dot_sq(theta0), theta_dot_sq(theta1)], [energy, h2], dict=True)[0]
    return fixed[energy], fixed[h2]


def _motion_in_theta(theta: Any, dtheta: Any) -> dict[str, Any]:
    """dt and dφ along the motion, from the first integrals (θ decreasing from θ0 at t = 0)."""
    (k,) = ledger_symbols("k")
    theta_dot_sq, h = _first_integrals(theta, k)
    dt = -dtheta / sp.sqrt(theta_dot_sq)
    return {"dt": dt, "dphi": h / sp.sin(theta) ** 2 * dt}


# (1), line 36, and (2), line 38: dt and dφ in θ.
def reference_first_integrals() -> Reference:
    """(1), (2): dt and dφ from the energy and areal integrals, apsides θ0 and θ1."""
    theta, dtheta = ledger_symbols("theta", "dtheta")
    exact = _motion_in_theta(theta, dtheta)
    return Reference(exact, what="the first integrals")


# --- the substitution (3), lines 42-52 -------------------------------------------------------


# Line 46 (dθ in dψ after (3)), (4) line 50, (5) line 52: the first integrals in ψ.
def reference_first_integrals_in_psi() -> Reference:
    """dθ, dt, dφ of the first integrals with θ, θ0, θ1 from (3): u = sin θ as a function of
    ψ, dθ its exact derivative times dψ (for the line after (3), (4), (5))."""
    u0, u1, psi, dpsi = ledger_symbols("u0", "u1", "psi", "dpsi")
    u = substitution_3()
    theta = sp.asin(u)
    dtheta = sp.diff(theta, psi) * dpsi
    theta0, theta1 = ledger_symbols("theta0", "theta1")
    apsides = {theta0: sp.asin(u0), theta1: sp.asin(u1)}
    exact = {n: e.subs(apsides) for n, e in _motion_in_theta(theta, dtheta).items()}
    exact.update(theta=theta, theta0=sp.asin(u0), theta1=sp.asin(u1), u=u, dtheta=dtheta)
    return Reference(exact, what="the first integrals with (3)")


# (3), line 42: the integrals in ψ of lines 82-88, tan²ψ of line 134 and the ellipse rest on it.
def substitution_3() -> Any:
    """(3): u = √(u0² cos²ψ + u1² sin²ψ)."""
    u0, u1, psi = ledger_symbols("u0", "u1", "psi")
    return sp.sqrt(u0**2 * sp.cos(psi) ** 2 + u1**2 * sp.sin(psi) ** 2)


# --- the developments in the small angles: lines 54-78, (6), (7) -------------------------


def _small_angles(in_scale: Any) -> dict[str, Any]:
    """u = sin θ, u0, u1 scaled by ``in_scale``: θ = arcsin(in_scale·u) and u -> in_scale·u."""
    out: dict[str, Any] = {}
    for suffix in ("", "0", "1"):
        (u,) = ledger_symbols(f"u{suffix}")
        out[f"theta{suffix}"] = sp.asin(in_scale * u)
        out[f"u{suffix}"] = in_scale * u
    return out


# Lines 54-66: « On a les développements suivants », cos θ and the sum and product of (4).
def reference_small_angles() -> Reference:
    """cos θ = √(1 − u²) with u = sin θ: the series through the fourth order in the angles."""
    x = sp.Symbol("x", positive=True)
    return Reference(_small_angles(x), what="u = sin θ, to order 4")


# Line 70 (the square root of the development) and (6), line 72: dt of (4) as a series.
def reference_differential_4() -> Reference:
    """(4), solved for dt, with u = sin θ: the series through the fourth order."""
    x = sp.Symbol("x", positive=True)
    exact = _small_angles(x)
    k, dpsi = ledger_symbols("k", "dpsi")
    c, c0, c1 = (sp.cos(exact[f"theta{s}"]) for s in ("", "0", "1"))
    total = 1 + c * c0 + c * c1 + c0 * c1
    product = (c + c0) * (c + c1) * (c0 + c1)
    root = sp.sqrt(1 - exact["u"] ** 2)
    exact["dt"] = dpsi / (k * sp.sqrt(2) * root) * sp.sqrt(product) / sp.sqrt(total)
    return Reference(exact, what="(4), to order 4")


def _dphi_from_5(scale_u0_u1: bool) -> dict[str, Any]:
    """u, u0, u1 scaled by s (u0, u1 only when ``scale_u0_u1``) and dφ from (5)."""
    s = scale()
    u, u0, u1, dpsi = ledger_symbols("u", "u0", "u1", "dpsi")
    v0, v1 = (s * u0, s * u1) if scale_u0_u1 else (u0, u1)
    c, c0, c1 = sp.sqrt(1 - s**2 * u**2), sp.sqrt(1 - v0**2), sp.sqrt(1 - v1**2)
    root = sp.sqrt((c + c0) * (c + c1)) / sp.sqrt(1 + c * c0 + c * c1 + c0 * c1)
    dphi = v0 * v1 * dpsi / (s**2 * u**2 * c) * root  # (5), with √(1 − u²) = cos θ
    return {"u": s * u, "u0": v0, "u1": v1, "dphi": dphi}


# (7), line 76: the Laurent series of (5).
def reference_formula_5() -> Reference:
    """(5) through the second order in the angles (its Laurent series in u, u0, u1): (7)."""
    return Reference(_dphi_from_5(True), what="(5)")


# Line 78: the coefficient 1 of 1/u² in (7), « si loin qu'on pousse les approximations ».
def reference_formula_5_near_u_zero() -> Reference:
    """(5) with u0, u1 exact and u → 0 only: the 1/u² coefficient to every order in u0, u1
    (« si loin qu'on pousse les approximations »)."""
    return Reference(_dphi_from_5(False), what="(5) as u → 0")


# Lines 68-70, « La formule (5) donnera ensuite »: the series of (4), cited as (5).
def reference_formula_5_as_cited() -> Reference:
    """« La formule (5) donnera »: what (5) gives (dφ, in the angles to order 4), which leaves
    dt undetermined; the reading is judged against (4), the formula that has dt."""
    x = sp.Symbol("x", positive=True)
    exact = _small_angles(x)
    exact["dphi"] = _dphi_from_5(True)["dphi"].subs(scale(), x)
    return Reference(exact, what="(5), to order 4", reading=reference_differential_4())
