"""Decide how a recomputed value stands against a printed one.

Rules (the printed string fixes the unit ``u`` of its last place, see :mod:`pendcli.data.numbers`):

``agrees``
    the recomputed value rounds to the printed one: ``|r - p| <= u/2``.
``truncated``
    it does not round to the printed value but truncates (chops toward zero) to it:
    same sign and ``|p| <= |r| < |p| + u``. This is the author dropping digits.
``last-digit``
    neither, but rounding ``r`` lands one unit away: ``|r - p| <= 3u/2``.
``discrepant``
    anything else.

An exact printed value (a fraction, a closed form such as ``2·2·4/(1·3·5)``) agrees when
the recomputed value equals it to floating-point accuracy (``|r - p| <= 8 eps |p|``) and is
discrepant otherwise. A claim of the form "at most p" (``comparison = "upper-bound"``) agrees
when ``r`` rounded to the printed precision is ``<= p``, and is discrepant otherwise.

A printed value that is not a finite number, or whose precision is not a finite positive
unit, is judged ``discrepant`` whatever the recomputed value: it cannot be agreed with (an
infinite printed value once widened every boundary to infinity and agreed with anything).
The table loader refuses such a value; this is the rule's own guard.

Boundaries are widened by a relative 1e-12 so that a value on a boundary, like 5.135 against
``5,14`` (stored as 5.13499999999999978...) or recomputed as 5.134999999999, is judged by its
digits, not by binary representation error; 5.13499999999 (2e-12 below) is not on it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from pendcli.data.numbers import PrintedNumber
from pendcli.data.vocabulary import CLAIM_VERDICTS, Verdict

__all__ = ["CLAIM_VERDICTS", "Comparison", "Verdict", "judge"]

_SLACK = 1e-12  # relative widening of every boundary (binary representation of decimals)
_EXACT_RTOL = 8 * 2.220446049250313e-16


@dataclass(frozen=True)
class Comparison:
    verdict: Verdict
    abs_diff: float  # recomputed - published
    rel_diff: float | None  # (recomputed - published) / |published|; None if published is 0
    digits: float  # agreeing significant digits, -log10 |rel diff|, capped at 17


def _digits(rel: float | None, abs_diff: float) -> float:
    if rel is None:
        return 17.0 if abs_diff == 0 else 0.0
    if rel == 0:
        return 17.0
    return round(min(17.0, max(0.0, -math.log10(abs(rel)))), 2)


def _judgeable(printed: PrintedNumber) -> bool:
    """A finite printed value, exact or known to a finite positive unit of its last place."""
    u = printed.resolution
    return math.isfinite(printed.value) and (u is None or (math.isfinite(u) and u > 0))


def judge(printed: PrintedNumber, recomputed: float, comparison: str = "equal") -> Comparison:
    """Compare a recomputed value with a printed one; see the module docstring for the rules."""
    if not (math.isfinite(recomputed) and _judgeable(printed)):
        return Comparison(Verdict.DISCREPANT, math.nan, None, 0.0)
    p = printed.value
    diff = recomputed - p
    rel = diff / abs(p) if p != 0 else None
    digits = _digits(rel, diff)

    if comparison not in ("equal", "upper-bound"):
        raise ValueError(f"unknown comparison {comparison!r}")
    if printed.resolution is None and comparison == "upper-bound":
        ok = recomputed <= p + _EXACT_RTOL * abs(p)
        return Comparison(Verdict.AGREES if ok else Verdict.DISCREPANT, diff, rel, digits)
    if printed.resolution is None:  # exact printed value
        ok = abs(diff) <= _EXACT_RTOL * max(abs(p), abs(recomputed))
        return Comparison(Verdict.AGREES if ok else Verdict.DISCREPANT, diff, rel, digits)

    u = printed.resolution
    slack = _SLACK * max(abs(p), u)
    if comparison == "upper-bound":
        rounded_ok = recomputed <= p + u / 2 + slack
        return Comparison(Verdict.AGREES if rounded_ok else Verdict.DISCREPANT, diff, rel, digits)

    if abs(diff) <= u / 2 + slack:
        verdict = Verdict.AGREES
    elif (p == 0 or math.copysign(1, recomputed) == math.copysign(1, p)) and (
        abs(p) - slack <= abs(recomputed) < abs(p) + u - slack
    ):
        verdict = Verdict.TRUNCATED
    elif abs(diff) <= 1.5 * u + slack:
        verdict = Verdict.LAST_DIGIT
    else:
        verdict = Verdict.DISCREPANT
    return Comparison(verdict, diff, rel, digits)
