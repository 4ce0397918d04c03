"""Lecornu (1894), chapter III: fast shortening (31) and finite oscillations (38) to (42').

Checked here, each against solve_ivp (the reduced variables, the sweep in p and the row
helper are those of :mod:`pendcli.papers.lecornu.formulas`, which gathers these rows) or
against mpmath's Jacobi functions:

* (31), θ(z) to second order in s when the string shortens fast;
* the series of am u, cn u and θ to k³ (lines 786-806), against θ = 2 arctg((k/k') cn u);
* (38), the finite oscillations θ(u) to order k³;
* the terms in p of (41), from the variational equation of (32) at p = 0;
* (41) with k³ neglected (lines 888-892), against (3) linearised;
* the terms in b of (42) and (42'), the time from an elongation to the vertical.

The checks added with the ledger's rows (the am u series, line 890, and § IV's in
:mod:`pendcli.papers.lecornu.formulas_conical`) evaluate the row's printed form (or its
reading) as the ledger transcribes it (:func:`ledger_sides`): no formula is typed twice.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from pendcli.papers.lecornu.formulas_base import (
    GRID_2PI,
    P_SWEEP,
    PI,
    Array,
    Solution,
    formula_row,
)
from pendcli.verify.claims import FormulaRow
from pendcli.verify.formula_engine import (
    DEFAULT_INTEGRATOR,
    Integrator,
    Study,
    fit_basis,
    identify_combination,
    leading_coefficient,
    make_row,
    study_verdict,
)

__all__ = [
    "amplitude_series_row",
    "evaluator",
    "fast_shortening_rows",
    "finite_rows",
    "k3_neglected_row",
    "ledger_sides",
    "ledger_text",
    "linear_solution",
    "slope_at_zero",
    "through_printed_state",
]

K_SWEEP = (0.2, 0.14, 0.1, 0.07, 0.05)  # k = sin(θ0/2)
S_SWEEP = (0.2, 0.1, 0.05, 0.025, 0.0125)  # s·z0 = g a / b² for (31)
K_PARAM = "k = sin(θ0/2) = 0.2 … 0.05"


def _k_study(residuals: Sequence[float] | Array, order: float, ref: Integrator) -> Study:
    """A study over K_SWEEP (k = sin(θ0/2))."""
    return Study(K_PARAM, K_SWEEP, tuple(residuals), order, ref.error_bound)


# --------------------------------------------------------- the ledger's printed forms
@cache
def _ledger_raw(tables: str) -> dict[str, Any]:
    from pendcli.data.ledger import ledger_path
    from pendcli.data.tables import read_toml

    return read_toml(ledger_path("lecornu", Path(tables)), "equation ledger")


@cache
def _ledger_row_in(row_id: str, tables: str) -> tuple[Any, dict[str, str]]:
    """Row ``lecornu.<row_id>`` validated as the ledger's loader does (its formulas parsed),
    alone: the other rows' formulas are not parsed again; and the symbols of its place."""
    from pendcli.data.ledger import ledger_path, parse_ledger

    raw = _ledger_raw(tables)
    entries = [e for e in raw["equation"] if e.get("id") == f"lecornu.{row_id}"]
    path = ledger_path("lecornu", Path(tables))
    ledger = parse_ledger({**raw, "equation": entries}, "lecornu", path, Path(tables), partial=True)
    (row,) = ledger.rows
    return row, ledger.symbols_for(row)


def ledger_row(row_id: str) -> tuple[Any, dict[str, str]]:
    """Ledger row ``lecornu.<row_id>`` of the tables in use, its formulas parsed alone (the
    whole ledger is not), and the symbols of its place in the text."""
    from pendcli.data.tables import tables_dir

    return _ledger_row_in(row_id, str(tables_dir()))


def ledger_text(row_id: str, field: str = "printed") -> str:
    """Ledger row ``lecornu.<row_id>``'s formula ``field`` (``printed``,
    ``reading_formula`` or ``corrected_formula``) as the ledger transcribes it."""
    row, _ = ledger_row(row_id)
    text = getattr(row, field)
    if text is None:
        raise ValueError(f"{row.id} has no {field}")
    return str(text)


def ledger_sides(row_id: str, field: str = "printed") -> tuple[tuple[Any, Any], ...]:
    """The (lhs, rhs) pairs of :func:`ledger_text`, parsed in the symbols of the row's place
    in the text: what a check of a printed formula evaluates, never a copy of it."""
    from pendcli.data.printed import parse_formula

    row, symbols = ledger_row(row_id)
    return parse_formula(row.id, ledger_text(row_id, field), symbols).equations


def _named(expr: Any, names: Sequence[str]) -> tuple[Any, list[Any]]:
    """``expr`` with a printed « … » (the terms a series leaves out) set to 0, and the sympy
    symbols of ``names`` in it (a name it lacks is a fresh symbol); any other symbol of
    ``expr`` is an error."""
    import sympy as sp

    from pendcli.data.printed import ELLIPSIS

    found = {s.name: s for s in expr.free_symbols}
    extra = set(found) - set(names) - {ELLIPSIS}
    if extra:
        raise ValueError(f"{expr} has symbols {sorted(extra)} beyond {list(names)}")
    cut = expr.subs({s: 0 for n, s in found.items() if n == ELLIPSIS})
    return cut, [found.get(n, sp.Symbol(n, real=True)) for n in names]


