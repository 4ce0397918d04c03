"""What one equation check returns: the contract between a paper's ``equations`` module and
the ledger engine.

A paper's ``pendcli/papers/<paper>/equations.py`` holds one pure function per checkable row
of its ledger (``tables/equations/<paper>.toml``); each returns an :class:`EquationCheck`.
The engine compares what the check found with the status the ledger records, so a ledger
row can never claim ``holds`` for an equation the computation refutes.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from pendcli.core.vocabulary import STATUSES
from pendcli.core.vocabulary import EquationStatus as Status

__all__ = ["CHECK_METHODS", "STATUSES", "EquationCheck", "Method", "Status"]


# sympy: an exact symbolic identity; numeric: against an independent solution (quadrature,
# ODE, mpmath), with an observed order where the equation is a truncated series;
# cross-reference: a statement "la formule (5) donnera ..." re-derived from the formula it
# cites.
Method = Literal["sympy", "numeric", "cross-reference"]
CHECK_METHODS: tuple[Method, ...] = ("sympy", "numeric", "cross-reference")


@dataclass(frozen=True)
class EquationCheck:
    """The outcome of checking one equation as printed (or as read, for a misprint).

    ``holds`` is what the computation found for the form the ledger row checks: the printed
    form for ``holds``/``fails`` rows, the evident reading for ``misprint`` rows. ``detail`` is
    one sentence with the numbers compared. A failing check carries the ``corrected`` form the
    computation found (e.g. the fitted leading term), never a guess.
    """

    holds: bool
    method: Method
    detail: str
    observed_order: float | None = None
    claimed_order: float | None = None
    corrected: str | None = None
