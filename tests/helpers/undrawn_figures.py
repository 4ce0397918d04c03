"""Figures plotted but not rendered to pixels, for the tests that read a report's text: the
pages embed a figure's bytes in an ``<img>`` attribute, which no reader reads as text, and
show its caption, which is the figure's own. Every page, report.md, JSON and CSV of a whole
report written so are those of a drawn one apart from the embedded image data (compared
once, on the committed tables); the Agg rendering and PNG encoding they skip are about half
of a report's figure CPU.

`python undrawn_figures.py ARGS` is `pendcli ARGS` as ``python -m pendcli`` runs it, its
figures not rendered (:data:`UNDRAWN_CLI`)."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import pytest

PLACEHOLDER = b"a figure plotted, not rendered"
UNDRAWN_CLI = (sys.executable, str(Path(__file__)))


def placeholder(fig: object, path: str | Path) -> Path:
    """What ``save_figure`` writes instead of the figure: a few fixed bytes at ``path``."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(PLACEHOLDER)
    return path


def figures_not_rendered(monkeypatch: pytest.MonkeyPatch) -> None:
    """From here on (in this process and the workers it forks), figures are not rendered."""
    from pendcli.base import plotting

    monkeypatch.setattr(plotting, "save_figure", placeholder)


def main() -> None:
    from pendcli.base import plotting

    plotting.save_figure = placeholder  # type: ignore[assignment]
    sys.argv = ["pendcli", *sys.argv[1:]]
    from pendcli.cli.main import run

    run()


if __name__ == "__main__":
    main()
