"""The comparison engine: published values (data) joined with recomputations (code).

A paper's claims module (``pendcli.papers.<paper>.claims``) exposes
``recompute() -> dict[id, Recomputed]``.
:func:`evaluate_paper` loads the paper's published table, calls it, and judges every claim.
Every published entry must have a recomputation and every recomputation a published entry:
a claim without a computation is a defect, reported as an error, never silently skipped.
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from types import ModuleType

from pendcli.core.errors import PendcliError
from pendcli.core.tables import PaperTable, PublishedValue, load_paper_table, missing_claim
from pendcli.core.verdict import judge

__all__ = [
    "FORMULA_VERDICTS",
    "PAPERS",
    "ClaimRow",
    "FormulaRow",
    "Recomputed",
    "evaluate_paper",
    "paper_module",
    "resolve_papers",
]

# Every paper pendcli reproduces, in report order. The module pendcli.<key> holds its claims.
PAPERS: tuple[str, ...] = ("tisserand", "lecornu", "charbonnier")


@dataclass(frozen=True)
class Recomputed:
    """A recomputed value in the claim's unit, with the author's model done exactly."""

    value: float
    exact: float | None = (
        None  # the same quantity from a fuller model, where one answers a question
    )
    method: str = ""  # how it was computed, briefly
    note: str = ""  # computed remark (appended to the table's note)


@dataclass(frozen=True)
class ClaimRow:
    """One line of the comparison: what the paper printed against what we recompute."""

    id: str
    paper: str
    source: str
    quantity: str
    unit: str
    published: str
    published_value: float
    recomputed: float
    verdict: str
    abs_diff: float
    rel_diff: float | None
    digits: float
    exact: float | None
    method: str
    note: str

    def as_dict(self) -> dict[str, object]:
        return {k: _json_number(v) for k, v in self.__dict__.items()}


# A derived formula holds or fails against the numerical solution (pendcli.core.formula_engine).
FORMULA_VERDICTS: tuple[str, ...] = ("holds", "fails")


@dataclass(frozen=True)
class FormulaRow:
    """A derived formula checked against a numerical solution of the governing equation."""

    id: str
    paper: str
    source: str
    published: str  # the formula as printed
    recomputed: str  # the formula as found (corrected term, if any)
    verdict: str  # "holds" or "fails"
    claimed_order: float | None
    observed_order: float | None
    note: str
    residuals: tuple[tuple[float, float], ...] = field(default=())  # (parameter, |residual|)

    def as_dict(self) -> dict[str, object]:
        out = {k: _json_number(v) for k, v in self.__dict__.items() if k != "residuals"}
        out["residuals"] = [[_json_number(p), _json_number(r)] for p, r in self.residuals]
        return out


def _json_number(v: object) -> object:
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def paper_module(key: str) -> ModuleType:
    if key not in PAPERS:
        raise PendcliError(f"unknown paper {key!r}; choose one of {', '.join(PAPERS)}")
    return importlib.import_module(f"pendcli.papers.{key}.claims")


def resolve_papers(paper: str | None) -> tuple[str, ...]:
    """All papers, or the one named (validated)."""
    if paper is None:
        return PAPERS
    key = paper.strip().lower()
    if key not in PAPERS:
        raise PendcliError(f"unknown paper {paper!r}; choose one of {', '.join(PAPERS)}")
    return (key,)


def list_rows(keys: Iterable[str]) -> list[dict[str, str]]:
    """Id, paper, source, quantity, printed string and unit of every claim (tables only)."""
    rows = []
    for key in keys:
        for c in load_paper_table(key).claims:
            rows.append(
                {
                    "id": c.id,
                    "paper": c.paper,
                    "source": c.source,
                    "quantity": c.quantity,
                    "published": c.published,
                    "unit": c.unit,
                }
            )
    return rows


def make_row(entry: PublishedValue, result: Recomputed) -> ClaimRow:
    comparison = judge(entry.number, result.value, entry.comparison)
    notes = [n for n in (entry.ocr and f"OCR: {entry.ocr}", entry.note, result.note) if n]
    return ClaimRow(
        id=entry.id,
        paper=entry.paper,
        source=entry.source,
        quantity=entry.quantity,
        unit=entry.unit,
        published=entry.published,
        published_value=entry.number.value,
        recomputed=result.value,
        verdict=comparison.verdict.value,
        abs_diff=comparison.abs_diff,
        rel_diff=comparison.rel_diff,
        digits=comparison.digits,
        exact=result.exact,
        method=result.method,
        note=" ".join(notes),
    )


def join_claims(table: PaperTable, results: dict[str, Recomputed]) -> list[ClaimRow]:
    missing = [c.id for c in table.claims if c.id not in results]
    extra = sorted(set(results) - {c.id for c in table.claims})
    if extra:  # an id renamed or removed in the file: name the file and the id the code uses
        unmatched = f"; the file's {', '.join(missing)} has no computation" if missing else ""
        raise PendcliError(
            f"{missing_claim(table.where, extra[0], 'its recomputation')}{unmatched}"
        )
    if missing:
        raise PendcliError(f"{table.where}: no computation for claim(s) {', '.join(missing)}")
    return [make_row(c, results[c.id]) for c in table.claims]


def evaluate_paper(
    key: str, recompute: Callable[[], dict[str, Recomputed]] | None = None
) -> list[ClaimRow]:
    """Judge every published claim of one paper against its recomputation."""
    table = load_paper_table(key)
    results = (recompute or paper_module(key).recompute)()
    return join_claims(table, results)
