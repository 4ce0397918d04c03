"""The bound of a conditional verdict is the change point rounded to the 4 decimals printed:
found by bisection in pendcli.verify.claims, checked here against mpmath's root."""

from __future__ import annotations

import mpmath
from helpers.evaluated import committed_claims

B, LENGTH, PRINTED_HALF = "0.35", "1", "1.655"  # the claim 1,66 turns where the time is 1,655


def test_the_bound_is_the_change_point_rounded_to_four_decimals() -> None:
    """Lecornu's third elongation time (1 − (b²/4g)·j²)/b (j the third zero of J₂) reaches
    1,655 at g*: the printed bound is g* rounded to 4 decimals, exactly (g* is not within
    1e-6 of a rounding tie)."""
    with mpmath.workdps(30):
        j, b = mpmath.besseljzero(2, 3), mpmath.mpf(B)

        def time_3(g: mpmath.mpf) -> mpmath.mpf:
            return (mpmath.mpf(LENGTH) - b**2 / (4 * g) * j**2) / b

        g = float(mpmath.findroot(lambda g: time_3(g) - mpmath.mpf(PRINTED_HALF), 9.82))
    assert 0.5 - abs(g * 1e4 - round(g * 1e4)) > 1e-2, g  # far from a tie at 4 decimals
    row = {r.id: r for r in committed_claims("lecornu")}["lecornu.example.time.3"]
    assert row.condition is not None
    printed = row.condition.split("g <= ", 1)[1].split(",", 1)[0]
    assert printed == f"{round(g, 4):g}", (printed, g)
