"""Tisserand (1881), lines 192-202: the numbers of the numerical application, computed for the
numeric mode of the printed-form engine (:mod:`pendcli.verify.printed_numeric`).

The coefficients of ψ (II) and φ' (V) are Tisserand's own series (``model.series_conical``,
every printed term) at the amplitudes the row prints, so that the printed « 30', 15' » and
their reading « 30°, 15° » are each judged by what they give; the shift of line 202 is
l sin θ0 |c| (the arc of the circle through the ends of the major axis turned through the
periodic angle c), with his printed c = 2'42'' and the example's θ0 = 30° (the table's
reading). Every printed number is read from ``tables/published/tisserand.toml``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import mpmath

from pendcli.papers.tisserand.model import series_conical
from pendcli.verify.printed_numeric import Numbers

COEFFICIENTS = (
    "tisserand.example.psi_sin2",
    "tisserand.example.psi_sin4",
    "tisserand.example.phi_sin2",
)


def _claim(claim_id: str) -> Any:
    from pendcli.data.tables import load_paper_table

    return load_paper_table("tisserand").claim(claim_id).number


def _coefficients(given: Mapping[str, float]) -> tuple[float, ...]:
    """The printed magnitudes of ψ's sin 2k't, sin 4k't and φ''s sin 2k't coefficients, in
    degrees, by (II) and (V) at θ0, θ1 given in degrees (30' is 0,5°)."""
    theta0, theta1 = (math.radians(given[name]) for name in ("theta0", "theta1"))
    motion = series_conical(theta0, theta1, order=6)
    # ψ = k't − b1 sin 2k't + b2 sin 4k't as printed: the minus sign is the formula's
    return tuple(
        math.degrees(v) for v in (-motion.psi_coeffs[0], motion.psi_coeffs[1], motion.phi_coeffs[0])
    )


# Lines 192-200: ψ and φ' for « θ0 = 30', θ1 = 15' », by (II) and (V).
def numbers_numerical_application() -> Any:
    """Lines 192-200: the three coefficients for the printed amplitudes (inputs, not judged)."""
    published = (None, None, *((c, _claim(c)) for c in COEFFICIENTS))
    return Numbers(
        _coefficients,
        what="Tisserand's (II), (V) at the printed θ0, θ1",
        published=published,
        inputs=("theta0", "theta1"),
    )


def _shift(given: Mapping[str, float]) -> tuple[float]:
    """l sin θ0 |c| in millimetres, l as printed (metres), c = 2'42'' (line 200)."""
    from pendcli.data.tables import load_paper_table

    with mpmath.workdps(30):
        theta0 = mpmath.radians(load_paper_table("tisserand").constant("theta0"))
        c = mpmath.radians(mpmath.mpf(_claim("tisserand.example.phi_sin2").value))
        shift = 1000 * mpmath.mpf(given["l"]) * mpmath.sin(theta0) * abs(c)
    return (float(shift),)


# Line 202: the bob's displacement by φ''s periodic term, for l = 0,5 m.
def numbers_displacement() -> Any:
    """Line 202: « un petit déplacement égal au plus à un cinquième de millimètre », an upper
    bound, for the printed l = 0^m,5."""
    claim = "tisserand.example.displacement"
    return Numbers(
        _shift,
        what="l sin θ0 |c|, c = 2'42'' (line 200), θ0 = 30°",
        published=(None, (claim, _claim(claim))),
        inputs=("l",),
        bounds=("shift",),
    )
