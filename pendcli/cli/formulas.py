"""`pendcli formulas`: every derived formula checked against direct numerical integration."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from pendcli.cli.common import FormatOption, PaperOption, QuietFlag, busy, emit
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from pendcli.output import Section
    from pendcli.verify.claims import FormulaRow

FigureFolderOption = Annotated[
    Path | None,
    typer.Option(
        "--plot", metavar="DIR", help="Also draw residual against parameter (log-log) into DIR."
    ),
]


def formulas(
    paper: PaperOption = None,
    fmt: FormatOption = OutputFormat.table,
    plot: FigureFolderOption = None,
    quiet: QuietFlag = False,
) -> None:
    """Residual of each derived formula as its small parameter shrinks: observed order, verdict."""
    from pendcli.papers.registry import formula_checks, resolve_papers

    keys = resolve_papers(paper)
    _check_figure_folder(plot)
    results = {key: formula_checks(key) for key in keys}
    rows = [r.as_dict() for key in keys for r in results[key]]
    emit(fmt, _sections(results), {"claims": [], "formulas": rows})
    if plot is not None:
        with busy("drawing the figures"):
            written = _draw(plot, results)
        if fmt is OutputFormat.table:
            from pendcli.cli.common import say

            say(f"wrote {len(written)} figure(s) to {plot}")


def _check_figure_folder(plot: Path | None) -> None:
    from pendcli.base.plotting import validate_plot_folder

    validate_plot_folder(plot)


def _sections(results: dict[str, list[FormulaRow]]) -> list[Section]:
    from pendcli.output.views import FORMULA_COLUMNS

    return [
        (f"{key.capitalize()}: derived formulas", [r.as_dict() for r in rows], FORMULA_COLUMNS)
        for key, rows in results.items()
    ]


def _draw(folder: Path, results: dict[str, list[FormulaRow]]) -> list[Path]:
    """Each paper's residual figures (its ``Paper.formula_figures``) into ``folder``."""
    from pendcli.papers.registry import paper

    written: list[Path] = []
    for key, rows in results.items():
        draw = paper(key).formula_figures
        if draw is not None:
            written += draw(folder, rows)
    return written
