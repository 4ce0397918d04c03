"""`pendcli tisserand ...`: the conical pendulum's series against its exact motion."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Annotated, Any

import typer

from pendcli.cli.common import FormatOption, PlotOption, QuietFlag, busy, emit
from pendcli.cli.help_format import command, group
from pendcli.cli.values import number
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from pendcli.output import Column

app = group("Tisserand 1881: the conical pendulum, series (I)-(VI) against the exact motion.",
            "tisserand")  # fmt: skip

AngleOption = Annotated[
    str | None,
    typer.Option(
        metavar="ANGLE",
        help="Angle with its unit: 30°, 30deg, 30', 30arcmin, 90arcsec, 0.52rad (a unit is "
        "required). Default: the example's θ0 and θ1; --theta0 alone keeps the example's "
        "ratio θ1/θ0.",
    ),
]
Row = Mapping[str, Any]


def _number(key: str, sig: int = 12) -> Callable[[Row], str]:
    from pendcli.output import fmt_float

    return lambda r: "" if r.get(key) is None else fmt_float(r[key], sig)


def _relative(key: str) -> Callable[[Row], str]:
    return lambda r: "" if r.get(key) is None else f"{r[key]:+.2e}"


def _angle_or_number(key: str) -> Callable[[Row], str]:
    """The sexagesimal text for an angle row, the number otherwise."""
    number = _number(key)

    def text(row: Row) -> str:
        if row.get("unit") == "rad" and f"{key}_text" in row:
            return str(row[f"{key}_text"])
        return number(row)

    return text


@command(app, "tisserand claims")
def claims(fmt: FormatOption = OutputFormat.table, quiet: QuietFlag = False) -> None:
    """The printed numbers of the example and Resal's rate, with verdicts and the unit reading."""
    from pendcli.output.views import FORMULA_COLUMNS, claim_columns
    from pendcli.papers.tisserand import explore, model
    from pendcli.papers.tisserand.claims import recompute
    from pendcli.papers.tisserand.formulas import formula_checks
    from pendcli.verify.claims import evaluate_paper

    rows = [r.as_dict() for r in evaluate_paper("tisserand", recompute)]
    formulas = [f.as_dict() for f in formula_checks()]
    readings = explore.reading_rows()
    printed0, printed1 = model.example_reading(model.PRINTED_UNIT)
    emit(
        fmt,
        [
            ("Tisserand 1881: printed against recomputed", rows, claim_columns(rows)),
            (
                f"Reading of « θ0 = {printed0}, θ1 = {printed1} »: Tisserand's series",
                readings,
                _reading_columns(explore.printed_example()),
            ),
            ("Series (I), (II), (V) against the exact motion", formulas, FORMULA_COLUMNS),
        ],
        {"claims": rows, "formulas": formulas, "readings": readings},
    )


def _reading_columns(printed: Mapping[str, str]) -> tuple[Column, ...]:
    from pendcli.output import Column

    return (
        Column("reading", "reading"),
        Column("theta0", "θ0"),
        Column("theta1", "θ1"),
        Column("psi_sin2", f"ψ: sin 2k't (printed {printed['b1']})", justify="right"),
        Column("psi_sin4", f"ψ: sin 4k't (printed {printed['b2']})", justify="right"),
        Column("phi_sin2", f"φ': sin 2k't (printed {printed['c1']})", justify="right"),
        Column(
            "displacement_mm",
            f"shift, mm (printed {printed['shift']})",
            digits=3,
            justify="right",
        ),
    )


@command(app, "tisserand example")
def example(
    theta0: AngleOption = None,
    theta1: AngleOption = None,
    length: Annotated[
        float | None,
        typer.Option(
            metavar="METRES",
            parser=number,
            help="Pendulum length in metres (default: the remark's l).",
        ),
    ] = None,
    fmt: FormatOption = OutputFormat.table,
    plot: PlotOption = None,
    quiet: QuietFlag = False,
) -> None:
    """Published / series / exact (by quadrature, ODE and elliptic integrals) side by side."""
    from pendcli.base.plotting import validate_plot_path
    from pendcli.papers.tisserand import explore, figures, model, units

    plot = validate_plot_path(plot)
    derived = theta0 is not None and theta1 is None
    theta0, theta1 = _angles(theta0, theta1)
    a, b = units.amplitudes(theta0, theta1)
    if derived:
        from pendcli.cli.common import say

        say(f"--theta1 not given: {theta1}, the example's ratio θ1/θ0 = {model.example_ratio():g}")
    length = units.parse_length(model.example_length_m() if length is None else length)
    rows = explore.example_rows(a, b, length)
    title = f"Conical pendulum θ0 = {theta0}, θ1 = {theta1}, l = {length:g} m"
    emit(
        fmt,
        [(title, rows, _example_columns(rows))],
        {"claims": [], "formulas": [], "example": rows},
    )
    if plot is not None:
        with busy("drawing the figure"):
            figures.plot_path(plot, a, b)


