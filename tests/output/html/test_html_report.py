"""The HTML edition: marks at their place, formulas rendered, links both ways, the graph's
geometry, everything escaped."""

from __future__ import annotations

import itertools
import re
import shutil
from functools import cache
from html import unescape
from pathlib import Path

import pytest
from helpers.edition import edition_rows, formula_is_printed, line_of, misplaced, same_form
from markupsafe import escape

from pendcli.data.numbers import edition_text
from pendcli.data.tables import tables_dir
from pendcli.output.html.graph import layered_graph
from pendcli.output.html.locate import locate
from pendcli.output.html.marks import Placement, place_marks
from pendcli.output.html.math import math_segments, plain_math, to_mathml
from pendcli.output.html.report import (
    cited_formulas,
    correction_of,
    paper_page,
    propagation_svg,
    render_stats,
    report_page,
)
from pendcli.papers.registry import PAPERS

TEXT = (
    "Les racines sont:\n\n$$5,14 \\quad 8,41$$\n\net la longueur 0^m, 68 <b>\n\n"
    "$$(15) \\quad x = 1$$\n"
)


def test_locate_follows_reading_order_and_tolerates_ocr_spacing() -> None:
    spans = locate(TEXT, [["5,14"], ["8,41"], ["0^m, 68", "0^m,68"], ["9,99"]])
    assert [TEXT[a:b] for a, b in spans[:3]] == ["5,14", "8,41", "0^m, 68"]  # type: ignore[misc]
    assert spans[3] is None


def test_locate_marks_the_value_inside_a_formula_and_its_neighbour_separately() -> None:
    text = "$$\\psi = k' t - 1^{\\circ} 7' 33'' \\sin 2 k' t + 2'' \\sin 4 k' t,$$"
    spans = locate(text, [[text[2:-3], "-1°7'33''"], ["+ 2'' \\sin 4 k' t", "2''"]])
    assert [text[a:b] for a, b in spans] == ["- 1^{\\circ} 7' 33''", "2''"]  # type: ignore[misc]


def test_a_bare_digit_is_not_found_inside_a_longer_number() -> None:
    assert locate("0,35 et 15", [["5"]]) == [None]


def test_the_ocr_tex_of_the_three_papers_converts_to_mathml() -> None:
    """Measured over every $$ block and inline formula; a failure would show as plain text."""
    for paper in PAPERS:
        stats = render_stats((tables_dir() / "papers" / f"{paper}.txt").read_text("utf-8"))
        assert stats.formulas > 50 and stats.mathml == stats.formulas, (paper, stats)


def test_a_formula_latex2mathml_cannot_render_gets_a_plain_reading() -> None:
    assert to_mathml("\\frac{1}{2} \\unknowncommand x", display=True) is None
    reading = plain_math("\\frac{\\pi(7\\pi^2 - 3)}{32} \\sqrt{a g} \\quad \\theta_0")
    assert reading == "(π(7π² - 3))/(32) √(a g) θ₀"
    assert "\\" not in reading and "{" not in reading


def _rows() -> tuple[list[dict[str, object]], list[dict[str, object]]]:
    claims: list[dict[str, object]] = [
        {"id": "p.a", "published": "5,14", "verdict": "agrees", "recomputed": 5.1356},
        {"id": "p.b", "published": "8,41", "verdict": "discrepant", "cause": "arithmetic-slip"},
        {
            "id": "p.c",
            "published": "0^m,68",
            "verdict": "discrepant",
            "cause": "propagated",
            "from": ["p.b"],
        },
        {"id": "p.d", "published": "7,77", "verdict": "agrees"},
    ]
    equations: list[dict[str, object]] = [
        {"id": "p.eq.15", "equation": "(15)", "status": "fails", "wrong_term": "x = 1",
         "corrected": "x = 2", "check": "numeric: formula checks: p.eq15 fails"}
    ]  # fmt: skip
    return claims, equations


