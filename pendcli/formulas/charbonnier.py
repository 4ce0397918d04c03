"""Charbonnier 1908: derived formulas checked (closed forms of I_n(π); issue 5 adds the rest)."""

from __future__ import annotations

from pendcli.charbonnier import integral_pi_exact, printed_closed_form
from pendcli.claims import FormulaRow


def formula_checks() -> list[FormulaRow]:
    """The printed closed forms for even and odd n against the recurrence, exactly, n <= 2001."""
    rows = []
    for parity, printed_text, label in (
        (0, "I_n(π) = 2·(2·4…n)/(1·3·5…(n+1))", "even"),
        (1, "I_n(π) = π·(1·3·5…n)/(2·4·6…(n+1))", "odd"),
    ):
        ns = range(parity, 2002, 2)
        bad = [n for n in ns if printed_closed_form(n) != integral_pi_exact(n)]
        rows.append(
            FormulaRow(
                id=f"charbonnier.I_pi.closed_form_{label}",
                paper="charbonnier",
                source="no. 15, closed form for n " + ("pair" if parity == 0 else "impair"),
                published=printed_text,
                recomputed=printed_text if not bad else f"differs at n = {bad[:5]}",
                verdict="holds" if not bad else "fails",
                claimed_order=None,
                observed_order=None,
                note=(
                    f"Equal to the recurrence in exact rational arithmetic for every {label} n "
                    f"from {parity} to {ns[-1]}."
                    if not bad
                    else f"Differs from the recurrence at n = {bad[:5]}."
                ),
            )
        )
    return rows
