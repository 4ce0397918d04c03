"""Values of a residual at exact random rational points: the engine's evaluation.

A residual (a printed equation's two sides, less one another, the reference substituted) is
compiled once per expression to an mpmath function (:func:`compiled`) and evaluated at
:data:`POINTS` random rational points of the reference's domain (:func:`random_value`) at
``DIGITS + 10`` digits; a definite integral in it is one mpmath quadrature per point and
precision, shared by the printed form, its reading and the residual's size. The residual
vanishes (:func:`vanishes_at_points`) when it is below ``_TOLERANCE`` relative to its size
(its terms' absolute values summed through sums and products) at every point.
"""

from __future__ import annotations

import itertools
import random
from collections.abc import Callable, Mapping
from typing import Any, Protocol

from pendcli.base.recent import Recent

__all__ = [
    "DIGITS",
    "FLOOR",
    "POINTS",
    "RELATION_POINTS",
    "Sampled",
    "compiled",
    "evaluator",
    "random_value",
    "vanishes_at_points",
]

POINTS = 3  # random rational points tried when sympy cannot simplify a residual to 0
# an inequality's points: it may fail on a part of its domain only, which few points miss
RELATION_POINTS = 32
DIGITS = 20


class Sampled(Protocol):
    """What the points read of a reference (:class:`pendcli.verify.printed_check.Reference`):
    each symbol's range, and the scale a series is taken in."""

    @property
    def domain(self) -> Mapping[str, tuple[Any, Any]]: ...

    @property
    def scale(self) -> Any: ...


def random_value(generator: random.Random, reference: Sampled, symbol: Any) -> Any:
    import sympy as sp

    low, high = reference.domain.get(symbol.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
    return low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)


def vanishes_at_points(expr: Any, reference: Sampled) -> tuple[bool, str]:
    import sympy as sp

    generator = random.Random(19)
    free = sorted(expr.free_symbols, key=lambda s: s.name)
    at = evaluator(expr, free)
    size_at: list[Any] = []  # the size's evaluator, built at the first point that needs it
    for _ in range(POINTS):
        point = {}
        for s in free:
            low, high = reference.domain.get(s.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
            point[s] = low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)
        value = at(point)
        shown = ", ".join(f"{k}={v}" for k, v in point.items())
        if not value.is_number:
            return False, f"the residual is not a number at {shown}"
        if abs(value) > FLOOR and abs(value) > _TOLERANCE * _size_at(expr, free, point, size_at):
            return False, f"residual {sp.N(value, 6)} at {shown}"
    return True, f"vanishes at {POINTS} random rational points"


def evaluator(expr: Any, free: list[Any]) -> Any:
    """point -> the value of ``expr`` there. mpmath at a fixed precision (integrals by
    mpmath.quad) where the expression is made of functions mpmath has: one pass, where sympy's
    evalf climbs in precision on a residual that cancels to 0 (for Bessel functions, seconds a
    point); evalf otherwise."""
    import mpmath
    import sympy as sp

    def by_evalf(point: dict[Any, Any]) -> Any:
        return sp.N(_integrals_by_quadrature(expr.subs(point)), DIGITS)

    if expr.atoms(sp.Derivative, sp.Subs) or any(
        isinstance(f, sp.core.function.AppliedUndef) for f in expr.atoms(sp.Function)
    ):
        return by_evalf
    function = compiled(tuple(free), expr)

    def by_mpmath(point: dict[Any, Any]) -> Any:
        with mpmath.workdps(DIGITS + 10):
            try:
                value = function(*(mpmath.mpf(q.p) / q.q for q in point.values()))
            except (ArithmeticError, TypeError, ValueError):
                return by_evalf(point)
            if isinstance(value, (mpmath.mpf, mpmath.mpc)):
                return sp.sympify(value, strict=True)
        return by_evalf(point)

    return by_mpmath


# residual -> its lambdified code; integral -> a function remembering its quadratures;
# each integral's quadratures by point and precision: the most recent few thousand of each
_COMPILED = Recent(4096)
_QUADRATURES = Recent(1024)
_QUADRATURES_EACH = 256
_NAMES = itertools.count()  # a quadrature function's name, never reused after a forgotten one


