"""Statuses computed from the printed form: a row's ``printed`` formula judged, by the kind
of check the row declares (:mod:`pendcli.core.check_kinds`), against its reference.

A reference (``reference = "name"`` in the row; the paper's table ``Paper.references`` maps
the name to the function that builds the :class:`Reference`) maps some of the ledger's
symbols to exact expressions: the preceding equation, the definition a formula rests on, the
exact solution; never a second copy of the printed formula. Each equation ``lhs = rhs`` of a
formula passes when ``lhs − rhs`` (with « … » set to 0), after the substitution, vanishes at
exact random rational points (evaluated to 30 digits, passing within 1e-15 of the residual's
size), or simplifies to 0 where a point gives no number; with a ``scale`` and an ``order``,
when its series in the scale vanishes below that order (an equation whose left side is a
symbol named in ``orders`` uses that order: a summary formula may carry one quantity further
than another; such a series is first judged numerically, its coefficients by Cauchy's
integral about 0 at random rational points (in a root of the scale where it enters as
s**(p/q)): proved at those points, or refused when a coefficient below the order is far from
0, and sympy's series is taken only where that decides nothing). A bare inequality (``a >
b``: a sign or a bound a sentence asserts) passes when its greater side less its lesser,
substituted alike, is ≥ -1e-15 at 32 points (strict: > 1e-15); a reference's ``cases`` judge
a formula's first equations each against its own (« pour n pair », « pour n impair »). The
status follows:

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

from pendcli.core.point_values import DIGITS, POINTS, evaluator, vanishes_at_points
from pendcli.core.printed import ELLIPSIS, Formula
from pendcli.core.series_proof import finite_limit, taylor_verdict

__all__ = ["Reference", "formula_passes", "is_relation", "judged"]

# an inequality's points: it may fail on a part of its domain only, which few points miss
RELATION_POINTS = 32


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
    ``bounded``: with a ``scale``, an equation passes when its residual stays finite as the
    scale tends to 0+ (sympy's limit, the other symbols at a random rational point): the
    text's « égal à un nombre fini augmenté de … », an expansion at a singular point whose
    growing parts (negative powers, logarithms) must agree;
    ``rounded``: the formula's decimals are the paper's roundings: an equation holding one
    decimal passes when the value that makes it hold is a constant within half a unit of
    the decimal's last printed digit (``0.13`` stands for any number in [0.125, 0.135]);
    ``cases``: the references the formula's first equations are judged against, one each
    (a formula printed « pour n pair » and « pour n impair »); a later equation, against
    this reference;
    ``each_case``: symbol name -> value maps, each added to ``exact`` in turn: the formula must
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
    rounded: bool = False
    bounded: bool = False
    cases: tuple[Reference, ...] = ()
    each_case: tuple[Mapping[str, Any], ...] = ()
    conditions: tuple[Any, ...] = ()

    def __post_init__(self) -> None:
        problem = _meaningless(self)
        if problem:
            raise ValueError(f"a reference{' for ' + self.what if self.what else ''}: {problem}")


def _meaningless(reference: Reference) -> str | None:
    """Why the reference's parameters make no kind of check (a combination the engine would
    otherwise ignore in silence), or None."""
    if reference.scale is None and (reference.order is not None or reference.orders):
        return "an order needs a scale"
    if reference.bounded and (reference.scale is None or reference.order is not None):
        return "bounded needs a scale and takes no order"
    if reference.scale is not None and not reference.bounded and reference.order is None:
        return "a scale needs an order (or bounded)"
    if reference.bounded and reference.rounded:
        return "bounded and rounded exclude each other"
    chosen = [n for n in ("cases", "each_case", "conditions") if getattr(reference, n)]
    if len(chosen) > 1:
        return f"{' and '.join(chosen)} exclude each other"
    return None


def formula_passes(formula: Formula, reference: Reference) -> tuple[bool, str]:
    """Whether every equation (and inequality) of ``formula`` holds under ``reference``, and
    why not."""
    for index, (lhs, rhs) in enumerate(formula.equations):
        against = reference.cases[index] if index < len(reference.cases) else reference
        if lhs is None:
            if not is_relation(rhs):  # a bare expression: no claim the engine could judge
                return False, f"{rhs}: neither an equation nor a relation, nothing to judge"
            ok, why = _relation_passes(rhs, against)
            if not ok:
                return False, f"{rhs}: {why}"
            continue
        order = against.orders.get(getattr(lhs, "name", ""), against.order)
        if against.bounded and against.scale is not None:
            ok, why = _bounded_passes(lhs - rhs, against)
        elif against.rounded and _decimals(lhs - rhs):
            ok, why = _rounded_passes(lhs - rhs, against, order, formula.source)
        else:
            ok, why = _equation_passes(lhs - rhs, against, order)
        if not ok:
            return False, f"{lhs} = {rhs}: {why}"
    return True, "every equation holds" + (f" against {reference.what}" if reference.what else "")


def _equation_passes(residual: Any, reference: Reference, order: int | None) -> tuple[bool, str]:
    import sympy as sp

    expr = _substituted(residual, reference)
    if reference.scale is not None and order is not None:
        proved, why = taylor_verdict(expr, reference, order)
        if proved is not None:
            return proved, why
        try:
            expr = _truncated(expr, reference.scale, order)
        except (sp.PoleError, NotImplementedError) as exc:  # sin(1/p): no series about 0
            return False, (
                f"the residual has no power series in {reference.scale} about 0 that sympy can "
                f"find ({type(exc).__name__}), so it is not shown to vanish to order {order}"
            )
    # The random points first: cheap, and decisive when the residual is not 0; simplify only
    # where a point gives no number. An integral is never simplified (sympy's antiderivatives
    # can take minutes).
    ok, why = vanishes_at_points(expr, reference)
    if ok or "not a number" not in why or expr.has(sp.Integral):
        return ok, why
    return (True, "simplifies to 0") if sp.simplify(expr) == 0 else (False, why)


def _substituted(residual: Any, reference: Reference) -> Any:
    """``residual`` with « … » set to 0, the reference's transform, rates and values put in
    and its derivatives taken: what :func:`_equation_passes` evaluates, before a series."""
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
    _refuse_clashes(expr)
    # a derivative of the reference's explicit functions is taken (integrals stay for quadrature)
    return expr.replace(lambda e: isinstance(e, sp.Derivative), lambda e: e.doit(deep=False))


def _refuse_clashes(expr: Any) -> None:
    """Two symbols of one name (the ledger's ``g`` and a reference's ``g`` made positive)
    would be two unknowns to every check: refused, naming them."""
    from collections import Counter

    from pendcli.core.errors import PendcliError

    names = Counter(s.name for s in expr.free_symbols)
    clashes = sorted(n for n, count in names.items() if count > 1)
    if clashes:
        raise PendcliError(
            f"the symbol(s) {', '.join(clashes)} enter twice with different assumptions: a "
            "reference's symbols must be the ledger's (pendcli.core.printed.ledger_symbols)"
        )


def is_relation(expr: Any) -> bool:
    from sympy.core.relational import Relational

    return isinstance(expr, Relational) and not expr.is_Equality


def _relation_passes(relation: Any, reference: Reference) -> tuple[bool, str]:
    """A printed inequality (``a > b``, ``a >= b``, ``<``, ``<=``: a sign, « toujours
    positive », « diminuée »): the greater side less the lesser, substituted as an equation's
    residual, at :data:`RELATION_POINTS` random rational points of the reference's ``domain``
    (30 digits); a strict one must hold by more than the engine's tolerance, a wide one fall
    short of 0 by no more. A symbol the reference neither gives nor bounds leaves it
    undetermined (it does not hold): an inequality, unlike an identity, is true only over the
    range its reference states. An inequality false on a share f of its domain passes with
    chance (1 - f)**RELATION_POINTS (0.03 for f = 0.1)."""
    import sympy as sp

    gap = _substituted(relation.gts - relation.lts, reference)
    if reference.scale is not None and reference.order is not None:
        gap = _truncated(gap, reference.scale, reference.order)
    free = sorted(gap.free_symbols, key=lambda s: s.name)
    unbounded = [s.name for s in free if s.name not in reference.domain]
    if unbounded:
        return False, f"undetermined: the reference fixes no value or range of {unbounded}"
    generator = random.Random(19)
    tolerance = sp.Float(10) ** (5 - DIGITS)
    strict = relation.rel_op in ("<", ">")
    at = evaluator(gap, free)
    for _ in range(RELATION_POINTS if free else 1):
        point = {}
        for s in free:
            low, high = reference.domain[s.name]
            point[s] = low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)
        value = at(point)
        shown = ", ".join(f"{k}={v}" for k, v in point.items()) or "the reference's values"
        if not value.is_number or not value.is_real:
            return False, f"not a real number at {shown}"
        if value < tolerance if strict else value < -tolerance:
            return False, f"the margin is {sp.N(value, 6)} at {shown}"
    return True, "the inequality holds" + (f" at {RELATION_POINTS} random points" if free else "")


def _bounded_passes(residual: Any, reference: Reference) -> tuple[bool, str]:
    """``reference.bounded``: the residual's limit as the scale tends to 0+ is finite (proved
    by :func:`finite_limit` by Cauchy's integral, else sympy's limit), at :data:`POINTS`
    random rational values of the other symbols."""
    import sympy as sp

    expr = _substituted(residual, reference)
    generator = random.Random(19)
    others = sorted(expr.free_symbols - {reference.scale}, key=lambda s: s.name)
    limit, shown = None, ""
    for _ in range(POINTS if others else 1):
        point = {}
        for s in others:
            low, high = reference.domain.get(s.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
            point[s] = low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)
        limit = finite_limit(expr.subs(point), reference.scale)
        if limit is None:
            limit = sp.limit(expr.subs(point), reference.scale, 0, "+")
        shown = ", ".join(f"{k}={v}" for k, v in point.items())
        if not limit.is_finite:
            return False, f"the residual tends to {limit} as {reference.scale} -> 0+ at {shown}"
    where = f" at {POINTS} points, the last {shown}" if others else ""
    return True, f"finite as {reference.scale} -> 0+ (limit {sp.N(limit, 6)}{where})"


def _decimals(expr: Any) -> set[Any]:
    import sympy as sp

    return set(expr.atoms(sp.Float))


def _rounded_passes(
    residual: Any, reference: Reference, order: int | None, source: str
) -> tuple[bool, str]:
    """An equation holding one printed decimal (``reference.rounded``): the value that makes
    it hold (it enters linearly) must be a constant within half a unit of the decimal's last
    printed digit."""
    import sympy as sp

    decimals = _decimals(residual)
    if len(decimals) != 1:
        return False, f"{len(decimals)} decimals in one equation: which is rounded is unclear"
    (printed,) = decimals
    unknown = sp.Dummy("decimal")
    linear = residual.subs(printed, unknown)
    slope = sp.diff(linear, unknown)
    if slope == 0 or slope.has(unknown):
        return False, f"the decimal {printed} does not enter linearly"
    needed = -linear.subs(unknown, 0) / slope
    value = _value_somewhere(needed, reference, order)
    if value is None:
        return False, f"the value the decimal {printed} stands for is not a number"
    ok, why = _equation_passes(needed - value, reference, order)
    if not ok:
        return False, f"the decimal {printed} stands for no constant ({why})"
    half = _half_unit(printed, source)
    shown = sp.N(value, 6)
    if abs(value - printed) > half:
        return False, f"{sp.N(printed, 6)} is not {shown} rounded (to ±{half})"
    return True, f"{sp.N(printed, 6)} is {shown} rounded"


def _value_somewhere(expr: Any, reference: Reference, order: int | None) -> Any:
    """``expr``'s value under the reference at the middle of each symbol's domain (None when
    that is no number): the constant a rounded decimal is compared with."""
    import sympy as sp

    expr = _substituted(expr, reference)
    if reference.scale is not None and order is not None:
        expr = _truncated(expr, reference.scale, order)
    middle = {}
    for s in expr.free_symbols:
        low, high = reference.domain.get(s.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
        middle[s] = (low + high) / 2
    value = sp.N(expr.subs(middle), DIGITS)
    return value if value.is_number else None


def _half_unit(decimal: Any, source: str) -> Any:
    """Half a unit of the last digit with which ``decimal`` is printed in ``source``."""
    import re

    import sympy as sp

    for token in re.findall(r"\d*\.\d+", source):
        if sp.Float(token) == abs(decimal):
            return sp.Rational(5, 10 ** (len(token.split(".")[1]) + 1))
    return sp.Rational(0)


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


# --- prose claims: each case, conditions for roots ----------------


def judged(formula: Formula, reference: Reference) -> tuple[bool, str]:
    """:func:`formula_passes`, in each of the reference's ``each_case`` (every one must pass)
    and with its ``conditions``."""
    from dataclasses import replace

    if reference.each_case:
        why = ""
        for index, case in enumerate(reference.each_case, 1):
            one = replace(reference, exact=_in_case(reference.exact, case), each_case=())
            ok, why = judged(formula, one)
            if not ok:
                return False, f"case {index} of {len(reference.each_case)}: {why}"
        return True, f"{why}, in each of {len(reference.each_case)} cases"
    if reference.conditions:
        pairs = zip(formula.equations, reference.conditions, strict=False)
        shifted = [(l, r if c is None or l is None else r + c) for (l, r), c in pairs]
        formula = Formula(formula.source, (*shifted, *formula.equations[len(shifted) :]))
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
