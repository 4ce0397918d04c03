"""The edition's numbers as the papers write them: a decimal comma in the notes, the tables
and the rendered formulas (the JSON and CSV outputs keep their decimal point)."""

from __future__ import annotations

import math
import random
import re
from html import unescape

import pytest

from pendcli.data.numbers import edition_number
from pendcli.data.tables import tables_dir
from pendcli.output.html.math import math_segments, to_mathml
from pendcli.output.html.paper import paper_page
from pendcli.papers.registry import PAPERS
from pendcli.papers.registry import paper as paper_of


def _read_back(text: str) -> float:
    """An edition number read back independently: comma as point, ·10ⁿ as a power of ten."""
    digits = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
    mantissa, _, power = text.replace("\u2212", "-").partition("·10")
    return float(mantissa.replace(",", ".")) * 10.0 ** int(power.translate(digits) or "0")


def test_an_edition_number_has_the_papers_decimal_comma_and_minus() -> None:
    assert edition_number(5.135622302) == "5,135622302"
    assert edition_number(-0.1322794874) == "\u22120,1322794874"
    assert edition_number(1.2e-5) == "1,2·10⁻⁵"
    assert edition_number(3) == "3" and edition_number(None) == "" and edition_number("x") == "x"


def test_an_edition_number_reads_back_as_its_value_to_ten_digits() -> None:
    rng = random.Random(21)
    for _ in range(500):
        value = rng.uniform(-1, 1) * 10.0 ** rng.randint(-12, 12)
        text = edition_number(value)
        assert "." not in text and "e" not in text and "-" not in text, text
        assert math.isclose(_read_back(text), value, rel_tol=1e-9), (value, text)


def test_the_edition_shows_recomputed_numbers_with_a_decimal_comma() -> None:
    text = "Les racines sont:\n\n$$5,14 \\quad 8,41$$\n"
    claims: list[dict[str, object]] = [
        {"id": "p.a", "published": "5,14", "verdict": "agrees", "recomputed": 5.135622302},
        {"id": "p.b", "published": "8,41", "verdict": "truncated", "recomputed": 8.41724414,
         "cause": "truncation"},
    ]  # fmt: skip
    page = paper_page("p", "A citation", text, claims)
    notes = re.findall(r'<p class="note[^"]*" id="note-[^"]+">(.*?)</p>', page, re.S)
    shown = unescape(re.sub(r"<[^>]+>", "", " ".join(notes)))
    assert "5,135622302" in shown and "recomputed 8,41724414" in shown, shown
    assert not re.search(r"\d\.\d", shown), shown
    cells = re.findall(r'<td class="num">([^<]*)</td>', page)
    assert "5,135622302" in cells and not any(re.search(r"\d\.\d", c) for c in cells), cells


def test_a_decimal_comma_in_a_formula_is_one_number_with_no_space() -> None:
    tex = "5,14 \\quad 0^m,35 \\quad 0^{sec}, 94 \\quad f(a,b) \\quad 0,91, 1,66"
    mathml = to_mathml(tex, False)
    assert mathml is not None
    assert "<mn>5,14</mn>" in mathml and "<mn>0,91</mn>" in mathml and "<mn>1,66</mn>" in mathml
    # after a unit set as an exponent, and a list's comma or an argument's, as before
    assert mathml.count('<mo lspace="0" rspace="0">,</mo>') == 2
    assert mathml.count("<mo>&#x0002C;</mo>") == 2  # f(a,b) and the list's « 0,91, 1,66 »


SEPARATED = r"<mn>(\d+)</mn>(?:<mrow>)?<mo>&#x0002C;</mo>(?:</mrow>)?<mn>(\d+)</mn>"


@pytest.mark.parametrize("paper", PAPERS)
def test_no_decimal_comma_of_the_papers_formulas_is_set_as_a_separator(paper: str) -> None:
    text = paper_of(paper).tables(tables_dir()).text.read_text("utf-8")
    split = []
    for s in math_segments(text):
        tex = text[s.tex_start : s.tex_end]
        mathml = to_mathml(tex, s.display) or ""
        # a comma between two numbers set as a separator: only where the TeX has a space
        for m in re.finditer(SEPARATED, mathml):
            if re.search(rf"{m.group(1)},{m.group(2)}", tex):
                split.append((m.group(0), tex[:60]))
    assert not split, split[:5]


