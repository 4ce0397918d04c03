"""Lecornu's prose, lines 1-461: every paragraph accounted for by its reading record
(tables/papers/lecornu.reading.toml), no `holds` row there whose note admits a slip, and each
slip the sentences make, found by the engine, found again by an independent computation
(scipy, mpmath: Bessel zeros, quadrature, an ODE), never by the engine's references."""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import mpmath
import numpy as np
import pytest
from helpers.ledgers import committed_ledger, paragraphs_by_hand
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq
from scipy.special import jn_zeros, jv

TABLES = Path(__file__).resolve().parents[3] / "tables"
LAST_LINE = 461
G = 9.81  # the tables' g (published/lecornu.toml), an assumption: not printed


def _text_lines() -> list[str]:
    return (TABLES / "papers" / "lecornu.txt").read_text(encoding="utf-8").split("\n")


def _record() -> list[dict[str, object]]:
    raw = tomllib.loads((TABLES / "papers" / "lecornu.reading.toml").read_text("utf-8"))
    return list(raw["paragraph"])


def test_every_paragraph_up_to_line_461_is_read_once_in_order() -> None:
    text = (TABLES / "papers" / "lecornu.txt").read_text(encoding="utf-8")
    runs = [r for r in paragraphs_by_hand(text) if r[1] <= LAST_LINE]
    listed = [tuple(e["lines"]) for e in _record() if e["lines"][1] <= LAST_LINE]  # type: ignore[index]
    assert len(runs) == 144
    assert listed == runs


def test_each_named_row_quotes_its_paragraph_and_each_quote_is_named() -> None:
    lines = _text_lines()
    rows = {r.id: r for r in committed_ledger("lecornu").rows}
    named: dict[str, list[str]] = {}
    for entry in _record():
        first, last = entry["lines"]  # type: ignore[misc]
        words = "\n".join(lines[first - 1 : last])
        assert ("rows" in entry) != ("none" in entry), entry
        for row_id in entry.get("rows", []):  # type: ignore[attr-defined]
            assert any(q in words for q in rows[row_id].quotes), (row_id, first)
            named.setdefault(row_id, []).append(words)
    for row_id, paragraphs in named.items():
        for quote in rows[row_id].quotes:
            assert any(quote in words for words in paragraphs), (row_id, quote)


# words with which a note owns up to a slip in its own lines
_ADMITS = re.compile(
    r"the text writes|as the OCR reads|\bslip\b|\bmisprint|\bwrong\b|\bfor e\^", re.IGNORECASE
)


def test_no_holds_row_of_the_opening_admits_a_slip_in_its_note() -> None:
    for row in committed_ledger("lecornu").rows:
        if row.status != "holds" or not row.lines or row.lines[0] > LAST_LINE:
            continue
        if row.carries:  # a step that holds and carries another row's slip, named
            continue
        assert not _ADMITS.search(row.note or ""), (row.id, row.note)


def _first_elongation_by_ode() -> float:
    """(9) for φ from x = 10⁻⁶ (φ = x − x²/2 + …), integrated until θ ∝ φ/x is stationary,
    xφ' − φ = 0 (solve_ivp with an event): ξ of the first elongation."""
    x0 = 1e-6

    def rhs(x: float, y: list[float]) -> list[float]:
        return [y[1], -y[0] / x]

    def stationary(x: float, y: list[float]) -> float:
        return x * y[1] - y[0]

    stationary.terminal = True  # type: ignore[attr-defined]
    stationary.direction = 0  # type: ignore[attr-defined]
    start = [x0 - x0**2 / 2, 1 - x0]
    solution = solve_ivp(
        rhs, (x0, 12), start, events=stationary, rtol=1e-11, atol=1e-13, first_step=1e-7
    )
    events = [x for x in solution.t_events[0] if x > 1]
    return float(events[0])


def test_the_root_of_14_is_two_root_xi_not_xi_squared_over_four() -> None:
    """Line 204: the root of (14) (2J₁(z) = zJ₀(z)) is z = 2√ξ, ξ the elongation's x."""
    z = brentq(lambda s: 2 * jv(1, s) - s * jv(0, s), 4.5, 6.0, xtol=1e-14)
    xi = _first_elongation_by_ode()
    assert 2 * math.sqrt(xi) == pytest.approx(z, rel=1e-7)
    assert round(z, 2) == 5.14  # (15)'s first root, as printed
    assert xi**2 / 4 == pytest.approx(10.87, abs=0.01)  # the text's name for it


def test_the_length_is_compared_with_a_speed_whose_verdict_turns_with_the_unit() -> None:
    """Line 204: at the first elongation of the 0,35 m/s example, l > b is false in metres and
    seconds, true in metres and milliseconds; x = gl/b² > 1 in both."""
    b, xi = 0.35, float(jn_zeros(2, 1)[0] ** 2 / 4)
    length = b**2 * xi / G
    for per_second in (1.0, 1000.0):  # seconds, then milliseconds
        speed, gravity = b / per_second, G / per_second**2
        assert gravity * length / speed**2 == pytest.approx(xi)
    assert length < b and length > b / 1000


