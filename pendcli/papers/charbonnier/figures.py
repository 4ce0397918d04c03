"""Charbonnier's figure: I_n(π) against n, the printed entries of no. 15 marked.

:func:`draw_table` draws on a given matplotlib Axes (what the tests inspect);
:func:`plot_table` writes it to a file; :func:`figures` is what the report draws.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.data.tables import load_paper_table
from pendcli.papers.charbonnier.model import integral_pi

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "MIN_N_MAX",
    "draw_printed_minus_recomputed",
    "draw_table",
    "figures",
    "plot_table",
    "printed_points",
]

# The report prints these under the figures (file stem -> caption).
CAPTIONS = {
    "charbonnier-In-pi": (
        "Charbonnier's Iₙ(π) = ∫₀^π sinⁿ⁺¹x dx against n + 2 (log-log): the printed table "
        "entries (circles) sit on the recomputed curve by construction, since every printed "
        "entry is an exact expression (π·1·3/(2·4), …); the lower panel shows the value of "
        "each printed expression minus the recomputed Iₙ(π), in units in the last place of "
        "the recomputed double (0 for all seven). The dotted line is the asymptote "
        "√(2π/(n+2)) the large-n entries approach."
    ),
}
MIN_N_MAX = 40  # the curve always reaches n = 40, where the asymptote is visibly close


def figures(outdir: str | Path, claims: object = None) -> list[Path]:
    """The report's Charbonnier figures: I_n(π) against n, printed entries marked (from the
    published table: ``claims``, the judged rows, are not needed)."""
    path = Path(outdir) / "charbonnier-In-pi.png"
    plot_table(path, n_max=200)
    return [path]


def printed_points() -> list[tuple[int, float]]:
    """(n, printed value) for every printed I_n(π) of the table (tables/published)."""
    claims = load_paper_table("charbonnier").claims
    return [
        (int(c.id.rsplit("n", 1)[1]), c.number.value)
        for c in claims
        if c.id.startswith("charbonnier.I_pi.n")
    ]


def plot_table(path: str | Path, n_max: int = 5) -> None:
    """Write :func:`draw_table` over :func:`draw_printed_minus_recomputed` to ``path``."""
    from pendcli.base.plotting import new_figure

    with new_figure(path, nrows=2, size=(7.0, 6.0)) as (_fig, axes):
        top, bottom = axes[:, 0]  # an nrows × 1 array
        top.get_gridspec().set_height_ratios((3, 1))
        draw_table(top, n_max)
        draw_printed_minus_recomputed(bottom)


def draw_printed_minus_recomputed(ax: Axes) -> None:
    """Each printed I_n(π) (its exact expression, evaluated) minus the recomputed value, in
    units in the last place of the recomputed double."""
    printed = printed_points()
    ulps = [(value - integral_pi(n)) / math.ulp(integral_pi(n)) for n, value in printed]
    ax.plot([n for n, _ in printed], ulps, "o", mfc="none", color="tab:red", ms=7)
    ax.axhline(0, color="tab:blue", lw=1)
    ax.set_xticks([n for n, _ in printed])
    ax.set_ylim(-2.5, 2.5)
    ax.set_xlabel("n")
    ax.set_ylabel("printed − recomputed\n(ulp)")
    ax.set_title(
        "printed entries are exact expressions: they match to the last bit", fontsize=10, y=1.0
    )
    ax.grid(True, alpha=0.3)


def draw_table(ax: Axes, n_max: int = 5) -> None:
    """I_n(π) against n + 2 on log-log axes, n = -1..max(n_max, 40), printed entries marked,
    with the asymptote √(2π/(n+2))."""
    ns = list(range(-1, max(n_max, MIN_N_MAX) + 1))
    xs = [n + 2 for n in ns]
    ax.plot(
        xs, [integral_pi(n) for n in ns], "-", color="tab:blue", lw=1.2, label="recomputed Iₙ(π)"
    )
    printed = printed_points()
    ax.plot(
        [n + 2 for n, _ in printed],
        [value for _, value in printed],
        "o",
        mfc="none",
        color="tab:red",
        ms=8,
        label="printed (Charbonnier 1908, no. 15)",
    )
    asymptote = [math.sqrt(2 * math.pi / x) for x in xs]
    ax.plot(xs, asymptote, ":", color="gray", label="asymptote √(2π/(n+2))")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("n + 2")
    ax.set_ylabel("Iₙ(π) = ∫₀$^π$ sinⁿ⁺¹x dx")
    _plain_ticks(ax)
    # the printed entries are exact expressions: on the curve by construction, not by fit
    ax.set_title("Charbonnier's Iₙ(π): printed (exact expressions) and recomputed", y=1.0)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()


def _plain_ticks(ax: Axes) -> None:
    """The log axes' ticks as plain numbers with the paper's decimal comma (0,2 · 1 · 100),
    not 2×10⁻¹."""
    from matplotlib.ticker import FuncFormatter, NullFormatter

    from pendcli.data.numbers import edition_number

    plain = FuncFormatter(lambda v, _pos: edition_number(float(f"{v:.3g}"), 3))
    ax.xaxis.set_major_formatter(plain)
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.yaxis.set_major_formatter(plain)
    ax.yaxis.set_minor_formatter(  # 0,2 0,3 0,5 between the decades, not every ninth
        FuncFormatter(lambda v, pos: plain(v, pos) if f"{v:.0e}"[0] in "235" else "")
    )
