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

import ast
import math
import random
from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction
from functools import cache
from typing import Any, Protocol

from pendcli.core.point_values import FLOOR, RELATION_POINTS


class Item(Protocol):
    """What float64 reads of an item (:class:`pendcli.core.derived.Item`)."""

    @property
    def call(self) -> str: ...
    @property
    def source(self) -> str | None: ...
    @property
    def scale(self) -> Any: ...
    @property
    def order(self) -> int | None: ...
    @property
    def domain(self) -> Mapping[str, tuple[Any, Any]]: ...
    @property
    def rooted(self) -> tuple[str, int] | None: ...
    @property
    def taylor(self) -> str | None: ...
    @property
    def limit(self) -> str | None: ...


__all__ = [
    "CIRCLE",
    "FAILS",
    "HOLDS",
    "POINTS",
    "certain_margins",
    "compile_text",
    "quick_verdict",
]

HOLDS = 1e-14
FAILS = 1e-6
POINTS = 8
CIRCLE = 64
_DEFAULT_DOMAIN = (Fraction(1, 10), Fraction(1, 2))
_DUMMY = "\\0"  # a dummy's name starts so: never a symbol of the ledger

Verdict = tuple[bool, str]


class Unsupported(Exception):
    """What float64 cannot evaluate here: the exact engine judges."""


def quick_verdict(item: Item) -> Verdict | None:
    """The item's verdict in float64, or None when float64 does not decide it."""
    if item.call not in ("equation", "relation", "bounded") or item.source is None:
        return None
    try:
        compiled = compile_text(item.source)
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
    """``count`` random rational points, drawn as the exact engine draws them."""
    generator = random.Random(19)
    out = []
    for _ in range(count):
        point = {}
        for name in names:
            low, high = _domain(item, name)
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

    names = sorted(compiled.names - _REAL_ONLY)
    points = _points(item, names, POINTS)
    env = {n: np.array([float(p[n]) for p in points]) for n in names}
    value, size = compiled.value(env, points=len(points)), compiled.size(env, points=len(points))
    if not (np.all(np.isfinite(value)) and np.all(np.isfinite(size))):
        return None
    if np.iscomplexobj(value) and np.any(np.abs(value.imag) > HOLDS * size):
        return None
    value = np.real(value)
    if np.all((np.abs(value) <= HOLDS * size) | (np.abs(value) <= FLOOR)):
        return True, f"vanishes at {POINTS} random points to 1e-14 of its terms (float64)"
    if _FREE_FUNCTION in compiled.names:
        return None  # nonzero for one function: the exact engine says what it is for the model's
    for index, (v, s) in enumerate(zip(value, size, strict=True)):
        if abs(v) > FAILS * s and abs(v) > FLOOR:
            return False, f"residual {v:.6g}{_at(points[index])} (float64)"
    return None


def _relation(item: Item, compiled: Compiled) -> Verdict | None:
    import numpy as np

    names = sorted(compiled.names - _REAL_ONLY)
    unbounded = [n for n in names if n not in item.domain]
    if unbounded or _FREE_FUNCTION in compiled.names:
        return None  # the exact engine words it
    points = _points(item, names, RELATION_POINTS if names else 1)
    env = {n: np.array([float(p[n]) for p in points]) for n in names}
    value, size = compiled.value(env, points=len(points)), compiled.size(env, points=len(points))
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
        compiled = compile_text(item.source)
        if _FREE_FUNCTION in compiled.names:
            return set()
        names = sorted(compiled.names - _REAL_ONLY)
        by_name = [{str(k): v for k, v in point.items()} for point in points]
        if any(set(point) != set(names) for point in by_name):
            return set()
        env = {n: np.array([float(p[n]) for p in by_name]) for n in names}
        value = compiled.value(env, points=len(points))
        size = compiled.size(env, points=len(points))
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
        compiled, branch = compile_text(item.rooted[0]), item.rooted[1]
        roots_of = [n for n in compiled.names if n.startswith(_DUMMY + "root_")]
        if len(roots_of) != 1:
            return None
        variable = roots_of[0]
    order = branch * item.order
    if compiled.names & _REAL_ONLY:
        return None
    others = sorted(compiled.names - {variable} - _REAL_ONLY)
    high = min(float(_domain(item, scale)[1]) ** (1 / branch), 0.5)
    failing = None
    for point in _points(item, others, 3 if others else 1):
        # two circles; when they decide nothing (a singularity near the larger one: slow
        # decay, aliasing), two four times smaller
        for radii in ((high, high / 2), (high / 4, high / 8)):
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
    verdict = _identity(item, compile_text(item.taylor))
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
    limit = compile_text(item.limit)
    others = sorted(compiled.names - {str(item.scale)} - _REAL_ONLY)
    if _FREE_FUNCTION in limit.names | compiled.names or not limit.names - _REAL_ONLY <= set(
        others
    ):
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
        value = compiled.value(env, points=CIRCLE)
        size = compiled.size(env, points=CIRCLE)
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