def test_paper_page_marks_every_located_row_and_links_both_ways() -> None:
    claims, equations = _rows()
    page = paper_page("p", "A <citation>", TEXT, claims, (), equations)
    for key in ("p.a", "p.b", "p.c", "p.eq.15"):
        assert re.search(rf'id="at-{re.escape(key)}"', page), key
        assert f'<tr id="row-{key}"' in page
        assert f'href="#at-{key}"' in page
    assert 'id="at-p.d"' not in page and "not placed in the text" in page
    assert "&lt;b&gt;" in page and "<b>" not in page and "A &lt;citation&gt;" in page
    assert "<math" in page and "$$" not in page and "\\quad" not in page
    # the wrong term of (15) is marked inside its formula, its correction beside it, once
    assert 'class="hl s-fails wrong" id="at-p.eq.15~term0"' in page
    assert page.count("corrected: x = 2") == 2  # the note beside the text and the table's cell
    assert "derivation-error" in page  # the equation row's cause column


def test_one_entry_per_finding_a_formula_check_joins_its_equation() -> None:
    claims, equations = _rows()
    formulas = [{"id": "p.eq15", "verdict": "fails", "published": "x = 1", "recomputed": "x = 2"}]
    assert [r["id"] for r in cited_formulas(equations, formulas)["p.eq.15"]] == ["p.eq15"]
    page = report_page(["p"], {"p": claims}, {"p": formulas}, {"p": equations})
    assert page.count('href="papers/p.html#row-p.eq.15"') == 1
    assert 'href="papers/p.html#row-p.eq15"' not in page and "with p.eq15: fails" in page
    paper = paper_page("p", "", TEXT, claims, formulas, equations)
    assert paper.count('href="#row-p.eq15"') == 0 and 'id="row-p.eq15"' in paper


def test_propagation_graph_draws_an_edge_from_each_source() -> None:
    claims, _ = _rows()
    svg = propagation_svg(claims)
    assert svg.count("<polyline") == 1 and "#row-p.b" in svg and "#row-p.c" in svg
    assert "No row inherits" in propagation_svg(claims[:2])


def test_report_page_counts_causes_and_lists_what_does_not_hold() -> None:
    claims, equations = _rows()
    page = report_page(["p"], {"p": claims}, {}, {"p": equations})
    assert page.count('href="papers/p.html#row-') >= 3  # two claims and the failing equation
    assert "arithmetic-slip" in page and "propagated" in page
    assert not re.search(r'(src|href)="(https?:)?//', page)  # self-contained: no fetch


# --- the graph: no edge through a label -----------------------------------------------------


def _crosses(p: tuple[float, float], q: tuple[float, float], box: tuple[float, ...]) -> bool:
    """Whether segment pq meets the open rectangle (x, y, w, h) (Liang-Barsky clipping)."""
    x, y, w, h = box
    t0, t1 = 0.0, 1.0
    dx, dy = q[0] - p[0], q[1] - p[1]
    for d, lo, hi in ((dx, x - p[0], x + w - p[0]), (dy, y - p[1], y + h - p[1])):
        if d == 0:
            if not lo < 0 < hi:
                return False
            continue
        a, b = sorted((lo / d, hi / d))
        t0, t1 = max(t0, a), min(t1, b)
    return t0 < t1


def test_the_segment_test_itself_sees_a_crossing() -> None:
    assert _crosses((0, 5), (20, 5), (5, 0, 5, 10))
    assert not _crosses((0, 20), (20, 20), (5, 0, 5, 10))


def _graph_of(paper: str) -> tuple[list[str], list[tuple[str, str]]]:
    """A layered graph of the paper's own: each printed input to the numbers the author's
    procedures compute from it (a superset of the propagation of slips, which is small)."""
    from pendcli.papers.registry import paper as registered

    procedures = registered(paper).author_procedures
    found = procedures() if procedures is not None else {}
    edges = [(s, i) for i, p in found.items() for s in p.inputs]
    return sorted({n for e in edges for n in e}), edges


