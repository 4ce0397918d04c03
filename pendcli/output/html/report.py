"""``out/report.html`` and ``out/papers/<paper>.html``: the report and an annotated edition.

Each paper page is the paper's OCR text (``tables/papers/<paper>.txt``) as an edition: its
TeX rendered as MathML at build time (:mod:`pendcli.output.html.math`), each printed number,
equation label and stated result marked where it is printed, a misprinted or wrong term
marked itself, and beside each paragraph a numbered note per mark with the verdict and the
reading or the correction. The overview page carries the counts, the propagation graph
(:mod:`pendcli.output.html.graph`) and one entry per finding. The pages come from the Jinja2
templates in ``pendcli/output/html/templates`` (autoescaped; one stylesheet, inlined),
figures are data URIs: nothing is fetched. Everything here works on row dicts (``as_dict()``
of the rows), read through the small accessors of :mod:`pendcli.output.html.marks`: it knows
the report's keys, not pendulums.

This module is the entry point: the overview page, writing both pages, printing them to
PDF. Locating and marking the rows is :mod:`pendcli.output.html.marks`; the paper page is
:mod:`pendcli.output.html.paper`.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.data.vocabulary import PROCEDURE_VERDICTS
from pendcli.output.html.paper import (
    FIGURES_LATER,
    Figure,
    cited_formulas,
    figure_section,
    formula_cell,
    markup,
    paper_page,
    render_stats,
    render_template,
)
from pendcli.output.html.rows import (
    EQUATION_CAUSE,
    STATUS_CLASSES,
    VERDICT_CLASSES,
    Row,
    correction_of,
    disagrees,
    id_of,
    own_of,
    sources_of,
    text_of,
    verdict_of,
    word_of,
)

if TYPE_CHECKING:
    from pendcli.data.rows import EquationRow
    from pendcli.run.reproduce import ReproduceResult

__all__ = [
    "Figure",
    "Pages",
    "chromium",
    "cited_formulas",
    "markdown_for_a_reader",
    "page_without_figures",
    "pages_for_result",
    "paper_page",
    "print_pdfs",
    "propagation_svg",
    "reference_words",
    "render_stats",
    "report_page",
    "require_chromium",
    "write_for_result",
    "write_html_report",
    "write_pages",
]


# --- the overview page ----------------------------------------------------------------------


def propagation_svg(rows: Sequence[Row]) -> str:
    """The layered graph of the slips: each root on the left, what inherits it to its right."""
    from pendcli.output.html.graph import layered_graph

    ids = {id_of(r) for r in rows}
    edges = [(s, id_of(r)) for r in rows for s in sources_of(r) if s in ids]
    if not edges:
        return "<p>No row inherits a slip from another.</p>"
    nodes = sorted({n for e in edges for n in e})
    propagated = {id_of(r) for r in rows if word_of(r.get("cause")) == "propagated"}
    svg, _, _ = layered_graph(
        nodes, edges, lambda n: f"{_page_of(n)}#row-{n}", lambda n: n not in propagated
    )
    return svg


def _page_of(row_id: str) -> str:
    return f"papers/{row_id.split('.', 1)[0]}.html"


def _tally(rows: Iterable[Row], word: Any) -> dict[str, int]:
    out: dict[str, int] = {}
    for r in rows:
        out[word(r)] = out.get(word(r), 0) + 1
    return out


def _findings(
    papers: Sequence[str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
) -> list[dict[str, object]]:
    """One entry per finding: claims, equations (citing their formula checks), and the
    formula checks no equation row cites."""
    out: list[dict[str, object]] = []
    for p in papers:
        cited = cited_formulas(equations.get(p, []), formulas.get(p, []))
        merged = {id_of(f) for fs in cited.values() for f in fs}
        for r in claims.get(p, []):
            entry = _entry(p, r, word_of(r.get("cause")), "", text_of(r, "note"))
            out.append({**entry, "own": own_of(r)})
        for r in equations.get(p, []):
            cause, correction = EQUATION_CAUSE.get(verdict_of(r), ""), correction_of(r)
            entry = _entry(p, r, cause, correction, text_of(r, "note"))
            entry["formulas"] = [formula_cell(f) for f in cited.get(id_of(r), [])]
            out.append(entry)
        for r in formulas.get(p, []):
            if id_of(r) not in merged:
                correction = text_of(r, "recomputed")
                out.append(_entry(p, r, word_of(r.get("cause")), correction, text_of(r, "note")))
    return [e for e in out if e.pop("disagrees")]


def _entry(paper: str, row: Row, cause: str, correction: str, note: str) -> dict[str, object]:
    return {
        "paper": paper,
        "id": id_of(row),
        "word": verdict_of(row),
        "formulas": [],
        "cause": cause,
        "sources": sources_of(row),
        "correction": correction,
        "note": note,
        "own": "",  # a claim's verdict against the author's procedure (set for claims)
        "disagrees": disagrees(row),
    }


def report_page(
    papers: Sequence[str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
    figures: Sequence[Figure] = (),
    intro: str = "",
    figures_later: bool = False,
) -> str:
    """The overview: counts, root slips and their propagation, the findings, figures
    (``figures_later``: as :func:`~pendcli.output.html.paper.paper_page`'s)."""
    every_claim = [r for p in papers for r in claims.get(p, [])]
    causes = {
        p: _tally((r for r in claims.get(p, []) if r.get("cause") and disagrees(r)),
                  lambda r: word_of(r.get("cause")))
        for p in papers
    }  # fmt: skip
    ledger = {p: _tally(equations.get(p, []), verdict_of) for p in papers if equations.get(p)}
    return render_template(
        "report.html.j2",
        title="pendcli reproduction report", intro=intro, papers=papers,
        verdicts={p: _tally(claims.get(p, []), verdict_of) for p in papers},
        verdict_keys=VERDICT_CLASSES, causes=causes,
        own={p: _tally(claims.get(p, []), lambda r: own_of(r).split(":")[0]) for p in papers},
        own_keys=(*PROCEDURE_VERDICTS, "no procedure known"),
        cause_keys=sorted({c for t in causes.values() for c in t}),
        graph=markup(propagation_svg(every_claim)), ledger=ledger, status_keys=STATUS_CLASSES,
        findings=_findings(papers, claims, formulas, equations),
        figure_section=markup(FIGURES_LATER) if figures_later else figure_section(figures),
    )  # fmt: skip


# How a caller shares work among its processes (base/workers ForkedWorkers.share): ``run``
# over the items, the results in their order.
Share = Callable[[Sequence[Any], Callable[[Any], Any]], list[Any]]


def _in_order(items: Sequence[Any], run: Callable[[Any], Any]) -> list[Any]:
    return [run(item) for item in items]


@dataclass(frozen=True)
class Pages:
    """What the pages are made of, but their figures (sent once to each process that renders
    some): each page is rendered without them (:func:`page_without_figures`, which needs no
    figure drawn yet) and finished with them (:func:`write_pages`)."""

    papers: Sequence[str]
    citations: Mapping[str, str]
    texts: Mapping[str, str]
    claims: Mapping[str, Sequence[Row]]
    formulas: Mapping[str, Sequence[Row]]
    equations: Mapping[str, Sequence[Row]]

    def order(self) -> list[str | None]:
        """The pages (a paper's, None the overview), the longest text first."""
        return [*sorted(self.papers, key=lambda p: -len(self.texts.get(p, ""))), None]


def page_without_figures(pages: Pages, paper: str | None) -> str:
    """The page of ``paper`` (None: the overview) as a reader reads it (no module path, no
    builder name, no raw TeX: data/reader_text), :data:`FIGURES_LATER` where its figures go."""
    from pendcli.data.reader_text import html_for_reader

    if paper is None:
        page = report_page(
            pages.papers, pages.claims, pages.formulas, pages.equations, figures_later=True
        )
    else:
        page = paper_page(
            paper,
            pages.citations.get(paper, ""),
            pages.texts.get(paper, ""),
            pages.claims.get(paper, []),
            pages.formulas.get(paper, []),
            pages.equations.get(paper, []),
            figures_later=True,
        )
    return html_for_reader(page, reference_words([page]))


def write_pages(
    out: Path,
    pages: Pages,
    rendered: Sequence[str],
    figures: Mapping[str, Sequence[Figure]],
) -> list[Path]:
    """Write ``out/report.html`` and ``out/papers/<paper>.html`` (atomically): each page of
    ``rendered`` (:func:`page_without_figures`, in :meth:`Pages.order`) with its figures
    (``figures``: a paper's by its key, the overview's by ""); return them."""
    from pendcli.base.files import atomic_write
    from pendcli.data.reader_text import html_for_reader

    (out / "papers").mkdir(parents=True, exist_ok=True)
    by_page = dict(zip(pages.order(), rendered, strict=True))
    written = []
    for paper in [*pages.papers, None]:
        anchor = "" if paper is None else "figures"
        section = str(figure_section(figures.get(paper or "", []), anchor))
        section = html_for_reader(section, reference_words([section]))
        path = out / "report.html" if paper is None else out / "papers" / f"{paper}.html"
        written.append(atomic_write(path, by_page[paper].replace(FIGURES_LATER, section, 1)))
    return written


def write_html_report(
    out: Path,
    papers: Sequence[str],
    citations: Mapping[str, str],
    texts: Mapping[str, str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
    figures: Mapping[str, Sequence[Figure]],
    share: Share | None = None,
) -> list[Path]:
    """Write ``out/report.html`` and ``out/papers/<paper>.html`` (atomically); return them.
    ``share``: how the pages are shared among processes (default: all rendered here), the
    longest text first."""
    made = Pages(papers, citations, texts, claims, formulas, equations)
    rendered = (share or _in_order)(made.order(), functools.partial(page_without_figures, made))
    return write_pages(out, made, rendered, figures)


def _ledger_fields(paper: str, rows: Sequence[Row]) -> list[Row]:
    """The equation rows with the ledger's own words for the reading and the correction (the
    row's ``reading`` and ``corrected`` are formulas) and its printed terms and quotes."""
    from pendcli.data.ledger import load_ledger
    from pendcli.papers.registry import ledger_papers

    if paper not in ledger_papers():
        return list(rows)
    recorded = {r.id: r for r in load_ledger(paper).rows}
    keys = ("reading", "corrected", "wrong_term", "quote")
    return [
        {**row, **{k: getattr(recorded[id_of(row)], k, None) for k in keys}}
        if id_of(row) in recorded else row
        for row in rows
    ]  # fmt: skip


def write_for_result(
    result: ReproduceResult,
    out: Path,
    figures: Mapping[str, Sequence[Figure]],
    equations: Mapping[str, Sequence[EquationRow]] | None = None,
    share: Share | None = None,
) -> list[Path]:
    """The HTML pages of a reproduction: rows from ``result``, texts from tables/papers/
    (``share``: as :func:`write_html_report`'s)."""
    made = pages_for_result(result, equations)
    rendered = (share or _in_order)(made.order(), functools.partial(page_without_figures, made))
    return write_pages(out, made, rendered, figures)


def pages_for_result(
    result: ReproduceResult, equations: Mapping[str, Sequence[EquationRow]] | None = None
) -> Pages:
    """What the HTML pages of a reproduction are made of: rows from ``result``, texts from
    tables/papers/."""
    from pendcli.data.tables import load_paper_table, tables_dir
    from pendcli.papers.registry import paper

    claims: dict[str, list[Row]] = {}
    for key in result.papers:
        printed = {c.id: c for c in load_paper_table(key).claims}
        claims[key] = [
            {**row.as_dict(), "as_printed": getattr(printed.get(row.id), "as_printed", ""),
             "ocr": getattr(printed.get(row.id), "ocr", ""),
             "lines": getattr(printed.get(row.id), "lines", None)}
            for row in result.claims.get(key, [])
        ]  # fmt: skip
    return Pages(
        result.papers,
        {key: paper(key).citation() for key in result.papers},
        {key: paper(key).tables(tables_dir()).text.read_text("utf-8") for key in result.papers},
        claims,
        {key: [f.as_dict() for f in result.formulas.get(key, [])] for key in result.papers},
        {
            key: _ledger_fields(key, [r.as_dict() for r in rows])
            for key, rows in (equations or {}).items()
        },
    )


# --- printing -------------------------------------------------------------------------------

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")


def chromium() -> str | None:
    """The headless browser that prints the pages, where one is installed."""
    import shutil

    return next((p for p in map(shutil.which, CHROMIUM_NAMES) if p), None)


def require_chromium() -> str:
    """The headless browser that prints the pages; one line naming the package where absent."""
    from pendcli.base.errors import PendcliError

    browser = chromium()
    if browser is None:
        raise PendcliError("--pdf needs Chromium (apt-get install chromium); nothing was written")
    return browser


def print_pdfs(out: Path) -> list[Path]:
    """Print ``out/report.html`` and each paper page to PDF beside it (the print stylesheet
    makes a paper page an annotated edition on A4), with headless Chromium."""
    browser = require_chromium()
    pages = [out / "report.html", *sorted((out / "papers").glob("*.html"))]
    return [_print_pdf(browser, page) for page in pages if page.is_file()]


def _print_pdf(browser: str, page: Path) -> Path:
    """One page to PDF, written beside it atomically (printed to a temporary name first)."""
    import os
    import subprocess
    import tempfile

    from pendcli.base.errors import PendcliError

    target = page.with_suffix(".pdf")
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".pdf", dir=page.parent)
    os.close(fd)
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run(
            [browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={profile}", "--no-pdf-header-footer", f"--print-to-pdf={tmp}",
             page.resolve().as_uri()],
            capture_output=True, text=True, timeout=300, check=False,
        )  # fmt: skip
    if done.returncode != 0 or os.path.getsize(tmp) == 0:
        os.unlink(tmp)
        raise PendcliError(f"Chromium could not print {page.name} (exit {done.returncode})")
    os.chmod(tmp, 0o644)
    os.replace(tmp, target)
    return target


def reference_words(texts: list[str]) -> dict[str, str]:
    """Reference builder name -> what it models, for each reference of a registered paper
    that one of ``texts`` names (only those are built): a note names a reference by what it
    models, never by its builder (:func:`pendcli.data.reader_text.reference_descriptions`)."""
    from pendcli.data.reader_text import reference_descriptions
    from pendcli.papers import registry
    from pendcli.verify.ledger_references import reference_table

    # one pass over the texts for their words, rather than a search per builder name over
    # megabytes of pages: only a name found among the words is searched for and built
    words = {w for text in texts for w in re.findall(r"\w+", text)}
    tables = {
        p.key: {
            name: builder
            for name, builder in reference_table(p).items()
            if name in words or not re.fullmatch(r"\w+", name)
        }
        for p in registry.all_papers()
    }
    return reference_descriptions(texts, tables)


def markdown_for_a_reader(text: str) -> str:
    """``report.md`` as a historian reads it: no module path, no reference builder's name, no
    raw TeX (:func:`pendcli.data.reader_text.markdown_for_reader`)."""
    from pendcli.data.reader_text import markdown_for_reader

    return markdown_for_reader(text, reference_words([text]))
