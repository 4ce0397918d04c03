"""A stored expression compiled to numpy, for float64 first (verify/float_verdict).

The expression's table of nodes (data/stored_expr: each distinct subexpression once) is walked,
never evaluated as code: each node becomes a function of the symbols' arrays, once per table,
for the expression's *value* and for its *size* (every sum a sum of absolute values, the scale
of the cancellation a vanishing residual shows), so a subexpression many residuals share is
compiled once. Bessel functions by scipy; definite integrals by tanh-sinh quadrature, the step
halved until two agree; an undefined function as a fixed generic analytic one
(:data:`FREE_FUNCTION`). What float64 cannot evaluate raises :class:`Unsupported`: the exact
engine judges it.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from functools import cache
from typing import Any
from weakref import WeakKeyDictionary

from pendcli.data.stored_expr import APPLY, Nodes, NodeWriter, StoredExpr

__all__ = [
    "DUMMY",
    "FREE_FUNCTION",
    "REAL_ONLY",
    "Compiled",
    "Unsupported",
    "compile_expr",
    "compile_text",
]

DUMMY = "\\0"  # a dummy's name starts so: never a symbol of the ledger


class Unsupported(Exception):
    """What float64 cannot evaluate here: the exact engine judges."""


class Compiled:
    """A residual's value and size as numpy functions of its symbols' arrays (``both``: the
    two in one walk, each node's value computed once)."""

    def __init__(
        self, value: Node, size: Node, names: frozenset[str], both: Node | None = None
    ) -> None:
        self._value, self._size, self.names = value, size, names
        self._both = both if both is not None else lambda env: (value(env), size(env))

    def both(self, env: dict[str, Any], points: int) -> tuple[Any, Any]:
        """(value, size), as :meth:`value` and :meth:`size` give them."""
        import numpy as np

        with np.errstate(all="ignore"):
            value, size = self._both(env)
            shape = (points,)
            return np.broadcast_to(value, shape), np.abs(np.broadcast_to(size, shape))

    def value(self, env: dict[str, Any], points: int) -> Any:
        import numpy as np

        with np.errstate(all="ignore"):
            return np.broadcast_to(self._value(env), (points,))

    def size(self, env: dict[str, Any], points: int) -> Any:
        import numpy as np

        with np.errstate(all="ignore"):
            return np.abs(np.broadcast_to(self._size(env), (points,)))


Node = Callable[[dict[str, Any]], Any]
Failure = (ArithmeticError, ValueError, TypeError, IndexError)


@cache
def compile_text(text: str) -> Compiled:
    """The value and size functions of an expression written as sympy's srepr (read into a
    table of its own by the store's closed grammar)."""
    from pendcli.base.errors import PendcliError

    writer = NodeWriter("an expression")
    try:
        index = writer.encode("an expression", text)
    except PendcliError as exc:
        raise Unsupported(str(exc)) from None
    return compile_expr(StoredExpr(writer.table("an expression"), index))


def compile_expr(expr: str | StoredExpr) -> Compiled:
    """The value and size functions of a stored expression (a node of its table, each node
    compiled once per table) or of an srepr text."""
    if isinstance(expr, str):
        return compile_text(expr)
    compiler = _compilers.get(expr.nodes)
    if compiler is None:
        compiler = _compilers[expr.nodes] = _Compiler(expr.nodes)
    return compiler.compiled(expr.index)


# heads whose value is not analytic in a complex scale: a series that has one is not judged here
REAL_ONLY = frozenset(
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
_CONSTANTS = {"pi": math.pi, "E": math.e, "I": 1j, "EulerGamma": 0.5772156649015329}

# an undefined function applied (a constant of integration, a function the reference leaves
# free): a residual that vanishes for every such function vanishes for a fixed generic one,
# so float64 evaluates it as one and decides "holds" only (:data:`FREE_FUNCTION` in names)
FREE_FUNCTION = "\0free function"


class _Compiler:
    """The functions of a table's nodes, each node's once: its value, its size and the
    names it reads (symbols, and the heads of :data:`REAL_ONLY` it holds); a node float64
    cannot evaluate keeps its :class:`Unsupported`."""

    def __init__(self, nodes: Nodes) -> None:
        self.nodes = nodes
        self._values: dict[int, tuple[Node, frozenset[str]] | Unsupported] = {}
        self._sizes: dict[int, Node | Unsupported] = {}
        self._both: dict[int, Node] = {}

    def compiled(self, index: int) -> Compiled:
        value, names = self.value(index)
        return Compiled(value, self.size(index), names, self.both(index))

    def both(self, index: int) -> Node:
        """The node's (value, size) in one walk: a sum's or product's from its terms' pairs,
        a power's to a positive integer from its base's; any other node's size is its
        value's absolute value (what :func:`_size_node` computes, the value not computed
        twice)."""
        found = self._both.get(index)
        if found is None:
            found = self._both[index] = _both_node(self, index)
        return found

    def value(self, index: int) -> tuple[Node, frozenset[str]]:
        return _kept(self._values, index, lambda: _value_node(self, self.nodes.nodes[index]))

    def size(self, index: int) -> Node:
        return _kept(self._sizes, index, lambda: _size_node(self, index))

    def integer(self, index: int) -> int | None:
        """A node that is an integer literal, its value; None for anything else."""
        node = self.nodes.nodes[index]
        return int(node[1]) if node[0] == "Integer" else None

    def head(self, index: int) -> str:
        return str(self.nodes.nodes[index][0])


def _kept(memo: dict[int, Any], index: int, compile_node: Callable[[], Any]) -> Any:
    """``memo[index]``, compiled once: what cannot be compiled is kept too and raised again
    (an Unsupported; a failure of the compilation becomes one)."""
    found = memo.get(index)
    if found is None:
        try:
            found = compile_node()
        except Failure as exc:
            found = Unsupported(repr(exc)[:60])
        except Unsupported as exc:
            found = exc
        memo[index] = found
    if isinstance(found, Unsupported):
        raise found
    return found


# each table's compiler (its nodes' functions, kept while the table is)
_compilers: WeakKeyDictionary[Nodes, _Compiler] = WeakKeyDictionary()


def _symbol_name(node: tuple[Any, ...]) -> str:
    """A symbol's name; a dummy's is its own (never the ledger's symbol of the same name)."""
    if node[0] == "Symbol":
        return str(node[1])
    if node[0] == "Dummy":
        return f"{DUMMY}{node[1]}_{node[2]}"
    raise Unsupported(str(node[0]))


def _value_node(compiler: _Compiler, node: tuple[Any, ...]) -> tuple[Node, frozenset[str]]:
    """The value of ``node`` as a function of the symbols' arrays, and the names it reads."""
    import numpy as np

    head, args = node[0], node[1:]
    if head == "Function":  # an undefined function not applied
        raise Unsupported(head)
    if head in ("Symbol", "Dummy"):
        name = _symbol_name(node)
        return (lambda env: env[name]), frozenset([name])
    if head in ("Integer", "Float", "Rational") or head in _CONSTANTS:
        value = _literal(node)
        return (lambda env: value), frozenset()
    if head == APPLY:
        return _free_function(compiler, args)
    if head == "Integral":
        return _integral(compiler, args)
    parts = [compiler.value(a) for a in args]
    names = frozenset().union(*(n for _, n in parts))
    names |= {head} if head in REAL_ONLY else set()
    functions = [f for f, _ in parts]
    if head == "Add":
        return (lambda env: sum(p(env) for p in functions)), names
    if head == "Mul":
        return (lambda env: math.prod((p(env) for p in functions), start=1.0)), names
    if head == "Pow":
        base, exponent = functions
        return (lambda env: np.power(base(env), exponent(env))), names
    if head in _UNARY:
        (inner,) = functions
        function = getattr(np, _UNARY[head])
        return (lambda env: function(inner(env))), names
    return _special(compiler, head, args, functions), names


def _literal(node: tuple[Any, ...]) -> Any:
    head, args = node[0], node[1:]
    if head in _CONSTANTS:
        return _CONSTANTS[head]
    if head == "Rational":
        return int(args[0]) / int(args[1])
    return float(args[0])


def _free_function(compiler: _Compiler, args: tuple[Any, ...]) -> tuple[Node, frozenset[str]]:
    """``Function('f')(z)`` as exp(a z) sin(b z + c) + d, its coefficients drawn from f's name."""
    import numpy as np

    if len(args) != 2:
        raise Unsupported("a free function of several arguments")
    generator = random.Random(str(compiler.nodes.nodes[args[0]][1]))
    a, b, c, d = (generator.uniform(0.5, 1.5) for _ in range(4))
    inner, names = compiler.value(args[1])

    def value(env: dict[str, Any]) -> Any:
        return np.exp(a * inner(env)) * np.sin(b * inner(env) + c) + d

    return value, names | {FREE_FUNCTION}


_FACTORIAL_MOST = 1000


def _special(compiler: _Compiler, head: str, args: tuple[Any, ...], functions: list[Node]) -> Node:
    import numpy as np

    if head == "atan2":
        y, x = functions
        return lambda env: np.arctan2(y(env), x(env))
    if head in ("besselj", "bessely"):
        from scipy import special

        function = special.jv if head == "besselj" else special.yv
        order, argument = functions
        return lambda env: function(order(env), argument(env))
    n = compiler.integer(args[0]) if head in ("factorial", "factorial2") and args else None
    # an integer's factorial, exact from sympy then rounded (beyond 170! a double overflows;
    # a far larger argument, which sympy would take long to multiply out, is not followed)
    if n is not None and abs(n) <= _FACTORIAL_MOST:
        from sympy import factorial, factorial2

        value = float((factorial if head == "factorial" else factorial2)(n))
        return lambda env: value
    raise Unsupported(head)


def _size_node(compiler: _Compiler, index: int) -> Node:
    """The size of a node: every sum a sum of absolute values (ε·(a − b): |ε|·(|a| + |b|))."""
    import numpy as np

    node = compiler.nodes.nodes[index]
    head, args = node[0], node[1:]
    if head in ("Add", "Mul"):
        parts = [compiler.size(a) for a in args]
        if head == "Add":
            return lambda env: sum(np.abs(p(env)) for p in parts)
        return lambda env: math.prod((np.abs(p(env)) for p in parts), start=1.0)
    if head == "Integral":
        return _integral(compiler, args, absolute=True)[0]
    power = compiler.integer(args[1]) if head == "Pow" else None
    if power is not None and power > 0:
        base = compiler.size(args[0])
        return lambda env: np.abs(base(env)) ** power
    value, _ = compiler.value(index)
    return lambda env: np.abs(value(env))


def _both_node(compiler: _Compiler, index: int) -> Node:
    import numpy as np

    node = compiler.nodes.nodes[index]
    head, args = node[0], node[1:]
    size = compiler.size(index)  # compiled first: what it cannot follow is refused alike
    value, _ = compiler.value(index)
    if head in ("Add", "Mul"):
        parts = [compiler.both(a) for a in args]
        if head == "Add":

            def added(env: dict[str, Any]) -> tuple[Any, Any]:
                pairs = [p(env) for p in parts]
                return sum(v for v, _ in pairs), sum(np.abs(s) for _, s in pairs)

            return added

        def multiplied(env: dict[str, Any]) -> tuple[Any, Any]:
            pairs = [p(env) for p in parts]
            product = math.prod((v for v, _ in pairs), start=1.0)
            return product, math.prod((np.abs(s) for _, s in pairs), start=1.0)

        return multiplied
    power = compiler.integer(args[1]) if head == "Pow" else None
    if power is not None and power > 0:
        base, (exponent, _) = compiler.both(args[0]), compiler.value(args[1])

        def raised(env: dict[str, Any]) -> tuple[Any, Any]:
            below, scale = base(env)
            return np.power(below, exponent(env)), np.abs(scale) ** power

        return raised
    if head == "Integral":
        return lambda env: (value(env), size(env))

    def other(env: dict[str, Any]) -> tuple[Any, Any]:
        computed = value(env)
        return computed, np.abs(computed)

    return other


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


def _integral(
    compiler: _Compiler, args: tuple[Any, ...], absolute: bool = False
) -> tuple[Node, frozenset[str]]:
    """A definite integral by tanh-sinh quadrature at every point at once (the ends may be
    singular; an upper end at infinity is brought to 1 by t = a + u/(1 − u)), the step halved
    until two agree (:data:`_SETTLED`); when none do, undecided."""
    if len(args) != 2 or compiler.head(args[1]) != "Tuple":
        raise Unsupported("a multiple integral")
    variable, low, high = compiler.nodes.nodes[args[1]][1:]
    name = _symbol_name(compiler.nodes.nodes[variable])
    integrand, inside = compiler.value(args[0])
    if absolute:  # the size of an integral: the integral of its integrand's absolute value
        signed = integrand

        def integrand(env: dict[str, Any]) -> Any:
            return abs(signed(env))

    lower, below = compiler.value(low)
    names = (inside - {name}) | below | {"Integral"}
    if compiler.head(high) == "oo":
        return _to_infinity(integrand, lower, name, absolute), names
    upper, above = compiler.value(high)
    return _settled(integrand, lower, upper, name, absolute), names | above


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
