"""Speed against accuracy, the catalogue: every paper's work-precision families by name, and
their diagrams.

Each paper declares its families in ``pendcli.papers.<paper>.speed`` (``FAMILIES:
list[Family]``, its ``Paper.tradeoff_families``), built with the engine
:mod:`pendcli.run.tradeoff_engine` (measuring, the tables, the choice of a method);
:func:`families` collects them, in the registry's order, on first use (so importing this
module loads no paper). This module asks the registry; no paper imports it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError, invalid_value
from pendcli.run.tradeoff_engine import Family, Point, measure

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "CAPTION",
    "ERROR_RANGE",
    "draw_family",
    "families",
    "family",
    "family_names",
    "family_title",
    "measure_family",
    "method_name",
    "plot_tradeoff",
]

# ---------------------------------------------------------------------------------------------
# The families the papers declare


# Built once per set of registered papers (a test may register one of its own for a while).
_FAMILIES: dict[str, Family] = {}
_PAPER_OF: dict[str, str] = {}  # family name -> the paper that declares it
_BUILT_FOR: tuple[object, ...] | None = None  # the papers _FAMILIES was built from


def families() -> dict[str, Family]:
    """Every paper's families by name, collected once from each ``Paper.tradeoff_families``
    (``papers/<paper>/speed.py``)."""
    global _BUILT_FOR
    from pendcli.papers.registry import all_papers

    papers = all_papers()
    if papers != _BUILT_FOR:
        collected: dict[str, Family] = {}
        owners: dict[str, str] = {}
        for paper in papers:
            declared = paper.tradeoff_families
            for fam in declared() if declared is not None else ():
                if fam.name in collected:
                    raise PendcliError(f"tradeoff family {fam.name!r} is declared twice")
                collected[fam.name] = fam
                owners[fam.name] = paper.key
        _FAMILIES.clear()
        _FAMILIES.update(collected)
        _PAPER_OF.clear()
        _PAPER_OF.update(owners)
        _BUILT_FOR = papers
    return _FAMILIES


def __getattr__(name: str) -> Any:
    if name == "FAMILIES":  # the mapping, built on first use
        return families()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def family_names(papers: Sequence[str] | None = None) -> list[str]:
    """The names of every family (or of those the given papers declare), in the papers' order."""
    names = list(families())
    return names if papers is None else [n for n in names if _PAPER_OF[n] in papers]


def family(name: str) -> Family:
    """The family called ``name``; a one-line error naming the valid ones otherwise."""
    known = families()
    if name not in known:
        raise invalid_value("family", name, f"one of {', '.join(known)}")
    return known[name]


def measure_family(
    name: str, quick: bool = False, progress: Callable[[str], None] | None = None
) -> list[Point]:
    """All points of the family called ``name``, measured now (see
    :func:`pendcli.run.tradeoff_engine.measure`)."""
    return measure(family(name), quick, progress)


# ---------------------------------------------------------------------------------------------
# Work-precision diagrams


#: the error axis of a work-precision panel; errors outside are drawn on its edge as ▲ / ▼
ERROR_RANGE = (1e-17, 1.0)
CAPTION = (
    "Work-precision diagrams, one panel per family of computations the papers need: the "
    "worst relative error over the family's problems against the time per evaluation, one "
    "line per method, its points the method's settings (terms, tolerances, iterations). "
    "Errors are against an independent reference (mpmath at 50 digits or a closed form). "
    f"The error axis is cut to [{ERROR_RANGE[0]:.0e}, {ERROR_RANGE[1]:g}]: a ▲ on the top edge "
    "is a method whose error exceeds 1 (it diverges there), a ▼ on the bottom edge an error "
    "below 1e-17 (exact to double precision). The dotted line is double rounding, 1.1e-16. "
    "Timings are those of the machine that ran the report."
)


def family_title(name: str) -> str:
    """The panel title of a family: its declared title, wrapped (the name if undeclared)."""
    from pendcli.data.reader_text import figure_text, wrapped

    title = families()[name].title if name in families() else name
    return wrapped(figure_text(title), 56)  # « (n, β) » whole; j_(ν,s) set as j with ν,s below


def _on_scale(error: float) -> tuple[float, str]:
    """(where an error is drawn, "" inside ERROR_RANGE or the edge marker ▲ / ▼ outside)."""
    low, high = ERROR_RANGE
    if error > high:
        return high, "^"
    if error < low:
        return low, "v"
    return error, ""


# Legend names of the methods (the keys stay the --method names and the tables' column).
_METHOD_NAMES: dict[str, str] = {
    "auto": "pendcli's default (mpmath first zeros, McMahon beyond)",
    "mcmahon": "McMahon's expansion",
    "mcmahon-newton": "McMahon + Halley steps",
    "mpmath": "mpmath besseljzero",
    "scipy": "scipy jn_zeros",
    "first-order": "Charbonnier's first-order formula (no. 16)",
    "ode-DOP853": "ODE, solve_ivp DOP853",
    "ode-LSODA": "ODE, solve_ivp LSODA",
    "ode-RK45": "ODE, solve_ivp RK45",
    "ode": "ODE, solve_ivp",
    "quad": "scipy quad",
    "asymptotic": "asymptotic series of Γ ratios",
    "exact-rational": "exact rationals (recurrence)",
    "gammaln": "exp of a gammaln difference",
    "integral_pi": "pendcli's default (Wallis, double-double)",
    "products": "the printed products, in floats",
    "recurrence": "the printed recurrence, in floats",
    "scipy-beta": "scipy beta(½, m)",
    "betainc": "scipy betainc, sin²x rounded",
    "fast": "scipy betainc + rounding correction",
    "pendcli": "pendcli's default (mpmath betainc, 40 digits)",
    "bessel": "Bessel solution (10)",
    "agm": "pendcli's default (AGM to convergence)",
    "agm-fixed": "AGM, fixed iterations",
    "ellipk": "scipy ellipk",
    "ellipkm1": "scipy ellipkm1",
}
_FAMILY_METHOD_NAMES = {
    ("conical", "series"): "Tisserand's series",
    ("bessel_zeros", "series"): "Lecornu's ascending series",
    ("planar_period", "series"): "series in sin²(θ0/2)",
}


