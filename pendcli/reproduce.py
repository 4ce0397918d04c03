"""Run every claim (and formula check) of the chosen papers: the data behind `reproduce`."""

from __future__ import annotations

from dataclasses import dataclass, field

from pendcli.core.claims import ClaimRow, FormulaRow, evaluate_paper
from pendcli.papers import formula_checks

__all__ = ["ReproduceResult", "reproduce_all"]


@dataclass
class ReproduceResult:
    papers: tuple[str, ...]
    claims: dict[str, list[ClaimRow]] = field(default_factory=dict)
    formulas: dict[str, list[FormulaRow]] = field(default_factory=dict)
    stability: list[dict] = field(default_factory=list)

    def claim_dicts(self) -> list[dict]:
        return [r.as_dict() for key in self.papers for r in self.claims.get(key, [])]

    def formula_dicts(self) -> list[dict]:
        return [r.as_dict() for key in self.papers for r in self.formulas.get(key, [])]

    def document(self) -> dict:
        doc: dict = {"claims": self.claim_dicts(), "formulas": self.formula_dicts()}
        if self.stability:
            doc["stability"] = self.stability
        return doc

    def sections(self) -> list:
        from pendcli.render.views import FORMULA_COLUMNS, claim_columns

        out = []
        from pendcli.render import Column

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
        counts: dict[str, dict[str, int]] = {}
        for key in self.papers:
            c: dict[str, int] = {}
            for r in self.claims.get(key, []):
                c[r.verdict] = c.get(r.verdict, 0) + 1
            for f in self.formulas.get(key, []):
                c[f"formula {f.verdict}"] = c.get(f"formula {f.verdict}", 0) + 1
            counts[key] = c
        return counts


def reproduce_all(
    keys: tuple[str, ...], formulas: bool = True, quiet: bool = True, stability: bool = False
) -> ReproduceResult:
    """Evaluate the claims (and, if asked, the formula checks and the stability measurements)."""
    result = ReproduceResult(papers=keys)
    steps = [(k, "claims") for k in keys] + ([(k, "formulas") for k in keys] if formulas else [])
    if stability:
        steps.append(("all", "stability"))
    with _progress(len(steps), quiet) as advance:
        for key, what in steps:
            advance(f"{key}: {what}")
            if what == "claims":
                result.claims[key] = evaluate_paper(key)
            elif what == "formulas":
                result.formulas[key] = formula_checks(key)
            else:
                from pendcli.stability import stability_rows

                result.stability = stability_rows()
    return result


class _progress:
    """A rich progress bar on stderr when it is a terminal and not quiet; else nothing."""

    def __init__(self, total: int, quiet: bool):
        import sys

        self.enabled = not quiet and sys.stderr.isatty()
        self.total = total

    def __enter__(self):
        if not self.enabled:
            return lambda label: None
        from rich.progress import Progress

        from pendcli.core.console import console

        self.progress = Progress(console=console(stderr=True), transient=True)
        self.progress.__enter__()
        self.task = self.progress.add_task("reproducing", total=self.total)
        first = [True]

        def advance(label: str) -> None:
            if not first[0]:
                self.progress.advance(self.task)
            first[0] = False
            self.progress.update(self.task, description=label)

        return advance

    def __exit__(self, *exc):
        if self.enabled:
            self.progress.__exit__(*exc)
        return False
