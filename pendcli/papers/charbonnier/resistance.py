"""Charbonnier 1908, no. 16: the amplitude lost per swing under a monomial resistance b_n v^n.

Charbonnier's principal motion is the linear pendulum θ'' + k²θ + (c/l0) F(v) = 0, v = l0 θ'
(no. 11), with F(v) = B_n v^n and b_n = c B_n (no. 14).  To first order in b_n the amplitude of
one simple oscillation (half period T = π/k, from -α to the next elongation) drops by (no. 16)

    Δα = -(b_n/g) (α g T/π)^n I_n(π) = -b_n k^(n-2) α^n l0^(n-1) I_n(π).

Here both sides are computed: the formula, and the direct integration of the same equation
θ'' + k²θ + (b_n/l0) sign(v)|v|^n = 0 over one swing.  With τ = kt and θ = α y the equation
becomes y'' + y + β sign(y')|y'|^n = 0, y(0) = -1, y'(0) = 0, with the single parameter

    β = b_n v_m^n / (g α),  v_m = k α l0 = α g T/π  (the speed at the vertical),

and the formula reads Δα/α = -β I_n(π).  The relative error of the formula depends on n and β
only; :func:`first_order_limit` finds the β (and the predicted relative loss β I_n(π)) at
which it reaches a stated bound.  For n = 0 (friction) the formula is exact (each swing of the
linear pendulum loses exactly 2 b_0/g) as long as the pendulum does not stick (β < 1).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from pendcli.base.errors import PendcliError, invalid_value, out_of_range
from pendcli.papers.charbonnier.model import integral_pi

__all__ = [
    "SwingResult",
    "amplitude_loss_first_order",
    "first_order_limit",
    "relative_loss_exact",
    "relative_loss_first_order",
    "relative_loss_ode",
]

_ODE_METHODS = ("DOP853", "RK45", "Radau", "LSODA")


def _check_order(n: int) -> int:
    if isinstance(n, bool) or not isinstance(n, int) or not 0 <= n <= 10:
        raise out_of_range("n", f"{n!r}", "0 <= n <= 10")
    return n


def _check_beta(beta: float, n: int) -> float:
    beta = float(beta)
    if not (math.isfinite(beta) and beta > 0):
        raise out_of_range("beta", f"{beta}", "beta > 0")
    if n == 0 and beta >= 1.0:
        raise PendcliError(
            f"beta: {beta} >= 1 with n = 0: friction holds the pendulum at rest; expected "
            "0 < beta < 1"
        )
    return beta


def amplitude_loss_first_order(b_n: float, n: int, alpha: float, length: float, g: float) -> float:
    """Δα = -(b_n/g) (α g T/π)^n I_n(π), T = π √(l0/g) (no. 16), in radians.

    Charbonnier prints no value of g: the caller gives it (SI units: b_n in m^(1-n) s^(n-2)).
    """
    _check_order(n)
    half_period = math.pi * math.sqrt(length / g)
    return -(b_n / g) * (alpha * g * half_period / math.pi) ** n * integral_pi(n)


def relative_loss_first_order(beta: float, n: int) -> float:
    """Δα/α = -β I_n(π), the formula of no. 16 in the dimensionless parameter β."""
    _check_order(n)
    return -_check_beta(beta, n) * integral_pi(n)


@dataclass(frozen=True)
class SwingResult:
    relative_loss: float  # (α1 - α)/α over one simple oscillation
    duration: float  # τ = k t of the swing (π for the undamped motion)
    evaluations: int  # right-hand-side evaluations of the ODE solver


class _Elongation:
    """solve_ivp's event: y' = 0 while y' decreases (the next elongation); it ends the run."""

    terminal = True
    direction = -1

    def __call__(self, _tau: float, state: Sequence[float]) -> float:
        return state[1]


