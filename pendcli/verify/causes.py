"""Why a printed value disagrees: the author's own procedure, and the one rule for causes.

A printed number gets two verdicts. *Against the truth* (:mod:`pendcli.verify.verdict`): the
author's model done exactly. *Against his own procedure*: a paper's claims module may expose
``author_procedures() -> dict[id, Procedure]``, how the author obtained a printed value from
his earlier printed values (his lengths from his rounded zeros, his times from his lengths);
a = the procedure on his printed inputs, and the number is

``faithful``
    when a, finished by the procedure's rule (``rounding``: ``rounded``, the default, or
    ``chopped`` where the text says so, its words in ``said``), is the printed value;
``faithful if chopped`` / ``faithful if rounded``
    when only the other finish gives it: faithful on a condition, that he finished this number
    otherwise than his rule (−0,130 for his J₀(5,14) = −0,13079 is faithful if chopped);
``faithful if he kept more digits``
    when neither finish of a gives it, but the procedure on the digits he may have kept does:
    an input he computed faithfully by his own procedure at its unrounded value, any other
    (a slip of his, a number without a procedure) anywhere within its printed last place (±
    half a unit; the procedure at the corners): faithful on the condition that he computed
    with digits he did not print (−3,45 from his −0,02087 needs a numerator of 0,0720 to
    0,0725, which his slip +0,072 may be);
``slip``
    when none does. A number with no known procedure has none (never guessed).

**The rule** (:func:`rule_cause`), for a number with a procedure that does not agree with the
truth. An input *carries a slip* when it is a slip against its own procedure, or is itself
``propagated``, or (an input with no procedure) the table gives it a cause of
:data:`SLIP_CAUSES`. An input correctly rounded is not a slip: it carries only its rounding.

``propagated`` (``from``: the inputs that carry a slip)
    some input carries a slip, and either the number is faithful to his inputs or the part of
    its error those inputs bring in (a - r, r the recomputation) exceeds his own (P - a);
``arithmetic-slip``
    a slip against his procedure, his inputs carrying none (or less than his own part);
``truncation``
    faithful, and the truth chopped is the printed value while his own a needs chopping too;
``input-rounding``
    faithful otherwise: his procedure on his correctly rounded inputs gives his digits, and
    the number's distance from the truth is that rounding carried through.

A number that agrees with the truth has no cause. For a number without a procedure the cause
is data (``tables/published``): ``rounding`` / ``truncation`` (the truth rounded / chopped
is the printed value), ``misprint``, ``derivation-error``, ``model-approximation``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from pendcli.base.errors import PendcliError
from pendcli.data.numbers import PrintedNumber
from pendcli.data.vocabulary import (
    CAUSES,
    FAITHFUL_VERDICTS,
    ROOT_CAUSES,
    SLIP_CAUSES,
    Cause,
    ProcedureVerdict,
)
from pendcli.verify.verdict import Verdict, judge

__all__ = [
    "CAUSES",
    "FINISHES",
    "ROOT_CAUSES",
    "SLIP_CAUSES",
    "ErrorSplit",
    "Judged",
    "OwnVerdict",
    "Procedure",
    "chops_to",
    "corrected_value",
    "own_verdicts",
    "procedure_verdict",
    "rounds_to",
    "rule_cause",
    "split_error",
]


# how the author finishes a procedure's value at the printed precision
FINISHES = ("rounded", "chopped")


@dataclass(frozen=True)
class Procedure:
    """How the author computed a printed value from earlier printed values (claim ids), and
    how he finishes it: ``rounding`` is ``rounded`` unless the text says he chops (``said``:
    its words, « Je néglige les décimales qui suivent la seconde »)."""

    inputs: tuple[str, ...]
    compute: Callable[..., float]  # the inputs' values, in order -> the value
    text: str = ""  # the procedure as the paper does it, e.g. "(1 - l)/0,35"
    rounding: str = "rounded"
    said: str = ""  # the text's words that fix ``rounding``, where it says so

    def __post_init__(self) -> None:
        if self.rounding not in FINISHES:
            raise PendcliError(f"a procedure's rounding is one of {FINISHES}: {self.rounding!r}")
        if self.rounding == "chopped" and not self.said.strip():
            raise PendcliError("a chopped procedure quotes the text's words that say so (said)")

    def __call__(self, values: Mapping[str, float]) -> float:
        """The procedure on ``values`` (claim id -> value; only the inputs are read)."""
        return float(self.compute(*(values[i] for i in self.inputs)))


def rounds_to(number: PrintedNumber, value: float) -> bool:
    """``value`` rounded at the printed precision is the printed value."""
    return judge(number, value).verdict is Verdict.AGREES


def chops_to(number: PrintedNumber, value: float) -> bool:
    """``value`` chopped (toward zero) at the printed precision is the printed value."""
    return judge(number, value).verdict is Verdict.TRUNCATED


@dataclass(frozen=True)
class ErrorSplit:
    """The error P - r of a printed value split at the author's own value a: a - r is what
    his inputs bring in, P - a what he added."""

    author: float  # a: his procedure on his printed inputs
    inherited: float  # a - r
    own: float  # P - a, or 0.0 when a rounds or chops to P

    @property
    def inherited_dominates(self) -> bool:
        return abs(self.inherited) > abs(self.own)


def split_error(
    published: PrintedNumber, procedure: Procedure, printed: Mapping[str, float], recomputed: float
) -> ErrorSplit:
    """How much of the printed value's error its inputs carry in, and how much is his own."""
    author = procedure(printed)
    reproduced = rounds_to(published, author) or chops_to(published, author)
    own = 0.0 if reproduced else published.value - author
    return ErrorSplit(author, author - recomputed, own)


