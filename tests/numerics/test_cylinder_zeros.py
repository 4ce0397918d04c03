"""Zeros of cos δ J_ν + sin δ Y_ν (pendcli.numerics.cylinder_zeros) against mpmath's own
zeros of J_ν and Y_ν and against mpmath.findroot started from McMahon's first term."""

from __future__ import annotations

import math

import mpmath
import pytest

from pendcli.numerics.cylinder_zeros import cylinder_zero

DIGITS = 30


@pytest.mark.parametrize("k", [1, 3, 8, 30, 65])
def test_zeros_of_j2_are_mpmaths(k: int) -> None:
    """δ = 0: the zeros of J₂ (mpmath.besseljzero), to the working precision."""
    with mpmath.workdps(DIGITS):
        found = cylinder_zero(2, mpmath.mpf(0), (k + 0.75) * math.pi)
        exact = mpmath.besseljzero(2, k)
        assert abs(found - exact) <= exact * mpmath.mpf(10) ** (2 - DIGITS)


@pytest.mark.parametrize("k", [2, 5, 17, 64])
def test_zeros_of_y2_are_mpmaths(k: int) -> None:
    """δ = π/2: the zeros of Y₂ (mpmath.besselyzero), to the working precision."""
    with mpmath.workdps(DIGITS):
        found = cylinder_zero(2, mpmath.pi / 2, (k + 0.25) * math.pi)
        exact = mpmath.besselyzero(2, k)
        assert abs(found - exact) <= exact * mpmath.mpf(10) ** (2 - DIGITS)


@pytest.mark.parametrize("n", [4, 8, 16, 32, 64])
def test_a_mixed_phase_zero_is_findroots(n: int) -> None:
    """δ = 0.3, the zeros Lecornu's amplitude factor is measured at: mpmath.findroot from
    McMahon's first term, C₂(z) ~ cos(z − 5π/4 + δ), finds the same zero to 30 digits."""
    with mpmath.workdps(DIGITS):
        delta = mpmath.mpf("0.3")

        def c2(z: mpmath.mpf) -> mpmath.mpf:
            return mpmath.cos(delta) * mpmath.besselj(2, z) + mpmath.sin(delta) * mpmath.bessely(
                2, z
            )

        exact = mpmath.findroot(c2, (n + 1.25) * mpmath.pi - delta)
        found = cylinder_zero(2, delta, (n + 1.25) * math.pi - 0.3)
        assert abs(found - exact) <= exact * mpmath.mpf(10) ** (2 - DIGITS)
