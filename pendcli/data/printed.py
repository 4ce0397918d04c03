"""A ledger row's ``printed`` formula (and its ``reading_formula``, ``corrected_formula``) as
data: sympy syntax over the symbols the ledger declares once, with their dimensions.

Notation (tables/README.md, "The equation ledger"): ``lhs = rhs`` (a chain ``a = b = c`` is
two equations), several formulas separated by ``;``, ``...`` for the paper's « + … »
(a truncated series; it takes the dimension of whatever it is added to), explicit ``*``,
``**`` for powers, ``Integral(f, (x, a, b))`` for ∫_a^b f dx, ``Derivative(f, t, 2)`` for
d²f/dt², differentials and derivatives of one symbol as declared symbols (``dt``,
``dtheta_dt``). Only declared
names parse: an undeclared one is an error naming the row. sympy is imported lazily.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache
from itertools import pairwise
from typing import Any

from pendcli.base.errors import PendcliError
from pendcli.base.recent import Recent
from pendcli.data.formula_grammar import (
    ARITY,
    DECLARED_ARITY,
    Arity,
    check_side,
    check_words,
    parse_side,
    plain_name,
)

__all__ = [
    "ELLIPSIS",
    "FUNCTIONS",
    "Formula",
    "check_formula",
    "ledger_symbols",
    "parse_dimension",
    "parse_formula",
]


def ledger_symbols(*names: str) -> list[Any]:
    """The ledger's symbols of these names, as a printed form parses them (real): what a
    reference must build its expressions over, or the engine sees a second unknown."""
    import sympy as sp

    return [sp.Symbol(n, real=True) for n in names]


# The functions a formula may call (besides the paper's declared function names).
FUNCTIONS = (
    *("sin", "cos", "tan", "atan", "asin", "acos", "exp", "log", "sqrt", "besselj"),
    "factorial2",  # n!! = n(n − 2)(n − 4)…: Charbonnier's 2·4…n and 1·3·5…(n+1)
)
ELLIPSIS = "etc"  # the name "..." becomes, a symbol no ledger may declare
# a base letter and its power: a rational (T^-2, L^1/2) or, in brackets, an expression in
# the paper's symbols (L^(1-n): a coefficient of vⁿ)
_BASE = re.compile(r"^([A-Z])(?:\^(-?\d+(?:/\d+)?|\([-+*/ a-z0-9_]+\)))?$")


@dataclass(frozen=True)
class Formula:
    """A parsed formula: the equations it states, each as (lhs, rhs); an expression that is
    not an equation (a bare quantity) has lhs None."""

    source: str
    equations: tuple[tuple[Any, Any], ...]


def parse_dimension(where: str, text: str) -> dict[str, Any]:
    """``"L T^-2"`` -> {"L": 1, "T": -2}; ``"1"`` is dimensionless; ``"L^(1-n)"`` has a
    symbolic power (sympy, over real symbols of the names it uses), read by the formulas'
    grammar (data/formula_grammar), bounds included."""
    if text.strip() == "1":
        return {}
    out: dict[str, Any] = {}
    for part in text.split():
        match = _BASE.match(part)
        if not match:
            raise PendcliError(f"{where}: dimension {text!r}: write base letters as 'L T^-2'")
        try:
            power = _power(match.group(2) or "1")
        except PendcliError as exc:
            raise PendcliError(f"{where}: dimension {text!r}: {exc}") from None
        out[match.group(1)] = out.get(match.group(1), 0) + power
    return {k: v for k, v in out.items() if v != 0}


@cache  # a ledger names ~100 exponents ("-2", "1/2"), most of them several times
def _power(text: str) -> Any:

    names = dict.fromkeys(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", text))
    for name in names:
        if not plain_name(name):
            raise PendcliError(f"the power {text!r}: {name!r} is not a plain name")
    space = dict(zip(names, ledger_symbols(*names), strict=True))
    check_words(f"the power {text!r}", text, space)
    return parse_side(f"the power {text!r}", text.strip(), space, {})


_CALLS = ("Rational", "Integer", "Float", "Integral", "Derivative")
# the names of the notation a formula may use besides its ledger's symbols and functions
_NOTATION = (*FUNCTIONS, "pi", "oo", *_CALLS, ELLIPSIS)


@cache
def _namespace(names: tuple[str, ...], functions: tuple[str, ...]) -> dict[str, Any]:
    import sympy as sp

    space: dict[str, Any] = {f: getattr(sp, f) for f in FUNCTIONS}
    space.update({"pi": sp.pi, "Rational": sp.Rational, "Integer": sp.Integer, "Float": sp.Float})
    space["oo"] = sp.oo  # an infinite limit of an integral, ∫_0^∞
    space["Integral"] = sp.Integral  # Integral(f, (x, a, b)), the paper's ∫_a^b f dx
    space["Derivative"] = sp.Derivative  # Derivative(f, t, 2): d²f/dt², left unevaluated
    space.update(zip(names, ledger_symbols(*names), strict=True))
    space.update({f: sp.Function(f) for f in functions})
    space[ELLIPSIS] = sp.Symbol(ELLIPSIS)
    return space


@cache
def _callable(functions: tuple[str, ...]) -> dict[str, Arity]:
    """The names a formula calls, each with the arguments it takes."""
    notation = {f: ARITY[f] for f in (*FUNCTIONS, *_CALLS)}
    return {**notation, **dict.fromkeys(functions, DECLARED_ARITY)}


@cache
def _not_plain(names: tuple[str, ...]) -> str | None:
    return next((n for n in names if not plain_name(n)), None)


# Each formula parsed once per text and symbol table, whichever step asks (the ledger's
# validation, the dimension check, the printed form's verdict, a paper's formula check):
# keyed by content, not by the place an error names (a parse that fails raises, is not kept).
_PARSED = Recent(8192)


def parse_formula(where: str, text: str, symbols: Mapping[str, str]) -> Formula:
    """Parse ``text`` with the declared ``symbols`` only (names ending in ``()`` are declared
    functions) by the notation's grammar (data/formula_grammar: checked words and tree,
    never python's eval); raises PendcliError naming ``where`` on a syntax error, an
    undeclared name, a word outside the notation or a bound exceeded."""
    key = (text, tuple(sorted(symbols.items())))
    found: Formula | None = _PARSED.get(key)
    if found is None:
        found = _parse(where, text, symbols)
        _PARSED.put(key, found)
    return found


# The formulas checked by the grammar alone (:func:`check_formula`), by content.
_CHECKED = Recent(8192)


def check_formula(where: str, text: str, symbols: Mapping[str, str]) -> None:
    """What :func:`parse_formula` refuses before sympy is called (the words, the tree and
    every bound: data/formula_grammar), checked without building the expression: what a
    ledger's loading checks of every formula. Raises PendcliError naming ``where``."""
    key = (text, tuple(sorted(symbols.items())))
    if _CHECKED.get(key) is not None or _PARSED.get(key) is not None:
        return
    names, functions = _declared(where, symbols)
    known = frozenset((*_NOTATION, *names, *functions))
    check_words(where, text.replace("...", f" {ELLIPSIS} "), known)
    for part in (p.strip() for p in text.split(";")):
        for side in re.split(r"(?<![=<>!])=(?!=)", part):
            side = side.replace("...", f" {ELLIPSIS} ").strip()
            check_side(where, side, known, _callable(functions))
    _CHECKED.put(key, True)


def _declared(where: str, symbols: Mapping[str, str]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The declared symbols' names and functions' names, each a plain name."""
    names = tuple(sorted(n for n in symbols if not n.endswith("()")))
    functions = tuple(sorted(n[:-2] for n in symbols if n.endswith("()")))
    bad = _not_plain((*names, *functions))
    if bad is not None:
        raise PendcliError(f"{where}: the symbol {bad!r} is not a plain name")
    return names, functions


def _parse(where: str, text: str, symbols: Mapping[str, str]) -> Formula:
    names, functions = _declared(where, symbols)
    space = _namespace(names, functions)
    check_words(where, text.replace("...", f" {ELLIPSIS} "), space)
    equations = []
    for part in (p.strip() for p in text.split(";")):
        sides = [
            _expression(where, s, space, _callable(functions))
            for s in re.split(r"(?<![=<>!])=(?!=)", part)
        ]
        if len(sides) == 1:
            equations.append((None, sides[0]))
        equations.extend(pairwise(sides))
    return Formula(text, tuple(equations))


def _expression(where: str, text: str, space: dict[str, Any], functions: dict[str, Arity]) -> Any:
    return parse_side(where, text.replace("...", f" {ELLIPSIS} ").strip(), space, functions)
