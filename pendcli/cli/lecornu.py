"""`pendcli lecornu ...`: the variable-length pendulum (claims, zeros, the 0,35 m/s example)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from pendcli.cli.common import FormatOption, PlotOption, QuietFlag, busy, emit, refuse_both
from pendcli.cli.help_format import command, group
from pendcli.cli.values import number, word
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

    import numpy as np

    from pendcli.output import Column, Row

app = group(
    "Lecornu: the pendulum of variable length (Bessel zeros, the 0,35 m/s example).", "lecornu"
)

SpeedOption = Annotated[
    float | None,
    typer.Option(
        "--speed",
        metavar="B",
        parser=number,
        help="Shortening speed b (m/s), 0.001 <= b <= 1000 (default: the table's).",
    ),
]
LengthOption = Annotated[
    float | None,
    typer.Option(
        "--length",
        metavar="METRES",
        parser=number,
        help="Length at t = 0 (m), 0.001 <= L <= 1000 (default: the table's).",
    ),
]
GOption = Annotated[
    float | None,
    typer.Option(
        "--g",
        metavar="G",
        parser=number,
        help="Gravity (m/s²), 0.1 <= g <= 100 (default: the table's g).",
    ),
]


def _col(key: str, header: str, sig: int = 10) -> Column:
    from pendcli.output import Column, fmt_float

    return Column(key, header, fmt=lambda r: fmt_float(r.get(key), sig), justify="right")


@command(app, "lecornu claims")
def claims(
    g: GOption = None,
    fmt: FormatOption = OutputFormat.table,
    quiet: QuietFlag = False,
) -> None:
    """Every printed number of the memoir against its recomputation, with a verdict."""
    from pendcli.base.checks import real_in_range
    from pendcli.output.views import claim_columns
    from pendcli.papers.lecornu.claims import author_procedures, recompute
    from pendcli.papers.lecornu.model import G_RANGE, constant
    from pendcli.verify.claims import evaluate_paper

    g = real_in_range("g", constant("g") if g is None else g, *G_RANGE, "m/s²")
    claims = evaluate_paper("lecornu", lambda: recompute(g), author_procedures())
    rows = [r.as_dict() for r in claims]
    emit(
        fmt,
        [(f"Lecornu: printed against recomputed (g = {g:g} m/s²)", rows, claim_columns(rows))],
        {"g": g, "claims": rows, "formulas": []},
    )


def _zeros_method(method: str | None, tol: float | None) -> tuple[str, str]:
    """The method of `zeros` and why: forced, the cheapest meeting --tol, or the default."""
    if method is not None:
        return method, "forced by --method"
    if tol is None:
        return "auto", "default"
    from pendcli.run.tradeoff import family
    from pendcli.run.tradeoff_engine import choose, measured_points

    chosen = choose("bessel_zeros", tol, measured_points(family("bessel_zeros")))
    reason = (
        f"cheapest with measured worst error {chosen.error:.1e} <= tol {tol:g}, "
        f"{chosen.seconds:.1e} s/evaluation"
    )
    return chosen.method, reason


@command(app, "lecornu zeros")
def zeros(
    order: Annotated[int, typer.Option("--order", metavar="ORDER", help="Order of J: 1 or 2.")] = 2,
    count: Annotated[
        int, typer.Option("--count", metavar="K", help="How many zeros, 1 <= K <= 10^7.")
    ] = 5,
    method: Annotated[
        str | None,
        typer.Option(
            "--method",
            metavar="METHOD",
            parser=word,
            help="Force one: auto, scipy, mcmahon, mcmahon-newton, mpmath or series.",
        ),
    ] = None,
    tol: Annotated[
        float | None,
        typer.Option(
            "--tol",
            metavar="TOL",
            parser=number,
            help="Cheapest method whose measured worst relative error is <= TOL "
            "(tables/tradeoff/bessel_zeros.csv).",
        ),
    ] = None,
    fmt: FormatOption = OutputFormat.table,
    quiet: QuietFlag = False,
) -> None:
    """The first K positive zeros of J_1 or J_2 (Lecornu's (15) and the vertical passages)."""
    refuse_both("tol", tol, "method", method)
    from functools import partial

    from pendcli.numerics.besselzeros import check_zeros_request, iter_bessel_zeros

    method, reason = _zeros_method(method, tol)
    check_zeros_request(order, count, method)  # a bad request fails before any output
    title = f"Zeros of J_{order} ({method})"
    document = {"order": order, "method": method, "method_reason": reason}
    chunks = partial(iter_bessel_zeros, order, count, method)
    if fmt is OutputFormat.table and count <= RICH_TABLE_MAX_ROWS:
        _zeros_rich_table(title, document, [float(z) for c in chunks() for z in c])
    else:
        _zeros_streamed(fmt, title, document, chunks, count)
    if fmt is OutputFormat.table:
        from pendcli.cli.common import say

        say(f"method: {method} ({reason})")


# Above this many rows the table format prints plain aligned text: a rich table holds every
# cell (and measures it) before drawing.
RICH_TABLE_MAX_ROWS = 5000


def _zeros_rich_table(title: str, document: dict[str, object], values: list[float]) -> None:
    from pendcli.output import Column

    rows = [{"k": k + 1, "zero": z} for k, z in enumerate(values)]
    columns = [
        Column("k", "k", justify="right"),
        Column("zero", "j", justify="right", digits=7),
    ]
    emit(OutputFormat.table, [(title, rows, columns)], {**document, "zeros": rows})


def _zeros_streamed(
    fmt: OutputFormat,
    title: str,
    document: dict[str, object],
    chunks: Callable[[], Iterator[np.ndarray]],
    count: int,
) -> None:
    """The zeros written as they are computed, in the key layout of the list output."""
    import numpy as np

    from pendcli.output.stream import StreamedColumn, StreamedRows, write_stream

    def numbered() -> Iterator[tuple[np.ndarray, np.ndarray]]:
        start = 1
        for zeros in chunks():
            yield np.arange(start, start + len(zeros)), zeros
            start += len(zeros)

    columns = (
        StreamedColumn("k", "k", width=len(str(count))),
        # 17 significant digits and the point: the longest repr of a zero below 1e16
        StreamedColumn("zero", "j", width=18),
    )
    write_stream(fmt, StreamedRows(title, columns, count, numbered), document, "zeros")


def _example_columns() -> tuple[list[Column], list[Column], list[Column]]:
    """Columns of `example`: elongations, vertical passages, summary."""
    from pendcli.output import Column

    elongations = [
        _col("k", "k"),
        _col("z", "z (J2 = 0)", 8),
        _col("length_m", "l (m)", 6),
        _col("time_s", "t (s)", 6),
        _col("j0", "J0(z)", 6),
        _col("ratio", "θ/θ0", 6),
        _col("from_rest_length_m", "from rest: l (m)", 6),
        _col("from_rest_time_s", "from rest: t (s)", 6),
        _col("from_rest_ratio", "from rest: θ/θ0", 6),
    ]
    passages = [
        _col("k", "k"),
        _col("z", "z (J1 = 0)", 8),
        _col("length_m", "l (m)", 6),
        _col("time_s", "t (s)", 6),
        _col("from_rest_time_s", "from rest: t (s)", 6),
    ]
    summary = [Column("quantity", "quantity"), _col("value", "value", 8), Column("unit", "unit")]
    return elongations, passages, summary


@command(app, "lecornu example")
def example(
    speed: SpeedOption = None,
    length: LengthOption = None,
    g: GOption = None,
    fmt: FormatOption = OutputFormat.table,
    plot: PlotOption = None,
    quiet: QuietFlag = False,
) -> None:
    """The shortening pendulum of the example: elongations, amplitudes, vertical passages."""
    from pendcli.base.plotting import validate_plot_path

    plot = validate_plot_path(plot)
    with busy("solving the example: elongations and vertical passages"):
        from pendcli.papers.lecornu.explore import example_rows

        elong, passages, summary = example_rows(speed, length, g)
    cols_e, cols_p, cols_s = _example_columns()
    emit(
        fmt,
        [
            ("Elongations (solution (10); from rest: released at rest at t = 0)", elong, cols_e),
            ("Vertical passages", passages, cols_p),
            ("Summary", summary, cols_s),
        ],
        {"elongations": elong, "passages": passages, "summary": summary},
    )
    if plot is not None:
        from pendcli.papers.lecornu.figures import plot_example

        with busy("drawing the figure"):
            plot_example(plot, speed, length, g)


@command(app, "lecornu ode-check")
def ode_check(
    speed: SpeedOption = None,
    length: LengthOption = None,
    g: GOption = None,
    amplitude: Annotated[
        list[float] | None,
        typer.Option(
            "--amplitude",
            metavar="DEGREES",
            parser=number,
            help="Initial amplitude(s) in degrees for eq. (3) with sin θ.",
        ),
    ] = None,
    floor: Annotated[
        float,
        typer.Option(
            "--floor",
            metavar="FRACTION",
            parser=number,
            help="Stop at this fraction of the length, 1e-9..0.5.",
        ),
    ] = 0.02,
    fmt: FormatOption = OutputFormat.table,
    quiet: QuietFlag = False,
) -> None:
    """Bessel elongation times against eq. (3) integrated directly, linear and with sin θ."""
    with busy("integrating eq. (3) from rest, linear and with sin θ"):
        from pendcli.papers.lecornu.explore import ode_check as check

        rows = check(speed, length, g, tuple(amplitude) if amplitude else None, floor)
    columns = [_col(k, _ode_header(k), 8) for k in rows[0]]
    emit(
        fmt,
        [("Released from rest: Bessel (9) against eq. (3) integrated", rows, columns)],
        {"rows": rows},
    )


# ode-check's keys -> headers (the keys stay as they are in JSON and CSV).
_ODE_HEADERS = {
    "k": "k",
    "length_m": "L (m)",
    "t_bessel_s": "t Bessel (s)",
    "t_ode_linear_s": "t ODE (s)",
    "linear_minus_bessel_s": "ODE − Bessel (s)",
    "ratio_bessel": "θ/θ0 Bessel",
    "ratio_ode_linear": "θ/θ0 ODE",
}


def _ode_header(key: str) -> str:
    """``sin_shift_5deg_s`` -> ``sin θ, 5°: shift (s)``; ``theta_5deg_at_elongation_deg`` ->
    ``sin θ, 5°: θ (°)``; the fixed keys from :data:`_ODE_HEADERS`."""
    if key in _ODE_HEADERS:
        return _ODE_HEADERS[key]
    for prefix, suffix, what in (
        ("sin_shift_", "deg_s", "shift (s)"),
        ("theta_", "deg_at_elongation_deg", "θ (°)"),
    ):
        if key.startswith(prefix) and key.endswith(suffix):
            return f"sin θ, {key[len(prefix) : -len(suffix)]}°: {what}"
    return key.replace("_", " ")


# A verdict as one mark beside the value, so each g takes one column.
_VERDICT_MARKS = {"agrees": "✓", "truncated": "t", "last-digit": "±1", "discrepant": "✗"}
_BEST_G_LABELS = {
    "best_g_least_squares": "g fitting best (least squares), m/s²",
    "score_at_best": "its score Σ((recomputed − printed)/u)²",
    "most_agreeing": "most claims agreeing at one g",
    "of": "g-dependent claims",
    "g_range_most_agreeing": "g range where that many agree, m/s²",
}


def _best_g_rows(best: dict[str, object], g0: float) -> list[dict[str, str]]:
    """best_g()'s keys as sentences, its numbers to the digits that matter."""
    labels = {
        **_BEST_G_LABELS,
        f"score_at_{g0:g}": f"score at the table's g = {g0:g}",
        f"agreeing_at_{g0:g}": f"claims agreeing at g = {g0:g}",
    }

    def shown(value: object) -> str:
        if isinstance(value, tuple):
            return " – ".join(f"{v:.4f}" for v in value)
        return f"{value:.4g}" if isinstance(value, float) else str(value)

    return [{"quantity": labels.get(k, k), "value": shown(v)} for k, v in best.items()]


def _g_column(key: str) -> Column:
    from pendcli.output import Column
    from pendcli.output.style import current

    def text(row: Row) -> str:
        value = row.get(key)
        mark = _VERDICT_MARKS.get(str(row.get(f"verdict {key}")), "?")
        return f"{current().fixed(value, 5)}\u00a0{mark}" if isinstance(value, float) else ""

    return Column(key, key.replace("g=", "g = "), fmt=text, justify="right")


@command(app, "lecornu g-sensitivity")
def g_sensitivity(fmt: FormatOption = OutputFormat.table, quiet: QuietFlag = False) -> None:
    """The g-dependent claims at several g, their verdicts, and the g that fits best."""
    from pendcli.output import Column
    from pendcli.output.views import printed_for_display
    from pendcli.papers.lecornu.explore import best_g
    from pendcli.papers.lecornu.explore import g_sensitivity as sensitivity
    from pendcli.papers.lecornu.model import constant

    with busy("the g-dependent claims at several g"):
        rows = sensitivity()
        best = best_g()
    columns = [
        Column("id", "claim", fmt=lambda r: str(r["id"]).removeprefix("lecornu.")),
        Column("published", "printed", fmt=lambda r: printed_for_display(r["published"])),
    ]
    columns += [_g_column(key) for key in rows[0] if key.startswith("g=")]
    columns.append(_col("d_value_dg", "d/dg", 4))
    marks = ", ".join(f"{m} {v}" for v, m in _VERDICT_MARKS.items())
    summary = _best_g_rows(best, constant("g"))
    emit(
        fmt,
        [
            (
                f"g-dependent claims at several g ({marks}; verdicts use g = {constant('g'):g})",
                rows,
                columns,
            ),
            (
                "Which g reproduces the printed figures best",
                summary,
                [Column("quantity", "quantity"), Column("value", "value")],
            ),
        ],
        {"rows": rows, "best_g": best},
    )


@command(app, "lecornu series")
def series(fmt: FormatOption = OutputFormat.table, quiet: QuietFlag = False) -> None:
    """Lecornu's series (10)/(13) in double precision: where cancellation destroys them."""
    with busy("the series (10) and (13) against mpmath"):
        from pendcli.numerics import besselzeros
        from pendcli.output import Column
        from pendcli.papers.lecornu.explore import series_cancellation

        rows = series_cancellation()
    columns = [Column("order", "order")] + [
        _col(k, k.replace("_", " "), 6) for k in rows[0] if k != "order"
    ]
    limits = [
        {
            "order": o,
            "safe_limit_z": besselzeros.series_safe_limit(o),
            "max_error": besselzeros.SERIES_MAX_ERROR,
        }
        for o in besselzeros.ORDERS
    ]
    emit(
        fmt,
        [
            ("Series against mpmath", rows, columns),
            (
                "Safe range of method 'series'",
                limits,
                [
                    Column("order", "order"),
                    _col("safe_limit_z", "z limit", 6),
                    _col("max_error", "max zero error", 3),
                ],
            ),
        ],
        {"rows": rows, "limits": limits},
    )


@command(app, "lecornu zero-length")
def zero_length(
    speed: SpeedOption = None,
    length: LengthOption = None,
    g: GOption = None,
    fmt: FormatOption = OutputFormat.table,
    quiet: QuietFlag = False,
) -> None:
    """Amplitude growth as the length goes to zero (linear eq. (3) from rest, to a floor)."""
    from pendcli.papers.lecornu.explore import zero_length_behaviour

    with busy("integrating eq. (3) down to the length floor"):
        rows = zero_length_behaviour(speed, length, g)
    columns = [_col(k, k.replace("_", " "), 6) for k in rows[0]]
    emit(fmt, [("|θ| / θ0 down to a length floor", rows, columns)], {"rows": rows})
