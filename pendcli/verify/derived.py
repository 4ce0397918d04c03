"""What the engine judges, once the reference is put in: a formula's items, and their verdicts.

Judging a printed formula against its reference is two steps. The *derivation*
(:func:`pendcli.verify.printed_check.derive`) is the exact symbolic work: each equation's
residual and each inequality's margin, the reference's expressions, transforms and rates put
in, its cases spelled out. Its result is a :class:`Derived`: the items to judge, in the
order the formula prints them, and what to say when every one passes. The *verdict*
(:func:`passes`) evaluates the items: the formula passes when every item does, and fails
with the first that does not.

A derivation is data (``tables/derivations/<paper>.json``, written by ``make
regen`` and read back without evaluating anything: :mod:`pendcli.verify.derivation_store`),
so that a cold run judges without building a reference; ``pendcli check`` derives them
again and fails on any difference.

Each item is judged first in float64 (:mod:`pendcli.verify.float_verdict`), which decides
only when its margin is wide, and otherwise by the exact engine: mpmath at ``DIGITS`` digits
at random rational points (:mod:`pendcli.verify.point_values`), Cauchy's integral for a series
(:mod:`pendcli.verify.series_proof`), sympy where neither decides.
"""

from __future__ import annotations

import random
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any, Protocol

from pendcli.verify.point_values import DIGITS, RELATION_POINTS, evaluator, vanishes_at_points
from pendcli.verify.series_proof import taylor_verdict

if TYPE_CHECKING:
    from pendcli.data.stored_expr import StoredExpr

__all__ = [
    "CALLS",
    "RELATION_POINTS",
    "Derived",
    "Item",
    "StoredRowFields",
    "derived_once",
    "item_passes",
    "passes",
    "stored_text",
    "truncated",
]

# what an item asks: an equation's residual vanishes (to an order, in a scale); a relation's
# margin has its sign; a residual stays finite as the scale tends to 0+; a rounded decimal
# stands for a constant (judged by a closure of the live reference: never stored); an item
# refused before any evaluation (a bare expression: nothing to judge)
CALLS = ("equation", "relation", "bounded", "rounded", "refused")


@dataclass(frozen=True)
class Item:
    """One claim of a formula, the reference put in. ``where``: what a failure names first
    (``lhs = rhs``, ``case 2 of 3: …``); ``residual``: the residual (equation, bounded) or the
    greater side less the lesser (relation), as derived, or ``text``, the same as the store
    keeps it (sympy's srepr, read when :attr:`expr` is first wanted); ``scale``, ``order``,
    ``domain``: as the reference's (a series' variable, the order it is compared through,
    each symbol's range for the random points); ``strict``: a relation's ``<``/``>``;
    ``why``: a refused item's reason; ``live``: a rounded item's verdict, computed from the
    live reference; ``rooted``: a series in a root t of its scale, its residual in t and the
    root's degree (what float64 expands; the exact engine rewrites ``expr`` alike);
    ``taylor``, ``limit``: derived once (:func:`derived_once`) where float64 cannot follow the
    residual itself, as the store keeps them (each stored text, a node of the store's table
    when read back): a series' terms below its order, a bounded
    residual's limit as the scale tends to 0+ (what float64 judges instead; never the exact
    engine)."""

    call: str
    where: str
    residual: Any = None
    scale: Any = None
    order: int | None = None
    domain: Mapping[str, tuple[Any, Any]] = field(default_factory=dict)
    strict: bool = False
    why: str = ""
    live: Callable[[], tuple[bool, str]] | None = field(default=None, compare=False)
    text: str | StoredExpr | None = None
    # a series entering through s**(p/q): (the residual in t = s**(1/q), as srepr; q)
    rooted: tuple[str | StoredExpr, int] | None = None
    taylor: str | StoredExpr | None = None
    limit: str | StoredExpr | None = None

    def __post_init__(self) -> None:
        if self.call not in CALLS:
            raise ValueError(f"unknown item call {self.call!r}; valid: {', '.join(CALLS)}")

    @cached_property
    def expr(self) -> Any:
        """The residual as a sympy expression (read from :attr:`text` the first time)."""
        if self.residual is not None or self.text is None:
            return self.residual
        if not isinstance(self.text, str):
            return self.text.expr()
        from pendcli.data.stored_expr import read_expr

        return read_expr(self.where, self.text)

    @cached_property
    def source(self) -> str | StoredExpr | None:
        """The residual as the store keeps it (a node of its table) or writes it (sympy's
        srepr), None without one."""
        if self.text is not None or self.residual is None:
            return self.text
        return stored_text(self.residual)


