"""Lecornu (1894), § I, Équation du mouvement (lines 1-116), and the opening of § III (lines
690-698, the shortening pendulum): the references the printed forms are judged against
(:mod:`pendcli.verify.printed_check`).

Each builder maps ledger symbols to exact expressions taken from what the printed formula
rests on: the bob's equations in x, y (lines 34-40), the chain rule of l = a + bt, the
compound pendulum itself; never a second copy of the formula the row prints.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.papers.lecornu.references_base import reference, symbols


@cache
def _bob_accelerations() -> tuple[Any, Any, dict[str, Any]]:
    """ẍ, ÿ of x = l sin θ, y = l cos θ (line 34) for any l(t), θ(t), in the ledger's
    derivative symbols; and the symbols themselves."""
    t, length, dl, d2l, theta, dtheta, d2theta = symbols(
        "t", "l", "dl_dt", "d2l_dt2", "theta", "dtheta_dt", "d2theta_dt2"
    )
    big_l, big_theta = sp.Function("L")(t), sp.Function("Theta")(t)
    jets = {
        big_l.diff(t, 2): d2l,
        big_theta.diff(t, 2): d2theta,
        big_l.diff(t): dl,
        big_theta.diff(t): dtheta,
    }

    def in_symbols(expr: Any) -> Any:
        return expr.subs(jets).subs({big_l: length, big_theta: theta})

    ax = in_symbols((big_l * sp.sin(big_theta)).diff(t, 2))
    ay = in_symbols((big_l * sp.cos(big_theta)).diff(t, 2))
    names = {"l": length, "dl_dt": dl, "d2l_dt2": d2l, "theta": theta, "d2theta_dt2": d2theta}
    return ax, ay, names


def _cartesian_exact(uniform: bool) -> dict[str, Any]:
    """From lines 34–40: θ'' solved from x ÿ − y ẍ − g x = 0 (line 44, itself from 38 and 40),
    the tension from x ẍ + y ÿ = −T l + g y; with ``uniform``, l = a + bt (line 62)."""
    # a fresh dict of the shared expressions: eight rows cite it, each solve costs 0.4 s
    return dict(_cartesian_items(uniform))


@cache
def _cartesian_items(uniform: bool) -> tuple[tuple[str, Any], ...]:
    a, b, t, g, ten = symbols("a", "b", "t", "g", "Ten")
    ax, ay, s = _bob_accelerations()
    length, theta = s["l"], s["theta"]
    if uniform:  # the general items with the law substituted: one solve and simplify, not two
        law = {length: a + b * t, s["dl_dt"]: b, s["d2l_dt2"]: 0}
        return tuple((k, v.subs(law, simultaneous=True)) for k, v in _cartesian_items(False))
    x, y = length * sp.sin(theta), length * sp.cos(theta)
    # (38), (40): ẍ = −T x/l, ÿ = g − T y/l; eliminating T gives line 44
    d2theta = sp.solve(sp.expand(x * ay - y * ax - g * x), s["d2theta_dt2"])[0]
    tension = sp.simplify((g * y - (x * ax + y * ay)) / length)
    exact = {
        "d2theta_dt2": d2theta,
        "Ten": tension,
        "xc": x,
        "yc": y,
        "d2xc_dt2": -ten * x / length,
        "d2yc_dt2": g - ten * y / length,
    }
    return tuple(exact.items())


def reference_cartesian() -> Any:
    """Lines 34–44: x = l sin θ, y = l cos θ and the bob's equations (38), (40); line 48 from
    line 44, θ'' solved from x ÿ − y ẍ − g x = 0: the printed d/dt of l²θ' taken by the chain
    rule (l' = dl/dt, (θ')' = θ'')."""
    dl, dtheta, d2theta = symbols("dl_dt", "dtheta_dt", "d2theta_dt2")
    rates = {"t": {"l": dl, "theta": dtheta, "dtheta_dt": d2theta}}
    what = "x = l sin θ, y = l cos θ and (38), (40)"
    return reference(_cartesian_exact(False), what, rates=rates)


def reference_cartesian_uniform() -> Any:
    """The same with l = a + bt (line 62): the source of (3) and (4)."""
    return reference(_cartesian_exact(True), "(38), (40) with l = a + bt")


