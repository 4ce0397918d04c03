"""Lecornu, II. Oscillations infiniment petites: (9)-(16), the graphical equation, J₁ and J₂.

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np

from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import (
    bessel_solution,
    equation_check,
    is_zero,
    sympy_module,
)


# ============================================== II. Oscillations infiniment petites: (9)-(16)
def result_graphical_equation() -> EquationCheck:
    """x = z/c in (9): d(z u_z − u)/dz + u/c = 0, and h = u − z u_z has dh/dz = u/c."""
    sp = sympy_module()
    z, c = sp.symbols("z c", positive=True)
    u = sp.Function("u")(z)
    big_u = sp.Function("U")
    nine = (z / c) * big_u(z / c).diff(z, 2) * c**2 + big_u(z / c)  # x U''(x) + U, x = z/c
    printed = (z * u.diff(z) - u).diff(z) + u / c
    h = u - z * u.diff(z)
    # h' = −(z u_z − u)', so the printed equation is exactly dh/dz = u/c
    ok = is_zero(printed.subs(u, big_u(z / c)).doit() - nine / c) and is_zero(
        h.diff(z) + (printed - u / c)
    )
    return equation_check(
        ok, "sympy", "c·[(z u_z − u)_z + u/c] = x U_xx + U with x = z/c; dh/dz = u/c"
    )


def result_inflection_at_vertical() -> EquationCheck:
    """From the graphical equation u_zz = −u/(cz): the curvature vanishes exactly where u = 0."""
    sp = sympy_module()
    z, c, u = sp.symbols("z c u", positive=True)
    u_zz = -u / (c * z)
    return equation_check(
        sp.solve(sp.Eq(u_zz, 0), u) == [0] or u_zz.subs(u, 0) == 0,
        "sympy",
        "u_zz = −u/(cz) vanishes iff u = 0 (z > 0), and changes sign with u",
    )


def result_curvature_proportional() -> EquationCheck:
    """'La courbure varie proportionnellement à l'écart horizontal': κ ≈ u_zz = −u/(cz)."""
    sp = sympy_module()
    z, c, u = sp.symbols("z c u", positive=True)
    ratio = (-u / (c * z)) / u  # curvature per unit horizontal deviation
    varies = sp.diff(ratio, z) != 0
    return equation_check(
        not varies,
        "sympy",
        f"κ/u = {ratio} depends on z: over one oscillation of a pendulum whose length doubles, "
        "κ/u halves; κ·z/u = −1/c is the constant",
        corrected="κ ≈ −u/(cz) = −(g/b²)θ: the curvature is proportional to the angle θ = u/z "
        "(horizontal deviation divided by the length), not to the horizontal deviation u",
    )


def result_area_theorem() -> EquationCheck:
    """∫u dz = 0 between two elongations (where h = u − z u_z = 0), exact Bessel solutions."""
    from scipy.integrate import quad
    from scipy.optimize import brentq
    from scipy.special import jv, yv

    worst = 0.0
    for delta in (0.7, 2.1):
        u, _ = bessel_solution(delta)
        c2 = lambda z, d=delta: math.cos(d) * jv(2, z) + math.sin(d) * yv(2, z)  # noqa: E731
        grid = np.linspace(3.0, 20.0, 200)
        vals = c2(grid)
        roots = [
            brentq(c2, grid[i], grid[i + 1], xtol=1e-14)
            for i in range(len(grid) - 1)
            if vals[i] * vals[i + 1] < 0
        ]
        xs = [(r / 2) ** 2 for r in roots]
        for x1, x2 in itertools.pairwise(xs):
            area, _ = quad(u, x1, x2, epsabs=1e-12, limit=200)
            scale, _ = quad(lambda x, f=u: abs(f(x)), x1, x2, limit=200)
            worst = max(worst, abs(area) / scale)
    return equation_check(
        worst < 1e-9,
        "numeric",
        f"u = √x C1(2√x) (two phases), elongations at the zeros of C2: max |∫u dx|/∫|u| dx "
        f"between successive elongations = {worst:.1e}",
    )


def _frobenius(n_terms: int) -> list[Any]:
    """Coefficients of the solution x + … of x φ'' + φ = 0: a_(n+1) = −a_n/(n(n+1))."""
    from fractions import Fraction

    coef = [Fraction(0), Fraction(1)]
    for n in range(1, n_terms):
        coef.append(-coef[n] / (n * (n + 1)))
    return coef


