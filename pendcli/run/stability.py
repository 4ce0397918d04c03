"""Numerical stability at the extremes: where each method is accurate, measured now.

Each paper declares its rows through its ``Paper.stability_rows`` hook (in
``pendcli.papers.<paper>.stability``), built with the helpers here;
:func:`pendcli.papers.registry.stability_rows` collects them in the registry's order. Every
method is evaluated on a grid running out to the extremes (n up to 10^12, amplitudes up to
within 1e-13 degree of 180°, resistance coefficients well past "small") against an independent
reference (mpmath at 30-50 digits, a positive series, closed forms, or direct ODE integration),
and each row summarises the range where the method is accurate and what fails beyond. Nothing
in a row is typed in: every number in ``measured``, ``accurate_range`` and ``fails_beyond``
comes from the run (about 1-2 s for all papers).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import Any

from pendcli.base.errors import PendcliError

__all__ = ["KEYS", "rel", "row", "short", "ulps", "worst"]

KEYS = ("family", "method", "accurate_range", "fails_beyond", "measured")


def short(exc: Exception, limit: int = 90) -> str:
    """An error message cut at a word boundary, marked when cut."""
    text = str(exc).split("; ")[0]
    if len(text) <= limit:
        return text
    return text[:limit].rsplit(" ", 1)[0] + " …"


def ulps(value: float, reference: Any) -> float:
    """|value - reference| in units in the last place of float(reference) (inf if undefined)."""
    import mpmath

    ref = float(reference)
    if ref == 0.0 or not math.isfinite(value):
        return math.inf
    return float(abs(mpmath.mpf(value) - reference) / math.ulp(ref))


def rel(value: float | None, reference: Any) -> float:
    """|value - reference| / |reference| (inf for a missing or non-finite value)."""
    import mpmath

    if value is None or not math.isfinite(value):
        return math.inf
    return float(abs((mpmath.mpf(value) - reference) / reference))


def row(family: str, method: str, accurate: str, fails: str, measured: str) -> dict[str, str]:
    """One row of the stability table."""
    return dict(zip(KEYS, (family, method, accurate, fails, measured), strict=True))


def worst(
    points: Iterable[tuple[Any, ...]], fn: Callable[..., float], ref: Callable[..., Any]
) -> tuple[float, tuple[Any, ...] | None]:
    """(worst ulp error, the point where it occurs), skipping underflowed references.

    A method that raises (overflow, refusal, domain error) at a point counts as infinitely
    wrong there.
    """
    worst_ulps, where = 0.0, None
    for p in points:
        r = ref(*p)
        if abs(float(r)) < 1e-290:
            continue
        try:
            u = ulps(fn(*p), r)
        except (OverflowError, PendcliError, ValueError):
            u = math.inf
        if u > worst_ulps or where is None:
            worst_ulps, where = u, p
    return worst_ulps, where