@pytest.mark.parametrize("paper", ["lecornu"])
def test_no_edge_of_the_propagation_graph_crosses_a_label(paper: str) -> None:
    nodes, edges = _graph_of(paper)
    assert len(edges) > 10
    _, boxes, lines = layered_graph(nodes, edges, lambda n: "#" + n, lambda n: True)
    for (a, b), line in zip(edges, lines, strict=True):
        others = [(k.x, k.y, k.w, k.h) for n, k in boxes.items() if n not in (a, b)]
        for p, q in itertools.pairwise(line):
            hits = [n for n, box in zip(boxes, others, strict=False) if _crosses(p, q, box)]
            assert not any(_crosses(p, q, box) for box in others), (a, b, p, q, hits)
        start, end = boxes[a], boxes[b]
        assert line[0] == (start.x + start.w, start.y + start.h / 2)  # from its source's label
        assert line[-1] == (end.x, end.y + end.h / 2)  # to its target's label


# --- placement over the three papers' own rows ----------------------------------------------


@pytest.mark.parametrize("paper", PAPERS)
def test_each_mark_is_what_its_row_prints_and_lies_within_its_lines(paper: str) -> None:
    text = (tables_dir() / "papers" / f"{paper}.txt").read_text("utf-8")
    claims, equations = edition_rows(paper)
    assert all(r["lines"] for r in [*claims, *equations])  # every row says where it is printed
    assert misplaced(paper, text, claims, equations) == []
    marks, _ = place_marks(text, claims, equations)
    displays = [(s.start, s.end) for s in math_segments(text) if s.display]
    for m in marks:  # a label: inside a display formula
        if re.fullmatch(r"\([0-9IVX]+'?\)", text[m.start : m.end]):
            assert any(a <= m.start < b for a, b in displays), m.key
    spans = sorted((m.start, m.end) for m in marks if not m.whole and not m.nests)
    assert all(b <= c for (_, b), (c, _) in itertools.pairwise(spans))  # disjoint
    for outer in (m for m in marks if m.nests):  # a wrong term or quote around marks: whole
        assert outer.how in ("term", "quote"), outer.key
        met = [(a, b) for a, b in spans if a < outer.end and outer.start < b]
        assert met and all(outer.start <= a and b <= outer.end for a, b in met), outer.key
    assert {m.row_id for m in marks} == {str(r["id"]) for r in [*claims, *equations]}


def test_the_placement_check_sees_a_mark_moved_to_a_neighbour() -> None:
    """Broken on purpose: a claim's lines shifted, and cos θ1's series checked against the
    cos θ printed just above it in the same lines, are both caught."""
    text = (tables_dir() / "papers" / "tisserand.txt").read_text("utf-8")
    claims, equations = edition_rows("tisserand")
    shifted = [{**c, "lines": [c["lines"][0] - 2, c["lines"][1] - 2]}  # type: ignore[index]
               if c["id"] == "tisserand.example.phi_sin2" else c for c in claims]  # fmt: skip
    assert any(b.startswith("tisserand.example.phi_sin2") for b in
               misplaced("tisserand", text, shifted, equations))  # fmt: skip
    series = next(r for r in equations if r["id"] == "tisserand.result.cos-series")
    cos_theta1 = str(series["printed"]).split(";")[2]
    own = r"\cos \theta_1 = 1 - \frac{1}{2} u_1^2 - \frac{1}{8} u_1^4"
    neighbour = r"\cos \theta = 1 - \frac{1}{2} u^2 - \frac{1}{8} u^4"
    assert formula_is_printed(own, cos_theta1, [neighbour])
    assert not formula_is_printed(neighbour, cos_theta1, [own])


