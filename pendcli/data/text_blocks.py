"""Where a ledger row is printed: line spans of ``tables/papers/<paper>.txt`` and the text's
display formulas (``$$ ... $$`` blocks), so that coverage is counted over the text itself.

Pure functions over the text; the ledger engine calls them, and knows nothing of LaTeX.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from pendcli.base.errors import PendcliError

__all__ = [
    "DisplayBlock",
    "Span",
    "blocks_covered",
    "display_blocks",
    "validate_span",
]

_DISPLAY = re.compile(r"\$\$(.*?)\$\$", re.DOTALL)

# [first, last]: 1-based, inclusive lines of a paper's text.
Span = tuple[int, int]


@dataclass(frozen=True)
class DisplayBlock:
    """One ``$$ ... $$`` block: its first and last line (1-based) and its LaTeX body."""

    first: int
    last: int
    body: str

    def inside(self, span: Span) -> bool:
        return span[0] <= self.first and self.last <= span[1]


def display_blocks(text: str) -> tuple[DisplayBlock, ...]:
    """Every display formula of the text, in order (an unclosed ``$$`` opens no block)."""
    blocks = []
    for match in _DISPLAY.finditer(text):
        first = text.count("\n", 0, match.start()) + 1
        last = first + match.group(0).count("\n")
        blocks.append(DisplayBlock(first, last, match.group(1)))
    return tuple(blocks)


def blocks_covered(blocks: Iterable[DisplayBlock], spans: Iterable[Span]) -> list[bool]:
    """For each block, whether it lies wholly inside one of the spans."""
    chosen = list(spans)
    return [any(block.inside(span) for span in chosen) for block in blocks]


def validate_span(where: str, value: object, line_count: int | None = None) -> Span:
    """``lines = [first, last]`` as the ledger gives it, checked against the text's length
    (``None``: the text is not at hand, only the shape and the order are checked)."""
    valid = (
        isinstance(value, list)
        and len(value) == 2
        and all(isinstance(v, int) and not isinstance(v, bool) for v in value)
    )
    if not valid:
        raise PendcliError(f"{where}: 'lines' must be [first, last], two line numbers")
    first, last = int(value[0]), int(value[1])  # type: ignore[index]
    last_line = line_count if line_count is not None else last
    if not 1 <= first <= last <= last_line:
        bound = "" if line_count is None else f" <= {line_count} (the text's last line)"
        raise PendcliError(
            f"{where}: 'lines' = [{first}, {last}] must satisfy 1 <= first <= last{bound}"
        )
    return (first, last)