def _angles(theta0: str | None, theta1: str | None) -> tuple[str, str]:
    """θ0 and θ1 as given, else the example's; θ1 alone missing keeps the example's ratio
    θ1/θ0 (the command says so on stderr): ``--theta0 10°`` does not fail on a θ1 never set."""
    import math

    from pendcli.papers.tisserand import model, units

    default0, default1 = model.example_reading()
    if theta0 is not None and theta1 is None:
        ratio = model.example_ratio()
        theta1 = f"{math.degrees(units.parse_angle(theta0, 'theta0') * ratio):.6g}°"
    return (default0 if theta0 is None else theta0), (default1 if theta1 is None else theta1)


def _example_columns(rows: list[dict[str, Any]]) -> tuple[Column, ...]:
    from pendcli.output import Column

    columns = (
        Column("quantity", "quantity"),
        Column("published", "published", justify="right"),
        Column("series", "series (I)-(V)", fmt=_angle_or_number("series"), justify="right"),
        Column("exact", "exact (quad)", fmt=_angle_or_number("exact"), justify="right"),
        Column("series_error", "series - exact", justify="right", digits=3),
        Column(
            "series_rel_error", "rel. error", fmt=_relative("series_rel_error"), justify="right"
        ),
        Column("methods_diff", "ODE - quad", justify="right", digits=2),
        Column(
            "elliptic_rel_diff",
            "elliptic/quad - 1",
            digits=2,
            justify="right",
        ),
        Column("unit", "diff. unit"),
        Column("note", "note"),
    )
    if not any(r.get("note") for r in rows):
        return tuple(c for c in columns if c.key != "note")
    return columns


@command(app, "tisserand series")
def series(
    ratio: Annotated[
        float | None,
        typer.Option(metavar="RATIO", parser=number, help="θ1/θ0, 0..1 (default: the example's)."),
    ] = None,
    order: Annotated[int, typer.Option(metavar="ORDER", help="Series order: 0, 2, 4 or 6.")] = 6,
    fmt: FormatOption = OutputFormat.table,
    plot: PlotOption = None,
    quiet: QuietFlag = False,
) -> None:
    """k', k'' and the precession from the series against the exact values over θ0."""
    from pendcli.base.plotting import validate_plot_path
    from pendcli.papers.tisserand import explore, figures, model

    plot = validate_plot_path(plot)
    ratio = model.example_ratio() if ratio is None else ratio
    rows = explore.series_rows(ratio=ratio, order=order)
    title = f"Tisserand's series (order {order}) against the exact motion, θ1 = {ratio:g}·θ0"
    emit(fmt, [(title, rows, _series_columns())], {"claims": [], "formulas": [], "series": rows})
    if plot is not None:
        with busy("drawing the figure"):
            figures.plot_series_error(plot, ratio=ratio)


def _series_columns() -> list[Column]:
    from pendcli.output import Column

    columns = [
        Column("theta0_deg", "θ0 (°)", justify="right", digits=6),
        Column("theta1_deg", "θ1 (°)", justify="right", digits=6),
    ]
    # The exact value to 6 digits and the series' relative error: the series value itself is
    # exact·(1 + error), in full in JSON and CSV (an 80-column terminal holds 8 columns).
    for key, label in (("k1", "k'/k"), ("k2", "k''/k"), ("precession", "Ω (rad)")):
        columns += [
            Column(f"{key}_exact", f"{label} exact", justify="right", digits=6),
            Column(
                f"{key}_rel_error",
                "series error",
                fmt=_relative(f"{key}_rel_error"),
                justify="right",
            ),
        ]
    return columns
