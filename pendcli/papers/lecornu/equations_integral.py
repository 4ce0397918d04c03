"""Lecornu, II: the definite-integral solution, second (18)-(22), the asymptotic forms (23), (24).

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from pendcli.core.formula_engine import DEFAULT_REFERENCE, Study, judge, leading_coefficient
from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import (
    P_SWEEP,
    PI,
    equation_check,
    from_formulas,
    is_zero,
    sympy_module,
)


# --- the definite-integral solution and the asymptotic forms: second (18)-(22), (23), (24)
def _integral_u(x: Any, alpha: Any, power: int = 3) -> Any:
    """x[∫cos(2√x cos ω + α) sin²ω dω + sin α ∫e^(−2√x tg ω) dω/cos^power ω] (mpmath)."""
    import mpmath

    r = 2 * mpmath.sqrt(x)
    first = mpmath.quad(
        lambda w: mpmath.cos(r * mpmath.cos(w) + alpha) * mpmath.sin(w) ** 2, [0, mpmath.pi / 2]
    )
    second = mpmath.quad(
        lambda w: mpmath.exp(-r * mpmath.tan(w)) / mpmath.cos(w) ** power,
        [0, mpmath.pi / 4, mpmath.pi / 2],
    )
    return x * (first + mpmath.sin(alpha) * second)


def eq_18_integral() -> EquationCheck:
    """Second (18): the integral is (π√x/4)[cos α J1(2√x) − sin α Y1(2√x)], a solution of (9)."""
    import mpmath

    with mpmath.workdps(20):
        alpha = mpmath.mpf("0.6")
        worst = 0.0
        for x in (mpmath.mpf("0.3"), mpmath.mpf(2), mpmath.mpf(7)):
            r = 2 * mpmath.sqrt(x)
            closed = (
                mpmath.pi
                * mpmath.sqrt(x)
                / 4
                * (
                    mpmath.cos(alpha) * mpmath.besselj(1, r)
                    - mpmath.sin(alpha) * mpmath.bessely(1, r)
                )
            )
            worst = max(worst, float(abs(_integral_u(x, alpha) - closed)))
        return equation_check(
            worst < 1e-12,
            "numeric",
            f"quadrature minus (π√x/4)(cos α J1 − sin α Y1) at x = 0.3, 2, 7 (α = 0.6): <= "
            f"{worst:.0e}; √x C1(2√x) solves (9) for any cylinder function C1",
        )


def result_c_equals_4_over_pi() -> EquationCheck:
    import mpmath

    with mpmath.workdps(20):
        worst = max(
            float(
                abs(
                    mpmath.sqrt(x) * mpmath.besselj(1, 2 * mpmath.sqrt(x))
                    - 4 / mpmath.pi * _integral_u(x, 0)
                )
            )
            for x in (mpmath.mpf("0.5"), mpmath.mpf(3))
        )
        return equation_check(
            worst < 1e-14, "numeric", f"φ − (4/π)x∫cos(2√x cos ω) sin²ω dω: {worst:.0e}"
        )


def eq_19_integral() -> EquationCheck:
    """Second (19) read with dω/cos³ω (as in (18)): θ = u/l with C = (b²/g)k."""
    import mpmath

    with mpmath.workdps(20):
        x, alpha = mpmath.mpf(2), mpmath.mpf("0.6")
        reading = _integral_u(x, alpha, 3) / x  # θ/k = u/(Cx)
        printed = _integral_u(x, alpha, 2) / x
        closed = (
            mpmath.pi
            / (4 * mpmath.sqrt(x))
            * (
                mpmath.cos(alpha) * mpmath.besselj(1, 2 * mpmath.sqrt(x))
                - mpmath.sin(alpha) * mpmath.bessely(1, 2 * mpmath.sqrt(x))
            )
        )
        return equation_check(
            abs(reading - closed) < 1e-12,
            "numeric",
            f"x = 2, α = 0.6: θ/k with cos³ω = {float(reading):.10f} = u/(Cx) = "
            f"{float(closed):.10f}; "
            f"with the printed cos²ω {float(printed):.10f}",
        )


def result_small_x_asymptotics() -> EquationCheck:
    """u/(Cx) − (sin α/4)(1/x − log x) tends to a finite limit as x → 0."""
    import mpmath

    with mpmath.workdps(30):
        alpha = mpmath.mpf("0.6")
        rest = []
        for x in (mpmath.mpf("1e-4"), mpmath.mpf("1e-6"), mpmath.mpf("1e-8")):
            r = 2 * mpmath.sqrt(x)
            ratio = (
                mpmath.pi
                / (4 * mpmath.sqrt(x))
                * (
                    mpmath.cos(alpha) * mpmath.besselj(1, r)
                    - mpmath.sin(alpha) * mpmath.bessely(1, r)
                )
            )
            rest.append(float(ratio - mpmath.sin(alpha) / 4 * (1 / x - mpmath.log(x))))
        return equation_check(
            abs(rest[-1] - rest[-2]) < 1e-4,
            "numeric",
            "remainder at x = 1e-4, 1e-6, 1e-8: "
            + ", ".join(f"{v:.6f}" for v in rest)
            + " (converges: the growing part is (sin α/4)(1/x − log x))",
        )


def eq_20_asymptotic() -> EquationCheck:
    """Second (20): v = x^(1/4) cos 2√x solves x v'' + (1 + 3/(16x)) v = 0 exactly."""
    sp = sympy_module()
    x, p = sp.symbols("x p", positive=True)
    v = x**p * sp.cos(2 * sp.sqrt(x))
    d2_printed = (p * (p - 1) * x ** (p - 2) - x ** (p - 1)) * sp.cos(2 * sp.sqrt(x)) - (
        2 * p - sp.Rational(1, 2)
    ) * x ** (p - sp.Rational(3, 2)) * sp.sin(2 * sp.sqrt(x))
    quarter = sp.Rational(1, 4)
    ok = is_zero(v.diff(x, 2) - d2_printed)
    for f in (sp.cos, sp.sin):
        w = x**quarter * f(2 * sp.sqrt(x))
        ok = ok and is_zero(x * w.diff(x, 2) + (1 + sp.Rational(3, 16) / x) * w)
    return equation_check(
        ok, "sympy", "printed v'' for any p; at p = 1/4 the residual is −3v/(16x)"
    )


def eq_21_asymptotic() -> EquationCheck:
    sp = sympy_module()
    L, b, g, a_, b_ = sp.symbols("l b g A B", positive=True)
    x = g * L / b**2
    u = x ** sp.Rational(1, 4) * (a_ * sp.cos(2 * sp.sqrt(x)) + b_ * sp.sin(2 * sp.sqrt(x)))
    printed = (
        (g / b**2) ** sp.Rational(1, 4)
        * (a_ * sp.cos(2 * sp.sqrt(g * L) / b) + b_ * sp.sin(2 * sp.sqrt(g * L) / b))
        / L ** sp.Rational(3, 4)
    )
    return equation_check(is_zero(u / L - printed), "sympy", "θ = u/l with x = gl/b²")


def eq_22_asymptotic() -> EquationCheck:
    sp = sympy_module()
    s, a_, b_ = sp.symbols("s A B", real=True)
    r, ph = sp.sqrt(a_**2 + b_**2), sp.atan2(-a_, b_)
    return equation_check(
        is_zero(sp.expand_trig(r * sp.sin(s - ph)) - a_ * sp.cos(s) - b_ * sp.sin(s)),
        "sympy",
        "A cos s + B sin s = R sin(s − φ), R = √(A² + B²), tg φ = −A/B",
    )


def eq_23() -> EquationCheck:
    """(23) and the interval between passages: πb/(4g)[2φ + (2m+1)π] = π√(l/g) + π²b/(4g)."""
    sp = sympy_module()
    b, g, L, ph, m = sp.symbols("b g l varphi m", positive=True)
    length = lambda lam: b**2 / (4 * g) * (ph + lam * sp.pi) ** 2  # noqa: E731
    interval = (length(m + 1) - length(m)) / b
    at_l = interval.subs(ph, 2 * sp.sqrt(g * L) / b - m * sp.pi)
    ok = is_zero(interval - sp.pi * b / (4 * g) * (2 * ph + (2 * m + 1) * sp.pi))
    ok = ok and is_zero(at_l - (sp.pi * sp.sqrt(L / g) + sp.pi**2 * b / (4 * g)))
    return equation_check(ok, "sympy", "exact, given the length at the first passage")


def result_oscillation_time_increase() -> EquationCheck:
    return from_formulas("oscillation_time_increase")


def result_elongation_condition() -> EquationCheck:
    sp = sympy_module()
    L, b, g, _ph, r = sp.symbols("l b g varphi R", positive=True)
    arg = sp.Symbol("X")  # 2√(gl)/b − φ, dX/dl = √g/(b√l)
    d = sp.expand(
        r * L ** sp.Rational(-3, 4) * sp.cos(arg) * sp.sqrt(g) / (b * sp.sqrt(L))
        + r * sp.Rational(-3, 4) * L ** sp.Rational(-7, 4) * sp.sin(arg)
    )
    tan_needed = -d.coeff(sp.cos(arg)) / d.coeff(sp.sin(arg))
    ok = is_zero(tan_needed - 4 * sp.sqrt(g * L) / (3 * b))
    return equation_check(ok, "sympy", "dθ/dl = 0 ⇔ tg(2√(gl)/b − φ) = 4√(gl)/(3b)")


def eq_24() -> EquationCheck:
    """(24): tg X = 4√(gl)/(3b), X = (2λ+1)π/2 − ε ⇒ ε = 3b/(4√(gl)) + O(b³)."""
    sp = sympy_module()
    q = sp.Symbol("q", positive=True)  # b/√(gl)
    eps = sp.atan(3 * q / 4)  # cot ε = 4/(3q)
    return equation_check(
        sp.series(eps - 3 * q / 4, q, 0, 3).removeO() == 0,
        "sympy",
        "ε = arctg(3b/(4√(gl))) = 3b/(4√(gl)) + O((b/√(gl))³)",
    )


def result_vertical_to_elongation() -> EquationCheck:
    """Vertical → elongation: (π/2)√(l/g) + (π² − 12)b/(16g) = … − 0,13 b/g (printed 12b)."""
    sp = sympy_module()
    from pendcli.papers.lecornu.model import half_oscillation_coefficient_exact

    s_ = sp.Symbol("s", positive=True)  # √(gl)/b, large
    # (23), (24): 2S = 2s + π/2 − 3/(4S) for S = √(gl'')/b; S = s + π/4 − 3/(8s) + O(s⁻²)
    big_s = s_ + sp.pi / 4 - sp.Rational(3, 8) / s_
    check_s = sp.limit((2 * big_s - 2 * s_ - sp.pi / 2 + 3 / (4 * big_s)) * s_, s_, sp.oo)
    derived = sp.limit(sp.expand(big_s**2 - s_**2) - sp.pi * s_ / 2, s_, sp.oo)  # ×b/g: time
    exact = half_oscillation_coefficient_exact()
    reading = (PI**2 - 12) / 16
    ok = check_s == 0 and is_zero(derived - (sp.pi**2 - 12) / 16) and abs(exact - reading) < 1e-6
    return equation_check(
        ok,
        "numeric",
        f"series of (23), (24): constant term {derived}; exact Bessel solution, b → 0: "
        f"{exact:.8f}; (π² − 12)/16 = {reading:.8f}",
    )


def result_largest_length_comparison() -> EquationCheck:
    """Against the largest length: ascending half shortened by (3π² + 12)b/(16g), the
    descending one 'shortened' by (π² − 12)b/(16g) (negative: it is lengthened)."""
    from pendcli.papers.lecornu.formulas import event_times

    ev = event_times(DEFAULT_REFERENCE)
    ps = np.array(P_SWEEP)
    longest = PI / 2 * np.sqrt(1 + ps * ev["vertical2"])
    ascending = longest - ev["elong1"]  # shortening of the ascending half
    descending = longest - (ev["vertical2"] - ev["elong1"])
    ca = leading_coefficient(P_SWEEP, tuple(ascending), 1)
    cd = leading_coefficient(P_SWEEP, tuple(descending), 1)
    ra, rd = (3 * PI**2 + 12) / 16, (PI**2 - 12) / 16
    return equation_check(
        abs(ca - ra) < 1e-4 and abs(cd - rd) < 1e-4,
        "numeric",
        f"(3) linearised from a vertical passage, shortening ×g/b fitted: ascending {ca:.6f} "
        f"((3π² + 12)/16 = {ra:.6f}), descending {cd:.6f} ((π² − 12)/16 = {rd:.6f}: a "
        "negative shortening, i.e. the descending half is 0,133 b/g longer)",
    )


def result_amplitude_factor() -> EquationCheck:
    """|θ| at an elongation ∝ cos(3b/(4√(gl)))/l^(3/4), to the first order in b/√(gl)."""
    import mpmath

    from pendcli.core.formula_engine import identify

    with mpmath.workdps(30):
        delta = mpmath.mpf("0.3")

        def c(nu: int, z: Any) -> Any:
            return mpmath.cos(delta) * mpmath.besselj(nu, z) + mpmath.sin(delta) * mpmath.bessely(
                nu, z
            )

        qs, residuals = [], []
        for n in (4, 8, 16, 32, 64):  # elongations further and further out: q = b/√(gl) = 2/z
            guess = (
                n * mpmath.pi + mpmath.pi / 4 - delta + mpmath.pi
            )  # McMahon, C2 ~ cos(z − 5π/4 + δ)
            z = mpmath.findroot(lambda w: c(2, w), guess)
            amplitude = abs(c(1, z)) * mpmath.sqrt(mpmath.pi * z / 2)  # → R l^(-3/4) × factor
            qs.append(float(2 / z))
            residuals.append(float(amplitude - mpmath.cos(3 / (2 * z))))
        second = leading_coefficient(qs, residuals, 2)
        verdict = _judged_params(residuals, 2, qs)
        name = identify(second, rel=1e-4) or f"{second:.6f}"
        return equation_check(
            verdict[0],
            "numeric",
            f"exact cylinder function, amplitude·l^(3/4) normalised at l → ∞ minus "
            f"cos(3b/(4√(gl))): order {verdict[1]:.2f} in b/√(gl) (claimed 2); leading residual "
            f"{name}·b²/(gl), so to second order the factor is cos(3b/(4√(gl)))(1 + {name} "
            "b²/(gl)), which the author then neglects",
            observed_order=verdict[1],
            claimed_order=2,
        )


def _judged_params(residuals: Sequence[float], order: float, params: Sequence[float]) -> tuple:
    verdict, observed, _ = judge(Study("q", tuple(params), tuple(residuals), order, 1e-25))
    return verdict == "holds", observed if observed is not None else float("nan")


def result_elongation_ratio() -> EquationCheck:
    return from_formulas("elongation_ratio")
