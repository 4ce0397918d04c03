"""``out/report.html`` and ``out/papers/<paper>.html``: the report as self-contained HTML.

The overview page carries the summary, the propagation graph of the slips and every
disagreement; each paper page is the paper's OCR text (``tables/papers/<paper>.txt``) with
every located printed number coloured by its verdict and every equation label by its ledger
status, each a link to its row below the text (published, recomputed, exact, cause, note).
Figures are embedded as data URIs and the CSS is inline, so the pages need no network and
can be mailed as they are. Everything here works on row dicts (``as_dict()`` of the rows):
it knows the report's keys, not pendulums.
"""

from __future__ import annotations

import base64
import html
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.core.vocabulary import (
    CLAIM_VERDICTS,
    STATUSES,
    EquationStatus,
    FormulaVerdict,
    Verdict,
)

if TYPE_CHECKING:
    from pendcli.core.rows import EquationRow
    from pendcli.reproduce import ReproduceResult

__all__ = [
    "Figure",
    "locate",
    "paper_page",
    "propagation_svg",
    "report_page",
    "write_for_result",
    "write_html_report",
]

Row = Mapping[str, object]

STYLE = """
body{font:15px/1.45 system-ui,sans-serif;margin:0 auto;max-width:72rem;padding:1rem 2rem;
color:#1d1d1f}
h1,h2,h3{line-height:1.2} table{border-collapse:collapse;margin:.5rem 0 1.5rem;font-size:13px}
th,td{border:1px solid #ccd;padding:.2rem .45rem;vertical-align:top;text-align:left}
th{background:#eef} td.num{font-variant-numeric:tabular-nums;white-space:nowrap}
pre.paper{white-space:pre-wrap;font:13px/1.5 ui-monospace,monospace;background:#fafaf7;
padding:1rem;border:1px solid #ddd}
a.hl{text-decoration:none;color:inherit;border-radius:3px;padding:0 2px}
.v-agrees,.s-holds{background:#c9f2c7} .v-truncated,.v-last-digit{background:#fbe7a1}
.v-discrepant,.s-fails{background:#f7b3ae} .s-misprint{background:#fcd3a1}
.s-definition{background:#dde3ee} .s-not-checkable{background:#eee}
tr:target,a.hl:target{outline:3px solid #2962ff}
figure{margin:1rem 0} figure img{max-width:100%;border:1px solid #ddd}
figcaption{font-size:13px;color:#444;max-width:60rem}
.legend span{padding:0 .4rem;margin-right:.3rem}
nav a{margin-right:1rem}
"""

VERDICT_CLASSES = CLAIM_VERDICTS
STATUS_CLASSES = STATUSES


@dataclass(frozen=True)
class Figure:
    """A figure file and the caption the report prints under it."""

    path: Path
    caption: str


def _e(value: object) -> str:
    return html.escape("" if value is None else str(value))


def _number(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.10g}"
    return _e(value)


# --- locating what the paper prints in its OCR text -----------------------------------------


# How the OCR's LaTeX writes a few symbols that the tables keep in plain notation.
_OCR_FORMS = {"°": r"(?:°|\^\{\\circ\})", "π": r"(?:π|\\pi\b)", "·": r"(?:·|\\cdot\b)"}


def _pattern(printed: str) -> re.Pattern[str] | None:
    """A regex for ``printed`` that tolerates the OCR's spacing (``0^m,68`` ~ ``0^m, 68``)."""
    chars = [c for c in printed if not c.isspace()]
    if not chars:
        return None
    body = r"\s*".join(_OCR_FORMS.get(c, re.escape(c)) for c in chars)
    # A bare number must not match inside a longer one ("5" inside "0,35").
    before = r"(?<![\d,.])" if chars[0].isdigit() else ""
    after = r"(?![\d])" if chars[-1].isdigit() else ""
    return re.compile(before + body + after)


def locate(text: str, candidates: Sequence[Sequence[str]]) -> list[tuple[int, int] | None]:
    """Where each item's printed form first occurs in ``text``, in reading order.

    ``candidates[i]`` are the forms of item i, widest first: the OCR's own text (which may be
    a whole formula), then the value alone. The value is marked inside the OCR text where it
    can be found there, so neighbouring numbers of one formula keep their own marks. An item
    is looked for after the previous item's place first, since tables list claims in the
    paper's order, then anywhere; spans already taken are skipped.
    """
    taken: list[tuple[int, int]] = []
    spans: list[tuple[int, int] | None] = []
    cursor = 0
    for forms in candidates:
        span = _find(text, forms, cursor, taken) or _find(text, forms, 0, taken)
        spans.append(span)
        if span is not None:
            taken.append(span)
            cursor = span[0]
    return spans


