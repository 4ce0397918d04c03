"""Verdict boundaries: agrees, truncated, last-digit, discrepant (rules in
pendcli.verify.verdict)."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from pendcli.data.numbers import parse_printed
from pendcli.verify.verdict import Verdict, judge


@pytest.mark.parametrize(
    ("printed", "recomputed", "verdict"),
    [
        ("5,14", 5.1356, Verdict.AGREES),  # J2 zero 5.13562...: rounds to 5,14
        ("5,14", 5.1449, Verdict.AGREES),
        ("8,41", 8.4172, Verdict.TRUNCATED),  # chops to 8,41, rounds to 8,42
        ("8,41", 8.4250, Verdict.LAST_DIGIT),
        ("8,41", 8.3951, Verdict.LAST_DIGIT),
        ("8,41", 8.3949, Verdict.DISCREPANT),
        ("8,41", 8.4300, Verdict.DISCREPANT),
        ("-0,130", -0.1300, Verdict.AGREES),
        ("-0,130", -0.1309, Verdict.TRUNCATED),
        ("-0,130", 0.1300, Verdict.DISCREPANT),
        ("0,94", 0.9449999, Verdict.AGREES),
        ("1°7'33''", 1 + 7 / 60 + 33.4 / 3600, Verdict.AGREES),
        ("1°7'33''", 1 + 7 / 60 + 33.7 / 3600, Verdict.TRUNCATED),
        ("1°7'33''", 1 + 7 / 60 + 31.9 / 3600, Verdict.LAST_DIGIT),
        ("1°7'33''", 1 + 7 / 60 + 31.4 / 3600, Verdict.DISCREPANT),
        ("2·2/(1·3)", 4 / 3, Verdict.AGREES),
        ("2·2/(1·3)", 4 / 3 * (1 + 1e-12), Verdict.DISCREPANT),
        ("π·1/2", math.pi / 2, Verdict.AGREES),
    ],
)
def test_examples(printed, recomputed, verdict):
    assert judge(parse_printed(printed), recomputed).verdict is verdict


@pytest.mark.parametrize(
    ("recomputed", "verdict"),
    [
        (5.135, Verdict.AGREES),  # exactly half a unit below, as written in decimal
        (5.134999999999, Verdict.AGREES),  # 2e-13 relative: within the 1e-12 slack
        (5.13499999999, Verdict.LAST_DIGIT),  # 2e-12 relative: beyond it
        (5.145, Verdict.AGREES),  # half a unit above
        (5.14500000001, Verdict.TRUNCATED),  # above half a unit: chops to 5,14
        (5.14999999999, Verdict.TRUNCATED),
        (5.155, Verdict.LAST_DIGIT),  # 1.5 units: the last-digit boundary, inclusive
        (5.15500000001, Verdict.DISCREPANT),
        (5.12500000001, Verdict.LAST_DIGIT),
        (5.12499999999, Verdict.DISCREPANT),
    ],
)
def test_boundaries_of_5_14(recomputed, verdict):
    assert judge(parse_printed("5,14"), recomputed).verdict is verdict


def test_upper_bound():
    fifth = parse_printed("1/5")
    assert judge(fifth, 0.19, "upper-bound").verdict is Verdict.AGREES
    assert judge(fifth, 0.21, "upper-bound").verdict is Verdict.DISCREPANT
    bound = parse_printed("0,20")
    assert judge(bound, 0.204, "upper-bound").verdict is Verdict.AGREES  # rounds to 0,20
    assert judge(bound, 0.206, "upper-bound").verdict is Verdict.DISCREPANT


def test_non_finite_is_discrepant():
    assert judge(parse_printed("5,14"), math.nan).verdict is Verdict.DISCREPANT
    assert judge(parse_printed("5,14"), math.inf).verdict is Verdict.DISCREPANT


def test_differences_and_digits():
    c = judge(parse_printed("2,00"), 2.002)
    assert c.abs_diff == pytest.approx(0.002)
    assert c.rel_diff == pytest.approx(0.001)
    assert c.digits == pytest.approx(3.0)
    assert judge(parse_printed("2"), 2.0).digits == 17.0


printed_decimals = st.tuples(
    st.integers(min_value=-(10**5), max_value=10**5), st.integers(min_value=0, max_value=4)
).map(lambda t: (f"{t[0] / 10 ** t[1]:.{t[1]}f}", t[1]))


def _judge_offset(printed_text, decimals, offset_units):
    p = parse_printed(printed_text)
    u = 10.0**-decimals
    return p, judge(p, p.value + offset_units * u)


@given(printed_decimals, st.floats(min_value=-0.499, max_value=0.499))
def test_within_half_unit_agrees(pd, frac):
    _, c = _judge_offset(*pd, frac)
    assert c.verdict is Verdict.AGREES


@given(printed_decimals, st.floats(min_value=0.501, max_value=0.999))
def test_chopped_value_is_truncated(pd, frac):
    p, _ = _judge_offset(*pd, 0)
    u = 10.0 ** -pd[1]
    # move away from zero by frac units: truncates to p, does not round to it
    r = p.value + math.copysign(frac * u, p.value) if p.value != 0 else frac * u
    assert judge(p, r).verdict is Verdict.TRUNCATED


@given(printed_decimals, st.floats(min_value=0.501, max_value=1.499), st.booleans())
def test_one_unit_off_is_last_digit_or_truncated(pd, frac, up):
    p, c = _judge_offset(pd[0], pd[1], frac if up else -frac)
    chopped_toward = (p.value >= 0) == up and frac < 1
    expected = {Verdict.TRUNCATED} if chopped_toward else {Verdict.LAST_DIGIT}
    if p.value == 0:
        expected = {Verdict.TRUNCATED, Verdict.LAST_DIGIT}
    assert c.verdict in expected


@given(printed_decimals, st.floats(min_value=1.51, max_value=1e6), st.booleans())
def test_far_is_discrepant(pd, units, up):
    _, c = _judge_offset(pd[0], pd[1], units if up else -units)
    assert c.verdict is Verdict.DISCREPANT
