"""The PNG a figure is saved as: the pixels matplotlib's own savefig draws, no metadata."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from pendcli.base.plotting import new_figure


def _draw(ax, transparent: bool) -> None:  # type: ignore[no-untyped-def]
    ax.plot([1, 20, 3000], [3, 1, 2], "o-", color="tab:red")
    ax.set_title("a title, $x^2$ and 10⁻³")
    ax.set_ylabel("turned: √(a/g), θ₀")  # drawn at 90°
    # x over decades: minor ticks without labels, with grid lines; y within one: labelled
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    if transparent:
        ax.figure.patch.set_alpha(0.0)
        ax.patch.set_alpha(0.5)


def _savefig_pixels(transparent: bool) -> np.ndarray:
    """The same figure through matplotlib's savefig (RGBA), decoded: the independent view."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    from pendcli.base.plotting import plain_powers

    fig, ax = plt.subplots(figsize=(4.0, 3.0), dpi=120)
    try:
        _draw(ax, transparent)
        plain_powers(fig)  # the same tick labels (tested below), drawn by matplotlib's Agg
        fig.tight_layout()
        buffer = io.BytesIO()
        fig.savefig(buffer, format="png", dpi=120)
    finally:
        plt.close(fig)
    return np.asarray(Image.open(io.BytesIO(buffer.getvalue())).convert("RGBA"))


@pytest.mark.parametrize("transparent", [False, True])
def test_a_saved_png_has_the_pixels_savefig_draws(tmp_path: Path, transparent: bool) -> None:
    path = tmp_path / "f.png"
    with new_figure(path, size=(4.0, 3.0)) as (_fig, ax):
        _draw(ax, transparent)
    image = Image.open(path)
    # opaque: RGB, a quarter fewer bytes to compress; see-through: the alpha is kept
    assert image.mode == ("RGBA" if transparent else "RGB")
    assert image.info.get("dpi") == pytest.approx((120, 120), abs=0.1)  # stored per metre
    assert not {"Software", "Creation Time"} & set(image.info)
    assert np.array_equal(np.asarray(image.convert("RGBA")), _savefig_pixels(transparent))


def test_another_matplotlib_draws_its_text_with_agg_s_own(monkeypatch, tmp_path: Path) -> None:
    """The fast text path mirrors one matplotlib series' private font methods: under another
    version (pyproject allows 3.8 on) Agg's own draw_text is used, the same pixels."""
    import matplotlib

    from pendcli.base import plotting

    if not plotting.fast_text_drawing():
        pytest.skip("the installed matplotlib already draws with Agg's own")
    with new_figure(tmp_path / "fast.png", size=(4.0, 3.0)) as (fig, ax):
        _draw(ax, False)
    assert "draw_text" in vars(fig.canvas.get_renderer())  # the mirrored series: the fast path
    monkeypatch.setattr(matplotlib, "__version__", "3.8.4")
    assert not plotting.fast_text_drawing()
    with new_figure(tmp_path / "f.png", size=(4.0, 3.0)) as (fig, ax):
        _draw(ax, False)
    assert "draw_text" not in vars(fig.canvas.get_renderer())
    image = np.asarray(Image.open(tmp_path / "f.png").convert("RGBA"))
    assert np.array_equal(image, _savefig_pixels(False))


def _superscript(n: int) -> str:
    digits = dict(zip("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹", strict=True))
    return "".join(digits[c] for c in str(n))


def test_log_tick_labels_are_plain_text_powers_of_the_tick_values(tmp_path: Path) -> None:
    """Every log tick label a saved figure shows is its tick's value written 10ⁿ or c×10ⁿ in
    Unicode (no mathtext), on a wide axis (decades) and a narrow one (2, 5 between)."""
    import math

    with new_figure(tmp_path / "f.png", ncols=2, size=(6.0, 3.0)) as (_fig, axes):
        wide, narrow = axes[0]  # one row of two
        wide.loglog([1e-9, 1e-2], [1e-12, 10.0])
        narrow.loglog([1.0, 3.0], [2e-5, 7e-5])
    shown = 0
    for ax in (wide, narrow):
        for axis in (ax.xaxis, ax.yaxis):
            low, high = sorted(axis.get_view_interval())
            for tick in [*axis.get_major_ticks(), *axis.get_minor_ticks()]:
                value, text = tick.get_loc(), tick.label1.get_text()
                if not text or not low <= value <= high:
                    continue
                exponent = math.floor(math.log10(value) + 1e-9)
                coefficient = round(value / 10.0**exponent)
                power = f"10{_superscript(exponent)}"
                assert text == (power if coefficient == 1 else f"{coefficient}×{power}")
                shown += 1
    assert shown >= 10


def test_a_saved_png_is_the_same_bytes_each_time(tmp_path: Path) -> None:
    for name in ("a.png", "b.png"):
        with new_figure(tmp_path / name, size=(4.0, 3.0)) as (_fig, ax):
            _draw(ax, transparent=False)
    assert (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()