def _find(
    text: str, forms: Sequence[str], start: int, taken: list[tuple[int, int]]
) -> tuple[int, int] | None:
    """The first free match of the widest form, narrowed to a later form found inside it."""
    for i, form in enumerate(forms):
        span = _first_free(text, form, start, len(text), taken)
        if span is not None:
            for narrower in forms[i + 1 :]:
                inner = _first_free(text, narrower, span[0], span[1], taken)
                if inner is not None:
                    return inner
            return span
    return None


def _first_free(
    text: str, form: str, start: int, end: int, taken: list[tuple[int, int]]
) -> tuple[int, int] | None:
    pattern = _pattern(form)
    if pattern is None:
        return None
    for m in pattern.finditer(text, start, end):
        if all(m.end() <= a or m.start() >= b for a, b in taken):
            return m.span()
    return None


def _label_forms(label: str) -> list[str]:
    """An equation label as the OCR prints it: ``(41)`` also appears as ``(41)`` in $$…$$."""
    return [label] if label else []


# --- the annotated paper page ---------------------------------------------------------------


@dataclass(frozen=True)
class _Mark:
    start: int
    end: int
    row_id: str
    css: str
    title: str


def _marks(text: str, claims: Sequence[Row], equations: Sequence[Row]) -> list[_Mark]:
    claim_forms = [[str(f) for f in (r.get("as_printed"), r.get("published")) if f] for r in claims]
    equation_forms = [_label_forms(str(r.get("equation") or "")) for r in equations]
    marks: list[_Mark] = []
    for row, span in zip(claims, locate(text, claim_forms), strict=True):
        if span is not None:
            title = f"{row['id']}: {row.get('verdict')}"
            marks.append(_Mark(*span, str(row["id"]), f"v-{row.get('verdict')}", title))
    eq_spans = locate(text, equation_forms)
    for row, span in zip(equations, eq_spans, strict=True):
        if span is not None and not any(m.start < span[1] and span[0] < m.end for m in marks):
            title = f"{row['id']}: {row.get('status')}"
            marks.append(_Mark(*span, str(row["id"]), f"s-{row.get('status')}", title))
    return sorted(marks, key=lambda m: m.start)


def annotate(text: str, marks: Iterable[_Mark]) -> str:
    """The text, HTML-escaped, with each mark a link to its row."""
    out: list[str] = []
    pos = 0
    for m in marks:
        out.append(_e(text[pos : m.start]))
        out.append(
            f'<a class="hl {_e(m.css)}" id="at-{_e(m.row_id)}" href="#row-{_e(m.row_id)}" '
            f'title="{_e(m.title)}">{_e(text[m.start : m.end])}</a>'
        )
        pos = m.end
    out.append(_e(text[pos:]))
    return "".join(out)


def _sources(row: Row) -> list[str]:
    """The ids a propagated row inherits from (its ``from`` key)."""
    value = row.get("from")
    return [str(s) for s in value] if isinstance(value, list | tuple) else []


def _cause(row: Row) -> str:
    cause = row.get("cause") or ""
    sources = _sources(row)
    if cause and sources:
        links = ", ".join(f'<a href="#row-{_e(s)}">{_e(s)}</a>' for s in sources)
        return f"{_e(cause)} from {links}"
    return _e(cause)


def _back_link(row_id: str, located: set[str]) -> str:
    if row_id in located:
        return f'<a href="#at-{_e(row_id)}">{_e(row_id)}</a>'
    return f"{_e(row_id)} <small>(not located in the OCR text)</small>"


def _claim_table(claims: Sequence[Row], located: set[str]) -> str:
    head = "<tr><th>id</th><th>source</th><th>published</th><th>recomputed</th><th>exact</th>"
    head += "<th>verdict</th><th>cause</th><th>note</th></tr>"
    body = [
        f'<tr id="row-{_e(r["id"])}" class="v-{_e(r.get("verdict"))}">'
        f"<td>{_back_link(str(r['id']), located)}</td><td>{_e(r.get('source'))}</td>"
        f'<td class="num">{_e(r.get("published"))} {_e(r.get("unit"))}</td>'
        f'<td class="num">{_number(r.get("recomputed"))}</td>'
        f'<td class="num">{_number(r.get("exact"))}</td><td>{_e(r.get("verdict"))}</td>'
        f"<td>{_cause(r)}</td><td>{_e(r.get('note'))}</td></tr>"
        for r in claims
    ]
    return f"<table>{head}{''.join(body)}</table>"