def eq_10() -> EquationCheck:
    """(10): φ = Σ (−1)^(n−1) n xⁿ/(n!)², against the ODE's recursion and √x J1(2√x)."""
    from fractions import Fraction

    import mpmath

    coef = _frobenius(30)
    printed = [Fraction((-1) ** (n - 1) * n, math.factorial(n) ** 2) for n in range(1, 30)]
    series_ok = coef[1:30] == printed
    with mpmath.workdps(30):
        x = mpmath.mpf("3.7")
        total = sum(
            mpmath.mpf(c.numerator) / c.denominator * x**n for n, c in enumerate(printed, 1)
        )
        err = abs(total - mpmath.sqrt(x) * mpmath.besselj(1, 2 * mpmath.sqrt(x)))
        return equation_check(
            series_ok and err < 1e-25,
            "numeric",
            f"29 coefficients equal the recursion of x φ'' + φ = 0 exactly; at x = 3.7 the series "
            f"minus √x J1(2√x) (mpmath, 30 digits) = {float(err):.1e}",
        )


def eq_11() -> EquationCheck:
    """(11): φ' = Σ (−1)^n xⁿ/(n!)² = J0(2√x)."""
    from fractions import Fraction

    import mpmath

    coef = _frobenius(30)
    derived = [n * coef[n] for n in range(1, 30)]  # coefficient of x^(n−1)
    printed = [Fraction((-1) ** n, math.factorial(n) ** 2) for n in range(29)]
    with mpmath.workdps(30):
        x = mpmath.mpf("3.7")
        total = sum(mpmath.mpf(c.numerator) / c.denominator * x**n for n, c in enumerate(printed))
        err = abs(total - mpmath.besselj(0, 2 * mpmath.sqrt(x)))
        return equation_check(
            derived == printed and err < 1e-25,
            "numeric",
            f"term-by-term derivative of (10) equals the printed series; minus J0(2√3.7) = "
            f"{float(err):.1e}",
        )


def eq_12() -> EquationCheck:
    """(12): at an elongation θ = gφ/(b²x) is stationary: d(φ/x)/dx = 0 ⇔ φ' = φ/x."""
    sp = sympy_module()
    x, b, g = sp.symbols("x b g", positive=True)
    phi = sp.Function("phi")(x)
    theta = g * phi / (b**2 * x)
    stationary = sp.solve(sp.Eq(theta.diff(x), 0), phi.diff(x))
    return equation_check(
        len(stationary) == 1 and is_zero(stationary[0] - phi / x),
        "sympy",
        "dθ/dx = 0 solved for φ' gives φ/x",
    )


def eq_13() -> EquationCheck:
    """(13): (φ/x − φ')/x = Σ (−1)^k (k+1)(k+2) x^k/((k+2)!)²."""
    from fractions import Fraction

    coef = _frobenius(30)
    derived = [coef[k + 2] - (k + 2) * coef[k + 2] for k in range(27)]  # (φ/x − φ')/x
    printed = [
        Fraction((-1) ** k * (k + 1) * (k + 2), math.factorial(k + 2) ** 2) for k in range(27)
    ]
    return equation_check(derived == printed, "sympy", "27 coefficients equal exactly (rationals)")


def result_eq13_is_j2() -> EquationCheck:
    """'Le premier membre de (13) est J2(2√x)': compare with mpmath."""
    import mpmath

    with mpmath.workdps(30):
        x = mpmath.mpf("2.5")
        coef = _frobenius(40)
        lhs = sum((coef[k + 2] - (k + 2) * coef[k + 2]) * x**k for k in range(37))
        j2 = mpmath.besselj(2, 2 * mpmath.sqrt(x))
        return equation_check(
            abs(lhs - j2) < 1e-20,
            "numeric",
            f"at x = 2.5: left side of (13) = {float(lhs):.10f}, J2(2√x) = {float(j2):.10f}, "
            f"J2(2√x)/x = {float(j2 / x):.10f}",
            corrected="the left side of (13) is J2(2√x)/x (same non-zero roots)",
        )