def relative_loss_ode(
    beta: float, n: int, rtol: float = 1e-10, method: str = "DOP853"
) -> SwingResult:
    """Integrate y'' + y + β sign(y')|y'|^n = 0 from y = -1 at rest to the next elongation."""
    _check_order(n)
    beta = _check_beta(beta, n)
    if method not in _ODE_METHODS:
        raise invalid_value("method", method, f"one of {', '.join(_ODE_METHODS)}")
    if not 1e-14 <= rtol <= 1e-1:
        raise out_of_range("rtol", f"{rtol}", "1e-14 <= rtol <= 0.1")
    from scipy.integrate import solve_ivp

    def rhs(_tau: float, state: Sequence[float]) -> list[float]:
        y, w = state
        drag = math.copysign(abs(w) ** n, w) if w != 0.0 else 0.0
        return [w, -y - beta * drag]

    sol = solve_ivp(
        rhs,
        (0.0, 60.0),
        [-1.0, 0.0],
        method=method,
        rtol=rtol,
        atol=rtol * 1e-3,
        events=_Elongation(),
    )
    if not sol.t_events[0].size:
        raise PendcliError(
            f"beta = {beta} with n = {n}: no second elongation (overdamped); use a smaller beta"
        )
    y1 = float(sol.y_events[0][0][0])
    return SwingResult(
        relative_loss=y1 - 1.0, duration=float(sol.t_events[0][0]), evaluations=int(sol.nfev)
    )


def relative_loss_exact(beta: float, n: int, digits: int = 30) -> Any:
    """Closed forms, independent of any ODE solver, for n = 0, 1, 2 (an mpmath number).

    n = 0: y1 = 1 - 2β.  n = 1: damped oscillator, y1 = exp(-β π/(2 ω)), ω = √(1 - β²/4).
    n = 2: E = y'²/2 obeys dE/dy = -y - 2βE, so E = C e^(-2βy) - y/(2β) + 1/(4β²) with
    E(-1) = 0; y1 is the positive root of E(y1) = 0.
    """
    import mpmath

    _check_order(n)
    beta = _check_beta(beta, n)
    with mpmath.workdps(digits):
        b = mpmath.mpf(beta)
        if n == 0:
            return -2 * b
        if n == 1:
            if b >= 2:
                raise PendcliError(f"beta: {beta} >= 2 with n = 1 is overdamped")
            omega = mpmath.sqrt(1 - b * b / 4)
            return mpmath.exp(-b * mpmath.pi / (2 * omega)) - 1
        if n == 2:
            c = -mpmath.exp(-2 * b) * (1 / (2 * b) + 1 / (4 * b * b))

            def energy(y):
                return c * mpmath.exp(-2 * b * y) - y / (2 * b) + 1 / (4 * b * b)

            guess = 1 - 4 * b / 3
            y1 = mpmath.findroot(
                energy, (guess * mpmath.mpf("0.9"), min(guess * 1.1, 1)), solver="anderson"
            )
            return y1 - 1
    raise PendcliError(f"no closed form for n = {n}; closed forms exist for n = 0, 1, 2")


def first_order_limit(n: int, bound: float = 0.01, rtol: float = 1e-11) -> dict[str, Any]:
    """The β where |formula - ODE|/|ODE| reaches ``bound``: secant steps in log β from 1e-3.

    The error of a first-order formula grows like β (the next term is O(β²)), so a few secant
    steps on log(error) against log(β) converge; each step is one ODE integration.
    """
    _check_order(n)
    if n == 0:
        beta = 0.5
        ode = relative_loss_ode(beta, 0, rtol=rtol).relative_loss
        err = abs(relative_loss_first_order(beta, 0) - ode) / abs(ode)
        return {"n": 0, "beta": None, "predicted_loss": None, "error_at_half": err, "steps": 1}

    def rel_error(beta: float) -> float:
        ode = relative_loss_ode(beta, n, rtol=rtol).relative_loss
        return abs(relative_loss_first_order(beta, n) - ode) / abs(ode)

    b0, e0 = 1e-3, rel_error(1e-3)
    b1 = b0 * bound / e0
    e1 = rel_error(b1)
    steps = 2
    while abs(math.log(e1 / bound)) > 0.005 and steps < 8:
        slope = math.log(e1 / e0) / math.log(b1 / b0)
        b0, e0 = b1, e1
        b1 = b1 * (bound / e1) ** (1.0 / slope)
        e1 = rel_error(b1)
        steps += 1
    return {
        "n": n,
        "beta": b1,
        "predicted_loss": b1 * integral_pi(n),
        "error": e1,
        "steps": steps,
    }
