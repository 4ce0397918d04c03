"""``out/papers/<paper>.html``: one paper's OCR text as an annotated edition.

Its TeX rendered as MathML (:mod:`pendcli.output.html.math`), the marks placed by
:mod:`pendcli.output.html.marks` drawn inside prose and formulas with a numbered note beside each
paragraph, then the paper's claims, equations, formulas and figures. Also the Jinja2
environment both pages are rendered with (:mod:`pendcli.output.html.report` writes the overview).
"""

from __future__ import annotations

import base64
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.data.numbers import edition_quantity, edition_text
from pendcli.output.html.locate import paragraph_spans
from pendcli.output.html.marks import Placement, place_marks
from pendcli.output.html.math import (
    balanced,
    mark_mathml,
    math_segments,
    plain_math,
    to_mathml,
    wrap_marks,
)
from pendcli.output.html.prose import (
    front_matter_end,
    is_heading,
    join_continued,
    page_breaks,
    prose_html,
    split_at_heads,
)
from pendcli.output.html.rows import (
    EQUATION_CAUSE,
    STATUS_CLASSES,
    VERDICT_CLASSES,
    Row,
    correction_of,
    css_of,
    disagrees,
    id_of,
    lines_of,
    number_text,
    own_of,
    printed_form,
    sources_of,
    text_of,
    verdict_of,
    word_of,
)

if TYPE_CHECKING:
    from jinja2 import Environment
    from markupsafe import Markup

    from pendcli.output.html.math import MathSegment


@dataclass(frozen=True)
class Figure:
    """A figure file and the caption the report prints under it."""

    path: Path
    caption: str


# --- the text rendered: prose escaped, formulas as MathML, marks inside both ----------------


@dataclass
class RenderStats:
    """How the page's formulas were rendered: MathML, or the plain reading where it failed."""

    formulas: int = 0
    mathml: int = 0
    plain: int = 0
    widened: int = 0  # marks drawn around their whole formula (their TeX did not balance)


def render_stats(text: str) -> RenderStats:
    """The conversion rate over every formula of ``text`` (no marks)."""
    stats = RenderStats()
    for s in math_segments(text):
        stats.formulas += 1
        ok = to_mathml(text[s.tex_start : s.tex_end], s.display) is not None
        stats.mathml += ok
        stats.plain += not ok
    return stats


_STRAY_TEX = re.compile(r"\\[A-Za-z]+(?:\{[^{}]*\})?(?:_\{?\w+\}?)?|\b\w_\{[^{}]*\}")


_PROSE_SUBSCRIPT = re.compile(r"(?<![\w&#;])([^\W\d_])_([A-Za-z0-9]{1,2}(?:-\d)?)(?![\w])")


def _prose(piece: str) -> str:
    """Prose escaped, its stray TeX (``\\mathbf{E}_c`` outside dollars) read plainly, its
    Markdown emphasis kept."""
    from markupsafe import escape

    piece = _STRAY_TEX.sub(lambda m: plain_math(m.group(0)), piece)
    piece = re.sub(r"(?<=[^\W\d_])_([0-9])(?!\d)", lambda m: plain_math("_" + m.group(1)), piece)
    piece = re.sub(r"(?<=\d)\^e\b", "ᵉ", piece).replace("\t", "\u2003\u2003")
    piece = re.sub(r"(?<=\d)\^o\b", "°", piece)  # « 1^o Durée … »: primo, printed 1°
    out = str(
        escape(re.sub(r"(?<=\w)\^([0-9])(?!\d)", lambda m: plain_math("^" + m.group(1)), piece))
    )
    # a letter's subscript the OCR left in the prose (« I_n et I_n-2 », « E_c », « θ_m »)
    out = _PROSE_SUBSCRIPT.sub(
        lambda m: f"{m.group(1)}<sub>{m.group(2).replace('-', chr(0x2212))}</sub>", out
    )
    out = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", out)
    return re.sub(r"(?<![\w*])\*(?!\s)(.+?)(?<!\s)\*(?![\w*])", r"<i>\1</i>", out)