def _chain_rule() -> dict[str, Any]:
    """l = a + bt: dθ/dt, d²θ/dt² of θ(t) = Θ(a + bt) by the chain rule (sympy)."""
    a, b, t, dtheta_dl, d2theta_dl2 = symbols("a", "b", "t", "dtheta_dl", "d2theta_dl2")
    of_t = sp.Function("Theta")(a + b * t)
    jet = {1: dtheta_dl, 2: d2theta_dl2}  # Θ's derivatives at l = a + bt

    def in_l(expr: Any) -> Any:
        return expr.replace(
            lambda e: isinstance(e, sp.Subs), lambda e: jet[e.expr.derivative_count]
        )

    return {"dtheta_dt": in_l(of_t.diff(t)), "d2theta_dt2": in_l(of_t.diff(t, 2))}


def reference_chain_rule() -> Any:
    """Line 72: the chain rule of l = a + bt."""
    return reference(_chain_rule(), "the chain rule of l = a + bt")


def reference_motion_in_l() -> Any:
    """(5), line 76: (3) in the variable l, θ'' of (3) by the chain rule, t = (l − a)/b."""
    a, b, length, dtheta_dl = symbols("a", "b", "l", "dtheta_dl")
    d2theta_dt2 = _cartesian_exact(True)["d2theta_dt2"].subs(
        a + sp.Symbol("b", real=True) * sp.Symbol("t", real=True), length
    )
    dtheta_dt = sp.Symbol("dtheta_dt", real=True)
    exact = {
        "d2theta_dl2": (d2theta_dt2 / b**2).subs(dtheta_dt, b * dtheta_dl),
        "t": (length - a) / b,
    }
    return reference(exact, "(3) in l by the chain rule")


def reference_eq6() -> Any:
    """(6), line 80, against (3): θ'' of (3) (written with l = a + bt) for a d²/dt², θ_ll of (3) in
    l (the chain rule) for a d²/dl²; l' = b. The printed d²/dt² gives lθ'' + 2bθ' = −g sin θ, not
    −(g/b²) sin θ."""
    a, b, t, length = symbols("a", "b", "t", "l")
    dtheta, d2theta, dtheta_dl, d2theta_dl2 = symbols(
        "dtheta_dt", "d2theta_dt2", "dtheta_dl", "d2theta_dl2"
    )
    exact = dict(reference_motion_in_l().exact)
    exact["d2theta_dt2"] = _cartesian_exact(True)["d2theta_dt2"].subs(a + b * t, length)
    rates = {
        "t": {"theta": dtheta, "dtheta_dt": d2theta, "l": b},
        "l": {"theta": dtheta_dl, "dtheta_dl": d2theta_dl2},
    }
    del exact["t"]  # (3)'s θ'' is written in l, so no t is left to substitute
    return reference(exact, "(3), in t and in l", rates=rates)


def reference_compound() -> Any:
    """Line 84, l' = l + R²/l, with l = a + bt; bt/a small: b scaled by ε, through ε¹."""
    eps = sp.Symbol("eps_", positive=True)
    a, b, t, rg = symbols("a", "b", "t", "Rg")
    length = a + eps * b * t
    return reference({"lp": length + rg**2 / length, "b": eps * b}, "l' = l + R²/l")


def reference_equivalent_length() -> Any:
    """Line 84's « formule connue » from the compound pendulum of fixed length: about the axis
    its moment of inertia per unit mass is l² + R² (the parallel axes), so
    (l² + R²)θ'' + g l sin θ = 0; the simple pendulum with the same θ'' has the length
    l' = −g sin θ/θ''."""
    length, rg, g, theta = symbols("l", "Rg", "g", "theta")
    d2theta = -g * length * sp.sin(theta) / (length**2 + rg**2)
    return reference({"lp": -g * sp.sin(theta) / d2theta}, "(l² + R²)θ'' + g l sin θ = 0")


def reference_compound_motion() -> Any:
    """Lines 92-94 against the compound pendulum itself: d/dt[(l² + R²)θ'] + g l sin θ = 0
    (moment of inertia l² + R² per unit mass, l = a + bt the distance of the centre of
    gravity), θ'' solved from it; bt/a small: b scaled by ε, through ε¹ (the order of the
    printed l' = a + R²/a + b(1 − R²/a²)t)."""
    eps = sp.Symbol("eps_", positive=True)
    a, b, t, rg, g, theta, dtheta, q = symbols("a", "b", "t", "Rg", "g", "theta", "dtheta_dt", "q_")
    length, rate = a + eps * b * t, eps * b
    motion = (length**2 + rg**2) * q + 2 * length * rate * dtheta + g * length * sp.sin(theta)
    d2theta = sp.solve(motion, q)[0]
    exact = {"b": rate, "d2theta_dt2": d2theta}
    return reference(exact, "d/dt[(l² + R²)θ'] + g l sin θ = 0")


