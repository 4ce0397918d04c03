"""Markup in the tables and in a paper's text reaches the HTML edition, report.html and
report.md only as text: no element, attribute, link or image of its own.

The paper's TeX goes through latex2mathml, which copies ``\\text{…}`` verbatim and keeps
``\\href``: its MathML is filtered through an allowlist (checked here on crafted formulas and on
hypothesis' junk, whose output must parse as XML holding allowlisted tags and attributes only).
The tables' strings (quantity, source, note, ocr, unit, citation, the ledger's fields) are
escaped in the pages by Jinja and in Markdown by :mod:`pendcli.output.markdown` (rendered
here by markdown-it with every link allowed, so that a link would show). Most tests build
the pages in this process from small crafted rows; one runs ``reproduce --out`` for real on
a copy of ``tables/`` full of markup.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from html.parser import HTMLParser
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from markdown_it import MarkdownIt

from pendcli.data.rows import ClaimRow
from pendcli.data.vocabulary import Verdict
from pendcli.output.columns import Column
from pendcli.output.html.math import MATHML_ATTRIBUTES, MATHML_ELEMENTS, sanitise_mathml, to_mathml
from pendcli.output.html.paper import paper_page
from pendcli.output.html.report import report_page
from pendcli.output.markdown import code_span, fence, markdown_text, to_markdown
from pendcli.output.report_sections import disagreement_digest, explanation_section
from pendcli.output.views import claim_columns
from pendcli.run.reproduce import ReproduceResult

REPO_TABLES = Path(__file__).resolve().parents[2] / "tables"

TEX_ATTACKS = {
    "text": r"$\text{<script>alert(1)</script>}$",
    "href": r"$\href{javascript:alert(1)}{x}$",
    "mbox": r"$$\mbox{</math><img src=x onerror=alert(1)>}$$",
}
# One string per kind of markup a table's field could carry into a page or report.md.
FIELD_ATTACKS = [
    "[ref]: javascript:alert('r') [ref]",  # a link's definition, where a string starts a line
    "<script>alert('s')</script>",
    "<img src=x onerror=alert('i')>",
    "[link](javascript:alert('l'))",
    "![image](javascript:alert('m'))",
    "<javascript:alert('a')>",
    "\\[x\\](javascript:alert('b'))",
    "a | b <!-- c --> <svg onload=alert('v')>",
    "`x` &lt;script&gt; [ref][] <http://example.org>",
]
ATTACK = " ".join(FIELD_ATTACKS)


# --- what counts as live markup -------------------------------------------------------------


class _Elements(HTMLParser):
    """Every element of a page with its attributes, and the page's text."""

    def __init__(self) -> None:
        super().__init__()
        self.elements: list[tuple[str, dict[str, str]]] = []
        self.text: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.elements.append((tag, {k: v or "" for k, v in attrs}))

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def _parsed(html: str) -> _Elements:
    parser = _Elements()
    parser.feed(html)
    parser.close()
    return parser


def live_markup(html: str) -> list[str]:
    """What in ``html`` could run or lead anywhere: a script, frame or object, an image that
    is not an embedded PNG, an on* attribute, a link that is not to a page of the report, a
    link on anything but ``<a>``."""
    problems = []
    for tag, attrs in _parsed(html).elements:
        if tag in ("script", "iframe", "object", "embed", "frame", "base"):
            problems.append(f"<{tag}>")
        if tag == "img" and not attrs.get("src", "").startswith("data:image/png;base64,"):
            problems.append(f"<img src={attrs.get('src')!r}>")
        for name, value in attrs.items():
            if name.startswith("on") or "javascript:" in value.lower():
                problems.append(f"<{tag} {name}={value!r}>")
            if name in ("href", "src", "xlink:href") and tag not in ("a", "img"):
                problems.append(f"<{tag} {name}={value!r}>")
            if tag == "a" and name == "href" and not re.match(r"#|papers/|\.\./report", value):
                problems.append(f"<a href={value!r}>")
    return problems


def page_text(html: str) -> str:
    return "".join(_parsed(html).text)


def _markdown() -> MarkdownIt:
    md = MarkdownIt("commonmark", {"html": True}).enable("table")
    md.validateLink = lambda url: True  # every link shows: none may come from a string
    return md


