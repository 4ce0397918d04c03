"""What a historian reads carries no internal name and no raw TeX.

The report (Markdown and HTML), the edition of the three texts and `pendcli list` are scanned
for module paths (verify/…), reference builders' names (reference_in_…), editors' tags (a letter
and two digits), TeX groups (^{…}, _{…}), TeX commands (\\frac) and the ledger's linear
subscripts (_(…)).
The edition's joins of the paragraphs the OCR cut are checked against the text file itself.
"""

from __future__ import annotations

import html
import itertools
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pendcli.data.reader_text import figure_text, for_reader, markdown_for_reader, wrapped
from pendcli.data.reading import prose_paragraphs
from pendcli.output.html.prose import continues, prose_html

ROOT = Path(__file__).resolve().parents[2]
PAPERS = ("tisserand", "lecornu", "charbonnier")

# what may not reach a reader, by name
INTERNAL = {
    "module path": (
        r"(?<![\w/])(?:core|render|numerics|pendcli|base|data|verify|output|run|papers|cli)/\w+"
    ),
    "reference builder": r"\breference_\w+|\bnumbers_\w+",
    "editor's tag": r"(?<![\w.])n\d{2}(?![\w.])",
    "TeX group": r"[\^_]\{",
    "TeX command": r"\\(?:frac|sqrt|int|sum|mathrm|text|quad)\b",
    "linear subscript": r"_\(",
    "unit in TeX": r"\d\^\{?(?:sec|m|s)\b",
}


def internal_names(text: str) -> list[str]:
    """Each internal name or piece of raw TeX in ``text``, with its context."""
    found = []
    for what, pattern in INTERNAL.items():
        for m in re.finditer(pattern, text):
            found.append(f"{what}: …{text[max(0, m.start() - 50) : m.end() + 30]}…")
    return found


def test_the_scan_knows_the_package_s_module_paths() -> None:
    for path in ("verify/printed_check", "data/ledger", "base/workers", "papers/lecornu"):
        assert internal_names(f"judged by ({path})"), path
    assert not internal_names("the file tables/papers/lecornu.txt")


def alt_texts(page: str) -> list[str]:
    """The images' alt texts of an HTML page, as a screen reader speaks them."""
    return [html.unescape(v) for v in re.findall(r'\salt="([^"]*)"', page)]


def test_an_images_alt_text_is_read_as_its_caption_is() -> None:
    """A module path in a figure's caption is dropped from the alt text as from the caption
    shown; the alt text stays escaped (a quote or a tag in it cannot leave the attribute)."""
    from pendcli.data.reader_text import html_for_reader

    caption = "residuals (verify/printed_check), &lt;b&gt; &#34;x&#34;"
    page = f'<figure><img alt="{caption}" src="data:,"><figcaption>{caption}</figcaption></figure>'
    assert internal_names(" ".join(alt_texts(page)))  # the scan sees the path unread
    read = html_for_reader(page)
    (alt,) = alt_texts(read)
    assert internal_names(alt) == [] and alt == visible_text(read).strip()
    assert alt == 'residuals, <b> "x"' and "<b>" not in read