def test_each_formula_of_a_printed_form_is_marked_at_its_own_formula() -> None:
    """The three series of « On a les développements suivants » each at its own line, and
    the numerical example's four formulas at theirs."""
    text = (tables_dir() / "papers" / "tisserand.txt").read_text("utf-8")
    marks = place_marks(text, *edition_rows("tisserand"))[0]
    lines = {m.key: m.lines[0] for m in marks}
    assert [lines.get(k) for k in ("tisserand.result.cos-series",
            "tisserand.result.cos-series~formula1", "tisserand.result.cos-series~formula2")] == [
        56, 58, 60]  # fmt: skip
    # the numerical application (its 30', 15' read as degrees): marked at θ0 = 30',
    # θ1 = 15' (line 194); its printed numbers, at lines 198 and 200, by their claims
    example = sorted(m.lines[0] for m in marks
                     if m.row_id == "tisserand.result.numerical-application")  # fmt: skip
    assert example == [194]
    numbers = {
        m.key: m.lines[0]
        for m in marks
        if m.key.startswith("tisserand.example.p") and "~" not in m.key
    }
    assert numbers == {"tisserand.example.psi_sin2": 198, "tisserand.example.psi_sin4": 198,
                       "tisserand.example.phi_sin2": 200}  # fmt: skip


EXPECTED_PLACES = [
    # marks once put on a neighbouring term: (paper, mark key, the mark's text, words of the
    # same line); the table entry "2" is found as the number standing alone in its line, not
    # the factor 2
    ("charbonnier", "charbonnier.I_pi.n0", "2", "$I_n \\dots \\dots$"),
    ("tisserand", "tisserand.resal.rate", "\\frac{3}{8} u_0 u_1", "la solution de M. Resal"),
    ("tisserand", "tisserand.eq.13~term0", "\\sin^2 4k' t", "(13) \\quad"),
    ("tisserand", "tisserand.example.psi_sin2~reading0", "\\theta_0 = 30', \\quad \\theta_1 = 15'",
     "\\theta_0 = 30'"),
    ("lecornu", "lecornu.result.mean_pendulum~term0", "\\frac{\\pi(7\\pi^2 - 3)}{32}",
     "c'est-à-dire à $6,47"),
]  # fmt: skip


@pytest.mark.parametrize(("paper", "key", "printed", "beside"), EXPECTED_PLACES)
def test_each_mark_sits_on_the_term_it_marks(
    paper: str, key: str, printed: str, beside: str
) -> None:
    text = (tables_dir() / "papers" / f"{paper}.txt").read_text("utf-8")
    marks = {m.key: m for m in place_marks(text, *edition_rows(paper))[0]}
    mark = marks[key]
    assert text[mark.start : mark.end] == printed
    assert mark.anchored and mark.how in ("value", "term", "reading")
    line_start = text.rfind("\n", 0, mark.start) + 1
    line_end = text.find("\n", mark.end)
    assert beside in text[line_start:line_end]


def _marks_in_page(page: str) -> dict[str, list[tuple[int, int]]]:
    """The lines each row's marked elements say they cover (``data-lines``), by row."""
    out: dict[str, list[tuple[int, int]]] = {}
    for m in re.finditer(r'<[a-z]+ class="hl [^"]*"[^>]*data-row="([^"]+)" '
                         r'data-lines="(\d+)-(\d+)"', page):  # fmt: skip
        row = unescape(m.group(1))
        out.setdefault(row, []).append((int(m.group(2)), int(m.group(3))))
    return out


def _outside_lines(page: str, equations: list[dict[str, object]]) -> list[str]:
    """The ledger rows with no mark in the page, or a mark outside their ``lines``."""
    marked = _marks_in_page(page)
    bad = []
    for row in equations:
        first, last = row["lines"]  # type: ignore[misc]
        spans = marked.get(str(row["id"]), [])
        if not spans or any(a < first or b > last for a, b in spans):
            bad.append(f"{row['id']} {row['lines']}: marked at {spans}")
    return bad


@cache  # four tests read the same page and marks of a paper (0.4-0.6 s for Lecornu's)
def _page_and_marks(paper: str) -> tuple[str, str, tuple[Placement, ...]]:
    """A paper's text, its page of the edition's rows, and the marks placed in its text."""
    text = (tables_dir() / "papers" / f"{paper}.txt").read_text("utf-8")
    claims, equations = edition_rows(paper)
    page = paper_page(paper, "", text, claims, (), equations)
    return text, page, tuple(place_marks(text, claims, equations)[0])


