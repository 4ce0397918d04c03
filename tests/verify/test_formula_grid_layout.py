"""A residual grid as saved: where each panel's title sits, measured on the drawn figure."""

from __future__ import annotations

from typing import Any

import pytest
from helpers.evaluated import committed_formulas

from pendcli.papers.tisserand.formulas import PANELS
from pendcli.verify import formula_plots


@pytest.fixture(scope="module")
def saved_grid(tmp_path_factory: Any) -> Any:
    """Tisserand's grid laid out and written as the report writes it; the figure kept (drawn
    once for the module: the tests only read it)."""
    with pytest.MonkeyPatch.context() as monkeypatch:
        yield _saved_grid(monkeypatch, tmp_path_factory.mktemp("grid"))


def _saved_grid(monkeypatch: Any, tmp_path: Any) -> Any:
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    from pendcli.base import plotting

    kept = []
    save = plotting.save_figure

    def keep(fig: Any, path: Any) -> Any:
        kept.append(fig)
        return save(fig, path)

    monkeypatch.setattr(plotting, "save_figure", keep)
    monkeypatch.setattr(plt, "close", lambda fig: None)
    rows = committed_formulas("tisserand")
    formula_plots.plot_studies(tmp_path / "grid.png", rows, "Tisserand", PANELS)
    (fig,) = kept
    return fig


def test_each_panel_title_sits_just_above_its_frame_clear_of_its_tick_labels(
    saved_grid: Any,
) -> None:
    """The title stands on the frame's top, its baseline the title pad above it (6 points: 10
    pixels at 120 dpi), clear of every tick label of its panel and below the figure's header:
    the panels' titles are fixed there, not searched for at each draw."""
    fig = saved_grid
    renderer = fig.canvas.get_renderer()
    pad = 6 * fig.dpi / 72
    (suptitle,) = [t for t in fig.texts if t.get_text() == "Tisserand"]
    header = min(
        suptitle.get_window_extent(renderer).y0, fig.legends[0].get_window_extent(renderer).y0
    )
    panels = [ax for ax in fig.get_axes() if ax.get_visible()]
    assert len(panels) >= 9
    for ax in panels:
        frame = ax.get_window_extent(renderer)
        title = ax.title.get_window_extent(renderer)
        # the baseline is the pad above the frame; the letters' descent reaches below it
        assert frame.y1 < title.y0 <= frame.y1 + pad, ax.get_title()
        labels = [t for t in (*ax.get_xticklabels(), *ax.get_yticklabels()) if t.get_text()]
        assert labels
        for label in labels:
            assert not title.overlaps(label.get_window_extent(renderer)), label.get_text()
        assert title.y1 <= header, ax.get_title()


def _shown_ticks(ax: Any) -> list[tuple[float, str]]:
    """The y ticks drawn within the panel: (value, label)."""
    low, high = ax.get_ylim()
    ticks = zip(ax.get_yticks(), ax.get_yticklabels(), strict=True)
    return [(float(v), t.get_text()) for v, t in ticks if low <= v <= high]


def test_each_panel_y_ticks_are_matplotlibs_own_for_its_data(saved_grid: Any) -> None:
    """The y ticks each panel shows are those matplotlib's log locator and formatter give an
    axes of the same lines (the panel's ticks are fixed once its limits are known). The other
    axes is not drawn: asking for its limits, ticks and labels has matplotlib autoscale,
    locate and format them as a draw would (the labels' text is set by the formatter then)."""
    import matplotlib.pyplot as plt
    from matplotlib.ticker import LogLocator

    fig = saved_grid
    other_fig, other = plt.subplots()
    try:
        for ax in (ax for ax in fig.get_axes() if ax.get_visible()):
            other.cla()
            for line in ax.get_lines():
                other.loglog(*line.get_data())
            other.yaxis.set_major_locator(LogLocator(numticks=6))
            other.set_xlim(ax.get_xlim())
            mine = _shown_ticks(ax)
            assert mine, ax.get_title()
            if ax.yaxis.get_major_locator().__class__.__name__ == "LogLocator":
                continue  # a sweep within a decade: 1, 2, 5 of each, left to matplotlib
            # matplotlib's ticks, labelled 10ⁿ in plain text (not its mathtext 10^{n})
            theirs = [(v, _power(v)) for v, _ in _shown_ticks(other)]
            assert mine == theirs, ax.get_title()
    finally:
        plt.close(other_fig)


def _power(value: float) -> str:
    """10⁻⁷ for 1e-7: the label of a decade tick."""
    import math

    digits = dict(zip("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹", strict=True))
    return "10" + "".join(digits[c] for c in str(round(math.log10(value))))
