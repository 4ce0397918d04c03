"""Regenerate the generated sections of the docs pages (`make regen`): docs/findings.md,
docs/verdicts.md, docs/schema.md and docs/ENGINE.md (the README links to them).

The pages show real output and the real JSON schema; this module produces both, so nothing
there is typed in. ``python -m tools.docs`` rewrites the text between each pair of markers
(``<!-- sample:start -->`` ... ``<!-- sample:end -->`` for the sample output,
``<!-- causes:start -->`` ... for the counts of the numbers that do not agree, by cause,
``<!-- schema:start -->`` ... ``<!-- schema:end -->`` for the JSON schema from
:mod:`pendcli.output.schema`, ``<!-- ledger:start -->`` ... for the equation ledgers'
coverage, ``<!-- findings:start -->`` ... for their findings by paper); ``--check`` exits 1
if one is stale.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.output.columns import Column, Row
from pendcli.output.markdown import to_markdown

if TYPE_CHECKING:
    from pendcli.data.rows import EquationRow
    from pendcli.run.reproduce import ReproduceResult
    from pendcli.verify.claims import ClaimRow

__all__ = [
    "SECTIONS",
    "causes_section",
    "findings_section",
    "ledger_section",
    "main",
    "sample_section",
    "schema_section",
    "splice",
]


def _reproduce_all(equations: bool = False) -> ReproduceResult:
    from pendcli.papers.registry import PAPERS
    from pendcli.run.reproduce import reproduce_all

    return reproduce_all(PAPERS, formulas=True, equations=equations, quiet=True)


def sample_section(result: ReproduceResult | None = None) -> str:
    from pendcli.output.views import claim_columns

    result = result if result is not None else _reproduce_all()
    summary = result.summary_rows()
    sample = _one_row_of_each_verdict(result.claim_dicts())
    columns = [c for c in claim_columns(sample, with_note=False) if c.key != "source"]
    return "\n".join(
        [
            "Verdicts over all three papers (`pendcli reproduce`):",
            "",
            to_markdown(summary, [Column(k, k) for k in summary[0]]),
            "One row of each verdict from `pendcli reproduce --format markdown` "
            "(notes and sources in the report):",
            "",
            to_markdown(sample, columns),
        ]
    )


def _one_row_of_each_verdict(rows: list[dict[str, object]]) -> list[Row]:
    """The first row (in paper order) of each verdict, with and without an exact model."""
    sample: list[Row] = []
    seen = set()
    for row in rows:
        kind = (row["verdict"], row["exact"] is not None)
        if kind not in seen:
            seen.add(kind)
            sample.append(row)
    return sample


def schema_section() -> str:
    from pendcli.output import schema

    return "\n".join(
        [
            "`pendcli reproduce --format json` prints one object whose keys hold lists of rows, "
            "described below; every paper subcommand prints `claims` and `formulas` the same "
            "way and adds its own keys beside them (`table`, `example`, ...).",
            "",
            schema.markdown(),
        ]
    )


# The README's words for each cause of a printed number that does not agree, in this order.
CAUSE_PHRASES = {
    "arithmetic-slip": "slips of his own",
    "input-rounding": "faithful to his correctly rounded inputs (their rounding is the "
    "distance from the truth, not a slip)",
    "propagated": "carrying an earlier slip",
    "truncation": "truncations",
    "rounding": "roundings",
    "model-approximation": "the model's approximations (an assumption such as g)",
    "misprint": "misprints",
    "derivation-error": "from a wrong formula",
}


def causes_section(result: ReproduceResult | None = None) -> str:
    """The counts of the printed numbers that do not agree, by cause (the rule of
    tables/README.md, as the code computes it), each with its rows: never typed."""
    result = result if result is not None else _reproduce_all()
    lines = [
        "The printed numbers that do not agree with the truth, by cause (`pendcli reproduce`; "
        "each is judged against the truth and against his own procedure on his printed "
        "inputs, and its cause computed by the rule of `tables/README.md`):",
        "",
    ]
    for key in result.papers:
        rows = [r for r in result.claims.get(key, []) if r.verdict != "agrees"]
        lines += _paper_causes(key, rows)
    return "\n".join(lines if len(lines) > 2 else [*lines, "- every printed number agrees."])


def _paper_causes(key: str, rows: list[ClaimRow]) -> list[str]:
    """One bullet per paper with a disagreement: how many, their verdicts against his own
    procedure, then one sub-bullet per cause with its rows."""
    if not rows:
        return []
    by_cause: dict[str, list[str]] = {}
    for r in rows:
        by_cause.setdefault(str(r.cause), []).append(r.id.split(".", 1)[1])
    from pendcli.data.vocabulary import PROCEDURE_VERDICTS

    own = {str(v): sum(r.procedure_verdict == v for r in rows) for v in PROCEDURE_VERDICTS}
    unknown = sum(r.procedure_verdict is None for r in rows)
    conditional = ", ".join(
        f"{n} {word}" for word, n in own.items() if word.startswith("faithful if") and n
    )
    faithful = f"{own['faithful']} faithful" + (f" ({conditional})" if conditional else "")
    lines = [
        f"- **{key.capitalize()}**: {len(rows)} do not agree; against his own procedure "
        f"{own['slip']} are slips, {faithful}, and {unknown} have no known "
        "procedure. By cause:"
    ]
    for cause in (*CAUSE_PHRASES, *sorted(set(by_cause) - set(CAUSE_PHRASES))):
        if ids := by_cause.get(cause):
            phrase = CAUSE_PHRASES.get(cause, "")
            lines.append(f"  - `{cause}`, {phrase}: {len(ids)} ({', '.join(ids)})")
    return lines


@cache
def _ledger_rows() -> tuple[EquationRow, ...]:
    """Every ledger row of the built-in papers, judged once for the sections that show them."""
    from pendcli.papers.registry import PAPERS, equation_rows

    return tuple(equation_rows(PAPERS))


# marker name -> what goes between <!-- name:start --> and <!-- name:end -->
def ledger_section() -> str:
    """Coverage of the equation ledgers: the labels each text prints, rows by status, the
    display formulas and the paragraphs of prose accounted for, and the findings (failing or
    misprinted rows that restate no other)."""
    from pendcli.data.ledger import labels_in_text
    from pendcli.data.ledger_coverage import ledger_text_coverage
    from pendcli.data.reading import reading_coverage
    from pendcli.data.tables import paper_text
    from pendcli.data.vocabulary import STATUSES
    from pendcli.papers.registry import PAPERS
    from pendcli.verify.ledger_evaluation import FINDING_KEYS, coverage

    counts = coverage(_ledger_rows())
    rows: list[Row] = []
    for key in PAPERS:
        text = paper_text(key)
        c = counts[key]
        blocks = ledger_text_coverage(key)
        prose = reading_coverage(key)
        rows.append(
            {
                "paper": key,
                "labels in the text": len(labels_in_text(text)),
                "rows": c["total"],
                **{status: c[status] for status in STATUSES},
                "checked": f"{round(100 * c['checked'] / c['total'])} %",
                "$$ blocks covered": f"{blocks.covered} of {blocks.blocks}",
                "paragraphs of prose read": f"{prose.read} of {prose.paragraphs}",
                **{key: c[key] for key in FINDING_KEYS},
            }
        )
    return to_markdown(rows, [Column(k, k) for k in rows[0]])


def kinds_section() -> str:
    """The ledgers' rows by the kind of check that decides them, per paper (docs/ENGINE.md)."""
    from collections import Counter

    from pendcli.data.ledger import load_ledger
    from pendcli.papers.registry import PAPERS, ledger_papers
    from pendcli.verify.check_kinds import KINDS

    papers = [key for key in PAPERS if key in ledger_papers()]
    counts = {key: Counter(r.kind for r in load_ledger(key).rows) for key in papers}
    rows: list[Row] = []
    for kind in (*KINDS, None):
        cells = {key: counts[key][kind] for key in papers}
        rows.append({"kind": kind or "none (not checked)", **cells, "all": sum(cells.values())})
    totals = {key: sum(counts[key].values()) for key in papers}
    rows.append({"kind": "all", **totals, "all": sum(totals.values())})
    return to_markdown(rows, [Column(k, k) for k in rows[0]])


