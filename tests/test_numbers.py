"""Parsing printed numbers: values and the precision the print implies."""

import math
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from pendcli.core.errors import PendcliError
from pendcli.core.numbers import parse_printed


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


@pytest.mark.parametrize(
    ("text", "degrees", "resolution_arcsec"),
    [
        ("1°7'33''", 1 + 7 / 60 + 33 / 3600, 1.0),
        ("2''", 2 / 3600, 1.0),
        ("2'42''", 2 / 60 + 42 / 3600, 1.0),
        ("30'", 0.5, 60.0),
        ("20°", 20.0, 3600.0),
        ("-1°7'33''", -(1 + 7 / 60 + 33 / 3600), 1.0),
        ("1°7′33″", 1 + 7 / 60 + 33 / 3600, 1.0),
    ],
)
def test_sexagesimal(text, degrees, resolution_arcsec):
    p = parse_printed(text)
    assert p.kind == "sexagesimal"
    assert p.value == pytest.approx(degrees, rel=1e-15)
    assert p.resolution * 3600 == pytest.approx(resolution_arcsec)


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
    assert p.value == pytest.approx(float(fraction) * math.pi**pi_power, rel=1e-15)


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
    expected = float(f"{whole}.{frac}" if frac else whole) * (-1 if sign == "-" else 1)
    assert p.value == expected
    assert p.decimals == len(frac)
    assert p.resolution == pytest.approx(10.0 ** -len(frac))


@given(d=st.integers(0, 359), m=st.integers(0, 59), s=st.integers(0, 59), which=st.integers(0, 2))
def test_sexagesimal_roundtrip(d, m, s, which):
    text = [f"{d}°{m}'{s}''", f"{m}'{s}''", f"{s}''"][which]
    expected = [d + m / 60 + s / 3600, m / 60 + s / 3600, s / 3600][which]
    p = parse_printed(text)
    assert p.value == pytest.approx(expected, abs=1e-12)
    assert p.resolution == pytest.approx(1 / 3600)
