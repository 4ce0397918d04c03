"""Python sources parsed once per test process: the rules over the package's code (imports,
layers, cycles, sizes, precision, the papers' contract) each walk the syntax trees of the same
~190 modules, and parsing them is most of their cost (3 ms a module). The trees are only read
(``ast.walk``): no test changes one another reads."""

from __future__ import annotations

import ast
from functools import cache
from pathlib import Path


@cache
def parsed(text: str) -> ast.Module:
    """``ast.parse(text)``, once per text."""
    return ast.parse(text)


def parsed_file(path: Path) -> ast.Module:
    """The syntax tree of the file ``path`` as it is now (its text read each time)."""
    return parsed(path.read_text(encoding="utf-8"))