# A letter's TeX subscript in a note's words (« θ_0 = 30' », E_c(π), Δθ'_m, I_{n-2}): a
# letter (or Δ and a letter) at the start of a word (not of an id's part, psi_sin2,
# lecornu.x_bound), primes allowed, then one or two letters or digits or a braced group,
# then the word's end.
_NOTE_SUBSCRIPT = re.compile(
    r"(?<![\w&#;.])(Δ?[^\W\d_](?:&#39;)*)_(?:\{([^{}]{1,6})\}|([A-Za-z0-9]{1,2}))(?!\w)"
)


def note_subscripts(text: str) -> Markup:
    """A note's text escaped, its letters' TeX subscripts set as subscripts."""
    from markupsafe import escape

    return markup(_NOTE_SUBSCRIPT.sub(
        lambda m: f"{m.group(1)}<sub>{(m.group(2) or m.group(3)).replace('-', chr(0x2212))}</sub>",
        str(escape(text))))  # fmt: skip


def _call(mark: Placement, number: int) -> str:
    if mark.continues:  # a later piece of a quote or formula: its first piece has the call
        return ""
    return f'<sup class="call"><a href="#note-{_attr(mark.key)}">[{number}]</a></sup>'


def _attr(value: str) -> str:
    from markupsafe import escape

    return str(escape(value))


def _open(mark: Placement) -> str:
    return (
        f'class="hl {_attr(mark.css)}{" whole" if mark.whole else ""}" id="at-{_attr(mark.key)}" '
        f'title="{_attr(mark.row_id)}: {_attr(mark.word)}" data-row="{_attr(mark.row_id)}" '
        f'data-lines="{mark.lines[0]}-{mark.lines[1]}" data-note="{_attr(note_key(mark))}"'
    )


def note_key(mark: Placement) -> str:
    """The key of the note a mark is called to: its own, or its first piece's."""
    return mark.continues or mark.key


def _render_span(page_text: str, a: int, b: int, marks: Sequence[Placement],
                 segments: Sequence[MathSegment], numbers: Mapping[str, int],
                 stats: RenderStats) -> str:  # fmt: skip
    """Text [a, b): formulas and prose in order, each mark at its place."""
    out: list[str] = []
    pos = a
    for s in [s for s in segments if a <= s.start and s.end <= b]:
        out.append(_render_prose(page_text, pos, s.start, marks, numbers))
        inner = [m for m in marks if m.start < s.end and s.start < m.end and m.end > m.start]
        out.append(_render_formula(page_text, s, inner, numbers, stats))
        pos = s.end
    out.append(_render_prose(page_text, pos, b, marks, numbers))
    return "".join(out)


def _render_prose(text: str, a: int, b: int, marks: Sequence[Placement],
                  numbers: Mapping[str, int]) -> str:  # fmt: skip
    """Prose [a, b) with its marks; a mark holding others (a wrong term around a claim's
    number) is a ``<span>`` around them, since a link cannot hold a link."""
    out, pos = [], a
    for m in (m for m in marks if a <= m.start and m.end <= b and m.end > m.start):
        if m.start < pos:  # held by the mark before, drawn inside it
            continue
        out.append(_prose(text[pos : m.start]))
        held = [o for o in marks if o is not m and m.start <= o.start and o.end <= m.end]
        if held:
            body = _render_prose(text, m.start, m.end, held, numbers)
            out.append(f"<span {_open(m)}>{body}</span>")
        else:
            href = f"#note-{_attr(m.continues)}" if m.continues else f"#row-{_attr(m.row_id)}"
            out.append(f'<a {_open(m)} href="{href}">{_prose(text[m.start : m.end])}</a>')
        out.append(_call(m, numbers.get(m.key, 0)))
        pos = m.end
    out.append(_prose(text[pos:b]))
    return "".join(out)