def findings_section() -> str:
    """The ledgers' findings by paper, from the rows themselves (never typed): each failing
    row (its slip carried by the author's later work) with its label or line, the count of
    misprints (not carried), the rows that only restate another's slip, the OCR readings."""
    from pendcli.data.ledger import load_ledger
    from pendcli.papers.registry import PAPERS

    rows = _ledger_rows()
    lines = []
    for key in PAPERS:
        mine = [r for r in rows if r.paper == key]
        ledger = load_ledger(key)
        lines.append(_findings_line(key, mine, [r.id for r in ledger.readings]))
    return "\n".join(lines) + "\n"


def _findings_line(key: str, rows: list[EquationRow], readings: list[str]) -> str:
    fails = [r for r in rows if r.finding and r.status == "fails"]
    misprints = [r for r in rows if r.finding and r.status == "misprint"]
    restating = [r for r in rows if not r.finding and r.status in ("fails", "misprint")]

    def listed(found: list[EquationRow]) -> str:
        return (": " + ", ".join(_place(r) for r in found)) if found else ""

    restated = ", ".join(f"{_place(r)} ({', '.join(r.restates)})" for r in restating)

    said = [
        f"{len(fails)} fail{'s' if len(fails) == 1 else ''} (the author's later work carries "
        f"the slip){listed(fails)}",
        f"{len(misprints)} misprint{'' if len(misprints) == 1 else 's'} (no later step "
        f"carries it){listed(misprints)}",
        f"{len(restating)} row{'' if len(restating) == 1 else 's'} only restate another's "
        f"slip{': ' + restated if restated else ''}",
        f"OCR readings applied: {', '.join(readings) or 'none'}",
    ]
    total = len(fails) + len(misprints)
    return f"- **{key.capitalize()}**: {total} findings. " + "; ".join(said) + "."