def evaluator(expr: Any, names: Sequence[str], modules: str = "numpy") -> Callable[..., Any]:
    """``expr`` (a parsed printed form) as a function of the symbols ``names``, in that
    order (numpy arrays, or mpmath numbers with ``modules="mpmath"``)."""
    import sympy as sp

    cut, symbols = _named(expr, names)
    return sp.lambdify(symbols, cut, modules=modules)


def slope_at_zero(expr: Any, variable: str, names: Sequence[str]) -> Callable[..., Any]:
    """d expr/d ``variable`` (one of ``names``) as a function of ``names``, by sympy."""
    import sympy as sp

    cut, symbols = _named(expr, names)
    return sp.lambdify(symbols, sp.diff(cut, symbols[list(names).index(variable)]))


@cache
def linear_solution(
    starts: tuple[float, ...], slopes: tuple[float, ...], t_end: float, ref: Integrator
) -> Solution:
    """(3) linearised in the reduced variables, (1 + pu)θ'' + 2pθ' + θ = 0, one copy per p
    of P_SWEEP, from θ(0) = ``starts``, θ'(0) = ``slopes`` (per p)."""
    ps = np.array(P_SWEEP)
    m = len(ps)

    def rhs(t: float, y: Array) -> Array:
        th, om = y[:m], y[m:]
        return np.concatenate((om, -(2.0 * ps * om + th) / (1.0 + ps * t)))

    return ref.solve(rhs, t_end, [*starts, *slopes])


def through_printed_state(
    expr: Any, names: Sequence[str], fixed: Sequence[float], t_end: float, ref: Integrator
) -> tuple[Callable[..., Any], Solution]:
    """The printed θ(u, p, *fixed) of ``expr`` (``names`` = u, p, then the fixed symbols)
    and the solution of (3) linearised from its value and slope at u = 0, per p."""
    value, slope = evaluator(expr, names), slope_at_zero(expr, names[0], names)
    starts = tuple(float(value(0.0, p, *fixed)) for p in P_SWEEP)
    slopes = tuple(float(slope(0.0, p, *fixed)) for p in P_SWEEP)
    return value, linear_solution(starts, slopes, t_end, ref)


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


def _eq31_residuals(ref: Integrator, alpha: float, z0: float = 1.0) -> list[float]:
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
    ref: Integrator = DEFAULT_INTEGRATOR, alpha: float = 0.5
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


def _nonlinear(ks: tuple[float, ...], t_end: float, ref: Integrator) -> Solution:
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


def _delta_found(grid: Array, ref: Integrator) -> dict[str, int]:
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
def _finite_solution(ref: Integrator) -> tuple[Array, Array, Solution]:
    """(grid 0 ≤ u ≤ 2π, [θ, θ', ε, ε'] on it per k of K_SWEEP, the dense solution)."""
    sol = _nonlinear(K_SWEEP, 2 * PI + 0.1, ref)
    grid = np.linspace(0.0, 2 * PI, GRID_2PI)
    return grid, sol(grid), sol


def _eq38_row(ref: Integrator) -> FormulaRow:
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


def _eq41_row(ref: Integrator) -> FormulaRow:
    grid, y, _ = _finite_solution(ref)
    found = _delta_found(grid, ref)
    delta_text = _trig_text(found)
    delta_fixed = sum(c * _TRIG_BASIS[n](grid) for n, c in found.items()) / 64
    fv, fo, _ = study_verdict(_k_study(_eq41_residuals(y, grid, delta_fixed), 4, ref))
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


def _quarter_period_terms(ref: Integrator) -> tuple[Array, Array]:
    """(K(k), ∂T/∂p) per k: T from the elongation at t = 0 to the vertical; ∂T/∂p = −ε(K)/θ'(K)."""
    from scipy.special import ellipk

    _, _, sol = _finite_solution(ref)
    m = len(K_SWEEP)
    quarter = ellipk(np.array(K_SWEEP) ** 2)
    at_k = [sol(t) for t in quarter]
    return quarter, np.array([-at_k[j][2 * m + j] / at_k[j][m + j] for j in range(m)])


def _eq42_row(ref: Integrator, t_p: Array, quarter: Array, c_k2: float, text: str) -> FormulaRow:
    ks = np.array(K_SWEEP)
    printed_b = (PI**2 / 4 + 3) / 4 + (2 * PI**2 + 1) / 16 * ks**2
    fv, fo, _ = study_verdict(_k_study(t_p - ((PI**2 / 4 + 3) / 4 + c_k2 * ks**2), 4, ref))
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


def _eq42_prime_row(ref: Integrator, t_p: Array, text: str) -> FormulaRow:
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