def _render_formula(text: str, s: MathSegment, marks: Sequence[Placement],
                    numbers: Mapping[str, int], stats: RenderStats) -> str:  # fmt: skip
    """One formula as MathML with its marks as ``<mrow class="hl">`` and their calls."""
    tex = text[s.tex_start : s.tex_end]
    inside = [m for m in marks if s.tex_start <= m.start and m.end <= s.tex_end
              and balanced(text[m.start : m.end]) and not m.whole]  # fmt: skip
    around = [m for m in marks if m not in inside]
    spans = [(m.start - s.tex_start, m.end - s.tex_start, i) for i, m in enumerate(inside)]
    mathml = to_mathml(wrap_marks(tex, spans), s.display) if inside else None
    if mathml is None:
        around, inside = [*around, *inside], []
        mathml = to_mathml(tex, s.display)
    if mathml is None:  # not converted: the plain reading, marks around it
        stats.plain += 1
        body = f'<span class="plain-math">{_attr(plain_math(tex))}</span>'
    else:
        stats.mathml += 1
        body = mark_mathml(
            mathml,
            lambda i: f"{'' if inside[i].continues else '<msup>'}<mrow {_open(inside[i])}>",
            lambda i: (
                ""
                if inside[i].continues
                else (
                    f'<mtext class="call"><a href="#note-{_attr(inside[i].key)}">'
                    f"[{numbers[inside[i].key]}]</a></mtext></msup>"
                )
            ),
            len(inside),
        )
    stats.formulas += 1
    stats.widened += len(around)
    for m in around:
        body = f"<span {_open(m)}>{body}</span>{_call(m, numbers.get(m.key, 0))}"
    return f'<div class="display">{body}</div>' if s.display else body


# --- the pages ------------------------------------------------------------------------------


@cache  # one per process: its templates compiled once, not at every page
def _environment() -> Environment:
    from jinja2 import Environment, PackageLoader, StrictUndefined

    return Environment(
        loader=PackageLoader("pendcli.output.html", "templates"),
        autoescape=True,
        undefined=StrictUndefined,
        keep_trailing_newline=True,
    )


def render_template(template: str, **context: object) -> str:
    return _environment().get_template(template).render(**context)


def markup(html: str) -> Markup:
    from markupsafe import Markup

    return Markup(html)


def _legend() -> list[dict[str, str]]:
    words = [*VERDICT_CLASSES, *STATUS_CLASSES]
    return [{"css": f"v-{w}" if w in VERDICT_CLASSES else f"s-{w}", "word": w} for w in words]


def figure_entries(figures: Sequence[Figure]) -> list[dict[str, str]]:
    return [
        {"stem": f.path.stem, "caption": f.caption,
         "data": base64.b64encode(f.path.read_bytes()).decode("ascii")}
        for f in figures
    ]  # fmt: skip


def figure_section(figures: Sequence[Figure], anchor: str = "") -> Markup:
    """A page's last section: its figures under a heading (``anchor``: the heading's id), or
    nothing without figures."""
    return markup(render_template("figures.html.j2", figs=figure_entries(figures), anchor=anchor))


# Where a page rendered before its figures are drawn holds them (:func:`paper_page`'s
# ``figures_later``): a comment, which the reader's text (data/reader_text) leaves as it is
FIGURES_LATER = "<!-- the figures -->"


def cited_formulas(equations: Sequence[Row], formulas: Sequence[Row]) -> dict[str, list[Row]]:
    """The formula rows each equation row's check cites: one entry for both checks."""
    out: dict[str, list[Row]] = {}
    for formula in formulas:
        pattern = re.compile(rf"(?<![\w.]){re.escape(id_of(formula))}(?![\w.])")
        named = [eq for eq in equations if _same_equation(id_of(formula), eq)]
        for eq in named or equations:
            if named or pattern.search(text_of(eq, "measured") + " " + text_of(eq, "corrected")):
                out.setdefault(id_of(eq), []).append(formula)
    return out


def _same_equation(formula_id: str, equation: Row) -> bool:
    """A formula check named after the equation's label: ``lecornu.eq52`` is (52)."""
    label = text_of(equation, "equation").strip("()").replace("'", "prime")
    paper = id_of(equation).split(".", 1)[0]
    return (
        bool(label)
        and re.fullmatch(rf"{paper}\.eq{re.escape(label)}(?:[._].*)?", formula_id) is not None
    )


