"""Lecornu, III. Oscillations finies: (30)-(42').

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from pendcli.core.formula_engine import DEFAULT_REFERENCE
from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import (
    all_zero,
    equation_check,
    from_formulas,
    is_zero,
    sympy_module,
    trig_form,
    trig_text,
)
from pendcli.papers.taylor import taylor


# ================================================================ III. Oscillations finies
def eq_30() -> EquationCheck:
    sp = sympy_module()
    t, a, b, g = sp.symbols("t a b g", positive=True)
    big = sp.Function("Theta")
    th = big(a / b - t)
    eq = ((a - b * t) * th.diff(t, 2) - 2 * b * th.diff(t) + g * sp.sin(th)).doit()
    z = sp.Symbol("z", positive=True)
    printed = z * big(z).diff(z, 2) + 2 * big(z).diff(z) + g / b * sp.sin(big(z))
    return equation_check(
        is_zero(eq.subs(t, a / b - z).doit() - b * printed), "sympy", "z = a/b − t, s = g/b"
    )


def eq_31() -> EquationCheck:
    """(31) by the quadratures with β = 0 (nested w), and against (30) numerically."""
    sp = sympy_module()
    z, z0, _s, al, y = sp.symbols("z z0 s alpha y", positive=True)
    v = -sp.integrate(sp.integrate(y * sp.sin(al), (y, z0, z)) / z**2, (z, z0, z))
    inner = sp.integrate((y * v.subs(z, y) * sp.cos(al)), (y, z0, z))
    w = -sp.integrate(inner / z**2, (z, z0, z))
    printed_v = -sp.sin(al) / (2 * z) * (z - z0) ** 2
    printed_w = (
        sp.sin(2 * al)
        / 12
        * ((z - z0) * (z**2 - 5 * z * z0 - 2 * z0**2) / (2 * z) + 3 * z0**2 * sp.log(z / z0))
    )
    ok = is_zero(v - printed_v) and is_zero(
        sp.expand_log(sp.expand_trig(w - printed_w), force=True)
    )
    numeric = from_formulas("eq31")
    return equation_check(
        ok and numeric.holds,
        "sympy",
        "v and the nested w = −∫dz/z²∫z v cos α dz equal the printed terms exactly; "
        + numeric.detail,
        observed_order=numeric.observed_order,
        claimed_order=numeric.claimed_order,
    )


def result_s_expansion() -> EquationCheck:
    """θ = u + vs + ws² in (30): the orders s⁰, s¹, s² (printed w''s, w's for w''s², w's²)."""
    sp = sympy_module()
    z, s = sp.symbols("z s", positive=True)
    u, v, w = (sp.Function(n)(z) for n in "uvw")
    th = u + v * s + w * s**2
    expr = sp.expand(taylor(z * th.diff(z, 2) + 2 * th.diff(z) + s * sp.sin(th), s, 3))
    ok = all_zero(
        expr.coeff(s, 0) - (z * u.diff(z, 2) + 2 * u.diff(z)),
        expr.coeff(s, 1) - (z * v.diff(z, 2) + 2 * v.diff(z) + sp.sin(u)),
        expr.coeff(s, 2) - (z * w.diff(z, 2) + 2 * w.diff(z) + v * sp.cos(u)),
    )
    return equation_check(ok, "sympy", "the three printed equations are the orders s⁰, s¹, s²")


def eq_32() -> EquationCheck:
    sp = sympy_module()
    t, a, b, g = sp.symbols("t a b g", positive=True)
    big = sp.Function("Theta")
    uu = sp.Symbol("u", positive=True)
    gam, p = sp.sqrt(g / a), b / sp.sqrt(g * a)
    th = big(gam * t)
    eq3 = ((a + b * t) * th.diff(t, 2) + 2 * b * th.diff(t) + g * sp.sin(th)).doit()
    printed = (
        big(uu).diff(uu, 2)
        + sp.sin(big(uu))
        + p * (uu * big(uu).diff(uu, 2) + 2 * big(uu).diff(uu))
    )
    return equation_check(
        is_zero(eq3.subs(t, uu / gam).doit() - g * printed), "sympy", "(3)/g with u = γt"
    )


def eq_33() -> EquationCheck:
    sp = sympy_module()
    uu, p = sp.symbols("u p")
    th = sp.Function("theta")(uu)
    eq32 = th.diff(uu, 2) + sp.sin(th) + p * (uu * th.diff(uu, 2) + 2 * th.diff(uu))
    return equation_check(
        is_zero(eq32.subs(p, 0) - (th.diff(uu, 2) + sp.sin(th))), "sympy", "(32) at p = 0"
    )


def _pendulum_vs_cn() -> tuple[float, float]:
    import mpmath

    k = 0.6
    theta0 = 2 * math.asin(k)
    sol = DEFAULT_REFERENCE.solve(lambda t, y: [y[1], -math.sin(y[0])], 8.0, [theta0, 0.0])
    worst34 = worst35 = 0.0
    for u in np.linspace(0, 8, 41):
        th = float(sol(u)[0])
        cn = float(mpmath.ellipfun("cn", u + 0.0, m=k * k))
        worst34 = max(worst34, abs(math.tan(th / 2) - math.tan(theta0 / 2) * cn))
        worst35 = max(worst35, abs(th - 2 * math.atan(k / math.sqrt(1 - k * k) * cn)))
    return worst34, worst35


def eq_34() -> EquationCheck:
    w, _ = _pendulum_vs_cn()
    return equation_check(
        w < 1e-9,
        "numeric",
        f"θ0 = 2 arcsin 0.6, C = 0, 0 ≤ u ≤ 8: max |tg θ/2 − tg(θ0/2) cn u| = {w:.1e}",
    )


def eq_35() -> EquationCheck:
    _, w = _pendulum_vs_cn()
    return equation_check(w < 1e-9, "numeric", f"as (34): max |θ − 2 arctg((k/k')cn u)| = {w:.1e}")


def eq_37() -> EquationCheck:
    """(37): solve (36) and (32) for dk/du, dC/du (θ_C = θ_u, θ_uC = θ_uu, θ_uu = −sin θ)."""
    sp = sympy_module()
    kp, cp, p, uu, tc, tk, tuk, tuc, tu, tuu = sp.symbols("kp cp p u t_C t_k t_uk t_uC t_u t_uu")
    eqs = [
        tk * kp + tc * cp,  # (36)
        (1 + p * uu) * (tuk * kp + tuc * cp) + p * (uu * tuu + 2 * tu),  # (32) minus (33)
    ]
    sol = sp.solve(eqs, [kp, cp], dict=True)[0]
    det = (1 + p * uu) * (tc * tuk - tk * tuc)
    printed_k = p * (2 * tu + uu * tuu) * tc / det
    printed_c = -p * (2 * tu + uu * tuu) * tk / det
    ok = is_zero(sol[kp] - printed_k) and is_zero(sol[cp] - printed_c)
    opposite = is_zero(sol[kp] + printed_k) and is_zero(sol[cp] + printed_c)
    return equation_check(
        ok,
        "sympy",
        "solving the linear system gives the printed expressions with the opposite sign"
        if opposite
        else "solved",
        corrected="dk/du = −p(2θ_u + uθ_uu)θ_C/[(1 + pu)(θ_Cθ_uk − θ_kθ_uC)], dC/du = "
        "+p(2θ_u + uθ_uu)θ_k/[(1 + pu)(θ_Cθ_uk − θ_kθ_uC)]",
    )


def eq_38() -> EquationCheck:
    return from_formulas("eq38")


def eq_39() -> EquationCheck:
    sp = sympy_module()
    uu, p = sp.symbols("u p")
    om, ep = sp.Function("omega")(uu), sp.Function("epsilon")(uu)
    th = om + p * ep
    eq32 = th.diff(uu, 2) + sp.sin(th) + p * (uu * th.diff(uu, 2) + 2 * th.diff(uu))
    first = sp.expand(taylor(eq32, p, 2)).coeff(p, 1)
    printed = ep.diff(uu, 2) + ep * sp.cos(om) + (uu * om.diff(uu, 2) + 2 * om.diff(uu))
    return equation_check(
        is_zero(first - printed), "sympy", "first order in p of (32) with θ = ω + pε"
    )


def _f_beta() -> tuple[Any, Any, Any]:
    sp = sympy_module()
    uu = sp.Symbol("u")
    f = 9 * sp.cos(uu) + 12 * uu * sp.sin(uu) - sp.cos(3 * uu)
    beta = (uu**2 * sp.sin(uu) - 3 * uu * sp.cos(uu) + 3 * sp.sin(uu)) / 2
    return uu, f, beta


def eq_40() -> EquationCheck:
    sp = sympy_module()
    uu, f, beta = _f_beta()
    k = sp.Symbol("k")
    om = 2 * k * sp.cos(uu) + k**3 / 24 * f
    cos_om = taylor(sp.cos(om), k, 3)
    big_f = -(uu * om.diff(uu, 2) + 2 * om.diff(uu))
    a = 2 * uu * sp.cos(uu) + 4 * sp.sin(uu)
    b = -(uu * f.diff(uu, 2) + 2 * f.diff(uu)) / 24
    ok = is_zero(cos_om - (1 - 2 * k**2 * sp.cos(uu) ** 2)) and is_zero(big_f - a * k - b * k**3)
    ok = ok and is_zero(beta.diff(uu, 2) + beta - a) and beta.subs(uu, 0) == 0
    return equation_check(
        ok, "sympy", "cos ω to k², F = Ak + Bk³ exactly; β solves β'' + β = A, β(0) = β'(0) = 0"
    )


def result_two_beta_cos2() -> EquationCheck:
    sp = sympy_module()
    uu, _, beta = _f_beta()
    printed = (uu**2 + 3) / 4 * (sp.sin(uu) + sp.sin(3 * uu)) + 3 * uu / 4 * (
        sp.cos(3 * uu) + 3 * sp.cos(uu)
    )
    found = trig_form(2 * beta * sp.cos(uu) ** 2, uu)
    return equation_check(
        is_zero(sp.expand_trig(2 * beta * sp.cos(uu) ** 2 - printed)),
        "sympy",
        f"2β cos²u = {trig_text(found)}",
        corrected="2β cos²u = ((u² + 3)/4)(sin u + sin 3u) − (3u/4)(cos 3u + 3 cos u)",
    )


def result_delta_rhs() -> EquationCheck:
    sp = sympy_module()
    uu, f, beta = _f_beta()
    b = -(uu * f.diff(uu, 2) + 2 * f.diff(uu)) / 24
    rhs = trig_form(b + 2 * beta * sp.cos(uu) ** 2, uu)
    h = sp.Rational(1, 2)
    printed = (
        sp.Rational(3, 4) * uu**2 * sp.sin(uu)
        + sp.Rational(5, 8) * uu * sp.cos(uu)
        + h * sp.sin(uu)
        + uu**2 * sp.sin(3 * uu) / 4
        + sp.Rational(3, 8) * uu * sp.cos(3 * uu)
        + h * sp.sin(3 * uu)
    )
    text = trig_text(rhs)
    return equation_check(
        trig_form(printed, uu) == rhs,
        "sympy",
        f"B + 2β cos²u = {text}",
        corrected=f"δ'' + δ = {text}",
    )


def eq_41() -> EquationCheck:
    return from_formulas("eq41_terms_in_p")


def eq_42() -> EquationCheck:
    return from_formulas("eq42_terms_in_b")


def eq_42_prime() -> EquationCheck:
    return from_formulas("eq42prime_terms_in_b")


def result_t_equals_t_prime() -> EquationCheck:
    """T = T' after (42), read with (π² ± 12)b/(16g) (printed 12b), to first order in b."""
    sp = sympy_module()
    p = sp.Symbol("p", positive=True)  # times in √(a/g), b/g = p√(a/g)
    big_t = sp.pi / 2 + (sp.pi**2 + 12) * p / 16  # (42) at k = 0
    length = 1 + p * big_t
    t_prime = sp.pi / 2 * sp.sqrt(length) - (sp.pi**2 - 12) * p / 16  # reversed motion
    diff = taylor(t_prime - big_t, p, 2)
    return equation_check(is_zero(diff), "sympy", f"T' − T = {sp.simplify(diff)} + O(p²)")


def homothety_check() -> EquationCheck:
    return from_formulas("homothety_ratio")
