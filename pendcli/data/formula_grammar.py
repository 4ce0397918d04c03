"""The ledger's formula notation as a closed grammar: a formula (a row's ``printed`` form, a
dimension's power) becomes a sympy expression without ever being run as Python.

Three steps, each refusing what it does not know, before sympy sees anything:

1. the words (:func:`check_words`): numbers written as digits with at most one decimal
   point, the names the formula may use (its declared symbols, the notation's functions),
   the operators ``+ - * / ** ( ) , < > <= >= = ;`` and spaces. Anything else (a quote, an
   attribute's ``.``, a subscript's ``[``, a keyword, a name not declared, a character
   outside ASCII) is refused, and the formula's length, its words, its bracket depth, the
   signs in a row and the digits of a number are bounded.
2. the tree (:func:`parse_side`): python's own parser (``ast``, which evaluates nothing)
   reads one side of an equation; only sums, differences, products, quotients, powers,
   signs, one comparison, calls of the notation's functions by position (a tuple only as an
   argument of Integral or Derivative), names and numbers pass. Before anything is built,
   a bound on every number sympy could form from it is checked: a power's exponent (a tower
   ``9**9**9`` reaches 9**9 in its exponent), exp's argument, a derivative's order,
   factorial2's argument, and the digits of any product or power.
3. the expression: built from the checked tree node by node with sympy's own operators
   (what ``sympy.parse_expr`` gives for the same text, with no ``eval``).
"""

from __future__ import annotations

import ast
import keyword
import math
import operator
import re
from collections.abc import Callable, Container, Mapping
from fractions import Fraction
from typing import Any

from pendcli.base.errors import PendcliError

__all__ = [
    "ARITY",
    "DECLARED_ARITY",
    "MAX_DEPTH",
    "MAX_EXPONENT",
    "MAX_FACTORIAL2",
    "MAX_FORMED_DIGITS",
    "MAX_FORMULA_CHARS",
    "MAX_NUMBER_DIGITS",
    "MAX_UNARY_RUN",
    "MAX_WORDS",
    "check_side",
    "check_words",
    "parse_side",
    "plain_name",
]

# The bounds, each beside the largest the committed ledgers reach (365 formulas).
MAX_FORMULA_CHARS = 2500  # characters of a formula (committed: 508)
MAX_WORDS = 1500  # numbers, names and operators of a formula (committed: 304)
MAX_DEPTH = 20  # brackets within brackets (committed: 5)
MAX_UNARY_RUN = 4  # signs in a row, as in 2*-(-x) (committed: 1)
MAX_NUMBER_DIGITS = 24  # digits of a number as written (committed: 6, in 0.00313)
# the bound (below) of a power's exponent, exp's argument, a derivative's or besselj's order
# (committed: 12, of p - 3/2 in lecornu.eq.20; 8, of exp(-2*sqrt(x)*tan(omega)); 2; 2)
MAX_EXPONENT = 100
MAX_FACTORIAL2 = 100  # the bound of factorial2's argument (committed: 2, of n + 1)
# digits of any number the arithmetic forms (committed: 19); sympy factors what it roots
MAX_FORMED_DIGITS = 120

NOTATION = "numbers, declared names, + - * / ** ( ) , < > <= >= = ; ..."
_WORD = re.compile(
    r"(?P<number>[0-9][0-9A-Za-z_.]*)|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
    r"|(?P<op>\*\*|<=|>=|[-+*/(),<>=;])|(?P<space>[ \t]+)"
)
_NUMBER = re.compile(r"[0-9]+(?:\.[0-9]+)?")
_PLAIN = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_BINARY: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.Pow: operator.pow,
}
_UNARY: dict[type, Callable[[Any], Any]] = {ast.USub: operator.neg, ast.UAdd: operator.pos}
_COMPARE: dict[type, Callable[[Any, Any], Any]] = {
    ast.Lt: operator.lt,
    ast.Gt: operator.gt,
    ast.LtE: operator.le,
    ast.GtE: operator.ge,
}
_WITH_TUPLES = ("Integral", "Derivative")  # Integral(f, (x, a, b)), Derivative(f, (t, 2))
Arity = tuple[int, int]  # the fewest and the most arguments of a function
# The notation's functions, each with the arguments it takes (sympy's others, such as
# Float's precision, Rational's gcd or sqrt's evaluate, are never passed).
ARITY: dict[str, Arity] = {
    **dict.fromkeys(("sin", "cos", "tan", "atan", "asin", "acos", "exp", "sqrt"), (1, 1)),
    **{"log": (1, 2), "besselj": (2, 2), "factorial2": (1, 1)},
    **{"Rational": (1, 2), "Integer": (1, 1), "Float": (1, 1)},
    **{"Integral": (1, 4), "Derivative": (1, 6)},  # Integral(f, (x, a, b)), Derivative(f, t, 2)
}
DECLARED_ARITY: Arity = (1, 8)  # a function the ledger declares, "E_s()": E_s(t)


