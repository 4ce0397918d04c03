"""What `pendcli reproduce` prints at a terminal: compact tables, then the summary.

The compact tables fit 80 columns without breaking a token: the paper's name leaves the ids
(the table's title carries it), notes and sources stay in ``--notes`` and the data formats,
and the causes take short labels (explained under the table). The summary counts verdicts,
separates root causes from the rows that only carry them, and draws the propagation as a
tree: each root with the rows that inherit from it, indented under it.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from pendcli.data.rows import equation_status
from pendcli.data.vocabulary import Cause, disagrees_word
from pendcli.output.columns import Column, Row
from pendcli.output.views import VERDICT_STYLES, format_like_printed

__all__ = [
    "CAUSE_LABELS",
    "compact_claim_columns",
    "compact_equation_columns",
    "compact_formula_columns",
    "disagrees",
    "propagation_tree",
]

# The table's short label of each cause (the full word is in JSON, CSV and --notes).
CAUSE_LABELS: dict[str, str] = {
    Cause.ROUNDING: "rounding",
    Cause.TRUNCATION: "chopped",
    Cause.INPUT_ROUNDING: "inputs",
    Cause.PROPAGATED: "carried",
    Cause.ARITHMETIC_SLIP: "slip",
    Cause.MISPRINT: "misprint",
    Cause.DERIVATION_ERROR: "derivation",
    Cause.MODEL_APPROXIMATION: "model",
}
CAUSE_LEGEND = (
    "truth: against the exact model; own: against his own procedure on his printed\n"
    "inputs, faithful or slip (— where none is known). cause: inputs = faithful to\n"
    "correctly rounded inputs (the distance is their rounding), carried = uses an\n"
    "earlier slip (see the tree), slip = arithmetic slip, chopped = truncation,\n"
    "derivation = derivation error, model = model approximation.\n"
    "Notes and sources: --notes; only what does not hold: --only-failing."
)
NO_PROCEDURE_MARK = "—"  # the own column of a number whose procedure is not known


def _short_id(row: Row) -> str:
    return str(row["id"]).split(".", 1)[-1]


def _cause(row: Row) -> str:
    cause = row.get("cause")
    if not cause or not disagrees(row):  # a source that agrees keeps its cause out of sight
        return ""
    return CAUSE_LABELS.get(str(cause), str(cause))


def _recomputed(row: Row) -> str:
    """As printed (an angle sexagesimal), three digits beyond it, in about ten characters."""
    value = row.get("recomputed")
    return format_like_printed(
        value if isinstance(value, float | int) else None, str(row["published"]), most=10
    )


def _style(text: str) -> str | None:
    return VERDICT_STYLES.get(text)


def _order(row: Row) -> str:
    observed, claimed = row.get("observed_order"), row.get("claimed_order")
    if observed is None:
        return ""
    return f"{observed:.2f}/{claimed:g}" if isinstance(claimed, int | float) else f"{observed:.2f}"


def disagrees(row: Row) -> bool:
    """A claim that does not agree, a formula that fails, an equation failing or misprinted."""
    return disagrees_word(row.get("verdict", row.get("status")))


def _printed(row: Row) -> str:
    from pendcli.output.views import printed_for_display

    return printed_for_display(row["published"])


def _own(row: Row) -> str:
    return str(row.get("procedure_verdict") or NO_PROCEDURE_MARK)


def compact_claim_columns() -> tuple[Column, ...]:
    """The two verdicts side by side: against the truth, against his own procedure."""
    return (
        Column("id", "claim", fmt=_short_id),
        Column("published", "printed", fmt=_printed, justify="right"),
        Column("recomputed", "recomputed", fmt=_recomputed, justify="right"),
        Column("verdict", "truth", style=_style),
        Column("procedure_verdict", "own", fmt=_own, style=_style),
        Column("cause", "cause", fmt=_cause),
    )


def compact_formula_columns() -> tuple[Column, ...]:
    return (
        Column("id", "formula", fmt=_short_id),
        Column("verdict", "verdict", style=_style),
        Column("observed_order", "seen/claimed order", fmt=_order, justify="right"),
        Column("cause", "cause", fmt=_cause),
    )


def _sources(row: Row) -> list[str]:
    value = row.get("from")
    return [str(s) for s in value] if isinstance(value, list | tuple) else []


def compact_equation_columns() -> tuple[Column, ...]:
    return (
        Column("id", "row", fmt=_short_id),
        Column("equation", "label"),
        Column(
            "status",
            "status",
            fmt=equation_status,
            style=lambda t: VERDICT_STYLES.get(t.split(" (")[0], "yellow"),
        ),
    )


def propagation_tree(rows: Sequence[Row]) -> list[str]:
    """Each root cause with the rows that inherit from it, indented, as text lines.

    A root is a row with a cause that a propagated row names in ``from`` (a source may agree:
    a rounded value whose rounding carries on). A row reached from two roots is drawn under
    each, its own descendants only the first time.
    """
    children: dict[str, list[str]] = {}
    for row in rows:
        for source in _sources(row):
            children.setdefault(str(source), []).append(str(row["id"]))
    by_id: Mapping[str, Row] = {str(r["id"]): r for r in rows}
    roots = [i for i in children if by_id.get(i, {}).get("cause") != Cause.PROPAGATED]
    lines: list[str] = []
    drawn: set[str] = set()

    def walk(node: str, depth: int) -> None:
        row = by_id.get(node, {})
        label = f"{node.split('.', 1)[-1]} ({row.get('cause') or 'no cause'})"
        again = node in drawn and node in children
        lines.append("  " * depth + ("└ " if depth else "") + label + (" …" if again else ""))
        if again:
            return
        drawn.add(node)
        for child in children.get(node, []):
            walk(child, depth + 1)

    for root in roots:
        walk(root, 0)
    return lines
