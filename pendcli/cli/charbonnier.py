"""`pendcli charbonnier ...`: the I_n(π) table and the integrals I_n(x)."""

from __future__ import annotations

import math
import sys
from typing import TYPE_CHECKING, Annotated

import typer

from pendcli.cli.common import FormatOption, PlotOption, QuietFlag, busy, emit, refuse_both
from pendcli.cli.help_format import command, group
from pendcli.cli.values import number, word
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from pendcli.output import Column

app = group("Charbonnier 1908: perturbations, the table of I_n(π).", "charbonnier")


@command(app, "charbonnier table")
def table(
    n_max: Annotated[
        int,
        typer.Option(
            "--n-max", metavar="N", help="Extend the table beyond the printed n = 5 up to N."
        ),
    ] = 5,
    fmt: FormatOption = OutputFormat.table,
    plot: PlotOption = None,
    quiet: QuietFlag = False,
) -> None:
    """The printed table of I_n(π), n = 0..5, and its closed forms, against recomputation."""
    from pendcli.base.plotting import validate_plot_path
    from pendcli.output.views import FORMULA_COLUMNS, claim_columns
    from pendcli.papers.charbonnier.claims import recompute
    from pendcli.papers.charbonnier.explore import table_rows
    from pendcli.papers.charbonnier.figures import plot_table
    from pendcli.papers.charbonnier.formulas import closed_form_rows
    from pendcli.verify.claims import evaluate_paper

    plot = validate_plot_path(plot)
    rows = table_rows(n_max)
    claims = [r.as_dict() for r in evaluate_paper("charbonnier", recompute)]
    # only the closed forms belong to the table; the ODE checks are `pendcli formulas`
    formulas = [f.as_dict() for f in closed_form_rows()]
    emit(
        fmt,
        [
            (
                "Charbonnier no. 15: printed I_n(π) against recomputation",
                claims,
                claim_columns(claims),
            ),
            (f"I_n(π) for n = -1..{n_max}", rows, _table_columns()),
            ("The printed closed forms", formulas, FORMULA_COLUMNS),
        ],
        {"claims": claims, "formulas": formulas, "table": rows},
    )
    if plot is not None:
        with busy("drawing the figure"):
            plot_table(plot, n_max=max(n_max, 5))


def _table_columns() -> tuple[Column, ...]:
    from pendcli.output import Column, fmt_float

    return (
        Column("n", "n", justify="right"),
        Column("published", "printed"),
        Column("exact", "exact (recurrence, rationals)"),
        Column(
            "closed_form_matches_recurrence",
            "printed closed form = recurrence",
            fmt=lambda r: "yes" if r["closed_form_matches_recurrence"] else "NO",
        ),
        Column(
            "recurrence_float",
            "recurrence (double)",
            fmt=lambda r: fmt_float(r["recurrence_float"], 17),
            justify="right",
        ),
        Column("beta", "B(1/2,(n+2)/2)", fmt=lambda r: fmt_float(r["beta"], 17), justify="right"),
    )


@command(app, "charbonnier integral", context_settings={"ignore_unknown_options": True})
def integral(
    n: Annotated[
        int, typer.Argument(metavar="N", help="The order N: an integer, -1 <= N <= 10^15.")
    ],
    x: Annotated[
        float,
        typer.Option(
            "--x",
            "-x",
            metavar="X",
            parser=number,
            help="The upper limit X: a real number, |X| <= 1e6; by default π.",
            show_default=False,
        ),
    ] = math.pi,
    tol: Annotated[
        float | None,
        typer.Option(
            "--tol",
            metavar="TOL",
            parser=number,
            help="Use the cheapest method whose measured worst relative error is <= TOL "
            "(tables/tradeoff, see `pendcli tradeoff`).",
        ),
    ] = None,
    method: Annotated[
        str | None,
        typer.Option(
            "--method",
            metavar="METHOD",
            parser=word,
            help="Force a method of the tradeoff tables (recurrence, quad, ...).",
        ),
    ] = None,
    fmt: FormatOption = OutputFormat.table,
    quiet: QuietFlag = False,
) -> None:
    """I_N(X) = ∫_0^X sin^(N+1) t dt for any integer N >= -1 and real X (by default π)."""
    refuse_both("tol", tol, "method", method)
    from pendcli.output import Column, fmt_float
    from pendcli.papers.charbonnier.explore import integral_row

    row = integral_row(n, x, tol=tol, method=method)
    if "warning" in row:  # on stderr, so stdout stays the value (JSON keeps it in the row)
        sys.stderr.write(f"pendcli: warning: {row['warning']}\n")
    columns = [
        Column("n", "N", justify="right"),
        Column("x", "X", fmt=lambda r: fmt_float(r["x"], 17), justify="right"),
        Column("value", "I_N(X)", fmt=lambda r: fmt_float(r["value"], 17), justify="right"),
    ]
    if "exact" in row:
        columns.append(Column("exact", "exact"))
    columns.append(Column("method", "method"))
    emit(fmt, [("", [row], columns)], {"claims": [], "formulas": [], "integral": row})
