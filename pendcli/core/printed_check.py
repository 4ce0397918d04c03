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

import itertools
import random
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from pendcli.core.printed import ELLIPSIS, Formula
from pendcli.core.recent import Recent

__all__ = ["Reference", "computed_status", "formula_passes", "is_relation", "judged"]

POINTS = 3  # random rational points tried when sympy cannot simplify a residual to 0
# an inequality's points: it may fail on a part of its domain only, which few points miss
RELATION_POINTS = 32
_DIGITS = 20
# samples on the circle of _cauchy_verdict: the error goes as (radius / distance to the
# nearest singularity)**_CIRCLE_POINTS
_CIRCLE_POINTS = 64


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
        proved, why = _taylor_verdict(expr, reference, order)
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
    ok, why = _vanishes_at_points(expr, reference)
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
    tolerance = sp.Float(10) ** (5 - _DIGITS)
    strict = relation.rel_op in ("<", ">")
    at = _evaluator(gap, free)
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
    by :func:`_finite_limit` by Cauchy's integral, else sympy's limit), at :data:`POINTS`
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
        limit = _finite_limit(expr.subs(point), reference.scale)
        if limit is None:
            limit = sp.limit(expr.subs(point), reference.scale, 0, "+")
        shown = ", ".join(f"{k}={v}" for k, v in point.items())
        if not limit.is_finite:
            return False, f"the residual tends to {limit} as {reference.scale} -> 0+ at {shown}"
    where = f" at {POINTS} points, the last {shown}" if others else ""
    return True, f"finite as {reference.scale} -> 0+ (limit {sp.N(limit, 6)}{where})"


def _finite_limit(expr: Any, scale: Any) -> Any:
    """The limit of ``expr`` (a number but for ``scale``) as the scale tends to 0+, proved
    finite by Cauchy's integral, or None (decides nothing; sympy's limit then judges). Each
    log(scale**p R) is p log(scale) + log(R) (scale > 0), so that ``expr`` = P + Q log(scale)
    with P, Q Laurent series in a root t of the scale: t**j log(t) outgrows t**j and is
    outgrown by t**(j-1), so the sum is finite at 0+ exactly when P has no negative power
    and Q no power up to t**0; the limit is then P's constant term."""
    import mpmath
    import sympy as sp

    logarithm = sp.Dummy("log_scale")
    if expr.has(sp.Integral, sp.Derivative, sp.Subs):
        return None
    split = expr.replace(
        lambda e: isinstance(e, sp.log) and e.has(scale), lambda e: _log_split(e, scale, logarithm)
    )
    if split.has(sp.log(scale)) or sp.diff(split, logarithm, 2) != 0:
        return None
    rest, slope = split.subs(logarithm, 0), sp.diff(split, logarithm)
    value: Any = None
    for part, order in ((rest, 0), (slope, 1)):
        in_root = _meromorphic_in_root(part, scale, positive=True)
        if in_root is None or in_root[0].free_symbols - {in_root[1]}:
            return None
        sums = _laurent_sums(in_root[0], in_root[1])
        if sums is None:
            return None
        with mpmath.workdps(3 * _DIGITS + 10):
            one, tolerance = mpmath.mpf(1), mpmath.mpf(10) ** (-2 * _DIGITS)
            if _lowest_failing(sums, order, one, one, tolerance) is not None:
                return None
            if order == 0:  # P's constant term: the limit, once Q (the next part) is proved
                value = sums[0] / len(sums)
    if abs(mpmath.im(value)) > _CONVERGED * max(abs(value), 1):
        return None
    return sp.Float(mpmath.re(value), 3 * _DIGITS)


def _log_split(log: Any, scale: Any, logarithm: Any) -> Any:
    """log(scale**p R) -> p logarithm + log(R) (unchanged when R holds the scale)."""
    import sympy as sp

    power, others = sp.Integer(0), []
    for factor in sp.Mul.make_args(log.args[0]):
        base, exponent = factor.as_base_exp()
        if base == scale and exponent.is_Rational:
            power += exponent
        elif factor.has(scale):
            return log
        else:
            others.append(factor)
    return power * logarithm + sp.log(sp.Mul(*others))