def _text_blocks(text: str, marks: Sequence[Placement], passages: Sequence[tuple[int, Placement]],
                 stats: RenderStats,
                 rows: Mapping[str, Row]) -> list[dict[str, object]]:  # fmt: skip
    segments = math_segments(text)
    # one number per note (a later piece of a quote or formula is called to its first's), in
    # the order the calls are read: at each mark's end, a mark held in another called first
    # (two marks of one span: the later in ``marks`` is drawn held in the earlier, called first)
    called = [(m.end, -m.start, -i, m) for i, m in enumerate(marks) if not m.continues]
    called += [(p.end, -p.start, 1, p) for _, p in passages if not p.continues]
    order = sorted(called, key=lambda c: c[:3])
    numbers = {c[3].key: i for i, c in enumerate(order, 1)}
    blocks: list[dict[str, object]] = []
    texts: list[str] = []  # each block's text: prose.py joins what the OCR cut in two
    front = front_matter_end(text)
    breaks = page_breaks(text)
    for a, b in split_at_heads(text, paragraph_spans(text, segments), breaks):
        texts.append(text[a:b])
        if (a, b) in breaks:
            blocks.append(_page_break(text, a, b, breaks.index((a, b))))
            continue
        inside = [m for m in marks if a <= m.start < b]
        notes = sorted([*(m for m in inside if not m.continues),
                        *(p for at, p in passages if a <= at < b)],
                       key=lambda m: numbers[m.key])  # fmt: skip
        html = _render_span(text, a, b, inside, segments, numbers, stats)
        blocks.append({
            "html": markup(prose_html(html, heading := is_heading(text[a:b]))),
            "heading": heading,
            "figure": bool(_FIGURE.fullmatch(text[a:b].strip())) and not inside,
            "front": b <= front,
            "pagebreak": "",
            "notes": (drawn := [_note(m, numbers[m.key], rows.get(m.row_id)) for m in notes]),
            "dense": _is_dense(drawn),
        })  # fmt: skip
    return join_continued(blocks, texts, _is_dense)


# A paragraph with this many findings (or notes in all) sets its notes below it, not in the
# margin: beside Lecornu's tables of numbers a margin column of eleven three-line findings ran
# 700 px below its table, and every later note after it; once every paragraph's claims were
# rows, Lecornu's margin drifted 376 px at 4 and 8 (tests/output/html/test_browser.py).
DENSE_FINDINGS, DENSE_NOTES = 3, 6


def _is_dense(notes: list[dict[str, object]]) -> bool:
    findings = sum(1 for n in notes if n.get("finding"))
    return findings >= DENSE_FINDINGS or len(notes) >= DENSE_NOTES


_PAGES = re.compile(r"\bp\. (\d+)\s*-\s*(\d+)")


def _page_break(text: str, a: int, b: int, index: int) -> dict[str, object]:
    """A running head as the edition's page break: the page it ends, counted from the first
    page the cover gives (« p. 145-162 »), and the head's words, set apart from the text."""
    pages = _PAGES.search(text[: front_matter_end(text)] or text[:2000])
    page = int(pages.group(1)) + index if pages else None
    label = f"p. {page} | p. {page + 1}" if page is not None else "page break"
    return {"html": markup(_prose(text[a:b].strip())), "pagebreak": label, "heading": False,
            "figure": False, "front": False, "notes": []}  # fmt: skip


# A figure's caption alone on its line (the figure itself is not in the OCR text): « Fig. 2. »
_FIGURE = re.compile(r"Fig\. \d+\.?")


MARGIN_DIGITS = 6  # an agreeing number's recomputed value in the margin; the table gives 10


def _note(mark: Placement, number: int, row: Row | None) -> dict[str, object]:
    """A margin note. An agreeing number's note is short, its recomputed value alone to six
    figures (the printed one is the marked text beside it, the verdict the colour of its
    label, all ten figures in the table): two such notes share a line of the margin, so the
    notes beside a table of numbers run on little past it (Lecornu's tables)."""
    text = edition_text(mark.note)  # the detail's numbers as the paper writes its own
    compact = not mark.finding and mark.how == "value" and row is not None and "recomputed" in row
    if compact and row is not None:
        text = edition_quantity(row.get("recomputed"), text_of(row, "unit"), MARGIN_DIGITS)
    text = note_subscripts(text)
    # the row's id without its paper's name, which the page is about (lecornu.eq.14: eq.14)
    return {"n": number, "key": mark.key, "row": mark.row_id, "css": mark.css.split()[0],
            "label": mark.row_id.split(".", 1)[-1], "compact": compact,
            "word": mark.word, "text": text, "finding": mark.finding}  # fmt: skip


