"""The named kinds of check that decide a ledger row, and the one rule that says which applies.

A checked ledger row (``holds``, ``fails``, ``misprint``) declares its ``kind`` in the TOML
beside the ``reference`` it is judged against. The kind is what the engine proves about the
printed form; the reference supplies the model (its exact expressions) and the kind's
parameters (a series' scale and order, a domain, cases). The rule, first match wins:

1. ``digits``: the reference gives the value of each printed number (``Numbers``);
2. ``cases``: the reference judges the formula in several cases (``cases``, ``each_case``,
   ``conditions``);
3. ``limit``: the reference asks that a residual stay finite as its scale tends to 0+;
4. ``decimal``: a decimal in a formula stands for a constant, rounded (``rounded``);
5. ``inequality``: the printed form is relations only (``a > b``), no equation;
6. ``series``: the reference gives a scale and an order (a truncated expansion);
7. ``identity``: every other row: each equation's residual vanishes identically.

A row whose declared kind is not the one its reference and printed form call for is refused
with a one-line error naming the row. ``docs/ENGINE.md`` says what each kind proves and
which verdicts are proofs and which agreement at random points.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from pendcli.core.printed import Formula

__all__ = ["KINDS", "kind_called_for", "kind_mismatch", "kind_problem"]

# kind -> what it proves, in one line (the docs page says more)
KINDS: dict[str, str] = {
    "identity": "each equation's residual vanishes once the reference's expressions are put in",
    "series": "each residual's expansion in the scale vanishes below the stated order",
    "inequality": "each relation's margin has the stated sign over the reference's domain",
    "limit": "each residual stays finite as the scale tends to 0+",
    "decimal": "the printed decimal is a constant the formula needs, rounded to its places",
    "digits": "each printed number is the model's value, rounded or chopped to its places",
    "cases": "the formula holds in each of the reference's cases",
}


def kind_called_for(formula: Formula, reference: Any) -> str:
    """The kind that ``reference`` (a ``Reference`` or ``Numbers``) and the printed
    ``formula`` call for, by the rule of the module docstring."""
    from pendcli.core.printed_check import is_relation as _is_relation
    from pendcli.core.printed_numeric import Numbers

    if isinstance(reference, Numbers):
        return "digits"
    if reference.cases or reference.each_case or reference.conditions:
        return "cases"
    if reference.bounded:
        return "limit"
    if reference.rounded:
        return "decimal"
    if formula.equations and all(
        lhs is None and _is_relation(rhs) for lhs, rhs in formula.equations
    ):
        return "inequality"
    if reference.scale is not None:
        return "series"
    return "identity"


def kind_problem(kind: str, formula: Formula, reference: Any) -> str | None:
    """Why the declared ``kind`` is not the one the reference and printed form call for, or
    None when it is."""
    called = kind_called_for(formula, reference)
    return None if called == kind else kind_mismatch(kind, called)


def kind_mismatch(declared: str, called: str) -> str:
    """The one line naming a declared kind that is not the one called for."""
    return f"kind {declared!r} is declared, but its reference and printed form make it {called!r}"
