"""Stored expressions: a table of nodes, each distinct subexpression once, read without
evaluating anything.

A node is a JSON array ``[head, arg, …]``. For a compound head (a sympy constructor of
:data:`HEADS` other than the leaves below) every argument is the index of an *earlier* node
of the same table, so a table is a graph without cycles, written children first, and a
subexpression shared by many residuals is one node. A leaf holds literals::

    ["Symbol", name]                 ["Symbol", name, {"real": true}]
    ["Dummy", name, index]           ["Dummy", name, index, {"positive": true}]
    ["Integer", n]   ["Rational", p, q]   ["Float", "digits", precision]
    ["Function", name]               an undefined function; ["Apply", f, x, …] applies it
    ["pi"]  ["E"]  ["I"]  ["oo"]  ["zoo"]  ["nan"]  ["EulerGamma"]

A table is checked whole when read (:func:`read_nodes`): each node's head and literals, each
argument an earlier node, integers at most :data:`_MAX_INTEGER`, and the tree a node stands
for (its shared nodes counted each time) at most :data:`_MAX_NODES` nodes and
:data:`_MAX_DEPTH` deep; anything else is an error naming the table and the node. sympy's
``srepr``, what a derivation writes, is turned into nodes by the same closed grammar
(:class:`NodeWriter`: its parsed syntax tree walked, only calls of :data:`HEADS`, the names of
:data:`CONSTANTS` and number, string and boolean literals; nothing evaluated). A node's sympy
expression is built on demand, each node once (:meth:`Nodes.expr`), a power or factorial of an
integer beyond :data:`_MAX_EXPONENT` refused.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from functools import cache
from typing import Any

from pendcli.base.errors import PendcliError

__all__ = [
    "APPLY",
    "CONSTANTS",
    "HEADS",
    "LEAVES",
    "NodeWriter",
    "Nodes",
    "StoredExpr",
    "read_expr",
    "read_nodes",
]

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
# the heads whose arguments are literals, not nodes
LEAVES = frozenset(["Symbol", "Dummy", "Integer", "Rational", "Float", "Function"])
APPLY = "Apply"  # an undefined function applied: ["Apply", f, x, …]
_MAX_BYTES = 8_000_000  # a stored expression's text
_MAX_NODES = 200_000  # the tree one expression stands for
_MAX_TABLE = 1_000_000  # a table's nodes
_MAX_DEPTH = 200
# an integer literal's bound: a power or factorial of larger ones would take the machine
_MAX_INTEGER = 10**60
_MAX_EXPONENT = 10_000
_MAX_NAME = 200  # a symbol's or function's name, a Float's digits

Node = tuple[Any, ...]


class Nodes:
    """A checked table of nodes (:func:`read_nodes`, :meth:`NodeWriter.table`): each node, its
    sympy expression and its text built on demand, each once."""

    def __init__(self, where: str, nodes: list[Node]) -> None:
        self.where, self.nodes = where, nodes
        self._exprs: dict[int, Any] = {}
        self._texts: dict[int, str] = {}

    def __len__(self) -> int:
        return len(self.nodes)

    def node(self, where: str, index: object) -> int:
        """``index`` as a node of this table, or an error naming ``where``."""
        if type(index) is not int or not 0 <= index < len(self.nodes):
            raise PendcliError(f"{where}: a stored expression must be a node of its table")
        return index

    def expr(self, index: int) -> Any:
        """The node's sympy expression (sympy's constructors called on its built arguments)."""
        found = self._exprs.get(index)
        if found is None:
            try:
                found = self._exprs[index] = _built(self, self.nodes[index])
            except PendcliError:
                raise
            except Exception as exc:  # a constructor refusing its arguments: malformed
                why = f"a stored expression sympy refuses ({type(exc).__name__})"
                raise PendcliError(f"{self.where}: node {index}: {why}") from None
        return found

    def text(self, index: int) -> str:
        """The node as sympy's srepr writes it (what :class:`NodeWriter` reads back)."""
        found = self._texts.get(index)
        if found is None:
            found = self._texts[index] = _text(self, self.nodes[index])
        return found


@dataclass(frozen=True)
class StoredExpr:
    """One node of a table: a stored expression (equal when of the same table and node)."""

    nodes: Nodes
    index: int

    def expr(self) -> Any:
        return self.nodes.expr(self.index)

    def text(self) -> str:
        return self.nodes.text(self.index)


def _built(table: Nodes, node: Node) -> Any:
    import sympy as sp

    head, args = node[0], node[1:]
    if head in CONSTANTS:
        return getattr(sp, head)
    if head in ("Symbol", "Dummy"):
        keywords = dict(args[-1]) if isinstance(args[-1], dict) else {}
        if head == "Dummy":
            keywords["dummy_index"] = args[1]
        return getattr(sp, head)(args[0], **keywords)
    if head == "Float":
        return sp.Float(args[0], precision=args[1])
    if head in LEAVES:
        return getattr(sp, head)(*args)
    built = [table.expr(a) for a in args]
    if head == APPLY:
        return built[0](*built[1:])
    _refuse_huge(table.where, head, built)
    return getattr(sp, head)(*built)


