"""Float64 first: an item judged in double precision, decided only where its margin is wide.

An item's residual (its stored text, sympy's srepr) is compiled once to a numpy function by
walking its syntax tree (no sympy object is built, nothing is evaluated as code), together
with its *size*: the same expression with every sum a sum of absolute values, the scale of
the cancellation a vanishing residual shows. Then:

* an **identity** (an equation without an order) holds when the residual is below
  :data:`HOLDS` of its size at :data:`POINTS` random points of the domain, and fails when it is
  above :data:`FAILS` of its size at one of them, a finite real number;
* a **series** (an equation with a scale and an order) is expanded by Cauchy's integral on two
  circles about 0 (:data:`CIRCLE` samples each, the other symbols at random real points): it
  holds when every coefficient below the order contributes less than :data:`HOLDS` of the
  size on the circle, on both circles; it fails when one contributes more than :data:`FAILS`
  and the two circles give the same Laurent coefficients (the function is analytic in the
  ring between them: no branch cut, which principal-branch arithmetic would show as spurious
  coefficients);
* a **relation** (an inequality) holds when its margin clears :data:`HOLDS` of its size with
  the right sign at the engine's 32 rational points, and fails when it has the wrong sign by
  more than :data:`FAILS` of its size at one of them.

Everything between (a residual of 1e-9 of its terms, a coefficient of 1e-8, a branch, a
function float64 lacks: an integral on the complex circle, an undefined function) is
undecided, and the exact engine (mpmath at 20 digits, Cauchy at 40, sympy) judges. Float64
rounding leaves a residual near 1e-16 of its size times the depth of the expression, so
:data:`HOLDS` = 1e-14 is a margin of about 100 over rounding, and a verdict of "holds" here is
agreement to fourteen digits of the residual's terms at each point, not a proof
(``docs/ENGINE.md``). It is that fine because a slip can hide there: a printed 2 made
2.000002 inside a function stationary at that point moves the residual by 1e-12 only. The slow tests
judge every stored item both ways and require the same verdict wherever float64 decides.
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Protocol

from pendcli.base.recent import Recent
from pendcli.verify.float_compile import (
    DUMMY,
    FREE_FUNCTION,
    REAL_ONLY,
    Compiled,
    Unsupported,
    compile_expr,
)
from pendcli.verify.point_values import FLOOR, RELATION_POINTS

if TYPE_CHECKING:
    from pendcli.data.stored_expr import StoredExpr


class Item(Protocol):
    """What float64 reads of an item (:class:`pendcli.verify.derived.Item`)."""

    @property
    def call(self) -> str: ...
    @property
    def source(self) -> str | StoredExpr | None: ...
    @property
    def scale(self) -> Any: ...
    @property
    def order(self) -> int | None: ...
    @property
    def domain(self) -> Mapping[str, tuple[Any, Any]]: ...
    @property
    def rooted(self) -> tuple[str | StoredExpr, int] | None: ...
    @property
    def taylor(self) -> str | StoredExpr | None: ...
    @property
    def limit(self) -> str | StoredExpr | None: ...


__all__ = [
    "CIRCLE",
    "FAILS",
    "HOLDS",
    "POINTS",
    "certain_margins",
    "quick_verdict",
]

HOLDS = 1e-14
FAILS = 1e-6
POINTS = 8
CIRCLE = 64
_DEFAULT_DOMAIN = (Fraction(1, 10), Fraction(1, 2))

Verdict = tuple[bool, str]


def quick_verdict(item: Item) -> Verdict | None:
    """The item's verdict in float64, or None when float64 does not decide it."""
    if item.call not in ("equation", "relation", "bounded") or item.source is None:
        return None
    try:
        compiled = compile_expr(item.source)
        if item.call == "bounded":
            return _stored_limit(item, compiled)
        if item.call == "relation":
            return _relation(item, compiled)
        if item.scale is not None and item.order is not None:
            verdict = _series(item, compiled)
            return verdict if verdict is not None else _stored_series(item)
        return _identity(item, compiled)
    except (Unsupported, ArithmeticError, ValueError, TypeError, RecursionError):
        return None