def _place(row: EquationRow) -> str:
    """``(16), line 220`` or ``line 228``; a conditional verdict with its two sides."""
    where = f"line {row.lines[0]}" if row.lines is not None else row.id
    label = f"{row.equation} " if row.equation else ""
    condition = f" [{row.condition.split(' (', 1)[0]}]" if row.condition else ""
    return f"{label}{where}{condition}"


SECTIONS: dict[str, Callable[[], str]] = {
    "sample": sample_section,
    "causes": causes_section,
    "schema": schema_section,
    "ledger": ledger_section,
    "kinds": kinds_section,
    "findings": findings_section,
}
# marker name -> the file holding its markers, relative to the README's folder
SECTION_FILES: dict[str, str] = {
    "sample": "docs/findings.md",
    "causes": "docs/findings.md",
    "schema": "docs/schema.md",
    "ledger": "docs/verdicts.md",
    "kinds": "docs/ENGINE.md",
    "findings": "docs/findings.md",
}


def splice(readme: str, section: str, name: str = "sample") -> str:
    """``readme`` with the text between the ``name`` markers replaced by ``section``."""
    start, end = f"<!-- {name}:start -->", f"<!-- {name}:end -->"
    if start not in readme or end not in readme:
        raise SystemExit(f"README has no {start} ... {end} markers")
    head, rest = readme.split(start, 1)
    _, tail = rest.split(end, 1)
    return f"{head}{start}\n{section}\n{end}{tail}"


def _store_derivations() -> None:
    """Each ledger's derivations stored (verify/derivation_store), for the package's own tables
    only: a tables folder of one's own is derived afresh when judged, never stored."""
    from pendcli.data.tables import tables_dir
    from pendcli.papers.registry import PAPERS, ledger_papers, paper
    from pendcli.verify.derivation_store import stores_here
    from pendcli.verify.ledger_references import store_derivations

    if not stores_here(tables_dir()):
        return
    for key in (k for k in ledger_papers() if k in PAPERS):  # an added paper has no store
        store_derivations(paper(key))


def main(argv: list[str]) -> int:
    """Rewrite (``--check``: compare) the generated sections of the README and docs/schema.md;
    ``--tables``: with the committed tables regenerated from the same run, all written as one
    set (``make regen``). A file edited after it was read here is refused in one line
    (nothing written, the edit kept): the sections take most of a minute to compute."""
    readme = Path(argv[argv.index("--readme") + 1]) if "--readme" in argv else Path("README.md")
    from dataclasses import replace

    from pendcli.base.files import content_digest
    from pendcli.data.tables import read_table_text

    if "--tables" in argv:  # the ledger's derivations first: its statuses are judged from them
        _store_derivations()
    # the ledger only for the committed tables; the README's sections show claims and formulas
    full = _reproduce_all(equations="--tables" in argv)
    result = replace(full, equations={})
    makers = {
        **SECTIONS,
        "sample": lambda: sample_section(result),
        "causes": lambda: causes_section(result),
    }  # one run for all
    old: dict[Path, str] = {}
    new: dict[Path, str] = {}
    for file in dict.fromkeys(SECTION_FILES.values()):
        path = readme if file == "README.md" else readme.parent / file
        old[path] = text = read_table_text(path, file)
        for name in (n for n, f in SECTION_FILES.items() if f == file):
            text = splice(text, makers[name](), name)
        new[path] = text
    # what was read, checked again just before the renames: an edit meanwhile is refused
    read: dict[Path, str | None] = {p: content_digest(t) for p, t in old.items()}
    if "--check" in argv:
        stale = [str(p) for p in new if new[p] != old[p]]
        for stale_path in stale:
            print(f"{stale_path}: a generated section is stale; run `make regen`", file=sys.stderr)
        return 1 if stale else 0
    if "--tables" in argv:
        from pendcli.run.regression import regenerated_tables, rewrite_with

        tables = regenerated_tables(full)
        removed = rewrite_with(tables, new, unchanged=read)
        gone = f"; removed {', '.join(removed)}" if removed else ""
        names = ", ".join(str(p) for p in new)
        print(f"rewrote {len(tables)} tables and {names}{gone}", file=sys.stderr)
        return 0
    from pendcli.base.files import write_set

    changes: dict[Path, str | bytes | None] = {p: t for p, t in new.items() if t != old[p]}
    write_set(changes, read)  # committed: never half written, never over an edit
    return 0


if __name__ == "__main__":
    from pendcli.base.interrupts import run_entry

    sys.exit(run_entry(lambda: main(sys.argv[1:]), "python -m tools.docs"))