def test_an_angle_is_shown_sexagesimal_as_the_paper_prints_it() -> None:
    from pendcli.data.numbers import edition_angle, edition_quantity, parse_printed

    assert edition_angle(-1.125872042) == "\u22121°7′33,14″"
    assert edition_quantity(0.0004685167801, "angle") == "1,69″"
    assert edition_quantity(0.1965922697, "mm") == "0,1965922697 mm"
    rng = random.Random(8)
    for _ in range(300):  # read back by the parser of the printed numbers, to 0,005″
        degrees = rng.uniform(-3, 3)
        shown = edition_angle(degrees).replace("\u2212", "-").replace("′", "'").replace("″", "''")
        assert abs(parse_printed(shown).value - degrees) <= 0.005 / 3600 + 1e-12, shown


def test_a_subscript_the_ocr_left_in_the_prose_is_set_as_one() -> None:
    from pendcli.output.html.paper import paper_page

    page = paper_page("p", "c", "Une relation entre I_n et I_n-2 ; E_c et psi_sin2.\n", [])
    assert "I<sub>n</sub> et I<sub>n\u22122</sub>" in page and "E<sub>c</sub>" in page
    assert "psi_sin2" in page  # a name, not a subscript
    assert "9. 1° Durée" in paper_page("p", "c", "9. 1^o Durée d'une oscillation.\n", [])


def test_the_reports_findings_name_a_cause_once_and_break_ids_at_their_dots() -> None:
    from pendcli.output.html.report import report_page

    claims: list[dict[str, object]] = [
        {"id": "p.b", "published": "8,41", "verdict": "discrepant", "cause": "arithmetic-slip"}
    ]
    equations: list[dict[str, object]] = [
        {"id": "p.eq.6", "equation": "(6)", "status": "misprint", "reading": "x = 3"},
        {"id": "p.result.compound_pendulum", "status": "fails", "corrected": "x = 2"},
    ]
    page = report_page(["p"], {"p": claims}, {}, {"p": equations})
    cells = [unescape(re.sub(r"<[^>]+>", "", c)) for c in re.findall(r"<td>(.*?)</td>", page)]
    assert "misprint" in cells and "misprint: misprint" not in cells, cells
    assert "fails: derivation-error" in cells and "discrepant: arithmetic-slip" in cells, cells
    assert "p.<wbr>result.<wbr>compound_pendulum</a>" in page


def test_a_claims_column_empty_for_every_row_is_left_out() -> None:
    text = "Les racines sont:\n\n$$5,14 \\quad 8,41$$\n"
    agree: list[dict[str, object]] = [
        {"id": "p.a", "published": "5,14", "verdict": "agrees", "recomputed": 5.1356}
    ]
    header = re.search(r"<h2>Printed numbers</h2>.*?</tr>", paper_page("p", "c", text, agree), re.S)
    assert header and "<th>cause</th>" not in header.group(0)
    assert "<th>exact</th>" not in header.group(0)
    slip = [{**agree[0], "verdict": "discrepant", "cause": "arithmetic-slip", "exact": 5.1}]
    header = re.search(r"<h2>Printed numbers</h2>.*?</tr>", paper_page("p", "c", text, slip), re.S)
    assert header and "<th>cause</th>" in header.group(0) and "<th>exact</th>" in header.group(0)


def _notes_text(page: str) -> str:
    notes = re.findall(r'<p class="note[^"]*" id="note-[^"]+">(.*?)</p>', page, re.S)
    return unescape(re.sub(r"<[^>]+>", "", " || ".join(notes)))


def test_a_printed_negative_value_is_shown_with_the_typeset_minus() -> None:
    """« −1,27 » as the text sets it, in the note and the claims table; the row keeps -1,27."""
    text = "La déviation est -1,27 ici.\n"
    claims: list[dict[str, object]] = [{"id": "p.d", "published": "-1,27",
        "verdict": "discrepant", "recomputed": -1.335486253, "cause": "propagated"}]  # fmt: skip
    page = paper_page("p", "c", text, claims)
    assert "printed \u22121,27, recomputed \u22121,335486253" in _notes_text(page)
    assert '<td class="num">\u22121,27 </td>' in page
    assert claims[0]["published"] == "-1,27"


