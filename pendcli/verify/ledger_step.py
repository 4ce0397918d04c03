"""A row's own slip beside the one it carries (tables/README.md, « Every slip in a row »).

A row that takes its input from another row's printed (wrong) form may add a slip of its
own. Its ``corrected_formula`` is the correction against the truth (both slips mended); its
step, against the author's own input, is judged here: ``step_from`` names the row whose
printed form is the input, ``step_at`` where the row takes it (``"u = pi/2"``), and
``step_symbols`` what each of the row's symbols is in the source's (``{ theta_pi2 = "theta",
dtheta_du_pi2 = "Derivative(theta, u)" }``); ``step_formula`` is the row's form with its own
slip mended only. The engine builds the reference those give (the source's printed
definitions put in, the derivatives taken, the point put in) and requires the printed form
to fail against it (the row's own slip is there) and ``step_formula`` to hold (that slip's
correction is computed).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError

if TYPE_CHECKING:
    from pendcli.data.ledger_rows import Ledger, LedgerRow
    from pendcli.verify.printed_check import Reference

__all__ = ["STEP_KEYS", "parse_step", "step_evidence", "validate_step"]

STEP_KEYS = ("step_from", "step_at", "step_symbols", "step_formula")


def parse_step(where: str, entry: Mapping[str, object]) -> dict[str, object]:
    """``step_symbols`` as (name, formula) pairs; the four keys come together."""
    given = [k for k in STEP_KEYS if k in entry]
    if not given:
        return {}
    if len(given) != len(STEP_KEYS):
        raise PendcliError(f"{where}: a step names all of {', '.join(STEP_KEYS)}")
    table = entry["step_symbols"]
    if not (isinstance(table, dict) and table
            and all(isinstance(v, str) and v.strip() for v in table.values())):  # fmt: skip
        raise PendcliError(f'{where}: step_symbols = {{ name = "formula in the source", ... }}')
    return {"step_symbols": tuple(sorted(table.items()))}


def validate_step(path: Path, ledger: Ledger) -> None:
    """Each step names another checked row and parses in its symbols (the source's for
    ``step_at`` and ``step_symbols``, the row's for ``step_formula``)."""
    from pendcli.verify.ledger_formulas import row_formula

    by_id = {r.id: r for r in ledger.rows}
    for row in ledger.rows:
        if row.step_from is None:
            continue
        where = f"{path}: {row.id}"
        source = by_id.get(row.step_from)
        if source is None or source is row or source.printed is None:
            raise PendcliError(f"{where}: step_from {row.step_from!r}, not another printed row")
        if row.carries != source.id:
            raise PendcliError(f"{where}: a step from {source.id} carries it (carries = the id)")
        theirs = ledger.symbols_for(source)
        row_formula(f"{where}: step_at", row.step_at or "", theirs)
        for name, text in row.step_symbols or ():
            if name not in ledger.symbols_for(row):
                raise PendcliError(f"{where}: step_symbols names {name!r}, not a row symbol")
            row_formula(f"{where}: step_symbols {name}", text, theirs)
        row_formula(
            f"{where}: step_formula", row.read("step_formula") or "", ledger.symbols_for(row)
        )


def _step_reference(row: LedgerRow, source: LedgerRow, ledger: Ledger) -> Reference:
    """The row's symbols as the source's printed definitions give them at ``step_at``."""
    import sympy as sp

    from pendcli.verify.ledger_formulas import row_formula
    from pendcli.verify.printed_check import Reference

    theirs = ledger.symbols_for(source)
    printed = row_formula(f"{source.id}: printed", source.read("printed") or "", theirs)
    defined = {lhs: rhs for lhs, rhs in printed.equations if isinstance(lhs, sp.Symbol)}
    ((at, value),) = row_formula(f"{row.id}: step_at", row.step_at or "", theirs).equations
    exact: dict[str, Any] = {}
    for name, text in row.step_symbols or ():
        ((_, expr),) = row_formula(f"{row.id}: step_symbols", text, theirs).equations
        exact[name] = sp.expand(expr.subs(defined).doit().subs(at, value))
    return Reference(exact, what=f"{source.id} as printed, at {row.step_at}")


def step_evidence(row: LedgerRow, ledger: Ledger) -> tuple[str | None, str | None]:
    """(what the step check found, as one line; why it contradicts the row, or None); (None,
    None) for a row without a step."""
    from pendcli.verify.ledger_formulas import row_formula
    from pendcli.verify.printed_check import judged

    if row.step_from is None:
        return None, None
    source = next(r for r in ledger.rows if r.id == row.step_from)
    reference = _step_reference(row, source, ledger)
    symbols = ledger.symbols_for(row)
    printed = row_formula(f"{row.id}: printed", row.read("printed") or "", symbols)
    step = row_formula(f"{row.id}: step_formula", row.read("step_formula") or "", symbols)
    printed_holds, why_printed = judged(printed, reference)
    step_holds, why_step = judged(step, reference)
    said = (
        f"against {reference.what}: the printed form "
        f"{'holds' if printed_holds else 'fails'} ({why_printed}); its own slip mended, "
        f"{row.step_formula} {'holds' if step_holds else 'fails'} ({why_step})"
    )
    problem = None
    if printed_holds or not step_holds:
        problem = f"the step from {source.id} does not show a slip of the row's own: {said}"
    return said, problem