def corrected_value(
    procedure: Procedure,
    printed: Mapping[str, float],
    recomputed: Mapping[str, float],
    sources: tuple[str, ...],
) -> float:
    """The author's procedure with the ``sources`` at their recomputed values, the other
    inputs as printed: what he would have printed had those sources been right."""
    values = {i: (recomputed[i] if i in sources else printed[i]) for i in procedure.inputs}
    return procedure(values)


# --- against his own procedure, and the rule ------------------------------------------------


def procedure_verdict(
    number: PrintedNumber,
    author: float,
    rounding: str = "rounded",
    span: tuple[float, float] | None = None,
) -> ProcedureVerdict:
    """``faithful`` when his own value ``author`` finished by his rule (``rounding``) is the
    printed one, faithful on the other finish when only that gives it, faithful if he kept
    more digits when the procedure's ``span`` over its inputs' printed last place holds a
    value his rule finishes to the printed one, else ``slip``."""
    rounded, chopped = rounds_to(number, author), chops_to(number, author)
    own, other = (rounded, chopped) if rounding == "rounded" else (chopped, rounded)
    if own:
        return ProcedureVerdict.FAITHFUL
    if other:
        if rounding == "rounded":
            return ProcedureVerdict.FAITHFUL_IF_CHOPPED
        return ProcedureVerdict.FAITHFUL_IF_ROUNDED
    if span is not None and _reachable(number, span, rounding):
        return ProcedureVerdict.FAITHFUL_IF_MORE_DIGITS
    return ProcedureVerdict.SLIP


def _reachable(number: PrintedNumber, span: tuple[float, float], rounding: str) -> bool:
    """Whether a value in ``span`` finishes (by ``rounding``) to the printed number: the
    printed value's own interval (± half a unit rounded, toward zero a unit chopped) meets it."""
    if number.resolution is None:
        return False
    unit, value = number.resolution, number.value
    if rounding == "rounded":
        low, high = value - unit / 2, value + unit / 2
    else:
        low, high = (value, value + unit) if value >= 0 else (value - unit, value)
    return span[0] <= high and low <= span[1]


def input_span(
    procedure: Procedure, claims: Mapping[str, Judged], known: Mapping[str, float]
) -> tuple[float, float] | None:
    """The procedure's least and greatest value over the digits he may have kept: an input
    whose own procedure he followed (``known``: its unrounded value, his computation) is that
    value; any other within half a unit of its printed last place (at the corners: a ratio, a
    root, a product are monotone in each input over so small a box). None when an input is
    exact."""
    import itertools

    boxes: list[tuple[str, tuple[float, ...]]] = []
    for name in procedure.inputs:
        number = claims[name].number
        if name in known:
            boxes.append((name, (known[name],)))
            continue
        if number.resolution is None:
            return None
        half = number.resolution / 2
        boxes.append((name, (number.value - half, number.value + half)))
    values = [
        procedure(dict(zip([n for n, _ in boxes], corner, strict=True)))
        for corner in itertools.product(*(b for _, b in boxes))
    ]
    return min(values), max(values)