def reference_small_angle() -> Any:
    """(7), line 98: (5) (from (3) and the chain rule) with sin θ ≈ θ: θ scaled by ε, through ε¹."""
    eps = sp.Symbol("eps_", positive=True)
    theta, dtheta_dl = symbols("theta", "dtheta_dl")
    base = reference_motion_in_l().exact
    d2 = base["d2theta_dl2"].subs({theta: eps * theta, dtheta_dl: eps * dtheta_dl})
    exact = {"theta": eps * theta, "dtheta_dl": eps * dtheta_dl, "d2theta_dl2": d2}
    return reference(exact, "(5) to first order in θ")


def reference_riccati() -> Any:
    """Lines 100-106, (8): (7) with θ = e^∫z dl (θ' = zθ, θ'' = (z' + z²)θ), then z = v − 1/l."""
    length, g, b, theta, zr, vr, dzr = symbols("l", "g", "b", "theta", "zr", "vr", "dzr_dl")
    # (7), l θ'' + 2θ' + (g/b²)θ = 0, with θ' = zθ and θ'' = (z' + z²)θ
    eq7 = length * (dzr + zr**2) * theta + 2 * zr * theta + g / b**2 * theta
    dz = sp.solve(eq7, dzr)[0]
    dv = dz.subs(zr, vr - 1 / length) - sp.diff(-1 / length, length)
    return reference({"dzr_dl": dz, "dvr_dl": dv}, "(7) with θ = exp ∫z dl, z = v − 1/l")


def reference_u_of_x() -> Any:
    """(9), line 116, from (7): u = θl, x = gl/b², d²u/dx² = (b²/g)²(lθ'' + 2θ') with θ'' from
    (7)."""
    length, g, b, theta, dtheta = symbols("l", "g", "b", "theta", "dtheta_dl")
    d2theta = sp.solve(length * sp.Symbol("q_") + 2 * dtheta + g / b**2 * theta, sp.Symbol("q_"))[0]
    exact = {
        "u": theta * length,
        "x": g * length / b**2,
        "d2u_dx2": (b**2 / g) ** 2 * (length * d2theta + 2 * dtheta),
    }
    return reference(exact, "(7) with u = θl, l = (b²/g)x")


def reference_u_of_x_shortened() -> Any:
    """Line 218, « au lieu de s'allonger, aille en se raccourcissant »: (9) from (7) as in
    reference_u_of_x, the speed b replaced by −b throughout."""
    (b,) = symbols("b")
    built = reference_u_of_x()
    exact = {name: value.subs(b, -b) for name, value in built.exact.items()}
    return reference(exact, "(7) with u = θl, l = (b²/g)x, b → −b")


def reference_speed_of_lengthening() -> Any:
    """Line 64: the rate of l = a + bt (line 62), for b > 0 (« sauf avis contraire »)."""
    a, b, t = symbols("a", "b", "t")
    return reference({"dl_dt": (a + b * t).diff(t)}, "l = a + bt")


def reference_shortening() -> Any:
    """Lines 690-698, (30): (3) with b → −b (line 694: « nous mettons en évidence le signe de b »),
    then z = a/b − t, s = g/b (line 696): dθ/dt = −dθ/dz, d²θ/dt² = d²θ/dz²."""
    a, b, t, g, zt, dtheta_dzt = symbols("a", "b", "t", "g", "zt", "dtheta_dzt")

    exact = _cartesian_exact(True)
    d2 = exact["d2theta_dt2"].subs(b, -b)  # θ'' of (3) for l = a − bt
    dtheta_dt = sp.Symbol("dtheta_dt", real=True)
    in_z = d2.subs({t: a / b - zt, dtheta_dt: -dtheta_dzt}, simultaneous=True)
    return reference(
        {"d2theta_dt2": d2, "d2theta_dzt2": in_z, "s": g / b}, "(3) for l = a − bt, z = a/b − t"
    )