# --- the points -------------------------------------------------------------------------


def _domain(item: Item, name: str) -> tuple[Fraction, Fraction]:
    if name not in item.domain:
        return _DEFAULT_DOMAIN
    low, high = item.domain[name]
    return _fraction(low), _fraction(high)


def _fraction(value: Any) -> Fraction:
    import sympy as sp

    value = sp.sympify(value, strict=True)
    if not isinstance(value, sp.Rational):
        raise Unsupported("an irrational end of a domain")
    return Fraction(int(value.p), int(value.q))


def _points(item: Item, names: list[str], count: int) -> list[dict[str, Fraction]]:
    """``count`` random rational points, drawn as the exact engine draws them (the same
    points for every item with the same symbols, domains and count: drawn once)."""
    ranges = tuple((name, _domain(item, name)) for name in names)
    key = (ranges, count)
    found: list[dict[str, Fraction]] | None = _DRAWN.get(key)
    if found is None:
        found = _drawn(ranges, count)
        _DRAWN.put(key, found)
    return [dict(point) for point in found]


# (each symbol's range, the count) -> the points drawn (seeded: the same every time)
_DRAWN = Recent(1024)


def _drawn(
    ranges: tuple[tuple[str, tuple[Fraction, Fraction]], ...], count: int
) -> list[dict[str, Fraction]]:
    generator = random.Random(19)
    out = []
    for _ in range(count):
        point = {}
        for name, (low, high) in ranges:
            point[name] = low + (high - low) * Fraction(generator.randint(1, 999), 1000)
        out.append(point)
    return out


def _shown(point: dict[str, Fraction]) -> str:
    return ", ".join(f"{k}={v}" for k, v in point.items())


def _at(point: dict[str, Fraction]) -> str:
    return f" at {_shown(point)}" if point else ""


# --- the three verdicts -----------------------------------------------------------------


def _identity(item: Item, compiled: Compiled) -> Verdict | None:
    import numpy as np

    names = sorted(compiled.names - REAL_ONLY)
    points = _points(item, names, POINTS)
    env = {n: np.array([float(p[n]) for p in points]) for n in names}
    value, size = compiled.both(env, points=len(points))
    if not (np.all(np.isfinite(value)) and np.all(np.isfinite(size))):
        return None
    if np.iscomplexobj(value) and np.any(np.abs(value.imag) > HOLDS * size):
        return None
    value = np.real(value)
    if np.all((np.abs(value) <= HOLDS * size) | (np.abs(value) <= FLOOR)):
        return True, f"vanishes at {POINTS} random points to 1e-14 of its terms (float64)"
    if FREE_FUNCTION in compiled.names:
        return None  # nonzero for one function: the exact engine says what it is for the model's
    for index, (v, s) in enumerate(zip(value, size, strict=True)):
        if abs(v) > FAILS * s and abs(v) > FLOOR:
            return False, f"residual {v:.6g}{_at(points[index])} (float64)"
    return None


def _relation(item: Item, compiled: Compiled) -> Verdict | None:
    import numpy as np

    names = sorted(compiled.names - REAL_ONLY)
    unbounded = [n for n in names if n not in item.domain]
    if unbounded or FREE_FUNCTION in compiled.names:
        return None  # the exact engine words it
    points = _points(item, names, RELATION_POINTS if names else 1)
    env = {n: np.array([float(p[n]) for p in points]) for n in names}
    value, size = compiled.both(env, points=len(points))
    if np.iscomplexobj(value) or not np.all(np.isfinite(value)):
        return None
    for index, (v, s) in enumerate(zip(value, size, strict=True)):
        if v < -FAILS * s:
            return False, f"the margin is {v:.6g}{_at(points[index])} (float64)"
    if np.all(value > HOLDS * size + 1e-300):
        return True, "the inequality holds" + (
            f" at {RELATION_POINTS} random points" if names else ""
        )
    return None


