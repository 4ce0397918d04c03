"""The HTML report: numbers located in the text, links both ways, everything escaped."""

from __future__ import annotations

import re
from pathlib import Path

from pendcli.html_report import locate, paper_page, propagation_svg, report_page

TEXT = "Les racines sont:\n$$5,14 \\quad 8,41$$ et la longueur 0^m, 68 <b> (15)\n"


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
    equations: list[dict[str, object]] = [{"id": "p.eq.15", "equation": "(15)", "status": "fails"}]
    return claims, equations


def test_paper_page_links_every_located_number_to_its_row_and_back() -> None:
    claims, equations = _rows()
    page = paper_page("p", "A <citation>", TEXT, claims, (), equations)
    for row_id in ("p.a", "p.b", "p.c", "p.eq.15"):
        assert f'id="at-{row_id}" href="#row-{row_id}"' in page
        assert f'<tr id="row-{row_id}"' in page
        assert f'href="#at-{row_id}"' in page
    assert 'id="at-p.d"' not in page and "not located in the OCR text" in page
    assert "&lt;b&gt;" in page and "<b>" not in page and "A &lt;citation&gt;" in page
    assert re.search(r'class="hl v-discrepant" id="at-p.b"', page)
    assert 'class="hl s-fails" id="at-p.eq.15"' in page


def test_propagation_graph_draws_an_edge_from_each_source() -> None:
    claims, _ = _rows()
    svg = propagation_svg(claims)
    assert svg.count("<line") == 1 and "#row-p.b" in svg and "#row-p.c" in svg
    assert "No row inherits" in propagation_svg(claims[:2])


def test_report_page_counts_causes_and_lists_what_does_not_hold(tmp_path: Path) -> None:
    claims, equations = _rows()
    page = report_page(["p"], {"p": claims}, {}, {"p": equations})
    assert page.count('href="papers/p.html#row-') >= 3  # two claims and the failing equation
    assert "arithmetic-slip" in page and "propagated" in page
    assert not re.search(r'(src|href)="(https?:)?//', page)  # self-contained: no fetch
