"""Parsing printed numbers: values and the precision the print implies.

Expectations are exact rationals (Fraction) or mpmath at 30 digits, never the parser's own
floating-point expression.
"""

from fractions import Fraction

import mpmath
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pendcli.base.errors import PendcliError
from pendcli.data.numbers import exact_number, parse_printed


@pytest.mark.parametrize(
    ("text", "value", "resolution"),
    [
        ("5,14", 5.14, 0.01),
        ("-0,130", -0.130, 0.001),
        ("+0,072", 0.072, 0.001),
        ("0.25", 0.25, 0.01),
        ("0,00313", 0.00313, 1e-5),
        ("1", 1.0, 1.0),
        ("0^m,35", 0.35, 0.01),
        ("2^{sec},86", 2.86, 0.01),
        ("0^{sec}", 0.0, 1.0),
        ("1^m", 1.0, 1.0),
    ],
)
def test_decimals(text, value, resolution):
    p = parse_printed(text)
    assert p.kind == "decimal"
    assert p.value == pytest.approx(value, abs=1e-15)
    assert p.resolution == pytest.approx(resolution, rel=1e-12)


def _arc(d: int, m: int, s: Fraction | int) -> Fraction:
    """Degrees, minutes, seconds of arc as an exact number of degrees."""
    return d + Fraction(m, 60) + Fraction(s) / 3600


@pytest.mark.parametrize(
    ("text", "degrees", "resolution_arcsec"),
    [
        ("1°7'33''", _arc(1, 7, 33), 1),
        ("2''", _arc(0, 0, 2), 1),
        ("2'42''", _arc(0, 2, 42), 1),
        ("30'", Fraction(1, 2), 60),
        ("20°", Fraction(20), 3600),
        ("-1°7'33''", -_arc(1, 7, 33), 1),
        ("1°7′33″", _arc(1, 7, 33), 1),
        ("1°7'33,25''", _arc(1, 7, Fraction(3325, 100)), Fraction(1, 100)),
    ],
)
def test_sexagesimal(text, degrees, resolution_arcsec):
    p = parse_printed(text)
    assert p.kind == "sexagesimal"
    assert p.value == pytest.approx(float(degrees), rel=2e-16, abs=1e-300)
    assert p.resolution == pytest.approx(float(Fraction(resolution_arcsec) / 3600), rel=1e-15)


@pytest.mark.parametrize(
    ("text", "fraction", "pi_power"),
    [
        ("1/5", Fraction(1, 5), 0),
        ("2·2/(1·3)", Fraction(4, 3), 0),
        ("2 2/(1·3)", Fraction(4, 3), 0),
        ("2·2·4/(1·3·5)", Fraction(16, 15), 0),
        ("π·1·3/(2·4)", Fraction(3, 8), 1),
        ("π", Fraction(1), 1),
        ("(7·π·π - 3)", None, None),
    ],
)
def test_exact_expressions(text, fraction, pi_power):
    if fraction is None:
        with pytest.raises(PendcliError):
            parse_printed(text)
        return
    p = parse_printed(text)
    assert p.is_exact and p.resolution is None
    assert p.exact == fraction
    assert p.pi_power == pi_power
    with mpmath.workdps(30):
        reference = mpmath.mpf(fraction.numerator) / fraction.denominator * mpmath.pi**pi_power
    assert p.value == pytest.approx(float(reference), rel=2e-16)


@pytest.mark.parametrize("text", ["", "  ", "abc", "1,2,3", "1°7'x", "(2", "2/0", "2·", "1'2'3'"])
def test_malformed_values_raise_one_clear_error(text):
    with pytest.raises(PendcliError) as err:
        parse_printed(text)
    assert "\n" not in str(err.value)


@given(
    sign=st.sampled_from(["", "-", "+"]),
    whole=st.integers(min_value=0, max_value=10**6),
    frac=st.text(alphabet="0123456789", min_size=0, max_size=8),
    comma=st.booleans(),
)
def test_decimal_roundtrip(sign, whole, frac, comma):
    text = f"{sign}{whole}" + ((("," if comma else ".") + frac) if frac else "")
    p = parse_printed(text)
    exact = whole + (Fraction(int(frac), 10 ** len(frac)) if frac else 0)
    # float(Fraction) rounds correctly, as the parse of a decimal must: equal, not close
    assert p.value == float(-exact if sign == "-" else exact)
    assert p.decimals == len(frac)
    assert p.resolution == pytest.approx(float(Fraction(1, 10 ** len(frac))), rel=1e-15)


@given(d=st.integers(0, 359), m=st.integers(0, 59), s=st.integers(0, 59), which=st.integers(0, 2))
def test_sexagesimal_roundtrip(d, m, s, which):
    text = [f"{d}°{m}'{s}''", f"{m}'{s}''", f"{s}''"][which]
    expected = [_arc(d, m, s), _arc(0, m, s), _arc(0, 0, s)][which]
    p = parse_printed(text)
    assert p.value == pytest.approx(float(expected), rel=4e-16, abs=1e-300)
    assert p.resolution == pytest.approx(float(Fraction(1, 3600)), rel=1e-15)


@pytest.mark.parametrize(
    ("text", "fraction"),
    [("5", Fraction(5)), ("0,35", Fraction(35, 100)), ("-2,50", Fraction(-5, 2))],
)
def test_exact_number_makes_a_decimal_exact(text, fraction):
    p = exact_number(parse_printed(text))
    assert p.is_exact and p.resolution is None and p.exact == fraction
    assert exact_number(p) is p  # already exact


def test_only_a_decimal_can_be_declared_exact():
    with pytest.raises(PendcliError, match="only a decimal"):
        exact_number(parse_printed("1°7'33''"))
