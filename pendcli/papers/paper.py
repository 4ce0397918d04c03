"""The contract of a paper: everything the rest of pendcli may ask of one.

Each paper package (``pendcli/papers/<key>/__init__.py``) declares one :class:`Paper`, and
:mod:`pendcli.papers.registry` lists them. A paper names each hook by where it lives,
``hook("package.module:name")`` (:class:`Hook`): the module is imported only when the hook is
first called, so building a ``Paper`` (and ``pendcli --help``) loads nothing heavy, and a
paper imports no module of the program above it (its CLI sub-app is a place, not an import).
A place whose module or name does not exist is a load error naming the paper's hook
(:func:`check_hooks`, run by the tests on every paper). A hook a paper does not have is
``None``: callers test for ``None``, never for an attribute's presence.

The published data stay in ``tables/`` (the paths are fixed by the key, see
:meth:`Paper.tables`): ``published/<key>.toml`` (the printed numbers), ``equations/<key>.toml``
(the equation ledger, optional) and ``papers/<key>.txt`` (the OCR'd text).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, fields
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from pendcli.verify.causes import Procedure
    from pendcli.verify.claims import ClaimRow, FormulaRow, Recomputed

__all__ = ["CliApp", "Hook", "Paper", "PaperTables", "check_hooks", "hook", "merged", "modules"]


@dataclass(frozen=True)
class Hook:
    """A hook by its places, each ``"package.module:name"``, resolved when called: a function
    is called with the hook's arguments, anything else (a table, a Typer app) is returned as
    it is;
    several places are mappings merged in order (a later place's keys win); a place without a
    name (``"package.module"``) is a module imported for its side: the hook returns None."""

    places: tuple[str, ...]

    def __call__(self, *args: Any) -> Any:
        found = [_resolved(place) for place in self.places]
        if all(":" not in place for place in self.places):
            return None
        if len(found) > 1:
            return {key: value for mapping in found for key, value in mapping.items()}
        return found[0](*args) if inspect.isroutine(found[0]) else found[0]


def hook(place: str) -> Hook:
    """The hook at ``place``, ``"package.module:name"``."""
    return Hook((place,))


def merged(*places: str) -> Hook:
    """One mapping from the mappings at ``places`` (a later one's keys win)."""
    return Hook(places)


def modules(*names: str) -> Hook:
    """A hook that imports the modules ``names`` (a paper's preload)."""
    return Hook(names)


def _resolved(place: str) -> Any:
    """What ``place`` names: the module, or its attribute after the colon."""
    import importlib

    from pendcli.base.errors import PendcliError

    module_name, _, name = place.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        raise PendcliError(f"the hook {place!r}: no module {exc.name!r}") from None
    if not name:
        return module
    if not hasattr(module, name):
        raise PendcliError(f"the hook {place!r}: {module_name} has no {name!r}") from None
    return getattr(module, name)


def check_hooks(paper: Paper) -> list[str]:
    """Every hook place of ``paper`` that does not resolve, with why (importing each module)."""
    from pendcli.base.errors import PendcliError

    problems = []
    hooks = [getattr(paper, f.name) for f in fields(paper)]
    if paper.cli is not None:
        hooks.append(paper.cli.load)
    for one in hooks:
        for place in one.places if isinstance(one, Hook) else ():
            try:
                _resolved(place)
            except PendcliError as exc:
                problems.append(f"{paper.key}: {exc}")
    return problems


@dataclass(frozen=True)
class PaperTables:
    """Where a paper's data live under ``tables/``."""

    published: Path  # the printed numbers (required)
    ledger: Path  # the equation ledger (may be absent)
    text: Path  # the OCR'd text


@dataclass(frozen=True)
class CliApp:
    """A paper's `pendcli <key> ...` sub-app: its one-line help and how to load it."""

    help: str
    load: Callable[[], Any]  # -> typer.Typer (typer is not imported to build a Paper)


@dataclass(frozen=True)
class Paper:
    """One reproduced paper: its key and every hook the program calls on it.

    ``recompute`` is the only required hook: every paper has printed numbers. The others:
    ``formula_checks`` (derived formulas against numerical solutions), ``references`` (each
    reference a ledger row cites, by name, to its builder), ``author_procedures`` (how the
    author obtained a printed value from his earlier ones, :mod:`pendcli.verify.causes`),
    ``tradeoff_families`` (work-precision families, :mod:`pendcli.run.tradeoff`),
    ``stability_rows`` (:mod:`pendcli.run.stability`), ``figures`` (the report's figures of the
    claims, into a folder, from the judged claim rows), ``formula_figures`` (residual figures of
    the formula rows), ``captions`` (figure file stem -> caption), ``explanations`` (the
    author's hand computations that ``pendcli explain`` searches, :mod:`pendcli.verify.explain`)
    and ``cli`` (the sub-app).
    """

    key: str
    recompute: Callable[[], Mapping[str, Recomputed]]
    formula_checks: Callable[[], Sequence[FormulaRow]] | None = None
    # reference name -> its builder (a Reference or Numbers): what the ledger's rows cite
    references: Callable[[], Mapping[str, Callable[[], Any]]] | None = None
    # imports what recompute and formula_checks run, so that a forked worker inherits it
    preload: Callable[[], None] | None = None
    author_procedures: Callable[[], Mapping[str, Procedure]] | None = None
    tradeoff_families: Callable[[], Sequence[Any]] | None = None  # -> tradeoff.Family
    stability_rows: Callable[[], list[dict[str, str]]] | None = None
    figures: Callable[[Path, list[ClaimRow]], Sequence[Path]] | None = None
    formula_figures: Callable[[Path, list[FormulaRow]], Sequence[Path]] | None = None
    captions: Callable[[], Mapping[str, str]] | None = None
    explanations: Callable[[], Any] | None = None  # -> verify.explain.Declared (`explain`)
    cli: CliApp | None = None

    def citation(self) -> str:
        """The full citation, as its published table records it (never retyped here)."""
        from pendcli.data.tables import load_paper_table

        return load_paper_table(self.key).citation

    def tables(self, root: Path) -> PaperTables:
        """The paper's files under the tables folder ``root``."""
        return PaperTables(
            published=root / "published" / f"{self.key}.toml",
            ledger=root / "equations" / f"{self.key}.toml",
            text=root / "papers" / f"{self.key}.txt",
        )
