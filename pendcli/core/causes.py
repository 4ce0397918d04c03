"""Why a printed value disagrees: the author's own procedure, and the checks behind a cause.

A claim's ``cause`` (``tables/published/<paper>.toml``, one of :data:`CAUSES`) says why its
printed value differs from the recomputed one. A cause is a statement about a computation,
so it can be checked against one. A paper's claims module may expose
``author_procedures() -> dict[id, Procedure]``: how the author obtained a printed value from
earlier printed values (his lengths from his rounded zeros, his times from his lengths).
With it:

``propagated`` (``from``: the rows it inherits from)
    *consistent*: the author's procedure on his printed inputs, each taken anywhere its
    printed digits allow (rounded or chopped, he may have carried digits he did not print),
    reaches the printed value; and *corrected*: with the ``from`` sources at their
    recomputed values (the other inputs as printed) it agrees with the recomputation at the
    printed precision. A row is not called a slip when its own inputs explain it.
``arithmetic-slip``
    no reading of the author's printed inputs within their printed digits reaches the
    printed value (a root: nothing before it explains it).
``rounding`` / ``truncation``
    the recomputed value rounded / chopped at the printed precision is the printed value.

``misprint``, ``derivation-error`` and ``model-approximation`` are explained in the note.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from pendcli.core.numbers import PrintedNumber
from pendcli.core.tables import CAUSES
from pendcli.core.verdict import Verdict, judge

__all__ = [
    "CAUSES",
    "ROOT_CAUSES",
    "Procedure",
    "author_range",
    "chops_to",
    "corrected_value",
    "printed_range",
    "reaches",
    "rounds_to",
]

# Every cause except "propagated": where an error starts.
ROOT_CAUSES: tuple[str, ...] = tuple(c for c in CAUSES if c != "propagated")
_GRID = 5  # samples per input across its printed range (the procedures are smooth)
_SLACK = 1e-12  # relative widening of range ends (binary representation of decimals)


@dataclass(frozen=True)
class Procedure:
    """How the author computed a printed value from earlier printed values (claim ids)."""

    inputs: tuple[str, ...]
    compute: Callable[[Mapping[str, float]], float]
    text: str = ""  # the procedure as the paper does it, e.g. "(1 - l)/0,35"

    def __call__(self, values: Mapping[str, float]) -> float:
        return float(self.compute({i: values[i] for i in self.inputs}))


def printed_range(number: PrintedNumber) -> tuple[float, float]:
    """Every value that prints as ``number`` when rounded or chopped at its last place."""
    if number.resolution is None:
        return number.value, number.value
    u, p = number.resolution, number.value
    if p > 0:
        return p - u / 2, p + u
    if p < 0:
        return p - u, p + u / 2
    return -u, u


def rounds_to(number: PrintedNumber, value: float) -> bool:
    """``value`` rounded at the printed precision is the printed value."""
    return judge(number, value).verdict is Verdict.AGREES


def chops_to(number: PrintedNumber, value: float) -> bool:
    """``value`` chopped (toward zero) at the printed precision is the printed value."""
    return judge(number, value).verdict is Verdict.TRUNCATED


def author_range(procedure: Procedure, inputs: Mapping[str, PrintedNumber]) -> tuple[float, float]:
    """Least and greatest value of ``procedure`` over its inputs' printed ranges (sampled)."""
    axes = []
    for name in procedure.inputs:
        lo, hi = printed_range(inputs[name])
        axes.append([lo + (hi - lo) * k / (_GRID - 1) for k in range(_GRID)] if hi > lo else [lo])
    values = [
        procedure(dict(zip(procedure.inputs, point, strict=True)))
        for point in itertools.product(*axes)
    ]
    finite = [v for v in values if math.isfinite(v)]
    return min(finite), max(finite)


def reaches(
    published: PrintedNumber, procedure: Procedure, inputs: Mapping[str, PrintedNumber]
) -> bool:
    """Whether the author's procedure, on inputs within their printed digits, can print as
    ``published``: the two ranges (:func:`printed_range`, :func:`author_range`) meet."""
    lo, hi = author_range(procedure, inputs)
    p_lo, p_hi = printed_range(published)
    slack = _SLACK * max(abs(p_lo), abs(p_hi), abs(lo), abs(hi))
    return lo <= p_hi + slack and p_lo <= hi + slack


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
