"""The number style of each output (pendcli.output.style), against independent expectations.

The expected texts are worked out here by other means: Decimal rounding for significant
digits, integer arithmetic in seconds of arc for angles, the printed-number parser reading an
angle back; never the style's own output.
"""

from __future__ import annotations

import math
import random
from decimal import ROUND_HALF_EVEN, Decimal

import pytest

from pendcli.data.numbers import edition_angle, edition_number, paper_decimals, parse_printed
from pendcli.output.columns import Column, fmt_float
from pendcli.output.style import EDITION, MACHINE, MARKDOWN, TERMINAL, current, using
from pendcli.output.views import format_like_printed


def _significant(text: str) -> int:
    """Significant digits written in a fixed or scientific number (trailing zeros count)."""
    mantissa = text.strip().lstrip("-−+").split("e")[0].split("·")[0].replace(",", ".")
    digits = mantissa.replace(".", "").lstrip("0")
    return len(digits)


def _rounded(value: float, digits: int) -> Decimal:
    """``value`` to ``digits`` significant digits, by Decimal (half-even on the exact binary)."""
    exact = Decimal(value)
    exponent = exact.adjusted() - digits + 1
    return exact.quantize(Decimal(1).scaleb(exponent), rounding=ROUND_HALF_EVEN)


@pytest.mark.parametrize(
    "value", [math.pi, -math.e, 0.196592269695166, 0.979298399213, 1234.56789012, 2 / 3]
)
def test_terminal_shows_seven_significant_digits(value):
    text = TERMINAL.number(value)
    assert _significant(text) <= 7
    assert Decimal(text) == _rounded(value, 7).normalize()


def test_a_column_format_asking_more_gets_the_outputs_digits():
    # a column asking for 17 digits (the double's repr) shows 7 in the terminal, 10 in
    # Markdown, and what it asks for outside a renderer
    with using(TERMINAL):
        assert fmt_float(math.pi, 17) == "3.141593"
    with using(MARKDOWN):
        assert fmt_float(math.pi, 17) == "3.141592654"
    assert current().digits is None
    assert fmt_float(math.pi, 17) == "3.1415926535897931"


def test_machine_style_round_trips_every_double():
    rng = random.Random(5)
    for _ in range(2000):
        value = rng.uniform(-1, 1) * 10.0 ** rng.randint(-300, 300)
        text = MACHINE.number(value)
        assert "," not in text and float(text) == value


def test_a_column_keeps_trailing_zeros_and_aligns_the_decimal_point():
    values = [1.2179, 1.221, 0.0031314, -0.028703, 12.0]
    texts = TERMINAL.column(values, 5)
    for value, text in zip(values, texts, strict=True):
        assert Decimal(text.strip()) == _rounded(value, 5)  # 1.221 -> 1.2210, 12 -> 12.000
        assert _significant(text) == 5
        assert "e" not in text
    points = {len(t) - t.index(".") for t in texts}
    assert len(points) == 1, texts  # right-justified, the points in one place


def test_a_column_does_not_switch_notation():
    fixed = TERMINAL.column([0.5, 0.000909237, 12.25])
    assert not any("e" in t for t in fixed)
    assert Decimal(fixed[1].strip()) == _rounded(0.000909237, 7)
    tiny = TERMINAL.column([0.5, 3.2e-13, 2.0])  # one needs a power of ten: all have one
    assert all("e" in t for t in tiny)
    assert [float(t) for t in tiny] == [0.5, 3.2e-13, 2.0]


def test_an_implicit_float_column_in_the_terminal_is_one_notation():
    column = Column("x", "x")
    rows = [{"x": 0.5}, {"x": 0.000909237}, {"x": 2.0}, {"x": None}]
    with using(TERMINAL):
        texts = column.texts(rows)
    assert texts == ["0.5", "0.0009092370".rstrip("0"), "2", ""]


