"""The reading table of a paper's OCR text: every substitution the OCR made (γ printed as r, k′
as k, a prime lost, two stacked fractions set on one line), listed once per paper with the
lines where it occurs, and applied to every row there alike (tables/README.md, « Readings »).

A ``[[reading]]`` of a ledger has an ``id``, ``what`` (the substitution, in words), ``lines``
(a list of ``[first, last]`` spans), ``tex`` (the OCR's TeX where it occurs, each within the
spans) and ``replace``: ``[[printed, read], ...]``, the OCR's token as the ledger's formulas
write it (``printed``, the formula exactly as printed) and the author's (empty when the
ledger's symbols already name the OCR's letter apart: Lecornu's ``rg``, the text's r at line
900, where r is another quantity). Every formula of a
row whose lines meet a span (``printed``, ``reading_formula``, ``corrected_formula``,
``step_formula``) is judged with the replacements made, and its output row names the entry:
a reading is never silent, and never a finding about the paper (the OCR made it, not the
author nor the printer).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from pendcli.base.errors import PendcliError
from pendcli.data.text_blocks import Span

__all__ = ["Reading", "apply_readings", "parse_readings", "readings_of"]

_KEYS = ("id", "what", "lines", "tex", "replace")
_ID = re.compile(r"^[a-z0-9][a-z0-9-]*$")
# (entry id, its replacements) as a row keeps them
Applied = tuple[tuple[str, tuple[tuple[str, str], ...]], ...]


@dataclass(frozen=True)
class Reading:
    id: str
    what: str
    lines: tuple[Span, ...]
    tex: tuple[str, ...]
    replace: tuple[tuple[str, str], ...]

    def meets(self, span: Span | None) -> bool:
        return span is not None and any(a <= span[1] and span[0] <= b for a, b in self.lines)

    def shown(self) -> str:
        spans = ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in self.lines)
        return f"{self.what} (OCR reading {self.id}, lines {spans})"


def parse_readings(path: Path, raw: object, text: list[str] | None) -> tuple[Reading, ...]:
    """The ``[[reading]]`` tables, each validated; ``text``: the paper's lines (None: not at
    hand, the TeX is then not looked for)."""
    if raw is None:
        return ()
    if not isinstance(raw, list):
        raise PendcliError(f"{path}: [[reading]] must be an array of tables")
    out: list[Reading] = []
    for index, entry in enumerate(raw):
        where = f"{path}: [[reading]] {index + 1}"
        out.append(_reading(where, entry, text))
    ids = [r.id for r in out]
    if len(set(ids)) != len(ids):
        raise PendcliError(f"{path}: [[reading]] ids must be unique: {ids}")
    return tuple(out)


def _reading(where: str, entry: object, text: list[str] | None) -> Reading:
    if not isinstance(entry, dict) or sorted(entry) != sorted(_KEYS):
        raise PendcliError(f"{where}: keys {', '.join(_KEYS)}, each once")
    if not (isinstance(entry["id"], str) and _ID.match(entry["id"])):
        raise PendcliError(f"{where}: id must be a slug (a-z, 0-9, -)")
    where = f"{where} ({entry['id']})"
    if not isinstance(entry["what"], str) or not entry["what"].strip():
        raise PendcliError(f"{where}: what must say the substitution in words")
    spans = _spans(where, entry["lines"], len(text) if text is not None else None)
    tex = _strings(where, "tex", entry["tex"])
    pairs = entry["replace"]
    if not (isinstance(pairs, list) and all(
            isinstance(p, list) and len(p) == 2 and all(isinstance(s, str) and s.strip()
                                                        for s in p) for p in pairs)):  # fmt: skip
        raise PendcliError(f"{where}: replace = [[printed, read], ...] (non-empty strings)")
    if text is not None:
        for item in tex:
            if not any(item in "\n".join(text[a - 1 : b]) for a, b in spans):
                raise PendcliError(f"{where}: tex {item!r} is not within its lines")
    return Reading(entry["id"], entry["what"], spans, tex, tuple((a, b) for a, b in pairs))


def _spans(where: str, value: object, count: int | None) -> tuple[Span, ...]:
    from pendcli.data.text_blocks import validate_span

    if not isinstance(value, list) or not value:
        raise PendcliError(f"{where}: lines = [[first, last], ...]")
    return tuple(validate_span(where, span, count) for span in value)


def _strings(where: str, key: str, value: object) -> tuple[str, ...]:
    if not (isinstance(value, list) and value and all(isinstance(v, str) and v for v in value)):
        raise PendcliError(f"{where}: {key} must be a non-empty list of strings")
    return tuple(value)


def _pattern(token: str) -> re.Pattern[str]:
    return re.compile(rf"(?<![\w.]){re.escape(token)}(?![\w])")


def apply_readings(text: str, applied: Applied) -> str:
    """``text`` (a formula of the ledger's notation) with each replacement made."""
    for _, pairs in applied:
        for printed, read in pairs:
            text = _pattern(printed).sub(read, text)
    return text


def readings_of(
    readings: Sequence[Reading],
    span: Span | None,
    formulas: Iterable[str | None],
    text: list[str] | None,
) -> Applied:
    """The entries that apply to a row at ``span`` with these formulas: those whose lines meet
    the row's and whose replacements change one of its formulas or whose TeX is printed
    within the row's lines (``text``: the paper's lines, None when not at hand)."""
    texts = [f for f in formulas if f]
    printed = "" if span is None or text is None else "\n".join(text[span[0] - 1 : span[1]])
    return tuple(
        (r.id, r.replace)
        for r in readings
        if r.meets(span)
        and (
            any(_pattern(p).search(t) for p, _ in r.replace for t in texts)
            or any(item in printed for item in r.tex)
        )
    )
