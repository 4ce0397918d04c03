"""Tisserand's figures: the projected path, and the series' error against the exact motion.

Each figure has a ``draw_*(ax, ...)`` that draws on a given matplotlib Axes (what the tests
inspect) and a ``plot_*(path, ...)`` that writes it to a file.
"""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.numerics.spherical import check_amplitudes, projected_path
from pendcli.papers.tisserand.model import (
    exact_conical,
    example_angles,
    example_ratio,
    series_conical,
    series_path,
)

if TYPE_CHECKING:
    import numpy as np
    from matplotlib.axes import Axes

__all__ = [
    "SERIES_ERROR_CURVES",
    "draw_path",
    "draw_series_error",
    "figures",
    "plot_path",
    "plot_series_error",
    "series_error_curves",
]

# The report prints these under the figures (file stem -> caption).
CAPTIONS = {
    "tisserand_path": (
        "The bob's projection on the horizontal plane over six radial periods, for "
        "θ0 = 30°, θ1 = 15° (large angles, so that the rotation of the ellipse is visible): the "
        "exact motion (an ODE integration of the spherical pendulum) and Tisserand's series "
        "(II)-(VI) coincide to the eye, which is the point; the lower panel gives their "
        "distance at equal times, in units of the length l. Dotted: the series' ellipse "
        "(III)-(IV), turned by the rotation (V) at the start of each radial period."
    ),
    "tisserand_series_error": (
        "Relative error of each coefficient of Tisserand's series against the exact motion "
        "(mpmath quadrature of (1)-(2)), as θ0 grows with θ1 = θ0/2. Straight lines are the "
        "orders the truncation leaves; the dotted line marks the 30° of the figure above."
    ),
}

# label of each curve of the series-error figure (Ω is drawn dashed: see draw_series_error)
SERIES_ERROR_CURVES = (
    "k'",
    "k''",
    "Ω",
    "sin 2k't in ψ",
    "sin 4k't in ψ",
    "sin 2k't in φ'",
)


def figures(outdir: str | Path, claims: object = None) -> list[Path]:
    """(1) the projected path over several turns with the series' ellipse; (2) series errors.
    (``claims``, the judged claim rows, draw nothing here.)"""
    outdir = Path(outdir)
    return [
        plot_path(outdir / "tisserand_path.png"),
        plot_series_error(outdir / "tisserand_series_error.png"),
    ]


# ---------------------------------------------------------------- the projected path


def draw_path(
    ax: Axes,
    theta0: float | None = None,
    theta1: float | None = None,
    turns: int = 6,
    gap_ax: Axes | None = None,
) -> None:
    """The bob's projection over ``turns`` radial periods: exact path, series path, ellipses.

    Sampled 120 times per radial period, so sample 120 j falls on the j-th apocentre. The two
    paths coincide to the eye, which is the point; ``gap_ax`` shows how far apart they are.
    """
    import numpy as np

    if theta0 is None or theta1 is None:
        theta0, theta1 = example_angles()
    theta0, theta1 = check_amplitudes(theta0, theta1)
    exact = exact_conical(theta0, theta1)
    series = series_conical(theta0, theta1, order=6)
    kt = np.linspace(0.0, turns * exact.radial_period, 120 * turns + 1)
    x, y = projected_path(theta0, theta1, kt)
    xs, ys = series_path(theta0, theta1, kt)
    ax.plot(x, y, "-", color="tab:blue", lw=1.0, label="exact motion (ODE)")
    ax.plot(xs, ys, "--", color="tab:red", lw=0.9, label="Tisserand (II)-(VI)")
    ex, ey = _ellipse(theta0, theta1)
    for j in range(turns + 1):
        rot = series.precession * series.k1 * j * exact.radial_period
        ax.plot(
            ex * math.cos(rot) - ey * math.sin(rot),
            ex * math.sin(rot) + ey * math.cos(rot),
            ":",
            color="gray",
            lw=0.6,
            label="series ellipse, each radial period" if j == 0 else None,
        )
    ax.set_aspect("equal")
    ax.set_xlabel("x / l (bob's projection on the horizontal plane)")
    ax.set_ylabel("y / l")
    gap = np.hypot(x - xs, y - ys)
    ax.set_title(
        f"Projected path, θ0 = {math.degrees(theta0):g}°, θ1 = {math.degrees(theta1):g}°, "
        f"{turns} radial periods:\nthe series lies on the exact path (at most {gap.max():.1e} l "
        "away)",
        fontsize=10,
        y=1.0,  # where matplotlib puts it, not searched for at each draw
    )
    if gap_ax is not None:
        _draw_gap(gap_ax, kt / exact.radial_period, gap)
    ax.legend(loc="lower left", fontsize=8)
    ax.grid(True, alpha=0.3)