def _text(table: Nodes, node: Node) -> str:
    head, args = node[0], node[1:]
    if head in CONSTANTS:
        return str(head)
    if head == APPLY:
        return f"{table.text(args[0])}({', '.join(table.text(a) for a in args[1:])})"
    if head not in LEAVES:
        return f"{head}({', '.join(table.text(a) for a in args)})"
    keywords = {}
    if head in ("Symbol", "Dummy") and isinstance(args[-1], dict):
        keywords, args = dict(args[-1]), args[:-1]
    if head in ("Dummy", "Float"):  # srepr writes the index and the precision as keywords
        keywords["dummy_index" if head == "Dummy" else "precision"] = args[1]
        args = args[:1]
    shown = [repr(a) for a in args] + [f"{k}={v!r}" for k, v in keywords.items()]
    return f"{head}({', '.join(shown)})"


def _refuse_huge(where: str, head: str, args: list[Any]) -> None:
    """A power or factorial whose exact value would not fit the machine is refused."""
    import sympy as sp

    if head not in ("Pow", "factorial", "factorial2"):
        return
    checked = args[1:] if head == "Pow" else args
    for arg in checked:
        if isinstance(arg, sp.Integer) and abs(arg) > _MAX_EXPONENT:
            raise PendcliError(f"{where}: a stored {head} of an integer beyond {_MAX_EXPONENT}")


# --- a table checked -----------------------------------------------------------------------


def _integer(value: object) -> bool:
    return type(value) is int and abs(value) <= _MAX_INTEGER


def _name(value: object) -> bool:
    return isinstance(value, str) and 0 < len(value) <= _MAX_NAME


def _assumptions(value: object) -> bool:
    return isinstance(value, dict) and all(
        _name(k) and k.isidentifier() and isinstance(v, bool) for k, v in value.items()
    )


def _leaf_ok(head: str, args: list[Any]) -> bool:
    """Whether a leaf's literals are those its head takes."""
    if head == "Symbol":
        return len(args) in (1, 2) and _name(args[0]) and all(map(_assumptions, args[1:]))
    if head == "Dummy":
        ok = len(args) in (2, 3) and _name(args[0]) and _integer(args[1])
        return ok and all(map(_assumptions, args[2:]))
    if head == "Integer":
        return len(args) == 1 and _integer(args[0])
    if head == "Rational":
        return len(args) == 2 and all(map(_integer, args)) and args[1] != 0
    if head == "Float":
        return len(args) == 2 and _name(args[0]) and type(args[1]) is int and 0 < args[1] <= 10_000
    return len(args) == 1 and _name(args[0])  # Function


def _shape(where: str, raw: object, count: int) -> Node:
    """A node as read: its head and literals checked, its arguments earlier nodes."""
    if not isinstance(raw, list) or not raw or not isinstance(raw[0], str):
        raise PendcliError(f"{where}: a node is [head, argument, …]")
    head, args = raw[0], raw[1:]
    if head in CONSTANTS:
        ok = not args
    elif head in LEAVES:
        ok = _leaf_ok(head, args)
    elif head in HEADS or head == APPLY:
        ok = all(type(a) is int and 0 <= a < count for a in args) and (head != APPLY or bool(args))
    else:
        shown = repr(head)[:40]
        raise PendcliError(f"{where}: a node holds what the grammar refuses: {shown}")
    if not ok:
        raise PendcliError(f"{where}: a {head} node with arguments it does not take")
    return (head, *(tuple(a.items()) if isinstance(a, dict) else a for a in args))


def _as_read(node: Node) -> Node:
    """A node's literals as the builders take them (assumptions back to a mapping)."""
    return tuple(dict(a) if isinstance(a, tuple) else a for a in node)


class _Bounds:
    """Each node's head, depth and size (the tree it stands for), bounded as they are added."""

    def __init__(self, where: str) -> None:
        self.where = where
        self.heads: list[str] = []
        self.depth: list[int] = []
        self.size: list[int] = []

    def add(self, node: Node) -> None:
        refs = [] if node[0] in LEAVES else node[1:]
        depth = 1 + max((self.depth[a] for a in refs), default=0)
        size = 1 + sum(self.size[a] for a in refs)
        index = len(self.depth)
        if depth > _MAX_DEPTH:
            raise PendcliError(f"{self.where}: node {index}: nested more than {_MAX_DEPTH} deep")
        if size > _MAX_NODES:
            raise PendcliError(f"{self.where}: node {index}: more than {_MAX_NODES} nodes")
        if node[0] == APPLY and self.heads[node[1]] != "Function":
            raise PendcliError(f"{self.where}: node {index}: Apply of what is no Function")
        self.heads.append(node[0])
        self.depth.append(depth)
        self.size.append(min(size, _MAX_NODES + 1))