def _cell(value: object, unit: str) -> str:
    """A number of the claims table: an angle sexagesimal as printed, others a decimal comma."""
    return edition_quantity(value, "angle") if unit == "angle" else number_text(value)


def _claim_rows(claims: Sequence[Row], at: Mapping[str, str]) -> list[dict[str, object]]:
    return [
        {"id": id_of(r), "at": at.get(id_of(r), ""), "css": css_of(r), "word": verdict_of(r),
         "source": text_of(r, "source"), "published": printed_form(text_of(r, "published")),
         "unit": text_of(r, "unit"), "recomputed": _cell(r.get("recomputed"), text_of(r, "unit")),
         "exact": _cell(r.get("exact"), text_of(r, "unit")), "own": own_of(r),
         "cause": word_of(r.get("cause")),
         "sources": sources_of(r), "note": text_of(r, "note")}
        for r in claims
    ]  # fmt: skip


def formula_cell(r: Row) -> dict[str, object]:
    order = r.get("observed_order")
    return {"id": id_of(r), "css": css_of(r), "word": verdict_of(r),
            "order": number_text(round(order, 2)) if isinstance(order, float) else ""}  # fmt: skip


def _equation_rows(equations: Sequence[Row], cited: Mapping[str, Sequence[Row]],
                   at: Mapping[str, str]) -> list[dict[str, object]]:  # fmt: skip
    return [
        {"id": id_of(r), "at": at.get(id_of(r), ""), "css": css_of(r), "word": verdict_of(r),
         "label": text_of(r, "equation"), "section": text_of(r, "section"),
         "statement": text_of(r, "statement"), "cause": EQUATION_CAUSE.get(verdict_of(r), ""),
         "correction": correction_of(r), "check": _check_of(r),
         "formulas": [formula_cell(f) for f in cited.get(id_of(r), [])],
         "note": _equation_note(r)}
        for r in equations
    ]  # fmt: skip


# an equation row's blame, condition and readings, shown after the ledger's note
_CONTEXT = (("condition", "conditional"), ("later_use", "blame"), ("carries", "carries"),
            ("step", "its own slip"), ("readings", "OCR, read"))  # fmt: skip


def _equation_note(row: Row) -> str:
    """The ledger's note, then a conditional verdict's two sides, the later use that decides
    the blame, what the row carries or restates and the OCR readings applied."""
    parts = [text_of(row, "note")] if text_of(row, "note") else []
    restated = row.get("restates")
    if isinstance(restated, list | tuple) and restated and verdict_of(row) != "definition":
        parts.append(f"restates {', '.join(map(str, restated))}: no finding of its own")
    parts += [f"{label}: {text_of(row, key)}" for key, label in _CONTEXT if text_of(row, key)]
    return "; ".join(parts)


def _check_of(row: Row) -> str:
    """The kind of check that decides the row and the engine's evidence ("" for none)."""
    kind, evidence = text_of(row, "kind"), text_of(row, "evidence")
    return f"{kind}: {evidence}" if kind else ""


def _formula_rows(formulas: Sequence[Row]) -> list[dict[str, object]]:
    return [
        {"id": id_of(r), "at": "", "css": css_of(r), "word": verdict_of(r),
         "source": text_of(r, "source"), "published": text_of(r, "published"),
         "recomputed": text_of(r, "recomputed"),
         "claimed_order": number_text(r.get("claimed_order")),
         "observed_order": number_text(r.get("observed_order")),
         "cause": word_of(r.get("cause")), "sources": sources_of(r), "note": text_of(r, "note")}
        for r in formulas
    ]  # fmt: skip


