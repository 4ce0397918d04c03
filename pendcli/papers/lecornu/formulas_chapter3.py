"""Lecornu (1894), chapter III: fast shortening (31) and finite oscillations (38) to (42').

Checked here, each against solve_ivp (the reduced variables, the sweep in p and the row
helper are those of :mod:`pendcli.papers.lecornu.formulas`, which gathers these rows):

* (31), θ(z) to second order in s when the string shortens fast;
* (38), the finite oscillations θ(u) to order k³;
* the terms in p of (41), from the variational equation of (32) at p = 0;
* the terms in b of (42) and (42'), the time from an elongation to the vertical.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from functools import cache

import numpy as np

from pendcli.core.claims import FormulaRow
from pendcli.core.formula_engine import (
    DEFAULT_REFERENCE,
    Reference,
    Study,
    fit_basis,
    identify_combination,
    judge,
    leading_coefficient,
)
from pendcli.papers.lecornu.formulas import GRID_2PI, PI, Array, Solution, formula_row

__all__ = ["fast_shortening_rows", "finite_rows"]

K_SWEEP = (0.2, 0.14, 0.1, 0.07, 0.05)  # k = sin(θ0/2)
S_SWEEP = (0.2, 0.1, 0.05, 0.025, 0.0125)  # s·z0 = g a / b² for (31)
K_PARAM = "k = sin(θ0/2) = 0.2 … 0.05"


def _k_study(residuals: Sequence[float] | Array, order: float, ref: Reference) -> Study:
    """A study over K_SWEEP (k = sin(θ0/2))."""
    return Study(K_PARAM, K_SWEEP, tuple(residuals), order, ref.error_bound)


def _eq31(z: Array, z0: float, s: float, alpha: float) -> Array:
    """(31) as printed: θ to second order in s."""
    return np.asarray(
        alpha
        - s * math.sin(alpha) / (2 * z) * (z - z0) ** 2
        + s**2
        * math.sin(2 * alpha)
        / 12
        * ((z - z0) * (z**2 - 5 * z * z0 - 2 * z0**2) / (2 * z) + 3 * z0**2 * np.log(z / z0))
    )


def _eq31_residuals(ref: Reference, alpha: float, z0: float = 1.0) -> list[float]:
    """Max |θ − (31)| from z0 down to z0/4, per s of S_SWEEP."""
    ss = np.array(S_SWEEP)
    m = len(ss)

    def rhs(z: float, y: Array) -> Array:
        th, om = y[:m], y[m:]
        return np.concatenate((om, -(2 * om + ss * np.sin(th)) / z))

    z_end = z0 / 4
    y0 = np.concatenate((np.full(m, alpha), np.zeros(m))).tolist()
    sol = ref.solve(rhs, z_end, y0, t0=z0)
    z = np.linspace(z0, z_end, 301)
    th = sol(z)[:m]
    return [float(np.max(np.abs(th[j] - _eq31(z, z0, s, alpha)))) for j, s in enumerate(S_SWEEP)]


def fast_shortening_rows(
    ref: Reference = DEFAULT_REFERENCE, alpha: float = 0.5
) -> list[FormulaRow]:
    """(31): z θ'' + 2θ' + s sin θ = 0 from z0 with θ = α, θ' = 0, to second order in s."""
    res = _eq31_residuals(ref, alpha)
    return [
        formula_row(
            "eq31",
            "(31)",
            "θ = α − (s sin α/(2z))(z − z0)² + (s² sin 2α/12)[(z − z0)(z² − 5zz0 − 2z0²)/(2z) "
            "+ 3z0² log(z/z0)]",
            Study("s·z0 = g a/b² = 0.2 … 0.0125", S_SWEEP, tuple(res), 3, ref.error_bound),
            ref,
            note=f"(30) integrated from z0 = a/b (θ = α = {alpha}, θ' = 0) down to z0/4; max "
            "over that range. The printed w, set on one line, reads as a product of two double "
            "integrals; it is the nested ∫dz/z² ∫z cos α·v dz with v the line above, i.e. "
            "w = (sin 2α/12)∫(z − z0)³/z² dz, which gives the printed bracket of (31).",
        )
    ]


def _nonlinear(ks: tuple[float, ...], t_end: float, ref: Reference) -> Solution:
    """(33) θ'' + sin θ = 0 from θ0 = 2 arcsin k at rest, with ε = ∂θ/∂p at p = 0 from (32)."""
    karr = np.array(ks)
    m = len(ks)

    def rhs(t: float, y: Array) -> Array:
        th, om, ep, ed = y[:m], y[m : 2 * m], y[2 * m : 3 * m], y[3 * m :]
        acc = -np.sin(th)
        return np.concatenate((om, acc, ed, -np.cos(th) * ep - (t * acc + 2 * om)))

    y0 = np.concatenate((2 * np.arcsin(karr), np.zeros(3 * m)))
    return ref.solve(rhs, t_end, y0.tolist())


_TRIG_BASIS = {
    f"{pw}{fn}{arg}": (lambda u, j=j, f=f, a=a: u**j * f(a * u))
    for j, pw in enumerate(("", "u ", "u² ", "u³ "))
    for f, fn in ((np.sin, "sin "), (np.cos, "cos "))
    for a, arg in ((1, "u"), (3, "3u"))
}


def _delta_found(grid: Array, ref: Reference) -> dict[str, int]:
    """64δ: the k³ coefficient of ∂θ/∂p, extrapolated (k² steps) and fitted on _TRIG_BASIS.

    Small k (0.014, 0.01) keep the k⁷ terms, large at u ~ 2π, out of the fit.
    """
    ks = (0.014, 0.01)
    eps = _nonlinear(ks, 2 * PI + 0.1, ref)(grid)[4:]
    c3 = leading_coefficient(ks, [eps[j] - k * _beta(grid) for j, k in enumerate(ks)], 3, 2)
    coef = fit_basis(grid, 64 * c3, _TRIG_BASIS)
    return {n: round(c) for n, c in coef.items() if round(c) != 0}


def _trig_text(coef: dict[str, int]) -> str:
    order = sorted(coef, key=lambda n: -n.count("³") * 3 - n.count("²") * 2 - n.startswith("u "))
    parts = []
    for n in order:
        c = coef[n]
        mag = "" if abs(c) == 1 else str(abs(c))
        term = mag + n if n[0] == "u" else (mag + " " if mag else "") + n
        parts.append(("− " if c < 0 else "+ ") + term)
    return " ".join(parts).lstrip("+ ").replace("− ", "−", 1 if parts[0][0] == "−" else 0)


def _beta(u: Array) -> Array:
    """β of (41): the term in pk of ∂θ/∂p is kβ."""
    return np.asarray((u**2 * np.sin(u) - 3 * u * np.cos(u) + 3 * np.sin(u)) / 2)


def _delta_printed(u: Array) -> Array:
    """δ of (41) as printed: the term in pk³ of ∂θ/∂p is k³δ."""
    s, c = np.sin(u), np.cos(u)
    return np.asarray(
        (
            -4 * u**3 * c
            + 11 * u**2 * s
            - u * c
            - u**2 * np.sin(3 * u)
            - 3 * u * np.cos(3 * u)
            + 4 * s
        )
        / 32
    )


@cache
def _finite_solution(ref: Reference) -> tuple[Array, Array, Solution]:
    """(grid 0 ≤ u ≤ 2π, [θ, θ', ε, ε'] on it per k of K_SWEEP, the dense solution)."""
    sol = _nonlinear(K_SWEEP, 2 * PI + 0.1, ref)
    grid = np.linspace(0.0, 2 * PI, GRID_2PI)
    return grid, sol(grid), sol


def _eq38_row(ref: Reference) -> FormulaRow:
    grid, y, _ = _finite_solution(ref)
    f = 9 * np.cos(grid) + 12 * grid * np.sin(grid) - np.cos(3 * grid)
    res = [
        np.max(np.abs(y[j] - (2 * k * np.cos(grid) + k**3 / 24 * f))) for j, k in enumerate(K_SWEEP)
    ]
    return formula_row(
        "eq38",
        "(38)",
        "θ = 2k cos u + (k³/24)(9 cos u + 12u sin u − cos 3u)",
        _k_study(res, 4, ref),
        ref,
        note="(33) from θ0 = 2 arcsin k at rest, max over 0 ≤ u ≤ 2π. The paper says the "
        "error is of order k⁴; θ is odd in k, so it is in fact O(k⁵).",
    )


def _eq41_residuals(y: Array, grid: Array, delta: Array) -> list[float]:
    """Max |∂θ/∂p − (kβ + k³δ)| per k."""
    m = len(K_SWEEP)
    return [
        np.max(np.abs(y[2 * m + j] - (k * _beta(grid) + k**3 * delta)))
        for j, k in enumerate(K_SWEEP)
    ]


def _eq41_row(ref: Reference) -> FormulaRow:
    grid, y, _ = _finite_solution(ref)
    found = _delta_found(grid, ref)
    delta_text = _trig_text(found)
    delta_fixed = sum(c * _TRIG_BASIS[n](grid) for n, c in found.items()) / 64
    fv, fo, _ = judge(_k_study(_eq41_residuals(y, grid, delta_fixed), 4, ref))
    return formula_row(
        "eq41_terms_in_p",
        "(41)",
        "∂θ/∂p at p = 0: (k/2)(u² sin u − 3u cos u + 3 sin u) + (k³/32)(−4u³ cos u "
        "+ 11u² sin u − u cos u − u² sin 3u − 3u cos 3u + 4 sin u)",
        _k_study(_eq41_residuals(y, grid, _delta_printed(grid)), 4, ref),
        ref,
        recomputed=f"(k/2)(u² sin u − 3u cos u + 3 sin u) + (k³/64)({delta_text})",
        note="The terms of (41) in p are its first p-derivative; the reference is the exact "
        "variational equation of (32) at p = 0 (Lecornu's (39) along the exact (33) "
        "solution), max over 0 ≤ u ≤ 2π. The term in pk is right, the term in pk³ is "
        "not: 64δ found numerically (k³ coefficient of ∂θ/∂p, Richardson-extrapolated, "
        "fitted on u^j sin u, u^j cos u, u^j sin 3u, u^j cos 3u, rounded to integers): "
        f"{delta_text}; with it the residual is O(k^{fo:.2f}) ({fv}). The slip is the "
        "sign of the last term of 2β cos²u: (−3u cos u)cos²u = −(3u/4)(cos 3u + 3 cos u), "
        "printed +; the right side of δ'' + δ then has −(31/8)u cos u and −(9/8)u cos 3u "
        "instead of +(5/8) and +(3/8).",
    )


def _quarter_period_terms(ref: Reference) -> tuple[Array, Array]:
    """(K(k), ∂T/∂p) per k: T from the elongation at t = 0 to the vertical; ∂T/∂p = −ε(K)/θ'(K)."""
    from scipy.special import ellipk

    _, _, sol = _finite_solution(ref)
    m = len(K_SWEEP)
    quarter = ellipk(np.array(K_SWEEP) ** 2)
    at_k = [sol(t) for t in quarter]
    return quarter, np.array([-at_k[j][2 * m + j] / at_k[j][m + j] for j in range(m)])


