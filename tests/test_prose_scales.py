"""A judgement a sentence makes, put on a stated scale and judged by the engine, checked apart:
Lecornu's line 248, « que si l'écart initial est extrêmement faible »
(``lecornu.result.small_start_needed``, an inequality against ``reference_small_start``)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from ledgers import committed_ledger, committed_row
from scipy.integrate import solve_ivp

from pendcli.core.ledger import reference_table, row_printed_status
from pendcli.papers.lecornu.references_prose import amplification_to_zero_length
from pendcli.papers.registry import paper

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