def _draw_gap(ax: Axes, periods: np.ndarray, gap: np.ndarray) -> None:
    """Distance between the series' bob and the exact one at the same time, in units of l."""
    ax.semilogy(periods[1:], gap[1:], color="tab:purple", lw=0.9)
    ax.set_xlabel("time (radial periods)")
    ax.set_ylabel("|series − exact| / l")
    ax.set_title("distance between the two paths at equal times", fontsize=9, y=1.0)
    ax.grid(True, which="both", alpha=0.3)


def _ellipse(theta0: float, theta1: float) -> tuple[np.ndarray, np.ndarray]:
    """(III)-(IV): the ellipse of semi-axes u0 = sin θ0, u1 = sin θ1, major axis along x."""
    import numpy as np

    angle = np.linspace(0, 2 * math.pi, 361)
    return math.sin(theta0) * np.cos(angle), math.sin(theta1) * np.sin(angle)


def plot_path(
    path: str | Path, theta0: float | None = None, theta1: float | None = None, turns: int = 6
) -> Path:
    """:func:`draw_path` written to ``path``."""
    from pendcli.base.plotting import new_figure

    with new_figure(path, nrows=2, size=(6.5, 8.2)) as (fig, axes):
        path_ax, gap_ax = axes.flat
        draw_path(path_ax, theta0, theta1, turns, gap_ax=gap_ax)
        gap_ax.set_box_aspect(0.3)
        fig.tight_layout()
    return Path(path)


# ---------------------------------------------------------------- the series' error


def series_error_curves(ratio: float, degrees: np.ndarray) -> dict[str, list[float]]:
    """|series - exact|/|exact| at θ0 = ``degrees``, θ1 = ratio·θ0, one list per curve."""
    curves: dict[str, list[float]] = {name: [] for name in SERIES_ERROR_CURVES}
    for deg in degrees:
        theta0 = math.radians(deg)
        s = series_conical(theta0, ratio * theta0, 6)
        x = exact_conical(theta0, ratio * theta0)
        pairs = (
            (s.k1, x.k1),
            (s.k2, x.k2),
            (s.precession, x.precession),
            (s.psi_coeffs[0], x.psi_coeffs[0]),
            (s.psi_coeffs[1], x.psi_coeffs[1]),
            (s.phi_coeffs[0], x.phi_coeffs[0]),
        )
        for name, (a, b) in zip(SERIES_ERROR_CURVES, pairs, strict=True):
            curves[name].append(abs(a - b) / abs(b) if b != 0 else math.nan)
    return curves


def _ratio_text(ratio: float) -> str:
    fraction = Fraction(ratio).limit_denominator(100)
    if fraction == ratio and fraction.numerator == 1 and fraction.denominator > 1:
        return f"θ0/{fraction.denominator}"
    return f"{ratio}·θ0"


def draw_series_error(ax: Axes, ratio: float | None = None) -> None:
    """|series - exact|/|exact| for k', k'', Ω and the printed coefficients, against θ0."""
    import numpy as np

    ratio = example_ratio() if ratio is None else ratio
    degrees = np.geomspace(0.5, 85.0, 40)
    for name, values in series_error_curves(ratio, degrees).items():
        # k'' and Ω = (3/8) u0 u1 k''/k' carry the same relative error: draw Ω dashed.
        style = "--" if name == "Ω" else "-"
        label = "Ω (same error as k'')" if name == "Ω" else name
        ax.plot(degrees, values, style, lw=1.2, label=label)
    example = math.degrees(example_angles()[0])
    ax.axvline(example, color="gray", ls=":", lw=0.8)
    ax.text(
        1.05 * example, 1e-9, f"example θ0 = {example:g}°", rotation=90, fontsize=7, color="gray"
    )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(1e-16, 10)
    ax.set_xlabel(f"θ0 (degrees), θ1 = {_ratio_text(ratio)}")
    ax.set_ylabel("relative error of the series")
    ax.set_title("Tisserand's series (I), (II), (V) against the exact motion", y=1.0)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)


def plot_series_error(path: str | Path, ratio: float | None = None) -> Path:
    """:func:`draw_series_error` written to ``path``."""
    from pendcli.base.plotting import new_figure

    with new_figure(path, size=(7.0, 4.8)) as (_fig, ax):
        draw_series_error(ax, ratio)
    return Path(path)
