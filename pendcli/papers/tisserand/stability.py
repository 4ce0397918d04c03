"""Tisserand's stability rows: Ω of the exact conical pendulum by quadrature, series and ODE,
against mpmath quadrature of the first integrals at 30 digits
(:func:`pendcli.papers.tisserand.speed.reference_conical`).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from pendcli.base.errors import PendcliError
from pendcli.papers.tisserand.speed import reference_conical
from pendcli.run.stability import rel, row, short

__all__ = ["conical_rows", "stability_rows"]

FAMILY = "exact conical pendulum"
CASES = ((5.0, 2.0), (20.0, 10.0), (45.0, 20.0), (80.0, 40.0), (30.0, 0.01))  # (θ0, θ1) in °
MEASURED = "relative error of Ω against mpmath quadrature of the first integrals (30 digits)"
SERIES_GOOD = 1e-4  # the series row's accurate range: relative error below this

Case = tuple[float, float]


def _radians(case: Case) -> tuple[float, float]:
    return math.radians(case[0]), math.radians(case[1])


def _label(case: Case) -> str:
    return f"{case[0]:g}°/{case[1]:g}°"


def _errors(precession: Callable[[float, float], float], refs: dict[Case, float]) -> dict:
    return {c: rel(precession(*_radians(c)), refs[c]) for c in CASES}


def _quad_row(refs: dict[Case, float]) -> dict[str, str]:
    from pendcli.numerics.spherical import exact_conical

    errs = _errors(lambda t0, t1: exact_conical(t0, t1).precession, refs)
    return row(
        FAMILY,
        "exact_conical quad (Tisserand's (4)-(5), default rtol)",
        ", ".join(f"{_label(c)}: {e:.0e}" for c, e in errs.items()),
        "θ0 > 89.999°: refused (the grid would pass 2^21 points near the horizontal)",
        MEASURED,
    )


def _series_row(refs: dict[Case, float]) -> dict[str, str]:
    from pendcli.papers.tisserand.model import series_conical

    errs = _errors(lambda t0, t1: series_conical(t0, t1, 6).precession, refs)
    return row(
        FAMILY,
        "series_conical, order 6 (Tisserand)",
        ", ".join(f"{_label(c)}: {e:.0e}" for c, e in errs.items() if e < SERIES_GOOD),
        ", ".join(f"{_label(c)}: {e:.0e}" for c, e in errs.items() if e >= SERIES_GOOD)
        or "none measured",
        MEASURED,
    )


def _ode_row(refs: dict[Case, float]) -> dict[str, str]:
    from pendcli.numerics.spherical import exact_conical

    errs, refused = {}, []
    for c in CASES:
        try:
            motion = exact_conical(*_radians(c), method="ode", rtol=1e-12)
            errs[c] = rel(motion.precession, refs[c])
        except PendcliError as exc:
            refused.append(f"{_label(c)}: {short(exc)}")
    return row(
        FAMILY,
        "exact_conical ode (DOP853, rtol 1e-12)",
        ", ".join(f"{_label(c)}: {e:.0e}" for c, e in errs.items()),
        "; ".join(refused) or "none measured",
        MEASURED,
    )


def conical_rows() -> list[dict[str, str]]:
    """Ω by Tisserand's quadrature (4)-(5), his series (order 6) and the ODE."""
    refs = {c: reference_conical(_radians(c))[1] for c in CASES}
    return [_quad_row(refs), _series_row(refs), _ode_row(refs)]


def stability_rows() -> list[dict[str, str]]:
    """Tisserand's rows."""
    return conical_rows()
