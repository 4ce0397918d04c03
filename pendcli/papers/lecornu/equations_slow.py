"""Lecornu, II (end): slow variation, (25)-(29).

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import (
    P_SWEEP,
    PI,
    Array,
    equation_check,
    from_formulas,
    is_zero,
    judged_series,
    linear_reduced_ode,
    sympy_module,
    trig_form,
    trig_text,
)
from pendcli.papers.taylor import taylor


# ================================================================ II (end): (25)-(29)
def _eq25(t: Array, p: float, psi: float) -> Array:
    return (1 - 0.75 * p * t) * np.sin(t - psi) - p * t**2 / 4 * np.cos(t - psi)


def eq25_residuals(psi: float) -> list[float]:
    theta0 = tuple(-math.sin(psi) for _ in P_SWEEP)
    omega0 = tuple(math.cos(psi) + 0.75 * p * math.sin(psi) for p in P_SWEEP)
    sol = linear_reduced_ode(P_SWEEP, theta0, omega0, 2 * PI)
    grid = np.linspace(0, 2 * PI, 401)
    y = sol(grid)
    return [float(np.max(np.abs(y[j] - _eq25(grid, p, psi)))) for j, p in enumerate(P_SWEEP)]


def eq_25() -> EquationCheck:
    return judged_series(
        eq25_residuals(0.7), 2, "(25) at ψ = 0.7 against (3) linearised, 0 ≤ γt ≤ 2π"
    )


def result_cr_note_formula() -> EquationCheck:
    """Footnote: the 1894 note's formula with ω = ψ + p/8 is (25) up to O(p²)?"""
    sp = sympy_module()
    t, p, psi, rho = sp.symbols("t p psi rho", real=True)
    eq25 = rho * (1 - sp.Rational(3, 4) * p * t) * sp.sin(t - psi) - rho * p * t**2 / 4 * sp.cos(
        t - psi
    )

    def note(last: Any) -> Any:
        om = psi + p / 8
        return rho * (1 - sp.Rational(3, 4) * p * t) * sp.sin(t - om) + rho * p / 8 * last * sp.cos(
            t - om
        )

    first = sp.simplify(taylor(note(1 - t**2) - eq25, p, 2))
    fixed = sp.simplify(taylor(note(1 - 2 * t**2) - eq25, p, 2))
    return equation_check(
        first == 0,
        "sympy",
        f"note − (25) to first order in p (γ = 1): {first}; with (1 − 2γ²t²) in the last term: "
        f"{fixed}",
        corrected="the note's last term must be ρ(k/8)(1 − 2γ²t²) cos(γt − ω) to agree with "
        "(25); as printed the two differ by ρpγ²t² cos(γt − ψ)/8 at first order",
    )


def result_psi_definition() -> EquationCheck:
    """'Remplaçons 2/p − φ par ψ': sin(2/p + γt − φ) = sin(γt − ψ) needs ψ = φ − 2/p."""
    sp = sympy_module()
    t, p, ph = sp.symbols("t p varphi", real=True)
    reading = sp.sin(2 / p + t - ph) - sp.sin(t - (ph - 2 / p))
    printed = sp.sin(2 / p + t - ph) - sp.sin(t - (2 / p - ph))
    return equation_check(
        is_zero(reading) and not is_zero(sp.expand_trig(printed)),
        "sympy",
        "with ψ = φ − 2/p the argument is γt − ψ; with the printed ψ = 2/p − φ it is γt + ψ",
    )


def eq_26() -> EquationCheck:
    return from_formulas("eq26")


def result_table_26() -> EquationCheck:
    return from_formulas(
        "table26.first_elongation",
        "table26.second_vertical",
        "table26.first_negative_elongation",
        "table26.third_vertical",
    )


def eq_27() -> EquationCheck:
    sp = sympy_module()
    t, p, gam = sp.symbols("t p gamma", positive=True)
    big_u = sp.Function("U")
    x = (1 + p * gam * t) / p**2
    u = big_u(x)
    expr = ((1 + p * gam * t) * u.diff(t, 2) + gam**2 * u).doit()
    xs = sp.Symbol("x", positive=True)
    nine = (xs * big_u(xs).diff(xs, 2) + big_u(xs)).subs(xs, x).doit()
    return equation_check(
        is_zero(expr - gam**2 * nine), "sympy", "(27) = γ²·(9) with x = (1 + pγt)/p²"
    )


def result_perturbation_hierarchy() -> EquationCheck:
    """u1 = cos γt∫u0'' t sin γt − sin γt∫u0'' t cos γt solves u1'' + γ²u1 = −γt u0'' (γ = 1)."""
    sp = sympy_module()
    t, s = sp.symbols("t s", positive=True)
    u0 = sp.sin(s)
    f = u0.diff(s, 2) * s
    u1 = sp.cos(t) * sp.integrate(f * sp.sin(s), (s, 0, t)) - sp.sin(t) * sp.integrate(
        f * sp.cos(s), (s, 0, t)
    )
    ok = is_zero(u1.diff(t, 2) + u1 + t * (-sp.sin(t))) and u1.subs(t, 0) == 0
    ok = ok and sp.simplify(u1.diff(t).subs(t, 0)) == 0
    return equation_check(ok, "sympy", f"u1 = {sp.simplify(u1)}; ODE and zero initial values exact")


def eq28_solution(sp: Any, t: Any, p: Any) -> Any:
    """Lecornu's (28) as printed (γ = 1): the solution of (27) to p², read by (28) and (29)."""
    s, c = sp.sin(t), sp.cos(t)
    return (
        s
        + p * t / 4 * (s - t * c)
        + p**2 / 32 * ((2 * t**3 - 3 * t) * c + (3 - 3 * t**2 - t**4) * s)
    )


def eq_28() -> EquationCheck:
    """(28) satisfies (27) up to p³ (γ = 1), with u(0) = 0, u'(0) = 1."""
    sp = sympy_module()
    t, p = sp.symbols("t p", positive=True)
    u = eq28_solution(sp, t, p)
    residual = sp.expand((1 + p * t) * u.diff(t, 2) + u)
    low = [sp.simplify(residual.coeff(p, n)) for n in range(3)]
    ok = low == [0, 0, 0] and u.subs(t, 0) == 0 and sp.simplify(u.diff(t).subs(t, 0) - 1) == 0
    return equation_check(
        ok, "sympy", "coefficients of p⁰, p¹, p² of the residual vanish; the p³ one does not"
    )


def result_period_second_order() -> EquationCheck:
    return from_formulas("period_second_order")


def result_mean_pendulum() -> EquationCheck:
    return from_formulas("mean_pendulum")


def eq_29() -> EquationCheck:
    """(29) = (28)/(1 + pγt) to p²: the p² bracket found exactly."""
    sp = sympy_module()
    t, p = sp.symbols("t p", positive=True)
    u = eq28_solution(sp, t, p)
    theta2 = sp.expand(taylor(u / (1 + p * t), p, 3)).coeff(p, 2) * 32
    s, c = sp.sin(t), sp.cos(t)
    printed2 = (10 * t**3 - 3 * t) * c + (3 - 43 * t**2 - t**4) * s
    found = trig_text(trig_form(theta2, t)).replace("u", "τ")
    return equation_check(
        is_zero(theta2 - printed2),
        "sympy",
        f"32× the p² coefficient of (28)/(1 + pγt), τ = γt: {found}; numeric: "
        + from_formulas("eq29").detail,
        corrected=f"θ = sin τ − (pτ/4)(3 sin τ + τ cos τ) + (p²/32)[{found}], τ = γt",
    )
