"""Lecornu's figures: the example's θ/θ0 against time, and printed minus recomputed.

Each figure is drawn by a ``draw_*`` function on a given matplotlib Axes (so the tests can
read back what is drawn) and written by :func:`figures` or :func:`plot_example`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from pendcli.papers.lecornu.model import (
    ExampleModel,
    constant,
    example_model,
    theta_curves,
)
from pendcli.verify.claims import ClaimRow

__all__ = [
    "GROUPS",
    "Bar",
    "difference_bars",
    "draw_example",
    "draw_example_claims",
    "draw_printed_minus_recomputed",
    "figures",
    "plot_example",
]

Axes = Any  # matplotlib.axes.Axes, imported lazily (pendcli --help stays fast)

_VERDICT_COLOURS = {"agrees": "C2", "truncated": "C1", "last-digit": "C1"}
PRINTED = {"color": "C3", "ms": 9, "mew": 2}  # the printed values: red crosses

# The groups of the difference figure, in the paper's order.
GROUPS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("lengths", tuple(f"lecornu.example.length.{k}" for k in range(1, 6))),
    (
        "times",
        (*(f"lecornu.example.time.{k}" for k in range(1, 6)), "lecornu.example.time_zero_length"),
    ),
    ("intervals", tuple(f"lecornu.example.interval.{k}" for k in range(1, 6))),
    ("J1 lengths", tuple(f"lecornu.j1_lengths.{k}" for k in range(1, 7))),
    ("J0", tuple(f"lecornu.j0_at_j2_zeros.{k}" for k in range(1, 6))),
    (
        "deviations",
        (*(f"lecornu.deviation.{k}" for k in range(2, 6)), "lecornu.deviation.zero_length"),
    ),
    ("mean\npendulum", ("lecornu.mean_pendulum_coefficient",)),
)


def _power(v: float) -> str:
    """−1,2·10⁴: two figures and a power of ten, the decimal comma of the other labels."""
    mantissa, exponent = f"{v:.1e}".split("e")
    sup = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
    return f"{_comma(float(mantissa))}·10{str(int(exponent)).translate(sup)}"


def _comma(v: float) -> str:
    """A number as the paper prints one: the decimal comma (0,35; g = 9,81), one style in
    every label of a figure."""
    from pendcli.data.numbers import edition_number

    return edition_number(float(v), 6)


def _passage_ticks(ax: Axes, times: np.ndarray, label: str) -> None:
    ax.plot(times, np.zeros_like(times), "|", color="C0", ms=14, mew=2, label=label)


# --- `pendcli lecornu example --plot` -------------------------------------------------------


def _times(start: float, end: float) -> np.ndarray:
    """Sample times up to ``end``: uniform, plus a geometric run into ``end``, where the
    oscillation quickens without bound as the length goes to zero (no straight segments)."""
    uniform = np.linspace(start, end, 6000)
    closing = end - np.geomspace(end - start, (end - start) * 1e-7, 3000)
    return np.unique(np.concatenate([uniform, closing[closing > start]]))


def _theta_axis(ax: Axes, theta10: np.ndarray) -> str:
    """A smooth scale (asinh: linear near 0, logarithmic beyond; symlog's corner at ±1 drew
    kinks), limited to solution (10)'s range. Returns the note for a clipped curve."""
    ax.set_yscale("asinh", linear_width=0.5)
    finite = theta10[np.isfinite(theta10)]
    low, high = float(finite.min()), float(finite.max())
    bottom, top = 1.6 * min(low, -1.0), 1.6 * max(high, 1.0)
    ax.set_ylim(bottom, top)
    steps = (0.0, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0)
    ticks = sorted({s * sign for s in steps for sign in (1, -1) if bottom <= s * sign <= top})
    ax.set_yticks(ticks, [f"{v:g}".replace("-", "−") for v in ticks])
    ax.minorticks_off()
    return f"; clipped below {bottom:.0f}"


