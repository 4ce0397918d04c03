"""The figures of the formula checks: one log-log panel of |reference − formula| against the
small parameter per formula (:func:`draw_study`), a grid of them per paper
(:func:`plot_studies`) and the report's caption of that grid (:func:`grid_caption`).
The studies and their verdicts are :mod:`pendcli.verify.formula_engine`'s.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from pendcli.data.vocabulary import FormulaVerdict
from pendcli.verify.claims import FormulaRow

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["PANEL_FONT", "PanelLabels", "draw_study", "grid_caption", "plot_studies"]


@dataclass(frozen=True)
class PanelLabels:
    """What one residual panel names: the formula, its small parameter, the residual's unit."""

    name: str  # a short name printed after the formula's label, e.g. "period to p²"
    parameter: str  # the x axis: the small parameter with its unit, e.g. "θ0 (rad)"
    residual: str  # the unit of |reference − formula|, e.g. "rad", "÷ amplitude"


PANEL_FONT = 8  # points at the saved size; nothing in a grid is smaller
_HOLDS, _FAILS = "tab:green", "tab:red"


def grid_caption(paper: str, details: str = "") -> str:
    """The report's caption of the residual grid ``formulas_<paper>`` (``details``: the
    paper's reference solution and parameters, appended)."""
    text = (
        f"{paper}'s derived formulas, one panel per formula: |reference − formula| against "
        "the formula's small parameter (named under each panel, with its unit) on log-log "
        "axes. Green: the formula holds; red: it fails. The dashed line has the claimed order "
        "and passes through the residual at the smallest parameter, so a red curve flatter "
        "than its dashed line is a formula wrong at the order the paper claims; a flat curve "
        "at the bottom is a residual at the reference's error level (exact in the model)."
    )
    return f"{text} {details}".strip()


def plot_studies(
    path: str | Path,
    rows: Sequence[FormulaRow],
    title: str,
    labels: Mapping[str, PanelLabels],
    ncols: int = 3,
) -> None:
    """One log-log panel per row (:func:`draw_study`), written to ``path``; ``labels`` names
    every drawn row's panel (by row id). Identity checks (no claimed order) have no parameter
    to shrink and are not drawn."""
    from pendcli.base.plotting import new_figure

    rows = [r for r in rows if r.residuals and r.claimed_order is not None]
    if not rows:
        return
    unlabelled = [r.id for r in rows if r.id not in labels]
    if unlabelled:
        raise ValueError(f"no panel labels for {', '.join(unlabelled)}")
    nrows = math.ceil(len(rows) / ncols)
    size = (4.3 * ncols, 3.4 * nrows + 0.6)
    with new_figure(path, nrows=nrows, ncols=ncols, size=size) as (fig, axes):
        flat = list(np.ravel(axes))
        for ax, row in zip(flat, rows, strict=False):  # more panels than rows
            draw_study(ax, row, labels[row.id])
        for ax in flat[len(rows) :]:
            ax.set_visible(False)
        _grid_header(fig, title)


def _grid_header(fig: Any, title: str) -> None:
    """The figure's title and, once for all panels, what the colours and the dashes mean."""
    from matplotlib.lines import Line2D

    handles = [
        Line2D([], [], color=_HOLDS, marker="o", ms=4, label="|residual|, formula holds"),
        Line2D([], [], color=_FAILS, marker="o", ms=4, label="|residual|, formula fails"),
        Line2D([], [], color="gray", ls="--", lw=1, label="claimed order (slope)"),
    ]
    # anchored in inches from the top: tight_layout reserves the suptitle's height there
    top = 1 - 0.06 / fig.get_figheight()
    fig.suptitle(title, fontsize=PANEL_FONT + 3, x=0.01, y=top, ha="left", va="top")
    fig.legend(
        handles=handles,
        loc="upper right",
        bbox_to_anchor=(0.99, top),  # inside the edge: the last label was clipped there
        ncols=3,
        fontsize=PANEL_FONT + 1,
        frameon=False,
        borderaxespad=0,
    )


def _verdict_line(row: FormulaRow) -> str:
    claimed = "" if row.claimed_order is None else f"{row.claimed_order:g}"
    if row.observed_order is None:
        if row.verdict == FormulaVerdict.HOLDS:
            return f"holds: residual at the reference's error (claimed order {claimed})"
        return f"{row.verdict} (claimed order {claimed})"
    return f"{row.verdict}: order {row.observed_order:.2f} observed, {claimed} claimed"


