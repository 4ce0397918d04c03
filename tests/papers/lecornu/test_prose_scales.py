"""A judgement a sentence makes, put on a stated scale and judged by the engine, checked apart:
Lecornu's line 248, « que si l'écart initial est extrêmement faible »
(``lecornu.result.small_start_needed``, an inequality against ``reference_small_start``)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from helpers.ledgers import committed_ledger, committed_row
from scipy.integrate import solve_ivp

from pendcli.papers.lecornu.references_prose import amplification_to_zero_length
from pendcli.papers.registry import paper
from pendcli.verify.ledger_references import reference_table, row_printed_status

ROW = "lecornu.result.small_start_needed"


def _amplification_by_integration() -> float:
    """θ ∝ u/x along x u'' + u = 0 ((9), x = gl/b²; θ = u/l), from the regular solution at
    x → 0 (u/x → 1, the deviation at zero length) to its fifth extremum (an elongation,
    x u' = u): |θ(0)/θ(fifth elongation)|, by scipy's ODE solver alone."""
    x0 = 1e-8
    start = [x0 - x0**2 / 2, 1 - x0]  # u = x − x²/2 + …, the solution u/x -> 1

    def rhs(x: float, y: np.ndarray) -> list[float]:
        return [y[1], -y[0] / x]

    def elongation(x: float, y: np.ndarray) -> float:
        return float(x * y[1] - y[0])

    solved = solve_ivp(rhs, (x0, 90.0), start, events=elongation, rtol=1e-11, atol=1e-13)
    xs, ys = solved.t_events[0], solved.y_events[0]
    fifth = ys[4][0] / xs[4]
    return 1 / abs(fifth)


def test_the_amplification_to_zero_length_agrees_with_the_integration() -> None:
    by_ode = _amplification_by_integration()
    assert abs(by_ode - 47.84) < 0.01
    assert abs(float(amplification_to_zero_length()) - by_ode) < 1e-6 * by_ode


def test_the_engine_judges_the_stated_scale_as_the_integration_does() -> None:
    """The row holds (« extrêmement faible », theta_xf: at most θs/10) because the
    amplification exceeds 10; the same form with a scale beyond the amplification (θs/50)
    fails, one below it (θs/40) holds: the engine's verdict turns where the integration's
    value lies."""
    row = committed_row(ROW)
    symbols = committed_ledger("lecornu").symbols_for(row)
    table = reference_table(paper("lecornu"))
    assert row.status == "holds" and row.kind == "inequality"
    assert row_printed_status(row, symbols, table)[0] == "holds"
    by_ode = _amplification_by_integration()
    for divisor in (10, 40, 50, 100):
        computed, _ = row_printed_status(
            replace(row, printed=f"theta0 <= theta_s/{divisor}"), symbols, table
        )
        assert (computed == "holds") == (divisor <= by_ode), divisor


# --- line 567: a shortening pendulum swaps the ascending and descending halves ------------------

SWAP = "lecornu.result.shortening_swaps_halves"


def _halves(a: float, b: float, g: float) -> tuple[float, float, float]:
    """From a vertical passage at t = 0 (θ = 0, θ' = 0,01) with l = a + bt: the ascending
    half (to the elongation, θ' = 0), the descending half (to the next vertical) and the
    length then, by scipy's ODE solver on l θ'' + 2bθ' + gθ = 0."""

    def rhs(t: float, y: np.ndarray) -> list[float]:
        return [y[1], -(2 * b * y[1] + g * y[0]) / (a + b * t)]

    def elongation(t: float, y: np.ndarray) -> float:
        return float(y[1])

    def vertical(t: float, y: np.ndarray) -> float:
        return float(y[0])

    elongation.direction = -1  # type: ignore[attr-defined]
    vertical.direction = -1  # type: ignore[attr-defined]
    vertical.terminal = True  # type: ignore[attr-defined]  # after the elongation: all it reads
    solved = solve_ivp(
        rhs, (0.0, 3.0), [0.0, 0.01], events=(elongation, vertical), rtol=1e-12, atol=1e-15
    )
    te1, tv2 = solved.t_events[0][0], solved.t_events[1][0]
    return te1, tv2 - te1, a + b * tv2


def test_the_shortening_pendulum_is_the_lengthening_one_run_backwards() -> None:
    """Integrated both ways: the shortening pendulum's ascending half is the descending half
    of the lengthening one started at the length the first ends at, and conversely (exactly:
    the motion is reversible); the unswapped halves differ by about π²b/(4g). The engine's
    first-order verdict agrees: the swapped form holds, the unswapped one does not."""
    a, b, g = 1.0, 0.05, 9.81
    asc_s, desc_s, end = _halves(a, -b, g)
    asc_l, desc_l, _ = _halves(end, b, g)
    assert abs(asc_s - desc_l) < 1e-8 and abs(desc_s - asc_l) < 1e-8
    assert abs(asc_s - asc_l) > 0.5 * np.pi**2 * b / (4 * g)
    row = committed_row(SWAP)
    symbols = committed_ledger("lecornu").symbols_for(row)
    table = reference_table(paper("lecornu"))
    assert row.status == "holds" and row_printed_status(row, symbols, table)[0] == "holds"
    unswapped = replace(row, printed="tasc_s = tasc_l; tdesc_s = tdesc_l")
    assert row_printed_status(unswapped, symbols, table)[0] is None
