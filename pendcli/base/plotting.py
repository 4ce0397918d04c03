"""Figures: matplotlib on the Agg backend, written to files, byte-identical run to run."""

from __future__ import annotations

import functools
import re
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError
from pendcli.base.recent import Recent

if TYPE_CHECKING:
    from types import ModuleType

    from matplotlib.figure import Figure

__all__ = ["new_figure", "save_figure"]

DPI = 120  # the saved figures' resolution (dots per inch)


def _pyplot() -> ModuleType:
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    # one resolution for the layout and the file: tight_layout measures the text with the
    # canvas's renderer, which savefig then draws with (its text metrics cached) where the
    # two resolutions agree, and makes anew where they differ (9 % of the figures' CPU)
    plt.rcParams.update({"svg.hashsalt": "pendcli", "figure.dpi": DPI, "savefig.dpi": DPI})
    return plt


@contextmanager
def new_figure(
    path: str | Path, *, nrows: int = 1, ncols: int = 1, size: tuple[float, float] = (7.0, 4.5)
) -> Iterator[tuple[Figure, Any]]:
    """Yield (fig, axes) and save to ``path`` on exit (PNG, no timestamp metadata).

    ``axes`` is one Axes for a single panel, else an array of them (``nrows`` × ``ncols``).
    The figure is made directly on an Agg canvas, not through pyplot (which would register
    it with a figure manager, and must be told to forget it).
    """
    _pyplot()  # the rcParams above
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, dpi=DPI)
    _canvas_class()(fig)
    axes = fig.subplots(nrows, ncols, squeeze=nrows * ncols == 1)
    yield fig, axes
    save_figure(fig, path)


def save_figure(fig: Figure, path: str | Path) -> Path:
    """Write ``fig`` to ``path`` atomically (base.files): a failure never leaves a 0-byte file."""
    import io

    from pendcli.base.files import atomic_write

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in FIGURE_SUFFIXES:
        raise PendcliError(f"plot path {str(path)!r} must end in .png, .svg or .pdf")
    try:
        # Internal callers (the report) write into folders they have not made yet.
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise PendcliError(f"cannot create folder for plot {str(path)!r}: {exc.strerror}") from None
    plain_powers(fig)
    held = [hold_unlabelled_minor_ticks(ax) for ax in fig.axes]
    fig.tight_layout()
    for ax, minor in zip(fig.axes, held, strict=True):
        lighter_ticks(ax, minor)
    # tight_layout leaves a placeholder layout engine behind, and savefig draws the whole
    # figure once more (without rendering) for any engine: none, so it draws once
    fig.set_layout_engine(None)
    metadata: dict[str, str | None] = {"Creator": None}
    if suffix == ".pdf":
        metadata = {"Creator": None, "Producer": None, "CreationDate": None}
    if suffix == ".png":
        data = _png(fig)
    else:
        buffer = io.BytesIO()
        fig.savefig(buffer, format=suffix[1:], metadata=metadata)
        data = buffer.getvalue()
    atomic_write(path, data)
    return path


