"""Tisserand's printed numbers recomputed: the example's coefficients, the 1/5 mm, Resal's rate.

:func:`recompute` returns one :class:`~pendcli.verify.claims.Recomputed` per row of
``tables/published/tisserand.toml``; each small builder below produces a few of them from
the example's motion (series and exact, computed once). ``value`` is what Tisserand's own
formulas give, ``exact`` the same quantity for the exact motion.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from pendcli.data.tables import load_paper_table
from pendcli.papers.tisserand.model import (
    DEGREES,
    PAPER,
    PRINTED_UNIT,
    ConicalMotion,
    displacement_mm,
    exact_conical,
    example_angles,
    example_length_m,
    example_reading,
    periodic_excursion_mm,
    resal_rate_limit,
    series_conical,
)
from pendcli.papers.tisserand.units import angle_text
from pendcli.verify.claims import Recomputed

__all__ = ["ReadingRow", "reading_evidence", "recompute"]


# ---------------------------------------------------------------- the reading of the units


@dataclass(frozen=True)
class ReadingRow:
    """Tisserand's series at the example's amplitudes under one reading of their unit."""

    reading: str
    theta0: str
    theta1: str
    b1: float  # rad, series (II)
    b2: float
    c1: float  # rad, series (V)
    displacement_mm: float


READINGS = (("as printed (arcmin)", PRINTED_UNIT), ("degrees", DEGREES))


def reading_evidence(length_m: float | None = None) -> list[ReadingRow]:
    """Tisserand's series under both readings of the printed « θ0 = 30', θ1 = 15' »."""
    length = example_length_m() if length_m is None else length_m
    rows = []
    for label, unit in READINGS:
        series = series_conical(*example_angles(unit), order=6)
        theta0, theta1 = example_reading(unit)
        rows.append(
            ReadingRow(
                reading=label,
                theta0=theta0,
                theta1=theta1,
                b1=series.psi_coeffs[0],
                b2=series.psi_coeffs[1],
                c1=series.phi_coeffs[0],
                displacement_mm=displacement_mm(series, length),
            )
        )
    return rows


def _reading_note() -> str:
    minutes, degrees = reading_evidence()
    return (
        f"Under the printed reading {minutes.theta0}, {minutes.theta1} the series give "
        f"{angle_text(minutes.b1)}, {angle_text(minutes.b2)}, {angle_text(minutes.c1)} and "
        f"{minutes.displacement_mm:.2e} mm; with {degrees.theta0}, {degrees.theta1}: "
        f"{angle_text(degrees.b1)}, {angle_text(degrees.b2)}, {angle_text(degrees.c1)}, "
        f"{degrees.displacement_mm:.4f} mm."
    )


# ---------------------------------------------------------------- the example's motion


@dataclass(frozen=True)
class _Example:
    theta0: float
    theta1: float
    series: ConicalMotion  # Tisserand's (I), (II), (V)
    exact: ConicalMotion  # quadrature of (4)-(5)
    methods: str


def _example() -> _Example:
    """The example's motion by the series and by the quadrature, checked against the ODE."""
    theta0, theta1 = example_angles()
    exact = exact_conical(theta0, theta1, method="quad")
    check = exact_conical(theta0, theta1, method="ode")
    agreement = max(
        abs(a - b)
        for a, b in zip(
            exact.psi_coeffs + exact.phi_coeffs, check.psi_coeffs + check.phi_coeffs, strict=True
        )
    )
    text0, text1 = example_reading()
    methods = (
        f"Tisserand's (II)/(V) at θ0 = {text0}, θ1 = {text1}; exact: quadrature of (4)-(5) "
        f"(ODE agrees to {agreement:.1e} rad)"
    )
    return _Example(theta0, theta1, series_conical(theta0, theta1, order=6), exact, methods)


# ---------------------------------------------------------------- the builders


def _series_error(series: float, exact: float) -> str:
    return (
        f"series {angle_text(series)}, exact {angle_text(exact)} "
        f"(series error {(series - exact) / exact:+.1%})."
    )


def _coefficient_claims(ex: _Example) -> dict[str, Recomputed]:
    """The printed coefficients of sin 2k't, sin 4k't in ψ (II) and of sin 2k't in φ' (V)."""
    reading = _reading_note()  # the unit reading is argued on the first coefficient
    rows = (
        ("psi_sin2", ex.series.psi_coeffs[0], ex.exact.psi_coeffs[0], f" {reading}"),
        ("psi_sin4", ex.series.psi_coeffs[1], ex.exact.psi_coeffs[1], ""),
        ("phi_sin2", ex.series.phi_coeffs[0], ex.exact.phi_coeffs[0], ""),
    )
    return {
        f"{PAPER}.example.{name}": Recomputed(
            value=math.degrees(series),
            exact=math.degrees(exact),
            method=ex.methods,
            note=_series_error(series, exact) + extra,
        )
        for name, series, exact, extra in rows
    }


def _displacement_claim(ex: _Example) -> dict[str, Recomputed]:
    """« un petit déplacement égal au plus à un cinquième de millimètre », l from the table."""
    claim = load_paper_table(PAPER).claim(f"{PAPER}.example.displacement")
    bound, printed = claim.number.value, claim.published
    length = example_length_m()
    shift_series = displacement_mm(ex.series, length)
    shift_exact = displacement_mm(ex.exact, length)
    excursion = periodic_excursion_mm(ex.theta0, ex.theta1, length)
    return {
        claim.id: Recomputed(
            value=shift_series,
            exact=shift_exact,
            method="l sin θ0 |c_1| with c_1 from (V) (value) and from the exact motion (exact)",
            note=(
                f"Series {shift_series:.4f} mm {'<=' if shift_series <= bound else '>'} "
                f"{printed} mm; exact motion {shift_exact:.4f} mm "
                f"{'<=' if shift_exact <= bound else '>'} {printed} mm (all harmonics of the "
                f"exact periodic part of φ': at most {excursion:.4f} mm)."
            ),
        )
    }


def _resal_claim(ex: _Example) -> dict[str, Recomputed]:
    """Resal's rate (3/8) u0 u1: the zero-amplitude limit of the exact Ω/(u0 u1)."""
    claim = load_paper_table(PAPER).claim(f"{PAPER}.resal.rate")
    u0u1 = math.sin(ex.theta0) * math.sin(ex.theta1)
    limit = resal_rate_limit()
    ratio_exact = ex.exact.precession / u0u1
    text0, text1 = example_reading()
    return {
        claim.id: Recomputed(
            value=limit,
            method="exact dφ'/dψ of eq. (5), per u0 u1, at zero amplitude",
            note=(
                f"At {text0}, {text1} the exact Ω/(u0 u1) is {ratio_exact:.5f} "
                f"({(ratio_exact / limit - 1):+.1%} from {claim.published}); Tisserand's k''/k' "
                f"gives {ex.series.precession / u0u1:.5f}."
            ),
        )
    }


BUILDERS: tuple[Callable[[_Example], dict[str, Recomputed]], ...] = (
    _coefficient_claims,
    _displacement_claim,
    _resal_claim,
)


def recompute() -> dict[str, Recomputed]:
    """The example's printed numbers and Resal's rate, from (I)-(V) and from the exact motion."""
    example = _example()
    out: dict[str, Recomputed] = {}
    for builder in BUILDERS:
        out.update(builder(example))
    return out
