"""Statuses computed from the printed form: a row's ``printed`` formula judged, by the kind
of check the row declares (:mod:`pendcli.verify.check_kinds`), against its reference.

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

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from pendcli.data.printed import ELLIPSIS, Formula
from pendcli.verify.derived import (
    Derived,
    Item,
    item_passes,
    passes,
    stored_text,
    truncated,
)
from pendcli.verify.point_values import DIGITS
from pendcli.verify.series_proof import cauchy_applies, in_root

__all__ = ["Reference", "derive", "derive_formula", "formula_passes", "is_relation", "judged"]


@dataclass(frozen=True)
class Reference:
    """Symbol name -> exact sympy expression (a declared function's name -> a callable of its
    arguments, e.g. a ``sympy.Lambda``). A paper's builder gives the model (``exact``,
    ``rates``, ``transform``, ``reading``, computed ``each_case`` or ``conditions``); the
    kind's parameters below are the ledger row's keys, put in by
    :func:`pendcli.verify.check_kinds.with_parameters`. ``scale``/``order``: compare a
    truncated series (the residual's series in ``scale`` must vanish through
    ``scale**(order - 1)``);
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
    return passes(derive_formula(formula, reference))


def derive_formula(formula: Formula, reference: Reference, where: str = "") -> Derived:
    """The items of ``formula`` under ``reference`` (verify/derived), each failure prefixed by
    ``where`` (a case's number)."""
    items = []
    for index, (lhs, rhs) in enumerate(formula.equations):
        against = reference.cases[index] if index < len(reference.cases) else reference
        if lhs is None:
            if not is_relation(rhs):  # a bare expression: no claim the engine could judge
                why = "neither an equation nor a relation, nothing to judge"
                items.append(Item("refused", f"{where}{rhs}", why=why))
            else:
                items.append(_relation_item(rhs, against, f"{where}{rhs}"))
            continue
        order = against.orders.get(getattr(lhs, "name", ""), against.order)
        named = f"{where}{lhs} = {rhs}"
        if against.bounded and against.scale is not None:
            items.append(_item("bounded", named, _substituted(lhs - rhs, against), against))
        elif against.rounded and _decimals(lhs - rhs):
            items.append(_rounded_item(lhs - rhs, against, order, formula.source, named))
        else:
            expr = _substituted(lhs - rhs, against)
            items.append(_item("equation", named, expr, against, order))
    holds = "every equation holds" + (f" against {reference.what}" if reference.what else "")
    return Derived(tuple(items), holds)


def _item(call: str, where: str, expr: Any, reference: Reference, order: int | None = None) -> Item:
    scale = reference.scale if call == "bounded" or order is not None else None
    if call == "equation" and scale is not None and order is not None:
        return _series_item(where, expr, reference, order)
    return Item(call, where, expr, scale, order, dict(reference.domain))


def _series_item(where: str, expr: Any, reference: Reference, order: int) -> Item:
    """A series residual; one Cauchy's integral cannot judge (an integral in it, a branch it
    cannot follow) is truncated by sympy here, once, and judged as an identity: the same
    verdict as truncating when judged, paid when derived."""
    import sympy as sp

    domain = dict(reference.domain)
    if cauchy_applies(expr, reference):
        rooted = in_root(expr, reference)
        if rooted is None:
            return Item("equation", where, expr, reference.scale, order, domain)
        in_t, _, branch = rooted  # for float64 only: the exact engine rewrites it alike
        text = stored_text(in_t)
        return Item("equation", where, expr, reference.scale, order, domain, rooted=(text, branch))
    try:
        expr = truncated(expr, reference.scale, order)
    except (sp.PoleError, NotImplementedError):  # the verdict says so, when judged
        return Item("equation", where, expr, reference.scale, order, domain)
    return Item("equation", where, expr, None, None, domain)


def _relation_item(relation: Any, reference: Reference, where: str) -> Item:
    """A printed inequality's margin, the greater side less the lesser, substituted as an
    equation's residual (and truncated, in a series' reference)."""
    gap = _substituted(relation.gts - relation.lts, reference)
    if reference.scale is not None and reference.order is not None:
        gap = truncated(gap, reference.scale, reference.order)
    strict = relation.rel_op in ("<", ">")
    return Item("relation", where, gap, None, None, dict(reference.domain), strict)


def _rounded_item(
    residual: Any, reference: Reference, order: int | None, source: str, where: str
) -> Item:
    def live() -> tuple[bool, str]:
        return _rounded_passes(residual, reference, order, source)

    return Item("rounded", where, live=live)


def _substituted(residual: Any, reference: Reference) -> Any:
    """``residual`` with « … » set to 0, the reference's transform, rates and values put in
    and its derivatives taken: the residual an item carries (verify/derived)."""
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

    from pendcli.base.errors import PendcliError

    names = Counter(s.name for s in expr.free_symbols)
    clashes = sorted(n for n, count in names.items() if count > 1)
    if clashes:
        raise PendcliError(
            f"the symbol(s) {', '.join(clashes)} enter twice with different assumptions: a "
            "reference's symbols must be the ledger's (pendcli.data.printed.ledger_symbols)"
        )


def is_relation(expr: Any) -> bool:
    from sympy.core.relational import Relational

    return isinstance(expr, Relational) and not expr.is_Equality


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
    expr = _substituted(needed - value, reference)
    ok, why = item_passes(_item("equation", "", expr, reference, order))
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
        expr = truncated(expr, reference.scale, order)
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
    return passes(derive(formula, reference))


def derive(formula: Formula, reference: Reference) -> Derived:
    """The items :func:`judged` judges: the formula's, in each of the reference's
    ``each_case`` in turn (a failure names its case), its ``conditions`` added."""
    from dataclasses import replace

    if reference.each_case:
        items: list[Item] = []
        holds = ""
        count = len(reference.each_case)
        for index, case in enumerate(reference.each_case, 1):
            one = replace(reference, exact=_in_case(reference.exact, case), each_case=())
            derived = _derive_one(formula, one, f"case {index} of {count}: ")
            items.extend(derived.items)
            holds = derived.holds
        return Derived(tuple(items), f"{holds}, in each of {count} cases")
    return _derive_one(formula, reference, "")


def _derive_one(formula: Formula, reference: Reference, where: str) -> Derived:
    if reference.conditions:
        pairs = zip(formula.equations, reference.conditions, strict=False)
        shifted = [(l, r if c is None or l is None else r + c) for (l, r), c in pairs]
        formula = Formula(formula.source, (*shifted, *formula.equations[len(shifted) :]))
    return derive_formula(formula, reference, where)


def _in_case(exact: Mapping[str, Any], case: Mapping[str, Any]) -> dict[str, Any]:
    """``exact`` with the case's values substituted into its expressions, and the case's."""
    import sympy as sp

    def at(value: Any) -> Any:
        if not isinstance(value, sp.Basic):
            return value
        names = {s.name: s for s in value.free_symbols}
        return value.subs({names[n]: v for n, v in case.items() if n in names}, simultaneous=True)

    return {**{k: at(v) for k, v in exact.items()}, **case}
