"""Why a printed value disagrees: the author's own procedure, and the checks behind a cause.

A claim's ``cause`` (``tables/published/<paper>.toml``, one of :data:`CAUSES`) says why its
printed value differs from the recomputed one. A cause is a statement about a computation,
so it is checked against one. A paper's claims module may expose
``author_procedures() -> dict[id, Procedure]``: how the author obtained a printed value from
his earlier printed values (his lengths from his rounded zeros, his times from his lengths).
The error of a printed value P against the recomputation r then splits in two
(:func:`split_error`), with a = the procedure on his printed inputs:

* *inherited*, a - r: what his inputs carry in;
* *own*, P - a: what he added; none when a rounds or chops to P (his last digit).

``propagated`` (``from``: the rows it inherits from)
    the inherited part is the larger (or his own is none), and with the ``from`` sources at
    their recomputed values (the other inputs as printed) the procedure agrees with r at the
    printed precision (:func:`corrected_value`): correcting the sources removes the error.
``arithmetic-slip``
    his own part is not none and is the larger: his printed inputs do not give P.
``rounding`` / ``truncation``
    r rounded / chopped at the printed precision is P.

A row with both parts gets the larger as its cause; its note names the other.
``misprint``, ``derivation-error`` and ``model-approximation`` are explained in the note.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from pendcli.core.numbers import PrintedNumber
from pendcli.core.verdict import Verdict, judge
from pendcli.core.vocabulary import CAUSES, ROOT_CAUSES

__all__ = [
    "CAUSES",
    "ROOT_CAUSES",
    "ErrorSplit",
    "Procedure",
    "chops_to",
    "corrected_value",
    "rounds_to",
    "split_error",
]

# Every cause except "propagated": where an error starts.


@dataclass(frozen=True)
class Procedure:
    """How the author computed a printed value from earlier printed values (claim ids)."""

    inputs: tuple[str, ...]
    compute: Callable[..., float]  # the inputs' values, in order -> the value
    text: str = ""  # the procedure as the paper does it, e.g. "(1 - l)/0,35"

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
    """The error P - r of a printed value split at the author's own value a (module doc)."""

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
