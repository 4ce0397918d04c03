"""Lecornu (1894): the sentences whose claim is a judgement with a scale, put in the notation
as an inequality against the model.

Line 248, « l'hypothèse des oscillations infiniment petites ne reste admissible, dans le
voisinage de la longueur nulle, que si l'écart initial est extrêmement faible »: the deviation
at zero length is θ0/|J₀(z₅)| (lines 236-246: θ ∝ J₀(z) at the elongations, the limit 1 at
z = 0, z₅ = 17,96 the fifth zero of J₂ where θ = θ0), so a start admissible at zero length is
θ0 = a·θs·|J₀(z₅)|, a in (0, 1) the share of θs, the largest deviation small oscillations
admit, that it reaches there. « Extrêmement faible » is put on a stated scale, a tenth of θs.

Line 567, « il suffirait, dans ce qui précède, de substituer le mot »descendante» au mot
»ascendante» et réciproquement »: the halves of an oscillation of the pendulum shortening at
speed b, from a vertical passage at length a, are those of the pendulum lengthening at b from
the length the first reaches at its next vertical passage, swapped (the table after (26) at
−b and at +b, first order in b).
"""

from __future__ import annotations

from typing import Any

import mpmath
import sympy as sp

from pendcli.papers.lecornu.references_base import float40, reference, symbols

# the scale the ledger states for « extrêmement faible »: at most this fraction of θs, the
# largest deviation the small-oscillation hypothesis admits (an order of magnitude below it)
EXTREMELY = (1, 10)


def amplification_to_zero_length() -> Any:
    """|θ at zero length / θ0| = 1/|J₀(z₅)|, z₅ the fifth zero of J₂ (mpmath, 40 digits)."""
    with mpmath.workdps(40):
        return 1 / abs(mpmath.besselj(0, mpmath.besseljzero(2, 5)))


def reference_small_start() -> Any:
    """Line 248: every start θ0 admissible at zero length, θ0 = a·θs/(1/|J₀(z₅)|), over
    a in (0, 1) and θs from 1/100 to 1/2 radian, against « extrêmement faible », θxf =
    θs/10 (:data:`EXTREMELY`)."""
    (theta_s,) = symbols("theta_s")
    share = sp.Symbol("a_share", real=True)
    exact = {
        "theta0": share * theta_s / float40(amplification_to_zero_length()),
        "theta_xf": sp.Rational(*EXTREMELY) * theta_s,
    }
    return reference(exact, "θ at zero length = θ0/|J₀(z₅)|, z₅ the fifth zero of J₂")


def reference_shortening_swap() -> Any:
    """Line 567: the ascending (te1 − tv1) and descending (tv2 − te1) halves of the table after
    (26) for l = a − bt (tasc_s, tdesc_s), and for l = a' + bt (tasc_l, tdesc_l), a' = a − b·tv2
    the length at the shortening pendulum's second vertical passage; b scaled by ε, through ε
    (the table's first order)."""
    from pendcli.papers.lecornu.references_slow import reference_table_26

    table = reference_table_26()
    a, b = symbols("a", "b")
    eps = sp.Symbol("eps_", positive=True)

    def at(speed: Any, length: Any) -> dict[str, Any]:
        return {k: v.subs({b: speed, a: length}, simultaneous=True) for k, v in table.exact.items()}

    short = at(-eps * b, a)
    long = at(eps * b, a - eps * b * short["tv2"])
    exact = {
        "tasc_s": short["te1"] - short["tv1"],
        "tdesc_s": short["tv2"] - short["te1"],
        "tasc_l": long["te1"] - long["tv1"],
        "tdesc_l": long["tv2"] - long["te1"],
    }
    what = "the table after (26) at −b from a, and at +b from the length of its next vertical"
    return reference(exact, what)
