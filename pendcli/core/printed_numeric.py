"""Statuses computed from a printed form that is NUMBERS (issue 19): a table the paper prints
(``5.14; 8.41; 11.62``), ``name = value`` pairs, or a formula with a printed decimal in it
(``... = 0.00313*metre*z**2``), judged against the values its paper's code computes.

A numeric reference (:class:`Numbers`, returned by the row's ``reference`` function) gives,
in printed order, the value of each printed number computed from the author's own model
(mpmath at high precision: the function the text evaluates, at the inputs the text gives,
read from the published table, never retyped). Each printed number is judged by the rule of
the claims (:func:`pendcli.core.verdict.judge`): it passes when the computed value rounds to
it (``agrees``) or chops to it (``truncated``) at its printed places, and the reason says
which; one unit off in the last place (``last-digit``) or more (``discrepant``) fails.

A list is judged entry by entry: it passes when every entry passes; the reason names each
entry that fails (its place, its printed text, the computed value and the verdict). The
equations of the formula that hold no printed number are checked as identities against
``Numbers.identity`` (:func:`pendcli.core.printed_check.formula_passes`). The status:

* ``holds``: every printed number passes (and every identity holds);
* ``misprint``: the printed form fails and every number of ``reading_formula`` passes;
* ``fails``: the printed form fails and ``corrected_formula`` is the correction computed:
  as many numbers, each to the places of the printed one; every one passes, and each one it
  changes is the computed value ROUNDED (a chopped or a one-off correction is not the
  computed one); the numbers that pass as printed may stay as printed;
* otherwise nothing the ledger may record: the row is refused.

Which printed numbers there are: a ``;``-separated part that is a bare number or
``name = number`` is one entry (its sign included); in any other part each decimal literal
(digits, a point, digits) is one, and an integer there (the 4 of b²/(4g)) is notation.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from pendcli.core.numbers import PrintedNumber, parse_printed
from pendcli.core.printed import Formula
from pendcli.core.printed_check import Reference, formula_passes
from pendcli.core.verdict import judge
from pendcli.core.vocabulary import Verdict

__all__ = ["Numbers", "numeric_status", "printed_numbers", "untied"]

_ENTRY = re.compile(r"^\s*(?:([A-Za-z_]\w*)\s*=\s*)?([+-]?\d+(?:\.\d+)?)\s*$")
_DECIMAL = re.compile(r"(?<![\w.])\d+\.\d+(?![\w.])")
_PASSING = (Verdict.AGREES, Verdict.TRUNCATED)


@dataclass(frozen=True)
class Numbers:
    """The computed value of each printed number of a row, in printed order (mpmath or any
    real number); ``what``: the model they come from; ``identity``: the reference for the
    formula's equations without a printed number (None: the formula has none);
    ``published``: for each printed number, the claim of the published table that prints it
    too (None: no claim does), so that a number is transcribed once and the ledger's copy is
    refused when it differs (value or printed places)."""

    values: Sequence[Any]
    what: str = ""
    identity: Reference | None = None
    # per printed number: (claim id, its published number) when a claims table prints it too
    published: Sequence[tuple[str, PrintedNumber] | None] = ()


@dataclass(frozen=True)
class _Entry:
    place: int  # 1-based, in printed order
    name: str  # the name of a ``name = value`` pair, else ""
    number: PrintedNumber


def printed_numbers(source: str) -> list[_Entry]:
    """The printed numbers of a formula's text, in order (see the module docstring)."""
    texts: list[tuple[str, str]] = []
    for part in source.split(";"):
        whole = _ENTRY.match(part)
        if whole:
            texts.append((whole.group(1) or "", whole.group(2)))
        else:
            texts.extend(("", m.group(0)) for m in _DECIMAL.finditer(part))
    return [_Entry(i + 1, n, parse_printed(t)) for i, (n, t) in enumerate(texts)]


def _shown(entry: _Entry) -> str:
    return f"#{entry.place} {entry.name + ' = ' if entry.name else ''}{entry.number.text}"


