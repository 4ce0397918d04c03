"""Lecornu, I. Équation du mouvement: (1)-(9) and the compound pendulum.

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import (
    all_zero,
    equation_check,
    from_formulas,
    is_zero,
    sympy_module,
)
from pendcli.papers.taylor import taylor


# ================================================================ I. Equation du mouvement
def _plane_symbols() -> tuple[Any, ...]:
    sp = sympy_module()
    t, g = sp.symbols("t g", positive=True)
    return t, g, sp.Function("l")(t), sp.Function("theta")(t)


def eq_1() -> EquationCheck:
    """(1) from x = l sin θ, y = l cos θ: x y'' − y x'' − g x = 0 is d(l²θ')/dt + g l sin θ = 0."""
    sp = sympy_module()
    t, g, l, th = _plane_symbols()
    x, y = l * sp.sin(th), l * sp.cos(th)
    eliminated = x * y.diff(t, 2) - y * x.diff(t, 2) - g * x
    areal = (l**2 * th.diff(t)).diff(t) + g * l * sp.sin(th)
    printed = l * th.diff(t, 2) + 2 * l.diff(t) * th.diff(t) + g * sp.sin(th)
    ok = all_zero(eliminated + areal, areal - l * printed)
    return equation_check(ok, "sympy", "x y'' − y x'' − g x = −[d(l²θ')/dt + g l sin θ] = −l·(1)")


def eq_2() -> EquationCheck:
    """(2): T = (g y − x x'' − y y'')/l from the two equations of motion."""
    sp = sympy_module()
    t, g, l, th = _plane_symbols()
    x, y = l * sp.sin(th), l * sp.cos(th)
    tension = (g * y - x * x.diff(t, 2) - y * y.diff(t, 2)) / l
    printed = g * sp.cos(th) + l * th.diff(t) ** 2 - l.diff(t, 2)
    return equation_check(is_zero(tension - printed), "sympy", "x·(x eq.) + y·(y eq.) solved for T")


def _with_length(expr: Any, length: Any) -> Any:
    sp = sympy_module()
    _t, _, l, _ = _plane_symbols()
    return sp.simplify(expr.subs(l, length).doit())


def eq_3() -> EquationCheck:
    """(3) = (1) with l = a + bt."""
    sp = sympy_module()
    t, g, l, th = _plane_symbols()
    a, b = sp.symbols("a b", positive=True)
    eq1 = l * th.diff(t, 2) + 2 * l.diff(t) * th.diff(t) + g * sp.sin(th)
    printed = (a + b * t) * th.diff(t, 2) + 2 * b * th.diff(t) + g * sp.sin(th)
    return equation_check(
        is_zero(_with_length(eq1, a + b * t) - printed), "sympy", "(1) at l = a + bt"
    )


def eq_4() -> EquationCheck:
    """(4) = (2) with l = a + bt (l'' = 0)."""
    sp = sympy_module()
    t, g, l, th = _plane_symbols()
    a, b = sp.symbols("a b", positive=True)
    eq2 = g * sp.cos(th) + l * th.diff(t) ** 2 - l.diff(t, 2)
    printed = g * sp.cos(th) + (a + b * t) * th.diff(t) ** 2
    return equation_check(
        is_zero(_with_length(eq2, a + b * t) - printed), "sympy", "(2) at l = a + bt"
    )


def _in_length(expr_of_t: Callable[[Any], Any]) -> tuple[Any, Any, Any]:
    """(expression in t evaluated on θ(t) = Θ(a + bt), rewritten in l; Θ(l); l, b, g)."""
    sp = sympy_module()
    t, g = sp.symbols("t g", positive=True)
    a, b, L = sp.symbols("a b L", positive=True)
    big = sp.Function("Theta")
    expr = expr_of_t(big(a + b * t)).subs(t, (L - a) / b).doit()
    return sp.simplify(expr), big(L), (L, b, g, t)


def eq_5() -> EquationCheck:
    """(5): (3) with θ(t) = Θ(l), dθ/dt = b dΘ/dl, divided by b²."""
    sp = sympy_module()
    t, g = sp.symbols("t g", positive=True)
    a, b = sp.symbols("a b", positive=True)

    def eq3(th: Any) -> Any:
        return (a + b * t) * th.diff(t, 2) + 2 * b * th.diff(t) + g * sp.sin(th)

    expr, big, (L, b, g, _) = _in_length(eq3)
    printed = L * big.diff(L, 2) + 2 * big.diff(L) + g / b**2 * sp.sin(big)
    return equation_check(is_zero(expr / b**2 - printed), "sympy", "(3)/b² in the variable l")


def eq_6() -> EquationCheck:
    """(6) read as d²(θl)/dl² + (g/b²) sin θ = 0, i.e. (5); printed d²/dt² is b² times that."""
    sp = sympy_module()
    L, b, g = sp.symbols("L b g", positive=True)
    big = sp.Function("Theta")(L)
    eq5 = L * big.diff(L, 2) + 2 * big.diff(L) + g / b**2 * sp.sin(big)
    reading = (big * L).diff(L, 2) + g / b**2 * sp.sin(big)
    printed_t = b**2 * (big * L).diff(L, 2) + g / b**2 * sp.sin(big)  # d/dt = b d/dl
    ok = is_zero(reading - eq5) and not is_zero(printed_t - b**2 * eq5)
    return equation_check(
        ok,
        "sympy",
        "d²(θl)/dl² = lθ'' + 2θ' gives (5) exactly; with d²/dt² = b² d²/dl² the printed form "
        "is b²(θl)'' + (g/b²) sin θ, not proportional to (5) unless b = 1",
    )


def result_compound_expansion() -> EquationCheck:
    """l' = a + bt + R²/(a + bt) ≈ a + R²/a + b(1 − R²/a²)t to first order in bt/a."""
    sp = sympy_module()
    a, b, big_r, t = sp.symbols("a b R t", positive=True)
    exact = a + b * t + big_r**2 / (a + b * t)
    series = taylor(exact, t, 2)
    printed = a + big_r**2 / a + b * (1 - big_r**2 / a**2) * t
    return equation_check(is_zero(series - printed), "sympy", "first-order Taylor series in t")


def result_compound_pendulum() -> EquationCheck:
    return from_formulas("compound_pendulum")


def eq_7() -> EquationCheck:
    """(7): (5) with sin θ replaced by its first-order term."""
    sp = sympy_module()
    th = sp.Symbol("theta")
    return equation_check(
        sp.series(sp.sin(th), th, 0, 3).removeO() == th, "sympy", "sin θ = θ + O(θ³)"
    )


def eq_8() -> EquationCheck:
    """θ = exp∫z dl in (7), then z = v − 1/l: the Riccati equation (8)."""
    sp = sympy_module()
    L, kk = sp.symbols("L k", positive=True)
    big_z = sp.Function("Zint")(L)  # ∫ z dl
    th = sp.exp(big_z)
    eq7 = (L * th.diff(L, 2) + 2 * th.diff(L) + kk * th) / (L * th)
    z = big_z.diff(L)
    z_eq = z.diff(L) + z**2 + 2 * z / L + kk / L
    v = sp.Function("v")(L)
    z_of_v = v - 1 / L
    printed_z = z_of_v.diff(L) + z_of_v**2 + 2 * z_of_v / L + kk / L
    ok = is_zero(eq7 - z_eq) and is_zero(printed_z - (v.diff(L) + v**2 + kk / L))
    return equation_check(ok, "sympy", "both substitutions exact (k = g/b²)")


def eq_9() -> EquationCheck:
    """(9) from (6) linearised with θl = u, l = (b²/g)x: (g/b²)²(x u'' + u)/x."""
    sp = sympy_module()
    x, b, g = sp.symbols("x b g", positive=True)
    big_u = sp.Function("U")(x)
    L = b**2 * x / g
    d_dl = lambda f: f.diff(x) * g / b**2  # noqa: E731 - chain rule, dl = (b²/g) dx
    th = big_u / L
    eq7 = L * d_dl(d_dl(th)) + 2 * d_dl(th) + g / b**2 * th
    expected = (g / b**2) ** 2 * (x * big_u.diff(x, 2) + big_u) / x
    return equation_check(is_zero(eq7 - expected), "sympy", "(7) = (g/b²)²(x u'' + u)/x")