def _png(fig: Figure) -> bytes:
    """``fig`` drawn once by Agg at its resolution (what savefig draws), as a PNG without
    metadata: RGB where every pixel is opaque (the figures' white ground: 11 % fewer bytes
    than savefig's RGBA, and 5 % less CPU to encode), else RGBA; zlib's fastest level (the
    report's nine PNGs took 0.48 s of CPU to encode, not 0.68, for 7 % more bytes)."""
    import io

    from PIL import Image

    canvas_class = _canvas_class()
    canvas: Any = fig.canvas if isinstance(fig.canvas, canvas_class) else canvas_class(fig)
    canvas.draw()
    size = (int(canvas.renderer.width), int(canvas.renderer.height))
    image = Image.frombuffer("RGBA", size, canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
    alpha = image.getchannel("A").getextrema()
    if alpha == (255, 255):
        image = image.convert("RGB")
    buffer = io.BytesIO()
    image.save(buffer, format="png", compress_level=1, dpi=(fig.dpi, fig.dpi))
    return buffer.getvalue()


FIGURE_SUFFIXES = (".png", ".svg", ".pdf")


# :func:`_draw_text` repeats, step for step, the Agg ``draw_text`` of this matplotlib series,
# through its private font methods; any other version (pyproject allows 3.8 to 3.x) draws
# with Agg's own, the same pixels a little slower
MIRRORED_MATPLOTLIB = "3.11."


def fast_text_drawing() -> bool:
    """Whether plain text is drawn by :func:`_draw_text` (the installed matplotlib is the
    series it mirrors)."""
    import matplotlib

    return str(matplotlib.__version__).startswith(MIRRORED_MATPLOTLIB)


@functools.cache
def _canvas_class() -> type:
    """An Agg canvas whose renderer draws plain text by :func:`_draw_text` where the installed
    matplotlib is the one it mirrors (:func:`fast_text_drawing`)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    class Canvas(FigureCanvasAgg):
        def get_renderer(self) -> Any:
            renderer = super().get_renderer()
            if "draw_text" not in vars(renderer) and fast_text_drawing():
                renderer.draw_text = functools.partial(_draw_text, renderer)
            return renderer

    return Canvas


# the glyphs a text is set in, by (font, size, resolution, hinting, text): a figure's tick
# labels and axis labels repeat, and setting a text costs as much as drawing its glyphs
_GLYPHS = Recent(20_000)


def _draw_text(
    renderer: Any, gc: Any, x: float, y: float, s: str, prop: Any, angle: float,
    ismath: Any = False, mtext: Any = None,
) -> None:  # fmt: skip
    """Agg's ``draw_text`` for plain text, pixel for pixel: the same glyphs set by the same
    layout at the same places, the layout kept (:data:`_GLYPHS`) and the rotation computed
    once per text rather than once per glyph (a third of Agg's glyph loop in Python)."""
    import math

    import numpy as np
    from matplotlib.backends.backend_agg import RendererAgg, get_hinting_flag
    from matplotlib.ft2font import RenderMode

    if ismath or (mtext is not None and (mtext.get_fontfeatures() or mtext.get_language())):
        RendererAgg.draw_text(renderer, gc, x, y, s, prop, angle, ismath, mtext)
        return
    font = renderer._prepare_font(prop)
    size, flags = prop.get_size_in_points(), get_hinting_flag()
    glyphs = _glyphs(font, size, renderer.dpi, flags, s)
    cos, sin = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    matrix = (0x10000 * np.array([[cos, -sin], [sin, cos]])).round().astype(int)
    mode = RenderMode.NORMAL if gc.get_antialiased() else RenderMode.MONO
    height = renderer.height
    sized = set()
    for face, index, dx, dy in glyphs:
        if face not in sized:  # a fallback font's glyphs
            face.set_size(size, renderer.dpi)
            sized.add(face)
        origin = [
            round(0x40 * (x + dx * cos - dy * sin)),
            round(0x40 * (height - y + dx * sin + dy * cos)),
        ]
        face._set_transform(matrix, origin)
        bitmap = face._render_glyph(index, flags, mode)
        buffer = bitmap.buffer if mode is RenderMode.NORMAL else bitmap.buffer * 0xFF
        top = int(height) - bitmap.top + buffer.shape[0]
        renderer._renderer.draw_text_image(buffer, bitmap.left, top, 0, gc)


def _glyphs(
    font: Any, size: float, dpi: float, flags: Any, s: str
) -> list[tuple[Any, int, float, float]]:
    """(font, glyph index, x, y) of each glyph of ``s``, as Agg sets it, kept."""
    key = (font, font.fname, size, dpi, flags, s)
    glyphs: list[tuple[Any, int, float, float]] | None = _GLYPHS.get(key)
    if glyphs is None:
        glyphs = [(g.ft_object, g.glyph_index, g.x, g.y) for g in font._layout(s, flags=flags)]
        _GLYPHS.put(key, glyphs)
    return glyphs


_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
# what matplotlib's log formatter writes: $\mathdefault{[-][c\times]b^{e}}$
_MATHTEXT_POWER = re.compile(
    r"\$\\mathdefault\{(-?)(?:([0-9.]+)\\times)?([0-9]+)\^\{(-?[0-9]+)\}\}\$"
)


def plain_power(label: str) -> str:
    """A log axis's tick label as plain text: ``$\\mathdefault{2\\times10^{-5}}$`` becomes
    ``2×10⁻⁵`` (Unicode superscripts): set and drawn as plain text (:func:`_draw_text`), not
    parsed and placed glyph by glyph as mathtext; any other label is returned as it is."""
    match = _MATHTEXT_POWER.fullmatch(label)
    if match is None:
        return label
    sign, coefficient, base, exponent = match.groups()
    times = f"{coefficient}×" if coefficient else ""
    return f"{'−' if sign else ''}{times}{base}{exponent.translate(_SUPERSCRIPT)}"


@functools.cache
def _power_formatter() -> type:
    from matplotlib.ticker import Formatter

    class PowerFormatter(Formatter):
        """A log formatter's labels (the same ticks labelled) in plain text."""

        def __init__(self, log: Any) -> None:
            self.log = log

        def set_axis(self, axis: Any) -> None:
            super().set_axis(axis)
            self.log.set_axis(axis)

        def set_locs(self, locs: Any) -> None:
            self.log.set_locs(locs)

        def __call__(self, x: float, pos: int | None = None) -> str:
            return plain_power(self.log(x, pos))

        def format_data(self, value: float) -> str:
            return plain_power(self.log.format_data(value))

    return PowerFormatter


def power_formatter(log: Any) -> Any:
    """The formatter ``log`` (matplotlib's LogFormatterSciNotation), its labels in plain text
    (:func:`plain_power`)."""
    return _power_formatter()(log)


def plain_powers(fig: Figure) -> None:
    """Every log tick label of ``fig`` in plain text (:func:`plain_power`): matplotlib's own
    log formatters wrapped by :func:`power_formatter`, fixed labels rewritten."""
    from matplotlib.ticker import FixedFormatter, LogFormatterSciNotation

    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            for formatter, use in (
                (axis.get_major_formatter(), axis.set_major_formatter),
                (axis.get_minor_formatter(), axis.set_minor_formatter),
            ):
                if type(formatter) is LogFormatterSciNotation:
                    use(power_formatter(formatter))
                elif isinstance(formatter, FixedFormatter):
                    formatter.seq = [plain_power(str(label)) for label in formatter.seq]


def hold_unlabelled_minor_ticks(ax: Any) -> dict[str, tuple[Any, Any]]:
    """Before the layout: each axis's minor ticks that carry no label (a log axis's 2…9
    between its decades) taken off the axis, so that no Tick (five artists, made and copied
    apiece) is made for them; their locator and the style of their first tick, by axis name,
    for :func:`lighter_ticks` to draw them once the layout is done."""
    from matplotlib.ticker import NullLocator

    held = {}
    for axis in (ax.xaxis, ax.yaxis):
        locs = _shown(axis, axis.get_minorticklocs())
        formatter = axis.get_minor_formatter()
        formatter.set_locs(locs)
        if locs and not any(formatter.format_ticks(locs)):
            held[axis.axis_name] = (axis.get_minor_locator(), axis.get_minor_ticks(1)[0])
            axis.set_minor_locator(NullLocator())
    return held


def lighter_ticks(ax: Any, held: dict[str, tuple[Any, Any]]) -> None:
    """After the layout (the ticks' places final): the minor ticks ``held`` by
    :func:`hold_unlabelled_minor_ticks`, their marks as one line of markers and their grid
    lines as one collection, in their first tick's style, instead of a Tick each (the
    work-precision diagram 0.93 -> 0.73 s of CPU, its pixels unchanged). (The major grid
    lines as one collection measured no gain on a residual grid: left as they are.)"""
    from matplotlib.ticker import NullLocator

    for axis, transform in (
        (ax.xaxis, ax.get_xaxis_transform()),
        (ax.yaxis, ax.get_yaxis_transform()),
    ):
        if axis.axis_name not in held:
            continue
        locator, tick = held[axis.axis_name]
        axis.set_minor_locator(locator)  # where it puts them now, those of a major left out
        locs = _shown(axis, axis.get_minorticklocs())
        axis.set_minor_locator(NullLocator())
        _tick_marks(ax, axis, transform, locs, tick)
        if tick.gridline.get_visible():
            _grid_lines(ax, axis, transform, locs, tick)


def _shown(axis: Any, locs: Any) -> list[float]:
    """The ``locs`` matplotlib draws a tick at: within the view, to 1e-10 of its width on the
    axis's scale (as ``Axis._update_ticks``)."""
    low, high = axis.get_transform().transform(sorted(axis.get_view_interval()))
    near = 1e-10 * (high - low)
    scaled = axis.get_transform().transform(locs) if len(locs) else []
    return [float(v) for v, t in zip(locs, scaled, strict=True) if low - near <= t <= high + near]


def _tick_marks(ax: Any, axis: Any, transform: Any, locs: list[float], tick: Any) -> None:
    """The marks of ticks at ``locs`` (on either side where shown), styled as ``tick``'s."""
    from matplotlib.lines import Line2D

    along_x = axis is ax.xaxis
    for line, edge in ((tick.tick1line, 0.0), (tick.tick2line, 1.0)):
        if line.get_visible():
            points = [(v, edge) for v in locs] if along_x else [(edge, v) for v in locs]
            marks = Line2D(*zip(*points, strict=True), linestyle="", marker=line.get_marker(),
                           markersize=line.get_markersize(), color=line.get_color(),
                           markeredgewidth=line.get_markeredgewidth(), transform=transform,
                           clip_on=False, zorder=axis.get_zorder())  # fmt: skip
            marks.set_in_layout(False)
            ax.add_artist(marks)


def _grid_lines(ax: Any, axis: Any, transform: Any, locs: list[float], tick: Any) -> None:
    """The grid lines of ticks at ``locs``, one collection styled as ``tick``'s."""
    from matplotlib.collections import LineCollection

    grid = tick.gridline
    along_x = axis is ax.xaxis
    segments = [((v, 0.0), (v, 1.0)) if along_x else ((0.0, v), (1.0, v)) for v in locs]
    lines = LineCollection(segments, colors=[grid.get_color()], alpha=grid.get_alpha(),
                           linewidths=grid.get_linewidth(), linestyles=grid.get_linestyle(),
                           transform=transform, zorder=axis.get_zorder())  # fmt: skip
    lines.set_clip_path(ax.patch)
    lines.set_in_layout(False)
    ax.add_collection(lines, autolim=False)


def cannot_create_in(folder: Path) -> str | None:
    """Why nothing can be created in ``folder`` (None when a probe file can): tried, not
    guessed from permission bits, which root, read-only mounts and /proc all defeat."""
    import tempfile

    try:
        with tempfile.NamedTemporaryFile(dir=folder, prefix=".pendcli-probe-"):
            return None
    except OSError as exc:
        return exc.strerror or type(exc).__name__


def _existing_folder(option: str, folder: Path) -> None:
    if not folder.exists():
        raise PendcliError(f"{option}: folder {folder} does not exist")
    if not folder.is_dir():
        raise PendcliError(f"{option}: {folder} is not a folder")
    problem = cannot_create_in(folder)
    if problem is not None:
        raise PendcliError(f"{option}: cannot write in {folder}: {problem}")


def validate_plot_path(path: str | Path | None, option: str = "--plot") -> Path | None:
    """Check a --plot FILE before any computation starts: suffix, an existing parent folder."""
    if path is None:
        return None
    path = Path(path)
    if path.suffix.lower() not in FIGURE_SUFFIXES:
        raise PendcliError(f"{option}: {str(path)!r} must end in .png, .svg or .pdf")
    if path.is_dir():
        raise PendcliError(f"{option}: {str(path)!r} is a folder; give a file name ending in .png")
    _existing_folder(option, path.parent if str(path.parent) else Path("."))
    return path


def validate_plot_folder(folder: str | Path | None, option: str = "--plot") -> Path | None:
    """Check a --plot DIR (several figures) before computing: a folder, its parent existing."""
    if folder is None:
        return None
    folder = Path(folder)
    if folder.suffix.lower() in FIGURE_SUFFIXES:
        raise PendcliError(
            f"{option}: this command draws several figures into a folder; "
            f"{str(folder)!r} looks like a file name"
        )
    if folder.exists():
        _existing_folder(option, folder)
    else:
        _existing_folder(option, folder.parent)
    return folder