def stored_text(expr: Any) -> str:
    """``expr`` as the store writes it: sympy's srepr, its dummies numbered 1, 2, … in order
    of appearance (a dummy's index is a counter of the process, and the store must not
    change with it)."""
    import re

    import sympy as sp

    text = str(sp.srepr(sp.sympify(expr, strict=True)))

    numbers: dict[str, str] = {}

    def renumbered(match: re.Match[str]) -> str:
        return f"dummy_index={numbers.setdefault(match.group(1), str(len(numbers) + 1))}"

    return re.sub(r"dummy_index=(\d+)", renumbered, text)


class StoredRowFields(Protocol):
    """What a row's store entry is keyed on (a ledger row has them): its forms as read through
    the paper's reading table, its reference and its kind."""

    @property
    def reference(self) -> str | None: ...
    @property
    def kind(self) -> str | None: ...
    def read(self, name: str) -> str | None: ...


@dataclass(frozen=True)
class Derived:
    """A formula's items, in order, and why it holds when every item passes."""

    items: tuple[Item, ...]
    holds: str


def passes(derived: Derived) -> tuple[bool, str]:
    """Whether every item passes, and, if not, the first failure, named by its ``where``."""
    for item in derived.items:
        ok, why = item_passes(item)
        if not ok:
            return False, f"{item.where}: {why}"
    return True, derived.holds


def item_passes(item: Item) -> tuple[bool, str]:
    """One item's verdict, float64 first where its margin is wide (verify/float_verdict)."""
    from pendcli.verify.float_verdict import quick_verdict

    if item.call == "refused":
        return False, item.why
    if item.call == "rounded":
        assert item.live is not None, "a rounded item is judged from its live reference"
        return item.live()
    quick = quick_verdict(item)
    if quick is not None:
        return quick
    if item.call == "relation":
        return _relation_passes(item)
    if item.call == "bounded":
        return _bounded_passes(item)
    return _equation_passes(item)


def _equation_passes(item: Item) -> tuple[bool, str]:
    import sympy as sp

    expr, order = item.expr, item.order
    if item.scale is not None and order is not None:
        proved, why = taylor_verdict(expr, item, order)
        if proved is not None:
            return proved, why
        try:
            expr = truncated(expr, item.scale, order)
        except (sp.PoleError, NotImplementedError) as exc:  # sin(1/p): no series about 0
            return False, (
                f"the residual has no power series in {item.scale} about 0 that sympy can "
                f"find ({type(exc).__name__}), so it is not shown to vanish to order {order}"
            )
    # The random points first: cheap, and decisive when the residual is not 0; simplify only
    # where a point gives no number. An integral is never simplified (sympy's antiderivatives
    # can take minutes).
    ok, why = vanishes_at_points(expr, item)
    if ok or "not a number" not in why or expr.has(sp.Integral):
        return ok, why
    return (True, "simplifies to 0") if sp.simplify(expr) == 0 else (False, why)


def relation_points(item: Item) -> list[dict[Any, Any]] | str:
    """The random rational points a relation is judged at (seeded: every run the same), or
    why it cannot be: a symbol the reference neither gives nor bounds leaves it undetermined
    (an inequality, unlike an identity, is true only over the range its reference states)."""
    import sympy as sp

    free = sorted(item.expr.free_symbols, key=lambda s: s.name)
    unbounded = [s.name for s in free if s.name not in item.domain]
    if unbounded:
        return f"undetermined: the reference fixes no value or range of {unbounded}"
    generator = random.Random(19)
    points = []
    for _ in range(RELATION_POINTS if free else 1):
        point = {}
        for s in free:
            low, high = item.domain[s.name]
            point[s] = low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)
        points.append(point)
    return points


