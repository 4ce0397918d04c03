"""Figures: matplotlib on the Agg backend, written to files, byte-identical run to run."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.core.errors import PendcliError

if TYPE_CHECKING:
    from types import ModuleType

    from matplotlib.figure import Figure

__all__ = ["new_figure", "save_figure"]


def _pyplot() -> ModuleType:
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    plt.rcParams.update({"svg.hashsalt": "pendcli", "figure.dpi": 100, "savefig.dpi": 120})
    return plt


@contextmanager
def new_figure(
    path: str | Path, *, nrows: int = 1, ncols: int = 1, size: tuple[float, float] = (7.0, 4.5)
) -> Iterator[tuple[Figure, Any]]:
    """Yield (fig, axes) and save to ``path`` on exit (PNG, no timestamp metadata).

    ``axes`` is one Axes for a single panel, else an array of them (``nrows`` × ``ncols``).
    """
    plt = _pyplot()
    fig, axes = plt.subplots(nrows, ncols, figsize=size, squeeze=nrows * ncols == 1)
    try:
        yield fig, axes
        save_figure(fig, path)
    finally:
        plt.close(fig)


def save_figure(fig: Figure, path: str | Path) -> Path:
    path = Path(path)
    if path.suffix.lower() not in (".png", ".svg", ".pdf"):
        raise PendcliError(f"plot path {str(path)!r} must end in .png, .svg or .pdf")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise PendcliError(f"cannot create folder for plot {str(path)!r}: {exc.strerror}") from None
    fig.tight_layout()
    metadata = {"Software": None} if path.suffix.lower() == ".png" else {"Creator": None}
    if path.suffix.lower() == ".pdf":
        metadata = {"Creator": None, "Producer": None, "CreationDate": None}
    try:
        fig.savefig(path, metadata=metadata)
    except OSError as exc:
        raise PendcliError(f"cannot write plot {str(path)!r}: {exc.strerror}") from None
    return path


def validate_plot_path(path: str | Path | None) -> Path | None:
    """Check a --plot argument before any computation starts."""
    if path is None:
        return None
    path = Path(path)
    if path.suffix.lower() not in (".png", ".svg", ".pdf"):
        raise PendcliError(f"plot path {str(path)!r} must end in .png, .svg or .pdf")
    if path.exists() and path.is_dir():
        raise PendcliError(f"plot path {str(path)!r} is a folder; give a file name ending in .png")
    return path
