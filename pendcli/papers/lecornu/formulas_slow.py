"""Lecornu (1894), § II, the slowly varying pendulum (lines 462-664): three studies against a
fuller model, each judged on its observed order (the ledger rows that show it name it in
``measured``; :mod:`pendcli.papers.lecornu.formulas` gathers these rows).

* ``quarter_time``, lines 549-555: the time (l'' − l)/b from a vertical passage at l to the
  next elongation l'', against l'' solved exactly from (23) at l and (24) at l'' (mpmath);
* ``amplitude_factor``, lines 569-573: the amplitude at an elongation, R cos(3b/(4√(gl)))
  l^(−3/4), against the exact cylinder function √x C₁(2√x) of (9) at the zeros of C₂
  (elongations: d(C₁(z)/z)/dz = −C₂(z)/z, z = 2√x, x = gl/b²);
* ``eq25``, (25) at ψ = 0.7, against (3) linearised (solve_ivp) from the values (25) itself
  gives at t = 0 ((26) is its case ψ = 0).

Every printed formula these use, (23) and (24) included, is its ledger row's printed form
(tables/equations/lecornu.toml), parsed and evaluated, never retyped here.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from pendcli.numerics.cylinder_zeros import cylinder, cylinder_zero
from pendcli.papers.lecornu.formulas_chapter3 import ledger_row
from pendcli.verify.claims import FormulaRow
from pendcli.verify.formula_engine import (
    DEFAULT_INTEGRATOR,
    Integrator,
    Study,
    identify,
    leading_coefficient,
    make_row,
)
from pendcli.verify.formula_plots import PanelLabels

if TYPE_CHECKING:
    from pendcli.data.ledger_rows import Ledger, LedgerRow

__all__ = ["SLOW_PANELS", "eq25_residuals", "slow_row", "slow_rows"]

PAPER = "lecornu"
Q_SWEEP = (0.032, 0.016, 0.008, 0.004, 0.002)  # q = b/√(gl), as p = b/√(ga) of formulas.py
Q_PARAM = "q = b/√(gl) = 0.032 … 0.002"
P_SWEEP = Q_SWEEP  # p = b/√(ga) for (25)
P_PARAM = "p = b/√(ga) = 0.032 … 0.002"
DIGITS = 30  # mpmath's working precision in the two studies without an ODE
MPMATH_FLOOR = 1e-20  # their error bound: 30 digits, ten kept as margin
GRID_2PI = 401  # points of the grid 0 ≤ γt ≤ 2π on which (25)'s residual is maximised
PHASE = 0.3  # δ of the cylinder function cos δ J_ν + sin δ Y_ν (any solution of (9))
ELONGATIONS = (4, 8, 16, 32, 64)  # which elongations (further out: smaller b/√(gl))

_Q, _P = "q = b/√(gl), dimensionless", "p = b/√(ga), dimensionless"
# What each residual panel of the figure shows (formula_figures.PANELS gathers them)
SLOW_PANELS = {
    f"{PAPER}.quarter_time": PanelLabels("vertical to next elongation", _Q, "units of √(l/g)"),
    f"{PAPER}.amplitude_factor": PanelLabels("amplitude at an elongation", _Q, "÷ R l^(−3/4)"),
    f"{PAPER}.eq25": PanelLabels("θ(t) to first order in p, ψ = 0.7", _P, "÷ amplitude"),
}


def _printed(ledger: Ledger | None, row_id: str) -> tuple[LedgerRow, tuple[tuple[Any, Any], ...]]:
    """A ledger row and the equations (lhs, rhs) of its printed form, as sympy parses them;
    ``ledger`` None: the row of the tables in use, parsed alone (not the whole ledger)."""
    from pendcli.data.printed import parse_formula

    if ledger is None:
        row, symbols = ledger_row(row_id.removeprefix(f"{PAPER}."))
    else:
        row = next(r for r in ledger.rows if r.id == row_id)
        symbols = ledger.symbols_for(row)
    assert row.printed is not None, row_id
    return row, parse_formula(row.id, row.printed, symbols).equations


def _function(expr: Any, *names: str, modules: str = "mpmath") -> Any:
    """``expr`` as a function of the symbols ``names`` (by name: the parser's symbols)."""
    import sympy as sp

    symbols = {s.name: s for s in expr.free_symbols}
    return sp.lambdify([symbols.get(n, sp.Symbol(n)) for n in names], expr, modules)


def _solved_for(expr: Any, symbol: Any) -> Any:
    """The root of ``expr`` = 0 in ``symbol``: sympy's solve_linear where ``expr`` is linear
    in it ((23) is: a thousandth of solve's cost), else solve's first root."""
    import sympy as sp

    found, root = sp.solve_linear(expr, symbols=[symbol])
    return root if found == symbol else sp.solve(expr, symbol)[0]


def _source(row: LedgerRow) -> str:
    assert row.lines is not None
    return row.equation or f"lines {row.lines[0]}-{row.lines[1]}"


# --- lines 549-555: from a vertical passage to the next elongation --------------------------
def _quarter_residuals(ledger: Ledger | None) -> list[float]:
    """(l'' − l)/b minus the printed right side of line 555, per q, g = l = 1 (times in units
    of √(l/g)): l'' the root of (24) (λ = 0) with φ from (23) at the vertical at l."""
    import mpmath

    _, ((left23, right23), *_) = _printed(ledger, "lecornu.eq.23")
    _, ((left24, right24),) = _printed(ledger, "lecornu.eq.24")
    _, ((left, right),) = _printed(ledger, "lecornu.result.quarter_time")
    phi = next(s for s in left23.free_symbols if s.name == "phi")
    phase = _function(_solved_for(left23 - right23, phi), "b", "g", "l", "lam")
    at_elongation = _function(left24 - right24, "b", "g", "l", "lam", "phi")
    printed = _function(left - right, "b", "g", "l", "lpp")
    out = []
    with mpmath.workdps(DIGITS):
        for q in (mpmath.mpf(str(v)) for v in Q_SWEEP):
            vertical = phase(q, 1, 1, 0)
            lpp = mpmath.findroot(
                lambda y, q=q, v=vertical: at_elongation(q, 1, y, 0, v), 1 + q * mpmath.pi / 2
            )
            out.append(float(printed(q, 1, 1, lpp)))
    return out


def _quarter_row(ledger: Ledger | None) -> FormulaRow:
    row, _ = _printed(ledger, "lecornu.result.quarter_time")
    return make_row(
        id=f"{PAPER}.quarter_time",
        paper=PAPER,
        source=_source(row),
        published=row.statement,
        study=Study(Q_PARAM, Q_SWEEP, tuple(_quarter_residuals(ledger)), 2, MPMATH_FLOOR),
        reference=f"(23) at l and (24) at l'' solved for l'' (mpmath findroot, {DIGITS} digits)",
        note="From the vertical passage at l = 1 (g = 1, times in units of √(l/g)) to the next "
        "elongation l'': the printed (l'' − l)/b keeps the terms in 1 and b; its residual "
        "against the exact root of (24) falls as b³ (the b² term vanishes). Line 551 is "
        "the same relation multiplied by 4g/b.",
    )


# --- lines 569-573: the amplitude at an elongation -------------------------------------------
def _amplitude_residuals(factor: Any) -> tuple[list[float], list[float]]:
    """(q = b/√(gl) = 2/z, the exact θl^(3/4)/R minus ``factor(q)``) at the zeros z of C₂."""
    import mpmath

    qs, residuals = [], []
    with mpmath.workdps(DIGITS):
        delta = mpmath.mpf(str(PHASE))
        for n in ELONGATIONS:
            guess = (n + 1.25) * math.pi - PHASE  # McMahon: C₂(z) ~ cos(z − 5π/4 + δ)
            z = cylinder_zero(2, delta, guess)
            # θl^(3/4)/R = |C₁(z)|√(πz/2), which tends to 1 as l → ∞ ((22) normalised)
            amplitude = abs(cylinder(1, delta, z)) * mpmath.sqrt(mpmath.pi * z / 2)
            qs.append(float(2 / z))  # x = gl/b² = z²/4
            residuals.append(float(amplitude - factor(2 / z)))
    return qs, residuals


def _amplitude_row(ledger: Ledger | None) -> FormulaRow:
    row, ((_, factor), *_) = _printed(ledger, "lecornu.result.amplitude_factor")
    at_unit = _function(factor, "b", "R", "g", "l")
    qs, residuals = _amplitude_residuals(lambda q: at_unit(q, 1, 1, 1))
    second = leading_coefficient(qs, residuals, 2)
    name = identify(second, rel=1e-4) or f"{second:.6f}"
    parameter = f"q = b/√(gl) = 2/z = {qs[0]:.3g} … {qs[-1]:.3g}"
    return make_row(
        id=f"{PAPER}.amplitude_factor",
        paper=PAPER,
        source=_source(row),
        published=row.statement,
        study=Study(parameter, tuple(qs), tuple(residuals), 2, MPMATH_FLOOR),
        reference=f"mpmath ({DIGITS} digits): cos δ J_ν + sin δ Y_ν, δ = {PHASE}, at the "
        f"zeros of C₂ (elongations {', '.join(map(str, ELONGATIONS))})",
        note="θl^(3/4)/R at an elongation of the exact solution √x C₁(2√x) of (9), normalised "
        "to 1 as l → ∞, against the printed factor cos(3b/(4√(gl))) (the first equality, "
        f"R = 1). Leading residual {name}·b²/(gl): to second order the factor is "
        f"cos(3b/(4√(gl)))(1 + {name} b²/(gl)), which the author neglects with the square "
        "of b/√(gl).",
    )


# --- (25): the slowly varying pendulum to first order -----------------------------------------
def eq25_residuals(psi: float, ref: Integrator = DEFAULT_INTEGRATOR) -> list[float]:
    """Max over 0 ≤ γt ≤ 2π of |θ − (25)| per p of P_SWEEP (ρ = γ = 1, phase ψ), θ of (3)
    linearised in the reduced variables, (1 + pτ)θ'' + 2pθ' + θ = 0, started from (25)'s
    value and slope at τ = 0; (25) is the ledger's printed form."""
    return _eq25_residuals(None, psi, ref)


def _eq25_residuals(ledger: Ledger | None, psi: float, ref: Integrator) -> list[float]:
    import sympy as sp

    _, ((_, right),) = _printed(ledger, "lecornu.eq.25")
    names = {s.name: s for s in right.free_symbols}
    tau, p = names["t"], names["p"]
    # ρ = 1 and γ = 1 (r is the OCR's γ): t is the reduced time τ = γt
    theta = right.subs({names[n]: 1 for n in ("rho", "r", "gamma")}).subs(names["psi"], psi)
    value, slope = (sp.lambdify(p, e.subs(tau, 0)) for e in (theta, sp.diff(theta, tau)))
    ps = np.array(P_SWEEP)
    y0 = [float(value(v)) for v in ps] + [float(slope(v)) for v in ps]
    m = len(ps)

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        th, om = y[:m], y[m:]
        return np.concatenate((om, -(2.0 * ps * om + th) / (1.0 + ps * t)))

    grid = np.linspace(0.0, 2 * math.pi, GRID_2PI)
    solved = ref.solve(rhs, 2 * math.pi, y0)(grid)
    printed = sp.lambdify((tau, p), theta, "numpy")
    return [float(np.max(np.abs(solved[j] - printed(grid, v)))) for j, v in enumerate(ps)]


def _eq25_row(ledger: Ledger | None, ref: Integrator) -> FormulaRow:
    row, _ = _printed(ledger, "lecornu.eq.25")
    return make_row(
        id=f"{PAPER}.eq25",
        paper=PAPER,
        source=_source(row),
        published=row.statement,
        study=Study(P_PARAM, P_SWEEP, tuple(_eq25_residuals(ledger, 0.7, ref)), 2, ref.error_bound),
        reference=ref.label,
        note="Max over 0 ≤ γt ≤ 2π of |θ − (25)| at ψ = 0.7 (ρ = γ = 1), θ of (3) linearised "
        "from (25)'s own value and slope at t = 0; first order in p, so the residual should "
        "be O(p²).",
    )


def slow_rows(
    ref: Integrator = DEFAULT_INTEGRATOR, ledger: Ledger | None = None
) -> list[FormulaRow]:
    """The quarter oscillation (line 555), the amplitude factor (line 573) and (25), their
    printed forms read from ``ledger`` (by default the tables in use, each row parsed alone)."""
    return [slow_row(name, ref, ledger) for name in ("quarter_time", "amplitude_factor", "eq25")]


def slow_row(
    name: str, ref: Integrator = DEFAULT_INTEGRATOR, ledger: Ledger | None = None
) -> FormulaRow:
    """One of :func:`slow_rows` alone, by its id without the paper (``quarter_time``,
    ``amplitude_factor``, ``eq25``): a study whose printed form was edited is measured again
    without the other two."""
    if name == "quarter_time":
        return _quarter_row(ledger)
    if name == "amplitude_factor":
        return _amplitude_row(ledger)
    if name == "eq25":
        return _eq25_row(ledger, ref)
    raise KeyError(f"no slow-variation study {name!r}")