MD = _markdown()


def live_markdown(text: str) -> list[str]:
    """The raw HTML, links and images Markdown would make of ``text`` (a figure of the
    report, ``figures/…`` or ``tradeoff/…``, aside)."""
    problems = []
    for token in MD.parse(text):
        for t in [token, *(token.children or [])]:
            if t.type in ("html_inline", "html_block", "link_open"):
                problems.append(f"{t.type}: {t.content or t.attrs}")
            src = str(t.attrs.get("src", "")) if t.type == "image" else ""
            if t.type == "image" and not re.match(r"(figures|tradeoff)/[\w/.-]+\.png$", src):
                problems.append(f"image: {src}")
    return problems


# --- the paper's TeX ------------------------------------------------------------------------


@pytest.mark.parametrize("kind", list(TEX_ATTACKS))
def test_tex_in_the_text_makes_no_markup(kind: str) -> None:
    text = f"Texte avant.\n\nAttaque {TEX_ATTACKS[kind]} fin.\n\nTexte après.\n"
    page = paper_page("lecornu", "a citation", text, [])
    assert live_markup(page) == []
    assert "<script" not in page and "<img" not in page and "javascript:" not in page


def test_tex_shows_its_words_where_the_formula_is_refused() -> None:
    page = paper_page("lecornu", "c", f"Attaque {TEX_ATTACKS['text']} fin.\n", [])
    assert "<script>alert(1)</script>" in page_text(page)  # shown, as text
    assert '<span class="plain-math">&lt;script&gt;' in page


def test_mathml_of_the_attacks_is_filtered() -> None:
    assert to_mathml(r"\text{<script>alert(1)</script>}", False) is None
    assert to_mathml(r"\mbox{</math><img src=x onerror=alert(1)>}", True) is None
    kept = to_mathml(r"\href{javascript:alert(1)}{x}", False)
    assert kept is not None and "href" not in kept and "<mi>x</mi>" in kept
    styled = to_mathml(r'{\color{red" onload="x} y}', False)
    assert styled is not None and "onload" not in styled and "<mi>y</mi>" in styled


def test_a_mark_colour_written_in_the_text_is_an_ordinary_colour() -> None:
    # the colour the marks are drawn with, in the text's own TeX: no mark of that number
    page = paper_page("lecornu", "c", r"Texte ${\color{#fe0009} x}$ fin." + "\n", [])
    assert '<mstyle mathcolor="#fe0009"><mi>x</mi></mstyle>' in page


def assert_allowlisted(mathml: str) -> None:
    """``mathml`` parses as XML: one <math>, MathML elements and attributes of the list."""
    root = ET.fromstring(mathml)
    assert root.tag.rpartition("}")[2] == "math"
    for element in root.iter():
        namespace, _, tag = element.tag.rpartition("}")
        assert namespace in ("", "{http://www.w3.org/1998/Math/MathML") and tag in MATHML_ELEMENTS
        for name, value in element.attrib.items():
            assert name in MATHML_ATTRIBUTES and MATHML_ATTRIBUTES[name].fullmatch(value)


MATHML_PIECES = [
    '<math xmlns="http://www.w3.org/1998/Math/MathML" display="block">', "</math>",
    "<mi>", "</mi>", "<mtext>", "</mtext>", '<mrow href="javascript:alert(1)">', "</mrow>",
    '<mspace width="1em" />', '<mspace width="<" />', "<script>", "</script>",
    "<img src=x onerror=alert(1)>", '<mstyle mathcolor="#fe0001" onclick="x">', "</mstyle>",
    '<mo stretchy="false" style="color:red">', "</mo>", '<mi mathvariant="javascript:x">',
    '<annotation-xml encoding="text/html">', "<svg>", '<a href="#x">', "</a>", "<math>",
    "&#x0003C;", "&#60;", "&lt;", "&nbsp;", "&#0;", "&#xD800;", "&", "<", ">", '"', "'",
    "<!--x-->", "<![CDATA[<b>]]>", "<?pi?>", "<!DOCTYPE x>", "\x00", "\x0b", "</", "\n",
]  # fmt: skip