def compiled(arguments: tuple[Any, ...], expr: Any) -> Callable[..., Any]:
    """``expr`` as an mpmath function of ``arguments``, lambdified once per expression: the
    printed and the reading form, each point's size, share a residual's code. No docstring:
    lambdify's prints the whole expression, a third of its time."""
    import sympy as sp

    key = (arguments, expr)
    function = _COMPILED.get(key)
    if function is None:
        code = _integrals_shared(expr)
        function = sp.lambdify(arguments, code, modules="mpmath", docstring_limit=0)
        _COMPILED.put(key, function)
    return function


def _integrals_shared(expr: Any) -> Any:
    """``expr`` with each definite integral a call of a function of its free symbols that
    runs the same mpmath quadrature lambdify would, once per point and precision: a
    residual's size, its printed and reading forms, evaluate the same integrals at the same
    random points. Nested integrals are left as they are."""
    import sympy as sp

    integrals = expr.atoms(sp.Integral)
    if not integrals or any(i.function.has(sp.Integral) for i in integrals):
        return expr
    calls = {}
    for integral in integrals:
        free = tuple(sorted(integral.free_symbols, key=lambda s: s.name))
        shared = _QUADRATURES.get(integral)
        if shared is None:
            shared = _remembered_quadrature(integral, free)
            _QUADRATURES.put(integral, shared)
        calls[integral] = shared(*free)
    return expr.xreplace(calls)


def _remembered_quadrature(integral: Any, free: tuple[Any, ...]) -> Any:
    """A sympy function of ``free`` whose mpmath code is ``integral``'s quadrature, each
    (precision, point) computed once."""
    import mpmath
    import sympy as sp
    from sympy.utilities.lambdify import implemented_function

    quadrature = sp.lambdify(free, integral, modules="mpmath", docstring_limit=0)
    memo = Recent(_QUADRATURES_EACH)

    def remembered(*args: Any) -> Any:
        at = (mpmath.mp.prec, *args)
        value = memo.get(at)
        if value is None:
            value = quadrature(*args)
            memo.put(at, value)
        return value

    return implemented_function(sp.Function(f"quadrature_{next(_NAMES)}"), remembered)


def _integrals_by_quadrature(expr: Any) -> Any:
    """``expr`` (at a point) with each definite integral replaced by its mpmath quadrature:
    sympy's own numerical integration is several times slower for the same digits."""
    import mpmath
    import sympy as sp

    values = {}
    for integral in expr.atoms(sp.Integral):
        (variable, low, high), *rest = integral.limits
        if rest or integral.function.free_symbols - {variable}:
            continue  # a multiple or a parametric integral: left to sympy
        integrand = compiled((variable,), integral.function)
        with mpmath.workdps(DIGITS + 5):
            bounds = [sp.N(b, DIGITS + 5)._to_mpmath(mpmath.mp.prec) for b in (low, high)]
            values[integral] = sp.Float(mpmath.quad(integrand, bounds), DIGITS + 5)
    return expr.subs(values)


# The residual is refused when above _TOLERANCE relative to its size (its terms' absolute
# values summed through sums and products, at the point): 1e-15 of terms of 1e6 is
# rounding, 1e-15 of terms of 1e-12 is not. Below FLOOR (far under the working precision's
# rounding) it is 0 whatever its terms, and the size is not computed.
_TOLERANCE = 10.0 ** (5 - DIGITS)
FLOOR = 10.0 ** -(DIGITS + 8)


def _size_at(expr: Any, free: list[Any], point: dict[Any, Any], built: list[Any]) -> Any:
    """The size of ``expr`` at ``point``: the value of ``expr`` with every sum a sum of
    absolute values (ε·(a − b) has size |ε|·(|a| + |b|), the scale its cancellation is on).
    ``built``: empty, or the size's evaluator from an earlier point of the same ``expr``."""
    import sympy as sp

    if not built:
        built.append(evaluator(_magnitude(expr), free))
    size = abs(built[0](point))
    # a size with an unevaluated function in it (a transform's F0_): the absolute tolerance
    return size if getattr(size, "is_comparable", False) else sp.Integer(1)


def _magnitude(expr: Any) -> Any:
    import sympy as sp

    if expr.is_Add:
        return sp.Add(*(_magnitude(a) for a in expr.args))
    if expr.is_Mul:
        return sp.Mul(*(_magnitude(a) for a in expr.args))
    if expr.is_Pow and expr.exp.is_Integer and expr.exp > 0:
        return _magnitude(expr.base) ** expr.exp
    return abs(expr)
