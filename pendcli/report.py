"""Write the reproduction report: ``out/report.md`` plus its tables and figures.

Everything written here is byte-identical run to run on the same machine (no timestamps,
fixed plot metadata), except the work-precision diagrams under ``out/tradeoff/``, which
are timings and vary by nature; the report says so where it links them.
"""

from __future__ import annotations

import importlib
import importlib.util
import platform
from pathlib import Path
from types import ModuleType

from pendcli.core.errors import PendcliError
from pendcli.core.verdict import CLAIM_VERDICTS
from pendcli.render.columns import Column
from pendcli.render.json import to_json
from pendcli.render.markdown import to_markdown
from pendcli.render.views import FORMULA_COLUMNS, claim_columns
from pendcli.reproduce import ReproduceResult

__all__ = ["write_report"]

_PACKAGES = ("pendcli", "numpy", "scipy", "mpmath", "matplotlib", "typer", "rich")

_VERDICT_RULES = """\
A printed number fixes its own precision: `5,14` is known to 0.01, `1°7'33''` to one
second of arc, `2·2/(1·3)` is exact. With `u` the unit of the last printed place:

| verdict | rule |
|---|---|
| agrees | the recomputed value rounds to the printed one: \\|r − p\\| ≤ u/2 |
| truncated | it does not round to it but chops to it (same sign, \\|p\\| ≤ \\|r\\| < \\|p\\| + u) |
| last-digit | neither, but it rounds one unit away: \\|r − p\\| ≤ 3u/2 |
| discrepant | anything else |

An exact printed value agrees only if equal to floating-point accuracy. A claim "at most
p" agrees when the recomputed value, rounded to the printed precision, is ≤ p. A derived
formula `holds` when its residual against a numerical solution vanishes at the claimed
order, and `fails` otherwise.
"""


def _module(name: str) -> ModuleType | None:
    return importlib.import_module(name) if importlib.util.find_spec(name) else None


def _environment() -> list[dict[str, str]]:
    from importlib.metadata import PackageNotFoundError, version

    rows = [{"item": "python", "version": platform.python_version()}]
    rows.append({"item": "platform", "version": f"{platform.system()} {platform.machine()}"})
    for pkg in _PACKAGES:
        try:
            rows.append({"item": pkg, "version": version(pkg)})
        except PackageNotFoundError:
            rows.append({"item": pkg, "version": "not installed"})
    return rows


def _rel(path: Path, out: Path) -> str:
    return path.resolve().relative_to(out.resolve()).as_posix()


def _first_sentence(text: str, limit: int = 220) -> str:
    text = text.removeprefix("OCR: ")
    cut = text.find(". ")
    sentence = text if cut < 0 else text[: cut + 1]
    return sentence if len(sentence) <= limit else sentence[: limit - 1].rstrip() + "…"


def disagreement_digest(result: ReproduceResult) -> list[str]:
    """One bullet per printed number that is not `agrees` and per formula that `fails`."""
    bullets = []
    for key in result.papers:
        for r in result.claims.get(key, []):
            if r.verdict != "agrees":
                bullets.append(
                    f"- **{r.id}** ({r.source}): printed `{r.published}`, recomputed "
                    f"{r.recomputed:.6g}: **{r.verdict}**. {_first_sentence(r.note)}"
                )
        for f in result.formulas.get(key, []):
            if f.verdict != "holds":
                bullets.append(
                    f"- **{f.id}** {f.source}: `{f.published}` fails; found `{f.recomputed}`."
                )
    return bullets or ["Every printed number and formula holds."]


class _Writer:
    """Writes files under the output folder and remembers every path written (in order)."""

    def __init__(self, out: Path | str, quiet: bool) -> None:
        self.out = Path(out)
        self.quiet = quiet
        self.written: list[Path] = []
        try:
            self.out.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise PendcliError(
                f"cannot create output folder {str(self.out)!r}: {exc.strerror}"
            ) from None
        if not self.out.is_dir():
            raise PendcliError(f"--out {str(self.out)!r} is not a folder")

    def text(self, name: str, text: str) -> Path:
        path = self.out / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        self.written.append(path)
        return path

    def status(self, message: str) -> None:
        if not self.quiet:
            from pendcli.core.console import console

            console(stderr=True).print(f"report: {message}")

    def links(self, figures: list[Path]) -> list[str]:
        """Markdown image links to figures already written, relative to the report."""
        return [f"![{fig.stem}]({_rel(fig, self.out)})" for fig in figures]


def write_report(result: ReproduceResult, out: Path | str, quiet: bool = True) -> list[Path]:
    """Write report.md, claims.json, the per-paper CSVs and every figure into ``out``."""
    from pendcli.regression import regenerated_tables

    writer = _Writer(out, quiet)
    writer.text("claims.json", to_json(result.document()))
    for name, text in regenerated_tables(result).items():
        writer.text(f"tables/{name}", text)
    lines = _introduction(result)
    for key in result.papers:
        lines += _paper_section(result, key, writer)
    lines += _stability_section(result)
    lines += _tradeoff_section(writer)
    lines += _environment_section()
    writer.text("report.md", "\n".join(lines))
    return writer.written


