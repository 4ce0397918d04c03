"""Zeros of a cylinder function C_ν(z) = cos δ J_ν(z) + sin δ Y_ν(z) in mpmath.

The root is found in double precision first (Newton on ``scipy.special.jv``/``yv`` from
McMahon's first term), then polished by secant steps at mpmath's working precision: three
evaluations of J_ν and Y_ν at full precision instead of the thirteen of ``mpmath.findroot``
started from McMahon's first term (Y_ν of integer order is the costly one).
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["cylinder", "cylinder_zero"]

_NEWTON_STEPS = 8  # double-precision Newton steps (quadratic: three or four suffice)
_SECANT_STEPS = 12  # at the working precision (three suffice from a double start)


def cylinder(nu: int, delta: Any, z: Any) -> Any:
    """C_ν(z) = cos δ J_ν(z) + sin δ Y_ν(z) in mpmath at the working precision."""
    import mpmath

    return mpmath.cos(delta) * mpmath.besselj(nu, z) + mpmath.sin(delta) * mpmath.bessely(nu, z)


def _double_zero(nu: int, delta: float, guess: float) -> float:
    """The zero of C_ν nearest ``guess`` in double precision: Newton with
    C_ν'(z) = C_(ν−1)(z) − (ν/z) C_ν(z) (DLMF 10.6.2)."""
    from scipy.special import jv, yv

    c, s = math.cos(delta), math.sin(delta)
    z = guess
    for _ in range(_NEWTON_STEPS):
        value = c * jv(nu, z) + s * yv(nu, z)
        slope = c * jv(nu - 1, z) + s * yv(nu - 1, z) - nu / z * value
        step = float(value / slope)
        z -= step
        if abs(step) <= 4e-16 * z:
            break
    return z


def cylinder_zero(nu: int, delta: Any, guess: float) -> Any:
    """The zero of C_ν nearest ``guess`` (within a quarter period), to mpmath's working
    precision: secant steps from the double-precision zero and a point 2⁻⁴⁰ away, until a
    step is below 16 ulp of the working precision (each step squares the error, roughly:
    three evaluations of C_ν from a double-precision start)."""
    import mpmath

    x0 = mpmath.mpf(_double_zero(nu, float(delta), guess))
    x1 = x0 * (1 + mpmath.mpf(2) ** -40)
    f0, f1 = cylinder(nu, delta, x0), cylinder(nu, delta, x1)
    tol = abs(x0) * mpmath.eps * 16
    for _ in range(_SECANT_STEPS):
        if f1 == f0:
            return x1
        x0, x1 = x1, x1 - f1 * (x1 - x0) / (f1 - f0)
        if abs(x1 - x0) <= tol:
            return x1
        f0, f1 = f1, cylinder(nu, delta, x1)
    raise ArithmeticError(f"no zero of C_{nu} near {guess}: the secant did not converge")
