"""Lecornu, IV. Pendule conique de longueur variable: (43)-(52).

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import (
    P_SWEEP,
    PI,
    equation_check,
    is_rational_zero,
    is_zero,
    judged_series,
    linear_reduced_ode,
    sympy_module,
)
from pendcli.papers.lecornu.equations_general import substitute_all
from pendcli.papers.lecornu.equations_slow import eq25_residuals
from pendcli.papers.taylor import taylor


# ================================================================ IV. Pendule conique
def eq_43() -> EquationCheck:
    sp = sympy_module()
    t, g, c = sp.symbols("t g c", positive=True)
    l, th = sp.Function("l")(t), sp.Function("theta")(t)
    r, z = l * sp.sin(th), l * sp.cos(th)
    eliminated = r * z.diff(t, 2) - z * r.diff(t, 2) - g * r + c**2 * z / r**3
    printed = (
        (l**2 * th.diff(t)).diff(t)
        + g * l * sp.sin(th)
        - c**2 * sp.cos(th) / (l**2 * sp.sin(th) ** 3)
    )
    return equation_check(
        is_zero(eliminated + printed), "sympy", "r z'' − z r'' − g r + c²z/r³ = −(43)"
    )


def eq_44() -> EquationCheck:
    sp = sympy_module()
    t = sp.Symbol("t")
    l, th, ph = (sp.Function(n)(t) for n in ("l", "theta", "phi"))
    x, y = l * sp.sin(th) * sp.cos(ph), l * sp.sin(th) * sp.sin(ph)
    return equation_check(
        is_zero(x * y.diff(t) - y * x.diff(t) - l**2 * sp.sin(th) ** 2 * ph.diff(t)),
        "sympy",
        "x y' − y x' = l² sin²θ φ'",
    )


def result_conical_linear_form() -> EquationCheck:
    """(43)/l with l = a + bt: the last term is c² cos θ/(l³ sin³θ) (printed l²)."""
    sp = sympy_module()
    t, a, b, g, c = sp.symbols("t a b g c", positive=True)
    th = sp.Function("theta")(t)
    l = a + b * t
    eq43 = (
        (l**2 * th.diff(t)).diff(t)
        + g * l * sp.sin(th)
        - c**2 * sp.cos(th) / (l**2 * sp.sin(th) ** 3)
    )

    def form(power: int) -> Any:
        return (
            l * th.diff(t, 2)
            + 2 * b * th.diff(t)
            + g * sp.sin(th)
            - c**2 * sp.cos(th) / (l**power * sp.sin(th) ** 3)
        )

    return equation_check(
        is_zero(eq43 / l - form(3)) and not is_zero(eq43 / l - form(2)),
        "sympy",
        "(43)/l has c² cos θ/(l³ sin³θ); the printed l² (twice) is not (43)/l, while the next "
        "u-equation follows from l³",
    )


def eq_45() -> EquationCheck:
    sp = sympy_module()
    x, b, c, g = sp.symbols("x b c g", positive=True)
    v = sp.Function("v")(x)
    u = v * sp.sqrt(b * c / g)
    eq = u.diff(x, 2) + u / x - b**2 * c**2 / g**2 / u**3
    return equation_check(
        is_zero(eq / sp.sqrt(b * c / g) - (v.diff(x, 2) + v / x - 1 / v**3)),
        "sympy",
        "u = v√(bc/g)",
    )


def _conical_general() -> tuple[Any, ...]:
    sp = sympy_module()
    x, s, x0 = sp.symbols("x s x0", positive=True)
    big_a, big_b = sp.symbols("A B", positive=True)
    om = sp.Function("omega")
    integral = sp.Integral(1 / om(s) ** 2, (s, x0, x)) + big_b
    w1 = om(x) / sp.sqrt(big_a)
    w2 = sp.sqrt(big_a) * om(x) * integral
    rules = {om(x).diff(x, 2): -om(x) / x}
    return x, om, w1, w2, rules


def result_conical_general_integral() -> EquationCheck:
    sp = sympy_module()
    x, _om, w1, w2, rules = _conical_general()
    v = sp.sqrt(w1**2 + w2**2)
    residual = substitute_all((v.diff(x, 2) + v / x - 1 / v**3).doit(integrals=False), rules)
    return equation_check(
        is_rational_zero(residual), "sympy", "v = √(ω²/A + Aω²(∫dx/ω² + B)²) solves (45)"
    )


def eq_46() -> EquationCheck:
    x, _om, w1, w2, rules = _conical_general()
    ok = is_rational_zero(substitute_all((x * w2.diff(x, 2) + w2).doit(integrals=False), rules))
    ok = ok and is_rational_zero((w1 * w2.diff(x) - w2 * w1.diff(x)).doit(integrals=False) - 1)
    return equation_check(ok, "sympy", "ω2 solves (9) and ω1ω2' − ω2ω1' = 1")


def eq_47() -> EquationCheck:
    sp = sympy_module()
    w1, w2, k, L = sp.symbols("omega1 omega2 K l", positive=True)
    return equation_check(
        is_zero(k / L * sp.sqrt(w1**2 + w2**2) - sp.sqrt((k * w1 / L) ** 2 + (k * w2 / L) ** 2)),
        "sympy",
        "θ = (K/l)√(ω1² + ω2²) = √(θ1² + θ2²), K = √(bc/g)",
    )


def eq_48() -> EquationCheck:
    sp = sympy_module()
    t, a, b, g, kk = sp.symbols("t a b g K", positive=True)
    w = sp.Function("W")
    l = a + b * t
    th = kk * w(g * l / b**2) / l
    eq = (l * th.diff(t, 2) + 2 * b * th.diff(t) + g * th).doit()
    x = sp.Symbol("x", positive=True)
    nine = (x * w(x).diff(x, 2) + w(x)).subs(x, g * l / b**2).doit()
    return equation_check(
        is_zero(eq - kk * g * nine / l), "sympy", "(48) = (Kg/l)·(9) at x = gl/b²"
    )


def eq_49() -> EquationCheck:
    sp = sympy_module()
    t, a, b, g, c = sp.symbols("t a b g c", positive=True)
    w1, w2 = sp.Function("W1"), sp.Function("W2")
    l, kk = a + b * t, sp.sqrt(b * c / g)
    x = g * l / b**2
    th1, th2 = kk * w1(x) / l, kk * w2(x) / l
    wr = (th1 * th2.diff(t) - th2 * th1.diff(t)).doit()
    xs = sp.Symbol("x", positive=True)
    w46 = (w1(xs) * w2(xs).diff(xs) - w2(xs) * w1(xs).diff(xs)).subs(xs, x).doit()
    return equation_check(
        is_zero(wr - c / l**2 * w46), "sympy", "θ1θ2' − θ2θ1' = (c/l²)(ω1ω2' − ω2ω1')"
    )


def eq_50() -> EquationCheck:
    r1, r2 = eq25_residuals(0.7), eq25_residuals(-0.4)
    return judged_series(
        [max(a, b) for a, b in zip(r1, r2, strict=True)], 2, "(25) at ψ1 = 0.7, ψ2 = −0.4"
    )


def eq_51() -> EquationCheck:
    """(49) with (50) to first order in p: ρ1ρ2γ sin(ψ2 − ψ1)(1 − 2pγt) = (c/a²)(1 − 2pγt)."""
    sp = sympy_module()
    t, p, p1, p2, r1, r2 = sp.symbols("t p psi1 psi2 rho1 rho2", real=True)

    def th(rho: Any, psi: Any) -> Any:
        return rho * (1 - sp.Rational(3, 4) * p * t) * sp.sin(
            t - psi
        ) - rho * p * t**2 / 4 * sp.cos(t - psi)

    wr = th(r1, p1) * th(r2, p2).diff(t) - th(r2, p2) * th(r1, p1).diff(t)
    first = taylor(wr, p, 2)
    reading = r1 * r2 * sp.sin(p2 - p1) * (1 - 2 * p * t)
    ok = is_zero(sp.expand_trig(first - reading))
    return equation_check(
        ok,
        "sympy",
        "γ = 1: θ1θ2' − θ2θ1' = ρ1ρ2 sin(ψ2 − ψ1)(1 − 2pγt) + O(p²); the "
        "printed sin(ψ1 − ψ2) has the opposite sign (and (52)'s ρ1ρ2 = c a^(−3/2)/√g with "
        "ψ1 = −π/2, ψ2 = 0 follows only from sin(ψ2 − ψ1))",
    )


def eq_52() -> EquationCheck:
    """(52) read as θ1/ρ1 = cos u − (pu/4)(3 cos u − u sin u),
    θ2/ρ2 = sin u − (pu/4)(3 sin u + u cos u)."""
    grid = np.linspace(0, 2 * PI, 401)
    one = linear_reduced_ode(
        P_SWEEP, tuple(1.0 for _ in P_SWEEP), tuple(-0.75 * p for p in P_SWEEP), 2 * PI
    )(grid)
    two = linear_reduced_ode(
        P_SWEEP, tuple(0.0 for _ in P_SWEEP), tuple(1.0 for _ in P_SWEEP), 2 * PI
    )(grid)
    c, s = np.cos(grid), np.sin(grid)
    res = []
    for j, p in enumerate(P_SWEEP):
        f1 = c - p * grid / 4 * (3 * c - grid * s)
        f2 = s - p * grid / 4 * (3 * s + grid * c)
        res.append(float(max(np.max(np.abs(one[j] - f1)), np.max(np.abs(two[j] - f2)))))
    return judged_series(res, 2, "(52) as read, both components, against (3) linearised")