@pytest.mark.parametrize("paper", PAPERS)
def test_every_ledger_row_is_marked_within_its_lines(paper: str) -> None:
    """On the page (its elements' data-lines) and in the text (the marks' own offsets,
    mapped to lines here, not by the code under test)."""
    text, page, placed = _page_and_marks(paper)
    equations = edition_rows(paper)[1]
    assert _outside_lines(page, equations) == []
    lines = {str(r["id"]): r["lines"] for r in equations}
    marks = [m for m in placed if m.row_id in lines]
    for m in marks:
        first, last = lines[m.row_id]  # type: ignore[misc]
        assert first <= line_of(text, m.start) and line_of(text, m.end - 1) <= last, m.key
        assert m.lines == (line_of(text, m.start), line_of(text, m.end - 1)), m.key
        assert text[m.start : m.end].strip(), m.key
    assert {m.row_id for m in marks} == set(lines)


def test_the_lines_check_sees_a_row_placed_by_shifted_lines() -> None:
    """Broken on purpose: (13) placed by lines shifted ten lines down is outside its own."""
    text = (tables_dir() / "papers" / "tisserand.txt").read_text("utf-8")
    claims, equations = edition_rows("tisserand")
    shifted = [
        {**r, "lines": [r["lines"][0] + 10, r["lines"][1] + 10]}  # type: ignore[index]
        if r["id"] == "tisserand.eq.13" else r
        for r in equations
    ]  # fmt: skip
    page = paper_page("tisserand", "", text, claims, (), shifted)
    assert [b.split()[0] for b in _outside_lines(page, equations)] == ["tisserand.eq.13"]


@pytest.mark.parametrize("paper", PAPERS)
def test_a_misprint_or_failure_has_its_reading_or_correction_beside_it_once(paper: str) -> None:
    page = _page_and_marks(paper)[1]
    equations = edition_rows(paper)[1]
    edition = page[page.index('<div class="edition">') : page.index("<h2>Printed numbers")]
    notes = [
        (k, _subscripts_as_tex(b))
        for k, b in re.findall(r'<p class="note [^"]*" id="note-([^"]+)">(.*?)</p>', edition)
    ]
    wrong = [r for r in equations if str(r["status"]) in ("misprint", "fails")]
    assert len(wrong) >= 3
    for row in wrong:
        correction = correction_of(row)
        own = [body for key, body in notes if unescape(key).split("~")[0] == row["id"]]
        assert own, row["id"]  # marked, with its note
        if correction:
            shown = _subscripts_as_tex(str(escape(edition_text(correction))))
            assert sum(shown in body for body in own) == 1, (row["id"], own)


def _subscripts_as_tex(html: str) -> str:
    """A note compared as the ledger writes it: a set subscript (<sub>m</sub>) and a TeX one
    (_m, _{n-2}) read alike."""
    plain = re.sub(r"<sub>(.*?)</sub>", r"_\1", html)
    return re.sub(r"_\{([^{}]*)\}", r"_\1", plain).replace("\u2212", "-")


Drawn = tuple[str, tuple[Placement, ...]]  # a page and the marks placed in its text


def _wrong_term_faults(text: str, claims: list[dict[str, object]],
                      equations: list[dict[str, object]],
                      drawn: Drawn | None = None) -> list[str]:  # fmt: skip
    """The misprint/fails rows whose wrong terms are not recorded, not each marked as printed
    within their lines (lines counted here), not drawn in the page, or whose reading or
    correction is not the note beside the first, once in the edition. ``drawn``: the page
    and marks of these rows when already made (the committed rows': _page_and_marks)."""
    wrong = [r for r in equations if str(r["status"]) in ("misprint", "fails")]
    if drawn is None:
        drawn = (paper_page("p", "", text, claims, (), equations),
                 tuple(place_marks(text, claims, equations)[0]))  # fmt: skip
    page, marks = drawn[0], {m.key: m for m in drawn[1]}
    edition = page[page.index('<div class="edition">') : page.index("<h2>Printed numbers")]
    notes = {
        k: _subscripts_as_tex(b)
        for k, b in re.findall(r'<p class="note [^"]*" id="note-([^"]+)">(.*?)</p>', edition)
    }
    bad = []
    for row in wrong:
        value = row["wrong_term"]
        shown = _subscripts_as_tex(str(escape(edition_text(correction_of(row)))))
        terms = [value] if isinstance(value, str) else list(value or ())  # type: ignore[call-overload]
        if not terms:
            bad.append(f"{row['id']}: no wrong term marked ({value!r})")
        bad += [_term_fault(text, row, i, term, marks, edition) for i, term in enumerate(terms)]
        key = str(escape(f"{row['id']}~term0"))
        if terms and (not shown or shown not in notes.get(key, "")):
            bad.append(f"{row['id']}~term0: its note is not {shown!r}")
        elif terms and sum(shown in body for body in notes.values()) != 1:
            bad.append(f"{row['id']}~term0: {shown!r} shown more than once")
    return [b for b in bad if b]


