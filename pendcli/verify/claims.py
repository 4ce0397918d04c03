"""The comparison engine: published values (data) joined with recomputations (code).

A paper's :class:`~pendcli.papers.paper.Paper` (listed in :mod:`pendcli.papers.registry`)
gives ``recompute() -> dict[id, Recomputed]``. :func:`evaluate_paper` loads the paper's
published table, calls it, and judges every claim. This module knows no paper: callers
pass the recomputation (the registry's :func:`~pendcli.papers.registry.claim_rows` looks it up).
Every published entry must have a recomputation and every recomputation a published entry:
a claim without a computation is a defect, reported as an error, never silently skipped.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass

from pendcli.base.errors import PendcliError
from pendcli.data.ledger_conditions import Assumption
from pendcli.data.rows import ClaimRow, FormulaRow, Recomputed
from pendcli.data.tables import (
    PaperTable,
    PublishedValue,
    load_paper_table,
    missing_claim,
)
from pendcli.data.vocabulary import (
    CAUSES,
    FORMULA_VERDICTS,
    PROCEDURE_VERDICTS,
    ROOT_CAUSES,
    Cause,
    FormulaVerdict,
    Verdict,
)
from pendcli.verify.causes import Judged, Procedure, own_verdicts
from pendcli.verify.verdict import judge

__all__ = [
    "CAUSES",
    "FORMULA_VERDICTS",
    "CauseTally",
    "ClaimRow",
    "FormulaCause",
    "FormulaRow",
    "Recomputed",
    "cause_tally",
    "evaluate_paper",
    "procedure_tally",
    "shared_formula_rows",
    "sharing_formula_rows",
    "with_causes",
    "with_conditions",
    "with_own_verdicts",
]


def list_rows(keys: Iterable[str]) -> list[dict[str, str]]:
    """Id, paper, source, quantity, printed string and unit of every claim (tables only)."""
    rows = []
    for key in keys:
        for c in load_paper_table(key).claims:
            rows.append(
                {
                    "id": c.id,
                    "paper": c.paper,
                    "source": c.source,
                    "quantity": c.quantity,
                    "published": c.published,
                    "unit": c.unit,
                }
            )
    return rows


def make_row(entry: PublishedValue, result: Recomputed) -> ClaimRow:
    comparison = judge(entry.number, result.value, entry.comparison)
    notes = [n for n in (entry.ocr and f"OCR: {entry.ocr}", entry.note, result.note) if n]
    return ClaimRow(
        id=entry.id,
        paper=entry.paper,
        source=entry.source,
        quantity=entry.quantity,
        unit=entry.unit,
        published=entry.published,
        published_value=entry.number.value,
        recomputed=result.value,
        verdict=comparison.verdict,
        abs_diff=comparison.abs_diff,
        rel_diff=comparison.rel_diff,
        digits=comparison.digits,
        exact=result.exact,
        method=result.method,
        note=" ".join(notes),
        cause=entry.cause,
        cause_from=entry.cause_from,
        as_printed=entry.as_printed,
    )


def join_claims(table: PaperTable, results: Mapping[str, Recomputed]) -> list[ClaimRow]:
    missing = [c.id for c in table.claims if c.id not in results]
    extra = sorted(set(results) - {c.id for c in table.claims})
    if extra:  # an id renamed or removed in the file: name the file and the id the code uses
        unmatched = f"; the file's {', '.join(missing)} has no computation" if missing else ""
        raise PendcliError(
            f"{missing_claim(table.where, extra[0], 'its recomputation')}{unmatched}"
        )
    if missing:
        raise PendcliError(f"{table.where}: no computation for claim(s) {', '.join(missing)}")
    return [make_row(c, results[c.id]) for c in table.claims]


def evaluate_paper(
    key: str,
    recompute: Callable[[], Mapping[str, Recomputed]],
    procedures: Mapping[str, Procedure] | None = None,
) -> list[ClaimRow]:
    """Judge every published claim of paper ``key`` against ``recompute()`` (the truth) and,
    where the author's ``procedures`` know how he got it, against his own procedure."""
    table = load_paper_table(key)
    rows = join_claims(table, recompute())
    rows = with_own_verdicts(table, rows, procedures) if procedures else rows
    return with_conditions(key, rows, recompute)


