"""The MathML the converter gives, as a reader sees it: no letter or digit of a formula lost,
and the papers' hard formulas set in the structure their TeX asks for."""

from __future__ import annotations

import re
import unicodedata
from collections import Counter
from html import unescape

import pytest

from pendcli.data.tables import tables_dir
from pendcli.output.html.math import math_segments, to_mathml
from pendcli.papers.registry import PAPERS

_FUNCTION_WORDS = {"sin", "cos", "tan", "cot", "sec", "log", "exp", "lim"}


def _letters_and_digits(s: str) -> Counter[str]:

    return Counter(c for c in unicodedata.normalize("NFKC", s) if c.isascii() and c.isalnum())


def _tex_letters(tex: str) -> Counter[str]:
    """The letters and digits a formula prints: its commands dropped (the function names
    kept, as they print), an environment's name too."""
    tex = re.sub(r"\\(?:begin|end)\{[^}]*\}(?:\{[rlc]+\})?", " ", tex)
    tex = re.sub(r"\\([A-Za-z]+)", lambda m: m.group(1) if m.group(1) in _FUNCTION_WORDS else " ",
                 tex)  # fmt: skip
    return _letters_and_digits(tex)


@pytest.mark.parametrize("paper", PAPERS)
def test_no_letter_or_digit_of_a_formula_is_lost_in_its_mathml(paper: str) -> None:
    """Every formula converts (none falls back to the plain reading: the count the page
    states), and its MathML prints the same letters and digits as its TeX."""
    text = (tables_dir() / "papers" / f"{paper}.txt").read_text("utf-8")
    lost, plain = [], 0
    for s in math_segments(text):
        tex = text[s.tex_start : s.tex_end]
        mathml = to_mathml(tex, s.display)
        if mathml is None:
            plain += 1
            continue
        shown = _letters_and_digits(unescape(re.sub(r"<[^>]+>", " ", mathml)))
        if shown != _tex_letters(tex):
            lost.append(tex[:80])
    assert (plain, lost) == (0, [])


def test_the_letter_check_sees_a_dropped_term() -> None:
    shown = _letters_and_digits(unescape(re.sub(r"<[^>]+>", " ", to_mathml("a + b", False) or "")))
    assert shown != _tex_letters("a + b + c") and shown == _tex_letters("a + b")


def _mathml(tex: str, display: bool = True) -> str:
    mathml = to_mathml(tex, display)
    assert mathml is not None, tex
    return mathml


def test_hard_formulas_of_the_papers_convert_to_the_structure_tex_sets() -> None:
    """The formulas Chromium showed wrongly: √(g/l) a root over the whole fraction, T' and
    φ'₀ a prime beside the letter (not a superscript, set twice raised and tiny), cos ω a
    thin space after the function, 0^{sec}, 94 an upright unit, an aligned formula's columns
    right then left, joined at its = sign."""
    root = _mathml(r"k = \sqrt{\frac{g}{l}},")
    assert re.search(r"<msqrt><mrow><mfrac><mrow><mi>g</mi></mrow><mrow><mi>l</mi></mrow>"
                     r"</mfrac></mrow></msqrt>", root)  # fmt: skip
    nested = _mathml(r"\sqrt{\frac{a}{g} \left(1 + \frac{\pi b}{2\sqrt{ag}}\right)}")
    assert nested.count("<msqrt>") == 2 and re.search(r"<msqrt><mrow><mfrac>.*<mrow><mo", nested)
    primed = _mathml(r"T' = \frac{1}{\varphi_0 \varphi'_0}")
    assert "<msup>" not in primed and "<msubsup>" not in primed
    assert re.search(r"<mi>T</mi><mo [^>]*>&#x02032;</mo>", primed)
    assert re.search(r"<msub><mrow><mi>&#x003C6;</mi><mo [^>]*>&#x02032;</mo></mrow><mn>0</mn>",
                     primed)  # fmt: skip
    spaced = _mathml(r"l \cos \omega + \sin^2 \omega + \sin(x)")
    assert re.search(r"<mi>l</mi><mspace [^>]*/><mi>cos</mi><mspace [^>]*/><mi>&#x003C9;</mi>",
                     spaced)  # fmt: skip
    assert re.search(r"<msup><mi>sin</mi><mn>2</mn></msup><mspace [^>]*/>", spaced)
    assert re.search(r"<mi>sin</mi><mo stretchy=\"false\">&#x00028;", spaced)  # sin(x): none
    unit = _mathml(r"0^{sec}, 94 \quad 1^m, 21 \quad x^m")
    assert "<mtext>sec</mtext>" in unit and "<mtext>m</mtext>" in unit
    assert "<msup><mi>x</mi><mi>m</mi></msup>" in unit  # an exponent m of a letter stays
    aligned = _mathml(r"\begin{aligned} k &= 1 \\ k' &= 2 \end{aligned}")
    assert aligned.count('<mtd columnalign="right">') == aligned.count('<mtd columnalign="left">')
    assert aligned.count("<mtr>") == 2
