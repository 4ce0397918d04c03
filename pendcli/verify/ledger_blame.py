"""Who carries a slip: the ledger's one rule for blame (tables/README.md, « Blame »).

A row's slip is the author's (``fails``) when his own later work uses the wrong form: a later
line, a footnote, a later section, or the text's next step computes with it. ``used_at``
lists those lines, each after the row's last (a row's own lines are the slip, never its later
use), and ``used`` the words there (verbatim, each on one of the lines) that
show it. A slip that the next step or a later use does not carry is a ``misprint``:
``used_at`` and ``used`` then show the right form taken, or ``unused`` says why nothing
later uses the form. A row whose only slip is another row's (cited in a sentence, or carried
by a step computing with that row's printed form) ``restates`` it: it has that row's status
and is no finding of its own. ``carries`` names the row whose printed (wrong) form a row
takes as its input: a step that holds on wrong values, or a row that adds a slip of its own
to a carried one; that row's ``used_at`` must then name a line of this one.

This module validates those keys; :func:`is_finding` says which rows the counts count.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.base.errors import PendcliError
from pendcli.data.vocabulary import CHECKED_STATUSES
from pendcli.data.vocabulary import EquationStatus as Status

if TYPE_CHECKING:
    from pendcli.data.ledger_conditions import Conditional
    from pendcli.data.ledger_rows import Ledger, LedgerRow

__all__ = [
    "BLAME_KEYS",
    "FLAWED",
    "Context",
    "is_finding",
    "later_use",
    "parse_blame",
    "row_context",
    "validate_blame",
]

BLAME_KEYS = ("used_at", "used", "unused", "carries")
# the statuses of a row whose printed form has a slip
FLAWED = (Status.FAILS, Status.MISPRINT)


def is_finding(row: LedgerRow) -> bool:
    """A failing or misprinted row that restates no other: one entry per slip found."""
    return row.status in FLAWED and not row.restated


def parse_blame(where: str, entry: Mapping[str, object]) -> dict[str, object]:
    """``used_at`` (a non-empty list of line numbers) and ``restates`` (a row id or a
    non-empty list of them) as the row keeps them; the other keys are plain strings."""
    out: dict[str, object] = {}
    if "used_at" in entry:
        lines = entry["used_at"]
        if not (isinstance(lines, list) and lines
                and all(type(n) is int and n >= 1 for n in lines)):  # fmt: skip
            raise PendcliError(f"{where}: 'used_at' must be a non-empty list of line numbers")
        out["used_at"] = tuple(lines)
    if "restates" in entry:
        ids = entry["restates"]
        items = ids if isinstance(ids, list) else [ids]
        if not items or not all(isinstance(i, str) and i.strip() for i in items):
            raise PendcliError(f"{where}: 'restates' must be a row id or a list of them")
        out["restates"] = ids if isinstance(ids, str) else tuple(items)
    return out


def validate_blame(
    path: Path, rows: Iterable[LedgerRow], lines: list[str] | None, partial: bool = False
) -> None:
    """Every blame key of every row against the rule (module docstring), the text's lines
    (None: not at hand) and the other rows (``partial``: a selection of them, so a row named
    but not given is not looked for)."""
    by_id = {r.id: r for r in rows}
    for row in by_id.values():
        where = f"{path}: {row.id}"
        _check_restates(where, row, by_id, partial)
        _check_record(where, row)
        if row.used_at is not None and lines is not None:
            _check_used(where, row, lines)
        if row.carries is not None and not (partial and row.carries not in by_id):
            _check_carries(where, row, by_id)


def _check_restates(
    where: str, row: LedgerRow, by_id: Mapping[str, LedgerRow], partial: bool
) -> None:
    for other in row.restated:
        if partial and other not in by_id and other != row.id:
            continue
        if other not in by_id or other == row.id:
            raise PendcliError(f"{where}: restates {other!r}, not another row")
        if row.status in CHECKED_STATUSES and row.status is not by_id[other].status:
            raise PendcliError(
                f"{where}: a row that restates another's slip has its status "
                f"({by_id[other].status.value} for {other}), not {row.status.value}"
            )


def _check_record(where: str, row: LedgerRow) -> None:
    """The later use each failing or misprinted row records, and no other row."""
    used, unused = row.used_at is not None, row.unused is not None
    if (row.used is not None) != used:
        raise PendcliError(f"{where}: 'used_at' (the lines) and 'used' (the words) go together")
    if row.status not in FLAWED and (used or unused):
        raise PendcliError(f"{where}: a {row.status.value} row records no later use of a slip")
    if row.status is Status.MISPRINT and used and unused:
        raise PendcliError(f"{where}: a misprint records either 'used_at' or 'unused'")
    if row.restated or row.status not in FLAWED:
        return
    if row.status is Status.FAILS and not used:
        raise PendcliError(
            f"{where}: a fails row records the later use that carries its slip (used_at = "
            "[lines], used = the words there); a slip nothing later carries is a misprint"
        )
    if row.status is Status.MISPRINT and not (used or unused):
        raise PendcliError(
            f"{where}: a misprint records the later use that does not carry its slip (used_at, "
            "used) or why nothing later uses it (unused)"
        )


def _check_used(where: str, row: LedgerRow, lines: list[str]) -> None:
    """Each line of ``used_at`` in the text and later than the row (after its last line: a
    row's own lines are the slip, never its later use), holding one of the words of ``used``;
    each word on one of those lines."""
    last = row.lines[1] if row.lines is not None else 0
    assert row.used_at is not None
    for number in row.used_at:
        if not last < number <= len(lines):
            raise PendcliError(
                f"{where}: used_at line {number} is not a later use: it must lie after the "
                f"row's lines, in [{last + 1}, {len(lines)}] (the line after the row's last to "
                "the text's last)"
            )
    texts = {n: lines[n - 1] for n in row.used_at}
    for word in row.used_words:
        if not any(word in text for text in texts.values()):
            raise PendcliError(f"{where}: used {word!r} is on none of the lines {row.used_at}")
    for number, text in texts.items():
        if not any(word in text for word in row.used_words):
            raise PendcliError(f"{where}: used_at line {number} holds none of the words of used")


def _check_carries(where: str, row: LedgerRow, by_id: Mapping[str, LedgerRow]) -> None:
    source = by_id.get(row.carries or "")
    if source is None or source.id == row.id:
        raise PendcliError(f"{where}: carries {row.carries!r}, not another row")
    if source.status is not Status.FAILS:
        raise PendcliError(
            f"{where}: carries {source.id}, a {source.status.value} row: a slip a later row "
            "carries makes its row fail"
        )
    first, last = row.lines if row.lines is not None else (0, -1)
    if not any(first <= n <= last for n in source.used_at or ()):
        raise PendcliError(
            f"{where}: carries {source.id}, whose used_at names no line of this row "
            f"[{first}, {last}]"
        )


def later_use(row: LedgerRow) -> str | None:
    """The later use the row records, as one line of prose (None: the row records none)."""
    if row.unused is not None:
        return f"not carried: nothing later uses it ({row.unused})"
    if row.used_at is None:
        return None
    where = ", ".join(str(n) for n in row.used_at)
    # the words where they are prose; a formula's TeX is located by its lines alone (every
    # output shows this line, the edition too, where raw TeX would be unreadable)
    words = "; ".join(f"« {w} »" for w in row.used_words if not re.search(r"[\\{}^_$]", w))
    said = "carried" if row.status is Status.FAILS else "not carried: the right form is used"
    at = f"{said} at line{'s' if len(row.used_at) > 1 else ''} {where}"
    return f"{at}: {words}" if words else at


def carried_text(row: LedgerRow, source: LedgerRow) -> str:
    """What a row that ``carries`` another shows: the step holds on wrong values, or it adds
    a slip of its own to the carried one."""
    what = source.corrected or source.reading or ""
    slip = f"{source.id}'s slip ({what})" if what else f"{source.id}'s slip"
    if row.status is Status.HOLDS:
        return f"the step holds; the values carry {slip}"
    return f"its input carries {slip}, and it adds a slip of its own"


@dataclass(frozen=True)
class Context:
    """What an output row shows beside its check: the later use that decides the blame, what
    it carries, its verdict on each side of an assumption, its own slip beside a carried one
    and the OCR readings applied (each a line of prose, None for none)."""

    later_use: str | None = None
    carries: str | None = None
    condition: str | None = None
    condition_evidence: str | None = None
    step: str | None = None
    readings: str | None = None
    assumptions: tuple[str, ...] = ()
    # a corrected or read row's companions, each judged (verify/ledger_companions)
    companions: tuple[str, ...] = ()


def row_context(
    row: LedgerRow,
    ledger: Ledger,
    condition: Conditional | None,
    step: str | None,
) -> Context:
    shown = {r.id: r.shown() for r in ledger.readings}
    source = next((r for r in ledger.rows if r.id == row.carries), None)
    return Context(
        later_use=later_use(row),
        carries=carried_text(row, source) if source is not None else None,
        condition=condition.text if condition is not None else None,
        condition_evidence=condition.evidence if condition is not None else None,
        step=step,
        readings="; ".join(shown[i] for i, _ in row.readings) or None,
        assumptions=tuple(a.id for a in ledger.assumptions if row.id in a.rows),
        companions=_companions(row, ledger),
    )


def _companions(row: LedgerRow, ledger: Ledger) -> tuple[str, ...]:
    from pendcli.verify.ledger_companions import ledger_companions

    return tuple(c.shown() for c in ledger_companions(ledger).get(row.id, ()))