def with_own_verdicts(
    table: PaperTable, rows: Sequence[ClaimRow], procedures: Mapping[str, Procedure]
) -> list[ClaimRow]:
    """``rows`` with their verdict against the author's procedure, and for those that have
    one the cause the rule computes (:mod:`pendcli.verify.causes`): the table may not state it."""
    stated = [c.id for c in table.claims if c.id in procedures and c.cause is not None]
    if stated:
        raise PendcliError(
            f"{table.where}: claim {stated[0]}: its cause is computed from the author's "
            "procedure by the rule of tables/README.md, never written; remove its 'cause'"
        )
    entries = {c.id: c for c in table.claims}
    judged = {
        r.id: Judged(entries[r.id].number, r.recomputed, r.cause, entries[r.id].comparison)
        for r in rows
    }
    own = own_verdicts(judged, procedures)
    return [
        dataclasses.replace(
            r,
            procedure_verdict=o.verdict,
            procedure_value=o.value,
            procedure=o.procedure.text,
            procedure_inputs=o.procedure.inputs,
            cause=o.cause,
            cause_from=o.cause_from,
        )
        if (o := own.get(r.id)) is not None
        else r
        for r in rows
    ]


# Formula rows computed by the running reproduction, by paper: set only inside
# sharing_formula_rows, so that the equation ledger, which re-reads some of them, takes the
# ones just computed instead of integrating everything again.
_SHARED: dict[str, list[FormulaRow]] = {}


def shared_formula_rows(key: str, compute: Callable[[], Sequence[FormulaRow]]) -> list[FormulaRow]:
    """The formula rows of paper ``key`` a running reproduction shares, else ``compute()``."""
    return list(_SHARED[key]) if key in _SHARED else list(compute())


@contextmanager
def sharing_formula_rows(key: str, rows: list[FormulaRow]) -> Iterator[None]:
    """Within the block, :func:`shared_formula_rows` of ``key`` returns ``rows`` (never cached
    beyond it, so a later run with other tables computes afresh)."""
    _SHARED[key] = rows
    try:
        yield
    finally:
        _SHARED.pop(key, None)


# A formula's cause: (cause, the ids of the formula rows it inherits from).
FormulaCause = tuple[str, tuple[str, ...]]


def with_causes(rows: Sequence[FormulaRow], causes: Mapping[str, FormulaCause]) -> list[FormulaRow]:
    """``rows`` with their causes set from ``causes`` (id -> (cause, from)), checked."""
    ids = {r.id for r in rows}
    unknown = sorted(set(causes) - ids)
    if unknown:
        raise PendcliError(f"cause given for unknown formula row(s) {', '.join(unknown)}")
    for row_id, (cause, sources) in causes.items():
        if cause not in CAUSES:
            raise PendcliError(f"{row_id}: cause {cause!r} is not one of {', '.join(CAUSES)}")
        if (cause == Cause.PROPAGATED) != bool(sources) or not set(sources) <= ids - {row_id}:
            raise PendcliError(f"{row_id}: 'from' must name other rows iff cause is propagated")
    return [
        dataclasses.replace(r, cause=causes[r.id][0], cause_from=causes[r.id][1])
        if r.id in causes
        else r
        for r in rows
    ]


@dataclass(frozen=True)
class CauseTally:
    """Root slips apart from what they propagate into, over the rows that do not agree/hold."""

    roots: dict[str, int]  # root cause -> rows (every cause but "propagated", in CAUSES order)
    propagated: int  # rows that only carry an error from earlier rows
    unexplained: int  # rows that do not agree or hold and have no cause
    edges: tuple[tuple[str, str], ...]  # (source id, row id): the row inherits from the source

    @property
    def root_total(self) -> int:
        return sum(self.roots.values())


def _disagrees(row: ClaimRow | FormulaRow) -> bool:
    return row.verdict not in (Verdict.AGREES, FormulaVerdict.HOLDS)


def cause_tally(rows: Iterable[ClaimRow | FormulaRow]) -> CauseTally:
    """Count the causes of the rows that do not agree (claims) or hold (formulas).

    Every propagated row gives an edge from each of its sources (a source may itself agree,
    e.g. a rounded zero whose rounding carries into a time), in row order.
    """
    roots = {c.value: 0 for c in ROOT_CAUSES}
    propagated = unexplained = 0
    edges: list[tuple[str, str]] = []
    for row in rows:
        if row.cause == Cause.PROPAGATED:
            edges += [(source, row.id) for source in row.cause_from]
        if not _disagrees(row):
            continue
        if row.cause is None:
            unexplained += 1
        elif row.cause == Cause.PROPAGATED:
            propagated += 1
        else:
            roots[row.cause] += 1
    return CauseTally(roots, propagated, unexplained, tuple(edges))


NO_PROCEDURE = "no procedure"  # the tally's key for the numbers whose procedure is not known


def procedure_tally(rows: Iterable[ClaimRow]) -> dict[str, int]:
    """The claims by verdict against the author's procedure (faithful, slip), and those
    with no known procedure, in that order."""
    counts = {str(v): 0 for v in PROCEDURE_VERDICTS} | {NO_PROCEDURE: 0}
    for row in rows:
        counts[NO_PROCEDURE if row.procedure_verdict is None else str(row.procedure_verdict)] += 1
    return counts


# --- verdicts that turn on an assumption the paper does not state -------------------------