TAGS = st.sampled_from(
    [*sorted(MATHML_ELEMENTS), "script", "img", "svg", "a", "annotation-xml", "iframe", "math"]
)
ATTRIBUTES = st.lists(
    st.tuples(
        st.sampled_from([*sorted(MATHML_ATTRIBUTES), "href", "onload", "style", "class", "src"]),
        st.sampled_from(["bold", "1em", "-.2em", "#fe0001", "red", "true", "left right", "0",
                         "javascript:alert(1)", "<", "x onload=y", "url(x)"])
        | st.text(max_size=5),
    ),
    max_size=3,
)  # fmt: skip
TEXTS = st.sampled_from(["x", "&#x0003C;", "&lt;", "&nbsp;", "<", "&", "</math>", "\x00"]) | (
    st.text(max_size=4)
)


def _element(tag: str, attributes: list[tuple[str, str]], children: list[str]) -> str:
    written = "".join(f' {name}="{value}"' for name, value in attributes)
    return f"<{tag}{written}>{''.join(children)}</{tag}>"


# A <math> element of elements, attributes and text drawn from the allowlist and beyond it,
# or tag soup.
MATHML = st.builds(
    lambda attributes, body: _element("math", attributes, [body]),
    ATTRIBUTES,
    st.recursive(
        TEXTS,
        lambda inner: st.builds(_element, TAGS, ATTRIBUTES, st.lists(inner, max_size=3)),
        max_leaves=12,
    ),
) | st.lists(st.sampled_from(MATHML_PIECES) | st.text(max_size=6), max_size=24).map("".join)


@settings(max_examples=400)
@given(MATHML)
def test_sanitised_mathml_is_allowlisted_xml(mathml: str) -> None:
    out = sanitise_mathml(mathml)
    if out is not None:
        assert_allowlisted(out)


@pytest.mark.parametrize(
    "reference", ["&#0;", "&#x0;", "&#xD800;", "&#xFFFE;", "&#x110000;", "&#11;"]
)
def test_a_reference_to_no_xml_character_refuses_the_formula(reference: str) -> None:
    """A character reference XML cannot hold (NUL, a surrogate, U+FFFE, past U+10FFFF, a
    control) would make the page's MathML ill-formed: the formula is refused (shown as its
    plain reading), where the reference alone would pass every other check."""
    assert sanitise_mathml(f"<math><mi>{reference}</mi></math>") is None
    kept = sanitise_mathml("<math><mi>&#x3C6;</mi><mo>&#60;</mo></math>")
    assert kept == "<math><mi>&#x3C6;</mi><mo>&#60;</mo></math>"
    assert ET.fromstring(kept).findtext("mi") == "φ"


TEX_PIECES = [
    r"\text{", r"\mbox{", r"\href{javascript:alert(1)}{", r"\style{color:red}{", r"\class{x}{",
    r"{\color{red"" onload=""x}", r"{\color{#fe0001}", "}", "{", "<script>", "</math>",
    "<img src=x onerror=alert(1)>", "x", r"\frac{1}{2}", "^", "_", "&", r"\\", r"\alpha",
    r"\begin{array}{cc}", r"\end{array}", r"\hspace{<x>}", r"\unicode{60}", r"\operatorname{",
    r"\mathrm{", r"\sqrt{", " ", "'", '"', r"\left(", r"\right)",
]  # fmt: skip


# 100 examples: an attribute kept whatever its value (the value patterns skipped) fails it
# within them for each of five seeds, as with 200
@settings(max_examples=100)
@given(st.lists(st.sampled_from(TEX_PIECES) | st.text(max_size=4), max_size=12), st.booleans())
def test_tex_junk_gives_allowlisted_mathml_or_none(pieces: list[str], display: bool) -> None:
    out = to_mathml("".join(pieces), display)
    if out is not None:
        assert_allowlisted(out)


# --- the tables' strings in the pages -------------------------------------------------------


def _claim(paper: str = "lecornu") -> dict[str, object]:
    return {"id": f"{paper}.attack", "paper": paper, "source": ATTACK, "quantity": ATTACK,
            "unit": ATTACK, "published": "1,5", "recomputed": 1.6, "exact": None,
            "verdict": "discrepant", "cause": "arithmetic-slip", "from": [], "note": ATTACK,
            "ocr": ATTACK, "as_printed": ATTACK, "lines": [1, 1]}  # fmt: skip