def visible_text(page: str) -> str:
    """An HTML page's text as a reader sees it: no tags, no MathML, style or script."""
    for tag in ("math", "style", "script"):
        page = re.sub(rf"<{tag}\b.*?</{tag}>", " ", page, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", " ", page))


# --- the rendering, against what a reader should see ---------------------------------------


@pytest.mark.parametrize(
    ("text", "shown"),
    [
        ("printed `0^{sec},94`", "printed `0ˢᵉᶜ,94`"),
        ("printed 1^m,21 and l = 0^m,5", "printed 1ᵐ,21 and l = 0ᵐ,5"),
        ("+ ∫_(x0)^(x1) dx/(xφ'²)", "+ ∫ₓ₀ˣ¹ dx/(xφ'²)"),
        ("exactly j_(1,1)²/4", "exactly j₁,₁²/4"),
        ("« I_{-1} à π »", "« I₋₁ à π »"),
        (
            "Judged by its printed digits (verify/printed_numeric), the",
            "Judged by its printed digits, the",
        ),
        ("an inequality (verify/printed_check), on", "an inequality, on"),
        (
            "the ids psi_sin2, eq_8 and lecornu.x_bound",
            "the ids psi_sin2, eq_8 and lecornu.x_bound",
        ),
    ],
)
def test_a_note_reads_as_the_page_prints_it(text: str, shown: str) -> None:
    assert for_reader(text) == shown


def test_a_reference_is_named_by_what_it_models() -> None:
    note = "cites (II)'s check eq_II and reference reference_in_kpt_order_4"
    shown = for_reader(note, {"reference_in_kpt_order_4": "(4), (5), (3) in k't, to order 4"})
    assert shown == "cites (II)'s check eq_II and reference “(4), (5), (3) in k't, to order 4”"


def test_a_script_without_unicode_is_a_tag_in_html_and_kept_whole_in_code() -> None:
    assert for_reader("φ'_(dθ0/dt)", html=True) == "φ'<sub>dθ0/dt</sub>"
    assert markdown_for_reader("`E_c = k^(n+1)` and k^(n−1)") == "`E_c = kⁿ⁺¹` and kⁿ⁻¹"


def test_a_figure_title_breaks_outside_parentheses_and_sets_its_scripts() -> None:
    title = "amplitude lost per swing Δα/α, resistance b_n v^n, (n, β) = (1, 0.01), (2, 0.01)"
    lines = wrapped(figure_text(title), 30).split("\n")
    for line in lines:
        assert line.count("(") == line.count(")"), lines
    assert "bₙ vⁿ" in " ".join(lines) and "_" not in "".join(lines)
    assert figure_text("zeros j_(ν,s) of J1") == "zeros j$_{ν,s}$ of J1"  # mathtext: no ν below
    assert figure_text("I_n(x) = ∫_0^x sin^(n+1) t dt") == "Iₙ(x) = ∫₀ˣ sinⁿ⁺¹ t dt"


def test_the_work_precision_titles_have_no_raw_notation() -> None:
    from pendcli.run.tradeoff import families, family_title

    for name in families():
        title = family_title(name)
        outside = re.sub(r"\$[^$]*\$", "", title)
        assert not re.search(r"[_^]", outside), title
        for line in title.split("\n"):
            assert line.count("(") == line.count(")"), title


# --- the edition's paragraphs, against the text file ---------------------------------------


def _cut_words(paper: str) -> list[tuple[str, str]]:
    """(the cut word's head, its tail) wherever a paragraph of the text file ends a word at its
    hyphen and the next paragraph, one blank line below, goes on in lower case."""
    text = (ROOT / "tables" / "papers" / f"{paper}.txt").read_text(encoding="utf-8")
    lines = text.split("\n")
    spans = prose_paragraphs(text)
    cuts = []
    for (_, end), (start, _) in itertools.pairwise(spans):
        last, first = lines[end - 1].rstrip(), lines[start - 1].lstrip()
        head = re.search(r"(\w+)-\**$", last)
        tail = re.match(r"(\w+)", first)
        if start == end + 2 and head and tail and first[0].islower():
            cuts.append((head.group(1), tail.group(1)))
    return cuts


def test_the_text_file_has_words_cut_across_paragraphs() -> None:
    assert ("résis", "tance") in _cut_words("charbonnier")  # the scan itself sees one


def test_a_word_cut_at_its_hyphen_is_joined() -> None:
    assert continues("l'accélération de cette résis-", "tance, c étant") == "cut"
    assert continues("un pendule ayant un mètre de", "longueur à l'instant") == "space"
    assert continues("la durée.", "une autre") is None
    assert continues("il est peut-", "être vrai") == "hyphen"
    assert prose_html("cette résis-\ntance, c") == "cette résistance, c"
    assert prose_html("a\u2003\u2003b\nc\u2003\u2003d") == "a\u2003\u2003b<br>c\u2003\u2003d"


@pytest.fixture(scope="module")
def edition_pages(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    """The three papers' pages and the report page, from the tables' rows (no computation),
    as write_html_report writes them."""
    from helpers.edition import edition_rows

    from pendcli.data.tables import load_paper_table, paper_text
    from pendcli.output.html.report import write_html_report

    out = tmp_path_factory.mktemp("edition")
    rows = {p: edition_rows(p) for p in PAPERS}
    write_html_report(
        out,
        PAPERS,
        {p: load_paper_table(p).citation for p in PAPERS},
        {p: paper_text(p) for p in PAPERS},
        {p: rows[p][0] for p in PAPERS},
        {p: [] for p in PAPERS},
        {p: rows[p][1] for p in PAPERS},
        {},
    )
    pages = {p: (out / "papers" / f"{p}.html").read_text("utf-8") for p in PAPERS}
    return {**pages, "report": (out / "report.html").read_text("utf-8")}


@pytest.mark.parametrize("paper", PAPERS)
def test_the_edition_joins_the_words_the_ocr_cut(edition_pages: dict[str, str], paper: str) -> None:
    shown = " ".join(visible_text(edition_pages[paper]).split())
    for head, tail in _cut_words(paper):
        assert f"{head}{tail}" in shown, (head, tail)
        assert f"{head}- {tail}" not in shown and f"{head}-\n" not in shown


def test_the_edition_calls_its_notes_in_order(edition_pages: dict[str, str]) -> None:
    for paper in PAPERS:
        body = edition_pages[paper].split('class="edition"', 1)[1].split("<h2>", 1)[0]
        calls = [int(n) for n in re.findall(r'<sup class="call[^"]*">(?:<a[^>]*>)?\[(\d+)\]', body)]
        assert calls == sorted(calls), paper


@pytest.mark.parametrize("page", [*PAPERS, "report"])
def test_the_edition_shows_no_internal_name(edition_pages: dict[str, str], page: str) -> None:
    assert internal_names(visible_text(edition_pages[page])) == []


def test_the_legend_explains_every_badge(edition_pages: dict[str, str]) -> None:
    page = edition_pages["lecornu"]
    legend = page.split('class="legend"', 1)[1].split("</p>", 1)[0]
    badges = set(re.findall(r'<span class="(?:hl )?(s-[\w-]+|v-[\w-]+)[" ]', page))
    assert badges and all(f'class="{b}"' in legend for b in badges), badges


def test_list_shows_printed_units_raised() -> None:
    from pendcli.cli.main import app

    for fmt in ("table", "markdown"):
        result = CliRunner().invoke(app, ["list", "-f", fmt], env={"COLUMNS": "200"})
        assert result.exit_code == 0
        assert internal_names(result.stdout) == [], fmt
        assert "0ᵐ,5" in result.stdout


# --- the whole report (slow: every paper reproduced) ---------------------------------------


def test_the_pages_of_a_whole_report_show_no_internal_name(
    tmp_path: Path, computed_tables: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every paper's pages, written from the run's shared computation of every table
    (tests/helpers/regenerated.py): what is scanned is the writing. The figures are plotted
    (their captions and titles made as in a report) but not rendered to pixels, which the
    scan does not read."""
    from helpers.regenerated import served
    from helpers.undrawn_figures import figures_not_rendered

    from pendcli.output.report import write_report
    from pendcli.papers import registry

    figures_not_rendered(monkeypatch)
    result = served(computed_tables)(registry.keys(), equations=True, jobs=1)
    write_report(result, tmp_path / "out", quiet=True, jobs=1)
    out = tmp_path / "out"
    assert internal_names((out / "report.md").read_text("utf-8")) == []
    for page in [out / "report.html", *sorted((out / "papers").glob("*.html"))]:
        text = page.read_text("utf-8")
        assert internal_names(" ".join([visible_text(text), *alt_texts(text)])) == [], page.name
