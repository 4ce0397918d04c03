"""Python sources parsed once per test process: the rules over the package's code (imports,
layers, cycles, sizes, precision, the papers' contract) each walk the syntax trees of the same
~190 modules, and parsing them is most of their cost (3 ms a module); walking a tree's nodes
(``ast.walk``, a million nodes in all) is the rest, done once per text too (:func:`walked`).
The trees are only read: no test changes one another reads."""

from __future__ import annotations

import ast
from functools import cache
from pathlib import Path


@cache
def parsed(text: str) -> ast.Module:
    """``ast.parse(text)``, once per text."""
    return ast.parse(text)


@cache
def walked(text: str) -> tuple[ast.AST, ...]:
    """Every node of ``parsed(text)``, in ``ast.walk``'s order, once per text."""
    return tuple(ast.walk(parsed(text)))


def walked_file(path: Path) -> tuple[ast.AST, ...]:
    """Every node of the file ``path`` as it is now (its text read each time)."""
    return walked(path.read_text(encoding="utf-8"))


def parsed_file(path: Path) -> ast.Module:
    """The syntax tree of the file ``path`` as it is now (its text read each time)."""
    return parsed(path.read_text(encoding="utf-8"))