def _angle(deg: int, minutes: int, hundredths: int) -> float:
    return deg + minutes / 60 + hundredths / 360000


@pytest.mark.parametrize(
    ("degrees", "text"),
    [
        (-_angle(1, 7, 3314), "-1°7'33.14''"),
        (_angle(0, 0, 169), "1.69''"),
        (_angle(0, 2, 4220), "2'42.20''"),
        (_angle(9, 36, 3051), "9°36'30.51''"),
        (59.9999999 / 3600, "1'0.00''"),  # rounding carries into the minutes
        (-0.001 / 3600, "0.00''"),  # a rounded zero has no sign
    ],
)
def test_angles_are_sexagesimal_as_printed(degrees, text):
    assert TERMINAL.angle(degrees) == text
    read = parse_printed(text).value  # the printed-number parser reads it back
    assert abs(read - degrees) <= 0.005 / 3600 + 1e-15


def test_edition_style_is_the_papers():
    assert EDITION.number(-0.1322787) == "−0,1322787"
    assert EDITION.number(1.2e-5) == "1,2·10⁻⁵"
    assert EDITION.number(5.135622301840683) == edition_number(5.135622301840683)
    assert EDITION.angle(-_angle(1, 7, 3314)) == "−1°7′33,14″" == edition_angle(-_angle(1, 7, 3314))
    assert EDITION.listing([0.0, 0.91, 1.66]) == "0 ; 0,91 ; 1,66"
    assert TERMINAL.listing([0.0, 0.91, 1.66]) == "0, 0.91, 1.66"


def test_a_note_in_the_papers_decimal_comma():
    assert paper_decimals("ratio -1.286; allow |ratio| in [1.84, 1.98].") == (
        "ratio -1,286; allow |ratio| in [1,84 ; 1,98]."
    )
    assert paper_decimals("see lecornu.eq.25, version 1.2.3 and 6.08e-02") == (
        "see lecornu.eq.25, version 1.2.3 and 6,08·10⁻²"
    )
    listed = "corrected: 0, 0,91, 1,66, 2,23, 2,63 s"  # five numbers, not nine
    assert paper_decimals(listed) == "corrected: 0 ; 0,91 ; 1,66 ; 2,23 ; 2,63 s"
    assert paper_decimals("n = 1, 2, 3; rtol 1e-12, 2.4…n") == "n = 1, 2, 3; rtol 1e-12, 2.4…n"
    already = "(1 - 0,68)/0,35 = 0,914 → 0,91, and no reading"
    assert paper_decimals(already) == already


@pytest.mark.parametrize(
    ("value", "published", "most"),
    [
        (0.196592269695166, "1/5", None),
        (0.000909237, "1/1000", 10),
        (0.9817477042468103, "π·1·3·5/(2·4·6)", None),
    ],
)
def test_recomputed_beside_an_exact_printed_value_is_fixed_and_short(value, published, most):
    with using(TERMINAL):
        text = format_like_printed(value, published, most)
    assert "e" not in text and _significant(text) <= 7
    assert most is None or len(text) <= most
    decimals = len(text.split(".")[1])
    assert abs(Decimal(text) - Decimal(value)) <= Decimal(5).scaleb(-decimals - 1)


def test_recomputed_beside_a_printed_angle_is_an_angle_in_every_output():
    value = -_angle(1, 7, 3314) - 0.001 / 3600
    for style in (TERMINAL, MARKDOWN):
        with using(style):
            for most in (None, 10):
                text = format_like_printed(value, "-1°7'33''", most)
                assert text.startswith("-1°7'33") and text.endswith("''"), text


def test_an_implicit_float_column_with_a_tiny_value_is_scientific_throughout():
    column = Column("x", "x")
    with using(TERMINAL):
        texts = column.texts([{"x": 0.5}, {"x": 1e-5}, {"x": 2.5e-13}])
    assert texts == ["5e-01", "1e-05", "2.5e-13"]  # one notation, no trailing zeros