_GRID = 21  # points across an assumption's range where every claim is judged
_BISECTIONS = 16  # halvings of a bracket where a claim's verdict changes


def with_conditions(
    key: str, rows: Sequence[ClaimRow], recompute: Callable[[], Mapping[str, Recomputed]]
) -> list[ClaimRow]:
    """``rows`` with, for each claim whose verdict against the truth changes within the range
    of an unstated numeric assumption of its paper (the ledger's ``[[assumption]]`` with a
    ``constant`` and a ``range``: Lecornu's g), the verdict on each side of each change, in
    ``condition`` (tables/README.md, « Assumptions and conditional verdicts »). Each change
    is found by computation: the claims judged at points across the range, recomputed afresh
    under each value (``tables.assuming``), the change bracketed and bisected."""
    out = list(rows)
    for found in _numeric_assumptions(key):
        texts = _conditions(key, found, recompute)
        out = [dataclasses.replace(r, condition=texts[r.id]) if r.id in texts else r for r in out]
    return out


def _numeric_assumptions(key: str) -> list[Assumption]:
    from pendcli.data.ledger import ledger_path
    from pendcli.data.ledger_conditions import parse_assumptions
    from pendcli.data.tables import read_toml

    path = ledger_path(key)
    if not path.is_file():
        return []
    raw = read_toml(path, "equation ledger").get("assumption")
    return [a for a in parse_assumptions(path, raw, None) if a.constant and a.range]


def _conditions(
    key: str, found: Assumption, recompute: Callable[[], Mapping[str, Recomputed]]
) -> dict[str, str]:
    """Claim id -> its verdicts on each side of each change within ``found``'s range."""
    from pendcli.data.tables import assuming

    assert found.constant is not None and found.range is not None
    constant, (low, high) = found.constant, found.range
    table = load_paper_table(key)
    seen: dict[float, dict[str, Verdict]] = {}

    def at(value: float) -> dict[str, Verdict]:
        if value not in seen:
            with assuming(key, constant, value):
                results = recompute()
            seen[value] = {
                c.id: judge(c.number, results[c.id].value, c.comparison).verdict
                for c in table.claims
            }
        return seen[value]

    grid = [low + (high - low) * k / (_GRID - 1) for k in range(_GRID)]
    out = {}
    for claim in table.claims:
        verdicts = [at(v)[claim.id] for v in grid]
        if len(set(verdicts)) > 1:
            sides = _sides(claim.id, grid, verdicts, at)
            out[claim.id] = _condition_text(found, sides, table.constant(constant))
    return out


def _sides(
    claim_id: str,
    grid: list[float],
    verdicts: list[Verdict],
    at: Callable[[float], dict[str, Verdict]],
) -> list[tuple[float, str, Verdict]]:
    """Each change of the claim's verdict: (the bound, as printed to 4 decimals, its side
    "<=" when the bound itself keeps the verdict below, else "<", the verdict below), then
    (inf, "", the last verdict). The bisection stops once both ends of its bracket round to
    the same 4 decimals (rounding is monotone, so the bound printed is then decided: the
    full _BISECTIONS halvings would end inside that bracket)."""
    sides = []
    for k in range(len(grid) - 1):
        if verdicts[k] == verdicts[k + 1]:
            continue
        a, b = grid[k], grid[k + 1]
        for _ in range(_BISECTIONS):
            if round(a, 4) == round(b, 4):
                break  # the bound printed is decided: every point of [a, b] rounds to it
            middle = (a + b) / 2
            a, b = (middle, b) if at(middle)[claim_id] == verdicts[k] else (a, middle)
        bound = round((a + b) / 2, 4)
        op = "<=" if at(bound)[claim_id] == verdicts[k] else "<"
        sides.append((bound, op, verdicts[k]))
    return [*sides, (math.inf, "", verdicts[-1])]


def _condition_text(
    found: Assumption, sides: list[tuple[float, str, Verdict]], table_value: float
) -> str:
    """« agrees for g <= 9.8, last-digit for g > 9.8 (assumption g: from 9.78 to 9.83, the
    tables take 9.81) »: every side named, as the ledger's conditional rows are."""
    name = found.id
    assert found.range is not None
    parts, previous = [], None
    flip = {"<=": ">", "<": ">="}
    for bound, op, verdict in sides:
        below = (
            f"{name} {op} {bound:g}"
            if previous is None
            else (
                f"{previous[0]:g} {flip[previous[1]].replace('>', '<')} {name} {op} {bound:g}"
                if math.isfinite(bound)
                else f"{name} {flip[previous[1]]} {previous[0]:g}"
            )
        )
        parts.append(f"{verdict} for {below}")
        previous = (bound, op)
    low, high = found.range
    return (
        f"{', '.join(parts)} (assumption {name}: from {low:g} to {high:g}, the tables take "
        f"{table_value:g})"
    )
