"""The text of ``out/report.md``: its sections, in Markdown, from a reproduction's rows.

Pure text: each section is a list of lines made from the result's rows (and, for a paper
and the speed figures, the figure lines the writer of the folder hands in). Writing the
folder is :mod:`~pendcli.output.report`; drawing the figures, :mod:`~pendcli.output.report_figures`.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from pendcli.data.rows import equation_notes, equation_status
from pendcli.data.vocabulary import CLAIM_VERDICTS, EquationStatus, FormulaVerdict, Verdict
from pendcli.output.columns import Column, Row
from pendcli.output.markdown import code_span, fence, markdown_text, to_markdown
from pendcli.output.views import FORMULA_COLUMNS, claim_columns

if TYPE_CHECKING:
    from pendcli.data.rows import EquationRow
    from pendcli.run.reproduce import ReproduceResult
    from pendcli.verify.claims import ClaimRow
    from pendcli.verify.explain import ExplainedRow

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
order, and `fails` otherwise: residual = reference − formula over the row's small parameter,
claimed order its exponent, `holds` iff the observed order is at least the claimed one minus
0.3 and the residuals stand at least 10 times above the reference's error.

Every printed number is judged twice: against the truth (above) and, where his procedure is
known, against it on his own printed inputs (`faithful`: rounded or chopped, it gives his
digits; `slip`: it does not). Every row that does not agree or hold has a cause, computed for a
number with a procedure by the rule of `tables/README.md`: `propagated` (*from*: an input
that is itself a slip), `arithmetic-slip`, or, faithful, `truncation` or `input-rounding`
(correctly rounded inputs, not a slip). Every cause but `propagated` is a root.
"""


def _environment() -> list[dict[str, str]]:
    from pendcli.base.versions import library_versions

    return [{"item": name, "version": found} for name, found in library_versions()]


def _first_sentence(text: str, limit: int = 220) -> str:
    text = text.removeprefix("OCR: ")
    cut = text.find(". ")
    sentence = text if cut < 0 else text[: cut + 1]
    return sentence if len(sentence) <= limit else sentence[: limit - 1].rstrip() + "…"


def _cause_text(cause: str | None, sources: tuple[str, ...]) -> str:
    if cause is None:
        return ""
    cause = markdown_text(cause)
    if not sources:
        return f" ({cause})"
    return f" ({cause} from {', '.join(map(markdown_text, sources))})"


def _own_text(row: ClaimRow) -> str:
    """The verdict against his own procedure, with his value, or that none is known."""
    if row.procedure_verdict is None or row.procedure_value is None:
        return "no procedure of his known"
    his = markdown_text(f"{row.procedure} = {row.procedure_value:.6g}")
    return f"against his procedure **{row.procedure_verdict}** ({his})"


def disagreement_digest(result: ReproduceResult) -> list[str]:
    """One bullet per printed number that is not `agrees` and per formula that `fails`,
    each with its cause (and, for a carried error, the rows it comes from)."""
    bullets = []
    for key in result.papers:
        for r in result.claims.get(key, []):
            if r.verdict != Verdict.AGREES:
                bullets.append(
                    f"- **{markdown_text(r.id)}** ({markdown_text(r.source)}): printed "
                    f"{code_span(r.published)}, recomputed {r.recomputed:.6g}: "
                    f"**{r.verdict}**{_cause_text(r.cause, r.cause_from)}; "
                    f"{_own_text(r)}. "
                    f"{markdown_text(_first_sentence(r.note))}"
                )
        for f in result.formulas.get(key, []):
            if f.verdict != FormulaVerdict.HOLDS:
                bullets.append(
                    f"- **{markdown_text(f.id)}** {markdown_text(f.source)}: "
                    f"{code_span(f.published)} fails{_cause_text(f.cause, f.cause_from)}; "
                    f"found {code_span(f.recomputed)}."
                )
    return bullets or ["Every printed number and formula holds."]