def draw_study(ax: Axes, row: FormulaRow, labels: PanelLabels) -> None:
    """|residual| against the parameter on log-log axes, green if it holds, red if it fails,
    with a dashed line of the claimed slope through the smallest parameter's residual."""
    from matplotlib.ticker import LogFormatterSciNotation, LogLocator, NullFormatter, NullLocator

    ps = np.array([p for p, _ in row.residuals])
    rs = np.array([r for _, r in row.residuals])
    positive = rs > 0
    color = _HOLDS if row.verdict == FormulaVerdict.HOLDS else _FAILS
    ax.loglog(ps[positive], rs[positive], "o-", color=color, ms=4)
    if row.claimed_order is not None and positive.any():
        i = int(np.argmin(np.where(positive, ps, np.inf)))
        line = rs[i] * (ps / ps[i]) ** row.claimed_order
        ax.loglog(ps, line, "--", color="gray", lw=1)
    # the title carries what a legend would (drawing 20 legends doubled the figure's cost)
    from pendcli.data.reader_text import figure_text  # b_n v^n as bₙ vⁿ

    title = figure_text(f"{row.source}  {labels.name}")
    # y given: where matplotlib would put it (no tick label above the frame), not searched
    # for at each draw by measuring the panel's axes (a tenth of the grid's CPU)
    ax.set_title(f"{title}\n{_verdict_line(row)}", fontsize=PANEL_FONT, y=1.0)
    ax.set_xlabel(figure_text(labels.parameter), fontsize=PANEL_FONT)
    ax.set_ylabel(figure_text(f"|reference − formula| ({labels.residual})"), fontsize=PANEL_FONT)
    # Minor log ticks over many decades make tight_layout take seconds: majors only, with
    # a labelled tick at each end of a sweep narrower than a decade.
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(LogLocator(numticks=6))
        axis.set_minor_locator(NullLocator())
        axis.set_minor_formatter(NullFormatter())
    _label_sweep_ends(ax, ps)
    shown = rs[positive]
    # fewer than two powers of ten within the residuals: 1, 2, 5 of each decade, so that the
    # axis has more than one labelled tick
    if shown.size and np.floor(np.log10(shown.max())) - np.ceil(np.log10(shown.min())) < 1:
        ax.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.yaxis.set_major_formatter(  # every one of them labelled, not only the decade
            LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(np.inf, np.inf))
        )
    else:
        _fix_ticks(ax.yaxis)
    ax.tick_params(labelsize=PANEL_FONT)
    ax.grid(True, alpha=0.3)


def _fix_ticks(axis: Any) -> None:
    """The ticks and labels the axis's locator and formatter give for its final limits (the
    data drawn), within them, fixed: each of the layout's and the drawing's many looks at the
    ticks then reads them rather than locates and formats them afresh."""
    from matplotlib.ticker import FixedFormatter, FixedLocator

    low, high = np.log10(axis.get_view_interval())
    near = 1e-10 * abs(high - low)  # matplotlib's own allowance at the ends
    locs = [t for t in axis.get_major_locator()() if t > 0]
    labels = axis.get_major_formatter().format_ticks(locs)
    kept = [
        (t, s)
        for t, s in zip(locs, labels, strict=True)
        if low - near <= np.log10(t) <= high + near
    ]
    axis.set_major_locator(FixedLocator([t for t, _ in kept]))
    axis.set_major_formatter(FixedFormatter([s for _, s in kept]))


def _label_sweep_ends(ax: Axes, ps: np.ndarray) -> None:
    """x ticks at the sweep's smallest and largest parameter (a 5-point sweep spans less than
    two decades, so the decade ticks alone often show one number or none)."""
    lo, hi = float(ps.min()), float(ps.max())
    if lo == hi:
        return
    decades = [10.0**k for k in range(math.ceil(math.log10(lo)), math.floor(math.log10(hi)) + 1)]
    # a decade tick within a factor 1.6 of an end would print on top of it
    ticks = [lo, *(d for d in decades if d / lo > 1.6 and hi / d > 1.6), hi]
    ax.set_xticks(ticks, [f"{t:.3g}" for t in ticks])
