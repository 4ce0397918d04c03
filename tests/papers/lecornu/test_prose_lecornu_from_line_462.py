"""Lecornu's prose from line 462 to the end: the reading record accounts for every paragraph,
and the slips its claim rows record are verified apart from the ledger's engine, by
integrating the slowly lengthening pendulum (solve_ivp) and by mpmath series and quadrature."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from pendcli.data.reading import prose_paragraphs

TABLES = Path(__file__).resolve().parents[3] / "tables"
FIRST = 462  # the first line of the part of the text read here


def _raw(path: str) -> dict[str, object]:
    return tomllib.loads((TABLES / path).read_text(encoding="utf-8"))


def _rows() -> dict[str, dict[str, object]]:
    return {str(r["id"]): r for r in _raw("equations/lecornu.toml")["equation"]}  # type: ignore[union-attr]


def _text_lines() -> list[str]:
    return (TABLES / "papers" / "lecornu.txt").read_text(encoding="utf-8").split("\n")


def _quotes(row: dict[str, object]) -> list[str]:
    quote = row.get("quote")
    return [quote] if isinstance(quote, str) else list(quote or [])  # type: ignore[arg-type]


# --- the record ---------------------------------------------------------------------------------


def test_every_paragraph_from_line_462_is_read_once_in_order() -> None:
    text = "\n".join(_text_lines())
    spans = [list(s) for s in prose_paragraphs(text) if s[0] >= FIRST]
    listed = [e["lines"] for e in _raw("papers/lecornu.reading.toml")["paragraph"]]  # type: ignore[index]
    assert [s for s in listed if s[0] >= FIRST] == spans
    assert len(spans) == 177


def test_each_claim_row_quotes_its_paragraph_and_each_reason_is_one_line() -> None:
    lines, rows = _text_lines(), _rows()
    for entry in _raw("papers/lecornu.reading.toml")["paragraph"]:  # type: ignore[union-attr]
        first, last = entry["lines"]
        if first < FIRST:
            continue
        words = "\n".join(lines[first - 1 : last])
        if "none" in entry:
            assert entry["none"].strip() and "\n" not in entry["none"], first
            continue
        for row_id in entry["rows"]:
            assert any(q in words for q in _quotes(rows[row_id])), (row_id, first)


def test_no_checked_row_of_these_lines_admits_a_slip_in_its_note() -> None:
    """A row that holds names a slip only as another row's, by its id: the slips are rows of
    their own."""
    for row in _rows().values():
        note = str(row.get("note", ""))
        if row["lines"][0] >= FIRST and row["status"] == "holds" and "slip" in note:  # type: ignore[index]
            assert "lecornu." in note, row["id"]


# --- the slowly lengthening pendulum, integrated ------------------------------------------------


def _events(a: float, b: float, g: float, amplitude: float) -> tuple[list[float], list[float]]:
    """l θ'' + 2bθ' + gθ = 0 (l = a + bt), from a vertical passage at t = 0: the instants of
    the next elongations (θ' = 0) with |θ| there, and of the vertical passages (θ = 0)."""

    def rhs(t: float, y: np.ndarray) -> list[float]:
        return [y[1], -(2 * b * y[1] + g * y[0]) / (a + b * t)]

    def vertical(t: float, y: np.ndarray) -> float:
        return float(y[0])

    def elongation(t: float, y: np.ndarray) -> float:
        return float(y[1])

    span = 2.2 * math.pi * math.sqrt(a / g)
    speed = amplitude * math.sqrt(g / a)
    sol = solve_ivp(rhs, (0, span), [0.0, speed], events=(vertical, elongation),
                    rtol=1e-12, atol=1e-14)  # fmt: skip
    passages = [float(t) for t in sol.t_events[0] if t > 1e-9]
    found = zip(sol.t_events[1], sol.y_events[1], strict=True)
    tops = [(float(t), abs(float(y[0]))) for t, y in found]
    return [t for t, _ in tops] + [v for _, v in tops], passages


A, B, G = 1.0, 0.01, 9.81  # p = b/√(ga) = 0.0032


def test_against_the_largest_length_the_descending_half_is_lengthened_not_shortened() -> None:
    """Line 565: the descending half (first elongation -> next vertical) against the ordinary
    pendulum of the largest length l' = a + b·T (T the second vertical passage)."""
    events, passages = _events(A, B, G, 0.01)
    first_top, second_vertical = events[0], passages[0]
    largest = A + B * second_vertical
    change = (second_vertical - first_top) - math.pi / 2 * math.sqrt(largest / G)
    assert change > 0  # a lengthening: « un léger raccourcissement » has the wrong sign
    assert change == pytest.approx((12 - math.pi**2) / 16 * B / G, rel=0.05)


def test_the_reference_of_the_largest_length_agrees_with_the_integration() -> None:
    from pendcli.data.printed import ledger_symbols
    from pendcli.papers.lecornu.references_slow import reference_largest_length

    ref = reference_largest_length()
    a, b, g = ledger_symbols("a", "b", "g")
    ddesc = float(ref.exact["ddesc"].subs({a: A, b: B, g: G}).evalf(30))
    events, passages = _events(A, B, G, 0.01)
    largest = A + B * passages[0]
    ode = math.pi / 2 * math.sqrt(largest / G) - (passages[0] - events[0])
    assert ddesc == pytest.approx(ode, rel=0.05)
    assert ddesc < 0


def test_successive_elongations_differ_by_a_relative_not_an_absolute_amount() -> None:
    """Line 579: (θ − θ')/θ' is (3/4)πb/√(gl) whatever the amplitude; θ − θ' doubles with θ,
    and (3/4)π√(b/(gl)) (as printed) is neither."""
    relative = []
    for amplitude in (0.01, 0.02):
        events, _ = _events(A, B, G, amplitude)
        t1, (th1, th2) = events[0], events[len(events) // 2 : len(events) // 2 + 2]
        relative.append(((th1 - th2) / th2, th1 - th2, A + B * t1))
    (rel1, abs1, l1), (rel2, abs2, _) = relative
    assert rel1 == pytest.approx(rel2, rel=1e-6)
    assert abs2 == pytest.approx(2 * abs1, rel=1e-6)
    assert rel1 == pytest.approx(0.75 * math.pi * B / math.sqrt(G * l1), rel=0.03)
    assert abs(0.75 * math.pi * math.sqrt(B / (G * l1)) - rel1) > 5 * rel1


# --- the conical pendulum's small angles (line 1010) ---------------------------------------------


def test_the_conical_replacement_is_no_cruder_than_the_plane_one() -> None:
    """cos θ/sin³θ = θ⁻³(1 − θ⁴/15 + …): with sin θ -> θ, cos θ -> 1 the centrifugal term errs
    at relative order θ⁴, the gravity term at θ²/6 as in the plane case."""
    with mpmath.workdps(40):
        theta = mpmath.mpf("1e-3")
        centrifugal = theta**3 * mpmath.cos(theta) / mpmath.sin(theta) ** 3 - 1
        gravity = mpmath.sin(theta) / theta - 1
        assert centrifugal / theta**4 == pytest.approx(-1 / 15, rel=1e-5)
        assert gravity / theta**2 == pytest.approx(-1 / 6, rel=1e-5)


# --- line 930, the root expanded ------------------------------------------------------------------


def test_the_root_of_line_930_is_expanded_outside_the_root() -> None:
    a, g, b = mpmath.mpf(1), mpmath.mpf("9.81"), mpmath.mpf("1e-4")
    with mpmath.workdps(30):
        q = mpmath.pi * b / mpmath.sqrt(a * g)
        root = mpmath.sqrt(a / g * (1 + q / 2))
        read = mpmath.sqrt(a / g) * (1 + q / 4)
        printed = mpmath.sqrt(a / g * (1 + q / 4))
        assert abs(root - read) < q**2 * mpmath.sqrt(a / g)
        assert abs(root - printed) == pytest.approx(q / 8 * mpmath.sqrt(a / g), rel=1e-3)


# --- the claims that hold ---------------------------------------------------------------------


def test_with_sin_alpha_zero_the_integral_of_18_is_a_multiple_of_phi() -> None:
    """Line 462: x∫cos(2√x cos ω) sin²ω dω = (π/4)√x J₁(2√x), the φ of (10)."""
    with mpmath.workdps(30):
        for x in (mpmath.mpf("0.3"), mpmath.mpf(7), mpmath.mpf(40)):
            integral = x * mpmath.quad(
                lambda w, x=x: mpmath.cos(2 * mpmath.sqrt(x) * mpmath.cos(w)) * mpmath.sin(w) ** 2,
                [0, mpmath.pi / 2],
            )
            phi = mpmath.sqrt(x) * mpmath.besselj(1, 2 * mpmath.sqrt(x))
            assert integral == pytest.approx(mpmath.pi / 4 * phi, rel=1e-20)


# --- line 599: the phase that vanishes is ψ, not φ ------------------------------------------------


def test_vertical_at_the_start_makes_psi_not_phi_a_multiple_of_pi() -> None:
    """(22) in t, θ = R l^(-3/4) sin((2/b)√(gl) − φ), vertical at t = 0 (l = a): φ = 2/p − λπ,
    and (25)'s ψ = φ − 2/p; then θ(0) = 0 while sin φ is not 0."""
    with mpmath.workdps(30):
        a, g, b = mpmath.mpf(1), mpmath.mpf("9.81"), mpmath.mpf("0.05")
        p = b / mpmath.sqrt(g * a)
        for lam in (0, 1, 2):
            phi = 2 / p - lam * mpmath.pi
            assert abs(mpmath.sin(2 / b * mpmath.sqrt(g * a) - phi)) < mpmath.mpf("1e-25")
            assert abs(mpmath.sin(phi - 2 / p)) < mpmath.mpf("1e-25")
            assert abs(mpmath.sin(phi)) > mpmath.mpf("0.1")


# --- line 690: s = g/b is a rate; (31) is good when s·z0 is small -------------------------------


def _error_of_31(s: float, z0: float, alpha: float = 0.3) -> float:
    """(30), z θ'' + 2θ' + s sin θ = 0, from z0 (θ = α, θ' = 0) down to z0/2, against (31)."""

    def rhs(z: float, y: np.ndarray) -> list[float]:
        return [y[1], -(2 * y[1] + s * math.sin(y[0])) / z]

    z = z0 / 2
    sol = solve_ivp(rhs, (z0, z), [alpha, 0.0], rtol=1e-12, atol=1e-14)
    bracket = (z - z0) * (z**2 - 5 * z * z0 - 2 * z0**2) / (2 * z) + 3 * z0**2 * math.log(z / z0)
    printed = alpha - s * math.sin(alpha) / (2 * z) * (z - z0) ** 2
    printed += s**2 * math.sin(2 * alpha) / 12 * bracket
    return abs(printed - float(sol.y[0, -1]))


def test_the_series_in_s_needs_s_times_z0_small_not_s() -> None:
    """The same small s = 0.01 per second: (31) is good for z0 = 1 s (s·z0 = 0.01) and useless
    for z0 = 3000 s (s·z0 = 30); its error grows as (s·z0)³, the first power it neglects: the
    number that must be small is s·z0 = ga/b²."""
    assert _error_of_31(0.01, 1.0) < 1e-9
    assert _error_of_31(0.01, 3000.0) > 0.1
    assert _error_of_31(0.01, 100.0) / _error_of_31(0.01, 10.0) == pytest.approx(1000, rel=0.05)