def paper_page(
    paper: str,
    citation: str,
    text: str,
    claims: Sequence[Row],
    formulas: Sequence[Row] = (),
    equations: Sequence[Row] = (),
    figures: Sequence[Figure] = (),
    stats: RenderStats | None = None,
    figures_later: bool = False,
) -> str:
    """One paper as an annotated edition, then its claims, equations, formulas and figures
    (``figures_later``: :data:`FIGURES_LATER` where they go, for figures still being drawn)."""
    stats = stats if stats is not None else RenderStats()
    marks, passages = place_marks(text, claims, equations)
    at: dict[str, str] = {}
    for m in [*marks, *(p for _, p in passages)]:
        at.setdefault(m.row_id, f"at-{m.key}" if m.end > m.start else f"note-{m.key}")
    cited = cited_formulas(equations, formulas)
    merged = {id_of(f) for fs in cited.values() for f in fs}
    alone = [f for f in formulas if id_of(f) not in merged]
    findings = [id_of(r) for r in [*claims, *equations, *alone] if disagrees(r)]
    rows = {id_of(r): r for r in [*claims, *equations]}
    blocks = _text_blocks(text, marks, passages, stats, rows)
    figures_html = markup(FIGURES_LATER) if figures_later else figure_section(figures, "figures")
    return render_template(
        "paper.html.j2",
        title=f"pendcli: {paper}", lang="fr", paper=paper, citation=citation, legend=_legend(),
        placed=_placed_text(claims, equations, marks, stats), findings=findings,
        front=[b for b in blocks if b["front"]], blocks=[b for b in blocks if not b["front"]],
        claims=_claim_rows(claims, at),
        equations=_equation_rows(equations, cited, at), formulas=_formula_rows(alone),
        figure_section=figures_html,
    )  # fmt: skip


def _placed_text(claims: Sequence[Row], equations: Sequence[Row], marks: Sequence[Placement],
                 stats: RenderStats) -> str:  # fmt: skip
    """What the page states about its marks, counted from the marks themselves: a row is
    *located* when a mark of it lies within its ``lines`` and covers what it was looked for
    by (its printed string, wrong term, label, the formula its printed form is, or its
    quoted words); a mark at the first formula or sentence of its lines is not."""
    tally = {
        "claims": placement_tally(claims, marks),
        "equations": placement_tally(equations, marks),
    }
    parts = []
    for what, name in (
        ("claims", "printed numbers"),
        ("equations", "equations and stated results"),
    ):
        t = tally[what]
        if t.rows:
            parts.append(
                f"{t.located} of {t.rows} {name} located within their printed lines"
                + (f" ({t.by_statement} of them at the formula nearest their statement, the "
                   "ledger giving no printed form)" if t.by_statement else "")
                + (f", {t.first} at the first formula or sentence of their lines (no printed "
                   "form to place them by: place not verified)" if t.first else "")
                + (f", {t.unverified} found by their printed string alone (no lines)"
                   if t.unverified else "")
                + f", {t.rows - t.located - t.first - t.unverified} not placed"
            )  # fmt: skip
    wrong = sum(m.how in ("term", "reading") for m in marks)
    slips = [r for r in equations if verdict_of(r) in ("misprint", "fails")]
    at_term = {m.row_id for m in marks if m.how == "term"}
    if slips:
        parts.append(
            f"{sum(id_of(r) in at_term for r in slips)} of {len(slips)} misprints and failures "
            "marked at their wrong term (the others at their label or formula: the ledger "
            "records no wrong term for them)"
        )
    return (
        "; ".join(parts) + f". {wrong} wrong terms or misread words marked. Formulas: "
        f"{stats.mathml} of {stats.formulas} rendered as MathML, {stats.plain} as a plain reading."
    )


@dataclass(frozen=True)
class PlacementTally:
    rows: int
    located: int  # a mark within its lines, on what it was looked for by
    first: int  # only at the first free formula or sentence of its lines
    unverified: int  # no lines: found by its printed string, its place not checked
    by_statement: int = 0  # located only at the formula nearest its statement (no printed form)


LOCATING = ("value", "term", "label", "formula", "quote", "reading")


def placement_tally(rows: Sequence[Row], marks: Sequence[Placement]) -> PlacementTally:
    """How the rows were placed, from the marks (see :func:`_placed_text`)."""
    by_row: dict[str, list[Placement]] = {}
    for m in marks:
        by_row.setdefault(m.row_id, []).append(m)
    located = first = unverified = by_statement = 0
    for row in rows:
        lines, own = lines_of(row), by_row.get(id_of(row), [])
        inside = [m for m in own if lines and lines[0] <= m.lines[0] and m.lines[1] <= lines[1]]
        if any(m.how in LOCATING for m in inside):
            located += 1
            by_statement += not text_of(row, "printed") and all(m.how == "formula" for m in inside)
        elif inside:
            first += 1
        elif own and lines is None:
            unverified += 1
    return PlacementTally(len(rows), located, first, unverified, by_statement)
