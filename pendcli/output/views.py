"""Columns for claim, formula and equation rows: what the table and Markdown outputs show.

The one module under :mod:`pendcli.output` that knows what a claim is: the renderers know
only columns and rows, the paper packages only numbers. The colour of a verdict is set here.
"""

from __future__ import annotations

from collections.abc import Sequence

from pendcli.data.numbers import fixed, parse_printed
from pendcli.data.rows import equation_notes, equation_status
from pendcli.data.vocabulary import FormulaVerdict, ProcedureVerdict, Verdict
from pendcli.output.columns import Column, Row
from pendcli.output.style import current, trimmed

__all__ = [
    "CLAIM_COLUMNS",
    "EQUATION_COLUMNS",
    "FORMULA_COLUMNS",
    "VERDICT_STYLES",
    "claim_columns",
    "format_like_printed",
    "printed_for_display",
    "sexagesimal",
]

VERDICT_STYLES: dict[str, str] = {
    Verdict.AGREES: "green",
    FormulaVerdict.HOLDS: "green",  # and an equation that holds
    Verdict.TRUNCATED: "yellow",
    Verdict.LAST_DIGIT: "yellow",
    Verdict.DISCREPANT: "bold red",
    FormulaVerdict.FAILS: "bold red",  # and an equation that fails
    ProcedureVerdict.FAITHFUL: "green",
    ProcedureVerdict.FAITHFUL_IF_CHOPPED: "yellow",  # faithful on a condition
    ProcedureVerdict.FAITHFUL_IF_ROUNDED: "yellow",
    ProcedureVerdict.FAITHFUL_IF_MORE_DIGITS: "yellow",
    ProcedureVerdict.SLIP: "bold red",
}
NO_PROCEDURE = "no procedure known"  # a number whose author's procedure is not known


# The OCR transcription's markup of units written as superscripts in the papers (1^m,22 is
# 1ᵐ,22: 1.22 m; 0^{sec},94 is 0ˢ,94: 0.94 s), as the page shows them.
_SUPERSCRIPTS = (("^{sec}", "ˢ"), ("^{s}", "ˢ"), ("^{m}", "ᵐ"), ("^m", "ᵐ"), ("^s", "ˢ"))


def printed_for_display(text: object) -> str:
    """A printed value as the page shows it: ``1^m,22`` -> ``1ᵐ,22``, ``0^{sec},94`` ->
    ``0ˢ,94``. For the eye only: JSON and CSV keep the transcription as stored."""
    shown = str(text)
    for markup, superscript in _SUPERSCRIPTS:
        shown = shown.replace(markup, superscript)
    return shown


def format_like_printed(value: float | None, published: str, most: int | None = None) -> str:
    """The recomputed value written as the printed one is: a decimal three digits beyond the
    printed precision, an angle sexagesimal (the seconds to two decimals), anything else (an
    exact expression, an integer) to the output's digits; always in fixed notation. With
    ``most``, a decimal too long for ``most`` characters keeps fewer digits (an angle stays
    sexagesimal, whole seconds at the least)."""
    if value is None:
        return ""
    style = current()
    try:
        printed = parse_printed(published)
    except Exception:
        return style.number(value)
    if printed.kind == "sexagesimal":
        for decimals in (2, 1, 0):
            text = style.angle(value, decimals)
            if most is None or len(text) <= most + 2:  # ° ' '' are narrow: two more allowed
                break
        return text
    if printed.kind == "decimal" and printed.decimals:
        text = fixed(value, printed.decimals + 3, style.decimal, style.minus)
        return text if most is None or len(text) <= most else style.fixed(value, most=most)
    if printed.kind == "decimal" and float(value).is_integer():  # a count, a round figure
        return style.number(value)
    if style.digits is None and most is None:
        return style.number(value)
    return trimmed(style.fixed(value, most=most), style.decimal)  # 3/8: 0.375, not 0.3750000


def sexagesimal(degrees: float, seconds_decimals: int = 2) -> str:
    """An angle in degrees as the output being drawn writes one (see
    :meth:`~pendcli.output.style.NumberStyle.angle`): ``-1°7'33.14''``, ``1.69''``."""
    return current().angle(degrees, seconds_decimals)