def plain_name(name: str) -> bool:
    """A name a ledger may declare: ASCII letters, digits and ``_``, starting with a letter,
    not a Python keyword (``lambda``, ``if``, ``True``) nor a soft one (``match``)."""
    return (
        _PLAIN.fullmatch(name) is not None
        and not keyword.iskeyword(name)
        and not keyword.issoftkeyword(name)
    )


def check_words(where: str, text: str, names: Container[str]) -> None:
    """Refuse ``text`` unless it is words of the notation, within the bounds; ``names``:
    the names it may use (symbols and functions). Raises PendcliError naming ``where``."""
    if len(text) > MAX_FORMULA_CHARS:
        raise PendcliError(
            f"{where}: {len(text)} characters, over the limit of {MAX_FORMULA_CHARS}"
        )
    state = _Words(where)
    position = 0
    while position < len(text):
        match = _WORD.match(text, position)
        if match is None:
            raise PendcliError(
                f"{where}: {text[position]!r} (character {position + 1}) is not in the "
                f"ledger's notation: {NOTATION}"
            )
        position = match.end()
        kind = match.lastgroup
        if kind == "number":
            state.number(match.group())
        elif kind == "name":
            state.name(match.group(), names)
        elif kind == "op":
            state.operator(match.group())
    if state.depth:
        raise PendcliError(f"{where}: cannot parse {_short(text.strip())!r}: a '(' is not closed")


class _Words:
    """The running count, bracket depth and run of signs of :func:`check_words`."""

    def __init__(self, where: str) -> None:
        self.where = where
        self.count = self.depth = self.signs = 0
        self.operand = False  # the last word ends an operand (a sign after it is binary)

    def _word(self, operand: bool) -> None:
        self.count += 1
        if self.count > MAX_WORDS:
            raise PendcliError(f"{self.where}: over the limit of {MAX_WORDS} words")
        self.operand = operand

    def number(self, word: str) -> None:
        if not _NUMBER.fullmatch(word):
            raise PendcliError(f"{self.where}: {word!r} is not a number (digits, one '.')")
        digits = len(word) - word.count(".")
        if digits > MAX_NUMBER_DIGITS:
            raise PendcliError(
                f"{self.where}: a number of {digits} digits, over the limit of {MAX_NUMBER_DIGITS}"
            )
        self._word(True)
        self.signs = 0

    def name(self, word: str, names: Container[str]) -> None:
        if word not in names:
            raise PendcliError(f"{self.where}: {word!r} is not a declared symbol (see [symbols])")
        self._word(True)
        self.signs = 0

    def operator(self, word: str) -> None:
        where = self.where
        unary = word in "+-" and not self.operand
        self.signs = self.signs + 1 if unary else 0
        if self.signs > MAX_UNARY_RUN:
            raise PendcliError(f"{where}: over the limit of {MAX_UNARY_RUN} signs in a row")
        self.depth += (word == "(") - (word == ")")
        if self.depth > MAX_DEPTH:
            raise PendcliError(f"{where}: brackets nested over the limit of {MAX_DEPTH} deep")
        if self.depth < 0:
            raise PendcliError(f"{where}: cannot parse: a ')' closes no bracket")
        if word == "," and not self.depth:
            raise PendcliError(f"{where}: a ',' outside a call's brackets")
        if word in "=;" and self.depth:
            raise PendcliError(f"{where}: a {word!r} inside brackets")
        self._word(word == ")")


def parse_side(
    where: str, text: str, space: Mapping[str, Any], functions: Mapping[str, Arity]
) -> Any:
    """One side of an equation (``text``, its words checked by :func:`check_words`) as a
    sympy expression over ``space`` (name -> sympy object; ``functions``: the names that
    are called, each with its arity: :data:`ARITY`, :data:`DECLARED_ARITY`). Raises
    PendcliError naming ``where`` on anything outside the grammar."""
    return _build(where, text, check_side(where, text, space, functions), space)


