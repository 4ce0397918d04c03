"""Explorations behind `pendcli tisserand example` and `pendcli tisserand series`.

Tisserand's series against the exact motion at any amplitudes (:func:`example_rows`) and over
a range of θ0 (:func:`series_rows`); the printed values are shown only at the example's
amplitudes.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from pendcli.base.errors import PendcliError, out_of_range
from pendcli.data.tables import load_paper_table
from pendcli.numerics.spherical import check_amplitudes
from pendcli.papers.tisserand.claims import reading_evidence
from pendcli.papers.tisserand.model import (
    PAPER,
    PRINTED_UNIT,
    ConicalMotion,
    displacement_mm,
    exact_conical,
    example_angles,
    example_length_m,
    example_ratio,
    series_conical,
)
from pendcli.papers.tisserand.units import angle_text, parse_length

__all__ = ["example_rows", "printed_example", "reading_rows", "series_rows"]

Row = dict[str, Any]

# key, label, unit ("angle": radians, shown sexagesimal), the value in a ConicalMotion
_EXAMPLE_QUANTITIES: tuple[tuple[str, str, str, Callable[[ConicalMotion], float]], ...] = (
    ("k1", "k'/k (mean motion of ψ)", "", lambda m: m.k1),
    (
        "radial_period",
        "k T_r: radial period, θ0 → θ1 → θ0 (= π k/k')",
        "",
        lambda m: m.radial_period,
    ),
    (
        "apsidal_advance",
        "rotation of the major axis per radial period, Δφ - π",
        "angle",
        lambda m: m.apsidal_advance,
    ),
    ("k2", "k''/k (eq. V)", "", lambda m: m.k2),
    ("precession", "Ω: rotation of the major axis per unit k't", "rad", lambda m: m.precession),
    ("b1", "ψ: coefficient of sin 2k't", "angle", lambda m: m.psi_coeffs[0]),
    ("b2", "ψ: coefficient of sin 4k't", "angle", lambda m: m.psi_coeffs[1]),
    ("c1", "φ': coefficient of sin 2k't", "angle", lambda m: m.phi_coeffs[0]),
)
_ELLIPTIC_KEYS = ("k1", "radial_period", "apsidal_advance", "k2", "precession")


@dataclass(frozen=True)
class _Motions:
    series: ConicalMotion
    quad: ConicalMotion
    ode: ConicalMotion | None  # None where the method refuses (see ``refused``)
    elliptic: ConicalMotion | None
    refused: str


def _motions(theta0: float, theta1: float) -> _Motions:
    """The series and the three exact methods; a method that refuses leaves its reason."""
    reasons = []
    others: dict[str, ConicalMotion | None] = {}
    for method in ("ode", "elliptic"):
        try:
            others[method] = exact_conical(theta0, theta1, method=method)
        except PendcliError as exc:
            others[method] = None
            reasons.append(str(exc))
    return _Motions(
        series=series_conical(theta0, theta1, order=6),
        quad=exact_conical(theta0, theta1, method="quad"),
        ode=others["ode"],
        elliptic=others["elliptic"],
        refused="; ".join(reasons),
    )


def printed_example() -> dict[str, str]:
    """The printed strings of the example by quantity key (b1, b2, c1; shift as a bound)."""
    table = load_paper_table(PAPER)
    return {
        "b1": table.claim(f"{PAPER}.example.psi_sin2").published,
        "b2": table.claim(f"{PAPER}.example.psi_sin4").published,
        "c1": table.claim(f"{PAPER}.example.phi_sin2").published,
        "shift": "<= " + table.claim(f"{PAPER}.example.displacement").published,
    }


def _printed_for(theta0: float, theta1: float, length_m: float) -> dict[str, str]:
    """The printed strings, when the amplitudes are the example's (either reading)."""
    readings = [example_angles(), example_angles(PRINTED_UNIT)]
    if not any(
        math.isclose(theta0, a, rel_tol=1e-12) and math.isclose(theta1, b, rel_tol=1e-12)
        for a, b in readings
    ):
        return {}
    out = printed_example()
    if not math.isclose(length_m, example_length_m()):
        del out["shift"]
    return out