def _formula_table(formulas: Sequence[Row]) -> str:
    head = "<tr><th>id</th><th>source</th><th>as printed</th><th>as found</th><th>verdict</th>"
    head += "<th>order claimed / observed</th><th>cause</th><th>note</th></tr>"
    body = [
        f'<tr id="row-{_e(r["id"])}" class="s-{_e(r.get("verdict"))}"><td>{_e(r["id"])}</td>'
        f"<td>{_e(r.get('source'))}</td><td>{_e(r.get('published'))}</td>"
        f"<td>{_e(r.get('recomputed'))}</td><td>{_e(r.get('verdict'))}</td>"
        f'<td class="num">{_number(r.get("claimed_order"))} / '
        f"{_number(r.get('observed_order'))}</td><td>{_cause(r)}</td>"
        f"<td>{_e(r.get('note'))}</td></tr>"
        for r in formulas
    ]
    return f"<table>{head}{''.join(body)}</table>"


def _equation_table(equations: Sequence[Row], located: set[str]) -> str:
    head = "<tr><th>id</th><th>label</th><th>section</th><th>statement</th><th>status</th>"
    head += "<th>check</th><th>observed order</th><th>note</th></tr>"
    body = [
        f'<tr id="row-{_e(r["id"])}" class="s-{_e(r.get("status"))}">'
        f"<td>{_back_link(str(r['id']), located)}</td><td>{_e(r.get('equation'))}</td>"
        f"<td>{_e(r.get('section'))}</td><td>{_e(r.get('statement'))}</td>"
        f"<td>{_e(r.get('status'))}</td><td>{_e(r.get('check'))}</td>"
        f'<td class="num">{_number(r.get("observed_order"))}</td>'
        f"<td>{_e(r.get('note'))}</td></tr>"
        for r in equations
    ]
    return f"<table>{head}{''.join(body)}</table>"


def _legend() -> str:
    spans = [f'<span class="v-{v}">{v}</span>' for v in VERDICT_CLASSES]
    spans += [f'<span class="s-{s}">{s}</span>' for s in STATUS_CLASSES]
    return f'<p class="legend">Numbers by verdict, equations by status: {" ".join(spans)}</p>'


def _figure_html(figure: Figure) -> str:
    data = base64.b64encode(figure.path.read_bytes()).decode("ascii")
    return (
        f'<figure id="fig-{_e(figure.path.stem)}"><img alt="{_e(figure.caption)}" '
        f'src="data:image/png;base64,{data}"><figcaption>{_e(figure.caption)}</figcaption>'
        "</figure>"
    )


def _page(title: str, body: str) -> str:
    return (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{_e(title)}'
        f"</title><style>{STYLE}</style></head><body>{body}</body></html>\n"
    )


def paper_page(
    paper: str,
    citation: str,
    text: str,
    claims: Sequence[Row],
    formulas: Sequence[Row] = (),
    equations: Sequence[Row] = (),
    figures: Sequence[Figure] = (),
) -> str:
    """One paper: its text annotated, then its claims, equations, formulas and figures."""
    marks = _marks(text, claims, equations)
    located = {m.row_id for m in marks}
    parts = [
        '<nav><a href="../report.html">← report</a></nav>',
        f"<h1>{_e(paper.capitalize())}</h1><p><i>{_e(citation)}</i></p>",
        _legend(),
        _located_text(claims, equations, located),
        _jump_list([*claims, *formulas, *equations]),
        f'<pre class="paper">{annotate(text, marks)}</pre>',
        "<h2>Printed numbers</h2>",
        _claim_table(claims, located),
    ]
    if equations:
        parts += ["<h2>Equation ledger</h2>", _equation_table(equations, located)]
    if formulas:
        parts += ["<h2>Derived formulas</h2>", _formula_table(formulas)]
    if figures:
        parts += ['<h2 id="figures">Figures</h2>', *(_figure_html(f) for f in figures)]
    return _page(f"pendcli: {paper}", "\n".join(parts))


def _located_text(claims: Sequence[Row], equations: Sequence[Row], located: set[str]) -> str:
    labelled = [q for q in equations if q.get("equation")]
    return (
        f"<p>{sum(c['id'] in located for c in claims)} of {len(claims)} printed numbers and "
        f"{sum(q['id'] in located for q in labelled)} of {len(labelled)} equation labels "
        "located in the OCR text (results stated in prose are in the ledger below); click a "
        "mark to reach its row, a row's id to come back.</p>"
    )