def _rest_label(theta_rest: np.ndarray, ax: Axes, base: str) -> str:
    """The from-rest curve's label; where it leaves the axis (it grows without bound as the
    length goes to zero: the Y₁ part of its solution), a note on the axis says how far."""
    low = float(np.nanmin(theta_rest))
    if low < ax.get_ylim()[0]:
        ax.text(
            0.99,
            0.02,
            f"dashed curve clipped: it goes on down to {_power(low)}",
            transform=ax.transAxes,
            ha="right",
            fontsize=7,
            color="C1",
        )
    return base


def draw_example(ax: Axes, m: ExampleModel) -> None:
    """θ/θ0 of solution (10) and of the release from rest, elongations and passages marked."""
    t = _times(min(0.0, float(m.passage_times[0])), m.zero_length_time * (1 - 0.02))
    theta10, theta_rest = theta_curves(m, t)
    _theta_axis(ax, theta10)
    ax.plot(t, theta10, color="0.3", lw=1.0, label="solution (10)")
    label = _rest_label(theta_rest, ax, "released from rest at t = 0")
    ax.plot(t, theta_rest, color="C1", lw=0.8, ls="--", label=label)
    ax.plot(m.elongation_times, m.amplitude_ratios, "o", color="C0", label="elongations (10)")
    _passage_ticks(ax, m.passage_times, "vertical passages (10)")
    ax.set_xlabel(
        f"t (s), L = {_comma(m.length)} m at t = 0, shortening at {_comma(m.speed)} m/s, "
        f"g = {_comma(m.g)} m/s²"
    )
    ax.set_ylabel("θ/θ0 (asinh scale)")
    ax.legend(fontsize=8, loc="lower left")


def plot_example(
    path: str | Path,
    speed: float | None = None,
    length: float | None = None,
    g: float | None = None,
) -> Path:
    """θ/θ0 against time for solution (10) and for the release from rest, events marked."""
    from pendcli.base.plotting import new_figure

    m = example_model(speed, length, g)
    with new_figure(path, size=(8.0, 4.8)) as (_fig, ax):
        draw_example(ax, m)
    return Path(path)


# --- the claim figures --------------------------------------------------------------------


def _draw_printed_points(ax: Axes, m: ExampleModel, rows: dict[str, ClaimRow]) -> None:
    """The printed elongations (time, deviation), zero length, and vertical passages."""
    pub_t = [rows[f"lecornu.example.time.{k}"].published_value for k in range(1, 6)]
    pub_r = [1.0] + [rows[f"lecornu.deviation.{k}"].published_value for k in range(2, 6)]
    ax.plot(pub_t, pub_r, "x", **PRINTED, label="elongations, printed")
    ax.plot([m.zero_length_time], [m.zero_length_ratio], "o", color="C0", mfc="none")
    ax.plot(
        [rows["lecornu.example.time_zero_length"].published_value],
        [rows["lecornu.deviation.zero_length"].published_value],
        "x",
        **PRINTED,
    )
    _passage_ticks(ax, m.passage_times, "vertical passages, recomputed")
    pub_lp = np.array([rows[f"lecornu.j1_lengths.{k}"].published_value for k in range(1, 7)])
    ax.plot(
        (m.length - pub_lp) / m.speed,
        np.zeros(6),
        "+",
        color="C3",
        ms=12,
        mew=1.5,
        label="vertical passages from printed lengths",
    )


