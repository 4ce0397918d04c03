"""Run every claim (and formula check) of the chosen papers: the data behind `reproduce`."""

from __future__ import annotations

import sys
from dataclasses import dataclass, field

from pendcli.core.claims import FORMULA_VERDICTS, ClaimRow, FormulaRow, evaluate_paper
from pendcli.core.verdict import CLAIM_VERDICTS
from pendcli.papers import formula_checks
from pendcli.render.columns import Column, Row, Section

__all__ = ["ReproduceResult", "reproduce_all"]


@dataclass
class ReproduceResult:
    papers: tuple[str, ...]
    claims: dict[str, list[ClaimRow]] = field(default_factory=dict)
    formulas: dict[str, list[FormulaRow]] = field(default_factory=dict)
    stability: list[dict[str, str]] = field(default_factory=list)

    def claim_dicts(self) -> list[dict[str, object]]:
        return [r.as_dict() for key in self.papers for r in self.claims.get(key, [])]

    def formula_dicts(self) -> list[dict[str, object]]:
        return [r.as_dict() for key in self.papers for r in self.formulas.get(key, [])]

    def document(self) -> dict[str, object]:
        """What `--format json` prints (keys described in :mod:`pendcli.core.schema`)."""
        doc: dict[str, object] = {"claims": self.claim_dicts(), "formulas": self.formula_dicts()}
        if self.stability:
            doc["stability"] = self.stability
        return doc

    def sections(self) -> list[Section]:
        """Titled sections for the table and Markdown outputs: claims, formulas, stability."""
        from pendcli.render.views import FORMULA_COLUMNS, claim_columns

        out: list[Section] = []
        for key in self.papers:
            rows = [r.as_dict() for r in self.claims.get(key, [])]
            if rows:
                out.append((f"{key.capitalize()}: claims", rows, claim_columns(rows)))
            frows = [r.as_dict() for r in self.formulas.get(key, [])]
            if frows:
                out.append((f"{key.capitalize()}: derived formulas", frows, FORMULA_COLUMNS))
        if self.stability:
            cols = [Column(k, k) for k in self.stability[0]]
            out.append(("Numerical stability: where each method is accurate", self.stability, cols))
        return out

    def verdict_counts(self) -> dict[str, dict[str, int]]:
        """Per paper: claim verdict -> count, and "formula holds"/"formula fails" -> count."""
        counts: dict[str, dict[str, int]] = {}
        for key in self.papers:
            c: dict[str, int] = {}
            for r in self.claims.get(key, []):
                c[r.verdict] = c.get(r.verdict, 0) + 1
            for f in self.formulas.get(key, []):
                c[f"formula {f.verdict}"] = c.get(f"formula {f.verdict}", 0) + 1
            counts[key] = c
        return counts

    def summary_rows(self) -> list[Row]:
        """One row per paper: how many claims reach each verdict, formulas holding/failing."""
        counts = self.verdict_counts()
        return [
            {
                "paper": key,
                **{v: counts[key].get(v, 0) for v in CLAIM_VERDICTS},
                "formulas holding": counts[key].get("formula holds", 0),
                "formulas failing": counts[key].get("formula fails", 0),
            }
            for key in self.papers
        ]

    def tally(self, key: str) -> str:
        """``"12 agrees, 1 truncated, 5 formula holds"``: the verdicts a paper reached."""
        counts = self.verdict_counts()[key]
        order = (*CLAIM_VERDICTS, *(f"formula {v}" for v in FORMULA_VERDICTS))
        return ", ".join(f"{counts[v]} {v}" for v in order if v in counts)


def reproduce_all(
    keys: tuple[str, ...], formulas: bool = True, quiet: bool = True, stability: bool = False
) -> ReproduceResult:
    """Evaluate the claims (and, if asked, the formula checks and the stability measurements).

    A progress bar on stderr shows the step running, only on a terminal and when not ``quiet``.
    """
    from rich.progress import Progress

    from pendcli.core.console import console

    steps = [(k, "claims") for k in keys] + ([(k, "formulas") for k in keys] if formulas else [])
    if stability:
        steps.append(("all", "stability"))
    result = ReproduceResult(papers=keys)
    hidden = quiet or not sys.stderr.isatty()
    with Progress(console=console(stderr=True), transient=True, disable=hidden) as progress:
        task = progress.add_task("reproducing", total=len(steps))
        for key, what in steps:
            progress.update(task, description=f"{key}: {what}")
            _run_step(result, key, what)
            progress.advance(task)
    return result


def _run_step(result: ReproduceResult, key: str, what: str) -> None:
    if what == "claims":
        result.claims[key] = evaluate_paper(key)
    elif what == "formulas":
        result.formulas[key] = formula_checks(key)
    else:
        from pendcli.stability import stability_rows

        result.stability = stability_rows(result.papers)
