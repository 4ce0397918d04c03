"""A paper's ledger judged: each row's printed form against its reference, its consistency
verified, and the counts by status and findings.

Each row of :func:`pendcli.data.ledger.load_ledger` is judged by its kind
(:mod:`pendcli.verify.ledger_references`), its dimensions, the assumption its verdict turns on,
its own slip and the formula checks it names; :meth:`Evaluated.output_row` is the row every
output shows. A status computed that differs from the one the row records is an error in the
ledger, reported, never re-labelled. What the engine needs of a paper is
:class:`pendcli.verify.ledger_paper.LedgerPaper`.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.base.errors import PendcliError
from pendcli.base.workers import row_done
from pendcli.data.ledger import load_ledger
from pendcli.data.ledger_rows import Ledger, LedgerRow
from pendcli.data.rows import EquationRow
from pendcli.data.vocabulary import CHECKED_STATUSES, STATUSES
from pendcli.data.vocabulary import EquationStatus as Status
from pendcli.verify.ledger_blame import FLAWED, Context, is_finding, row_context
from pendcli.verify.ledger_paper import LedgerPaper
from pendcli.verify.ledger_references import (
    Computed,
    conditional,
    printed_dimensions,
    printed_problem,
    reference_table,
    row_printed_status,
)
from pendcli.verify.ledger_step import step_evidence

if TYPE_CHECKING:
    from pendcli.data.rows import FormulaRow
    from pendcli.verify.dimensions import DimensionCheck

__all__ = [
    "FINDING_KEYS",
    "Evaluated",
    "Measured",
    "Part",
    "coverage",
    "equation_rows",
    "evaluate",
    "measured",
    "names_formula_checks",
    "with_measured",
]


@dataclass(frozen=True)
class Measured:
    """What the formula checks a row names (``measured``) found: each ``id verdict (order)``,
    and the lowest observed order among them (None: none is measured)."""

    detail: str
    observed_order: float | None


@dataclass(frozen=True)
class Evaluated:
    row: LedgerRow
    problem: str | None
    dimensions: DimensionCheck | None = None  # the printed form's, when it has one
    computed: Computed | None = None  # computed from the printed form; None without a reference
    measured: Measured | None = None
    # blame, what it carries, condition, step, readings
    context: Context = field(default_factory=Context)

    def output_row(self) -> EquationRow:
        """The row every output shows: each piece in a field of its own."""
        row, dims, measured, more = self.row, self.dimensions, self.measured, self.context
        status, why = self.computed if self.computed is not None else (None, None)
        return EquationRow(
            id=row.id,
            paper=row.paper,
            equation=row.equation,
            section=row.section,
            statement=row.statement,
            status=row.status,
            kind=row.kind,
            observed_order=measured.observed_order if measured is not None else None,
            note=row.note or "",
            lines=row.lines,
            printed=row.printed,
            reading=row.reading_formula,
            corrected=row.corrected_formula,
            dimensions=dims.verdict if dims is not None else None,
            dimensions_detail=dims.detail if dims is not None else None,
            reading_note=row.reading,
            corrected_note=row.corrected,
            measured=measured.detail if measured is not None else None,
            against=row.reference,
            computed=Status(status) if status is not None else None,
            evidence=why,
            inconsistency=self.problem,
            finding=is_finding(row),
            restates=row.restated,
            used_at=row.used_at,
            **asdict(more),
        )


def measured(row: LedgerRow, formulas: Iterable[FormulaRow]) -> Measured | None:
    """What the formula checks ``row`` names found (None: it names none); a name that is no
    formula check of the paper is an error naming the row."""
    if not row.measured:
        return None
    by_id = {r.id: r for r in formulas}
    wanted = [f"{row.paper}.{name}" for name in row.measured]
    missing = [i for i in wanted if i not in by_id]
    if missing:
        raise PendcliError(f"{row.id}: measured names no formula check {', '.join(missing)}")
    chosen = [by_id[i] for i in wanted]
    orders = [r.observed_order for r in chosen if r.observed_order is not None]
    detail = "; ".join(f"{r.id} {r.verdict} (order {_order(r.observed_order)})" for r in chosen)
    return Measured(detail, min(orders) if orders else None)


def names_formula_checks(paper: str) -> bool:
    """Whether a row of ``paper``'s ledger names a formula check (``measured``); False for a
    ledger that does not load (judging it says why)."""
    try:
        return any(row.measured for row in load_ledger(paper).rows)
    except (PendcliError, OSError):
        return False


def _formula_rows(paper: LedgerPaper, ledger: Ledger) -> list[FormulaRow]:
    """The paper's formula checks when a row of its ledger names one (else none: not run)."""
    from pendcli.verify.claims import shared_formula_rows

    if paper.formula_checks is None or not any(r.measured for r in ledger.rows):
        return []
    return shared_formula_rows(paper.key, paper.formula_checks)