def explanation_section(result: ReproduceResult) -> list[str]:
    """ "Explanations": how the author got each printed number that does not agree (the
    search of :mod:`pendcli.verify.explain`), with its coincidence rate, or the space searched."""
    from pendcli.papers.registry import explanations
    from pendcli.verify.explain import COINCIDENCE_THRESHOLD, explain_rows

    lines = [
        "## Explanations",
        "",
        "For each printed number that does not agree, the simplest hand computation (fewest "
        "steps away from his own procedure) that gives his digits exactly, and the share of "
        "random targets of the same precision and size the same search reproduces as simply "
        f"(explained at most {COINCIDENCE_THRESHOLD:.0%}; *near*: targets within 10 % of "
        "the printed value). `pendcli explain` prints every step.",
        "",
    ]
    for key in result.papers:
        verdicts = {r.id: (r.verdict, r.cause, r.published) for r in result.claims.get(key, [])}
        for row in explain_rows(key, explanations(key), verdicts):
            if row.verdict != "agrees":
                lines.append(_explanation_line(row))
    return [*lines, ""]


def _explanation_line(row: ExplainedRow) -> str:
    """One bullet of "Explanations": the steps that give the printed digits, the mechanism
    that reproduces them no better than chance, or the space searched."""
    d = row.as_dict()
    head = f"- **{markdown_text(row.id)}** {code_span(row.printed)}:"
    if row.explained:
        steps = " → ".join(d["steps"][0])  # type: ignore[index]
        odds = f"coincidence {d['coincidence']:.1%}, near {d['coincidence_near']:.1%}"
        return f"{head} {markdown_text(row.cause_with_mechanism)} ({odds}). {markdown_text(steps)}."
    cause = markdown_text(str(row.cause))
    if d["mechanism"] is not None:
        odds = f"{d['coincidence']:.1%} of random targets"
        return (
            f"{head} **unexplained** ({cause}): {markdown_text(str(d['mechanism']))} "
            f"reproduces it, and as simply {odds}."
        )
    return f"{head} **unexplained** ({cause}); searched: {markdown_text(str(d['searched']))}."


# The convention every formula note ends with: stated once in the report, not per row.
_CONVENTION = re.compile(
    r"Residual = reference − formula over (?P<parameter>.+?) \(claimed order.*?\)\. "
    r"Reference: (?P<reference>.+?)\.$"
)


def _short_formula_note(row: Row) -> str:
    """The note without the residual convention, keeping its small parameter and reference."""
    note = str(row.get("note", ""))
    return _CONVENTION.sub(r"Small parameter: \g<parameter>; reference: \g<reference>.", note)


def introduction(result: ReproduceResult) -> list[str]:
    from pendcli.output.summary import propagation_tree

    summary = result.summary_rows()
    rows = [*result.claim_dicts(), *result.formula_dicts()]
    tree = propagation_tree(rows)
    lines = [
        "# pendcli reproduction report",
        "",
        "Every numerical claim of three papers on the pendulum, as printed, against its "
        "recomputation with the author's own model (and, where it answers a question about "
        "the claim, a fuller model). Regenerate with `make reproduce`; the same data is in "
        "`claims.json` and `tables/`, and `report.html` shows each paper's text with every "
        "number coloured by its verdict.",
        "",
        "## Summary",
        "",
        to_markdown(summary, [Column(k, k) for k in summary[0]]) if summary else "",
    ]
    if tree:  # the rows' ids as they are: in a code block no line of them can end
        lines += [
            "Where errors enter (roots, with their cause) and the rows that carry them:",
            "",
            fence(tree),
            *tree,
            fence(tree),
            "",
        ]
    return [
        *lines,
        "## What does not hold",
        "",
        *disagreement_digest(result),
        "",
        *explanation_section(result),
        "## How verdicts are decided",
        "",
        _VERDICT_RULES,
    ]