def _judged(
    entries: list[_Entry], numbers: Numbers, rounded: frozenset[int] = frozenset()
) -> tuple[bool, str]:
    """Whether every entry passes against its computed value (an entry whose place is in
    ``rounded`` only when the computed value rounds to it)."""
    if len(entries) != len(numbers.values):
        return False, f"{len(entries)} printed numbers, {len(numbers.values)} computed"
    said, wrong = [], []
    for entry, value in zip(entries, numbers.values, strict=True):
        verdict = judge(entry.number, float(value)).verdict
        said.append(f"{entry.number.text} {verdict.value} ({float(value):.6g})")
        passing = (Verdict.AGREES,) if entry.place in rounded else _PASSING
        if verdict not in passing:
            wrong.append(f"{_shown(entry)}: computed {float(value):.6g}, {verdict.value}")
    if wrong:
        return False, f"{len(wrong)} of {len(entries)} off: " + "; ".join(wrong)
    against = f" against {numbers.what}" if numbers.what else ""
    return True, f"every number passes{against}: " + ", ".join(said)


def _identities(formula: Formula, numbers: Numbers) -> tuple[bool, str]:
    """The equations without a printed number, checked as identities."""
    import sympy as sp

    kept = tuple(e for e in formula.equations if e[0] is not None and not _has_float(e, sp))
    if not kept:
        return True, ""
    if numbers.identity is None:
        return False, f"{len(kept)} equation(s) without a number and no identity reference"
    ok, why = formula_passes(Formula(formula.source, kept), numbers.identity)
    return ok, f"; identities: {why}"


def _has_float(equation: tuple[Any, Any], sp: Any) -> bool:
    """Whether an equation holds a printed number (a decimal, or a side that is a number)."""
    return any(side is not None and (side.has(sp.Float) or side.is_number) for side in equation)


def _passes(formula: Formula, numbers: Numbers, rounded: frozenset[int] = frozenset()) -> Any:
    ok, why = _judged(printed_numbers(formula.source), numbers, rounded)
    same, said = _identities(formula, numbers)
    return ok and same, why + said


def _changes(printed: Formula, corrected: Formula) -> tuple[frozenset[int], str | None]:
    """The places where ``corrected`` changes a printed number, and why it is not a
    correction of the printed numbers (another count, or a number to other places)."""
    old, new = printed_numbers(printed.source), printed_numbers(corrected.source)
    if len(old) != len(new):
        return frozenset(), f"{len(new)} numbers for the {len(old)} printed"
    pairs = list(zip(old, new, strict=True))
    off = [
        f"{_shown(c)} for {p.number.text}"
        for p, c in pairs
        if p.number.decimals != c.number.decimals
    ]
    changed = frozenset(c.place for p, c in pairs if p.number.value != c.number.value)
    return changed, (f"other printed places: {'; '.join(off)}" if off else None)


def untied(printed: Formula, numbers: Numbers) -> str | None:
    """Why the printed numbers are not the published claims' numbers, or None."""
    entries = printed_numbers(printed.source)
    if numbers.published and len(numbers.published) != len(entries):
        return f"{len(entries)} printed numbers, {len(numbers.published)} published ones named"
    off = []
    for entry, tie in zip(entries, numbers.published, strict=False):
        if tie is None:
            continue
        claim, number = tie
        if (entry.number.value, entry.number.decimals) != (number.value, number.decimals):
            off.append(f"{_shown(entry)} is not claim {claim}'s {number.text}")
    return "; ".join(off) or None


def numeric_status(
    printed: Formula, reading: Formula | None, corrected: Formula | None, numbers: Numbers
) -> tuple[str | None, str]:
    """The status the printed numbers earn (None: none the ledger may record) and why."""
    drift = untied(printed, numbers)
    if drift:
        return None, f"the printed numbers are not the published table's: {drift}"
    ok, why = _passes(printed, numbers)
    if ok:
        return "holds", f"the printed numbers hold: {why}"
    if reading is not None:
        other_ok, other_why = _passes(reading, numbers)
        if other_ok:
            return "misprint", f"the printed numbers fail ({why}); the reading holds: {other_why}"
        return None, f"the printed numbers fail ({why}) and so does the reading ({other_why})"
    if corrected is not None:
        changed, not_a_correction = _changes(printed, corrected)
        other_ok, other_why = _passes(corrected, numbers, rounded=changed)
        if other_ok and not not_a_correction and changed:
            return "fails", f"the printed numbers fail ({why}); the correction is computed"
        because = not_a_correction or ("it changes nothing" if other_ok else other_why)
        return None, (
            f"the printed numbers fail ({why}) and the correction is not the computed one "
            f"({because})"
        )
    return None, f"the printed numbers fail ({why}) and the row gives no reading or correction"