def _eq42_row(ref: Reference, t_p: Array, quarter: Array, c_k2: float, text: str) -> FormulaRow:
    ks = np.array(K_SWEEP)
    printed_b = (PI**2 / 4 + 3) / 4 + (2 * PI**2 + 1) / 16 * ks**2
    fv, fo, _ = judge(_k_study(t_p - ((PI**2 / 4 + 3) / 4 + c_k2 * ks**2), 4, ref))
    p0_res = quarter - PI / 2 * (1 + ks**2 / 4)
    p0_order = np.polyfit(np.log(ks), np.log(np.abs(p0_res)), 1)[0]
    return formula_row(
        "eq42_terms_in_b",
        "(42)",
        "T = (π/2)√(a/g)(1 + k²/4) + (b/4g)(π²/4 + 3) + (bk²/16g)(2π² + 1)",
        _k_study(t_p - printed_b, 4, ref),
        ref,
        recomputed=f"T = (π/2)√(a/g)(1 + k²/4) + (b/4g)(π²/4 + 3) + {text}·bk²/g",
        note=f"The coefficient of bk²/g is {c_k2:.6f} = {text} (fitted), not "
        f"(2π² + 1)/16 = {(2 * PI**2 + 1) / 16:.6f}; with it the residual is "
        f"O(k^{fo:.2f}) ({fv}). The error comes from the pk³ term of (41) (see that row). "
        "Coefficient of b/g (i.e. ∂T/∂p in units of √(a/g)) of the time from the "
        "elongation at t = 0 to the next vertical passage, from the variational equation "
        "of (32): ∂T/∂p = −ε(K)/θ'(K), K = K(k) the exact quarter period. The terms in "
        f"b⁰ are the classical K(k) = (π/2)(1 + k²/4 + …): residual O(k^{p0_order:.2f}).",
    )


