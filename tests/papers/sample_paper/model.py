"""The sample paper's model: the small-amplitude period, from the table's constants."""

from __future__ import annotations

import math
from pathlib import Path

from pendcli.data.tables import paper_constant
from pendcli.verify.claims import Recomputed


def period(length: float | None = None) -> float:
    """T = 2π√(l/g), (1) of the sample paper; l and g from its table unless given."""
    metres = paper_constant("sample", "length") if length is None else length
    return 2 * math.pi * math.sqrt(metres / paper_constant("sample", "g"))


def plot_period(path: Path) -> Path:
    """T against l from 0,1 to 2 m."""
    from pendcli.base.plotting import new_figure

    lengths = [0.1 * k for k in range(1, 21)]
    with new_figure(path) as (_fig, ax):
        ax.plot(lengths, [period(x) for x in lengths])
        ax.set_xlabel("l (m)")
        ax.set_ylabel("T (s)")
    return path


CAPTIONS = {"sample-period": "The small-amplitude period 2π√(l/g) against the length l."}


def recompute() -> dict[str, Recomputed]:
    """The paper's one printed number, recomputed."""
    return {"sample.period": Recomputed(period(), method="2π√(l/g), l and g from the table")}


def figures(folder: Path, claims: object = None) -> list[Path]:
    """The paper's one figure, into ``folder`` (``claims``: the judged rows, not needed)."""
    return [plot_period(folder / "sample-period.png")]
