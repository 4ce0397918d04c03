"""What one equation check returns: the contract between a paper's ``equations`` module and
the ledger engine.

A paper's ``pendcli/papers/<paper>/equations.py`` holds one pure function per checkable row
of its ledger (``tables/equations/<paper>.toml``); each returns an :class:`EquationCheck`.
The engine compares what the check found with the status the ledger records, so a ledger
row can never claim ``holds`` for an equation the computation refutes.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from pendcli.core.errors import PendcliError
from pendcli.core.vocabulary import STATUSES, FormulaVerdict
from pendcli.core.vocabulary import EquationStatus as Status

if TYPE_CHECKING:
    from pendcli.core.claims import FormulaRow

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


def check_from_formula_rows(rows: Iterable[FormulaRow], ids: Iterable[str]) -> EquationCheck:
    """One equation checked by existing formula checks (``formulas.py``): it holds when every
    named row holds; the lowest observed order and the failing rows' corrected forms carry."""
    by_id = {r.id: r for r in rows}
    wanted = list(ids)
    missing = [i for i in wanted if i not in by_id]
    if missing:
        raise PendcliError(f"no formula check {', '.join(missing)} (renamed or removed?)")
    chosen = [by_id[i] for i in wanted]
    failing = [r for r in chosen if r.verdict != FormulaVerdict.HOLDS]
    orders = [r.observed_order for r in chosen if r.observed_order is not None]
    claimed = [r.claimed_order for r in chosen if r.claimed_order is not None]
    parts = [f"{r.id} {r.verdict} (order {_order(r.observed_order)})" for r in chosen]
    return EquationCheck(
        holds=not failing,
        method="numeric",
        detail="formula checks: " + "; ".join(parts),
        observed_order=min(orders) if orders else None,
        claimed_order=min(claimed) if claimed else None,
        corrected="; ".join(r.recomputed for r in failing) or None,
    )


def _order(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.2f}"
