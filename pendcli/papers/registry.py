"""Every paper pendcli reproduces, listed once, in report order.

Each entry is the :class:`~pendcli.core.paper.Paper` its package declares; nothing is found by
a module name at run time. Adding a paper is one folder under ``pendcli/papers/`` and one
line in :data:`_BUILT_IN`. A test adds a paper of its own for the length of a block with
:func:`registered`.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING

from pendcli.core.errors import PendcliError
from pendcli.papers import charbonnier, lecornu, tisserand

if TYPE_CHECKING:
    from pendcli.core.claims import FormulaRow
    from pendcli.core.paper import Paper

__all__ = [
    "PAPERS",
    "all_papers",
    "formula_checks",
    "keys",
    "paper",
    "registered",
    "sharing_formula_rows",
]

_BUILT_IN: tuple[Paper, ...] = (tisserand.PAPER, lecornu.PAPER, charbonnier.PAPER)
_registry: dict[str, Paper] = {p.key: p for p in _BUILT_IN}

# The built-in papers' keys, for callers that need a constant (a schema, a test's ids).
PAPERS: tuple[str, ...] = tuple(p.key for p in _BUILT_IN)


def keys() -> tuple[str, ...]:
    """The keys of every registered paper, in report order."""
    return tuple(_registry)


def all_papers() -> tuple[Paper, ...]:
    return tuple(_registry.values())


def paper(key: str) -> Paper:
    """The paper registered under ``key``; an unknown key is a one-line error."""
    found = _registry.get(key)
    if found is None:
        raise PendcliError(f"unknown paper {key!r}; choose one of {', '.join(_registry)}")
    return found


@contextmanager
def registered(extra: Paper, alone: bool = False) -> Iterator[Paper]:
    """Within the block, ``extra`` is registered after the built-in papers, or (``alone``)
    instead of them: for a test of a paper of its own."""
    if extra.key in _registry:
        raise PendcliError(f"paper {extra.key!r} is already registered")
    before = dict(_registry)
    if alone:
        _registry.clear()
    _registry[extra.key] = extra
    try:
        yield extra
    finally:
        _registry.clear()
        _registry.update(before)


# Rows computed by the running reproduction, by paper: set only inside sharing_formula_rows.
_SHARED: dict[str, list[FormulaRow]] = {}


def formula_checks(key: str) -> list[FormulaRow]:
    """The formula checks of one paper (empty if it has none): the rows a running
    reproduction shares (:func:`sharing_formula_rows`), else computed now."""
    if key in _SHARED:
        return list(_SHARED[key])
    checks = paper(key).formula_checks
    return [] if checks is None else list(checks())


@contextmanager
def sharing_formula_rows(key: str, rows: list[FormulaRow]) -> Iterator[None]:
    """Within the block, :func:`formula_checks` of ``key`` returns ``rows`` (never cached
    beyond it, so a later run with other tables computes afresh)."""
    _SHARED[key] = rows
    try:
        yield
    finally:
        _SHARED.pop(key, None)