def rule_cause(
    number: PrintedNumber,
    recomputed: float,
    author: float,
    slip_inputs: tuple[str, ...],
    comparison: str = "equal",
    rounding: str = "rounded",
    span: tuple[float, float] | None = None,
) -> tuple[Cause | None, tuple[str, ...]]:
    """The cause of a printed number with a known procedure, and its ``from`` (module doc):
    ``author`` is his procedure on his printed inputs, ``slip_inputs`` those that carry a slip,
    ``span`` the procedure over his inputs' printed last place."""
    if judge(number, recomputed, comparison).verdict is Verdict.AGREES:
        return None, ()
    faithful = procedure_verdict(number, author, rounding, span) in FAITHFUL_VERDICTS
    own = 0.0 if faithful else number.value - author
    if slip_inputs and (faithful or abs(author - recomputed) > abs(own)):
        return Cause.PROPAGATED, slip_inputs
    if not faithful:
        return Cause.ARITHMETIC_SLIP, ()
    if chops_to(number, recomputed) and not rounds_to(number, author):
        return Cause.TRUNCATION, ()
    return Cause.INPUT_ROUNDING, ()


@dataclass(frozen=True)
class Judged:
    """What the rule reads of one claim: its printed number, the truth, the table's cause."""

    number: PrintedNumber
    recomputed: float
    cause: str | None = None  # the table's (read only for an input without a procedure)
    comparison: str = "equal"


@dataclass(frozen=True)
class OwnVerdict:
    """A printed number against his own procedure, and the cause the rule derives."""

    verdict: ProcedureVerdict
    value: float  # his procedure on his printed inputs
    procedure: Procedure
    cause: Cause | None
    cause_from: tuple[str, ...]


def own_verdicts(
    claims: Mapping[str, Judged], procedures: Mapping[str, Procedure]
) -> dict[str, OwnVerdict]:
    """Every number with a procedure against it, its cause by the rule (inputs first)."""
    printed = {i: c.number.value for i, c in claims.items()}
    done: dict[str, OwnVerdict] = {}
    visiting: set[str] = set()

    def carries_slip(source: str) -> bool:
        if source in procedures:
            own = visit(source)
            return own.verdict is ProcedureVerdict.SLIP or own.cause is Cause.PROPAGATED
        return claims[source].cause in (*SLIP_CAUSES, Cause.PROPAGATED)

    def kept_digits(inputs: tuple[str, ...]) -> dict[str, float]:
        """The inputs whose digits beyond the printed ones are known: those he computed by
        his own procedure without a slip (its value unrounded)."""
        known = {}
        for source in inputs:
            if source in procedures and visit(source).verdict is ProcedureVerdict.FAITHFUL:
                known[source] = visit(source).value
        return known

    def visit(claim_id: str) -> OwnVerdict:
        if claim_id in done:
            return done[claim_id]
        if claim_id in visiting:
            raise PendcliError(f"{claim_id}: the author's procedures form a cycle")
        visiting.add(claim_id)
        procedure, claim = procedures[claim_id], claims[claim_id]
        author = procedure(printed)
        span = input_span(procedure, claims, kept_digits(procedure.inputs))
        slips = tuple(s for s in procedure.inputs if carries_slip(s))
        cause, sources = rule_cause(
            claim.number, claim.recomputed, author, slips, claim.comparison,
            procedure.rounding, span,
        )  # fmt: skip
        verdict = procedure_verdict(claim.number, author, procedure.rounding, span)
        done[claim_id] = OwnVerdict(verdict, author, procedure, cause, sources)
        return done[claim_id]

    unknown = sorted(
        {*procedures, *(i for p in procedures.values() for i in p.inputs)} - set(claims)
    )
    if unknown:
        raise PendcliError(f"an author's procedure names no claim of the table: {unknown[0]}")
    return {claim_id: visit(claim_id) for claim_id in procedures}
