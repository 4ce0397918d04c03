"""Lecornu (1894): the figure of his derived formulas, each residual against its small
parameter (log-log), with what each panel shows; the checks themselves are
:mod:`pendcli.papers.lecornu.formulas`."""

from __future__ import annotations

from pathlib import Path

from pendcli.papers.lecornu.formulas import formula_checks
from pendcli.papers.lecornu.formulas_base import PAPER
from pendcli.papers.lecornu.formulas_slow import SLOW_PANELS
from pendcli.verify.claims import FormulaRow
from pendcli.verify.formula_plots import PanelLabels, grid_caption, plot_studies

__all__ = ["CAPTIONS", "PANELS", "figures"]

# What each residual panel shows. Times are in units of √(a/g) (the reduced time τ = γt);
# angles of the small oscillations are divided by their amplitude (ρ, θ0 or u's, set to 1).
_P, _K = "p = b/√(ga), dimensionless", "k = sin(θ0/2), dimensionless"
_TIME, _AMPLITUDE = "units of √(a/g)", "÷ amplitude"
_PANELS: tuple[tuple[str, str, str, str], ...] = (
    ("table26.first_elongation", "time of the first elongation", _P, _TIME),
    ("table26.second_vertical", "time of the 2nd vertical passage", _P, _TIME),
    ("table26.first_negative_elongation", "time of the 2nd elongation", _P, _TIME),
    ("table26.third_vertical", "time of the 3rd vertical passage", _P, _TIME),
    ("oscillation_time_increase", "oscillation time increase", _P, _TIME),
    ("eq26", "θ(t) to first order in p", _P, _AMPLITUDE),
    ("eq28", "u = θl/a to second order in p", _P, _AMPLITUDE),
    ("eq29", "θ(t) to second order in p", _P, _AMPLITUDE),
    ("period_second_order", "period to second order in p", _P, _TIME),
    ("mean_pendulum", "lag behind the mean pendulum", _P, _TIME),
    ("elongation_ratio", "ratio of successive elongations", _P, "ratio, dimensionless"),
    ("eq52", "conical pendulum θ1, θ2", _P, _AMPLITUDE),
    ("homothety_ratio", "homothety ratio, half a turn", _P, "ratio, dimensionless"),
    ("compound_pendulum", "compound as simple pendulum", f"{_P}; R/a = 0.5", "÷ θ0"),
    ("eq31", "fast shortening θ(z)", "s·z0 = ga/b², dimensionless", "rad; α = 0.5 rad"),
    ("amplitude_series", "θ to k³ from am u", _K, "rad"),
    ("eq38", "finite oscillations θ(u)", _K, "rad"),
    ("eq41_terms_in_p", "∂θ/∂p at p = 0", _K, "rad"),
    ("k3_neglected", "(41) with k³ neglected", _P, _AMPLITUDE),
    ("eq42_terms_in_b", "∂T/∂p of the quarter period", _K, _TIME),
    ("eq42prime_terms_in_b", "(42) with k = θ0/2", "θ0 (rad)", _TIME),
    ("area_small_angle", "θ² for sin²θ in (44)", "θ (rad)", "relative"),
    ("composed_planes", "two plane pendulums for the conical", "first angle A (rad)", "relative"),
    ("eq50", "conical pendulum θ1, θ2", _P, _AMPLITUDE),
    ("inverse_square_length", "1/l² to first order", _P, "× a²"),
    ("eq52_as_read", "conical pendulum θ1, θ2", _P, _AMPLITUDE),
    ("trajectory_after_52", "the trace's equation", _P, "dimensionless"),
    ("homothety_axes", "axes of the trace's ellipse", _P, "÷ ρi"),
)
PANELS: dict[str, PanelLabels] = SLOW_PANELS | {
    f"{PAPER}.{id_}": PanelLabels(name, parameter, unit) for id_, name, parameter, unit in _PANELS
}

# The report prints these under the figures (file stem -> caption).
CAPTIONS = {
    "formulas_lecornu": grid_caption(
        "Lecornu",
        "Reference: solve_ivp (DOP853, rtol 1e-12) on Lecornu's own equations in his reduced "
        "variables τ = t√(g/a), p = b/√(ga); times in units of √(a/g). The amplitude series "
        "against mpmath's am u; θ² for sin²θ and 1/l² against their closed forms; the two "
        "plane pendulums of line 1094 against the bob's motion in space (l = 1 + 0.05t m).",
    ),
}


def figures(outdir: str | Path, rows: list[FormulaRow] | None = None) -> list[Path]:
    """One PNG: residual against parameter for every Lecornu formula (log-log)."""
    path = Path(outdir) / "formulas_lecornu.png"
    plot_studies(
        path,
        rows if rows is not None else formula_checks(),
        "Lecornu (1894): derived formulas against direct integration",
        PANELS,
    )
    return [path]