def _laurent_sums(expr: Any, variable: Any) -> list[Any] | None:
    """The Cauchy sums of ``expr`` (a function of ``variable`` alone) on the circle of
    :func:`_cauchy_verdict`, the whole circle sampled (None: no number there)."""
    import mpmath

    try:
        function = _compiled((variable,), expr)
    except (SyntaxError, TypeError, ValueError, NameError):
        return None
    with mpmath.workdps(3 * _DIGITS + 10):
        count = _CIRCLE_POINTS
        roots = _unit_roots(count)
        try:
            sums = _fourier(_circle_samples(function, mpmath.mpf(1) / 100, roots, [], False), roots)
        except (ArithmeticError, TypeError, ValueError, NameError, AttributeError):
            return None
        if not all(mpmath.isfinite(v) for v in sums):
            return None
        # the terms about count/2 small (no singularity near the circle but the one at 0),
        # or all of them rounding (the expression is 0 to the working precision)
        tail = _aliased_tail(sums)
        peak = max(abs(v) for v in sums)
        return sums if tail < _CONVERGED * peak or peak < 10 ** -(3 * _DIGITS) else None


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
    value = sp.N(expr.subs(middle), _DIGITS)
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


def _taylor_verdict(expr: Any, reference: Reference, order: int) -> tuple[bool | None, str]:
    """A quick proof that the series of ``expr`` in the scale vanishes below ``order`` (its
    Laurent coefficients: sympy's series keeps a pole's terms too) at random rational values
    of the other symbols: each coefficient by Cauchy's integral on a small circle about 0
    (the trapezoidal rule, exact far beyond 20 digits for a function analytic on the circle;
    a removable singularity at 0 costs nothing), every term bounded over the scale's domain
    by 10**-(2 * digits). A scale that enters through powers s**(p/q) (a branch point at 0)
    is s = t**q, t > 0: a Puiseux series in s is a Laurent series in t, its terms below
    s**order those below t**(q * order). (True, why): proved; (False, why): a coefficient
    below the order is decisively not 0 (:func:`_cauchy_verdict`); (None, ""): decides
    nothing, ``expr`` is then truncated by sympy and judged at the points as before."""
    import sympy as sp

    scale = reference.scale
    low, high = reference.domain.get(scale.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
    if expr.has(sp.Integral, sp.Derivative, sp.Subs) or not all(
        isinstance(sp.sympify(b, strict=True), sp.Rational) for b in (low, high)
    ):
        return None, ""
    in_root = _meromorphic_in_root(expr, scale, positive=sp.sympify(low, strict=True) > 0)
    if in_root is None:
        return None, ""
    variable, branch = in_root[1:]
    return _cauchy_verdict(in_root[0], reference, branch * order, variable, branch)


def _meromorphic_in_root(expr: Any, scale: Any, positive: bool) -> tuple[Any, Any, int] | None:
    """(``expr`` in t, t, q) with scale = t**q (t > 0 when q > 1: a ``positive`` scale) and
    ``expr`` in t analytic about 0 but for a pole (:func:`_analytic_at_zero`); None if not."""
    import sympy as sp

    if _analytic_at_zero(expr, scale):
        return expr, scale, 1
    branch = _branch_denominator(expr, scale)
    if branch is None or not positive:
        return None
    root = sp.Dummy("root", positive=True)  # s = root**branch over the scale's domain s > 0
    in_root = expr.subs(scale, root**branch)
    # a root's base expanded: (t**2 b (c + d/(t**2 b)))**2 is 0 * zoo at t = 0, its expansion
    # a polynomial in t whose value at 0 says whether the root branches there
    in_root = in_root.replace(
        lambda e: e.is_Pow and not e.exp.is_Integer and e.base.has(root),
        lambda e: sp.expand(e.base) ** e.exp,
    )
    return (in_root, root, branch) if _analytic_at_zero(in_root, root) else None


def _branch_denominator(expr: Any, scale: Any) -> int | None:
    """The least q such that every power of ``expr`` with a base 0 at scale = 0 has an
    exponent in (1/q)Z (None: an exponent not rational, or none fractional)."""
    import math

    import sympy as sp

    denominators = []
    for node in sp.preorder_traversal(expr):
        if isinstance(node, sp.Pow) and node.has(scale) and not node.exp.is_Integer:
            if not node.exp.is_Rational:
                return None
            if node.base.subs(scale, 0) == 0:
                denominators.append(int(node.exp.q))
    return math.lcm(*denominators) if denominators else None


def _cauchy_verdict(
    expr: Any, reference: Reference, order: int, variable: Any, branch: int
) -> tuple[bool | None, str]:
    """:func:`_taylor_verdict` in ``variable`` (the scale, or its ``branch``-th root), whose
    domain is the scale's domain's ``branch``-th root."""
    import mpmath
    import sympy as sp

    count = _CIRCLE_POINTS
    if order >= count // 2:
        return None, ""
    free = sorted(expr.free_symbols - {variable}, key=lambda s: s.name)
    try:
        function = _compiled((variable, *free), expr)
    except (SyntaxError, TypeError, ValueError, NameError):
        return None, ""
    generator = random.Random(23)
    scale = reference.scale
    bounds = reference.domain.get(scale.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
    with mpmath.workdps(3 * _DIGITS + 10):
        radius, tolerance = mpmath.mpf(1) / 100, mpmath.mpf(10) ** (-2 * _DIGITS)
        # a_j = c_j radius**j; the term c_j t**j is at most |a_j| (t / radius)**j on the domain
        ends = [mpmath.root(abs(mpmath.mpf(b.p) / b.q), branch) for b in map(sp.Rational, bounds)]
        far, near = max(ends) / radius, min(ends) / radius
        roots = _unit_roots(count)
        real = not expr.has(sp.I)
        for _ in range(POINTS):
            values = [_random_value(generator, reference, s) for s in free]
            if not all(isinstance(q, sp.Rational) for q in values):
                return None, ""
            args = [mpmath.mpf(q.p) / q.q for q in values]
            try:
                # sums[j % count] = sum_k samples[k] roots[k]**-j, all j at once
                samples = _circle_samples(function, radius, roots, args, real)
                sums = _fourier(samples, roots)
                failing = _lowest_failing(sums, order, far, near, tolerance)
                if failing is not None and real:  # judged again on the whole circle
                    samples = _circle_samples(function, radius, roots, args, False)
                    sums = _fourier(samples, roots)
                    failing = _lowest_failing(sums, order, far, near, tolerance)
            except (ArithmeticError, TypeError, ValueError, NameError, AttributeError):
                return None, ""
            if failing is None:
                continue
            if expr.has(sp.Float) or not _decisive(samples, sums, failing):
                return None, ""
            shown = ", ".join(f"{s}={q}" for s, q in zip(free, values, strict=True))
            value = sums[failing % count] / count / radius**failing
            if abs(mpmath.im(value)) < _CONVERGED * abs(value):  # rounding's imaginary part
                value = mpmath.re(value)
            power = sp.Rational(failing, branch)
            where = f" at {shown}" if shown else ""
            return False, f"the coefficient of {scale}**{power} is {mpmath.nstr(value, 6)}{where}"
    return True, f"vanishes at {POINTS} random rational points"


def _lowest_failing(sums: list[Any], order: int, far: Any, near: Any, tolerance: Any) -> Any:
    """The lowest power j < ``order`` whose Cauchy coefficient is not below the tolerance
    (-count/2 for one that is no number), or None."""
    import mpmath

    count = len(sums)
    for j in range(-(count // 2), order):
        a = abs(sums[j % count])
        bound = far ** (-j) if j >= 0 else min(near, 1) ** (-j)
        if not mpmath.isfinite(a):
            return -(count // 2)
        if a / count > tolerance * bound:
            return j
    return None


# A coefficient of an exact residual (no decimal: a 20-digit Float leaves noise at 1e-20
# that the points' tolerance forgives) is decisively not 0 when it exceeds _DECISIVE times
# the largest sample on the circle while the coefficients about count/2 (what the
# trapezoidal rule aliases onto the low ones) are below _CONVERGED times it: far above
# the aliasing, the working precision's rounding and the points' relative tolerance.
_DECISIVE, _CONVERGED = 1e-10, 1e-24


def _aliased_tail(sums: list[Any]) -> Any:
    """The largest Cauchy sum about count/2: what the trapezoidal rule aliases onto the low
    coefficients, small once the circle has converged."""
    count = len(sums)
    return max(abs(sums[j % count]) for j in range(count // 2 - 4, count // 2 + 5))


def _decisive(samples: list[Any], sums: list[Any], power: int) -> bool:
    import mpmath

    count = len(samples)
    peak = max(abs(v) for v in samples)
    if not mpmath.isfinite(peak) or peak == 0:
        return False
    tail = _aliased_tail(sums) / count
    return tail < _CONVERGED * peak and abs(sums[power % count]) / count > _DECISIVE * peak


def _circle_samples(
    function: Callable[..., Any], radius: Any, roots: list[Any], args: list[Any], real: bool
) -> list[Any]:
    """``function(radius * w, *args)`` at each root of unity ``w``. A ``real`` expression
    (no I in it) whose values at ±radius are real is taken to have real coefficients: its
    lower half circle is the conjugate of its upper (f(z̄) = f(z)‾), half the evaluations.
    Were the coefficients not real, the mirrored samples would jump across the real axis
    and their low coefficients would not vanish: the proof then fails, never passes."""
    import mpmath

    half = len(roots) // 2
    upper = [function(radius * w, *args) for w in roots[: half + 1]]
    if real and mpmath.im(upper[0]) == 0 and mpmath.im(upper[half]) == 0:
        return upper + [mpmath.conj(v) for v in reversed(upper[1:half])]
    return upper + [function(radius * w, *args) for w in roots[half + 1 :]]


def _unit_roots(count: int) -> list[Any]:
    """The ``count``-th roots of unity at the working precision: the circle's directions."""
    import mpmath

    return [mpmath.expjpi(mpmath.mpf(2 * k) / count) for k in range(count)]


def _fourier(samples: list[Any], roots: list[Any]) -> list[Any]:
    """The discrete Fourier transform ``X[j] = sum_k samples[k] * roots[k]**-j`` (``roots``:
    the len(samples)-th roots of unity, a power of two of them) by the radix-2 FFT: the
    Cauchy coefficients of :func:`_cauchy_verdict` in n log n products, not n² of them."""
    count = len(samples)
    if count == 1:
        return list(samples)
    even = _fourier(samples[0::2], roots[0::2])
    odd = _fourier(samples[1::2], roots[0::2])
    half = count // 2
    turned = [odd[j] * roots[-j % count] for j in range(half)]
    return [even[j] + turned[j] for j in range(half)] + [even[j] - turned[j] for j in range(half)]


def _random_value(generator: random.Random, reference: Reference, symbol: Any) -> Any:
    import sympy as sp

    low, high = reference.domain.get(symbol.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
    return low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)


def _analytic_at_zero(expr: Any, scale: Any) -> bool:
    """Whether every part of ``expr`` that depends on ``scale`` is a sum, a product, a power
    with a constant rational exponent (a fractional one of a base that is not 0 at 0) or a
    function analytic where it is finite, none of its branch points at 0 (Abs, Piecewise,
    an unknown function: False)."""
    import sympy as sp

    plain = (sp.Add, sp.Mul, sp.sin, sp.cos, sp.tan, sp.exp, sp.atan, sp.sinh, sp.cosh)
    for node in sp.preorder_traversal(expr):
        if node.is_Atom or not node.has(scale):
            continue
        at_zero = node.args[0].subs(scale, 0) if node.args else None
        if isinstance(node, sp.Pow):
            power = node.args[1]
            if not power.is_Rational or (not power.is_Integer and at_zero == 0):
                return False
        elif isinstance(node, sp.log):
            if at_zero == 0:
                return False
        elif isinstance(node, (sp.asin, sp.acos)):
            if at_zero in (1, -1):
                return False
        elif isinstance(node, sp.besselj):
            if not node.args[0].is_Integer:
                return False
        elif not isinstance(node, plain):
            return False
    return True


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
        if abs(value) > _FLOOR and abs(value) > _TOLERANCE * _size_at(expr, free, point, size_at):
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
    function = _compiled(tuple(free), expr)

    def by_mpmath(point: dict[Any, Any]) -> Any:
        with mpmath.workdps(_DIGITS + 10):
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


def _compiled(arguments: tuple[Any, ...], expr: Any) -> Callable[..., Any]:
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
        integrand = _compiled((variable,), integral.function)
        with mpmath.workdps(_DIGITS + 5):
            bounds = [sp.N(b, _DIGITS + 5)._to_mpmath(mpmath.mp.prec) for b in (low, high)]
            values[integral] = sp.Float(mpmath.quad(integrand, bounds), _DIGITS + 5)
    return expr.subs(values)


# The residual is refused when above _TOLERANCE relative to its size (its terms' absolute
# values summed through sums and products, at the point): 1e-15 of terms of 1e6 is
# rounding, 1e-15 of terms of 1e-12 is not. Below _FLOOR (far under the working precision's
# rounding) it is 0 whatever its terms, and the size is not computed.
_TOLERANCE = 10.0 ** (5 - _DIGITS)
_FLOOR = 10.0 ** -(_DIGITS + 8)


def _size_at(expr: Any, free: list[Any], point: dict[Any, Any], built: list[Any]) -> Any:
    """The size of ``expr`` at ``point``: the value of ``expr`` with every sum a sum of
    absolute values (ε·(a − b) has size |ε|·(|a| + |b|), the scale its cancellation is on).
    ``built``: empty, or the size's evaluator from an earlier point of the same ``expr``."""
    import sympy as sp

    if not built:
        built.append(_evaluator(_magnitude(expr), free))
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


def computed_status(
    printed: Formula, reading: Formula | None, corrected: Formula | None, reference: Reference
) -> tuple[str | None, str]:
    """The status the printed form earns (None: none the ledger may record) and why."""
    from pendcli.core.printed_numeric import Numbers, numeric_status

    if isinstance(reference, Numbers):  # printed numbers, judged by their printed digits
        return numeric_status(printed, reading, corrected, reference)
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
