"""The named kinds of check that decide a ledger row, and the one rule that says which applies.

A checked ledger row (``holds``, ``fails``, ``misprint``) declares its ``kind`` in the TOML
beside the ``reference`` it is judged against and the kind's parameters (``scale``,
``order``, ``orders``, ``domain``, ``bounded``, ``rounded``, ``cases``, ``each_case``: keys of
the row, :data:`KIND_KEYS`, validated when the ledger loads by :func:`parse_parameters`). The
kind is what the engine proves about the printed form; the reference supplies only the model
(its exact expressions), the row's keys are put in place of its own (:func:`with_parameters`).
The rule, first match wins:

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

import re
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from pendcli.data.printed import Formula

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
    from pendcli.verify.printed_check import is_relation as _is_relation
    from pendcli.verify.printed_numeric import Numbers

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


# The kind's parameters a row may give beside its reference (the reference is then only the
# model: its exact expressions), by kind; each read and validated when the ledger loads.
PARAMETER_KEYS = ("scale", "order", "orders", "domain", "bounded", "rounded", "cases", "each_case")
KIND_KEYS: dict[str, tuple[str, ...]] = {
    "identity": ("domain",),
    "series": ("scale", "order", "orders", "domain"),
    "inequality": ("scale", "order", "domain"),
    "limit": ("scale", "bounded", "domain"),
    "decimal": ("rounded", "scale", "order", "orders", "domain"),
    "digits": (),
    "cases": ("cases", "each_case", "scale", "order", "orders", "domain"),
}

# a row's parameters as the ledger row keeps them: (key, value) pairs, hashable
Parameters = tuple[tuple[str, Any], ...]


def parse_parameters(where: str, kind: object, entry: dict[str, Any]) -> Parameters:
    """The kind's parameters of a ledger row's ``entry`` (its TOML table), validated: a key
    the kind does not take, a value of the wrong shape or a meaningless combination is a
    one-line error naming the row (``where``) and the key."""
    from pendcli.base.errors import PendcliError

    given = [k for k in PARAMETER_KEYS if k in entry]
    if not given:
        return ()
    valid = KIND_KEYS.get(kind, ()) if isinstance(kind, str) else ()
    for key in given:
        if key not in valid:
            takes = ", ".join(valid) or "none"
            raise PendcliError(f"{where}: kind {kind!r} takes no {key!r} (its keys: {takes})")
    out = []
    for key in given:
        try:
            out.append((key, _PARSERS[key](entry[key])))
        except (TypeError, ValueError) as exc:
            raise PendcliError(f"{where}: {key!r} {exc}") from None
    problem = _combination_problem(dict(out))
    if problem:
        raise PendcliError(f"{where}: {problem}")
    return tuple(out)


def _combination_problem(values: dict[str, Any]) -> str | None:
    for key in ("order", "orders", "bounded"):
        if key in values and "scale" not in values:
            return f"{key!r} needs a 'scale'"
    if values.get("bounded") is False or values.get("rounded") is False:
        return "'bounded' and 'rounded' are true or absent"
    if "scale" in values and "order" not in values and "bounded" not in values:
        return "'scale' needs an 'order' (or 'bounded')"
    if "cases" in values and "each_case" in values:
        return "'cases' and 'each_case' exclude each other"
    return None


def _name(value: object) -> str:
    if not isinstance(value, str) or not value.isidentifier():
        raise ValueError(f"must be a symbol name, not {value!r}")
    return value


def _order(value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise ValueError(f"must be a non-negative integer, not {value!r}")
    return value


def _true(value: object) -> bool:
    if not isinstance(value, bool):
        raise ValueError(f"must be true or false, not {value!r}")
    return value


def _table(value: object) -> dict[str, Any]:
    if not isinstance(value, dict) or not value:
        raise ValueError("must be a non-empty table of symbol names")
    for name in value:
        _name(name)
    return value


def _orders(value: object) -> tuple[tuple[str, int], ...]:
    return tuple((n, _order(v)) for n, v in _table(value).items())


# An integer, a decimal or a fraction as the ledger writes one, its digits and exponent
# bounded: "1e99999999" would make a ten-million-digit integer (a crafted ledger's hang).
_NUMBER = re.compile(r"-?\d{1,30}(?:\.\d{0,30})?(?:[eE][-+]?\d{1,3})?(?:/\d{1,30})?")


def number(value: object) -> Any:
    """A domain bound or a case's value as the ledger writes it (an integer, a decimal, or a
    fraction "p/q" as a string), as an exact sympy number."""
    import sympy as sp

    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise ValueError(f"is not a number: {value!r}")
    if not _NUMBER.fullmatch(str(value).strip()):
        raise ValueError(f"is not a number of at most 30 digits: {str(value)[:40]!r}")
    try:
        exact = sp.Rational(str(value).strip())
    except (TypeError, ValueError, SyntaxError, sp.SympifyError):
        raise ValueError(f"is not a number: {value!r}") from None
    return exact


def _bounds(value: object) -> tuple[Any, Any]:
    if not isinstance(value, list) or len(value) != 2:
        raise ValueError(f"bounds must be [low, high], not {value!r}")
    low, high = number(value[0]), number(value[1])
    if not low < high:
        raise ValueError(f"bounds reversed or empty: [{value[0]}, {value[1]}]")
    return low, high


def _domain(value: object) -> tuple[tuple[str, tuple[Any, Any]], ...]:
    out = []
    for name, bounds in _table(value).items():
        try:
            out.append((name, _bounds(bounds)))
        except ValueError as exc:
            raise ValueError(f"of {name!r}: {exc}") from None
    return tuple(out)


def _names(value: object) -> tuple[str, ...]:
    if not isinstance(value, list) or not value:
        raise ValueError("must be a non-empty list of reference names")
    return tuple(_name(v) for v in value)


def _each_case(value: object) -> tuple[tuple[tuple[str, Any], ...], ...]:
    if not isinstance(value, list) or not value:
        raise ValueError("must be a non-empty list of tables (symbol = value)")
    return tuple(tuple((n, number(v)) for n, v in _table(case).items()) for case in value)


_PARSERS: dict[str, Any] = {
    "scale": _name,
    "order": _order,
    "orders": _orders,
    "domain": _domain,
    "bounded": _true,
    "rounded": _true,
    "cases": _names,
    "each_case": _each_case,
}


def with_parameters(reference: Any, parameters: Parameters, cases: tuple[Any, ...] = ()) -> Any:
    """``reference`` (a ``Reference``) with the row's ``parameters`` in place of its own (a
    domain: added to its own); its reading and its cases (the row's ``cases``: the references
    it names, built) each given the row's parameters but the cases'."""
    from dataclasses import replace

    if not parameters:
        return reference
    values = dict(parameters)
    given: dict[str, Any] = {}
    if "scale" in values:
        given["scale"] = _scale_symbol(reference, values["scale"])
    for key in ("order", "bounded", "rounded"):
        if key in values:
            given[key] = values[key]
    if "orders" in values:
        given["orders"] = dict(values["orders"])
    if "domain" in values:
        given["domain"] = {**reference.domain, **dict(values["domain"])}
    if "each_case" in values:
        given["each_case"] = tuple(dict(case) for case in values["each_case"])
    # the reading and each case are judged for the same row: its parameters apply to them
    own = tuple(p for p in parameters if p[0] not in ("cases", "each_case"))
    if reference.reading is not None:
        given["reading"] = with_parameters(reference.reading, own)
    if cases or reference.cases:
        given["cases"] = tuple(with_parameters(c, own) for c in cases or reference.cases)
    return replace(reference, **given)


def _scale_symbol(reference: Any, name: str) -> Any:
    """The reference's own symbol named ``name`` (the scale its expressions are written in),
    else a real symbol of that name (the ledger's)."""
    import sympy as sp

    if reference.scale is not None and reference.scale.name == name:
        return reference.scale
    for value in reference.exact.values():
        for symbol in getattr(value, "free_symbols", ()):
            if symbol.name == name:
                return symbol
    return sp.Symbol(name, real=True)