def _equation(paper: str = "lecornu") -> dict[str, object]:
    fields = ("section", "statement", "reading", "corrected", "wrong_term", "quote",
              "ledger_note", "note", "check")  # fmt: skip
    return {"id": f"{paper}.eq.6", "equation": "(6)", "status": "misprint", "lines": [1, 1],
            **dict.fromkeys(fields, ATTACK)}  # fmt: skip


def test_table_fields_in_the_paper_page_are_text() -> None:
    page = paper_page("lecornu", ATTACK, "Une ligne, 1,5.\n", [_claim()], [], [_equation()])
    assert live_markup(page) == []
    assert "<script" not in page and "<img" not in page and "<svg" not in page
    assert page_text(page).count(ATTACK) >= 8  # shown whole: citation, claim, ledger fields


def test_table_fields_in_report_html_are_text() -> None:
    root = {**_claim(), "id": "lecornu.<img src=x onerror=alert('id')>"}
    carried = {**_claim(), "cause": "propagated", "from": [root["id"]]}  # a node of the graph
    claims, equations = {"lecornu": [root, carried]}, {"lecornu": [_equation()]}
    page = report_page(["lecornu"], claims, {}, equations)
    assert live_markup(page) == []
    assert "<script" not in page and "<img" not in page and "<svg" in page
    assert page_text(page).count(ATTACK) >= 3  # the claims' notes, the ledger's


def _claim_row() -> ClaimRow:
    return ClaimRow(
        id="lecornu.<img src=x onerror=alert('id')>", paper="lecornu", source=ATTACK,
        quantity=ATTACK, unit=ATTACK, published="1,5", published_value=1.5, recomputed=1.6,
        verdict=Verdict.DISCREPANT, abs_diff=0.1, rel_diff=0.06, digits=1.0, exact=None,
        method="m", note=ATTACK, cause="propagated", cause_from=("lecornu.[x](javascript:y)",),
    )  # fmt: skip


def test_report_md_digest_and_explanations_are_text() -> None:
    result = ReproduceResult(papers=("lecornu",), claims={"lecornu": [_claim_row()]})
    text = "\n".join([*disagreement_digest(result), *explanation_section(result)])
    assert live_markdown(text) == []
    assert "<script" not in text and "<img" not in text and "<svg" not in text


def test_markdown_tables_of_rows_are_text() -> None:
    rows = [_claim_row().as_dict()]
    text = to_markdown(rows, claim_columns(rows))
    assert live_markdown(text) == []
    assert "<script" not in text and "<img" not in text
    cells = [t for t in MD.parse(text) if t.type == "td_open"]
    assert len(cells) == len(claim_columns(rows))  # a pipe in a string splits no cell


@pytest.mark.parametrize(
    "honest",
    ["a < b and x <= 1", "[0, π] and k'[1 + u²]/16", "E_c(π/2), θ'_m", "(p²/32)[(2γ³t³)]"],
)
def test_honest_strings_are_written_as_they_are(honest: str) -> None:
    assert markdown_text(honest) == honest


SPECIALS = st.text(alphabet="<>&[]()!\\`*_|:/ \nabcjs=\"'#;", max_size=40)


def _seen(text: str) -> str:
    """What a reader sees of ``text``, its spacing and the marks of emphasis and code aside."""
    return re.sub(r"[\s*_`]", "", text)


def _cells_seen(table: str) -> list[str]:
    tokens = MD.parse(table)
    cells = [tokens[i + 1] for i, t in enumerate(tokens) if t.type == "td_open"]
    shown = ("text", "code_inline", "html_inline")
    return [
        _seen("".join(c.content for c in cell.children or [] if c.type in shown)) for cell in cells
    ]


@settings(max_examples=400)
@given(SPECIALS)
def test_any_string_is_one_cell_of_text(text: str) -> None:
    """The cell shows the string's every character: a pipe left unescaped would cut it (the
    extra cell dropped), an escape inside a code span would show its backslash."""
    table = to_markdown([{"x": text}], [Column("x", "x")])
    assert live_markdown(table) == []
    assert _cells_seen(table) == [_seen(text)]