def _jump_list(rows: Sequence[Row]) -> str:
    """Links to every row that does not agree or hold, at the top of the page."""
    wrong = [r for r in rows if _disagrees(r)]
    if not wrong:
        return "<p>Everything on this page agrees or holds.</p>"
    links = ", ".join(f'<a href="#row-{_e(r["id"])}">{_e(r["id"])}</a>' for r in wrong)
    return f"<p><strong>Does not agree or hold ({len(wrong)}):</strong> {links}</p>"


# --- the overview page ----------------------------------------------------------------------


def propagation_svg(rows: Sequence[Row]) -> str:
    """A small layered graph: each root slip on the left, what inherits it to its right."""
    by_id = {str(r["id"]): r for r in rows}
    depth: dict[str, int] = {}

    def level(row_id: str, seen: frozenset[str] = frozenset()) -> int:
        if row_id not in depth:
            row = by_id.get(row_id, {})
            sources = [s for s in _sources(row) if s not in seen]
            depth[row_id] = 1 + max((level(s, seen | {row_id}) for s in sources), default=-1)
        return depth[row_id]

    nodes = [i for i, r in by_id.items() if r.get("cause") == "propagated" or _is_source(i, rows)]
    if not nodes:
        return "<p>No row inherits a slip from another.</p>"
    for node in nodes:
        level(node)
    columns: dict[int, list[str]] = {}
    for node in sorted(nodes):
        columns.setdefault(depth[node], []).append(node)
    pos: dict[str, tuple[int, int]] = {}
    for d in sorted(columns):  # each row beside the mean height of its sources: few crossings
        col = sorted(columns[d], key=lambda n: _mean_y(pos, _sources(by_id[n])))
        pos.update({n: (20 + 300 * d, 24 + 26 * i) for i, n in enumerate(col)})
    height = 40 + 26 * max(len(c) for c in columns.values())
    edges = [
        f'<line x1="{pos[s][0] + 7 * len(s) + 4}" y1="{pos[s][1] - 4}" x2="{pos[n][0] - 4}" '
        f'y2="{pos[n][1] - 4}" stroke="#888" marker-end="url(#arrow)"/>'
        for n in nodes
        for s in _sources(by_id[n])
        if s in pos
    ]
    labels = [
        f'<a href="{_e(_page_of(n))}#row-{_e(n)}"><text x="{x}" y="{y}" font-size="12" '
        f'fill="{"#b00" if by_id[n].get("cause") != "propagated" else "#333"}">{_e(n)}</text></a>'
        for n, (x, y) in pos.items()
    ]
    width = 300 * (max(columns) + 1)
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        'role="img" aria-label="propagation of slips"><defs><marker id="arrow" '
        'viewBox="0 0 10 10" refX="10" refY="5" markerWidth="6" markerHeight="6" '
        'orient="auto"><path d="M0,0L10,5L0,10z" fill="#888"/></marker></defs>'
        f"{''.join(edges)}{''.join(labels)}</svg>"
    )


def _mean_y(pos: Mapping[str, tuple[int, int]], sources: list[str]) -> float:
    ys = [pos[s][1] for s in sources if s in pos]
    return sum(ys) / len(ys) if ys else 0.0


def _is_source(row_id: str, rows: Sequence[Row]) -> bool:
    return any(row_id in _sources(r) for r in rows)


def _page_of(row_id: str) -> str:
    return f"papers/{row_id.split('.', 1)[0]}.html"


def _disagreements(claims: Sequence[Row], formulas: Sequence[Row], eqs: Sequence[Row]) -> str:
    rows = [r for r in claims if r.get("verdict") != Verdict.AGREES]
    rows += [r for r in formulas if r.get("verdict") == FormulaVerdict.FAILS]
    rows += [r for r in eqs if r.get("status") in (EquationStatus.FAILS, EquationStatus.MISPRINT)]
    if not rows:
        return "<p>Everything holds.</p>"
    body = [
        f'<tr><td><a href="{_e(_page_of(str(r["id"])))}#row-{_e(r["id"])}">{_e(r["id"])}</a>'
        f"</td><td>{_e(r.get('verdict') or r.get('status'))}</td><td>{_cause(r)}</td>"
        f"<td>{_e(r.get('note'))}</td></tr>"
        for r in rows
    ]
    head = "<tr><th>row</th><th>verdict / status</th><th>cause</th><th>note</th></tr>"
    return f"<table>{head}{''.join(body)}</table>"


def _disagrees(row: Row) -> bool:
    from pendcli.summary import disagrees

    return disagrees(row)


def _counts_table(counts: Mapping[str, Mapping[str, int]], keys: Sequence[str]) -> str:
    head = "<tr><th>paper</th>" + "".join(f"<th>{_e(k)}</th>" for k in keys) + "</tr>"
    body = [
        f'<tr><td><a href="papers/{_e(p)}.html">{_e(p)}</a></td>'
        + "".join(f'<td class="num">{c.get(k, 0)}</td>' for k in keys)
        + "</tr>"
        for p, c in counts.items()
    ]
    return f"<table>{head}{''.join(body)}</table>"