def eq_14() -> EquationCheck:
    """(14) read as 2J1(z) = zJ0(z) ((1/√x)J1 = J0 with 2√x = z): its roots are those of J2."""
    import mpmath

    with mpmath.workdps(25):
        worst, printed_gap = 0.0, 0.0
        for k in range(1, 6):
            zk = mpmath.besseljzero(2, k)
            worst = max(worst, float(abs(2 * mpmath.besselj(1, zk) - zk * mpmath.besselj(0, zk))))
            printed_gap = max(
                printed_gap, float(abs(mpmath.besselj(1, zk) - mpmath.besselj(0, zk)))
            )
        return equation_check(
            worst < 1e-20,
            "numeric",
            f"at the first five zeros of J2, |2J1 − zJ0| <= {worst:.0e} (mpmath); the printed "
            f"zJ1 = zJ0 is off there by up to {printed_gap:.2f}·z",
        )


def result_roots_interlace() -> EquationCheck:
    """Each elongation root (zero of J2) lies between two zeros of J1, near their mean."""
    import mpmath

    worst = 0.0
    ok = True
    for k in range(1, 8):
        lo, hi = mpmath.besseljzero(1, k), mpmath.besseljzero(1, k + 1)
        z2 = mpmath.besseljzero(2, k)
        ok = ok and lo < z2 < hi
        worst = max(worst, float(abs(z2 - (lo + hi) / 2) / (hi - lo)))
    return equation_check(
        ok,
        "numeric",
        f"j1,k < j2,k < j1,k+1 for k <= 7; |j2,k − mean|/(j1,k+1 − j1,k) <= {worst:.3f}",
    )


def eq_15() -> EquationCheck:
    """(15): the five zeros of J2 below 20, to two decimals (rounded or chopped, as he says)."""
    import mpmath

    from pendcli.papers.lecornu.model import constant, printed

    limit = constant("table_limit")
    zeros = [float(mpmath.besseljzero(2, k)) for k in range(1, 7)]
    below = [z for z in zeros if z < limit]
    listed = [printed(f"lecornu.j2_zeros.{k}") for k in range(1, 6)]
    forms = []
    for z, v in zip(below, listed, strict=False):
        rounded = abs(round(z, 2) - v) < 1e-9
        chopped = abs(math.floor(z * 100) / 100 - v) < 1e-9
        forms.append("rounded" if rounded else "chopped" if chopped else "neither")
    ok = len(below) == len(listed) and "neither" not in forms
    return equation_check(
        ok,
        "numeric",
        f"{len(below)} zeros of J2 below {limit:g}: "
        + ", ".join(f"{z:.4f} ({f})" for z, f in zip(below, forms, strict=False)),
    )


def eq_16() -> EquationCheck:
    """(16): l = (b²/g)ξ = (b²/4g)z² with ξ = z²/4; the coefficient for b = 0,35 m/s."""
    sp = sympy_module()
    from pendcli.papers.lecornu.model import constant, printed_number

    b, g, z = sp.symbols("b g z", positive=True)
    identity = is_zero(b**2 / g * (z**2 / 4) - b**2 / (4 * g) * z**2)
    number = printed_number("lecornu.coefficient_b2_4g")
    speed = constant("speed")
    g_needed = speed**2 / (4 * (number.value - (number.resolution or 0) / 2))
    return equation_check(
        identity,
        "sympy",
        f"identity exact; b²/(4g) = {speed**2 / (4 * constant('g')):.6f} at g = "
        f"{constant('g'):g} (printed {number.text} needs g <= {g_needed:.3f}; see claim "
        "lecornu.coefficient_b2_4g)",
    )


def result_amplitude_j0() -> EquationCheck:
    """θ at an elongation = φ/l with l = (b²/g)x: (g/b²)·2J1(z)/z = (g/b²)J0(z) at J2 = 0."""
    import mpmath

    with mpmath.workdps(25):
        worst = 0.0
        for k in range(1, 6):
            z = mpmath.besseljzero(2, k)
            x = z**2 / 4
            phi_over_x = mpmath.sqrt(x) * mpmath.besselj(1, z) / x
            worst = max(worst, float(abs(phi_over_x - mpmath.besselj(0, z))))
        return equation_check(
            worst < 1e-20,
            "numeric",
            f"φ/x − J0(z) at the five zeros of J2: <= {worst:.0e}; with the printed denominator "
            "(b²/g)z the ratio would carry an extra factor x/z = z/4",
        )


def result_zero_length_limit() -> EquationCheck:
    sp = sympy_module()
    z = sp.Symbol("z", positive=True)
    lim = sp.limit(2 * sp.besselj(1, z) / z, z, 0)
    return equation_check(lim == 1, "sympy", f"lim 2J1(z)/z at z → 0 = {lim}")