def certain_margins(item: Item, points: Sequence[Mapping[Any, Any]], tolerance: float) -> set[int]:
    """Of a relation float64 did not decide, the indices of the exact engine's ``points``
    (symbol -> rational) where float64 alone shows the margin positive: a finite real number
    above :data:`HOLDS` of its size and above twice the exact engine's ``tolerance``. The
    exact engine judges the others only (a wide relation whose margin is 0 at some points)."""
    import numpy as np

    if item.call != "relation" or item.source is None or not points:
        return set()
    try:
        compiled = compile_expr(item.source)
        if FREE_FUNCTION in compiled.names:
            return set()
        names = sorted(compiled.names - REAL_ONLY)
        by_name = [{str(k): v for k, v in point.items()} for point in points]
        if any(set(point) != set(names) for point in by_name):
            return set()
        env = {n: np.array([float(p[n]) for p in by_name]) for n in names}
        value, size = compiled.both(env, points=len(points))
    except (Unsupported, ArithmeticError, ValueError, TypeError, RecursionError):
        return set()
    if np.iscomplexobj(value) or np.iscomplexobj(size):
        return set()
    clear = np.isfinite(value) & (value > HOLDS * size) & (value > 2 * tolerance)
    return {int(i) for i in np.nonzero(clear)[0]}


def _series(item: Item, compiled: Compiled) -> Verdict | None:

    scale = str(item.scale)
    assert item.order is not None
    variable, branch = scale, 1
    if item.rooted is not None:  # s = t**q: a Laurent series in t, its terms below t**(q n)
        compiled, branch = compile_expr(item.rooted[0]), item.rooted[1]
        roots_of = [n for n in compiled.names if n.startswith(DUMMY + "root_")]
        if len(roots_of) != 1:
            return None
        variable = roots_of[0]
    order = branch * item.order
    if compiled.names & REAL_ONLY:
        return None
    others = sorted(compiled.names - {variable} - REAL_ONLY)
    high = min(float(_domain(item, scale)[1]) ** (1 / branch), 0.5)
    failing = None
    for point in _points(item, others, 3 if others else 1):
        # two circles; when they decide nothing (a singularity near the larger one: slow
        # decay, aliasing), two twice smaller, then two four times smaller
        for radii in ((high, high / 2), (high / 2, high / 4), (high / 4, high / 8)):
            found = _on_circles(compiled, variable, others, point, radii)
            if found is None:
                return None
            coefficients, sizes = found
            if _vanishes_below(coefficients, sizes, radii, high, order):
                break
            failing = _decisive_failure(coefficients, sizes, radii, order, scale, branch)
            if failing is not None:
                where = f" at {_shown(point)}" if others else ""
                return False, f"{failing}{where} (float64 Cauchy)"
        else:
            return None
    stated = item.order
    return True, f"its series in {scale} vanishes below order {stated} (float64 Cauchy)"


def _stored_series(item: Item) -> Verdict | None:
    """A series Cauchy's integral did not decide, by its terms below the order derived once
    (the store's ``taylor``: sympy's series, as the exact engine truncates it), judged as an
    identity with the scale among the random points. Holds only: a failure is the exact
    engine's to word."""
    if item.taylor is None:
        return None
    verdict = _identity(item, compile_expr(item.taylor))
    if verdict is None or not verdict[0]:
        return None
    return True, (
        f"its terms below order {item.order} in {item.scale} vanish at {POINTS} random points "
        "(float64, stored series)"
    )


def _stored_limit(item: Item, compiled: Compiled) -> Verdict | None:
    """A residual that must stay finite as the scale tends to 0+, by its limit derived once
    (the store's ``limit``: sympy's, the other symbols free): a finite real number at
    :data:`POINTS` random points of the residual's other symbols. Holds only: a divergence
    is the exact engine's to word."""
    import numpy as np

    if item.limit is None:
        return None
    limit = compile_expr(item.limit)
    others = sorted(compiled.names - {str(item.scale)} - REAL_ONLY)
    if FREE_FUNCTION in limit.names | compiled.names or not limit.names - REAL_ONLY <= set(others):
        return None
    points = _points(item, others, POINTS if others else 1)
    env = {n: np.array([float(p[n]) for p in points]) for n in others}
    value = limit.value(env, points=len(points))
    if np.iscomplexobj(value) or not np.all(np.isfinite(value)):
        return None
    return True, f"finite as {item.scale} -> 0+ (float64, stored limit)"