def draw_example_claims(ax: Axes, m: ExampleModel, rows: dict[str, ClaimRow]) -> None:
    """Figure 1: θ/θ0 of the example against time, recomputed and printed events marked.

    ``m`` is the author's model at the paper's speed, length and g; ``rows`` the judged claims.
    """
    t = _times(m.passage_times[0] - 0.05, m.zero_length_time * (1 - 1e-6))
    theta, theta_rest = theta_curves(m, t)
    speed = _comma(m.speed)
    _theta_axis(ax, theta)
    ax.plot(
        t,
        theta,
        color="0.3",
        lw=1.0,
        label=f"solution (10), b = {speed} m/s, g = {_comma(m.g)} m/s²",
    )
    base = f"released from rest at {_comma(m.length)} m (exact column)"
    ax.plot(t, theta_rest, color="C1", lw=0.8, ls="--", label=_rest_label(theta_rest, ax, base))
    ax.plot(
        m.elongation_times, m.amplitude_ratios, "o", color="C0", label="elongations, recomputed"
    )
    _draw_printed_points(ax, m, rows)
    ax.set_xlabel(f"t (s), pendulum {_comma(m.length)} m long at t = 0, shortening at {speed} m/s")
    ax.set_ylabel("θ/θ0 (asinh scale)")
    ax.set_title("Lecornu's example: elongations and vertical passages", y=1.0)
    ax.axhline(0, color="0.8", lw=0.5)
    ax.legend(fontsize=8, loc="lower left")


Bar = tuple[int, float, str, str]  # x, (printed - recomputed)/unit, verdict, tick label


def difference_bars(rows: dict[str, ClaimRow]) -> tuple[list[Bar], list[tuple[str, int, int]]]:
    """(printed - recomputed) in units of the printed last digit, per claim of GROUPS; and
    each group's (name, first x, last x). Groups are one empty slot apart."""
    from pendcli.data.numbers import parse_printed

    bars: list[Bar] = []
    spans = []
    x = 0
    for name, ids in GROUPS:
        start = x
        for cid in ids:
            r = rows[cid]
            printed = parse_printed(r.published)
            d = (r.published_value - r.recomputed) / (printed.resolution or 1.0)
            bars.append((x, d, r.verdict, f"{r.published_value:.{printed.decimals}f}"))
            x += 1
        spans.append((name, start, x - 1))
        x += 1
    return bars, spans


# the verdict against his own procedure, as the bar's fill pattern and edge (None: no
# procedure of his is known)
_OWN_HATCHES: dict[str | None, tuple[str, str]] = {
    "faithful": ("", "faithful to his procedure (plain)"),
    "faithful if chopped": ("//", "faithful if he chopped here (hatched /)"),
    "faithful if rounded": ("\\\\", "faithful if he rounded here (hatched \\)"),
    "faithful if he kept more digits": ("--", "faithful if he kept unprinted digits (dashed -)"),
    "slip": ("xx", "a slip against his procedure (crossed)"),
    None: ("..", "no known procedure (dotted)"),
}
_TRUTH_LEGEND = (("C2", "agrees"), ("C1", "truncated / last digit"), ("C3", "discrepant"))


def _legend(ax: Axes, seen: set[str | None]) -> None:
    """Colour: the verdict against the truth; fill: the verdict against his procedure."""
    from matplotlib.patches import Patch

    handles = [Patch(facecolor=c, label=f"truth: {w}") for c, w in _TRUTH_LEGEND]
    handles += [
        Patch(facecolor="white", edgecolor="0.2", hatch=h, label=f"own: {w}")
        for key, (h, w) in _OWN_HATCHES.items()
        if key in seen
    ]
    ax.legend(
        handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False
    )


