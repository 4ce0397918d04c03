"""The words of a verdict, a ledger status and a cause: defined here once, used everywhere.

Each is a ``StrEnum``: a member is its word (``Verdict.AGREES == "agrees"``, and it prints,
formats and serialises to JSON and CSV as that word), so outputs read as they always did
while code names the word instead of typing it. The tuples are the words in their canonical
order (tallies, summaries, schema).
"""

from __future__ import annotations

from enum import StrEnum

__all__ = [
    "CAUSES",
    "CHECKED_STATUSES",
    "CLAIM_VERDICTS",
    "FAITHFUL_VERDICTS",
    "FORMULA_VERDICTS",
    "PROCEDURE_VERDICTS",
    "ROOT_CAUSES",
    "SLIP_CAUSES",
    "STATUSES",
    "Cause",
    "EquationStatus",
    "FormulaVerdict",
    "ProcedureVerdict",
    "Verdict",
    "disagrees_word",
]


class Verdict(StrEnum):
    """A printed number against its recomputation (:mod:`pendcli.verify.verdict`), best first."""

    AGREES = "agrees"
    TRUNCATED = "truncated"
    LAST_DIGIT = "last-digit"
    DISCREPANT = "discrepant"


class ProcedureVerdict(StrEnum):
    """A printed number against the author's own procedure on his own printed inputs
    (:mod:`pendcli.verify.causes`): his digits follow from them with his rounding, or not."""

    FAITHFUL = "faithful"
    # his digits follow only if he finished this number otherwise than his procedure's rule
    # (a condition on the number, as an assumed g is on a verdict): chopped where he rounds
    FAITHFUL_IF_CHOPPED = "faithful if chopped"
    FAITHFUL_IF_ROUNDED = "faithful if rounded"  # rounded where he says he chops
    # his digits follow only from inputs within their printed last place, not from the inputs
    # as printed: he computed with digits he did not print
    FAITHFUL_IF_MORE_DIGITS = "faithful if he kept more digits"
    SLIP = "slip"


class FormulaVerdict(StrEnum):
    """A derived formula against a numerical solution (:mod:`pendcli.verify.formula_engine`)."""

    HOLDS = "holds"
    FAILS = "fails"


class EquationStatus(StrEnum):
    """What the equation ledger records for a numbered equation or stated result."""

    HOLDS = "holds"
    FAILS = "fails"
    MISPRINT = "misprint"
    DEFINITION = "definition"
    NOT_CHECKABLE = "not-checkable"


class Cause(StrEnum):
    """Why a printed value or a formula does not agree or hold (``tables/README.md``)."""

    ROUNDING = "rounding"
    TRUNCATION = "truncation"
    INPUT_ROUNDING = "input-rounding"
    PROPAGATED = "propagated"
    ARITHMETIC_SLIP = "arithmetic-slip"
    MISPRINT = "misprint"
    DERIVATION_ERROR = "derivation-error"
    MODEL_APPROXIMATION = "model-approximation"


CLAIM_VERDICTS: tuple[Verdict, ...] = tuple(Verdict)
PROCEDURE_VERDICTS: tuple[ProcedureVerdict, ...] = tuple(ProcedureVerdict)
# the verdicts that find his digits in his procedure (unconditionally or on a finishing rule)
FAITHFUL_VERDICTS: tuple[ProcedureVerdict, ...] = tuple(
    v for v in ProcedureVerdict if v is not ProcedureVerdict.SLIP
)
FORMULA_VERDICTS: tuple[FormulaVerdict, ...] = tuple(FormulaVerdict)
STATUSES: tuple[EquationStatus, ...] = tuple(EquationStatus)
# the statuses whose row names a check (a definition or a not-checkable row has none)
CHECKED_STATUSES: tuple[EquationStatus, ...] = (
    EquationStatus.HOLDS,
    EquationStatus.FAILS,
    EquationStatus.MISPRINT,
)
CAUSES: tuple[Cause, ...] = tuple(Cause)
# where an error enters (every cause but one that only carries an earlier row's error)
ROOT_CAUSES: tuple[Cause, ...] = tuple(c for c in Cause if c is not Cause.PROPAGATED)
# the causes that are the author's own slip: a row that uses a value with one of these (or one
# that carries it, propagated) inherits a slip; every other root is a rounding or a model
SLIP_CAUSES: tuple[Cause, ...] = (Cause.ARITHMETIC_SLIP, Cause.MISPRINT, Cause.DERIVATION_ERROR)

# The words of a row that does not agree (a claim), hold (a formula) or hold as printed or
# read (an equation: failing or misprinted).
_DISAGREEING = frozenset(
    {
        Verdict.TRUNCATED,
        Verdict.LAST_DIGIT,
        Verdict.DISCREPANT,
        FormulaVerdict.FAILS,
        EquationStatus.MISPRINT,
    }
)


def disagrees_word(word: object) -> bool:
    """Whether a verdict or status word marks a row that does not agree or hold."""
    return isinstance(word, str) and word in _DISAGREEING