def method_name(family: str, method: str) -> str:
    """What a method is, for a legend: ``fast`` -> ``scipy betainc + rounding correction``."""
    return _FAMILY_METHOD_NAMES.get((family, method)) or _METHOD_NAMES.get(method, method)


def draw_family(ax: Axes, name: str, points: list[Point]) -> None:
    """One panel: log error against log time, one line per method (failed points left out);
    errors outside ERROR_RANGE sit on its edge as ▲ (above) or ▼ (below, exact)."""
    from matplotlib.colors import to_hex

    rows = [p for p in points if p.family == name and p.error is not None]
    edges: dict[str, set[str]] = {}  # marker -> the colours drawn with it
    for method in dict.fromkeys(p.method for p in rows):
        pts = [p for p in rows if p.method == method]  # in order of the setting
        drawn = [_on_scale(p.error or 0.0) for p in pts]
        inside = [i for i, (_, edge) in enumerate(drawn) if not edge]
        (line,) = ax.plot(
            [p.seconds for p in pts],
            [y for y, _ in drawn],
            "o-" if len(pts) > 1 else "s",
            ms=4,
            markevery=inside,
            label=method_name(name, method),
        )
        for marker in ("^", "v"):
            off = [
                (p.seconds, y) for p, (y, edge) in zip(pts, drawn, strict=True) if edge == marker
            ]
            if off:
                edges.setdefault(marker, set()).add(to_hex(line.get_color()))
                ax.plot(
                    *zip(*off, strict=True),
                    marker,
                    ms=8,
                    color=line.get_color(),
                    clip_on=False,
                    label=f"_{method} off scale",
                )
    _family_axes(ax, name, edges)


def _family_axes(ax: Axes, name: str, edges: dict[str, set[str]]) -> None:
    """Scales, the cut error range, labels, and a legend outside the data (with the edges')."""
    from matplotlib.lines import Line2D
    from matplotlib.ticker import LogLocator, NullFormatter

    ax.set_xscale("log")
    ax.set_yscale("log")
    low, high = ERROR_RANGE
    ax.set_ylim(low / 3, high * 3)
    ax.axhline(1.1e-16, color="gray", lw=0.6, ls=":")
    # below a few decades matplotlib labels the minor ticks too, printing them on each other
    ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.yaxis.set_major_locator(LogLocator(numticks=10))
    ax.set_title(family_title(name), fontsize=9, y=1.0)
    ax.set_xlabel("seconds per evaluation")
    ax.set_ylabel("worst relative error")
    ax.grid(True, which="both", alpha=0.3)
    handles, _ = ax.get_legend_handles_labels()
    notes = {"^": f"error > {high:g}, off scale", "v": f"error < {low:.0e}, off scale"}
    # drawn in its method's colour: the key shows that colour where one method is off scale,
    # and a hollow marker (« in its method's colour ») where several are
    extra = []
    for m in ("^", "v"):
        colours = edges.get(m, set())
        if len(colours) == 1:
            extra.append(Line2D([], [], color=next(iter(colours)), ls="", marker=m, ms=7,
                                label=notes[m]))  # fmt: skip
        elif colours:
            extra.append(Line2D([], [], color="black", mfc="none", ls="", marker=m, ms=7,
                                label=f"{notes[m]} (its method's colour)"))  # fmt: skip
    ax.legend(
        handles=[*handles, *extra],
        fontsize=8,
        loc="upper left",
        bbox_to_anchor=(1.01, 1.0),
        borderaxespad=0,
    )


def plot_tradeoff(points: list[Point], path: str | Path) -> Path:
    """The work-precision diagram: one panel per family (:func:`draw_family`), saved."""
    from pendcli.base.plotting import new_figure

    names = list(dict.fromkeys(p.family for p in points))
    ncols = 2 if len(names) > 1 else 1
    nrows = max(1, math.ceil(len(names) / ncols))
    size = (7.5 * ncols, 4.4 * nrows)  # each panel's legend sits to its right
    with new_figure(path, nrows=nrows, ncols=ncols, size=size) as (fig, axes):
        flat = [ax for row in axes for ax in row] if nrows * ncols > 1 else [axes]
        if len(names) % ncols:  # a last row of one: centred, not beside an empty cell
            for ax in flat[-ncols:]:
                ax.remove()
            spec = flat[-1].get_subplotspec().get_gridspec()[nrows - 1, :]
            flat[-ncols] = fig.add_subplot(spec.subgridspec(1, 4)[0, 1:3])
        for ax, name in zip(flat, names, strict=False):
            draw_family(ax, name, points)
    return Path(path)
