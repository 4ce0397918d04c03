"""Statuses computed from the printed form (issue 19): a row's ``printed`` formula checked as
an identity against the reference its paper's code supplies.

A reference (``reference = "name"`` in the row; ``pendcli.papers.<paper>.equations.name()``
returns a :class:`Reference`) maps some of the ledger's symbols to exact expressions: the
preceding equation, the definition a formula rests on, the exact solution; never a second
copy of the printed formula. Each equation ``lhs = rhs`` of a formula passes when
``lhs − rhs`` (with « … » set to 0), after the substitution, vanishes at exact random
rational points (to 20 digits), or simplifies to 0 where a point gives no number; with a
``scale`` and an ``order``, when its series in the scale vanishes below that order (an
equation whose left side is a symbol named in ``orders`` uses that order: a summary formula
may carry one quantity further than another). The status follows:

* ``holds``: the printed form passes;
* ``misprint``: the printed form fails and its ``reading_formula`` passes;
* ``fails``: the printed form fails and its ``corrected_formula`` passes;
* otherwise nothing the ledger may record: the row is refused.
"""

from __future__ import annotations

import random
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from pendcli.core.printed import ELLIPSIS, Formula

__all__ = ["Reference", "computed_status", "formula_passes", "judged"]

POINTS = 3  # random rational points tried when sympy cannot simplify a residual to 0
_DIGITS = 20


@dataclass(frozen=True)
class Reference:
    """Symbol name -> exact sympy expression (a declared function's name -> a callable of its
    arguments, e.g. a ``sympy.Lambda``); ``scale``/``order``: compare a truncated series
    (the residual's series in ``scale`` must vanish through ``scale**(order - 1)``);
    ``domain``: symbol name -> (low, high) for the random points (default (1/10, 1/2));
    ``orders``: left-side symbol name -> the order its equation is compared through;
    ``reading``: the reference the reading is judged against, when the slip is the text's
    cross-reference itself (the printed form is judged against the equation the text cites,
    the reading against the one it should cite);
    ``rates``: variable name -> {symbol name -> its derivative in that variable}, how a printed
    ``Derivative(f, t)`` is evaluated (the chain rule; an unlisted symbol is a constant);
    ``transform``: applied to the residual before the substitution (a total derivative, a
    change of variable the notation leaves implicit);
    ``cases``: symbol name -> value maps, each added to ``exact`` in turn: the formula must
    pass in every case (a claim « chaque fois que », at each root of a function);
    ``conditions``: the model's own equation (its residual) for each printed equation in
    order, None to skip: a printed equation that is a condition for roots, not an identity
    (φ/x = φ' with φ, φ' by their series), passes when lhs − rhs − condition vanishes."""

    exact: Mapping[str, Any]
    scale: Any = None
    order: int | None = None
    domain: Mapping[str, tuple[Any, Any]] = field(default_factory=dict)
    what: str = ""
    orders: Mapping[str, int] = field(default_factory=dict)
    reading: Reference | None = None
    rates: Mapping[str, Mapping[str, Any]] = field(default_factory=dict)
    transform: Callable[[Any], Any] | None = None
    cases: tuple[Mapping[str, Any], ...] = ()
    conditions: tuple[Any, ...] = ()


def formula_passes(formula: Formula, reference: Reference) -> tuple[bool, str]:
    """Whether every equation of ``formula`` holds under ``reference``, and why not."""
    for lhs, rhs in formula.equations:
        if lhs is None:
            continue
        order = reference.orders.get(getattr(lhs, "name", ""), reference.order)
        ok, why = _equation_passes(lhs - rhs, reference, order)
        if not ok:
            return False, f"{lhs} = {rhs}: {why}"
    return True, "every equation holds" + (f" against {reference.what}" if reference.what else "")


def _equation_passes(residual: Any, reference: Reference, order: int | None) -> tuple[bool, str]:
    import sympy as sp

    expr = residual.subs({s: 0 for s in residual.free_symbols if s.name == ELLIPSIS})
    if reference.transform is not None:
        expr = reference.transform(expr)
    if reference.rates:
        expr = _along_the_rates(expr, reference.rates)
    names = {s.name: s for s in expr.free_symbols}
    exact = {names[n]: v for n, v in reference.exact.items() if n in names}
    # the symbols first: a function's value is an expression in the unsubstituted symbols
    expr = _functions_replaced(expr.subs(exact, simultaneous=True), reference)
    # a derivative of the reference's explicit functions is taken (integrals stay for quadrature)
    expr = expr.replace(lambda e: isinstance(e, sp.Derivative), lambda e: e.doit())
    if reference.scale is not None and order is not None:
        expr = _truncated(expr, reference.scale, order)
    # The random points first: cheap, and decisive when the residual is not 0; simplify only
    # where a point gives no number. An integral is never simplified (sympy's antiderivatives
    # can take minutes).
    ok, why = _vanishes_at_points(expr, reference)
    if ok or "not a number" not in why or expr.has(sp.Integral):
        return ok, why
    return (True, "simplifies to 0") if sp.simplify(expr) == 0 else (False, why)


