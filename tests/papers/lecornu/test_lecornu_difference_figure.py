"""Lecornu's difference figure (printed minus recomputed) as drawn: where its text sits."""

from __future__ import annotations

from helpers.evaluated import committed_claims

from pendcli.data.tables import load_paper_table
from pendcli.papers.lecornu import figures

G = load_paper_table("lecornu").constant("g")


def test_difference_figure_group_names_sit_inside_the_frame_clear_of_every_bar():
    """Each group's name, as drawn at the saved figure's size, lies within the axes and
    overlaps no bar (a two-line name once crossed the frame's top, beside the tallest bar)."""
    import matplotlib

    rows = {r.id: r for r in committed_claims("lecornu")}

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(11.5, 4.5))
    try:
        figures.draw_printed_minus_recomputed(ax, rows, G)
        fig.tight_layout()
        renderer = fig.canvas.get_renderer()
        frame = ax.get_window_extent(renderer)
        names = {name for name, _ in figures.GROUPS}
        drawn = [t for t in ax.texts if t.get_text() in names]
        assert {t.get_text() for t in drawn} == names
        bars = [bar.get_window_extent(renderer) for c in ax.containers for bar in c]
        for text in drawn:
            box = text.get_window_extent(renderer)
            assert frame.x0 <= box.x0 and box.x1 <= frame.x1, text.get_text()
            assert frame.y0 <= box.y0 and box.y1 <= frame.y1, text.get_text()
            assert not any(box.overlaps(bar) for bar in bars), text.get_text()
    finally:
        plt.close(fig)