def check_side(
    where: str, text: str, names: Container[str], functions: Mapping[str, Arity]
) -> list[ast.AST]:
    """Steps 1 and 2 of :func:`parse_side` without building anything (sympy is not needed):
    the tree of one side, each node in the grammar and every bound checked, its nodes in
    post-order. Raises PendcliError naming ``where``."""
    try:
        tree = ast.parse(text, mode="eval").body
    except SyntaxError as exc:
        raise PendcliError(f"{where}: cannot parse {_short(text)!r}: {exc.msg}") from None
    nodes = _post_order(tree)
    _check_tree(where, text, nodes, names, functions)
    return nodes


def _children(node: ast.AST) -> tuple[ast.AST, ...]:
    if isinstance(node, ast.BinOp):
        return (node.left, node.right)
    if isinstance(node, ast.UnaryOp):
        return (node.operand,)
    if isinstance(node, ast.Compare):
        return (node.left, *node.comparators)
    if isinstance(node, ast.Call):
        return (*node.args, *(k.value for k in node.keywords))  # the callee is a name
    if isinstance(node, ast.Tuple | ast.Starred):
        return tuple(node.elts) if isinstance(node, ast.Tuple) else (node.value,)
    return ()


def _post_order(root: ast.AST) -> list[ast.AST]:
    """The nodes, each after its children (no recursion: a long sum is a deep tree)."""
    out: list[ast.AST] = []
    stack: list[tuple[ast.AST, bool]] = [(root, False)]
    while stack:
        node, done = stack.pop()
        if done:
            out.append(node)
            continue
        stack.append((node, True))
        stack.extend((child, False) for child in reversed(_children(node)))
    return out


def _short(text: str, most: int = 60) -> str:
    return text if len(text) <= most else text[: most - 3] + "..."


def _segment(text: str, node: ast.AST) -> str:
    # the words are ASCII, so the parser's byte offsets are character offsets
    return _short(text[getattr(node, "col_offset", 0) : getattr(node, "end_col_offset", None)])


def _check_tree(
    where: str,
    text: str,
    nodes: list[ast.AST],
    space: Container[str],
    functions: Mapping[str, Arity],
) -> None:
    """Each node of the grammar, and every bound (:func:`_digits`), before anything is built."""
    tuples = {
        id(arg)
        for node in nodes
        if isinstance(node, ast.Call) and getattr(node.func, "id", None) in _WITH_TUPLES
        for arg in node.args
        if isinstance(arg, ast.Tuple)
    }
    digits: dict[int, float] = {}
    sums: dict[int, tuple[float, int]] = {}  # a sum's terms: their digits, their count
    for node in nodes:
        problem = _shape(node, space, functions, id(node) in tuples)
        if problem:
            raise PendcliError(f"{where}: {_segment(text, node)!r}: {problem}")
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add | ast.Sub):
            # k terms over k denominators: a numerator and a denominator of at most
            # k times the product of the terms' bounds
            terms = [sums.get(id(c), (digits[id(c)], 1)) for c in (node.left, node.right)]
            sums[id(node)] = (terms[0][0] + terms[1][0], terms[0][1] + terms[1][1])
            size = sums[id(node)][0] + math.log10(sums[id(node)][1])
        else:
            size = _digits(where, text, node, [digits[id(c)] for c in _children(node)])
        if size > MAX_FORMED_DIGITS:
            raise PendcliError(
                f"{where}: {_segment(text, node)!r} can form a number of 10^{size:.0f}, "
                f"over the limit of {MAX_FORMED_DIGITS} digits"
            )
        digits[id(node)] = size


def _shape(
    node: ast.AST, space: Container[str], functions: Mapping[str, Arity], tuple_ok: bool
) -> str | None:
    """Why ``node`` is outside the grammar, or None."""
    if isinstance(node, ast.BinOp):
        return None if type(node.op) in _BINARY else "not an operator of the notation"
    if isinstance(node, ast.UnaryOp):
        return None if type(node.op) in _UNARY else "not a sign of the notation"
    if isinstance(node, ast.Compare):
        one = len(node.ops) == 1 and type(node.ops[0]) in _COMPARE
        return None if one else "one comparison, <, >, <= or >=, between two sides"
    if isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in functions:
            return "a call of a name that is not a function"
        name = node.func.id
        low, high = functions[name]
        if not low <= len(node.args) <= high or node.keywords:
            return f"{name} takes {low} to {high} arguments, by position"
        return None
    if isinstance(node, ast.Name):
        if node.id in functions:
            return "a function, written without its arguments"
        return None if node.id in space else "not a declared symbol"
    if isinstance(node, ast.Constant):
        return None if type(node.value) in (int, float) else "not a number"
    if isinstance(node, ast.Tuple):
        return None if tuple_ok else "a tuple outside the limits of Integral or Derivative"
    return "not in the ledger's notation"