def _along_the_rates(expr: Any, rates: Mapping[str, Mapping[str, Any]]) -> Any:
    """Each ``Derivative(f, x, n)`` of ``expr`` by the chain rule along ``rates[x]`` (the
    printed d/dt of a product of declared symbols: l² dθ/dt -> 2l l' θ' + l² θ'')."""
    import sympy as sp

    def total(f: Any, x: Any) -> Any:
        rate = rates.get(x.name, {})
        terms = (sp.diff(f, s) * (1 if s == x else rate.get(s.name, 0)) for s in f.free_symbols)
        return sp.Add(*terms)

    def evaluate(derivative: Any) -> Any:
        f = derivative.expr
        for x, count in derivative.variable_count:
            for _ in range(count):
                f = total(f, x)
        return f

    return expr.replace(lambda e: isinstance(e, sp.Derivative), evaluate)


def _truncated(expr: Any, scale: Any, order: int) -> Any:
    """The series of ``expr`` in ``scale`` below ``order`` (sympy's series of a polynomial
    with unevaluated integrals for coefficients can take minutes)."""
    import sympy as sp

    if expr.is_polynomial(scale):  # its Taylor coefficients, by differentiation
        terms, term = [], expr
        for j in range(order):
            terms.append(term.subs(scale, 0) * scale**j / sp.factorial(j))
            term = sp.diff(term, scale)
        return sum(terms)
    return sp.series(expr, scale, 0, order).removeO()


def _functions_replaced(expr: Any, reference: Reference) -> Any:
    """Each call of a declared function the reference gives (``E_c(pi)``) by its value."""
    from sympy.core.function import AppliedUndef

    def given(e: Any) -> bool:
        return isinstance(e, AppliedUndef) and callable(reference.exact.get(type(e).__name__))

    return expr.replace(given, lambda e: reference.exact[type(e).__name__](*e.args))


def _vanishes_at_points(expr: Any, reference: Reference) -> tuple[bool, str]:
    import sympy as sp

    generator = random.Random(19)
    free = sorted(expr.free_symbols, key=lambda s: s.name)
    at = _evaluator(expr, free)
    for _ in range(POINTS):
        point = {}
        for s in free:
            low, high = reference.domain.get(s.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
            point[s] = low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)
        value = at(point)
        shown = ", ".join(f"{k}={v}" for k, v in point.items())
        if not value.is_number:
            return False, f"the residual is not a number at {shown}"
        if abs(value) > sp.Float(10) ** (5 - _DIGITS):
            return False, f"residual {sp.N(value, 6)} at {shown}"
    return True, f"vanishes at {POINTS} random rational points"


def _evaluator(expr: Any, free: list[Any]) -> Any:
    """point -> the value of ``expr`` there. mpmath at a fixed precision (integrals by
    mpmath.quad) where the expression is made of functions mpmath has: one pass, where sympy's
    evalf climbs in precision on a residual that cancels to 0 (for Bessel functions, seconds a
    point); evalf otherwise."""
    import mpmath
    import sympy as sp

    def by_evalf(point: dict[Any, Any]) -> Any:
        return sp.N(_integrals_by_quadrature(expr.subs(point)), _DIGITS)

    if expr.atoms(sp.Derivative, sp.Subs) or any(
        isinstance(f, sp.core.function.AppliedUndef) for f in expr.atoms(sp.Function)
    ):
        return by_evalf
    function = sp.lambdify(free, expr, modules="mpmath")

    def by_mpmath(point: dict[Any, Any]) -> Any:
        with mpmath.workdps(_DIGITS + 10):
            try:
                value = function(*(mpmath.mpf(q.p) / q.q for q in point.values()))
            except (ArithmeticError, TypeError, ValueError):
                return by_evalf(point)
            if isinstance(value, (mpmath.mpf, mpmath.mpc)):
                return sp.sympify(value)
        return by_evalf(point)

    return by_mpmath


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
        integrand = sp.lambdify(variable, integral.function, modules="mpmath")
        with mpmath.workdps(_DIGITS + 5):
            bounds = [sp.N(b, _DIGITS + 5)._to_mpmath(mpmath.mp.prec) for b in (low, high)]
            values[integral] = sp.Float(mpmath.quad(integrand, bounds), _DIGITS + 5)
    return expr.subs(values)