def test_a_notes_detail_numbers_have_a_decimal_comma_but_not_its_names() -> None:
    """Numbers a detail string embeds take the decimal comma in the note; identifiers,
    versions, code words and products printed with points do not."""
    from pendcli.data.numbers import edition_text

    assert edition_text("holds (order 1.99); max residual 6.08e-02") == (
        "holds (order 1,99); max residual 6,08·10⁻²"
    )
    assert edition_text("ratio -1.286 at z = 5.14.") == "ratio \u22121,286 at z = 5,14."
    kept = "lecornu.eq.25, table26.first, v1.2.3, DOP853, rtol 1e-12, 2.4…n, 1.3.5…, 1°-2°"
    assert edition_text(kept) == kept
    text = "Donc\n\n$$x = 1$$\n"
    row = {
        "id": "p.eq.1",
        "status": "fails",
        "lines": [3, 3],
        "printed": "x = 1",
        "corrected": "x = 3.66723 (order 1.99, see p.eq.25)",
    }
    shown = _notes_text(paper_page("p", "c", text, [], (), [row]))
    assert "corrected: x = 3,66723 (order 1,99, see p.eq.25)" in shown, shown
    assert row["corrected"] == "x = 3.66723 (order 1.99, see p.eq.25)"


def test_a_quote_over_prose_and_a_formula_has_one_note_call() -> None:
    """Charbonnier's « $\\cos kt$ ne diffère de -1 … »: two marked pieces, one call, one note;
    the later piece links to the first's note (broken on purpose: with a call per piece the
    page has two calls and a 'continued' note)."""
    text = (tables_dir() / "papers" / "charbonnier.txt").read_text("utf-8")
    from helpers.edition import edition_rows

    claims, equations = edition_rows("charbonnier")
    page = paper_page("charbonnier", "c", text, claims, (), equations)
    key = "charbonnier.result.amplitude"
    pieces = re.findall(rf'id="at-{re.escape(key)}(~[^"]*)?"[^>]*data-note="([^"]*)"', page)
    assert len(pieces) >= 2 and {note for _, note in pieces} == {key}, pieces
    assert page.count(f'class="call"><a href="#note-{key}"') == 1
    assert len(re.findall(rf'id="note-{re.escape(key)}[~"]', page)) == 1
    assert "continued" not in _notes_text(page)
    calls = len(re.findall(r'class="call"', page))
    assert calls == len(re.findall(r'<p class="note', page)), calls


def test_a_subscript_in_a_notes_words_is_set_as_one_and_a_name_is_not() -> None:
    """Broken on purpose: without it the note shows « θ_0 = 30' » and Δθ'_m raw."""
    text = "Donc\n\n$$x = 1$$\n"
    row = {
        "id": "p.eq.1",
        "status": "fails",
        "lines": [3, 3],
        "printed": "x = 1",
        "corrected": "Δθ'_m = −ε E_s(π/2) and I_{n-2}; see psi_sin2 and p.x_bound",
    }
    page = paper_page("p", "c", text, [], (), [row])
    (note,) = re.findall(r'<p class="note[^"]*" id="note-p.eq.1">(.*?)</p>', page, re.S)
    assert "Δθ&#39;<sub>m</sub> = −ε E<sub>s</sub>(π/2) and I<sub>n\u22122</sub>" in note, note
    assert "psi_sin2 and p.x_bound" in note and "<script" not in note
    tisserand = (tables_dir() / "papers" / "tisserand.txt").read_text("utf-8")
    from helpers.edition import edition_rows

    shown = paper_page("tisserand", "c", tisserand, *edition_rows("tisserand")[:1])
    assert "« θ<sub>0</sub> = 30&#39;, θ<sub>1</sub> = 15&#39; »" in shown
    assert "θ_0 = 30" not in _notes_text(shown)