def _digits(where: str, text: str, node: ast.AST, inner: list[float]) -> float:
    """An upper bound of log10 of any number sympy could form from ``node`` (the largest
    numerator or denominator), given the bounds of its children (a sum's: in
    :func:`_check_tree`): a name counts as 1 (what it cancels to), a product adds its
    factors', a power multiplies its base's by its exponent's bound, checked first."""
    if isinstance(node, ast.Constant):
        value = Fraction(text[node.col_offset : node.end_col_offset])
        return math.log10(max(abs(value.numerator), value.denominator))
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
        _bound(where, text, node.right, "a power's exponent", inner[1], MAX_EXPONENT)
        return float(10 ** inner[1]) * inner[0]
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        return _call_digits(where, text, node, node.func.id, inner)
    return sum(inner)  # a product, a quotient, a sign, a comparison, a tuple, a name: 0


def _call_digits(where: str, text: str, node: ast.Call, name: str, inner: list[float]) -> float:
    """exp(k*log(b)) is b**k and factorial2(n) is n**(n/2) at most: their arguments are
    bounded as an exponent; a derivative's order and a Bessel function's too. Any other
    function of the notation forms nothing much larger than its arguments (sin(pi/6) = 1/2,
    tan(pi/3) = sqrt(3), Rational(p, q)): a factor 2 is left for it."""
    size = sum(inner)
    argument = node.args[0] if node.args else node
    if name == "factorial2":
        _bound(where, text, argument, "factorial2's argument", size, MAX_FACTORIAL2)
        return float(10**size) * max(size, 1.0) / 2
    if name == "exp":
        _bound(where, text, argument, "exp's argument", size, MAX_EXPONENT)
        return float(10**size) * max(size, 1.0)
    if name == "Derivative":
        for arg, order in list(zip(node.args, inner, strict=True))[1:]:
            _bound(where, text, arg, "a derivative's order", order, MAX_EXPONENT)
    if name == "besselj" and inner:  # mpmath's series, asked for its sign, needs its order
        _bound(where, text, node.args[0], "besselj's order", inner[0], MAX_EXPONENT)
    return size + math.log10(2)


def _bound(where: str, text: str, node: ast.AST, what: str, size: float, limit: int) -> None:
    if size > math.log10(limit):
        reach = f"{10**size:.0f}" if size < 15 else f"10^{size:.0f}"
        raise PendcliError(
            f"{where}: {what} {_segment(text, node)!r} can reach {reach}, over the limit of {limit}"
        )


def _build(where: str, text: str, nodes: list[ast.AST], space: Mapping[str, Any]) -> Any:
    """The sympy expression of a checked tree, each node from its children's values."""
    import sympy as sp

    value: dict[int, Any] = {}
    try:
        for node in nodes:
            args = [value[id(c)] for c in _children(node)]
            value[id(node)] = _node_value(text, node, args, space)
    except (TypeError, ValueError, ZeroDivisionError, AttributeError, sp.SympifyError) as exc:
        why = " ".join(str(exc).split())  # sympy's message may span lines
        raise PendcliError(f"{where}: cannot parse {_short(text)!r}: {why}") from None
    return value[id(nodes[-1])]


def _node_value(text: str, node: ast.AST, args: list[Any], space: Mapping[str, Any]) -> Any:
    import sympy as sp

    if isinstance(node, ast.Constant):
        # as sympy's parser reads a number: an integer exactly, a decimal with its digits
        if type(node.value) is int:
            return sp.Integer(node.value)
        return sp.Float(text[node.col_offset : node.end_col_offset])
    if isinstance(node, ast.Name):
        return space[node.id]
    if isinstance(node, ast.BinOp):
        return _BINARY[type(node.op)](*args)
    if isinstance(node, ast.UnaryOp):
        return _UNARY[type(node.op)](*args)
    if isinstance(node, ast.Compare):
        return _COMPARE[type(node.ops[0])](*args)
    if isinstance(node, ast.Call):
        return space[node.func.id](*args)  # type: ignore[attr-defined]
    return tuple(args)  # a tuple, as python makes one: Integral(f, (x, a, b))
