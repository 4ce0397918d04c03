"""`pendcli tradeoff [FAMILY]`: speed against accuracy, measured now (work-precision tables)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from pendcli.cli.common import FormatOption, PlotOption, QuietFlag, busy, emit
from pendcli.cli.values import word
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from pendcli.output import Column
    from pendcli.run.tradeoff_engine import Point


def tradeoff(
    family: Annotated[
        str | None,
        typer.Argument(
            metavar="FAMILY",
            parser=word,
            help="One family, e.g. integral_pi, planar_period, bessel_zeros, conical (an "
            "unknown name lists them all); default: every family of every paper.",
        ),
    ] = None,
    fmt: FormatOption = OutputFormat.table,
    plot: PlotOption = None,
    quick: Annotated[
        bool, typer.Option("--quick", help="Fewer settings and repeats (a smoke test).")
    ] = False,
    write_tables: Annotated[
        Path | None,
        typer.Option(
            "--write-tables",
            metavar="DIR",
            help="Also write each family's table as DIR/FAMILY.csv (DIR: an existing folder, "
            "or a new one inside an existing folder).",
        ),
    ] = None,
    quiet: QuietFlag = False,
) -> None:
    """Measure each method's worst error (against an independent reference) and its cost."""
    from pendcli.base.plotting import validate_plot_path
    from pendcli.cli.targets import check_folder_target
    from pendcli.run import tradeoff as wp
    from pendcli.run.tradeoff_engine import write_table

    plot = validate_plot_path(plot)
    check_folder_target(write_tables, "--write-tables")
    names = wp.family_names() if family is None else [wp.family(family).name]
    points = _measure(names, quick)
    rows = [p.as_dict() for p in points]
    sections = [
        (f"{name}: {wp.family(name).title}", [r for r in rows if r["family"] == name], _columns())
        for name in names
    ]
    # "skipped" stays in the document (the JSON schema names it): every family is measured now.
    emit(fmt, sections, {"rows": rows, "skipped": {}})
    if write_tables is not None:
        for name in names:
            write_table([p for p in points if p.family == name], write_tables / f"{name}.csv")
    if plot is not None:
        with busy("drawing the figure"):
            wp.plot_tradeoff(points, plot)


def _measure(names: list[str], quick: bool) -> list[Point]:
    """Every family in ``names``, with a rich progress bar on stderr when it is a terminal."""
    import sys

    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from pendcli.base.console import console
    from pendcli.run import tradeoff as wp

    points: list[Point] = []
    with Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        TextColumn("{task.completed}/{task.total} families"),
        TimeElapsedColumn(),
        console=console(stderr=True),
        transient=True,
        disable=not sys.stderr.isatty(),
    ) as bar:
        task = bar.add_task("measuring", total=len(names))
        for name in names:
            points += wp.measure_family(
                name, quick=quick, progress=lambda label: bar.update(task, description=label)
            )
            bar.advance(task)
    return points


def _columns() -> tuple[Column, ...]:
    from pendcli.output import Column, fmt_float

    return (
        Column("method", "method"),
        Column("setting", "setting"),
        Column("error", "worst rel. error", fmt=_err, justify="right"),
        Column(
            "seconds", "s / evaluation", fmt=lambda r: fmt_float(r["seconds"], 3), justify="right"
        ),
        Column("evaluations", "f-evals", justify="right"),
    )


def _err(row: Mapping[str, Any]) -> str:
    if row["error"] is None:
        return str(row["note"] or "failed")
    return f"{row['error']:.1e}"