# (i, n): the i-th of n contiguous slices of a ledger's rows, so that two processes can
# share a long ledger; (0, 1) is the whole ledger.
Part = tuple[int, int]


def evaluate(
    paper: LedgerPaper, root: Path | None = None, part: Part = (0, 1), measure: bool = True
) -> list[Evaluated]:
    """Every row of the paper's ledger (or of ``part`` of it) judged from its printed form,
    with its consistency verified. ``measure`` False: what the formula checks a row names
    found is left out (the run that computes them adds it: :func:`with_measured`), so that a
    part judged in another process does not run every formula check again."""
    ledger = load_ledger(paper.key, root)
    rows = ledger.rows
    index, count = part
    start, stop = len(rows) * index // count, len(rows) * (index + 1) // count
    references = reference_table(paper)
    formulas = _formula_rows(paper, ledger) if measure else []
    out = []
    for row in rows[start:stop]:
        symbols = ledger.symbols_for(row)
        dims = printed_dimensions(row, symbols)
        computed = row_printed_status(row, symbols, references) if row.reference else None
        condition = conditional(paper, ledger, row, references)
        step, step_problem = step_evidence(row, ledger)
        problem = printed_problem(row, computed) or step_problem
        problem = problem or (condition.problem if condition is not None else None)
        context = row_context(row, ledger, condition, step)
        found = measured(row, formulas) if measure else None
        out.append(Evaluated(row, problem, dims, computed, found, context))
        row_done()  # a progress bar counts rows (base.workers)
    return out


def equation_rows(
    papers: Iterable[LedgerPaper],
    root: Path | None = None,
    part: Part = (0, 1),
    measure: bool = True,
) -> list[EquationRow]:
    """The rows of ``reproduce --format json`` under "equations" for ``papers`` (``part`` of
    each ledger; ``measure``: as :func:`evaluate`); raises PendcliError if a paper's ledger is
    missing, empty or not a file, or a check contradicts its row's status."""
    rows = []
    problems = []
    for paper in papers:
        if paper.references is None:  # a paper without a ledger (its file is then not read)
            continue
        for item in evaluate(paper, root, part, measure):
            rows.append(item.output_row())
            if item.problem:
                problems.append(f"{item.row.id}: {item.problem}")
    if problems:
        raise PendcliError(f"equation ledger inconsistent: {problems[0]} ({len(problems)} rows)")
    return rows


def with_measured(
    rows: Iterable[EquationRow], ledger: Ledger, formulas: Sequence[FormulaRow]
) -> list[EquationRow]:
    """``rows`` of ``ledger`` judged without their formula checks (``measure`` False), with
    what the checks each names found (``measured``, ``observed_order``), as :func:`evaluate`
    gives them."""
    names = {row.id: row for row in ledger.rows}
    out = []
    for row in rows:
        found = measured(names[row.id], formulas)
        if found is not None:
            row = replace(row, measured=found.detail, observed_order=found.observed_order)
        out.append(row)
    return out


def coverage(rows: Iterable[EquationRow]) -> dict[str, dict[str, int]]:
    """Per paper: the count of rows by status, the total and how many are checked; then the
    findings (failing or misprinted rows that restate no other: one per slip, by status) and
    the rows that only restate another's slip (verify/ledger_blame)."""
    table: dict[str, dict[str, int]] = {}
    for row in rows:
        counts = table.setdefault(row.paper, {s.value: 0 for s in STATUSES} | _NO_FINDINGS)
        counts[row.status.value] += 1
        if row.finding:
            counts[f"{row.status.value} findings"] += 1
        elif row.status in FLAWED:
            counts["restating"] += 1
    for counts in table.values():
        counts["total"] = sum(counts[s] for s in STATUSES)
        counts["checked"] = sum(counts[s] for s in CHECKED_STATUSES)
        counts["findings"] = sum(counts[f"{s.value} findings"] for s in FLAWED)
    return table


# the counts of findings coverage() adds to the counts by status
_NO_FINDINGS = {f"{s.value} findings": 0 for s in FLAWED} | {"restating": 0}


FINDING_KEYS = ("findings", *_NO_FINDINGS)


def _order(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.2f}"