# --- compiling a stored expression ------------------------------------------------------


class Compiled:
    """A residual's value and size as numpy functions of its symbols' arrays."""

    def __init__(self, value: Node, size: Node, names: frozenset[str]) -> None:
        self._value, self._size, self.names = value, size, names

    def value(self, env: dict[str, Any], points: int) -> Any:
        import numpy as np

        with np.errstate(all="ignore"):
            return np.broadcast_to(self._value(env), (points,))

    def size(self, env: dict[str, Any], points: int) -> Any:
        import numpy as np

        with np.errstate(all="ignore"):
            return np.abs(np.broadcast_to(self._size(env), (points,)))


Node = Callable[[dict[str, Any]], Any]


@cache
def compile_text(text: str) -> Compiled:
    """The value and size functions of a stored expression (sympy's srepr)."""
    tree = ast.parse(text, mode="eval").body
    names: set[str] = set()
    value = _node(tree, names)
    size = _size_node(tree, names)
    return Compiled(value, size, frozenset(names))


# heads whose value is not analytic in a complex scale: a series that has one is not judged here
_REAL_ONLY = frozenset(
    {"Abs", "floor", "sign", "arg", "re", "im", "atan2", "Integral", "\0free function"}
)
_UNARY = {
    "sin": "sin",
    "cos": "cos",
    "tan": "tan",
    "exp": "exp",
    "log": "log",
    "atan": "arctan",
    "asin": "arcsin",
    "acos": "arccos",
    "sinh": "sinh",
    "cosh": "cosh",
    "tanh": "tanh",
    "Abs": "abs",
    "floor": "floor",
    "sign": "sign",
    "re": "real",
    "im": "imag",
    "arg": "angle",
}
_CONSTANTS = {"pi": math.pi, "E": math.e, "I": 1j}


def _head(node: ast.AST) -> str:
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        return node.func.id
    raise Unsupported(ast.dump(node)[:40])


# an undefined function applied (a constant of integration, a function the reference leaves
# free): a residual that vanishes for every such function vanishes for a fixed generic one,
# so float64 evaluates it as one and decides "holds" only (:data:`_FREE_FUNCTION` in names)
_FREE_FUNCTION = "\0free function"


def _free_function(tree: ast.Call, names: set[str]) -> Node:
    """``Function('f')(z)`` as exp(a z) sin(b z + c) + d, its coefficients drawn from f's name."""
    import numpy as np

    func = tree.func
    if not (
        isinstance(func, ast.Call)
        and isinstance(func.func, ast.Name)
        and func.func.id == "Function"
        and len(tree.args) == 1
    ):
        raise Unsupported(ast.dump(tree)[:40])
    generator = random.Random(str(_number(func.args[0])))
    a, b, c, d = (generator.uniform(0.5, 1.5) for _ in range(4))
    (inner,) = (_node(x, names) for x in tree.args)
    names.add(_FREE_FUNCTION)
    return lambda env: np.exp(a * inner(env)) * np.sin(b * inner(env) + c) + d


def _number(node: ast.AST) -> float | int | str:
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float, str)):
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        inner = _number(node.operand)
        if isinstance(inner, (int, float)):
            return -inner
    raise Unsupported("not a literal")


