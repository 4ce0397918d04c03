"""Lecornu (1894), § II, lines 206-256: the numbers of the 0,35 m/s example (after (14) to
after (16)), computed for the numeric mode of the printed-form engine
(:mod:`pendcli.verify.printed_numeric`).

Each ``numbers_*`` returns a :class:`~pendcli.verify.printed_numeric.Numbers`: the value of
every printed number of its ledger row, in printed order, by the author's own step (mpmath at
30 digits): the function the text evaluates (the zeros of J₂ and J₁, J₀), at the inputs the
text gives, which are his printed numbers of the preceding lines, read from the published
table (``tables/published/lecornu.toml``), never retyped. g is the table's assumption (9,81;
not printed); b = 0,35 m/s and l = 1 m are printed. ``published`` names, for each printed
number, the claim that prints the same number, so that the ledger and the table cannot drift.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import pairwise
from typing import Any

import mpmath
import sympy as sp

from pendcli.papers.lecornu.model import constant, printed_number
from pendcli.verify.printed_check import Reference
from pendcli.verify.printed_numeric import Numbers

_DPS = 30
J2 = [f"lecornu.j2_zeros.{k}" for k in range(1, 6)]  # (15), ascending
J1 = [f"lecornu.j1_zeros.{k}" for k in range(1, 7)]  # line 252, descending
LENGTHS = [f"lecornu.example.length.{k}" for k in range(1, 6)]
TIMES = [f"lecornu.example.time.{k}" for k in range(1, 6)]
J0 = [f"lecornu.j0_at_j2_zeros.{k}" for k in range(1, 6)]
COEFFICIENT = "lecornu.coefficient_b2_4g"


def _published(claim_id: str) -> Any:
    """The printed number of a claim as an exact mpmath decimal (its printed digits)."""
    number = printed_number(claim_id)
    return mpmath.mpf(f"{number.value:.{number.decimals or 0}f}")


def _numbers(values: list[Any], what: str, claims: Sequence[str | None], **kw: Any) -> Any:
    published = tuple(None if c is None else (c, printed_number(c)) for c in claims)
    return Numbers(tuple(values), what=what, published=published, **kw)


def numbers_j2_roots() -> Any:
    """(15), line 208: the first five zeros of J₂ (2J₁(z) = zJ₀(z), line 202), mpmath."""
    with mpmath.workdps(_DPS):
        roots = [mpmath.besseljzero(2, k) for k in range(1, 6)]
    return _numbers(roots, "the zeros of J₂ (mpmath.besseljzero)", list(J2))


def numbers_j2_roots_chopped() -> Any:
    """Line 210, « Je néglige les décimales qui suivent la seconde », applied to (15): each
    zero of J₂ (mpmath) with its decimals after the second dropped (toward zero), the value
    the sentence says each printed root is."""
    with mpmath.workdps(_DPS):
        hundred = mpmath.mpf(100)
        roots = [mpmath.floor(mpmath.besseljzero(2, k) * hundred) / hundred for k in range(1, 6)]
    what = "the zeros of J₂ (mpmath.besseljzero) with the decimals after the second dropped"
    return _numbers(roots, what, list(J2))


def numbers_table_speeds() -> Any:
    """Line 216: √(g l/ξ) = 2√(g l)/z for l = 1 m at the roots z of (15) as printed."""
    with mpmath.workdps(_DPS):
        gl = mpmath.mpf(constant("g")) * mpmath.mpf(constant("length"))
        speeds = [2 * mpmath.sqrt(gl) / _published(c) for c in J2]
    ids = [f"lecornu.speed.{k}" for k in range(1, 6)]
    return _numbers(speeds, f"2√(gl)/z, g = {constant('g')}, at the printed (15)", list(ids))


def numbers_eq16() -> Any:
    """(16), line 220: its printed 0,00313 against b²/(4g) in metres (b = 0,35 m/s printed,
    g = 9,81 assumed); its equalities as identities from x = gl/b² (line 170) at the root
    x = ξ = z²/4 (z = 2√x, line 200)."""
    b, g, z = (sp.Symbol(n, real=True) for n in ("b", "g", "z"))
    xi = z**2 / 4
    identity = Reference({"xi": xi, "l": b**2 / g * xi}, what="x = gl/b² at x = ξ = z²/4")
    with mpmath.workdps(_DPS):
        speed, gravity = mpmath.mpf(constant("speed")), mpmath.mpf(constant("g"))
        coefficient = speed**2 / (4 * gravity)
    what = f"b²/(4g) in metres, b = {constant('speed')} m/s, g = {constant('g')} m/s²"
    return _numbers([coefficient], what, [COEFFICIENT], identity=identity)


def numbers_table_lengths() -> Any:
    """Line 224: the lengths 0,00313 z² of (16) at the roots (15) as printed, largest first."""
    with mpmath.workdps(_DPS):
        lengths = [_published(COEFFICIENT) * _published(c) ** 2 for c in J2[::-1]]
    return _numbers(lengths, "0,00313 z² (16) at the printed (15)", list(LENGTHS))


def numbers_table_times() -> Any:
    """Line 228: the instants (1 − l)/0,35 of the elongations at the lengths of line 224."""
    with mpmath.workdps(_DPS):
        start, speed = mpmath.mpf(constant("length")), mpmath.mpf(constant("speed"))
        times = [(start - _published(c)) / speed for c in LENGTHS]
    return _numbers(times, "(1 − l)/0,35 at the printed lengths (line 224)", list(TIMES))


def numbers_table_intervals() -> Any:
    """Line 232: the intervals between the successive limit positions, the differences of
    the instants of line 228 and of the zero length, 2,86 s (line 230)."""
    with mpmath.workdps(_DPS):
        instants = [_published(c) for c in [*TIMES, "lecornu.example.time_zero_length"]]
        gaps = [later - sooner for sooner, later in pairwise(instants)]
    ids = [f"lecornu.example.interval.{k}" for k in range(1, 6)]
    return _numbers(gaps, "differences of the printed instants (lines 228, 230)", list(ids))


def numbers_table_j0() -> Any:
    """Line 240: J₀ at the roots (15) as printed (« les valeurs de J₀(z) correspondant aux
    valeurs de z comprises dans le tableau (15) », line 238)."""
    with mpmath.workdps(_DPS):
        values = [mpmath.besselj(0, _published(c)) for c in J2]
    return _numbers(values, "J₀ at the printed (15) (mpmath.besselj)", list(J0))


def numbers_table_amplitudes() -> Any:
    """Line 246: θ/θ0 = J₀(z)/J₀(17,96) (line 236) from the J₀ values of line 240, from
    z = 17,96 down, then the zero length, whose limit is 1 (line 242) over J₀(17,96)."""
    with mpmath.workdps(_DPS):
        printed = [_published(c) for c in J0[::-1]]
        limit = _published("lecornu.limit_2j1_over_z")
        ratios = [v / printed[0] for v in printed] + [limit / printed[0]]
    ids = [None, *(f"lecornu.deviation.{k}" for k in range(2, 6)), "lecornu.deviation.zero_length"]
    return _numbers(ratios, "J₀(z)/J₀(17,96) from the printed J₀ (line 240)", ids)


def numbers_j1_roots() -> Any:
    """Line 252: the zeros of J₁ below 20, from the largest (mpmath.besseljzero)."""
    with mpmath.workdps(_DPS):
        roots = [mpmath.besseljzero(1, k) for k in range(6, 0, -1)]
    return _numbers(roots, "the zeros of J₁ (mpmath.besseljzero)", list(J1))


def numbers_vertical_lengths() -> Any:
    """Line 256: the lengths « en vertu de (16) », 0,00313 z², at the zeros of line 252."""
    with mpmath.workdps(_DPS):
        lengths = [_published(COEFFICIENT) * _published(c) ** 2 for c in J1]
    ids = [f"lecornu.j1_lengths.{k}" for k in range(1, 7)]
    return _numbers(lengths, "0,00313 z² (16) at the printed zeros of J₁", ids)
