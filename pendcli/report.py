"""Write the reproduction report: ``out/report.md`` plus its tables and figures.

Everything written here is byte-identical run to run on the same machine (no timestamps,
fixed plot metadata): the work-precision tables under ``out/tradeoff/`` are copies of the
committed ``tables/tradeoff/*.csv`` (measured by ``make bench``, on the date the report names)
unless ``--measure`` times them now, which the report then says.

The folder is built beside ``out`` and swapped in whole (:func:`pendcli.core.files.
replace_directory`); the figures are drawn in two forked processes where two cores exist
(``PENDCLI_JOBS=1`` draws them here), the costliest first.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any

from pendcli.core.errors import PendcliError
from pendcli.core.rows import equation_notes, equation_status
from pendcli.core.vocabulary import CLAIM_VERDICTS, EquationStatus, FormulaVerdict, Verdict
from pendcli.render.columns import Column, Row
from pendcli.render.json import to_json
from pendcli.render.markdown import code_span, fence, markdown_text, to_markdown
from pendcli.render.views import FORMULA_COLUMNS, claim_columns
from pendcli.run.reproduce import ReproduceResult

if TYPE_CHECKING:
    from pendcli.core.cache import ResultCache
    from pendcli.core.claims import ClaimRow
    from pendcli.core.explain import ExplainedRow
    from pendcli.core.rows import EquationRow
    from pendcli.run.tradeoff_engine import Point

__all__ = ["write_report"]

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
    from pendcli.core.versions import library_versions

    return [{"item": name, "version": found} for name, found in library_versions()]


def _rel(path: Path, out: Path) -> str:
    return path.resolve().relative_to(out.resolve()).as_posix()


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
    search of :mod:`pendcli.core.explain`), with its coincidence rate, or the space searched."""
    from pendcli.core.explain import COINCIDENCE_THRESHOLD, explain_rows
    from pendcli.papers.registry import explanations

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


def check_out_folder(out: Path | str) -> Path:
    """Refuse an unusable output folder before any computation (one line, exit 2).

    The folder is replaced as a whole, so it must not be the current folder (or hold it), nor a
    file, nor a folder pendcli did not make (:func:`pendcli.core.files.check_owned`: its
    manifest lists every file in it), nor one another run is writing; its nearest existing
    parent must be a writable folder. A symlink is followed: the folder it names is written.
    """
    text = str(out)
    if text.strip() in ("", "."):
        raise PendcliError(
            f"--out {text!r} is the current folder; give a folder of its own, e.g. --out out"
        )
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise PendcliError(f"--out {text!r} is a file, not a folder; give a folder name")
    here = Path.cwd().resolve()
    if path.resolve() in (here, *here.parents):
        raise PendcliError(f"--out {text!r} holds the current folder; give a folder of its own")
    from pendcli.core.files import check_owned, probe_lock, write_through

    check_owned(write_through(path, "--out"), "--out")
    probe_lock(path, "--out")
    parent = path.resolve().parent
    while not parent.exists():
        parent = parent.parent
    from pendcli.core.plotting import cannot_create_in

    problem = "is not a folder" if not parent.is_dir() else cannot_create_in(parent)
    if problem is not None:
        raise PendcliError(f"--out: cannot create folder {text!r}: {parent}: {problem}")
    return path


class _Writer:
    """Writes files under the (temporary) output folder; remembers each one, relative to it."""

    def __init__(self, out: Path, quiet: bool) -> None:
        self.out = out
        self.quiet = quiet
        self.written: list[Path] = []

    def text(self, name: str, text: str) -> Path:
        path = self.out / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        self.written.append(Path(name))
        return path

    def add(self, paths: list[Path]) -> None:
        self.written += [p.relative_to(self.out) for p in paths]

    def status(self, message: str) -> None:
        if not self.quiet:
            from pendcli.core.console import console

            console(stderr=True).print(f"report: {message}")

    def figure_lines(self, figures: list[Path]) -> list[str]:
        """Each figure already written: its image (relative to the report), its caption."""
        lines = []
        for figure in figures:
            caption = figure_caption(figure)
            lines += [f"![{caption}]({_rel(figure, self.out)})", "", f"*{caption}*", ""]
        return lines