def _relation_passes(item: Item) -> tuple[bool, str]:
    """A printed inequality (``a > b``, ``a >= b``, ``<``, ``<=``: a sign, « toujours
    positive », « diminuée »): its margin at :data:`RELATION_POINTS` random rational points
    of the reference's ``domain`` (30 digits); a strict one must hold by more than the
    engine's tolerance, a wide one fall short of 0 by no more. An inequality false on a
    share f of its domain passes with chance (1 - f)**RELATION_POINTS (0.03 for f = 0.1).
    A point where float64 alone shows the margin positive, well above the tolerance, is not
    computed again (verify/float_verdict.certain_margins)."""
    import sympy as sp

    from pendcli.verify.float_verdict import certain_margins

    points = relation_points(item)
    if isinstance(points, str):
        return False, points
    tolerance = sp.Float(10) ** (5 - DIGITS)
    shown_positive = certain_margins(item, points, float(tolerance))
    at = None
    for index, point in enumerate(points):
        if index in shown_positive:
            continue
        if at is None:
            at = evaluator(item.expr, sorted(item.expr.free_symbols, key=lambda s: s.name))
        value = at(point)
        shown = ", ".join(f"{k}={v}" for k, v in point.items()) or "the reference's values"
        if not value.is_number or not value.is_real:
            return False, f"not a real number at {shown}"
        if value < tolerance if item.strict else value < -tolerance:
            return False, f"the margin is {sp.N(value, 6)} at {shown}"
    free = item.expr.free_symbols
    return True, "the inequality holds" + (f" at {RELATION_POINTS} random points" if free else "")


def _bounded_passes(item: Item) -> tuple[bool, str]:
    """The residual's limit as the scale tends to 0+ is finite (proved by
    :func:`~pendcli.verify.series_proof.finite_limit` by Cauchy's integral, else sympy's
    limit), at ``POINTS`` random rational values of the other symbols."""
    import sympy as sp

    from pendcli.verify.point_values import POINTS
    from pendcli.verify.series_proof import finite_limit

    expr, scale = item.expr, item.scale
    generator = random.Random(19)
    others = sorted(expr.free_symbols - {scale}, key=lambda s: s.name)
    limit, shown = None, ""
    for _ in range(POINTS if others else 1):
        point = {}
        for s in others:
            low, high = item.domain.get(s.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
            point[s] = low + (high - low) * sp.Rational(generator.randint(1, 999), 1000)
        at_point = expr.subs(point)  # once: Cauchy's proof, then sympy's limit if need be
        limit = finite_limit(at_point, scale)
        if limit is None:
            limit = sp.limit(at_point, scale, 0, "+")
        shown = ", ".join(f"{k}={v}" for k, v in point.items())
        if not limit.is_finite:
            return False, f"the residual tends to {limit} as {scale} -> 0+ at {shown}"
    where = f" at {POINTS} points, the last {shown}" if others else ""
    return True, f"finite as {scale} -> 0+ (limit {sp.N(limit, 6)}{where})"


def derived_once(item: Item) -> dict[str, str]:
    """What the store keeps beside an item's residual for float64, derived here (``make
    regen``) and again by ``pendcli check``: where the exact engine's Cauchy integral decides
    nothing about a series (a branch, a singularity that overflows the circle), the
    residual's terms below the order (``taylor``, sympy's series: what the exact engine then
    truncates it to); for a bounded residual, its limit as the scale tends to 0+ (``limit``,
    sympy's limit with the other symbols free). Empty where sympy gives neither. Nothing here
    depends on float64 (whose rounding may differ between machines): the store is the same
    wherever it is derived."""
    import sympy as sp

    expr, scale, order = item.expr, item.scale, item.order
    if item.call == "equation" and scale is not None and order is not None:
        if taylor_verdict(expr, item, order)[0] is not None:
            return {}
        try:
            return {"taylor": stored_text(truncated(expr, scale, order))}
        except (sp.PoleError, NotImplementedError, ValueError):
            return {}
    if item.call == "bounded" and expr is not None:
        try:
            return {"limit": stored_text(sp.limit(expr, scale, 0, "+"))}
        except (sp.PoleError, NotImplementedError, ValueError):
            return {}
    return {}


def truncated(expr: Any, scale: Any, order: int) -> Any:
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
