"""`pendcli tisserand ...`: the conical pendulum's series against its exact motion."""

from __future__ import annotations

from typing import Annotated

import typer

from pendcli.cli.common import FormatOption, PlotOption, emit
from pendcli.render import OutputFormat

app = typer.Typer(
    help="Tisserand 1881: the conical pendulum, series (I)-(VI) against the exact motion.",
    no_args_is_help=True,
    add_completion=False,
    rich_markup_mode=None,
)

AngleOption = Annotated[
    str,
    typer.Option(help="Angle with its unit: 30°, 30deg, 30', 30arcmin, 90arcsec, 0.52rad."),
]


def _angle_text(fmt_key: str):
    def text(row: dict) -> str:
        value = row.get(fmt_key)
        if value is None:
            return ""
        if row.get("unit") == "rad" and f"{fmt_key}_text" in row:
            return row[f"{fmt_key}_text"]
        from pendcli.render import fmt_float

        return fmt_float(value, 12)

    return text


@app.command("claims")
def claims(fmt: FormatOption = OutputFormat.table) -> None:
    """The printed numbers of the example and Resal's rate, with verdicts and the unit reading."""
    from pendcli.core.claims import evaluate_paper
    from pendcli.papers import formula_checks
    from pendcli.papers.tisserand import claims as tisserand
    from pendcli.render import Column
    from pendcli.render.views import FORMULA_COLUMNS, claim_columns

    rows = [r.as_dict() for r in evaluate_paper("tisserand")]
    formulas = [f.as_dict() for f in formula_checks("tisserand")]
    readings = [
        {
            "reading": r.reading,
            "theta0": r.theta0,
            "theta1": r.theta1,
            "psi_sin2": tisserand.angle_text(r.b1),
            "psi_sin4": tisserand.angle_text(r.b2),
            "phi_sin2": tisserand.angle_text(r.c1),
            "displacement_mm": r.displacement_mm,
        }
        for r in tisserand.reading_evidence()
    ]
    reading_columns = (
        Column("reading", "reading"),
        Column("theta0", "θ0"),
        Column("theta1", "θ1"),
        Column("psi_sin2", "ψ: sin 2k't (printed -1°7'33'')", justify="right"),
        Column("psi_sin4", "ψ: sin 4k't (printed 2'')", justify="right"),
        Column("phi_sin2", "φ': sin 2k't (printed 2'42'')", justify="right"),
        Column(
            "displacement_mm",
            "shift, mm (printed <= 1/5)",
            fmt=lambda r: f"{r['displacement_mm']:.3g}",
            justify="right",
        ),
    )
    emit(
        fmt,
        [
            ("Tisserand 1881: printed against recomputed", rows, claim_columns(rows)),
            ("Reading of « θ0 = 30', θ1 = 15' »: Tisserand's series", readings, reading_columns),
            ("Series (I), (II), (V) against the exact motion", formulas, FORMULA_COLUMNS),
        ],
        {"claims": rows, "formulas": formulas, "readings": readings},
    )


@app.command("example")
def example(
    theta0: AngleOption = "30°",
    theta1: AngleOption = "15°",
    length: Annotated[float, typer.Option(help="Pendulum length in metres.")] = 0.5,
    fmt: FormatOption = OutputFormat.table,
    plot: PlotOption = None,
) -> None:
    """Published / series / exact (two methods) side by side for any amplitudes."""
    from pendcli.core.plotting import validate_plot_path
    from pendcli.papers.tisserand import claims as tisserand
    from pendcli.render import Column, fmt_float

    plot = validate_plot_path(plot)
    a, b = tisserand.amplitudes(theta0, theta1)
    length = tisserand.parse_length(length)
    rows = tisserand.example_rows(a, b, length)

    def num(key: str, sig: int = 12):
        return lambda r: "" if r.get(key) is None else fmt_float(r[key], sig)

    columns = (
        Column("quantity", "quantity"),
        Column("published", "published", justify="right"),
        Column("series", "series (I)-(V)", fmt=_angle_text("series"), justify="right"),
        Column("exact", "exact (quad)", fmt=_angle_text("exact"), justify="right"),
        Column("series_error", "series - exact", fmt=num("series_error", 3), justify="right"),
        Column(
            "series_rel_error",
            "rel. error",
            fmt=lambda r: (
                "" if r.get("series_rel_error") is None else f"{r['series_rel_error']:+.2e}"
            ),
            justify="right",
        ),
        Column("methods_diff", "ODE - quad", fmt=num("methods_diff", 2), justify="right"),
        Column(
            "elliptic_rel_diff",
            "elliptic/quad - 1",
            fmt=num("elliptic_rel_diff", 2),
            justify="right",
        ),
        Column("unit", "diff. unit"),
        Column("note", "note"),
    )
    if not any(r.get("note") for r in rows):
        columns = tuple(c for c in columns if c.key != "note")
    title = f"Conical pendulum θ0 = {theta0}, θ1 = {theta1}, l = {length:g} m"
    emit(fmt, [(title, rows, columns)], {"claims": [], "formulas": [], "example": rows})
    if plot is not None:
        tisserand.plot_path(plot, a, b)


@app.command("series")
def series(
    ratio: Annotated[float, typer.Option(help="θ1/θ0, 0..1 (the example has 0.5).")] = 0.5,
    order: Annotated[int, typer.Option(help="Series order: 0, 2, 4 or 6.")] = 6,
    fmt: FormatOption = OutputFormat.table,
    plot: PlotOption = None,
) -> None:
    """k', k'' and the precession from the series against the exact values over θ0."""
    from pendcli.core.plotting import validate_plot_path
    from pendcli.papers.tisserand import claims as tisserand
    from pendcli.render import Column, fmt_float

    plot = validate_plot_path(plot)
    rows = tisserand.series_rows(ratio=ratio, order=order)

    def num(key: str, sig: int = 12):
        return lambda r: "" if r.get(key) is None else fmt_float(r[key], sig)

    def rel(key: str):
        return lambda r: "" if r.get(key) is None else f"{r[key]:+.2e}"

    columns = [
        Column("theta0_deg", "θ0 (°)", fmt=num("theta0_deg", 6), justify="right"),
        Column("theta1_deg", "θ1 (°)", fmt=num("theta1_deg", 6), justify="right"),
    ]
    for key, label in (("k1", "k'/k"), ("k2", "k''/k"), ("precession", "Ω")):
        columns += [
            Column(f"{key}_series", f"{label} series", fmt=num(f"{key}_series"), justify="right"),
            Column(f"{key}_exact", f"{label} exact", fmt=num(f"{key}_exact"), justify="right"),
            Column(f"{key}_rel_error", "rel. error", fmt=rel(f"{key}_rel_error"), justify="right"),
        ]
    title = f"Tisserand's series (order {order}) against the exact motion, θ1 = {ratio:g}·θ0"
    emit(fmt, [(title, rows, columns)], {"claims": [], "formulas": [], "series": rows})
    if plot is not None:
        tisserand.plot_series_error(plot, ratio=ratio)
