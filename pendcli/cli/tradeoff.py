"""`pendcli tradeoff [FAMILY]`: speed against accuracy, measured now (work-precision tables)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from pendcli.cli.common import FormatOption, PlotOption, emit
from pendcli.render import OutputFormat

app = typer.Typer(
    help="Speed against accuracy: error achieved and time per evaluation, per method.",
    invoke_without_command=True,
    # a group stops reading options at its first positional argument unless told otherwise
    context_settings={"allow_interspersed_args": True},
)


@app.callback(invoke_without_command=True)
def tradeoff(
    family: Annotated[
        str | None,
        typer.Argument(
            help="One family (integral_pi, integral_x, planar_period, charbonnier_loss, "
            "bessel_zeros, conical, ...); default: every family whose module is there."
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
            "--write-tables", help="Also write each family's table as <DIR>/<family>.csv."
        ),
    ] = None,
) -> None:
    """Measure each method's worst error (against an independent reference) and its cost."""
    from pendcli import tradeoff as wp
    from pendcli.cli.common import say
    from pendcli.core.plotting import validate_plot_path
    from pendcli.render import Column, fmt_float

    plot = validate_plot_path(plot)
    ready, skipped = wp.available_families()
    if family is not None:
        if family in skipped:
            from pendcli.core.errors import PendcliError

            raise PendcliError(f"family {family!r} is skipped: {skipped[family]}")
        wp._family(family)  # one-line error for an unknown name
        ready, skipped = [family], {}
    for name, why in skipped.items():
        say(f"tradeoff: skipping {name}: {why}")
    points = []
    with _progress(len(ready)) as report:
        for name in ready:
            points.extend(wp.measure_family(name, quick=quick, progress=report))
            report(None)
    rows = [p.as_dict() for p in points]
    columns = (
        Column("method", "method"),
        Column("setting", "setting"),
        Column("error", "worst rel. error", fmt=lambda r: _err(r), justify="right"),
        Column(
            "seconds", "s / evaluation", fmt=lambda r: fmt_float(r["seconds"], 3), justify="right"
        ),
        Column("evaluations", "f-evals", justify="right"),
    )
    sections = [
        (f"{name}: {wp.FAMILIES[name].title}", [r for r in rows if r["family"] == name], columns)
        for name in ready
    ]
    emit(fmt, sections, {"rows": rows, "skipped": skipped})
    if write_tables is not None:
        for name in ready:
            wp.write_table([p for p in points if p.family == name], write_tables / f"{name}.csv")
    if plot is not None:
        wp.plot_tradeoff(points, plot)


def _err(row: dict) -> str:
    if row["error"] is None:
        return row["note"] or "failed"
    return f"{row['error']:.1e}"


class _progress:
    """A rich progress bar on stderr, only when stderr is a terminal."""

    def __init__(self, families: int):
        import sys

        self.enabled = sys.stderr.isatty()
        self.total = families

    def __enter__(self):
        if not self.enabled:
            return lambda label: None
        from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

        from pendcli.core.console import console

        self.bar = Progress(
            TextColumn("{task.description}"),
            BarColumn(),
            TextColumn("{task.completed}/{task.total} families"),
            TimeElapsedColumn(),
            console=console(stderr=True),
            transient=True,
        )
        self.bar.__enter__()
        self.task = self.bar.add_task("measuring", total=self.total)

        def report(label: str | None) -> None:
            if label is None:  # a family is done
                self.bar.advance(self.task)
            else:
                self.bar.update(self.task, description=label)

        return report

    def __exit__(self, *exc):
        if self.enabled:
            self.bar.__exit__(*exc)
        return False