def _term_fault(text: str, row: dict[str, object], i: int, term: str,
                marks: dict[str, Placement], edition: str) -> str:  # fmt: skip
    """Why the row's i-th wrong term is not marked as printed within its lines ("" if it is)."""
    key, (first, last) = f"{row['id']}~term{i}", row["lines"]  # type: ignore[misc]
    mark = marks.get(key)
    drawn = rf'class="hl [^"]*\bwrong\b[^"]*" id="at-{re.escape(str(escape(key)))}"'
    if mark is None:
        return f"{key}: no wrong term marked ({term!r})"
    if not same_form(text[mark.start : mark.end], term):
        return f"{key}: marks {text[mark.start : mark.end]!r}"
    if not first <= line_of(text, mark.start) <= line_of(text, mark.end - 1) <= last:
        return f"{key}: outside its lines {row['lines']}"
    if not re.search(drawn, edition):
        return f"{key}: not drawn in the page"
    return ""


@pytest.mark.parametrize("paper", PAPERS)
def test_every_misprint_or_failure_is_marked_at_its_wrong_term_with_its_note_once(
    paper: str,
) -> None:
    text, page, placed = _page_and_marks(paper)
    claims, equations = edition_rows(paper)
    assert len([r for r in equations if str(r["status"]) in ("misprint", "fails")]) >= 3
    assert _wrong_term_faults(text, claims, equations, (page, placed)) == []


def test_the_wrong_term_check_sees_a_term_missing_or_not_printed_in_its_lines() -> None:
    """Broken on purpose: (13)'s wrong term dropped, or one the OCR does not print in its
    lines, is caught."""
    text = (tables_dir() / "papers" / "tisserand.txt").read_text("utf-8")
    row = next(r for r in edition_rows("tisserand")[1] if r["id"] == "tisserand.eq.13")
    for term in (None, "\\sin^3 4k' t"):
        # the row alone on the page: the other rows' marks are checked on the committed page
        faults = _wrong_term_faults(text, [], [{**row, "wrong_term": term}])
        assert {b.split(":")[0].split("~")[0] for b in faults} == {"tisserand.eq.13"}


def test_the_wrong_term_check_sees_a_second_term_that_is_not_printed() -> None:
    """Broken on purpose: delta_rhs's second wrong term (the 3/8 of u cos 3u) changed to one
    the text does not print is caught, as that term alone."""
    text = (tables_dir() / "papers" / "lecornu.txt").read_text("utf-8")
    row = next(r for r in edition_rows("lecornu")[1] if r["id"] == "lecornu.result.delta_rhs")
    first, second = row["wrong_term"]  # type: ignore[misc]
    assert second == "+ \\frac{3}{8} u \\cos 3u"
    # the row alone on the page: the other rows' marks are checked on the committed page
    broken = [{**row, "wrong_term": (first, "+ \\frac{7}{8} u \\cos 3u")}]
    faults = _wrong_term_faults(text, [], broken)
    assert [b.split(":")[0] for b in faults] == ["lecornu.result.delta_rhs~term1"]