def write_report(
    result: ReproduceResult,
    out: Path | str,
    quiet: bool = True,
    measure: bool = False,
    jobs: int | None = None,
    pdf: bool = False,
    cache: ResultCache | None = None,
) -> list[Path]:
    """Write report.md, claims.json, the per-paper CSVs and every figure into ``out`` (and,
    with ``pdf``, each HTML page printed to PDF by headless Chromium).

    With a ``cache`` (:func:`pendcli.run.reproduce.result_cache`), the report's files are read
    from it when a report of the same result was stored (its key: every field of every row
    of ``result``, and the code, tables and versions), else written and stored; never with
    ``measure`` (timings of now) or ``pdf`` (Chromium's output is not pendcli's).

    The whole folder is built beside ``out`` and swapped in at the end, under ``out``'s lock
    (a concurrent run is refused): files of an earlier report that this one does not write
    are gone, and a failure leaves the old ``out`` as it was. The folder's manifest
    (``pendcli-manifest.txt``) lists every file written, and only such a folder is replaced.
    ``measure`` times the speed/accuracy families now instead of reading the committed
    work-precision tables; ``jobs`` processes draw the figures (default: up to 2).
    """
    from pendcli.core.files import MANIFEST, replace_owned_folder
    from pendcli.core.tables import paper_text

    target = check_out_folder(out)
    if pdf:  # refused before anything is written, not after
        from pendcli.html_report import require_chromium

        require_chromium()
    for key in result.papers:  # the HTML pages show them: missing or empty is an error
        paper_text(key)
    written: list[Path] = []

    params = None if cache is None or measure or pdf else {"result": result_digest(result)}

    def fill(folder: Path) -> None:
        stored = cache.get("report", params) if cache is not None and params else None
        if stored is None or not _unpack(stored, folder, written):
            written.extend(_fill(result, folder, quiet, measure, jobs, pdf))
            if cache is not None and params:
                cache.put("report", params, _pack(folder, written))

    replace_owned_folder(target, fill, "--out")
    return [target / p for p in (*written, Path(MANIFEST))]


def result_digest(result: ReproduceResult) -> str:
    """SHA-256 over every field of every row of ``result`` (and its papers, in order)."""
    import hashlib
    import json

    from pendcli.core.cache import rows_to_json

    rows = {
        name: {key: rows_to_json(table[key]) for key in sorted(table)}
        for name, table in (
            ("claims", result.claims),
            ("formulas", result.formulas),
            ("equations", result.equations),
        )
    }
    every = {"papers": list(result.papers), **rows, "stability": result.stability}
    return hashlib.sha256(json.dumps(every, sort_keys=True).encode()).hexdigest()


def _pack(folder: Path, names: list[Path]) -> dict[str, Any]:
    """The report's files (relative name -> base64 of the bytes), to be stored."""
    import base64

    files = {n.as_posix(): base64.b64encode((folder / n).read_bytes()).decode() for n in names}
    return {"files": files}


def _unpack(entry: Any, folder: Path, written: list[Path]) -> bool:
    """Write a stored report into ``folder`` (and its names into ``written``); False, with
    nothing written, when the entry is not a stored report (:func:`_stored_files`)."""
    decoded = _stored_files(entry)
    if decoded is None:
        return False
    for name, data in decoded.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_bytes(data)
    written.extend(decoded)
    return True


# A stored report's file names are names pendcli writes: relative paths of at most
# _STORED_DEPTH parts (each a letter, digit or "_", then those or ".", "+", "-"), at most
# _STORED_NAME characters, at most _STORED_FILES of them.
_STORED_PART = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.+-]{0,99}")
_STORED_DEPTH, _STORED_NAME, _STORED_FILES = 8, 200, 1000


def _stored_files(entry: Any) -> dict[Path, bytes] | None:
    """The files of a stored report, name -> bytes; None unless ``entry`` is ``{"files":
    {name: base64}}`` with 1 to _STORED_FILES names of the form above, none of them the
    manifest nor a folder of another, each with strict base64."""
    import base64
    import binascii

    from pendcli.core.files import MANIFEST

    files = entry.get("files") if isinstance(entry, dict) and set(entry) == {"files"} else None
    if not isinstance(files, dict) or not 0 < len(files) <= _STORED_FILES:
        return None
    names = set(files)
    if MANIFEST in names or not all(_stored_name(n) for n in names):
        return None
    if any(
        name.rsplit("/", i)[0] in names for name in names for i in range(1, name.count("/") + 1)
    ):
        return None  # "zz" and "zz/b": a file where a folder must be
    try:
        return {Path(n): base64.b64decode(d, validate=True) for n, d in files.items()}
    except (TypeError, ValueError, binascii.Error):
        return None


def _stored_name(name: object) -> bool:
    if not isinstance(name, str) or len(name) > _STORED_NAME:
        return False
    parts = name.split("/")
    return len(parts) <= _STORED_DEPTH and all(_STORED_PART.fullmatch(p) for p in parts)