def _node(tree: ast.AST, names: set[str]) -> Node:
    """The value of ``tree`` as a function of the symbols' arrays."""
    import numpy as np

    if isinstance(tree, ast.Name):
        if tree.id not in _CONSTANTS and tree.id != "EulerGamma":
            raise Unsupported(tree.id)
        constant = float(np.euler_gamma) if tree.id == "EulerGamma" else _CONSTANTS[tree.id]
        return lambda env: constant
    if isinstance(tree, ast.Call) and isinstance(tree.func, ast.Call):
        return _free_function(tree, names)
    head = _head(tree)
    names.add(head) if head in _REAL_ONLY else None
    args = tree.args  # type: ignore[attr-defined]
    if head in ("Symbol", "Dummy"):
        name = _symbol_name(tree)
        names.add(name)
        return lambda env: env[name]
    if head in ("Integer", "Rational", "Float"):
        numbers = [_number(a) for a in args]
        value = float(numbers[0]) if head != "Rational" else int(numbers[0]) / int(numbers[1])
        return lambda env: value
    if head in ("Add", "Mul"):
        parts = [_node(a, names) for a in args]
        if head == "Add":
            return lambda env: sum(p(env) for p in parts)
        return lambda env: math.prod((p(env) for p in parts), start=1.0)
    if head == "Pow":
        base, exponent = (_node(a, names) for a in args)
        return lambda env: np.power(base(env), exponent(env))
    if head in _UNARY:
        (inner,) = (_node(a, names) for a in args)
        function = getattr(np, _UNARY[head])
        return lambda env: function(inner(env))
    return _special(head, args, names)


def _symbol_name(node: ast.AST) -> str:
    """A symbol's name; a dummy's is its own (never the ledger's symbol of the same name)."""
    head = _head(node)
    if head not in ("Symbol", "Dummy"):
        raise Unsupported(head)
    name = str(_number(node.args[0]))  # type: ignore[attr-defined]
    if head == "Symbol":
        return name
    index = [k.value for k in node.keywords if k.arg == "dummy_index"]  # type: ignore[attr-defined]
    return f"{_DUMMY}{name}_{_number(index[0]) if index else 0}"


def _special(head: str, args: list[ast.AST], names: set[str]) -> Node:
    import numpy as np

    if head == "atan2":
        y, x = (_node(a, names) for a in args)
        return lambda env: np.arctan2(y(env), x(env))
    if head in ("besselj", "bessely"):
        from scipy import special

        function = special.jv if head == "besselj" else special.yv
        order, argument = (_node(a, names) for a in args)
        return lambda env: function(order(env), argument(env))
    if head in ("factorial", "factorial2") and _head(args[0]) == "Integer":
        from sympy import factorial, factorial2

        n = int(_number(args[0].args[0]))  # type: ignore[attr-defined]
        value = float((factorial if head == "factorial" else factorial2)(n))
        return lambda env: value
    if head == "Integral":
        return _integral(args, names)
    raise Unsupported(head)


def _size_node(tree: ast.AST, names: set[str]) -> Node:
    """The size of ``tree``: every sum a sum of absolute values (ε·(a − b): |ε|·(|a| + |b|))."""
    import numpy as np

    named = isinstance(tree, ast.Call) and isinstance(tree.func, ast.Name)
    head = _head(tree) if named else ""
    args = getattr(tree, "args", [])
    if head in ("Add", "Mul"):
        parts = [_size_node(a, names) for a in args]
        if head == "Add":
            return lambda env: sum(np.abs(p(env)) for p in parts)
        return lambda env: math.prod((np.abs(p(env)) for p in parts), start=1.0)
    if head == "Integral":
        return _integral(args, names, absolute=True)
    if head == "Pow" and _head(args[1]) == "Integer" and int(_number(args[1].args[0])) > 0:
        base, power = _size_node(args[0], names), int(_number(args[1].args[0]))
        return lambda env: np.abs(base(env)) ** power
    value = _node(tree, names)
    return lambda env: np.abs(value(env))


