"""The ledger's types: a row as the ledger records it (:class:`LedgerRow`) and a paper's whole
ledger (:class:`Ledger`), with what the rows are written in (symbols, scopes, readings,
assumptions). Read and validated by :mod:`pendcli.data.ledger`; judged in
:mod:`pendcli.verify`, which imports these types from here."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pendcli.data.ledger_conditions import Assumption
from pendcli.data.ledger_readings import Reading
from pendcli.data.text_blocks import Span
from pendcli.data.vocabulary import EquationStatus as Status

__all__ = ["Ledger", "LedgerRow", "as_strings"]


@dataclass(frozen=True)
class LedgerRow:
    """One equation or stated result, as the ledger records it."""

    id: str
    paper: str
    equation: str
    section: str
    statement: str
    status: Status
    kind: str | None = None
    # ids of the paper's formula checks whose observed order the row shows
    measured: tuple[str, ...] | None = None
    reading: str | None = None
    corrected: str | None = None
    # the wrong term(s) as the OCR text prints them (marked in the HTML)
    wrong_term: str | tuple[str, ...] | None = None
    note: str | None = None
    lines: Span | None = None
    # the words of the text the row rests on (a sentence, a phrase), verbatim from its lines
    quote: str | tuple[str, ...] | None = None
    # the row(s) whose formula it repeats (a definition), or whose slip it only cites or
    # carries (a failing or misprinted row, then no finding of its own)
    restates: str | tuple[str, ...] | None = None
    printed: str | None = None
    reading_formula: str | None = None
    corrected_formula: str | None = None
    reference: str | None = None
    # the later use that decides the blame of a slip (verify/ledger_blame)
    used_at: tuple[int, ...] | None = None
    used: str | tuple[str, ...] | None = None
    unused: str | None = None
    carries: str | None = None
    condition: str | None = None  # "g <= 9.80": the verdict turns there (data/ledger_conditions)
    # the row's own slip judged against the printed input it carries (verify/ledger_step)
    step_from: str | None = None
    step_at: str | None = None
    step_symbols: tuple[tuple[str, str], ...] | None = None
    step_formula: str | None = None
    # the kind's parameters the row gives (verify/check_kinds), validated on load
    parameters: tuple[tuple[str, Any], ...] = ()
    # the reading table's entries that apply to the row (data/ledger_readings), set on load
    readings: tuple[tuple[str, tuple[tuple[str, str], ...]], ...] = ()

    @property
    def wrong_terms(self) -> tuple[str, ...]:
        return as_strings(self.wrong_term)

    @property
    def used_words(self) -> tuple[str, ...]:
        return as_strings(self.used)

    @property
    def restated(self) -> tuple[str, ...]:
        return as_strings(self.restates)

    def read(self, name: str) -> str | None:
        """Formula ``name`` as the engine judges it: the reading table's replacements made."""
        from pendcli.data.ledger_readings import apply_readings

        text: str | None = getattr(self, name)
        return None if text is None else apply_readings(text, self.readings)

    @property
    def quotes(self) -> tuple[str, ...]:
        return as_strings(self.quote)


def as_strings(value: str | tuple[str, ...] | None) -> tuple[str, ...]:
    return (value,) if isinstance(value, str) else value or ()


@dataclass(frozen=True)
class Ledger:
    paper: str
    text: Path
    path: Path
    rows: tuple[LedgerRow, ...]
    # [symbols]: (name, dimension) pairs the formulas of the rows are written in.
    symbols: tuple[tuple[str, str], ...] = ()
    # [[scope]]: a stretch of the text where some letters mean something else (Lecornu's u is
    # a length in § I and a pure number from (32) on): (first, last line), its (name, dim).
    scopes: tuple[tuple[tuple[int, int], tuple[tuple[str, str], ...]], ...] = ()
    # [[reading]]: the OCR's substitutions; [[assumption]]: what the paper leaves unstated
    readings: tuple[Reading, ...] = ()
    assumptions: tuple[Assumption, ...] = ()

    def symbols_for(self, row: LedgerRow) -> dict[str, str]:
        """The symbols ``row``'s formulas are written in: [symbols], then the names of the
        scope whose lines hold the row's first line, which take precedence."""
        table = dict(self.symbols)
        first = row.lines[0] if row.lines is not None else 0
        for (low, high), names in self.scopes:
            if low <= first <= high:
                table.update(names)
        return table

    def labels(self) -> Counter[str]:
        """How many rows each printed label has (stated results, with no label, excluded)."""
        return Counter(r.equation for r in self.rows if r.equation)
