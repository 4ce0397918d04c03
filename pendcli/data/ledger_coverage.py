"""Coverage of a paper's text by its ledger: the display formulas (``$$`` blocks) of
``tables/papers/<paper>.txt`` that lie inside some row's ``lines``, over all of them."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from pendcli.data.ledger import load_ledger
from pendcli.data.ledger_rows import Ledger
from pendcli.data.tables import read_table_text
from pendcli.data.text_blocks import DisplayBlock, blocks_covered, display_blocks

__all__ = ["TextCoverage", "ledger_text_coverage", "text_coverage"]


@dataclass(frozen=True)
class TextCoverage:
    paper: str
    blocks: int
    covered: int
    uncovered: tuple[DisplayBlock, ...]

    def as_dict(self) -> dict[str, object]:
        """The keys ``pendcli equations`` adds to a paper's coverage."""
        share = self.covered / self.blocks if self.blocks else 1.0
        return {
            "blocks": self.blocks,
            "blocks_covered": self.covered,
            "blocks_share": round(share, 4),
            "uncovered_lines": [b.first for b in self.uncovered],
        }


def text_coverage(ledger: Ledger) -> TextCoverage:
    """Which of the text's display blocks the ledger's rows cover."""
    blocks = display_blocks(read_table_text(ledger.text, "paper text"))
    spans = [r.lines for r in ledger.rows if r.lines is not None]
    flags = blocks_covered(blocks, spans)
    uncovered = tuple(b for b, ok in zip(blocks, flags, strict=True) if not ok)
    return TextCoverage(ledger.paper, len(blocks), len(blocks) - len(uncovered), uncovered)


def ledger_text_coverage(paper: str, root: Path | None = None) -> TextCoverage:
    return text_coverage(load_ledger(paper, root))