@pytest.mark.parametrize("paper", PAPERS)
def test_located_counts_only_rows_at_their_own_place(paper: str) -> None:
    """The page's counts, recounted here from the marks' offsets: a row is located when a
    mark of it within its lines is not merely the first formula or sentence there."""
    text, page, marks = _page_and_marks(paper)
    claims, equations = edition_rows(paper)
    for rows, name in ((claims, "printed numbers"), (equations, "equations and stated results")):
        lines = {str(r["id"]): r["lines"] for r in rows}
        inside = {m.row_id for m in marks if m.row_id in lines and m.how != "first"
                  and lines[m.row_id][0] <= line_of(text, m.start)  # type: ignore[index]
                  and line_of(text, m.end - 1) <= lines[m.row_id][1]}  # type: ignore[index]  # fmt: skip
        stated = re.search(rf"(\d+) of (\d+) {name} located within their printed lines", page)
        assert stated and int(stated.group(2)) == len(rows), name
        assert int(stated.group(1)) == len(inside), name


def test_the_cover_page_of_the_digitisation_is_shown_apart() -> None:
    text = (tables_dir() / "papers" / "tisserand.txt").read_text("utf-8")
    claims, equations = edition_rows("tisserand")
    page = paper_page("tisserand", "", text, claims, (), equations)
    front = page[page.index('<details class="front">') : page.index("</details>")]
    edition = page[page.index('<div class="edition">') : page.index("<h2>Printed numbers")]
    assert "tous droits réservés" in front and "numdam.org/conditions" in front
    assert "tous droits réservés" not in edition and "numdam" not in edition.lower()
    assert "M. Resal a montré" in edition and "M. Resal a montré" not in front
    lecornu = (tables_dir() / "papers" / "lecornu.txt").read_text("utf-8")
    assert '<details class="front">' not in paper_page("lecornu", "", lecornu, [], (), [])