@pytest.mark.parametrize("text", ["`a\\b` & `<x>`", "a|b `c|d`", "[x`](`javascript:y)"])
def test_a_code_span_in_a_cell_shows_its_content_as_it_is(text: str) -> None:
    table = to_markdown([{"x": text}], [Column("x", "x")])
    assert live_markdown(table) == [] and _cells_seen(table) == [_seen(text)]


@settings(max_examples=300)
@given(SPECIALS.filter(lambda s: s.strip() != ""))
def test_a_code_span_holds_its_string_whole(text: str) -> None:
    tokens = MD.parseInline(f"printed {code_span(text)}, then")[0].children or []
    code = [t.content for t in tokens if t.type == "code_inline"]
    assert code == [re.sub(r"\r\n?|\n", " ", text)]


def test_a_code_block_of_ids_is_not_closed_by_them() -> None:
    lines = ["root (rounding)", "  └ x```` (propagated)", "````", "<script>alert(1)</script>"]
    block = "\n".join([fence(lines), *lines, fence(lines), "", "after"])
    tokens = MD.parse(block)
    assert [t.type for t in tokens][:1] == ["fence"] and live_markdown(block) == []
    assert tokens[0].content == "\n".join(lines) + "\n"
    assert fence(["root (rounding)"]) == "```"  # as the report always wrote it


# --- the whole report, for real -------------------------------------------------------------


def _sub(path: Path, old: str, new: str) -> None:
    text = path.read_text(encoding="utf-8")
    assert text.count(old) == 1, (path.name, old)
    path.write_text(text.replace(old, new), encoding="utf-8")


def markup_tables(folder: Path) -> Path:
    """A copy of ``tables/`` whose Tisserand strings and text carry markup."""
    shutil.copytree(REPO_TABLES, folder, ignore=shutil.ignore_patterns(".*"))
    published = folder / "published" / "tisserand.toml"
    ledger = folder / "equations" / "tisserand.toml"
    attack = json.dumps(ATTACK, ensure_ascii=False)[1:-1]  # in a TOML string
    _sub(published, 'p. 448-454"', f'p. 448-454 {attack}"')
    _sub(published, '"No value of g enters:', f'"{attack} No value of g enters:')
    _sub(published, "quantity = \"coefficient of sin 2k't in ψ(t),", f'quantity = "{attack}')
    _sub(published, "note = \"Arithmetic right: Tisserand's (II)", f'note = "{attack} (II)')
    _sub(ledger, 'section = "p. 450, « La formule (5) donnera ensuite »"', f'section = "{attack}"')
    _sub(ledger, 'reading = "« La formule (4) donnera »:', f'reading = "{attack} (4):')
    text = folder / "papers" / "tisserand.txt"
    body = text.read_text(encoding="utf-8").rstrip("\n")
    text.write_text(body + "\n\n" + " et ".join(TEX_ATTACKS.values()) + "\n", encoding="utf-8")
    return folder


def test_reproduce_out_of_tables_full_of_markup(tmp_path: Path) -> None:
    """`reproduce --out` in a process of its own, its figures plotted but not rendered to
    pixels (tests/helpers/undrawn_figures.py: the pages' text is what is read)."""
    from helpers.undrawn_figures import UNDRAWN_CLI

    tables = markup_tables(tmp_path / "tables")
    out = tmp_path / "out"
    env = {**os.environ, "PENDCLI_TABLES": str(tables), "PENDCLI_JOBS": "1"}
    command = [*UNDRAWN_CLI, "reproduce", "-p", "tisserand", "--no-formulas", "--no-stability",
               "--out", str(out)]  # fmt: skip
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr
    report = (out / "report.md").read_text(encoding="utf-8")
    assert live_markdown(report) == []
    assert "<script" not in report and "<img" not in report and "<svg" not in report
    shown = page_text(MD.render(report))  # as a reader of the rendered report.md sees it
    assert "<script>alert('s')</script>" in shown and "[ref]: javascript:" in shown
    for page in (out / "report.html", out / "papers" / "tisserand.html"):
        html = page.read_text(encoding="utf-8")
        assert live_markup(html) == [], page.name
        assert "<script" not in html and "<img src=x" not in html
    edition = page_text((out / "papers" / "tisserand.html").read_text(encoding="utf-8"))
    assert edition.count(ATTACK) >= 4 and "<script>alert(1)</script>" in edition