def read_nodes(where: str, raw: object) -> Nodes:
    """A store's table of nodes, checked whole (an error names ``where`` and the node)."""
    if not isinstance(raw, list) or len(raw) > _MAX_TABLE:
        raise PendcliError(f"{where}: 'nodes' must be a list of at most {_MAX_TABLE} nodes")
    bounds = _Bounds(where)
    nodes = []
    for index, item in enumerate(raw):
        node = _shape(f"{where}: node {index}", item, index)
        bounds.add(node)
        nodes.append(_as_read(node))
    return Nodes(where, nodes)


# --- srepr read into nodes -------------------------------------------------------------------


class NodeWriter:
    """A table built from sympy's srepr texts, each distinct subexpression once (children
    first), by the closed grammar: only calls of :data:`HEADS`, the names of :data:`CONSTANTS`
    and literals; anything else is an error naming where it was found."""

    def __init__(self, where: str = "a stored expression") -> None:
        self.nodes: list[Node] = []
        self.nodes_read = Nodes(where, [])  # the same nodes, as a table reads them
        self._index: dict[Node, int] = {}
        self._bounds = _Bounds(where)

    def add(self, node: Node) -> int:
        found = self._index.get(node)
        if found is None:
            self._bounds.add(node)
            found = self._index[node] = len(self.nodes)
            self.nodes.append(node)
            self.nodes_read.nodes.append(_as_read(node))
        return found

    def encode(self, where: str, text: str) -> int:
        """The node of srepr ``text`` (its subexpressions added first)."""
        if not isinstance(text, str) or len(text) > _MAX_BYTES:
            raise PendcliError(f"{where}: a stored expression must be a string")
        try:
            tree = ast.parse(text, mode="eval")
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            raise PendcliError(f"{where}: a stored expression does not parse") from None
        self._bounds.where = where
        return self._walk(where, tree.body, 0)

    def table(self, where: str) -> Nodes:
        """The nodes written so far, as a table of their own."""
        return Nodes(where, list(self.nodes_read.nodes))

    def raw(self) -> list[list[Any]]:
        """The nodes as the store writes them (JSON arrays)."""
        return [[dict(a) if isinstance(a, tuple) else a for a in n] for n in self.nodes]

    def _walk(self, where: str, tree: ast.AST, depth: int) -> int:
        if depth > _MAX_DEPTH:
            raise PendcliError(f"{where}: a stored expression nested more than {_MAX_DEPTH} deep")
        if isinstance(tree, ast.Name) and tree.id in CONSTANTS:
            return self.add((tree.id,))
        if isinstance(tree, ast.Call) and isinstance(tree.func, ast.Call):  # Function('f')(x)
            function = self._walk(where, tree.func, depth + 1)
            if self.nodes[function][0] == "Function" and not tree.keywords:
                args = (self._walk(where, a, depth + 1) for a in tree.args)
                return self.add((APPLY, function, *args))
        elif isinstance(tree, ast.Call) and isinstance(tree.func, ast.Name):
            head = tree.func.id
            if head in LEAVES:
                return self.add(_leaf(where, head, tree))
            if head in HEADS and not tree.keywords:
                return self.add((head, *(self._walk(where, a, depth + 1) for a in tree.args)))
        shown = ast.dump(tree)[:60]
        raise PendcliError(f"{where}: a stored expression holds what the grammar refuses: {shown}")


def _literal(where: str, tree: ast.AST) -> Any:
    if isinstance(tree, ast.Constant) and isinstance(tree.value, (int, str, bool)):
        if type(tree.value) is int and abs(tree.value) > _MAX_INTEGER:
            raise PendcliError(f"{where}: a stored integer beyond {_MAX_INTEGER:.0e}")
        return tree.value
    if isinstance(tree, ast.UnaryOp) and isinstance(tree.op, ast.USub):
        value = _literal(where, tree.operand)
        if type(value) is int:
            return -value
    shown = ast.dump(tree)[:60]
    raise PendcliError(f"{where}: a stored expression holds what the grammar refuses: {shown}")


def _leaf(where: str, head: str, tree: ast.Call) -> Node:
    """A leaf's node from its srepr call, its literals checked as a table's are."""
    args = [_literal(where, a) for a in tree.args]
    if any(k.arg is None for k in tree.keywords):
        raise PendcliError(f"{where}: a stored expression with ** arguments")
    keywords = {str(k.arg): _literal(where, k.value) for k in tree.keywords}
    if head == "Dummy":
        args.append(keywords.pop("dummy_index", 0))
    if head == "Float":
        args.append(keywords.pop("precision", 53))
    if head in ("Symbol", "Dummy") and keywords:
        args.append(keywords)
        keywords = {}
    if keywords or not _leaf_ok(head, args):
        raise PendcliError(f"{where}: a {head} with arguments the store does not take")
    return (head, *(tuple(a.items()) if isinstance(a, dict) else a for a in args))


@cache
def read_expr(where: str, text: str) -> Any:
    """A sympy expression from its ``srepr``, read by the closed grammar (:class:`NodeWriter`):
    anything else is an error naming ``where``. Nothing is evaluated as code."""
    writer = NodeWriter(where)
    index = writer.encode(where, text)
    return writer.table(where).expr(index)
