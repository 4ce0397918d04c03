"""What the ledger engine needs of a paper: a protocol, so that the engine imports no paper
and no contract above it (:class:`pendcli.papers.paper.Paper` is one)."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from pendcli.data.rows import FormulaRow

__all__ = ["LedgerPaper"]


class LedgerPaper(Protocol):
    """A paper's key, its references' builders by name and its formula checks (each None
    when the paper has none)."""

    @property
    def key(self) -> str: ...

    @property
    def references(self) -> Callable[[], Mapping[str, Callable[[], Any]]] | None: ...

    @property
    def formula_checks(self) -> Callable[[], Sequence[FormulaRow]] | None: ...
