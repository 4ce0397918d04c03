"""`pendcli formulas`: every derived formula checked against direct numerical integration."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from pendcli.cli.common import FormatOption, emit
from pendcli.render import OutputFormat

app = typer.Typer(
    help="Derived formulas (series in a small parameter) against direct numerical integration.",
    invoke_without_command=True,
)


@app.callback(invoke_without_command=True)
def formulas(
    paper: Annotated[
        str | None,
        typer.Option("--paper", "-p", help="Only this paper: tisserand, lecornu or charbonnier."),
    ] = None,
    fmt: FormatOption = OutputFormat.table,
    plot: Annotated[
        Path | None,
        typer.Option("--plot", help="Also draw residual against parameter (log-log) into DIR."),
    ] = None,
) -> None:
    """Residual of each derived formula as its small parameter shrinks: observed order, verdict."""
    from pendcli.core.claims import resolve_papers
    from pendcli.core.errors import PendcliError
    from pendcli.papers import formula_checks
    from pendcli.render.views import FORMULA_COLUMNS

    keys = resolve_papers(paper)
    if plot is not None and plot.exists() and not plot.is_dir():
        raise PendcliError(f"--plot {str(plot)!r} is a file; give a folder for the figures")
    results = {key: formula_checks(key) for key in keys}
    sections = []
    for key in keys:
        rows = [r.as_dict() for r in results[key]]
        sections.append((f"{key.capitalize()}: derived formulas", rows, FORMULA_COLUMNS))
    emit(fmt, sections, {"claims": [], "formulas": [r.as_dict() for k in keys for r in results[k]]})
    if plot is not None:
        import importlib

        from pendcli.cli.common import say

        written = []
        for key in keys:
            module = importlib.import_module(f"pendcli.papers.{key}.formulas")
            written += module.figures(plot, results[key])
        if fmt is OutputFormat.table:
            say(f"wrote {len(written)} figure(s) to {plot}")