def _eq42_prime_row(ref: Reference, t_p: Array, text: str) -> FormulaRow:
    theta0 = 2 * np.arcsin(np.array(K_SWEEP))
    printed_b_theta = (PI**2 / 4 + 3) / 4 + (2 * PI**2 + 1) / 64 * theta0**2
    return formula_row(
        "eq42prime_terms_in_b",
        "(42')",
        "T = (π/2)√(a/g)(1 + θ0²/16) + (b/4g)(π²/4 + 3) + (bθ0²/64g)(2π² + 1)",
        Study(
            "θ0 = 2 arcsin k = 0.40 … 0.10",
            tuple(float(t) for t in theta0),
            tuple(t_p - printed_b_theta),
            4,
            ref.error_bound,
        ),
        ref,
        recomputed=f"T = (π/2)√(a/g)(1 + θ0²/16) + (b/4g)(π²/4 + 3) + {text}·bθ0²/(4g)",
        note="As (42) with k replaced by θ0/2 (the difference is O(θ0⁴), so the claimed "
        "order is unchanged); it inherits the wrong coefficient of (42).",
    )


def _eq42_rows(ref: Reference) -> list[FormulaRow]:
    """(42) and (42'): the terms in b of the time from an elongation to the vertical."""
    quarter, t_p = _quarter_period_terms(ref)
    ks = np.array(K_SWEEP)
    printed_b = (PI**2 / 4 + 3) / 4 + (2 * PI**2 + 1) / 16 * ks**2
    c_k2 = (2 * PI**2 + 1) / 16 + leading_coefficient(K_SWEEP, tuple(t_p - printed_b), 2, 2)
    text = identify_combination(c_k2, [(PI**2, "π²"), (1.0, "")]) or f"{c_k2:.6f}"
    return [_eq42_row(ref, t_p, quarter, c_k2, text), _eq42_prime_row(ref, t_p, text)]


def finite_rows(ref: Reference = DEFAULT_REFERENCE) -> list[FormulaRow]:
    """(38), the terms in p of (41), and the terms in b of (42) and (42')."""
    return [_eq38_row(ref), _eq41_row(ref), *_eq42_rows(ref)]
