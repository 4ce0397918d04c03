"""Charbonnier's printed claims recomputed: the table of I_n(π), n = -1..5 (no. 15).

:func:`recompute` collects the builders; each builder produces the claims of one printed
passage (here there is one: the table, with I_(-1)(π) = π and I_0(π) = 2 from the text).
"""

from __future__ import annotations

from pendcli.papers.charbonnier.model import exact_text, integral_pi, integral_pi_exact
from pendcli.verify.claims import Recomputed

__all__ = ["PRINTED_N", "recompute", "table_claims"]

PRINTED_N = range(-1, 6)  # the table of no. 15 (n = 0..5) and I_(-1)(π) = π in the text


def recompute() -> dict[str, Recomputed]:
    """Every printed claim of the paper, recomputed (id -> Recomputed)."""
    return table_claims()


def table_claims() -> dict[str, Recomputed]:
    """Every printed I_n(π), n = -1..5 (no. 15): B(½, (n+2)/2), with the exact rational."""
    out: dict[str, Recomputed] = {}
    for n in PRINTED_N:
        q, p = integral_pi_exact(n)
        out[f"charbonnier.I_pi.n{n}"] = Recomputed(
            value=integral_pi(n),
            method="recurrence in exact rationals; B(1/2,(n+2)/2) in floating point",
            note=f"Exact value {exact_text(q, p)}.",
        )
    return out