_POWERS_OF: dict[
    int, Any
] = {}  # the circle's sample count -> the power each FFT coefficient belongs to


def _powers() -> Any:
    import numpy as np

    if CIRCLE not in _POWERS_OF:
        _POWERS_OF[CIRCLE] = np.fft.fftfreq(CIRCLE, 1 / CIRCLE).astype(int)  # 0, 1, …, -1
    return _POWERS_OF[CIRCLE]


def _on_circles(
    compiled: Compiled,
    variable: str,
    others: list[str],
    point: dict[str, Fraction],
    radii: tuple[float, float],
) -> tuple[list[Any], list[float]] | None:
    """Each circle's Laurent coefficients (by the FFT of CIRCLE samples) and the residual's
    largest size on it; None where a sample is not a finite number."""
    import numpy as np

    roots = np.exp(2j * np.pi * np.arange(CIRCLE) / CIRCLE)
    powers = _powers().astype(float)
    coefficients, sizes = [], []
    for radius in radii:
        env = {n: np.full(CIRCLE, float(point[n]), dtype=complex) for n in others}
        env[variable] = radius * roots
        value, size = compiled.both(env, points=CIRCLE)
        if not (np.all(np.isfinite(value)) and np.all(np.isfinite(size))):
            return None
        coefficients.append(np.fft.fft(value) / CIRCLE / radius**powers)
        sizes.append(float(np.max(size)))
    return coefficients, sizes


def _vanishes_below(
    coefficients: list[Any],
    sizes: list[float],
    radii: tuple[float, float],
    reach: float,
    order: int,
) -> bool:
    """Every coefficient below the order, measured on either circle, contributes less than
    HOLDS of the size: a power j >= 0 at the largest circle's radius ``reach`` (the same bound
    whichever circles measured it: a smaller one aliases less and rounds more, never loosens
    it), a negative power (a pole) on its own circle."""
    import numpy as np

    powers = _powers()
    below = (powers < order) & (powers >= 0)
    poles = powers < 0
    for a, s, r in zip(coefficients, sizes, radii, strict=True):
        if np.any(np.abs(a[below]) * reach ** powers[below].astype(float) > HOLDS * s):
            return False
        if np.any(np.abs(a[poles]) * r ** powers[poles].astype(float) > HOLDS * s):
            return False
    return True


def _decisive_failure(
    coefficients: list[Any],
    sizes: list[float],
    radii: tuple[float, float],
    order: int,
    scale: str,
    branch: int = 1,
) -> str | None:
    """The lowest power below the order whose coefficient is decisively not 0, when the two
    circles agree on every coefficient (the residual analytic between them); else None."""
    import numpy as np

    powers = _powers()

    near, far = coefficients[1], coefficients[0]
    inner = radii[1] ** powers.astype(float)
    agree = np.abs(near - far) * inner <= 1e-9 * max(sizes)
    tail = np.abs(powers) >= CIRCLE // 4
    if not np.all(agree[~tail]) or np.any(
        np.abs(far[tail]) * radii[0] ** powers[tail].astype(float) > 1e-9 * sizes[0]
    ):
        return None
    for power in sorted(int(p) for p in powers[powers < order]):
        index = int(np.nonzero(powers == power)[0][0])
        if power < 0 and abs(far[index]) * radii[0] ** power > HOLDS * sizes[0]:
            return None  # a pole or worse: the exact engine says whether a series exists
        if abs(far[index]) * radii[0] ** power > FAILS * sizes[0]:
            value = far[index]
            shown = f"{value.real:.6g}" if abs(value.imag) <= 1e-9 * abs(value) else f"{value:.6g}"
            return f"the coefficient of {scale}**{Fraction(power, branch)} is {shown}"
    return None