def draw_printed_minus_recomputed(ax: Axes, rows: dict[str, ClaimRow], g: float) -> None:
    """Figure 2: printed minus recomputed, in printed units; the colour is the verdict
    against the truth, the fill pattern the verdict against his own procedure."""
    bars, spans = difference_bars(rows)
    ids = [cid for _, group in GROUPS for cid in group]
    # Symmetric-log beyond ±1: the deviations miss by up to ~40 units, the rest by under 1;
    # headroom above the tallest bar for the group names hung from the frame's top
    top = 8.0 * max(max(b[1] for b in bars), 1.0)
    bottom = 1.6 * min(min(b[1] for b in bars), -1.0)
    owns = [rows[cid].procedure_verdict for cid in ids]
    keys = [None if own is None else str(own) for own in owns]
    seen = set(keys)
    ax.bar(  # one call for all the bars (one call each cost as much again as their drawing)
        [b[0] for b in bars], [b[1] for b in bars],
        color=[_VERDICT_COLOURS.get(b[2], "C3") for b in bars],
        hatch=[_OWN_HATCHES[key][0] for key in keys], edgecolor="0.2", linewidth=0.6,
    )  # fmt: skip
    for name, start, end in spans:  # hung from the frame's top: a two-line name stays inside
        ax.text(
            (start + end) / 2, 0.97, name, ha="center", va="top", fontsize=8,
            transform=ax.get_xaxis_transform(),
        )  # fmt: skip
    ax.axhspan(-0.5, 0.5, color="0.9", zorder=0)
    ax.set_xticks([b[0] for b in bars], [b[3] for b in bars], rotation=90, fontsize=8)
    ax.set_yscale("symlog", linthresh=1.0)
    ax.set_ylabel("(printed − recomputed) / last printed unit\n(linear in ±1, logarithmic beyond)")
    ax.set_ylim(bottom, top)
    steps = (0.0, 0.5, 1.0, 3.0, 10.0, 30.0, 100.0)
    ticks = sorted({s * sign for s in steps for sign in (1, -1) if bottom <= s * sign <= top})
    ax.set_yticks(ticks, [f"{v:g}".replace("-", "−") for v in ticks])
    ax.minorticks_off()
    ax.set_title(f"Lecornu's example, printed minus recomputed (g = {g:g})", fontsize=9, y=1.0)
    _legend(ax, seen)


# The report prints these under the figures (file stem -> caption).
CAPTIONS = {
    "lecornu_example_theta": (
        "Lecornu's example (pendulum 1 m long at t = 0, shortened at 0,35 m/s, g = 9,81 m/s²): "
        "θ/θ0 of the Bessel solution (10) against time, on an asinh scale (linear near 0, "
        "logarithmic beyond). Crosses: the "
        "printed elongation times and amplitudes; dots: recomputed; the vertical passages from "
        "the printed lengths against the recomputed ones. The dashed curve starts from rest at "
        "1 m (the exact column), the solid one is the solution the paper uses; the dashed one "
        "grows without bound as the length goes to zero and leaves the axis (a note on the "
        "axis says how far)."
    ),
    "lecornu_printed_minus_recomputed": (
        "Every number of Lecornu's example, printed minus recomputed, in units of its last "
        "printed digit (linear within ±1, logarithmic beyond, so the deviations, off by up to "
        "about 40 units, fit beside the rest): inside the grey band (±½) a number agrees. "
        "The colour is the verdict against the truth (green agrees, orange truncated or one "
        "unit away, red discrepant: see each row's cause); the fill is the verdict against "
        "his own procedure on his printed inputs (plain faithful, hatched faithful only if he "
        "chopped, crossed a slip, dotted no known procedure), as the legend says."
    ),
}


def figures(outdir: str | Path, claims: list[ClaimRow] | None = None) -> list[Path]:
    """(1) θ/θ0 of the example against time, published and recomputed elongations and vertical
    passages marked; (2) printed minus recomputed, in units of the printed last digit.
    ``claims``: the judged claim rows (the report's), else judged here."""
    from pendcli.base.plotting import new_figure

    if claims is None:
        from pendcli.papers.lecornu.claims import author_procedures, recompute
        from pendcli.verify.claims import evaluate_paper

        claims = evaluate_paper("lecornu", recompute, author_procedures())
    outdir = Path(outdir)
    m = example_model()
    rows = {r.id: r for r in claims}
    path1 = outdir / "lecornu_example_theta.png"
    with new_figure(path1, size=(8.0, 4.8)) as (_fig, ax):
        draw_example_claims(ax, m, rows)
    path2 = outdir / "lecornu_printed_minus_recomputed.png"
    with new_figure(path2, size=(11.5, 4.5)) as (_fig, ax):
        draw_printed_minus_recomputed(ax, rows, constant("g"))
    return [path1, path2]
