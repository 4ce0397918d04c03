"""Tisserand (1881): the references of the claims his sentences make (the reading record,
tables/papers/tisserand.reading.toml), where no reference of the formulas serves.

    line 30, 180   Resal's ellipse whose major axis turns uniformly, in the same sense as
                   the pendulum: the exact motion through the fourth order in ψ
    line 44        « Pour t = 0, on aura ψ = 0 »: (3) at ψ = 0
    line 128       (16), ρ = lu: the radius vector of the projection, from the bob's position
    line 178       « u0u1 est un terme du second ordre »

Each builder maps ledger symbols to exact expressions from the model or the definitions the
sentence rests on, never from the words it checks.
"""

from __future__ import annotations

import sympy as sp

from pendcli.papers.tisserand.references_differentials import ledger_symbols, scale, substitution_3
from pendcli.papers.tisserand.references_series import motion_reference, motion_series
from pendcli.verify.printed_check import Reference


# Lines 30 and 180: the projection on the ellipse (17) and φ' against a uniform rotation.
def reference_uniform_rotation() -> Reference:
    """The exact motion (4), (5), (3) in ψ through the fourth order in the angles, with the
    polar coordinates of the projection (ρ = l sin θ = lu, φ1 of (9)) and the axis's mean
    angular velocity dφ'/dt = k'P (P the secular coefficient of φ' in ψ): φ' less that rate
    times t is of the fourth order (its periodic part), so the rotation is uniform through the
    third; the axes ρ0 = lu0, ρ1 = lu1. The domain: the apsides' order u0 > u1 > 0, ψ in its
    first half-turn, small amplitudes (the scale s), g and l over the default range."""
    base = motion_reference(5, "(4), (5), (3) to order 4, the projection in polar coordinates")
    s, length = scale(), ledger_symbols("l")[0]
    u0, u1 = ledger_symbols("u0", "u1")
    u = substitution_3()
    exact = {
        **base.exact,
        "rho": length * s * u,
        "rho0": length * s * u0,
        "rho1": length * s * u1,
        "dphip_dt": base.exact["kp"] * motion_series(5)["P"],
    }
    return Reference(exact, what=base.what)


# Line 128, (16): the radius vector of the projection, from the bob's position.
def reference_projection_radius() -> Reference:
    """The bob at l(sin θ cos φ, sin θ sin φ, −cos θ) from the point of suspension, its
    projection on the horizontal plane at the distance √(x² + y²) from O, the foot of the
    vertical; u = sin θ (line 42)."""
    length, theta, phi = ledger_symbols("l", "theta", "phi")
    x = length * sp.sin(theta) * sp.cos(phi)
    y = length * sp.sin(theta) * sp.sin(phi)
    return Reference({"rho": sp.sqrt(x**2 + y**2), "u": sp.sin(theta)}, what="the bob's position")


# Line 178, « u0u1 est un terme du second ordre »: the angles' order.
def reference_angles_second_order() -> Reference:
    """u0, u1 of the first order in the angles (each scaled by s): a product of two is of the
    second, no term below s²."""
    s = scale()
    u0, u1 = ledger_symbols("u0", "u1")
    return Reference({"u0": s * u0, "u1": s * u1}, what="u0, u1 of order 1")
