"""Statuses computed from a printed form that is NUMBERS: a table the paper prints
(``5.14; 8.41; 11.62``), ``name = value`` pairs, or a formula with a printed decimal in it
(``... = 0.00313*metre*z**2``), judged against the values its paper's code computes.

A numeric reference (:class:`Numbers`, returned by the row's ``reference`` function) gives,
in printed order, the value of each printed number computed from the author's own model
(mpmath at high precision: the function the text evaluates, at the inputs the text gives,
read from the published table, never retyped). Each printed number is judged by the rule of
the claims (:func:`pendcli.verify.verdict.judge`): it passes when the computed value rounds to
it (``agrees``) or chops to it (``truncated``) at its printed places, and the reason says
which; one unit off in the last place (``last-digit``) or more (``discrepant``) fails.

A list is judged entry by entry: it passes when every entry passes; the reason names each
entry that fails (its place, its printed text, the computed value and the verdict). The
equations of the formula that hold no printed number are checked as identities against
``Numbers.identity`` (:func:`pendcli.verify.printed_check.formula_passes`). The status:

* ``holds``: every printed number passes (and every identity holds);
* ``misprint``: the printed form fails and every number of ``reading_formula`` passes;
* ``fails``: the printed form fails and ``corrected_formula`` is the correction computed:
  as many numbers, each to the places of the printed one; every one passes, and each one it
  changes is the computed value ROUNDED (a chopped or a one-off correction is not the
  computed one); the numbers that pass as printed may stay as printed;
* otherwise nothing the ledger may record: the row is refused.

Which printed numbers there are: a ``;``-separated part that is a bare number or
``name = number`` (a fraction, a unit symbol after it: ``l = 0.5*metre``; ``shift = mm/5``
for « un cinquième de millimètre ») is one entry, its sign included; so is an angle
``name = 30*arcmin`` (``1*degree + 7*arcmin + 33*arcsec`` is 1°7'33'', known to the second).
In any other part each decimal literal (digits, a point, digits) and each angle is one, its
sign being the formula's notation, and an integer there (the 4 of b²/(4g)) is notation.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from itertools import pairwise
from typing import Any

from pendcli.data.numbers import PrintedNumber, parse_printed
from pendcli.data.printed import Formula
from pendcli.data.vocabulary import Verdict
from pendcli.verify.printed_check import Reference, formula_passes
from pendcli.verify.verdict import judge

__all__ = ["Numbers", "numeric_status", "printed_numbers", "untied"]

_NUMBER = r"[+-]?\d+(?:\.\d+)?"
# a number, a name = number pair; a fraction (1/5) and a unit symbol after it (0.5*metre)
_ENTRY = re.compile(
    rf"^\s*(?:([A-Za-z_]\w*)\s*=\s*)?({_NUMBER}(?:/\d+)?)(?:\s*\*\s*[A-Za-z_]\w*)?\s*$"
)
# an angle as the ledger writes 1°7'33'': 1*degree + 7*arcmin + 33*arcsec (in brackets or not)
_UNIT = r"\d+(?:\.\d+)?\s*\*\s*(?:degree|arcmin|arcsec)"
_ANGLE = rf"\(?\s*{_UNIT}(?:\s*\+\s*{_UNIT})*\s*\)?"
_IN_FORMULA = re.compile(rf"(?P<angle>{_ANGLE})|(?<![\w.])(?P<decimal>\d+\.\d+)(?![\w.])")
_NAMED_ANGLE = re.compile(rf"^\s*([A-Za-z_]\w*)\s*=\s*({_ANGLE})\s*$")
_SIGNS = {"degree": "°", "arcmin": "'", "arcsec": "''"}
# a fraction of a unit printed in words (« un cinquième de millimètre »): shift = mm/5
_PER = re.compile(r"^\s*([A-Za-z_]\w*)\s*=\s*[A-Za-z_]\w*\s*/\s*(\d+)\s*$")
_EQUALS = re.compile(r"(?<![=<>!])=(?!=)")  # as pendcli.data.printed splits a chain
_PASSING = (Verdict.AGREES, Verdict.TRUNCATED)
Values = Sequence[Any] | Callable[[Mapping[str, float]], Sequence[Any]]


@dataclass(frozen=True)
class Numbers:
    """The computed value of each printed number of a row, in printed order (mpmath or any
    real number), or a function of the row's ``inputs`` giving them; ``inputs``: the names of
    ``name = value`` pairs that are the data of the computation (the example's amplitudes),
    not judged but passed, as printed (an angle in degrees), to ``values``; ``what``: the
    model; ``identity``: the reference for the formula's equations without a printed number
    (None: the formula has none); ``published``: for each printed number (inputs included),
    the claim of the published table that prints it too (None: no claim does), so that a
    number is transcribed once and the ledger's copy is refused when it differs; ``bounds``:
    the names of pairs the text gives as a bound (« au plus »), judged as an upper bound
    (the computed value, rounded to the printed precision, at most the printed one)."""

    values: Values
    what: str = ""
    identity: Reference | None = None
    # per printed number: (claim id, its published number) when a claims table prints it too
    published: Sequence[tuple[str, PrintedNumber] | None] = ()
    inputs: tuple[str, ...] = ()
    bounds: tuple[str, ...] = ()  # names printed as « at most »: judged as upper bounds


@dataclass(frozen=True)
class _Entry:
    place: int  # 1-based, in printed order
    name: str  # the name of a ``name = value`` pair, else ""
    number: PrintedNumber
    signed: bool = True  # its sign is printed (a whole part); inside a formula it is notation


def _angle_text(match: str) -> str:
    """``(1*degree + 7*arcmin + 33*arcsec)`` -> ``1°7'33''`` (as numbers.parse_printed reads)."""
    units = re.findall(r"(\d+(?:\.\d+)?)\s*\*\s*(degree|arcmin|arcsec)", match)
    return "".join(f"{value}{_SIGNS[unit]}" for value, unit in units)


def _numbers_in(text: str) -> list[tuple[str, str, bool]]:
    """(name, printed text, sign printed) of each printed number of one ``;`` part or side."""
    named = _NAMED_ANGLE.match(text)  # first: 30*arcmin is an angle, not 30 of a unit
    if named:
        return [(named.group(1), _angle_text(named.group(2)), True)]
    whole = _ENTRY.match(text)
    if whole:
        return [(whole.group(1) or "", whole.group(2), True)]
    per = _PER.match(text)
    if per:
        return [(per.group(1), f"1/{per.group(2)}", True)]
    found = []
    for m in _IN_FORMULA.finditer(text):
        shown = _angle_text(m.group("angle")) if m.group("angle") else m.group(0)
        found.append(("", shown, False))
    return found


def printed_numbers(source: str) -> list[_Entry]:
    """The printed numbers of a formula's text, in order (see the module docstring)."""
    texts = [found for part in source.split(";") for found in _numbers_in(part)]
    return [_Entry(i + 1, n, parse_printed(t), sign) for i, (n, t, sign) in enumerate(texts)]


def _shown(entry: _Entry) -> str:
    return f"#{entry.place} {entry.name + ' = ' if entry.name else ''}{entry.number.text}"


def _judged(
    entries: list[_Entry], numbers: Numbers, rounded: frozenset[int] = frozenset()
) -> tuple[bool, str]:
    """Whether every entry passes against its computed value (an entry whose place is in
    ``rounded`` only when the computed value rounds to it); inputs are passed, not judged."""
    given = {e.name: e.number.value for e in entries if e.name in numbers.inputs}
    judged = [e for e in entries if e.name not in numbers.inputs]
    values = numbers.values(given) if callable(numbers.values) else numbers.values
    if len(judged) != len(values):
        return False, f"{len(judged)} printed numbers, {len(values)} computed"
    said, wrong = [], []
    for entry, value in zip(judged, values, strict=True):
        comparison = "upper-bound" if entry.name in numbers.bounds else "equal"
        verdict = judge(entry.number, float(value), comparison).verdict
        said.append(f"{entry.number.text} {verdict.value} ({float(value):.6g})")
        passing = (Verdict.AGREES,) if entry.place in rounded else _PASSING
        if verdict not in passing:
            wrong.append(f"{_shown(entry)}: computed {float(value):.6g}, {verdict.value}")
    data = "".join(f", {name} = {value:g}" for name, value in given.items())
    if wrong:
        return False, f"{len(wrong)} of {len(judged)} off{data}: " + "; ".join(wrong)
    against = f" against {numbers.what}" if numbers.what else ""
    return True, f"every number passes{against}{data}: " + ", ".join(said)


def _identities(formula: Formula, numbers: Numbers) -> tuple[bool, str]:
    """The equations without a printed number on either side, checked as identities."""
    marks = zip(formula.equations, _numbered(formula.source), strict=True)
    kept = tuple(e for e, numbered in marks if e[0] is not None and not numbered)
    if not kept:
        return True, ""
    if numbers.identity is None:
        return False, f"{len(kept)} equation(s) without a number and no identity reference"
    ok, why = formula_passes(Formula(formula.source, kept), numbers.identity)
    return ok, f"; identities: {why}"


def _numbered(source: str) -> list[bool]:
    """For each equation of ``source``, in the order pendcli.data.printed parses them,
    whether one of its two sides holds a printed number."""
    out = []
    for part in source.split(";"):
        sides = _EQUALS.split(part)
        if len(sides) == 1 or any(p.match(part) for p in (_ENTRY, _NAMED_ANGLE, _PER)):
            out.extend([True] * max(1, len(sides) - 1))  # a number, or a name = number pair
            continue
        out.extend(bool(_numbers_in(a) or _numbers_in(b)) for a, b in pairwise(sides))
    return out


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
        if p.number.resolution != c.number.resolution
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
        value = number.value if entry.signed else abs(number.value)  # a formula's sign: notation
        if (entry.number.value, entry.number.resolution) != (value, number.resolution):
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