# tanh-sinh quadrature on [-1, 1]: steps h, h/2, h/4, nodes until the weights underflow; a
# value is taken from the first two consecutive steps that agree
_LEVELS = (1 / 16, 1 / 32, 1 / 64)
# how closely two steps must agree: a value to 1e-13 of the integral of |terms| (what a
# vanishing residual is measured against); a size (the integral of |f|, a scale for the
# margins, not a value compared with them) to 1e-3, and the smaller of the two is taken
_SETTLED = {False: 1e-13, True: 1e-3}


@cache
def _tanh_sinh(step: float) -> tuple[Any, Any]:
    import numpy as np

    k = np.arange(-int(3.2 / step), int(3.2 / step) + 1) * step
    u = np.pi / 2 * np.sinh(k)
    nodes = np.tanh(u)
    weights = step * np.pi / 2 * np.cosh(k) / np.cosh(u) ** 2
    keep = np.abs(nodes) < 1.0  # the nodes float64 still tells from the ends
    return nodes[keep], weights[keep]


def _integral(args: list[ast.AST], names: set[str], absolute: bool = False) -> Node:
    """A definite integral by tanh-sinh quadrature at every point at once (the ends may be
    singular; an upper end at infinity is brought to 1 by t = a + u/(1 − u)), the step halved
    until two agree (:data:`_SETTLED`); when none do, undecided."""
    if len(args) != 2 or _head(args[1]) != "Tuple":
        raise Unsupported("a multiple integral")
    variable, low, high = args[1].args  # type: ignore[attr-defined]
    name = _symbol_name(variable)
    inside: set[str] = set()
    integrand = _node(args[0], inside)
    names |= inside - {name}
    if absolute:  # the size of an integral: the integral of its integrand's absolute value
        signed = integrand

        def integrand(env: dict[str, Any]) -> Any:
            return abs(signed(env))

    lower = _node(low, names)
    if isinstance(high, ast.Name) and high.id == "oo":
        return _to_infinity(integrand, lower, name, absolute)
    return _settled(integrand, lower, _node(high, names), name, absolute)


def _settled(integrand: Node, lower: Node, upper: Node, name: str, absolute: bool) -> Node:
    import numpy as np

    def at_step(env: dict[str, Any], step: float) -> tuple[Any, Any]:
        a, b = np.asarray(lower(env)), np.asarray(upper(env))
        nodes, weights = _tanh_sinh(step)
        inner = {k: np.asarray(v)[..., None] for k, v in env.items()}
        half, middle = (b - a)[..., None] / 2, (b + a)[..., None] / 2
        inner[name] = middle + half * nodes
        terms = integrand(inner) * weights * half
        # the sum, and the scale a vanishing integral is on
        return np.sum(terms, axis=-1), np.sum(np.abs(terms), axis=-1)

    def value(env: dict[str, Any]) -> Any:
        coarse, _ = at_step(env, _LEVELS[0])
        for step in _LEVELS[1:]:
            fine, size = at_step(env, step)
            unsettled = np.abs(fine - coarse) > _SETTLED[absolute] * size + 1e-300
            if not np.any(unsettled) and np.all(np.isfinite(fine)):
                return np.minimum(coarse, fine) if absolute else fine
            coarse = fine
        raise Unsupported("a quadrature that does not settle")

    return value


def _to_infinity(integrand: Node, lower: Node, name: str, absolute: bool) -> Node:
    """∫_a^∞ f(t) dt = ∫_0^1 f(a + u/(1 − u)) du/(1 − u)²."""
    import numpy as np

    def mapped(env: dict[str, Any]) -> Any:
        u = env["\0u"]
        inner = dict(env)
        inner[name] = lower(env) + u / (1 - u)
        with np.errstate(all="ignore"):
            values = integrand(inner) / (1 - u) ** 2
        far = np.broadcast_to(inner[name], np.shape(values)) > 1e8  # underflow of a decaying tail
        return np.where(far & ~np.isfinite(values), 0.0, values)

    return _settled(mapped, lambda env: 0.0, lambda env: 1.0, "\0u", absolute)
