"""A stored expression read back: sympy's ``srepr`` walked as a syntax tree, never evaluated.

Only calls of the sympy constructors in :data:`HEADS` with number, string and boolean
arguments, and the names of :data:`CONSTANTS`, are read; anything else is an error naming
where it was found. Sizes are bounded: the text, the nodes, the depth, an integer literal,
the exponent of a power and the argument of a factorial.
"""

from __future__ import annotations

import ast
from functools import cache
from typing import Any

from pendcli.base.errors import PendcliError

__all__ = ["CONSTANTS", "HEADS", "read_expr"]

# the sympy constructors (and constants) an expression of the store may name
HEADS = frozenset(
    [
        "Symbol",
        "Dummy",
        "Integer",
        "Rational",
        "Float",
        "Add",
        "Mul",
        "Pow",
        "Tuple",
        "Function",
        "Integral",
        "Derivative",
        "Subs",
        "sin",
        "cos",
        "tan",
        "exp",
        "log",
        "atan",
        "asin",
        "acos",
        "atan2",
        "sinh",
        "cosh",
        "tanh",
        "Abs",
        "floor",
        "sign",
        "arg",
        "factorial2",
        "factorial",
        "besselj",
        "bessely",
        "elliptic_k",
        "elliptic_e",
        "sqrt",
        "re",
        "im",
    ]
)
CONSTANTS = frozenset(["pi", "E", "I", "oo", "zoo", "nan", "EulerGamma"])
_MAX_BYTES = 8_000_000  # a stored expression's text
_MAX_NODES = 200_000  # one expression's
_MAX_DEPTH = 200
# an integer literal's bound: a power or factorial of larger ones would take the machine
_MAX_INTEGER = 10**60
_MAX_EXPONENT = 10_000


@cache
def read_expr(where: str, text: str) -> Any:
    """A sympy expression from its ``srepr``, read by walking the parsed syntax tree: only
    calls of :data:`HEADS`, the names of :data:`CONSTANTS`, and number, string and boolean
    literals; anything else is an error naming ``where``. Nothing is evaluated as code."""
    if not isinstance(text, str) or len(text) > _MAX_BYTES:
        raise PendcliError(f"{where}: a stored expression must be a string")
    try:
        tree = ast.parse(text, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise PendcliError(f"{where}: a stored expression does not parse") from None
    if sum(1 for _ in ast.walk(tree)) > _MAX_NODES:
        raise PendcliError(f"{where}: a stored expression of more than {_MAX_NODES} nodes")
    try:
        return _build(where, tree.body, 0)
    except PendcliError:
        raise
    except Exception as exc:  # a constructor refusing its arguments: the file is malformed
        raise PendcliError(
            f"{where}: a stored expression sympy refuses ({type(exc).__name__})"
        ) from None


def _refuse_huge(where: str, head: str, args: list[Any]) -> None:
    """A power or factorial whose exact value would not fit the machine is refused."""
    import sympy as sp

    if head not in ("Pow", "factorial", "factorial2"):
        return
    checked = args[1:] if head == "Pow" else args
    for arg in checked:
        if isinstance(arg, sp.Integer) and abs(arg) > _MAX_EXPONENT:
            raise PendcliError(f"{where}: a stored {head} of an integer beyond {_MAX_EXPONENT}")


def _build(where: str, node: ast.AST, depth: int) -> Any:
    import sympy as sp

    if depth > _MAX_DEPTH:
        raise PendcliError(f"{where}: a stored expression nested more than {_MAX_DEPTH} deep")
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, str, bool)):
        if isinstance(node.value, int) and abs(node.value) > _MAX_INTEGER:
            raise PendcliError(f"{where}: a stored integer beyond {_MAX_INTEGER:.0e}")
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        value = _build(where, node.operand, depth + 1)
        if isinstance(value, int) and not isinstance(value, bool):
            return -value
    if isinstance(node, ast.Name) and node.id in CONSTANTS:
        return getattr(sp, node.id)
    if isinstance(node, ast.Call):
        if isinstance(node.func, ast.Call):  # Function('f')(x): an undefined function applied
            head = _build(where, node.func, depth + 1)
            if isinstance(head, sp.core.function.UndefinedFunction):
                return head(*(_build(where, a, depth + 1) for a in node.args))
        elif isinstance(node.func, ast.Name) and node.func.id in HEADS:
            args = [_build(where, a, depth + 1) for a in node.args]
            if any(k.arg is None for k in node.keywords):
                raise PendcliError(f"{where}: a stored expression with ** arguments")
            keywords = {str(k.arg): _build(where, k.value, depth + 1) for k in node.keywords}
            _refuse_huge(where, node.func.id, args)
            return getattr(sp, node.func.id)(*args, **keywords)
    shown = ast.dump(node)[:60]
    raise PendcliError(f"{where}: a stored expression holds what the grammar refuses: {shown}")
