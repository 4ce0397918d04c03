"""Every paper pendcli reproduces, listed once, in report order.

Each entry is the :class:`~pendcli.papers.paper.Paper` its package declares; nothing is found by
a module name at run time. Adding a paper is one folder under ``pendcli/papers/`` and one
line in :data:`_BUILT_IN`. A test adds a paper of its own for the length of a block with
:func:`registered`.

Only the layers above the papers (the CLI, the reproduction, the report) look a paper up by
its key, here; the engines in :mod:`pendcli.base`, :mod:`pendcli.data`, :mod:`pendcli.verify` are
given what they need (a paper's recomputation, its :class:`Paper`), and a paper's own modules call
their own functions.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.base.errors import PendcliError
from pendcli.papers import charbonnier, lecornu, tisserand

if TYPE_CHECKING:
    from pendcli.data.rows import ClaimRow, EquationRow, FormulaRow
    from pendcli.papers.paper import Paper
    from pendcli.verify.explain import Declared
    from pendcli.verify.ledger_evaluation import Part

# The engines load when a function here first needs them: `pendcli --help` lists the papers'
# sub-commands through this module and must stay instant.

__all__ = [
    "PAPERS",
    "all_papers",
    "claim_rows",
    "equation_rows",
    "formula_checks",
    "keys",
    "ledger_papers",
    "paper",
    "registered",
    "resolve_papers",
    "stability_rows",
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


def resolve_papers(name: str | None) -> tuple[str, ...]:
    """All registered papers, or the one named (validated)."""
    known = keys()
    if name is None:
        return known
    key = name.strip().lower()
    if key not in known:
        raise PendcliError(f"unknown paper {name!r}; choose one of {', '.join(known)}")
    return (key,)


def claim_rows(key: str) -> list[ClaimRow]:
    """Every published claim of paper ``key`` judged against its recomputation and, where the
    paper knows the author's procedure, against that procedure on his printed inputs."""
    from pendcli.verify.claims import evaluate_paper

    found = paper(key)
    procedures = found.author_procedures
    return evaluate_paper(key, found.recompute, procedures() if procedures else None)


def formula_checks(key: str) -> list[FormulaRow]:
    """The formula checks of one paper (empty if it has none): the rows a running
    reproduction shares (:func:`~pendcli.verify.claims.sharing_formula_rows`), else computed
    now."""
    from pendcli.verify.claims import shared_formula_rows

    checks = paper(key).formula_checks
    return shared_formula_rows(key, checks if checks is not None else _no_rows)


def _no_rows() -> list[FormulaRow]:
    return []


def stability_rows(keys_: Iterable[str] | None = None) -> list[dict[str, str]]:
    """The stability rows (:mod:`pendcli.run.stability`) of the papers ``keys_`` (default: every
    paper), in the registry's order."""
    wanted = None if keys_ is None else tuple(keys_)
    rows: list[dict[str, str]] = []
    for found in all_papers():
        if found.stability_rows is not None and (wanted is None or found.key in wanted):
            rows += found.stability_rows()
    return rows


def explanations(key: str) -> Declared:
    """The hand computations paper ``key`` declares for ``pendcli explain`` (none: empty)."""
    from pendcli.verify.explain import Declared

    found = paper(key).explanations
    return found() if found is not None else Declared({}, {})


def ledger_papers(root: Path | None = None) -> tuple[str, ...]:
    """The registered papers that have an equation ledger, in the registry's order (a paper
    with equation checks must have its ledger file: a missing one is an error, never skipped)."""
    return tuple(k for k in keys() if paper(k).references is not None)


def equation_rows(
    keys_: Iterable[str], root: Path | None = None, part: Part = (0, 1), measure: bool = True
) -> list[EquationRow]:
    """The equation ledger rows of the papers ``keys_`` (see :func:`pendcli.verify.
    ledger_evaluation.equation_rows`)."""
    from pendcli.verify.ledger_evaluation import equation_rows as ledger_equation_rows

    return ledger_equation_rows([paper(k) for k in keys_], root, part, measure)
