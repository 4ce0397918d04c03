"""Lecornu, II: the general integral (17)-(22) and the continuation rules (17'), (21').

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import (
    bessel_solution,
    equation_check,
    is_zero,
    phi_solution,
    sympy_module,
)


# --- (17)-(22): the general integral -------------------------------------------------------
def _generic_phi() -> tuple[Any, ...]:
    """x, φ(x), the rule φ'' = −φ/x (and φ''' from it) as a substitution."""
    sp = sympy_module()
    x, s, x0 = sp.symbols("x s x0", positive=True)
    phi = sp.Function("phi")
    rules = {
        phi(x).diff(x, 3): -phi(x).diff(x) / x + phi(x) / x**2,
        phi(x).diff(x, 2): -phi(x) / x,
    }
    return x, s, x0, phi, rules


def substitute_all(expr: Any, rules: dict[Any, Any]) -> Any:
    for old, new in rules.items():
        expr = expr.subs(old, new)
    return expr


def _seventeen() -> tuple[Any, ...]:
    sp = sympy_module()
    x, s, x0, phi, rules = _generic_phi()
    a, b = sp.symbols("A B")
    integral = sp.Integral(1 / phi(s) ** 2, (s, x0, x))
    u = a * phi(x) + b * phi(x) * integral
    return u, x, phi, rules, a, b, integral


def eq_17() -> EquationCheck:
    u, x, _phi_fn, rules, *_ = _seventeen()
    residual = substitute_all(x * u.diff(x, 2) + u, rules)
    return equation_check(is_zero(residual), "sympy", "x u'' + u = 0 given x φ'' + φ = 0")


def eq_18() -> EquationCheck:
    u, x, phi, _rules, a, b, integral = _seventeen()
    printed = a * phi(x).diff(x) + b / phi(x) + b * phi(x).diff(x) * integral
    return equation_check(is_zero(u.diff(x) - printed), "sympy", "derivative of (17)")


def eq_19() -> EquationCheck:
    u, x, phi, _rules, _a, b, _ = _seventeen()
    return equation_check(
        is_zero(phi(x) * u.diff(x) - phi(x).diff(x) * u - b), "sympy", "φu' − φ'u = B"
    )


def eq_20() -> EquationCheck:
    u, x, phi, _rules, _a, b, _ = _seventeen()
    return equation_check(
        is_zero((u / phi(x)).diff(x) - b / phi(x) ** 2), "sympy", "d(u/φ)/dx = B/φ²"
    )


def result_xref_monotone() -> EquationCheck:
    """'L'équation (10) montre que u/φ varie toujours dans le même sens': it is (20)."""
    u, x, phi, _rules, _a, b, _ = _seventeen()
    slope = (u / phi(x)).diff(x)
    return equation_check(
        is_zero(slope * phi(x) ** 2 - b),
        "cross-reference",
        "(20): d(u/φ)/dx = B/φ², of the sign of B on the whole interval; (10) (the series "
        "of φ) says nothing about u/φ",
    )


def _exact_u(x0: float, a_const: float, b_const: float) -> tuple[Callable[[float], float], ...]:
    """The solution of (9) with u = Aφ, φu' − φ'u = B at x0, as αφ + βχ (χ = √x Y1(2√x))."""
    phi, dphi = phi_solution()
    chi, dchi = bessel_solution(math.pi / 2)
    u0 = a_const * phi(x0)
    du0 = a_const * dphi(x0) + b_const / phi(x0)
    det = phi(x0) * dchi(x0) - dphi(x0) * chi(x0)  # Wronskian 1/π
    alpha = (u0 * dchi(x0) - du0 * chi(x0)) / det
    beta = (phi(x0) * du0 - dphi(x0) * u0) / det
    return (lambda x: alpha * phi(x) + beta * chi(x)), phi, dphi


X0, X1, X2 = 2.5, 5.0, 9.0  # φ has roots at 3.67 and 12.3, φ' at 1.45 and 7.62 (x units)
A0, B0 = 0.7, 0.4


def result_u_at_roots() -> EquationCheck:
    """At a root β of φ, (19) gives u = −B/φ'(β) (printed −B/φ, with φ = 0 there)."""
    from scipy.optimize import brentq

    u, phi, dphi = _exact_u(X0, A0, B0)
    beta = brentq(phi, 3.0, 4.0, xtol=1e-15)
    value, predicted = u(beta), -B0 / dphi(beta)
    return equation_check(
        abs(value - predicted) < 1e-12,
        "numeric",
        f"exact solution (A = {A0}, B = {B0} at x0 = {X0}): u(β = {beta:.6f}) = {value:.12f}, "
        f"−B/φ'(β) = {predicted:.12f}",
    )


def result_one_vertical_between_j1_zeros() -> EquationCheck:
    """Exactly one zero of u = √x C1(2√x) between consecutive zeros of J1 (five phases)."""
    from scipy.special import jn_zeros

    zeros = jn_zeros(1, 8)
    counts = set()
    for delta in np.linspace(0.3, 2.9, 5):
        u, _ = bessel_solution(float(delta))
        for lo, hi in itertools.pairwise(zeros):
            grid = np.linspace(lo, hi, 400)[1:-1]
            vals = np.array([u((z / 2) ** 2) for z in grid])
            counts.add(int(np.sum(np.signbit(vals[:-1]) != np.signbit(vals[1:]))))
    return equation_check(counts == {1}, "numeric", f"sign changes per interval: {sorted(counts)}")


def result_integration_by_parts() -> EquationCheck:
    """∫dx/φ² = 1/(φ0φ'0) − 1/(φφ') − ∫φ'' dx/(φφ'²) (printed φ' in the last integrand)."""
    from scipy.integrate import quad

    phi, dphi = phi_solution()
    x = 3.2
    lhs, _ = quad(lambda s: 1 / phi(s) ** 2, X0, x, epsabs=1e-13)
    ends = 1 / (phi(X0) * dphi(X0)) - 1 / (phi(x) * dphi(x))
    reading, _ = quad(lambda s: -phi(s) / s / (phi(s) * dphi(s) ** 2), X0, x, epsabs=1e-13)
    printed, _ = quad(lambda s: dphi(s) / (phi(s) * dphi(s) ** 2), X0, x, epsabs=1e-13)
    final, _ = quad(lambda s: 1 / (s * dphi(s) ** 2), X0, x, epsabs=1e-13)
    ok = abs(lhs - (ends - reading)) < 1e-10 and abs(lhs - (ends + final)) < 1e-10
    return equation_check(
        ok,
        "numeric",
        f"x0 = {X0}, x = {x}: ∫dx/φ² = {lhs:.10f}; with φ'' (= −φ/x) the right side is "
        f"{ends - reading:.10f}; with the printed φ' it is {ends - printed:.10f}",
    )


def eq_21() -> EquationCheck:
    sp = sympy_module()
    x, s, x0, phi, rules = _generic_phi()
    b, c = sp.symbols("B C")
    dphi = phi(x).diff(x)
    u = c * phi(x) - b / dphi + b * phi(x) * sp.Integral(1 / (s * phi(s).diff(s) ** 2), (s, x0, x))
    residual = substitute_all(x * u.diff(x, 2) + u, rules)
    return equation_check(
        is_zero(residual.doit(integrals=False)), "sympy", "x u'' + u = 0 given x φ'' + φ = 0"
    )


def eq_22() -> EquationCheck:
    """(22) = derivative of (21); and u'φ − uφ' = B."""
    sp = sympy_module()
    x, s, x0, phi, rules = _generic_phi()
    b, c = sp.symbols("B C")
    dphi = phi(x).diff(x)
    integral = sp.Integral(1 / (s * phi(s).diff(s) ** 2), (s, x0, x))
    u = c * phi(x) - b / dphi + b * phi(x) * integral
    printed = c * dphi + b * dphi * integral
    du = substitute_all(u.diff(x), rules)
    ok = is_zero((du - printed).doit(integrals=False)) and is_zero(
        (printed * phi(x) - u * dphi - b).doit(integrals=False)
    )
    return equation_check(ok, "sympy", "u' of (21) with φ'' = −φ/x; and u'φ − uφ' = B")


def _quad(f: Callable[[float], float], lo: float, hi: float) -> float:
    from scipy.integrate import quad

    return float(quad(f, lo, hi, epsabs=1e-13, epsrel=1e-12, limit=200)[0])


def _continuation() -> dict[str, float]:
    """A' (after the root β of φ) and C' (after the root α' of φ'), exact and as printed."""
    u, phi, dphi = _exact_u(X0, A0, B0)
    pp = {x: phi(x) * dphi(x) for x in (X0, X1, X2)}
    a_exact = u(X1) / phi(X1)  # (17') at x = x1
    c0 = A0 + B0 / pp[X0]
    c_exact = (u(X2) + B0 / dphi(X2)) / phi(X2)  # (21') at x = x2
    over_root = _quad(lambda s: 1 / (s * dphi(s) ** 2), X0, X1)
    over_droot = _quad(lambda s: 1 / phi(s) ** 2, X1, X2)
    return {
        "a_exact": a_exact,
        "a_printed": A0 + B0 * (1 / pp[X0] - 1 / pp[X1]),
        "a_corrected": A0 + B0 * (1 / pp[X0] - 1 / pp[X1] + over_root),
        "c_exact": c_exact,
        "c_printed": c0 + B0 * (1 / pp[X2] - 1 / pp[X0]),
        "c_corrected": c0 + B0 * (1 / pp[X2] - 1 / pp[X1] + over_root + over_droot),
    }


def eq_17_prime() -> EquationCheck:
    """(17') past β: u = A'φ + Bφ∫_(x1)^x dx/φ² with the same B (checked at x = 6)."""
    u, phi, _ = _exact_u(X0, A0, B0)
    a_new = _continuation()["a_exact"]
    x = 6.0
    form = a_new * phi(x) + B0 * phi(x) * _quad(lambda s: 1 / phi(s) ** 2, X1, x)
    return equation_check(
        abs(form - u(x)) < 1e-10,
        "numeric",
        f"exact solution at x = {x}: {u(x):.12f}; (17') with A' = u(x1)/φ(x1): {form:.12f}",
    )


def eq_21_prime() -> EquationCheck:
    """(21') past α': u = C'φ − B/φ' + Bφ∫_(x2)^x dx/(xφ'²), same B (checked at x = 10)."""
    u, phi, dphi = _exact_u(X0, A0, B0)
    c_new = _continuation()["c_exact"]
    x = 10.0
    form = (
        c_new * phi(x) - B0 / dphi(x) + B0 * phi(x) * _quad(lambda s: 1 / (s * dphi(s) ** 2), X2, x)
    )
    return equation_check(
        abs(form - u(x)) < 1e-10,
        "numeric",
        f"exact solution at x = {x}: {u(x):.12f}; (21') with C' from x2: {form:.12f}",
    )


def result_constant_a_prime() -> EquationCheck:
    """A' − A = B(1/(φ0φ'0) − 1/(φ1φ'1)), from identifying (21) and (17')."""
    v = _continuation()
    return equation_check(
        abs(v["a_exact"] - v["a_printed"]) < 1e-9,
        "numeric",
        f"x0 = {X0}, x1 = {X1}, A = {A0}, B = {B0}: A' of the exact solution "
        f"{v['a_exact']:.10f}; printed relation {v['a_printed']:.10f}; with the integral "
        f"added {v['a_corrected']:.10f}",
        corrected="A' − A = B[1/(φ0φ'0) − 1/(φ1φ'1) + ∫_(x0)^(x1) dx/(xφ'²)] (the integral "
        "term of (21) between x0 and x1 was dropped)",
    )


def result_constant_c_prime() -> EquationCheck:
    """C' − C = B(1/(φ2φ'2) − 1/(φ0φ'0)) across a root α' of φ'."""
    v = _continuation()
    return equation_check(
        abs(v["c_exact"] - v["c_printed"]) < 1e-9,
        "numeric",
        f"x2 = {X2}: C' of the exact solution {v['c_exact']:.10f}; printed relation "
        f"{v['c_printed']:.10f}; with the two integrals {v['c_corrected']:.10f}",
        corrected="C' − C = B[1/(φ2φ'2) − 1/(φ1φ'1) + ∫_(x0)^(x1) dx/(xφ'²) + ∫_(x1)^(x2) "
        "dx/φ²] (x1 any point between the root of φ and that of φ')",
    )


def result_general_constants() -> EquationCheck:
    """The general rule: in the k-th interval of φ, A_k = A + B(1/(φ0φ'0) − 1/(φkφ'k))."""
    u, phi, dphi = _exact_u(X0, A0, B0)
    xk = 15.0  # between the roots 12.3 and 24.6 of φ, two roots of φ/φ' away from x0
    a_exact = u(xk) / phi(xk)
    a_printed = A0 + B0 * (1 / (phi(X0) * dphi(X0)) - 1 / (phi(xk) * dphi(xk)))
    return equation_check(
        abs(a_exact - a_printed) < 1e-9,
        "numeric",
        f"x_k = {xk}: A_k of the exact solution {a_exact:.10f}, printed rule {a_printed:.10f} "
        "(the same omission as in A' and C'; the second rule also prints −B/φ for −B/φ')",
        corrected="each passage over a root of φ adds B∫dx/(xφ'²) over the step and each "
        "passage over a root of φ' adds B∫dx/φ² (see A', C')",
    )


def result_initial_constants() -> EquationCheck:
    """u'0 = (b²/g)θ0 + (ab/g)ω0; A, B, C from (17), (18), (19) and C = A + B/(φ0φ'0)."""
    sp = sympy_module()
    a, b, g, t = sp.symbols("a b g t", positive=True)
    th0, om0, p0, dp0 = sp.symbols("theta0 omega0 phi0 dphi0")
    theta = sp.Function("theta")(t)
    u = theta * (a + b * t)
    du_dx = u.diff(t) / (g / b)  # x = g(a + bt)/b², dx/dt = g/b
    du0 = du_dx.subs(t, 0).subs({theta.diff(t).subs(t, 0): om0}).subs(theta.subs(t, 0), th0)
    ok = is_zero(du0 - (b**2 / g * th0 + a * b / g * om0))
    big_a = a * th0 / p0
    big_b = p0 * du0 - dp0 * a * th0  # (19) at x0
    ok = ok and is_zero(big_b - (b / g * p0 * (b * th0 + a * om0) - a * dp0 * th0))
    c = big_a + big_b / (p0 * dp0)
    ok = ok and is_zero(c - b / g * (b * th0 + a * om0) / dp0)
    return equation_check(
        ok, "sympy", "u'0, B = φ0u'0 − φ'0u0 and C = A + B/(φ0φ'0) reduce as printed"
    )


def result_limit_u_at_zero() -> EquationCheck:
    """φ∫_(x0)^x dx/φ² → a finite non-zero limit as x → 0 (it is −1: u → −B)."""
    import mpmath

    with mpmath.workdps(20):

        def phi(s: Any) -> Any:
            return mpmath.sqrt(s) * mpmath.besselj(1, 2 * mpmath.sqrt(s))

        x0 = mpmath.mpf(2)
        values = []
        for x in (mpmath.mpf("1e-4"), mpmath.mpf("1e-6"), mpmath.mpf("1e-8")):
            pts = [x * 10**j for j in range(int(-mpmath.log10(x)) + 1) if x * 10**j < x0] + [x0]
            values.append(float(phi(x) * -mpmath.quad(lambda s: 1 / phi(s) ** 2, pts)))
        return equation_check(
            abs(values[-1] + 1) < 1e-6,
            "numeric",
            "φ∫_(x0)^x dx/φ² at x = 1e-4, 1e-6, 1e-8 (x0 = 2, mpmath): "
            + ", ".join(f"{v:.8f}" for v in values)
            + " → −1, so u → −B (finite, non-zero) and θ = gu/(b²x) grows without bound",
        )