def paper_section(result: ReproduceResult, key: str, figure_lines: list[str]) -> list[str]:
    """Citation, assumptions, verdicts, the claim, formula and equation tables, the figures
    (``figure_lines``: each written figure's image and caption)."""
    from pendcli.data.tables import load_paper_table

    table = load_paper_table(key)
    rows = [r.as_dict() for r in result.claims.get(key, [])]
    text = f"tables/papers/{key}.txt"
    citation = markdown_text(table.citation)
    lines = [f"## {key.capitalize()}", "", f"*{citation}* (text: `{text}`).", ""]
    if table.assumptions:
        lines += ["Assumptions:", ""] + [f"- {markdown_text(a)}" for a in table.assumptions]
        lines += [""]
    counts = result.verdict_counts().get(key, {})
    tally = ", ".join(f"{counts.get(v, 0)} {v}" for v in CLAIM_VERDICTS)
    lines.append(f"Verdicts: {tally} ({len(rows)} claims).")
    lines += ["", "### Claims", "", to_markdown(rows, claim_columns(rows))]
    frows = [f.as_dict() for f in result.formulas.get(key, [])]
    if frows:
        columns = [
            Column("note", "note", fmt=_short_formula_note) if c.key == "note" else c
            for c in FORMULA_COLUMNS
        ]
        lines += ["### Derived formulas", "", to_markdown(frows, columns)]
    lines += _equation_section(result.equations.get(key, []))
    if figure_lines:
        lines += ["### Figures", "", *figure_lines]
    return lines


def _equation_section(rows: list[EquationRow]) -> list[str]:
    """Coverage of the ledger by status, then every equation that fails or is misprinted."""
    if not rows:
        return []
    from pendcli.data.vocabulary import STATUSES
    from pendcli.verify.ledger_evaluation import FINDING_KEYS, coverage

    counts = [{"paper": p, **c} for p, c in coverage(rows).items()]
    keys = ("paper", *STATUSES, "total", "checked", *FINDING_KEYS)
    failing = (EquationStatus.FAILS, EquationStatus.MISPRINT)
    wrong = [r.as_dict() for r in rows if r.status in failing]
    columns = [Column(k, k) for k in ("equation", "section", "statement")]
    columns.append(Column("status", "status", fmt=equation_status))
    columns.append(Column("note", "note", fmt=equation_notes))
    return [
        "### Equation ledger",
        "",
        "Every numbered equation and stated result, checked (`pendcli equations`); the "
        "findings are the failing and misprinted rows that restate no other (one per slip: "
        "`fails` when the author's later work carries it, `misprint` when it does not), the "
        "restating rows only cite or carry another's slip:",
        "",
        to_markdown(counts, [Column(k, k) for k in keys]),
        "Those that fail (with the corrected form the computation found) or are misprinted "
        "(with the evident reading, which then holds):",
        "",
        to_markdown(wrong, columns) if wrong else "None.\n",
    ]


def stability_section(result: ReproduceResult) -> list[str]:
    if not result.stability:
        return []
    return [
        "## Numerical stability: where each method is accurate",
        "",
        "Measured at run time against mpmath or closed forms, far outside the papers' range.",
        "",
        to_markdown(result.stability, [Column(k, k) for k in result.stability[0]]),
    ]


def tradeoff_section(provenance: str, figure_lines: list[str]) -> list[str]:
    """The work-precision diagrams (``figure_lines``) and where their timings come from."""
    return [
        "## Speed against accuracy",
        "",
        "Work-precision diagrams: the worst error each method reaches against an "
        "independent reference, against its time per evaluation (`pendcli tradeoff`). "
        f"Timings: {provenance}.",
        "",
        *figure_lines,
    ]


def environment_section() -> list[str]:
    return [
        "## Environment",
        "",
        to_markdown(_environment(), [Column("item", "item"), Column("version", "version")]),
        "Made by `pendcli reproduce --out DIR` (`make reproduce`).",
        "",
    ]