def _tally(rows: Iterable[Row], key: str) -> dict[str, int]:
    out: dict[str, int] = {}
    for r in rows:
        out[str(r.get(key))] = out.get(str(r.get(key)), 0) + 1
    return out


def report_page(
    papers: Sequence[str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
    figures: Sequence[Figure] = (),
    intro: str = "",
) -> str:
    """The overview: counts, root slips and their propagation, disagreements, figures."""
    every_claim = [r for p in papers for r in claims.get(p, [])]
    every_formula = [r for p in papers for r in formulas.get(p, [])]
    every_eq = [r for p in papers for r in equations.get(p, [])]
    causes = {
        p: _tally((r for r in claims.get(p, []) if r.get("cause") and _disagrees(r)), "cause")
        for p in papers
    }
    cause_keys = sorted({c for t in causes.values() for c in t})
    parts = [
        "<h1>pendcli reproduction report</h1>",
        f"<p>{_e(intro)}</p>" if intro else "",
        "<nav>" + "".join(f'<a href="papers/{_e(p)}.html">{_e(p)}</a>' for p in papers) + "</nav>",
        "<h2>Printed numbers by verdict</h2>",
        _counts_table({p: _tally(claims.get(p, []), "verdict") for p in papers}, VERDICT_CLASSES),
        "<h2>Causes of what does not agree</h2>",
        "<p>Counted over the numbers that do not agree. Every cause but <i>propagated</i> is a "
        "root, where an error enters; <i>propagated</i> rows only carry the error of the rows "
        "they come from. In the graph, red rows are roots (an agreeing row can be one: its "
        "rounding carries on), each arrow points to a row that inherits its error.</p>",
        _counts_table(causes, cause_keys) if cause_keys else "<p>No causes recorded.</p>",
        propagation_svg(every_claim),
    ]
    if every_eq:
        parts += [
            "<h2>Equation ledger coverage</h2>",
            _counts_table(
                {p: _tally(equations.get(p, []), "status") for p in papers}, STATUS_CLASSES
            ),
        ]
    parts += [
        "<h2>What does not hold</h2>",
        _disagreements(every_claim, every_formula, every_eq),
    ]
    if figures:
        parts += ["<h2>Figures</h2>", *(_figure_html(f) for f in figures)]
    return _page("pendcli reproduction report", "\n".join(parts))


def write_html_report(
    out: Path,
    papers: Sequence[str],
    citations: Mapping[str, str],
    texts: Mapping[str, str],
    claims: Mapping[str, Sequence[Row]],
    formulas: Mapping[str, Sequence[Row]],
    equations: Mapping[str, Sequence[Row]],
    figures: Mapping[str, Sequence[Figure]],
) -> list[Path]:
    """Write ``out/report.html`` and ``out/papers/<paper>.html`` (atomically); return them."""
    from pendcli.core.files import atomic_write

    (out / "papers").mkdir(parents=True, exist_ok=True)
    written = []
    for p in papers:
        page = paper_page(
            p,
            citations.get(p, ""),
            texts.get(p, ""),
            claims.get(p, []),
            formulas.get(p, []),
            equations.get(p, []),
            figures.get(p, []),
        )
        written.append(atomic_write(out / "papers" / f"{p}.html", page))
    general = figures.get("", [])
    page = report_page(papers, claims, formulas, equations, general)
    written.append(atomic_write(out / "report.html", page))
    return written


def write_for_result(
    result: ReproduceResult,
    out: Path,
    figures: Mapping[str, Sequence[Figure]],
    equations: Mapping[str, Sequence[EquationRow]] | None = None,
) -> list[Path]:
    """The HTML pages of a reproduction: rows from ``result``, texts from tables/papers/."""
    from pendcli.core.tables import tables_dir
    from pendcli.papers.registry import paper

    claims = {
        key: [{**row.as_dict(), "as_printed": row.as_printed} for row in result.claims.get(key, [])]
        for key in result.papers
    }
    return write_html_report(
        out,
        result.papers,
        {key: paper(key).citation() for key in result.papers},
        {key: paper(key).tables(tables_dir()).text.read_text("utf-8") for key in result.papers},
        claims,
        {key: [f.as_dict() for f in result.formulas.get(key, [])] for key in result.papers},
        {key: [r.as_dict() for r in rows] for key, rows in (equations or {}).items()},
        figures,
    )