def _introduction(result: ReproduceResult) -> list[str]:
    summary = result.summary_rows()
    return [
        "# pendcli reproduction report",
        "",
        "Every numerical claim of three papers on the pendulum, as printed, against its "
        "recomputation with the author's own model (and, where it answers a question about "
        "the claim, a fuller model). Regenerate with `make reproduce`; the same data is in "
        "`claims.json` and `tables/`.",
        "",
        "## Summary",
        "",
        to_markdown(summary, [Column(k, k) for k in summary[0]]) if summary else "",
        "## What does not hold",
        "",
        *disagreement_digest(result),
        "",
        "## How verdicts are decided",
        "",
        _VERDICT_RULES,
    ]


def _paper_section(result: ReproduceResult, key: str, writer: _Writer) -> list[str]:
    """Citation, assumptions, verdicts, the claim and formula tables, and the figures."""
    from pendcli.core.tables import load_paper_table

    table = load_paper_table(key)
    rows = [r.as_dict() for r in result.claims.get(key, [])]
    lines = [f"## {key.capitalize()}", "", f"*{table.citation}* (seed `{table.seed}`).", ""]
    if table.assumptions:
        lines += ["Assumptions:", ""] + [f"- {a}" for a in table.assumptions] + [""]
    counts = result.verdict_counts().get(key, {})
    tally = ", ".join(f"{counts.get(v, 0)} {v}" for v in CLAIM_VERDICTS)
    lines.append(f"Verdicts: {tally} ({len(rows)} claims).")
    lines += ["", "### Claims", "", to_markdown(rows, claim_columns(rows))]
    frows = [f.as_dict() for f in result.formulas.get(key, [])]
    if frows:
        lines += ["### Derived formulas", "", to_markdown(frows, FORMULA_COLUMNS)]
    figures = _paper_figures(result, key, writer)
    writer.written += figures
    if figures:
        lines += ["### Figures", ""]
        for link in writer.links(figures):
            lines += [link, ""]
    return lines


def _paper_figures(result: ReproduceResult, key: str, writer: _Writer) -> list[Path]:
    """The paper's claim figures, then its formula figures (from the rows already computed)."""
    folder = writer.out / "figures" / key
    figures: list[Path] = []
    # papers/<key>/figures.py (the layout of issue 11); claims.py until a paper has moved
    module = _module(f"pendcli.papers.{key}.figures") or _module(f"pendcli.papers.{key}.claims")
    if module is not None and hasattr(module, "figures"):
        writer.status(f"drawing the {key} figures")
        figures += list(module.figures(folder))
    fmodule = _module(f"pendcli.papers.{key}.formulas")
    if fmodule is not None and hasattr(fmodule, "figures"):
        figures += list(fmodule.figures(folder / "formulas", result.formulas.get(key)))
    return figures


def _stability_section(result: ReproduceResult) -> list[str]:
    if not result.stability:
        return []
    return [
        "## Numerical stability: where each method is accurate",
        "",
        "Measured at run time against mpmath or closed forms, far outside the papers' range.",
        "",
        to_markdown(result.stability, [Column(k, k) for k in result.stability[0]]),
    ]


def _tradeoff_section(writer: _Writer) -> list[str]:
    tradeoff = _module("pendcli.tradeoff")
    if tradeoff is None:
        return []
    writer.status("measuring speed against accuracy (about 10 s)")
    figs = _tradeoff_figures(tradeoff, writer.out / "tradeoff")
    writer.written += figs
    return [
        "## Speed against accuracy",
        "",
        "Work-precision diagrams: the worst error each method reaches against an "
        "independent reference, against its time per evaluation (`pendcli tradeoff`). "
        "These are timings on the machine that ran `make reproduce`: unlike every other "
        "file here, `tradeoff/` changes from run to run.",
        "",
        *[f"{link}\n" for link in writer.links([f for f in figs if f.suffix == ".png"])],
    ]


def _environment_section() -> list[str]:
    return [
        "## Environment",
        "",
        to_markdown(_environment(), [Column("item", "item"), Column("version", "version")]),
        "Made by `pendcli reproduce --out DIR` (`make reproduce`).",
        "",
    ]


def _tradeoff_figures(tradeoff: ModuleType, folder: Path) -> list[Path]:
    """Measure every available family, write its table and the work-precision diagram."""
    ready = tradeoff.family_names()
    points = [p for name in ready for p in tradeoff.measure_family(name)]
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for name in ready:
        path = folder / f"{name}.csv"
        tradeoff.write_table([p for p in points if p.family == name], path)
        written.append(path)
    figure = folder / "work-precision.png"
    tradeoff.plot_tradeoff(points, figure)
    return [*written, figure]
