"""Charbonnier's I_n: the printed table and I_n(x), checked against mpmath (independent)."""

import math

import mpmath
import pytest

from pendcli.core.claims import evaluate_paper
from pendcli.core.errors import PendcliError
from pendcli.core.tables import load_paper_table
from pendcli.papers import formula_checks
from pendcli.papers.charbonnier import claims as charbonnier

CLAIMS = load_paper_table("charbonnier").claims


def mp_integral(n: int, x: float) -> mpmath.mpf:
    """∫_0^x sin^(n+1) t dt at 40 digits: mpmath's incomplete beta for x <= π/2 (quadrature
    has an absolute tolerance, useless for tiny values), else quadrature split at kπ/2."""
    with mpmath.workdps(40):
        xm = mpmath.mpf(x)
        if xm <= mpmath.pi / 2:
            return (
                mpmath.betainc(mpmath.mpf(n + 2) / 2, mpmath.mpf(1) / 2, 0, mpmath.sin(xm) ** 2) / 2
            )
        points = [mpmath.mpf(0)]
        k = 1
        while k * mpmath.pi / 2 < xm:
            points.append(k * mpmath.pi / 2)
            k += 1
        points.append(xm)
        return mpmath.quad(lambda t: mpmath.sin(t) ** (n + 1), points)


def mp_beta_pi(n: int) -> mpmath.mpf:
    with mpmath.workdps(40):
        return mpmath.beta(mpmath.mpf(1) / 2, mpmath.mpf(n + 2) / 2)


@pytest.mark.parametrize("claim", CLAIMS, ids=[c.id for c in CLAIMS])
def test_printed_entry_equals_independent_quadrature(claim):
    n = int(claim.id.rsplit(".n", 1)[1])
    reference = mp_integral(n, math.pi)
    assert float(abs(claim.number.value - reference) / reference) < 1e-15  # the print holds
    rows = {r.id: r for r in evaluate_paper("charbonnier")}
    assert rows[claim.id].verdict == "agrees"
    assert float(abs(rows[claim.id].recomputed - reference) / reference) < 3e-16


@pytest.mark.parametrize("n", [-1, 0, 1, 2, 7, 58, 59, 60, 61, 150, 1001, 10**5, 10**9, 10**12])
def test_integral_pi_against_mpmath_beta(n):
    ref = mp_beta_pi(n)
    assert float(abs(charbonnier.integral_pi(n) - ref) / ref) < 4 * 2.3e-16


@pytest.mark.parametrize("n", [-1, 0, 1, 2, 3, 6, 11, 40])
@pytest.mark.parametrize(
    "x", [1e-3, 0.3, 1.0, math.pi / 2, 2.0, 3.0, math.pi - 1e-6, 5.0, 10.0, -2.5]
)
def test_integral_general_x_against_quadrature(n, x):
    ref = mp_integral(n, x) if x >= 0 else (-1) ** n * mp_integral(n, -x)
    got = charbonnier.integral(n, x)
    assert float(abs(got - ref)) <= 1e-13 * float(abs(ref)) + 1e-300


def test_exact_recurrence_matches_printed_closed_forms():
    for n in range(-1, 400):
        assert charbonnier.printed_closed_form(n) == charbonnier.integral_pi_exact(n)


def test_closed_form_formula_rows_hold():
    rows = {r.id: r for r in formula_checks("charbonnier")}
    assert rows["charbonnier.I_pi.closed_form_even"].verdict == "holds"
    assert rows["charbonnier.I_pi.closed_form_odd"].verdict == "holds"


def test_recurrence_in_floating_point_is_exact_at_pi_but_not_at_small_x():
    for n in range(0, 30):
        assert charbonnier.integral_recurrence(n, math.pi) == pytest.approx(
            float(mp_beta_pi(n)), rel=1e-14
        )
    # At x = 0.01 the printed recurrence subtracts nearly equal terms: digits vanish.
    ref = mp_integral(12, 0.01)
    rel = abs(charbonnier.integral_recurrence(12, 0.01) - ref) / ref
    assert rel > 1e-3


@pytest.mark.parametrize(
    ("n", "x"), [(-2, 1.0), (10**13, 1.0), (1.5, 1.0), (3, math.nan), (3, math.inf), (3, 2e6)]
)
def test_bad_inputs_raise_clear_errors(n, x):
    with pytest.raises(PendcliError) as err:
        charbonnier.integral(n, x)
    assert "range" in str(err.value) or "must be" in str(err.value)