def test_pdf_printing_refuses_without_out_or_without_chromium(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from helpers.cli import invoke

    from pendcli.base.errors import PendcliError
    from pendcli.output.html import report as html_report

    code, _, err = invoke("reproduce", "-p", "tisserand", "--pdf")
    assert code == 2 and "--pdf needs --out" in err
    monkeypatch.setattr(shutil, "which", lambda _: None)
    with pytest.raises(PendcliError, match=r"needs Chromium \(apt-get install chromium\)"):
        html_report.print_pdfs(tmp_path)
    out = tmp_path / "out"
    code, _, err = invoke(
        "reproduce", "-p", "tisserand", "--no-formulas", "--out", str(out), "--pdf"
    )
    assert code == 2 and "needs Chromium" in err
    assert not out.exists()  # refused before anything was written


def test_the_ledgers_spellings_read_as_the_tex_prints_them() -> None:
    """∂²θ/∂u∂k spelt th_uk, ∂²θ/∂u² th_uu, ∫dx Integral(1, …): the same atoms as the TeX;
    an environment's name is no atom (a two-line aligned formula matches its printed form)."""
    from pendcli.output.html.match import atoms_of_printed, atoms_of_tex

    assert atoms_of_printed("th_uk") == atoms_of_tex(
        r"\frac{\partial^2 \theta}{\partial u \partial k}"
    )
    assert atoms_of_printed("th_uu") == atoms_of_tex(r"\frac{\partial^2 \theta}{\partial u^2}")
    assert atoms_of_printed("th_u") != atoms_of_tex(r"\frac{\partial \theta}{\partial k}")
    assert "1" not in atoms_of_printed("Integral(1, (x, 0, x)) = x")
    assert "1" in atoms_of_printed("Integral(1/x, (x, 0, x))")
    assert atoms_of_tex(r"\begin{aligned} x &= 1 \\ &= y \end{aligned}") == atoms_of_tex("x=1=y")


def test_a_running_head_is_shown_as_the_editions_page_break_not_as_text() -> None:
    """Charbonnier's foot of p. 145 (« Ann. de Mathémat., … (Avril 1908.) 10 ») sits between
    « quan- » and « tités »: the page shows it as the break between pp. 145 and 146, after
    the paragraph, not in it; the word it cut is joined, « quantités »."""
    text = (tables_dir() / "papers" / "charbonnier.txt").read_text("utf-8")
    page = paper_page("charbonnier", "", text, *edition_rows("charbonnier")[:1], ())
    edition = page[page.index('<div class="edition">') : page.index("<h2>Printed numbers")]
    body = "".join(re.findall(r'<div class="txt[^"]*">(.*?)</div>', edition, re.S))
    assert "Avril 1908" not in body and "Ann. de Math" not in body
    # the word cut at its hyphen either side of the foot, joined (tables/papers keeps the cut)
    assert "quantités de mouvement" in re.sub(r"<[^>]+>", "", body) and "quan-" not in body
    (shown,) = re.findall(r'<div class="pagebreak"[^>]*>(.*?)</div>', edition, re.S)
    assert "p. 145 | p. 146" in shown and "Avril 1908" in shown
    # the break after the paragraph it fell inside
    assert edition.index("tités de mouvement") < edition.index("pagebreak")
    for paper in ("tisserand", "lecornu"):  # no running head left in their OCR
        other = (tables_dir() / "papers" / f"{paper}.txt").read_text("utf-8")
        assert 'class="pagebreak"' not in paper_page(paper, "", other, [], (), [])


def test_reference_words_builds_only_the_names_the_texts_name(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Builders named as a whole word, not after a dot, are built; the others never are
    (the texts are searched once for their words, then each found name as a word)."""
    import pendcli.verify.ledger_references as ledger_references
    from pendcli.output.html.report import reference_words
    from pendcli.papers import registry

    built: list[str] = []

    class Built:
        def __init__(self, what: str) -> None:
            self.what = what

    def builder(name: str) -> object:
        return lambda: built.append(name) or Built(f"what {name} models")

    names = ["ref_a", "ref_b", "ref_c", "ref_d", "ref_é", "ref-e"]
    table = {n: builder(n) for n in names}
    monkeypatch.setattr(ledger_references, "reference_table", lambda p: table)
    texts = ["against ref_a, and module.ref_b", "ref_cd and (ref_é) and ref-e."]
    found = reference_words(texts)
    joined = "\n".join(texts)
    expected = {  # an independent search: each name as a word not after a dot
        n for n in names if re.search(rf"(?<![\w.]){re.escape(n)}(?![\w])", joined)
    }
    assert set(found) == expected == {"ref_a", "ref_é", "ref-e"}
    assert found["ref_a"] == "what ref_a models"
    assert set(built) == expected  # ref_b, ref_c, ref_d never built
    assert len(built) == len(expected) * len(registry.all_papers())


def test_a_page_finished_with_its_figures_is_the_page_drawn_with_them(tmp_path: Path) -> None:
    """The pages are rendered while the figures are drawn, without them, and finished with
    them: each file is the page rendered with its figures at once, read as a reader reads it."""
    from pendcli.data.reader_text import html_for_reader
    from pendcli.output.html.report import (
        Figure,
        Pages,
        page_without_figures,
        reference_words,
        write_pages,
    )

    claims, equations = _rows()
    figures = {}
    for key in ("p", ""):
        path = tmp_path / f"fig{key}.png"
        path.write_bytes(b"\x89PNG not really" + key.encode())
        figures[key] = [Figure(path, f"x_(n,s) against n <b> for {key or 'all'}")]
    made = Pages(["p"], {"p": "A citation"}, {"p": TEXT}, {"p": claims}, {}, {"p": equations})
    rendered = [page_without_figures(made, page) for page in made.order()]
    written = write_pages(tmp_path / "out", made, rendered, figures)
    at_once = {
        "p.html": paper_page("p", "A citation", TEXT, claims, (), equations, figures["p"]),
        "report.html": report_page(["p"], {"p": claims}, {}, {"p": equations}, figures[""]),
    }
    assert [p.name for p in written] == ["p.html", "report.html"]
    for path in written:
        expected = html_for_reader(at_once[path.name], reference_words([at_once[path.name]]))
        assert path.read_text("utf-8") == expected, path.name
        assert "<figcaption>x<sub>n,s</sub> against n &lt;b&gt; for" in expected