def _rel(row: Row) -> str:
    rel = row.get("rel_diff")
    return "" if rel is None else f"{rel:+.2e}"


def _verdict_style(text: str) -> str | None:
    return VERDICT_STYLES.get(text)


def _truth(row: Row) -> str:
    """The verdict against the truth; one that turns on an unstated assumption names each
    side (« last-digit (last-digit for g <= 9.8277, agrees for g > 9.8277) »)."""
    condition = str(row.get("condition") or "")
    verdict = str(row.get("verdict", ""))
    return f"{verdict} ({condition.split(' (', 1)[0]})" if condition else verdict


def _truth_style(text: str) -> str | None:
    return VERDICT_STYLES.get(text.split(" (", 1)[0])


def _own(row: Row) -> str:
    """The verdict against his own procedure, and the procedure; or that none is known."""
    verdict = row.get("procedure_verdict")
    if verdict is None:
        return NO_PROCEDURE
    value = row.get("procedure_value")
    shown = f" = {value:.6g}" if isinstance(value, float | int) else ""
    return f"{verdict}: {row.get('procedure')}{shown}" if row.get("procedure") else str(verdict)


def _own_style(text: str) -> str | None:
    return VERDICT_STYLES.get(text.split(":", 1)[0])


def _cause(row: Row) -> str:
    """The cause, and for a carried error the rows it comes from."""
    cause, sources = row.get("cause"), row.get("from") or []
    if not cause:
        return ""
    return f"{cause} from {', '.join(map(str, sources))}" if sources else str(cause)


def _observed(row: Row) -> str:
    order = row.get("observed_order")
    return "" if order is None else f"{order:.2f}"


CLAIM_COLUMNS: tuple[Column, ...] = (
    Column("id", "claim"),
    Column("quantity", "quantity"),
    Column("source", "source"),
    Column(
        "published",
        "published",
        fmt=lambda r: printed_for_display(r["published"]),
        justify="right",
    ),
    Column(
        "recomputed",
        "recomputed",
        fmt=lambda r: format_like_printed(r.get("recomputed"), r["published"]),
        justify="right",
    ),
    Column(
        "exact",
        "exact model",
        fmt=lambda r: format_like_printed(r.get("exact"), r["published"]),
        justify="right",
    ),
    Column("unit", "unit"),
    Column("rel_diff", "rel. diff", fmt=_rel, justify="right"),
    Column("verdict", "against the truth", fmt=_truth, style=_truth_style),
    Column("procedure_verdict", "against his procedure", fmt=_own, style=_own_style),
    Column("cause", "cause", fmt=_cause),
    # Notes can run to paragraphs: the terminal table shows their start, JSON, CSV, Markdown
    # and the report show them whole.
    Column("note", "note"),  # whole: the table wraps prose at spaces
)

FORMULA_COLUMNS: tuple[Column, ...] = (
    Column("id", "formula"),
    Column("source", "source"),
    Column("published", "as printed"),
    Column("recomputed", "as found"),
    Column("claimed_order", "claimed order", justify="right"),
    Column(
        "observed_order",
        "observed order",
        fmt=_observed,
        justify="right",
    ),
    Column("verdict", "verdict", style=_verdict_style),
    Column("note", "note"),  # whole: the table wraps prose at spaces
)

# An equation row's pieces (reading, correction, note, the status computed from the printed
# form, a dimension mismatch) shown in one note column; JSON and CSV keep each in its field.
EQUATION_COLUMNS: tuple[Column, ...] = (
    *(Column(k, k) for k in ("id", "equation", "section")),
    Column("status", "status", fmt=equation_status),
    *(Column(k, k) for k in ("kind", "observed_order")),
    Column("note", "note", fmt=equation_notes),
)


def claim_columns(rows: Sequence[Row], with_note: bool = True) -> tuple[Column, ...]:
    """Drop the exact-model column when no row has one."""
    cols = CLAIM_COLUMNS
    if not any(r.get("exact") is not None for r in rows):
        cols = tuple(c for c in cols if c.key != "exact")
    if not with_note:
        cols = tuple(c for c in cols if c.key != "note")
    return cols
