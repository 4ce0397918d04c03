"""Verdicts that hold under an assumption the paper does not state (tables/README.md,
« Assumptions and conditional verdicts »).

A ledger lists each unstated assumption of its paper once, in an ``[[assumption]]`` table:
``id``, ``what`` (the assumption in words), ``rows`` (the rows whose verdict turns on it) and,
for a number the paper leaves open, ``constant`` (the ``[paper.constants]`` entry of the
published table the references read) and ``range`` (the values a reader may take, ends
included). A row whose verdict changes within that range says where: ``condition = "g <=
9.80"``. The engine then computes the row's status at both ends of each side of the bound
(:func:`conditional_status`): every point of a side must give one status, the two sides two
different ones, and the side holding the table's value the row's recorded status; otherwise
the row is refused. The output row names both verdicts and their ranges.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from pendcli.base.errors import PendcliError
from pendcli.data.vocabulary import CHECKED_STATUSES, EquationStatus

__all__ = [
    "Assumption",
    "Conditional",
    "ConditionedRow",
    "check_listed",
    "conditional_status",
    "parse_assumptions",
    "parse_condition",
    "row_conditional",
]


class ConditionedRow(Protocol):
    """What this module reads of a ledger row (:class:`pendcli.data.ledger_rows.LedgerRow`):
    its id, status, reference and the condition its verdict turns on."""

    @property
    def id(self) -> str: ...

    @property
    def status(self) -> EquationStatus: ...

    @property
    def reference(self) -> str | None: ...

    @property
    def condition(self) -> str | None: ...


_KEYS = ("id", "what", "rows", "constant", "range")
_ID = re.compile(r"^[A-Za-z][A-Za-z0-9_-]*$")
_CONDITION = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_-]*)\s*(<=|<|>=|>)\s*([0-9]+(?:\.[0-9]+)?)\s*$")
_OTHER_SIDE = {"<=": ">", "<": ">=", ">=": "<", ">": "<="}
# the open end of a side is taken this fraction of the range inside it
_NEAR = 1e-6


@dataclass(frozen=True)
class Assumption:
    id: str
    what: str
    rows: tuple[str, ...]
    constant: str | None = None
    range: tuple[float, float] | None = None


@dataclass(frozen=True)
class Conditional:
    """A row's verdict on each side of its condition: ``text`` names both and their ranges,
    ``evidence`` each status computed, ``problem`` why they contradict the row (or None)."""

    text: str
    evidence: str
    problem: str | None


def parse_assumptions(
    path: Path, raw: object, row_ids: Iterable[str] | None
) -> tuple[Assumption, ...]:
    """The ``[[assumption]]`` tables, each validated (its rows must be ``row_ids``'; None:
    the ledger's rows are a selection, the rows named are not looked for)."""
    if raw is None:
        return ()
    if not isinstance(raw, list):
        raise PendcliError(f"{path}: [[assumption]] must be an array of tables")
    known = None if row_ids is None else set(row_ids)
    out = [_assumption(f"{path}: [[assumption]] {i + 1}", e, known) for i, e in enumerate(raw)]
    ids = [a.id for a in out]
    if len(set(ids)) != len(ids):
        raise PendcliError(f"{path}: [[assumption]] ids must be unique: {ids}")
    return tuple(out)


def _assumption(where: str, entry: object, known: set[str] | None) -> Assumption:
    if (
        not isinstance(entry, dict)
        or set(entry) - set(_KEYS)
        or not {"id", "what", "rows"} <= set(entry)
    ):
        raise PendcliError(f"{where}: keys id, what, rows and, for a number, constant and range")
    if not (isinstance(entry["id"], str) and _ID.match(entry["id"])):
        raise PendcliError(f"{where}: id must be a plain name (letters, digits, _ or -)")
    where = f"{where} ({entry['id']})"
    rows = entry["rows"]
    if not (isinstance(rows, list) and rows and all(isinstance(r, str) for r in rows)):
        raise PendcliError(f"{where}: rows must list the rows whose verdict turns on it")
    if known is not None and (unknown := [r for r in rows if r not in known]):
        raise PendcliError(f"{where}: rows {unknown} are not rows of the ledger")
    if not isinstance(entry["what"], str) or not entry["what"].strip():
        raise PendcliError(f"{where}: what must state the assumption")
    if ("constant" in entry) != ("range" in entry):
        raise PendcliError(f"{where}: a number the paper leaves open has a constant and a range")
    span = entry.get("range")
    if span is not None and not (
        isinstance(span, list) and len(span) == 2
        and all(isinstance(v, int | float) and math.isfinite(v) for v in span)
        and span[0] < span[1]
    ):  # fmt: skip
        raise PendcliError(f"{where}: range must be [low, high], two ascending finite numbers")
    constant = entry.get("constant")
    if constant is not None and not (isinstance(constant, str) and constant.strip()):
        raise PendcliError(f"{where}: constant must name a [paper.constants] entry")
    bounds = None if span is None else (float(span[0]), float(span[1]))
    return Assumption(entry["id"], entry["what"], tuple(rows), constant, bounds)


def parse_condition(where: str, row: ConditionedRow, assumptions: Mapping[str, Assumption]) -> None:
    """A row's ``condition`` names a numeric assumption that lists the row, with a bound
    strictly inside its range; and every row a numeric assumption lists has one."""
    if row.condition is None:
        return
    match = _CONDITION.match(row.condition)
    if not match:
        raise PendcliError(f"{where}: condition must read '<assumption> <op> <number>'")
    name, _, value = match.groups()
    found = assumptions.get(name)
    if found is None or found.range is None:
        raise PendcliError(f"{where}: condition names {name!r}, no [[assumption]] with a range")
    if not found.range[0] < float(value) < found.range[1]:
        raise PendcliError(f"{where}: the bound {value} is not inside {name}'s range {found.range}")
    if row.id not in found.rows:
        raise PendcliError(f"{where}: assumption {name} does not list the row it turns")
    if row.status not in CHECKED_STATUSES or row.reference is None:
        raise PendcliError(f"{where}: a condition splits a checked row's computed status")


def check_listed(
    path: Path, rows: Iterable[ConditionedRow], assumptions: Iterable[Assumption]
) -> None:
    """Each row a numeric assumption lists carries a condition on it."""
    by_id = {r.id: r for r in rows}
    for found in assumptions:
        if found.range is None:
            continue
        for row_id in (r for r in found.rows if r in by_id):  # a selection: the rows given
            condition = by_id[row_id].condition or ""
            match = _CONDITION.match(condition)
            if not match or match.group(1) != found.id:
                raise PendcliError(
                    f"{path}: {row_id}: listed by the assumption {found.id}, it needs a "
                    f"condition on it (its verdict turns within {found.range})"
                )


def _points(op: str, bound: float, low: float, high: float) -> tuple[list[float], list[float]]:
    """(the points of the condition's side, those of the other side): each side's two ends,
    an open end taken just inside it."""
    near = (high - low) * _NEAR
    if op in ("<=", "<"):
        inside = [low, bound if op == "<=" else bound - near]
        outside = [bound + near if op == "<=" else bound, high]
    else:
        inside = [bound if op == ">=" else bound + near, high]
        outside = [low, bound - near if op == ">=" else bound]
    return inside, outside


def conditional_status(
    row: ConditionedRow,
    found: Assumption,
    table_value: float,
    status_at: Callable[[float], tuple[str | None, str]],
) -> Conditional:
    """The row's status on each side of its condition, ``status_at(value)`` computing it with
    the assumption's constant at ``value``."""
    match = _CONDITION.match(row.condition or "")
    assert match is not None and found.range is not None
    name, op, text = match.groups()
    bound, (low, high) = float(text), found.range
    inside, outside = _points(op, bound, low, high)
    seen: dict[float, str] = {}
    for value in (*inside, *outside):
        seen[value] = status_at(value)[0] or "no status"
    first, second = {seen[v] for v in inside}, {seen[v] for v in outside}
    said = "; ".join(f"{name} = {v:.8g}: {seen[v]}" for v in (*inside, *outside))
    own = first if _on(op, bound, table_value) else second
    problem = None
    if len(first) != 1 or len(second) != 1 or first == second or own != {row.status.value}:
        problem = (
            f"the condition {row.condition} does not split the verdict as recorded "
            f"({row.status.value} at the table's {name} = {table_value:g}): {said}"
        )
    other = _OTHER_SIDE[op]
    text_out = (
        f"{'/'.join(sorted(first))} for {name} {op} {text}, {'/'.join(sorted(second))} for "
        f"{name} {other} {text} (assumption {found.id}: from {low:g} to {high:g}, the tables "
        f"take {table_value:g})"
    )
    return Conditional(text_out, f"computed at {said}", problem)


def _on(op: str, bound: float, value: float) -> bool:
    return {"<=": value <= bound, "<": value < bound, ">=": value >= bound, ">": value > bound}[op]


def row_conditional(
    paper: str,
    row: ConditionedRow,
    assumptions: Iterable[Assumption],
    compute: Callable[[], tuple[str | None, str]],
) -> Conditional | None:
    """The row's verdict on each side of its condition (None: it has none); ``compute`` gives
    its status from a reference built afresh, here under each assumed value in turn."""
    from pendcli.data.tables import assuming, load_paper_table

    match = _CONDITION.match(row.condition or "")
    if match is None:
        return None
    found = next(a for a in assumptions if a.id == match.group(1))
    assert found.constant is not None
    constant = found.constant

    def at(value: float) -> tuple[str | None, str]:
        with assuming(paper, constant, value):
            return compute()

    return conditional_status(row, found, load_paper_table(paper).constant(constant), at)
