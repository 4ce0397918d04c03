"""The contract of a paper: everything the rest of pendcli may ask of one.

Each paper package (``pendcli/papers/<key>/__init__.py``) declares one :class:`Paper`, and
:mod:`pendcli.papers.registry` lists them. Every hook is a callable that imports its module
only when called, so building a ``Paper`` (and ``pendcli --help``) loads nothing heavy. A
hook a paper does not have is ``None`` (or an empty default): callers test for ``None``,
never for an attribute's presence.

The published data stay in ``tables/`` (the paths are fixed by the key, see
:meth:`Paper.tables`): ``published/<key>.toml`` (the printed numbers), ``equations/<key>.toml``
(the equation ledger, optional) and ``papers/<key>.txt`` (the OCR'd text).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from pendcli.core.causes import Procedure
    from pendcli.core.claims import FormulaRow, Recomputed

__all__ = ["CliApp", "Paper", "PaperTables"]


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
    author obtained a printed value from his earlier ones, :mod:`pendcli.core.causes`),
    ``tradeoff_families`` (work-precision families, :mod:`pendcli.tradeoff`),
    ``stability_rows`` (:mod:`pendcli.stability`), ``figures`` (the report's figures of the
    claims, into a folder), ``formula_figures`` (residual figures of the formula rows),
    ``captions`` (figure file stem -> caption), ``explanations`` (the author's hand computations
    that ``pendcli explain`` searches, :mod:`pendcli.core.explain`) and ``cli`` (the sub-app).
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
    figures: Callable[[Path], Sequence[Path]] | None = None
    formula_figures: Callable[[Path, list[FormulaRow]], Sequence[Path]] | None = None
    captions: Callable[[], Mapping[str, str]] | None = None
    explanations: Callable[[], Any] | None = None  # -> core.explain.Declared (`explain`)
    cli: CliApp | None = None

    def citation(self) -> str:
        """The full citation, as its published table records it (never retyped here)."""
        from pendcli.core.tables import load_paper_table

        return load_paper_table(self.key).citation

    def tables(self, root: Path) -> PaperTables:
        """The paper's files under the tables folder ``root``."""
        return PaperTables(
            published=root / "published" / f"{self.key}.toml",
            ledger=root / "equations" / f"{self.key}.toml",
            text=root / "papers" / f"{self.key}.txt",
        )