def test_the_speed_of_line_214_is_root_g_l_over_xi_with_l_one_metre() -> None:
    """Line 214: √(g/ξ) at z = 17,96 gives 0,35 m/s, but in centimetres it gives 3,5 where
    the speed is 35 cm/s; √(gl/ξ) with l = 100 cm gives 35."""
    xi = float(jn_zeros(2, 5)[4] ** 2 / 4)
    assert math.sqrt(G / xi) == pytest.approx(0.35, abs=0.005)
    g_cm = 100 * G
    assert math.sqrt(g_cm / xi) == pytest.approx(3.49, abs=0.01)
    assert math.sqrt(g_cm * 100 / xi) == pytest.approx(100 * math.sqrt(G / xi))


def _phi(x: float) -> float:
    return float(math.sqrt(x) * jv(1, 2 * math.sqrt(x)))


def test_lhopitals_limit_at_a_root_of_phi_is_minus_one_over_phi_prime() -> None:
    """Lines 278-282: φ∫_(x0)^x dx/φ² at x → β (quadrature) tends to −1/φ'(β), finite; the
    printed −1/φ² grows without bound."""
    beta, x0 = float(jn_zeros(1, 1)[0] ** 2 / 4), 2.0
    slope = float(jv(0, 2 * math.sqrt(beta)))
    values = []
    for gap in (1e-2, 1e-3, 1e-4):
        integral, _ = quad(lambda s: 1 / _phi(s) ** 2, x0, beta - gap, limit=200)
        values.append(_phi(beta - gap) * integral)
    assert values[-1] == pytest.approx(-1 / slope, rel=1e-3)
    assert abs(values[-1] + 1 / slope) < abs(values[0] + 1 / slope)
    assert 1 / _phi(beta - 1e-4) ** 2 > 1e8


def test_the_second_derivative_is_proportional_to_u_over_z_not_to_u() -> None:
    """Line 134: on a path of (9) in z (x = z/c, c = 1), u''/u by finite differences of an ODE
    solution is −1/z: three times smaller in size at z = 3 than at z = 1."""
    solution = solve_ivp(
        lambda z, y: [y[1], -y[0] / z], (0.5, 4), [0.3, 1.0], dense_output=True, rtol=1e-11
    )
    step = 1e-3

    def ratio(z: float) -> float:
        u = solution.sol([z - step, z, z + step])[0]
        return float((u[0] - 2 * u[1] + u[2]) / step**2 / u[1])

    assert ratio(1.0) == pytest.approx(-1.0, rel=1e-4)
    assert ratio(3.0) == pytest.approx(-1 / 3, rel=1e-4)


def test_x_is_g_l_over_b_squared_a_pure_number_not_g_over_l() -> None:
    """Line 344: x = gl/b² is the same in seconds and in minutes (80,08 at 1 m, 0,35 m/s);
    (g/l²)l = g/l changes by 3600: a rate squared."""
    for per_second in (1.0, 60.0):
        gravity, speed = G * per_second**2, 0.35 * per_second
        assert gravity * 1.0 / speed**2 == pytest.approx(80.08, abs=0.01)
    rates = [G * per_second**2 / 1.0**2 * 1.0 for per_second in (1.0, 60.0)]  # (g/l²)l, l = 1 m
    assert rates[1] / rates[0] == pytest.approx(3600)


def test_q_the_limit_of_the_mean_value_p_is_plus_one() -> None:
    """Line 376: M = φ/x is positive on (0, 3,67) and p² = (1/x0 − 1/x)/∫dx/φ² → 1 as x → 0,
    p a value of M: q = 1 > 0."""
    grid = np.linspace(1e-6, 3.6, 2000)
    assert min(_phi(x) / x for x in grid) > 0
    for x, tolerance in ((1e-3, 1e-2), (1e-5, 1e-3)):
        integral, _ = quad(lambda s: 1 / _phi(s) ** 2, 1.0, x, limit=200)
        assert (1 - 1 / x) / integral == pytest.approx(1, abs=tolerance)


def test_expanding_e_to_minus_a_root_x_leaves_a_growing_term() -> None:
    """Line 450: with e^(−2a√x) (line 448) the growing part minus (1/(4x)) stays finite as
    x → 0 (→ −a²/2); with e^(−a√x) it grows as a/(4√x). And the integral w of (18) itself
    (mpmath quadrature) minus (1/(4x) − log(x)/4) converges."""
    a = mpmath.mpf(2)
    with mpmath.workdps(30):
        for x in (mpmath.mpf("1e-8"), mpmath.mpf("1e-10")):
            right = mpmath.exp(-2 * a * mpmath.sqrt(x)) * (1 + 2 * a * mpmath.sqrt(x)) / (4 * x)
            named = mpmath.exp(-a * mpmath.sqrt(x)) * (1 + 2 * a * mpmath.sqrt(x)) / (4 * x)
            assert right - 1 / (4 * x) == pytest.approx(-(a**2) / 2, abs=1e-3)
            assert (named - 1 / (4 * x)) * mpmath.sqrt(x) == pytest.approx(a / 4, rel=1e-3)
    rests = []
    with mpmath.workdps(20):
        for x in (mpmath.mpf("1e-4"), mpmath.mpf("1e-5"), mpmath.mpf("1e-6")):
            w = mpmath.quad(
                lambda lam, x=x: mpmath.exp(-2 * lam * mpmath.sqrt(x)) * mpmath.sqrt(1 + lam**2),
                [0, 1, 10, mpmath.inf],
            )
            rests.append(w - (1 / (4 * x) - mpmath.log(x) / 4))
    assert abs(rests[2] - rests[1]) < abs(rests[1] - rests[0]) < 0.1
