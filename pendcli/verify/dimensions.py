"""Dimensional analysis of a parsed formula from the ledger's declared dimensions.

Every equation's two sides, every sum's terms and every argument of sin, cos, tan, exp, log,
the inverse functions and besselj (order and argument) must agree (arguments: be
dimensionless); a power of a dimensioned quantity needs a rational exponent. The verdict is
``consistent``, ``dimensionless`` (every quantity a pure number) or ``inconsistent`` with the
first disagreement found.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Literal

from pendcli.data.printed import ELLIPSIS, Formula

__all__ = ["DIMENSION_VERDICTS", "DimensionCheck", "check_dimensions", "show"]

Verdict = Literal["consistent", "inconsistent", "dimensionless"]
DIMENSION_VERDICTS: tuple[Verdict, ...] = ("consistent", "inconsistent", "dimensionless")
# base letter -> exponent: a Fraction, or a sympy expression for a symbolic power (vⁿ)
Dim = dict[str, Any]
_TRANSCENDENTAL = ("sin", "cos", "tan", "atan", "asin", "acos", "exp", "log", "besselj")
_OF_NUMBERS = (*_TRANSCENDENTAL, "factorial2")  # n!!: Charbonnier's I_n(π)


class _Mismatch(Exception):
    pass


@dataclass(frozen=True)
class DimensionCheck:
    verdict: Verdict
    detail: str


def show(dim: Dim | None) -> str:
    if dim is None:
        return "any"
    return " ".join(f"{k}^{v}" if v != 1 else k for k, v in sorted(dim.items())) or "1"


def check_dimensions(formula: Formula, dims: Mapping[str, Dim]) -> DimensionCheck:
    """The formula's verdict; ``dims`` maps each declared name (functions: ``"f()"``)."""
    seen: list[Dim] = []
    try:
        for lhs, rhs in formula.equations:
            right = _dim(rhs, dims, seen)
            if lhs is not None:
                left = _dim(lhs, dims, seen)
                _agree(left, right, "the two sides of {} = {}", lhs, rhs)
    except _Mismatch as exc:
        return DimensionCheck("inconsistent", str(exc))
    if all(not d for d in seen):
        return DimensionCheck("dimensionless", "every quantity is a pure number")
    return DimensionCheck("consistent", "sides, terms and function arguments agree")


def _agree(a: Dim | None, b: Dim | None, what: str, *parts: Any) -> None:
    """Raise a mismatch naming ``what`` filled with ``parts`` (printed only then: 365
    formulas agree, and their expressions cost a second to print) unless ``a`` and ``b``
    agree."""
    if a is not None and b is not None and a != b and _quotient(a, b):
        raise _Mismatch(f"{what.format(*parts)}: {show(a)} against {show(b)}")


def _quotient(a: Dim, b: Dim) -> Dim:
    """a / b: the base letters whose exponents differ (symbolic ones simplified)."""
    import sympy as sp

    out = {}
    for k in {*a, *b}:
        difference = sp.simplify(
            sp.sympify(a.get(k, 0), strict=True) - sp.sympify(b.get(k, 0), strict=True)
        )
        if difference != 0:
            out[k] = difference
    return out


def _dim(expr: Any, dims: Mapping[str, Dim], seen: list[Dim]) -> Dim | None:
    """The dimension of ``expr`` (None: the ellipsis or 0, which adapt to their sum)."""
    import sympy as sp

    if expr.is_Symbol:
        if expr.name == ELLIPSIS:
            return None
        seen.append(dims[expr.name])
        return dict(dims[expr.name])
    if expr == 0:  # structurally: the assumptions' is_zero costs most of the check
        return None  # 0 = 0 m = 0 s: a zero side or limit takes any dimension
    if expr.is_Number or expr in (sp.pi, sp.E):
        return {}
    if expr.is_Add:
        terms = [(t, _dim(t, dims, seen)) for t in expr.args]
        known = [(t, d) for t, d in terms if d is not None]
        for t, d in known[1:]:
            _agree(known[0][1], d, "the terms {} and {}", known[0][0], t)
        return known[0][1] if known else None
    if expr.is_Mul:
        total: Dim = {}
        for factor in expr.args:
            part = _dim(factor, dims, seen)
            if part is None:
                return None
            total = _product(total, part)
        return total
    if expr.is_Pow:
        return _power(expr, dims, seen)
    if isinstance(expr, sp.Integral):
        return _integral(expr, dims, seen)
    if isinstance(expr, sp.Derivative):
        return _derivative(expr, dims, seen)
    if isinstance(expr, sp.core.relational.Relational):  # an inequality: its sides agree
        _agree(_dim(expr.lhs, dims, seen), _dim(expr.rhs, dims, seen), "the sides of {}", expr)
        return {}
    return _function(expr, dims, seen)


def _integral(expr: Any, dims: Mapping[str, Dim], seen: list[Dim]) -> Dim | None:
    """∫ f dx: the dimension of f times that of x; the limits have the dimension of x."""
    total = _dim(expr.function, dims, seen)
    for limit in expr.limits:
        variable = _dim(limit[0], dims, seen)
        for bound in limit[1:]:
            _agree(variable, _dim(bound, dims, seen), "the limits of {}", expr)
        if total is None or variable is None:
            return None
        total = _product(total, variable)
    return total


def _derivative(expr: Any, dims: Mapping[str, Dim], seen: list[Dim]) -> Dim | None:
    """dⁿf/dxⁿ: the dimension of f over that of x to the n."""
    total = _dim(expr.expr, dims, seen)
    for variable, count in expr.variable_count:
        d = _dim(variable, dims, seen)
        if total is None or d is None:
            return None
        total = _product(total, {k: -v * count for k, v in d.items()})
    return total


def _product(a: Dim, b: Dim) -> Dim:
    summed = {k: a.get(k, 0) + b.get(k, 0) for k in {*a, *b}}
    return {k: v for k, v in summed.items() if v != 0}


def _power(expr: Any, dims: Mapping[str, Dim], seen: list[Dim]) -> Dim | None:
    base, exponent = expr.args
    exponent_dim = _dim(exponent, dims, seen)
    if exponent_dim:
        raise _Mismatch(f"the exponent of {expr} has dimension {show(exponent_dim)}")
    d = _dim(base, dims, seen)
    if not d:
        return d
    # a symbolic exponent (vⁿ) gives symbolic exponents of the base letters
    return {k: v * exponent for k, v in d.items()}


def _function(expr: Any, dims: Mapping[str, Dim], seen: list[Dim]) -> Dim | None:
    name = type(expr).__name__
    if name in _OF_NUMBERS:
        for arg in expr.args:
            d = _dim(arg, dims, seen)
            if d:
                raise _Mismatch(f"the argument of {name}({arg}) has dimension {show(d)}")
        return {}
    if f"{name}()" in dims:
        for arg in expr.args:
            _dim(arg, dims, seen)
        seen.append(dims[f"{name}()"])
        return dict(dims[f"{name}()"])
    raise _Mismatch(f"no dimension for {expr}")