def computed_status(
    printed: Formula, reading: Formula | None, corrected: Formula | None, reference: Reference
) -> tuple[str | None, str]:
    """The status the printed form earns (None: none the ledger may record) and why."""
    ok, why = judged(printed, reference)
    if ok:
        return "holds", f"the printed form holds: {why}"
    for status, other in (("misprint", reading), ("fails", corrected)):
        if other is not None:
            against = reference.reading if status == "misprint" and reference.reading else reference
            other_ok, other_why = judged(other, against)
            if other_ok:
                return status, f"the printed form fails ({why}); the {status} form holds"
            return None, f"the printed form fails ({why}) and so does its {status} ({other_why})"
    return None, f"the printed form fails ({why}) and the row gives no reading or correction"


# --- prose claims (issue 19, a19): cases, conditions for roots, inequalities ----------------


def judged(formula: Formula, reference: Reference) -> tuple[bool, str]:
    """:func:`formula_passes`, with the reference's ``cases`` (every one must pass) and
    ``conditions``, and each bare inequality (``a < b``, ``a <= b``) judged by
    :func:`inequality_holds`."""
    from dataclasses import replace

    if reference.cases:
        why = ""
        for index, case in enumerate(reference.cases, 1):
            one = replace(reference, exact=_in_case(reference.exact, case), cases=())
            ok, why = judged(formula, one)
            if not ok:
                return False, f"case {index} of {len(reference.cases)}: {why}"
        return True, f"{why}, in each of {len(reference.cases)} cases"
    if reference.conditions:
        pairs = zip(formula.equations, reference.conditions, strict=False)
        shifted = [(l, r if c is None or l is None else r + c) for (l, r), c in pairs]
        formula = Formula(formula.source, (*shifted, *formula.equations[len(shifted) :]))
    for lhs, rhs in formula.equations:
        if lhs is None and _is_inequality(rhs):
            ok, why = inequality_holds(rhs, reference)
            if not ok:
                return False, f"{rhs}: {why}"
    return formula_passes(formula, reference)


def _in_case(exact: Mapping[str, Any], case: Mapping[str, Any]) -> dict[str, Any]:
    """``exact`` with the case's values substituted into its expressions, and the case's."""
    import sympy as sp

    def at(value: Any) -> Any:
        if not isinstance(value, sp.Basic):
            return value
        names = {s.name: s for s in value.free_symbols}
        return value.subs({names[n]: v for n, v in case.items() if n in names}, simultaneous=True)

    return {**{k: at(v) for k, v in exact.items()}, **case}


def _is_inequality(expr: Any) -> bool:
    import sympy as sp

    return isinstance(expr, (sp.StrictLessThan, sp.LessThan, sp.StrictGreaterThan, sp.GreaterThan))


def inequality_holds(relation: Any, reference: Reference) -> tuple[bool, str]:
    """``a < b`` (``<=``, ``>``, ``>=``) under the reference, at random rational points of the
    reference's ``domain`` (30 digits): a strict one must hold by more than the engine's
    tolerance. A symbol the reference neither gives nor bounds leaves it undetermined (it
    does not hold): an inequality is true only over the range its reference states."""
    import sympy as sp

    less = relation.rel_op in ("<", "<=")
    small, big = (relation.lhs, relation.rhs) if less else (relation.rhs, relation.lhs)
    expr = big - small  # the claim: expr > 0 (strict) or >= 0
    if reference.transform is not None:
        expr = reference.transform(expr)
    if reference.rates:
        expr = _along_the_rates(expr, reference.rates)
    names = {s.name: s for s in expr.free_symbols}
    exact = {names[n]: v for n, v in reference.exact.items() if n in names}
    expr = _functions_replaced(expr.subs(exact, simultaneous=True), reference)
    expr = expr.replace(lambda e: isinstance(e, sp.Derivative), lambda e: e.doit())
    free = sorted(expr.free_symbols, key=lambda s: s.name)
    unbounded = [s.name for s in free if s.name not in reference.domain]
    if unbounded:
        return False, f"undetermined: the reference fixes no value or range of {unbounded}"
    generator = random.Random(19)
    tolerance = sp.Float(10) ** (5 - _DIGITS)
    strict = relation.rel_op in ("<", ">")
    for _ in range(POINTS):
        point = {}
        for s in free:
            low, high = reference.domain[s.name]
            point[s] = low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)
        value = sp.N(_integrals_by_quadrature(expr.subs(point)), _DIGITS + 10)
        shown = ", ".join(f"{k}={v}" for k, v in point.items()) or "the reference's values"
        if not value.is_number or not value.is_real:
            return False, f"not a real number at {shown}"
        if value < tolerance if strict else value < -tolerance:
            return False, f"the margin is {sp.N(value, 6)} at {shown}"
    return True, "the inequality holds" + (f" at {POINTS} random points" if free else "")
