"""A stored expression (sympy's srepr) compiled to numpy, for float64 first (verify/float_verdict).

The text's syntax tree is walked, never evaluated as code: each node becomes a function of the
symbols' arrays, for the expression's *value* and for its *size* (every sum a sum of absolute
values, the scale of the cancellation a vanishing residual shows). Bessel functions by scipy;
definite integrals by tanh-sinh quadrature, the step halved until two agree; an undefined
function as a fixed generic analytic one (:data:`FREE_FUNCTION`). What float64 cannot evaluate
raises :class:`Unsupported`: the exact engine judges it.
"""

from __future__ import annotations

import ast
import math
import random
import re
from collections.abc import Callable
from functools import cache
from typing import Any

__all__ = ["DUMMY", "FREE_FUNCTION", "REAL_ONLY", "Compiled", "Unsupported", "compile_text"]

DUMMY = "\\0"  # a dummy's name starts so: never a symbol of the ledger


class Unsupported(Exception):
    """What float64 cannot evaluate here: the exact engine judges."""


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
    tree = ast.parse(_shortened(text), mode="eval").body
    names: set[str] = set()
    value = _node(tree, names)
    size = _size_node(tree, names)
    return Compiled(value, size, frozenset(names))


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
_CONSTANTS = {"pi": math.pi, "E": math.e, "I": 1j}


# srepr spells each symbol and integer as a call; parsed as such, they are most of the nodes
# of a stored text (half its characters), so they are written shorter before it is parsed:
# Symbol('x', real=True) as the name symbol__x (its assumptions are no part of a value),
# Integer(-2) as the literal (-2)
_SYMBOL = "symbol__"
_SYMBOL_CALL = re.compile(r"Symbol\('([A-Za-z_][A-Za-z0-9_]*)'(?:, [a-z_]+=(?:True|False))*\)")
_INTEGER_CALL = re.compile(r"Integer\((-?[0-9]+)\)")


def _shortened(text: str) -> str:
    return _INTEGER_CALL.sub(r"(\1)", _SYMBOL_CALL.sub(_SYMBOL + r"\1", text))


def _integer(node: ast.AST) -> int | None:
    """An integer written as a literal or as Integer(n); None for anything else."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        if node.func.id != "Integer" or len(node.args) != 1:
            return None
        node = node.args[0]
    try:
        value = _number(node)
    except Unsupported:
        return None
    return value if isinstance(value, int) else None


def _head(node: ast.AST) -> str:
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        return node.func.id
    raise Unsupported(ast.dump(node)[:40])


# an undefined function applied (a constant of integration, a function the reference leaves
# free): a residual that vanishes for every such function vanishes for a fixed generic one,
# so float64 evaluates it as one and decides "holds" only (:data:`FREE_FUNCTION` in names)
FREE_FUNCTION = "\0free function"


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
    names.add(FREE_FUNCTION)
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

    if isinstance(tree, ast.Name) and tree.id.startswith(_SYMBOL):
        name = tree.id[len(_SYMBOL) :]
        names.add(name)
        return lambda env: env[name]
    if isinstance(tree, (ast.Constant, ast.UnaryOp)):
        literal = float(_number(tree))
        return lambda env: literal
    if isinstance(tree, ast.Name):
        if tree.id not in _CONSTANTS and tree.id != "EulerGamma":
            raise Unsupported(tree.id)
        constant = float(np.euler_gamma) if tree.id == "EulerGamma" else _CONSTANTS[tree.id]
        return lambda env: constant
    if isinstance(tree, ast.Call) and isinstance(tree.func, ast.Call):
        return _free_function(tree, names)
    head = _head(tree)
    names.add(head) if head in REAL_ONLY else None
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
    if isinstance(node, ast.Name) and node.id.startswith(_SYMBOL):
        return node.id[len(_SYMBOL) :]
    head = _head(node)
    if head not in ("Symbol", "Dummy"):
        raise Unsupported(head)
    name = str(_number(node.args[0]))  # type: ignore[attr-defined]
    if head == "Symbol":
        return name
    index = [k.value for k in node.keywords if k.arg == "dummy_index"]  # type: ignore[attr-defined]
    return f"{DUMMY}{name}_{_number(index[0]) if index else 0}"


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
    if head in ("factorial", "factorial2") and _integer(args[0]) is not None:
        from sympy import factorial, factorial2

        n = _integer(args[0])
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
    power = _integer(args[1]) if head == "Pow" else None
    if power is not None and power > 0:
        base = _size_node(args[0], names)
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