def reading_rows() -> list[Row]:
    """Tisserand's series under both readings of the example's units, as display rows."""
    return [
        {
            "reading": r.reading,
            "theta0": r.theta0,
            "theta1": r.theta1,
            "psi_sin2": angle_text(r.b1),
            "psi_sin4": angle_text(r.b2),
            "phi_sin2": angle_text(r.c1),
            "displacement_mm": r.displacement_mm,
        }
        for r in reading_evidence()
    ]


def _comparison_row(
    quantity: tuple[str, str, str],
    series: float,
    exact: float,
    ode: float | None,
    elliptic: float | None,
) -> Row:
    """One quantity: series, quadrature, ODE (or None) and elliptic (or None) side by side."""
    label, unit, published = quantity
    is_angle = unit == "angle"
    row: Row = {
        "quantity": label,
        "published": published,
        "series": series,
        "exact": exact,
        "exact_ode": ode,
        "methods_diff": None if ode is None else ode - exact,
        "elliptic_rel_diff": None if elliptic is None or not exact else elliptic / exact - 1.0,
        "series_error": series - exact,
        "series_rel_error": (series - exact) / exact if exact else None,
        "unit": "rad" if is_angle else unit,
    }
    if is_angle:
        row["series_text"] = angle_text(series)
        row["exact_text"] = angle_text(exact)
    return row


def example_rows(theta0: float, theta1: float, length_m: float | None = None) -> list[Row]:
    """Series against exact motion (two methods) for every quantity of the example."""
    theta0, theta1 = check_amplitudes(theta0, theta1)
    length_m = parse_length(example_length_m() if length_m is None else length_m)
    m = _motions(theta0, theta1)
    printed = _printed_for(theta0, theta1, length_m)
    rows = []
    for key, label, unit, get in _EXAMPLE_QUANTITIES:
        ode = None if m.ode is None else get(m.ode)
        elliptic = get(m.elliptic) if m.elliptic is not None and key in _ELLIPTIC_KEYS else None
        quantity = (label, unit, printed.get(key, ""))
        rows.append(_comparison_row(quantity, get(m.series), get(m.quad), ode, elliptic))
    rows.append(
        _comparison_row(
            (
                f"largest shift on the circle of radius l sin θ0 (l = {length_m:g} m)",
                "mm",
                printed.get("shift", ""),
            ),
            displacement_mm(m.series, length_m),
            displacement_mm(m.quad, length_m),
            None if m.ode is None else displacement_mm(m.ode, length_m),
            None,
        )
    )
    if m.refused:
        rows.append({"quantity": "methods refused", "published": "", "note": m.refused})
    return rows


SERIES_GRID_DEGREES = (0.5, 1, 2, 5, 10, 15, 20, 30, 45, 60, 75, 85, 89)


def series_rows(
    ratio: float | None = None,
    order: int = 6,
    theta0_degrees: Sequence[float] | None = None,
) -> list[Row]:
    """k', k'' and Ω from the series against the exact motion, θ1 = ratio·θ0, over θ0."""
    ratio = example_ratio() if ratio is None else ratio
    if isinstance(ratio, bool) or not isinstance(ratio, (int, float)) or not 0 <= ratio <= 1:
        raise out_of_range("ratio", f"{ratio!r}", "0 <= ratio <= 1")
    rows = []
    for deg in theta0_degrees or SERIES_GRID_DEGREES:
        theta0 = math.radians(deg)
        theta1 = ratio * theta0
        s = series_conical(theta0, theta1, order)
        x = exact_conical(theta0, theta1, method="quad")
        row: Row = {"theta0_deg": float(deg), "theta1_deg": math.degrees(theta1)}
        for key, a, b in (
            ("k1", s.k1, x.k1),
            ("k2", s.k2, x.k2),
            ("precession", s.precession, x.precession),
        ):
            row[f"{key}_series"] = a
            row[f"{key}_exact"] = b
            row[f"{key}_rel_error"] = (a - b) / b if b else None
        rows.append(row)
    return rows
