"""Lecornu (1894), § IV, the conical pendulum of variable length: its series in p (lines
1086-1134) against (3) linearised (solve_ivp), each printed form evaluated as the ledger
transcribes it (:func:`~pendcli.papers.lecornu.formulas_chapter3.ledger_sides`):

* line 1088, l²θ²φ' for (44)'s l² sin²θ φ' (θ² neglected beside 1);
* line 1094, the conical pendulum as two plane pendulums (48) in fixed planes, against the
  bob's motion in space;
* (50), the two plane components to first order in p;
* line 1102, 1/l² = (1/a²)(1 − 2pγt) to first order in p;
* (52) as read (the printed form is :mod:`pendcli.papers.lecornu.formulas`' ``eq52``);
* the trace after (52) and the axes of its ellipse, as read (the arctangent's argument
  ρ1y/(ρ2x), printed ρ2y/(ρ1x)).

The reduced variables (u = γt, p = b/√(ga)), the sweep in p and the row helper are those of
:mod:`pendcli.papers.lecornu.formulas`, which gathers these rows.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import cache
from typing import Any

import numpy as np

from pendcli.papers.lecornu.formulas_base import P_SWEEP, PI, Array, Solution, formula_row
from pendcli.papers.lecornu.formulas_chapter3 import (
    evaluator,
    ledger_sides,
    ledger_text,
    through_printed_state,
)
from pendcli.verify.claims import FormulaRow
from pendcli.verify.formula_engine import DEFAULT_INTEGRATOR, Integrator, Study

__all__ = ["conical_row", "conical_rows"]

P_PARAM = "p = b/√(ga) = 0.032 … 0.002"
ANGLES = (0.2, 0.1, 0.05, 0.025, 0.0125)  # θ for line 1088
RHO1, RHO2 = 1.0, 0.4  # the axes of the trace (lines 1120-1134)
NEAR = np.linspace(0.05, 1.4, 200)  # u on the first quarter turn: x, y > 0 (the arctangent)
TURN = np.linspace(0.0, 2 * PI, 401)
AMPLITUDES = (0.04, 0.02, 0.01, 0.005)  # the bob's first angle, rad (line 1094)
SPACE_A, SPACE_B = 1.0, 0.05  # l = a + bt of the motion in space (m, m/s); g the tables'


def _p_study(residuals: Sequence[float] | Array, ref: Integrator) -> Study:
    return Study(P_PARAM, P_SWEEP, tuple(float(r) for r in residuals), 2, ref.error_bound)


def _area_row(ref: Integrator) -> FormulaRow:
    """Line 1088: l²θ²φ' = l² sin²θ φ' + …, the relative gap of the two sides (l = φ' = 1)."""
    ((lhs, rhs),) = ledger_sides("result.area_small_angle")
    names = ("l", "theta", "dphi_dt")
    left, right = evaluator(lhs, names), evaluator(rhs, names)
    gaps = tuple(float(1 - right(1.0, t, 1.0) / left(1.0, t, 1.0)) for t in ANGLES)
    return formula_row(
        "area_small_angle",
        "line 1088",
        ledger_text("result.area_small_angle"),
        Study("θ = 0.2 … 0.0125 rad", ANGLES, gaps, 2, 1e-14),
        ref,
        note="(44), l² sin²θ φ' = c, against l²θ²φ' = c « pour le degré d'approximation "
        "adopté »: 1 − (right side)/(left side) = 1 − sin²θ/θ², evaluated in double "
        "precision (no integration: the floor is the arithmetic's).",
    )


def _in_space(g: float) -> Callable[[float, Array], Array]:
    """The bob in space (z downward, |r| = a + bt): the tension per unit length from the
    constraint differentiated twice, r·r'' + v·v = b² (l'' = 0)."""

    def rhs(t: float, y: Array) -> Array:
        r, v = y[:3], y[3:]
        pull = (g * r[2] + v @ v - SPACE_B**2) / (SPACE_A + SPACE_B * t) ** 2
        return np.concatenate([v, np.array([0.0, 0.0, g]) - pull * r])

    return rhs


def _plane_law(g: float) -> Callable[[float, Array], list[float]]:
    """The printed law of line 1094's row (its first equation) solved for θ'' (it is linear
    in it): y' = (θ', θ'') in one plane."""
    ((lhs, rhs), _) = ledger_sides("result.composed_planes")
    names = ("l", "b", "g", "theta1", "dtheta1_dt", "d2theta1_dt2")
    law = evaluator(lhs - rhs, names)

    def rhs_(t: float, y: Array) -> list[float]:
        at = (SPACE_A + SPACE_B * t, SPACE_B, g, y[0], y[1])
        free = law(*at, 0.0)
        return [y[1], -free / (law(*at, 1.0) - free)]

    return rhs_


def _composed_row(ref: Integrator) -> FormulaRow:
    """Line 1094: the angles of the rod's projections on the fixed planes xz, yz of the
    motion in space against the printed law integrated in each plane, started alike
    (θ1 = A at rest, θ2' = 0.6·A·√(g/a)); the largest gap over the largest angle, 4 s."""
    from pendcli.papers.lecornu.model import constant

    g = constant("g")
    space, law, end = _in_space(g), _plane_law(g), 4.0
    ts = np.linspace(0.0, end, 801)
    gaps = []
    for amp in AMPLITUDES:
        w2 = 0.6 * amp * np.sqrt(g / SPACE_A)
        x0, z0 = SPACE_A * np.sin(amp), SPACE_A * np.cos(amp)
        start = [x0, 0.0, z0, SPACE_B * np.sin(amp), z0 * w2, SPACE_B * np.cos(amp)]
        x, y, z = ref.solve(space, end, start)(ts)[:3]
        one, two = ref.solve(law, end, [amp, 0.0])(ts)[0], ref.solve(law, end, [0.0, w2])(ts)[0]
        angles = (np.arctan2(x, z), np.arctan2(y, z))
        gap = np.hypot(angles[0] - one, angles[1] - two)
        gaps.append(float(np.max(gap) / np.max(np.hypot(*angles))))
    return formula_row(
        "composed_planes",
        "line 1094",
        ledger_text("result.composed_planes"),
        Study("first angle A = 0.04 … 0.005 rad", AMPLITUDES, tuple(gaps), 2, ref.error_bound),
        ref,
        note="The bob in space (l = 1 + 0.05t m, the tables' g) against two plane pendulums of "
        "the printed law in fixed rectangular planes: the angles of the projections, "
        "atan(x/z) and atan(y/z), their largest gap over the largest angle, 0 ≤ t ≤ 4 s.",
    )


def _eq50_row(ref: Integrator) -> FormulaRow:
    """(50): each θi (ρi = γ = 1, ψ1 = 0.7, ψ2 = −0.4) against (3) linearised from its own
    value and slope at t = 0; the larger residual of the two per p."""
    worst = np.zeros(len(P_SWEEP))
    for (_, theta), i, psi in zip(ledger_sides("eq.50"), "12", (0.7, -0.4), strict=True):
        names = ("t", "p", "gamma", f"rho{i}", f"psi{i}")
        printed, solution = through_printed_state(theta, names, (1.0, 1.0, psi), 2 * PI, ref)
        solved = solution(TURN)
        for j, p in enumerate(P_SWEEP):
            gap = np.max(np.abs(solved[j] - printed(TURN, p, 1.0, 1.0, psi)))
            worst[j] = max(worst[j], gap)
    return formula_row(
        "eq50",
        "(50)",
        ledger_text("eq.50"),
        _p_study(worst, ref),
        ref,
        note="Both plane components of the conical pendulum, (48) linear in u = γt: "
        "(1 + pu)θ'' + 2pθ' + θ = 0 from the printed θi and θi' at t = 0 (ρi = 1, ψ1 = 0.7, "
        "ψ2 = −0.4); max over 0 ≤ γt ≤ 2π.",
    )


def _inverse_square_row(ref: Integrator) -> FormulaRow:
    """Line 1102 as read: 1/(a + bt)² against (1/a²)(1 − 2pγt), b = pγa, a = γt = 1."""
    (_, (exact, series)) = ledger_sides("result.inverse_square_length", "reading_formula")
    names = ("a", "b", "t", "p", "gamma")
    whole, first = evaluator(exact, names), evaluator(series, names)
    gaps = [abs(whole(1.0, p, 1.0, p, 1.0) - first(1.0, p, 1.0, p, 1.0)) for p in P_SWEEP]
    return formula_row(
        "inverse_square_length",
        "line 1102",
        ledger_text("result.inverse_square_length", "reading_formula"),
        _p_study(gaps, ref),
        ref,
        note="The printed 1/ρ² is 1/l² (ρ, (50)'s amplitude, is no length): read so. "
        "1/(a + bt)² with b = pγa (p = b/√(ga), γ = √(g/a)) against its first-order "
        "form, at a = 1, γt = 1 (no integration).",
    )


def _plane_solutions(ref: Integrator) -> tuple[list[Callable[..., Any]], list[Solution]]:
    """(52) as read, θ1/ρ1 and θ2/ρ2 as functions (u, p), and (3) linearised from their
    values and slopes at u = 0, per p: the trace of the conical pendulum (derived once per
    tables folder, for the three rows that read it)."""
    from pendcli.data.tables import tables_dir

    return _plane_solutions_in(ref, str(tables_dir()))


@cache
def _plane_solutions_in(
    ref: Integrator, tables: str
) -> tuple[list[Callable[..., Any]], list[Solution]]:
    printed, solved = [], []
    for _, component in ledger_sides("eq.52", "reading_formula")[:2]:
        value, solution = through_printed_state(component, ("u", "p"), (), 2 * PI + 1.5, ref)
        printed.append(value)
        solved.append(solution)
    return printed, solved


def _eq52_row(ref: Integrator) -> FormulaRow:
    printed, solved = _plane_solutions(ref)
    worst = np.zeros(len(P_SWEEP))
    for value, solution in zip(printed, solved, strict=True):
        exact = solution(TURN)
        for j, p in enumerate(P_SWEEP):
            worst[j] = max(worst[j], np.max(np.abs(exact[j] - value(TURN, p))))
    return formula_row(
        "eq52_as_read",
        "(52) as read",
        ledger_text("eq.52", "reading_formula"),
        _p_study(worst, ref),
        ref,
        note="(52) with the last terms as (25) gives them at ψ = −π/2 and 0 (−u sin u in "
        "θ1, +u cos u in θ2; lecornu.eq52 measures the printed ones): both components "
        "against (48) linear from their values and slopes at u = 0; max over 0 ≤ u ≤ 2π.",
    )


def _trace(ref: Integrator) -> tuple[Array, Array]:
    """x = ρ1θ1/ρ1, y = ρ2θ2/ρ2 of the solved trace on NEAR, per p (rows)."""
    _, solved = _plane_solutions(ref)
    return RHO1 * solved[0](NEAR), RHO2 * solved[1](NEAR)


def _trajectory_row(ref: Integrator) -> FormulaRow:
    ((lhs, rhs),) = ledger_sides("result.trajectory_after_52", "corrected_formula")
    gap = evaluator(lhs - rhs, ("x", "y", "rho1", "rho2", "p"))
    xs, ys = _trace(ref)
    res = [np.max(np.abs(gap(xs[j], ys[j], RHO1, RHO2, p))) for j, p in enumerate(P_SWEEP)]
    return formula_row(
        "trajectory_after_52",
        "line 1126 as read",
        ledger_text("result.trajectory_after_52", "corrected_formula"),
        _p_study(res, ref),
        ref,
        note="The trace (x, y) = (θ1, θ2) of (48) linear, started as (52) (ρ1 = 1, "
        "ρ2 = 0.4), in the printed equation with the arctangent's argument ρ1y/(ρ2x) "
        "(printed ρ2y/(ρ1x), which leaves an O(p) residual); max over 0.05 ≤ u ≤ 1.4.",
    )


def _homothety_axes_row(ref: Integrator) -> FormulaRow:
    """Lines 1130-1134 as read: the axes ρi s of the ellipse through the trace,
    s = √((x/ρ1)² + (y/ρ2)²), against the printed ρi(1 − (3p/4) arctg(ρ1y/(ρ2x)))."""
    xs, ys = _trace(ref)
    worst = np.zeros(len(P_SWEEP))
    axes = ledger_sides("result.homothety_ratio", "corrected_formula")[:2]
    for (_, axis), rho in zip(axes, (RHO1, RHO2), strict=True):
        printed = evaluator(axis, ("x", "y", "rho1", "rho2", "p"))
        for j, p in enumerate(P_SWEEP):
            size = np.sqrt((xs[j] / RHO1) ** 2 + (ys[j] / RHO2) ** 2)
            gap = np.abs(rho * size - printed(xs[j], ys[j], RHO1, RHO2, p)) / rho
            worst[j] = max(worst[j], np.max(gap))
    return formula_row(
        "homothety_axes",
        "lines 1130-1134 as read",
        "; ".join(ledger_text("result.homothety_ratio", "corrected_formula").split("; ")[:2]),
        _p_study(worst, ref),
        ref,
        note="The ellipse homothetic to the one of axes ρ1, ρ2 through each point of the "
        "trace (as for line 1126: ρ1 = 1, ρ2 = 0.4, 0.05 ≤ u ≤ 1.4), its axes over ρi "
        "against the printed ones with the argument ρ1y/(ρ2x) (printed ρ2y/(ρ1x)); the "
        "ratio after half a turn is lecornu.homothety_ratio.",
    )


def conical_rows(ref: Integrator = DEFAULT_INTEGRATOR) -> list[FormulaRow]:
    """Lines 1086-1134: θ² for sin²θ, (50), 1/l², (52), the trace and its ellipse's axes,
    each as read where it is a misprint."""
    return [build(ref) for build in _BUILDERS.values()]


def conical_row(name: str, ref: Integrator = DEFAULT_INTEGRATOR) -> FormulaRow:
    """One of :func:`conical_rows` alone, by its id without the paper (``eq52_as_read``):
    a row whose ledger form was edited is measured again without the other six."""
    return _BUILDERS[name](ref)


# each row's id (without the paper) and its builder, in the order of the lines
_BUILDERS: dict[str, Callable[[Integrator], FormulaRow]] = {
    "area_small_angle": _area_row,
    "composed_planes": _composed_row,
    "eq50": _eq50_row,
    "inverse_square_length": _inverse_square_row,
    "eq52_as_read": _eq52_row,
    "trajectory_after_52": _trajectory_row,
    "homothety_axes": _homothety_axes_row,
}