def _fill(
    result: ReproduceResult,
    folder: Path,
    quiet: bool,
    measure: bool,
    jobs: int | None,
    pdf: bool = False,
) -> list[Path]:
    """Every file of the report, written into ``folder``; their paths relative to it."""
    from pendcli.html_report import markdown_for_a_reader
    from pendcli.run.regression import regenerated_tables

    writer = _Writer(folder, quiet)
    tradeoff = _tradeoff_data(result.papers, measure, writer)  # timings first, alone
    tasks = _figure_tasks(result, folder, tradeoff)
    writer.status(f"drawing {len(tasks)} sets of figures")
    with _Drawing(tasks, jobs) as drawing:
        writer.text("claims.json", to_json(result.document()))
        for name, table in regenerated_tables(result).items():
            writer.text(f"tables/{name}", table)
        figures = drawing.results()
    writer.status(f"drew {sum(p.suffix == '.png' for ps in figures.values() for p in ps)} figures")
    lines = _introduction(result)
    for key in result.papers:
        lines += _paper_section(result, key, writer, figures.get(key, []))
    lines += _stability_section(result)
    lines += _tradeoff_section(writer, tradeoff, figures.get("tradeoff", []))
    lines += _environment_section()
    writer.text("report.md", markdown_for_a_reader("\n".join(lines)))
    pages = _html_pages(result, folder, figures)
    writer.add(pages)
    if pdf:  # inside the folder being built, so the manifest lists the PDFs too
        from pendcli.html_report import print_pdfs

        writer.status(f"printing {len(pages)} pages to PDF")
        writer.add(print_pdfs(folder))
    return writer.written


def _html_pages(
    result: ReproduceResult, folder: Path, figures: dict[str, list[Path]]
) -> list[Path]:
    """report.html and one annotated page per paper, figures embedded with their captions."""
    from pendcli.html_report import Figure, write_for_result

    captioned = {
        ("" if key == "tradeoff" else key): [
            Figure(p, figure_caption(p)) for p in paths if p.suffix == ".png"
        ]
        for key, paths in figures.items()
    }
    return write_for_result(result, folder, captioned, result.equations)


def _introduction(result: ReproduceResult) -> list[str]:
    from pendcli.summary import propagation_tree

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


def _paper_section(
    result: ReproduceResult, key: str, writer: _Writer, figures: list[Path]
) -> list[str]:
    """Citation, assumptions, verdicts, the claim, formula and equation tables, the figures."""
    from pendcli.core.tables import load_paper_table

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
    writer.add(figures)
    if figures:
        lines += ["### Figures", "", *writer.figure_lines(figures)]
    return lines


def _equation_section(rows: list[EquationRow]) -> list[str]:
    """Coverage of the ledger by status, then every equation that fails or is misprinted."""
    if not rows:
        return []
    from pendcli.core.ledger import FINDING_KEYS, coverage
    from pendcli.core.vocabulary import STATUSES

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


def figure_caption(path: Path) -> str:
    """The caption of a report figure: its paper's ``captions``, or the tradeoff's ``CAPTION``."""
    from pendcli.papers.registry import all_papers

    for paper in all_papers():
        captions = paper.captions() if paper.captions is not None else {}
        if path.stem in captions:
            return str(captions[path.stem])
    if path.stem == "work-precision":
        from pendcli.run.tradeoff import CAPTION

        return str(CAPTION)
    return path.stem.replace("_", " ")


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


def _tradeoff_section(writer: _Writer, data: _Tradeoff | None, figures: list[Path]) -> list[str]:
    if data is None:
        return []
    writer.add(figures)
    return [
        "## Speed against accuracy",
        "",
        "Work-precision diagrams: the worst error each method reaches against an "
        "independent reference, against its time per evaluation (`pendcli tradeoff`). "
        f"Timings: {data.provenance}.",
        "",
        *writer.figure_lines([f for f in figures if f.suffix == ".png"]),
    ]


def _environment_section() -> list[str]:
    return [
        "## Environment",
        "",
        to_markdown(_environment(), [Column("item", "item"), Column("version", "version")]),
        "Made by `pendcli reproduce --out DIR` (`make reproduce`).",
        "",
    ]


@dataclass
class _Tradeoff:
    """The work-precision points of the chosen papers and where their timings come from."""

    points: list[Point]
    provenance: str


