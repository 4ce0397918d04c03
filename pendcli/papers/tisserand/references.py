"""Tisserand (1881): the references the ledger's printed forms are judged against
(``reference = "<name>"`` in tables/equations/tisserand.toml; verify/printed_check and
verify/printed_numeric), by the sections of the paper, and their table :data:`REFERENCES`.

    p. 448-450, lines 32-88     the first integrals, (1)-(7): :mod:`.references_differentials`
    p. 450-452, lines 92-154    the series (8)-(15) in ψ and in k't: :mod:`.references_series`
    p. 448-452, lines 42-156    the ellipse (3), (9), (10), (16), (17): here
    p. 453-454, lines 158-206   the summary (I)-(VI) and its approximations: here
    p. 454, lines 192-202       the numerical application: :mod:`.references_numeric`
    lines 30, 44, 128, 152,     the sentences' own claims (the reading record):
    178-180                     :mod:`.references_prose`

Each builder maps ledger symbols to exact expressions (or, for the numbers, computes them)
from what the printed formula rests on, never from a copy of the formula the row prints.
"""

from __future__ import annotations

import sys

import sympy as sp

from pendcli.papers.tisserand import references_differentials as differentials
from pendcli.papers.tisserand import references_numeric as numeric
from pendcli.papers.tisserand import references_prose as prose
from pendcli.papers.tisserand import references_series as series
from pendcli.papers.tisserand.references_differentials import ledger_symbols, substitution_3
from pendcli.papers.tisserand.references_series import (
    in_kpt_reference,
    motion_reference,
    motion_series,
)
from pendcli.verify.ledger_references import builders
from pendcli.verify.printed_check import Reference

# --- the ellipse: (3), (9), (10), (16), (17), p. 452 --------------------------------------


# (3) line 42 and what rests on it alone: the integrals in ψ of lines 82-88, tan²ψ of line
# 134, ψ = 0 at t = 0 (line 44); (10), line 100, « d'où »: the tangent of (9)'s φ1; tan²φ1 in
# u (lines 136-138) and in ρ (line 146), (17) line 150, the eccentric anomaly of line 156:
# (3), (9) and (16) together; line 152, the ellipse (17)'s centre, major axis Ox' and axes
# 2ρ0, 2ρ1 (ρ0 = lu0, ρ1 = lu1, line 142).
def reference_ellipse() -> Reference:
    """(3), (9) and (16): u as in (3), φ1 = arctan((u1/u0) tan ψ), ρ = lu, ρ0 = lu0, ρ1 = lu1."""
    u0, u1, psi, length = ledger_symbols("u0", "u1", "psi", "l")
    u = substitution_3()
    exact = {
        "u": u,
        "phi1": sp.atan(u1 / u0 * sp.tan(psi)),
        "rho": length * u,
        "rho0": length * u0,
        "rho1": length * u1,
    }
    return Reference(exact, what="(3), (9), (16)")


# --- the summary (I)-(VI) and its approximations, p. 453-454 -----------------------------


# (I), line 160: k' and k'' with k = √(g/l), to the orders line 158 announces.
def reference_summary() -> Reference:
    """(I): k' through the sixth order, k'' through the fourth, as line 158 announces."""
    return motion_reference(7, "(4), (5), (3): k' to order 6, k'' to order 4")


# Line 180, « k'' diffère peu de l'unité »: the axis's angular velocity (Resal's solution).
def reference_resal() -> Reference:
    """Line 180: k'' and the mean angular velocity of the major axis, dφ'/dt = k'·P (P the
    secular coefficient of φ' in ψ), k'' through the first order, the rate through the second."""
    base = motion_reference(3, "(4), (5), (3): k'' to order 1, dφ'/dt to order 2")
    exact = {**base.exact, "dphip_dt": base.exact["kp"] * motion_series(3)["P"]}
    return Reference(exact, what=base.what)


# Lines 182-188, « Deuxième approximation », and line 206, the periodic term cited again.
def reference_second_approximation() -> Reference:
    """« Deuxième approximation »: ψ and φ' through the third order."""
    return in_kpt_reference(4, "(4), (5), (3) in k't, to order 3")


# --- the table the ledger's rows cite, in the order of the paper -------------------------

# Every builder the ledger cites, by its name there (verify/ledger_references.builders).
REFERENCES = builders(sys.modules[__name__], differentials, series, prose, numeric)