def _eq42_rows(ref: Integrator) -> list[FormulaRow]:
    """(42) and (42'): the terms in b of the time from an elongation to the vertical."""
    quarter, t_p = _quarter_period_terms(ref)
    ks = np.array(K_SWEEP)
    printed_b = (PI**2 / 4 + 3) / 4 + (2 * PI**2 + 1) / 16 * ks**2
    c_k2 = (2 * PI**2 + 1) / 16 + leading_coefficient(K_SWEEP, tuple(t_p - printed_b), 2, 2)
    text = identify_combination(c_k2, [(PI**2, "π²"), (1.0, "")]) or f"{c_k2:.6f}"
    return [_eq42_row(ref, t_p, quarter, c_k2, text), _eq42_prime_row(ref, t_p, text)]


def finite_rows(ref: Integrator = DEFAULT_INTEGRATOR) -> list[FormulaRow]:
    """The series of am u to k³, (38), the terms in p of (41), (41) with k³ neglected, and
    the terms in b of (42) and (42')."""
    return [
        amplitude_series_row(),
        _eq38_row(ref),
        _eq41_row(ref),
        k3_neglected_row(ref),
        *_eq42_rows(ref),
    ]


# ----------------------------------------------------- the series of am u and line 890
K_SMALL = (0.08, 0.04, 0.02, 0.01)  # k for the series of am u (mpmath: no solver's floor)
MP_DIGITS = 30
MP_LABEL = f"mpmath ellipfun (Jacobi cn), {MP_DIGITS} digits"


def _amplitude_residuals(theta: Any, grid: Array) -> list[float]:
    """Max over ``grid`` of |2 arctg((k/k') cn u) − θ(k, u)| per k of K_SMALL, θ the printed
    series (mpmath at MP_DIGITS digits)."""
    import mpmath

    series = evaluator(theta, ("k", "u"), modules="mpmath")
    out = []
    with mpmath.workdps(MP_DIGITS):
        for k in (mpmath.mpf(str(x)) for x in K_SMALL):
            ratio = k / mpmath.sqrt(1 - k**2)
            worst = mpmath.mpf(0)
            for u in (mpmath.mpf(str(x)) for x in grid):
                exact = 2 * mpmath.atan(ratio * mpmath.ellipfun("cn", u, m=k**2))
                worst = max(worst, abs(exact - series(k, u)))
            out.append(float(worst))
    return out


def amplitude_series_row() -> FormulaRow:
    """Lines 786-806: θ to k³ as line 802 prints it (row lecornu.result.arctg_series, the
    end of the series of am u, cn u and the arctangent) against the exact (35) at C = 0."""
    (*_, (_, theta)) = ledger_sides("result.arctg_series")
    grid = np.linspace(0.0, 2 * PI, 41)
    study = Study(
        "k = sin(θ0/2) = 0.08 … 0.01",
        K_SMALL,
        tuple(_amplitude_residuals(theta, grid)),
        4,
        10.0 ** (5 - MP_DIGITS),
    )
    return make_row(
        id="lecornu.amplitude_series",
        paper="lecornu",
        source="lines 786-806",
        published=ledger_text("result.arctg_series").split(";")[-1].strip(),
        study=study,
        reference=MP_LABEL,
        note="θ of line 802, the last step of the series of am u, cn u = cos am u and "
        "arctg((k/k') cn u) to k³ (lines 786-806, « en négligeant k⁴ »), against the exact "
        "θ = 2 arctg((k/k') cn u) of (35) at C = 0 by mpmath's Jacobi cn; max over "
        "0 ≤ u ≤ 2π. θ is odd in k: the neglected terms are O(k⁵). With cos³u = "
        "(cos 3u + 3 cos u)/4 (line 806) it is (38).",
    )


def k3_neglected_row(ref: Integrator) -> FormulaRow:
    """Line 890: θ of (41) with k³ neglected (row lecornu.result.k3_neglected, ρ = 1)
    against (3) linearised from its own value and slope at u = 0."""
    ((_, theta),) = ledger_sides("result.k3_neglected")
    printed, solution = through_printed_state(theta, ("u", "p", "rho"), (1.0,), 2 * PI, ref)
    grid = np.linspace(0.0, 2 * PI, 300)
    solved = solution(grid)
    res = [np.max(np.abs(solved[j] - printed(grid, p, 1.0))) for j, p in enumerate(P_SWEEP)]
    return formula_row(
        "k3_neglected",
        "lines 888-892",
        ledger_text("result.k3_neglected"),
        Study("p = b/√(ga) = 0.032 … 0.002", P_SWEEP, tuple(res), 2, ref.error_bound),
        ref,
        note="(41) with k³ neglected, ρ = 2k set to 1 (the equation is linear): (25) at "
        "γt = u, ψ = 3p/4 − π/2. Reference: (3) linearised in u = γt, "
        "(1 + pu)θ'' + 2pθ' + θ = 0, from the printed θ and θ' at u = 0; max over "
        "0 ≤ u ≤ 2π.",
    )