def _tradeoff_data(keys: tuple[str, ...], measure: bool, writer: _Writer) -> _Tradeoff | None:
    """The families' tables, copied from the committed ones or (``measure``) measured now,
    written under ``tradeoff/``."""
    from pendcli.run import tradeoff, tradeoff_engine

    names = tradeoff.family_names(keys)
    if not names:
        return None
    points: list[Point] = []
    fresh = []
    for name in names:
        committed = tradeoff_engine.table_path(name)
        if measure or not committed.is_file():
            writer.status(f"measuring {name}")
            measured = tradeoff.measure_family(name)
            tradeoff_engine.write_table(measured, writer.out / "tradeoff" / f"{name}.csv")
            writer.written.append(Path("tradeoff") / f"{name}.csv")
            points += measured
            fresh.append(name)
        else:  # validated (UTF-8, every cell) before it is copied
            points += tradeoff_engine.read_table(committed)
            writer.text(f"tradeoff/{name}.csv", committed.read_text(encoding="utf-8"))
    return _Tradeoff(points, _provenance(tradeoff_engine, names, fresh))


def _provenance(tradeoff: ModuleType, names: list[str], fresh: list[str]) -> str:
    if len(fresh) == len(names):
        return "measured now, by this run, on the machine that wrote this report"
    date = tradeoff.measured_on()
    when = f"measured {date} by `make bench`" if date else "measured by `make bench`"
    text = f"committed tables `tables/tradeoff/<family>.csv`, {when}"
    if fresh:
        text += f" (measured now: {', '.join(fresh)}, whose committed table is missing)"
    return text + "; `pendcli reproduce --out DIR --measure` measures them again"


# (paper or "tradeoff", "claims"/"formulas"/"tradeoff", the drawing function, its arguments):
# each figure is drawn by one call, in any process
_Task = tuple[str, str, Callable[..., Any], tuple[Any, ...]]


def _figure_tasks(result: ReproduceResult, folder: Path, tradeoff: _Tradeoff | None) -> list[_Task]:
    """Every figure to draw, the costliest first (so two processes finish together)."""
    from pendcli.papers.registry import paper

    tasks: list[_Task] = []
    for key in result.papers:
        formula_figures = paper(key).formula_figures
        if key in result.formulas and formula_figures is not None:
            args = (folder / "figures" / key / "formulas", result.formulas[key])
            tasks.append((key, "formulas", formula_figures, args))
    if tradeoff is not None:
        from pendcli.run.tradeoff import plot_tradeoff

        path = folder / "tradeoff" / "work-precision.png"
        tasks.append(("tradeoff", "tradeoff", plot_tradeoff, (tradeoff.points, path)))
    for key in result.papers:
        claim_figures = paper(key).figures
        if claim_figures is not None:
            tasks.append((key, "claims", claim_figures, (folder / "figures" / key,)))
    return tasks


def _draw(function: Callable[..., Any], args: tuple[Any, ...]) -> list[Path]:
    """Draw one task (in a worker process or this one); the files it wrote."""
    out = function(*args)
    return [Path(p) for p in out] if isinstance(out, list | tuple) else [Path(out)]


def _draw_task(task: _Task) -> list[Path]:
    _, _, function, args = task
    return _draw(function, args)


def _task_name(task: _Task) -> str:
    """``tisserand claims figures``, ``tradeoff figures``: what a dead worker was drawing."""
    return " ".join(dict.fromkeys(task[:2])) + " figures"


class _Drawing:
    """Draws the tasks in ``jobs`` processes: this one and forked workers (core/workers.py)."""

    def __init__(self, tasks: list[_Task], jobs: int | None) -> None:
        from pendcli.core.workers import ForkedWorkers, job_count

        self.tasks = tasks
        self.workers = ForkedWorkers(job_count(jobs, len(tasks)) - 1)

    def __enter__(self) -> _Drawing:
        if self.workers.processes:
            _pyplot()  # once, here: the forked workers inherit it
        self.workers.__enter__()
        return self

    def results(self) -> dict[str, list[Path]]:
        """Figures per paper (and "tradeoff"), claim figures before formula figures."""
        drawn = self.workers.share(self.tasks, _draw_task, name=_task_name)
        by_key: dict[str, list[Path]] = {}
        for (key, kind, _, _), paths in zip(self.tasks, drawn, strict=True):
            claims_first = kind == "claims"
            by_key.setdefault(key, [])
            by_key[key] = [*paths, *by_key[key]] if claims_first else [*by_key[key], *paths]
        return by_key

    def __exit__(self, *exc: Any) -> None:
        self.workers.__exit__(*exc)


def _pyplot() -> None:
    """Load matplotlib (Agg) before forking the workers, rather than once in each."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot
