"""Lecornu's model of the shortening pendulum and the fuller models it is measured against.

Pure functions of (speed b, length L at t = 0, g); ``None`` means the paper's value, read from
``[paper.constants]`` of ``tables/published/lecornu.toml`` (:func:`constant`).

* the author's model: series (10)/(13) (:func:`lecornu_series`), solution (10) bounded at
  zero length, its elongations at the zeros of J_2 and vertical passages at those of J_1
  (:func:`example_model`);
* the fuller model: eq. (9) solved exactly for a pendulum released from rest
  (:func:`from_rest_model`), and eq. (3) integrated directly (:func:`integrate_shortening`);
* the coefficients -0,13, 3π/32 and 6,47 of section II from the exact Bessel solution,
  extrapolated to b → 0 (:func:`half_oscillation_coefficient_exact` and the two below it);
* k⁴ = sin⁴(θ0/2), the order Lecornu neglects in (38) (:func:`lecornu_k4`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cache

import numpy as np
from numpy.typing import NDArray

from pendcli.base.checks import real_in_range
from pendcli.base.errors import PendcliError, invalid_value
from pendcli.data.numbers import PrintedNumber
from pendcli.data.tables import load_paper_table, paper_constant
from pendcli.numerics.besselzeros import ascending_series, bessel_zeros
from pendcli.numerics.planar import modulus_squared
from pendcli.verify.formula_engine import richardson

__all__ = [
    "FLOOR_RANGE",
    "G_RANGE",
    "LENGTH_RANGE",
    "MAX_Z0",
    "MAX_Z0_ODE",
    "PAPER",
    "SPEED_RANGE",
    "ExampleModel",
    "FromRestModel",
    "Integration",
    "check_example",
    "constant",
    "elongation_times",
    "example_model",
    "from_rest_cylinder",
    "from_rest_model",
    "half_oscillation_coefficient_exact",
    "integrate_shortening",
    "lecornu_k4",
    "lecornu_series",
    "lengthening_from_vertical",
    "mean_pendulum_coefficient_exact",
    "period_b2_coefficient_exact",
    "printed",
    "printed_number",
    "theta_curves",
]

Array = NDArray[np.float64]

PAPER = "lecornu"
SPEED_RANGE = (1e-3, 1e3)  # m/s
LENGTH_RANGE = (1e-3, 1e3)  # m
G_RANGE = (0.1, 100.0)  # m/s²
MAX_Z0 = 2.0e4  # 2√(gL)/b: about 6000 oscillations; beyond, lists get silly and slow
MAX_Z0_ODE = 1.0e3  # the ODE method integrates every oscillation: keep it to ~300
FLOOR_RANGE = (1e-9, 0.5)  # length floor as a fraction of the initial length
EXTRAPOLATION_PS = (0.004, 0.002, 0.001)  # p = b/√(ga) for the limits b → 0


# --- the paper's numbers ------------------------------------------------------------------


def constant(name: str) -> float:
    """A number the paper fixes or pendcli assumes: ``g`` (m/s²), ``speed`` (0,35 m/s),
    ``length`` (1 m at t = 0), ``table_limit`` (20), ``k4_amplitude`` (20°),
    ``horizontal_amplitude`` (90°); from ``[paper.constants]`` of the published table."""
    return paper_constant(PAPER, name)


def printed_number(claim_id: str) -> PrintedNumber:
    """The printed number of claim ``claim_id`` (value and the precision it was printed to)."""
    return load_paper_table(PAPER).claim(claim_id).number


def printed(claim_id: str) -> float:
    """The printed value of claim ``claim_id``: an intermediate the author's procedure reuses."""
    return float(printed_number(claim_id).value)


def check_example(
    speed: float | None,
    length: float | None,
    g: float | None,
    max_z0: float = MAX_Z0,
) -> tuple[float, float, float, float]:
    """(b, L, g, z0 = 2√(gL)/b) validated; ``None`` takes the paper's value."""
    b = real_in_range("speed", constant("speed") if speed is None else speed, *SPEED_RANGE, "m/s")
    a = real_in_range(
        "length", constant("length") if length is None else length, *LENGTH_RANGE, "m"
    )
    gg = real_in_range("g", constant("g") if g is None else g, *G_RANGE, "m/s²")
    z0 = 2.0 * math.sqrt(gg * a) / b
    if z0 > max_z0:
        raise PendcliError(
            f"speed: {b:g} m/s is too slow for length {a:g} m (2√(gL)/b = {z0:.3g} > {max_z0:g} "
            f"oscillation phases); expected speed >= {2 * math.sqrt(gg * a) / max_z0:.3g} m/s"
        )
    return b, a, gg, z0


# --- Lecornu's series (10) and (13), and k⁴ of (38) ------------------------------------------


def lecornu_series(order: int, x: float | Array) -> Array:
    """Lecornu's series in double precision, as printed, in the variable x = z²/4.

    order 1: eq. (10), φ(x) = Σ_(n>=1) (-1)^(n-1) n x^n/(n!)² = √x J_1(2√x);
    order 2: eq. (13), Σ_(k>=0) (-1)^k x^k/(k!(k+2)!) = J_2(2√x)/x.
    These are the ascending series of J_1 and J_2, summed by the numerics module.
    """
    return ascending_series(order, x)


def lecornu_k4(amplitude: float) -> float:
    """k⁴ = sin⁴(θ0/2), the order of the error Lecornu neglects in eq. (38) (θ0 in degrees)."""
    m, _ = modulus_squared(amplitude)
    return m * m


# --- the author's model: solution (10) -------------------------------------------------


@dataclass(frozen=True)
class ExampleModel:
    """Solution (10) of the shortening pendulum: elongations and vertical passages.

    Lengths l = (b²/4g) z² (eq. (16)) at the zeros z of J_2 (elongations) and J_1 (vertical
    passages); times t = (L - l)/b (the pendulum is L long at t = 0); amplitude at an
    elongation ∝ J_0(z) (since 2J_1(z)/z = J_0(z) where J_2 = 0), relative to the elongation
    nearest the release, and 1/J_0 at zero length (2J_1(z)/z → 1).
    """

    speed: float
    length: float
    g: float
    coefficient: float  # b²/(4g), eq. (16)
    elongation_z: Array  # zeros of J_2, descending (the order the pendulum meets them)
    elongation_lengths: Array
    elongation_times: Array
    j0_at_elongations: Array
    amplitude_ratios: Array  # θ/θ0 at each elongation; θ0 at the first one listed
    zero_length_time: float
    zero_length_ratio: float  # θ/θ0 in the limit l → 0
    intervals: Array  # between successive elongations, the last one up to l = 0
    passage_z: Array  # zeros of J_1, descending
    passage_lengths: Array
    passage_times: Array


def _listed_zeros(b: float, a: float, g: float, z_release: float) -> tuple[Array, Array]:
    """Zeros of J_2 from the one nearest z_release down, and of J_1 up to the next above it."""
    count = int(z_release / math.pi) + 3
    z2 = bessel_zeros(2, count)
    # Zeros are ~π apart: at most one lies within π/2 above z_release (the rounded-b case).
    if z2[0] > z_release + math.pi / 2:
        fastest = 2 * math.sqrt(g * a) / (z2[0] - math.pi / 2)
        raise PendcliError(
            f"speed: {b:g} m/s is too fast for length {a:g} m: solution (10) has no elongation "
            f"below the release; expected speed <= {fastest:.4g} m/s "
            "(see `pendcli lecornu zero-length` for fast shortening)"
        )
    first = int(np.argmin(np.abs(z2 - z_release)))
    ze = z2[: first + 1][::-1]
    z1 = bessel_zeros(1, count + 1)
    zp = z1[: int(np.searchsorted(z1, ze[0])) + 1][::-1]
    return ze, zp


def example_model(
    speed: float | None = None, length: float | None = None, g: float | None = None
) -> ExampleModel:
    """The author's example (eqs. (10), (15), (16)) for any speed b, initial length L and g.

    Listed: the elongations of (10) from the one nearest the release length L (the author
    chooses b so that L is one, then rounds b, so the nearest may lie a little above L) down
    to zero length, and every vertical passage below the next zero of J_1 above that
    elongation (the author lists the J_1 zeros up to 20, one of them before the release).
    A speed so fast that no elongation of (10) lies near or below L is refused.
    """
    from scipy.special import j0

    b, a, gg, z_release = check_example(speed, length, g)
    ze, zp = _listed_zeros(b, a, gg, z_release)
    coefficient = b * b / (4.0 * gg)
    le = coefficient * ze**2
    lp = coefficient * zp**2
    j0e = j0(ze)
    te = (a - le) / b
    return ExampleModel(
        speed=b,
        length=a,
        g=gg,
        coefficient=coefficient,
        elongation_z=ze,
        elongation_lengths=le,
        elongation_times=te,
        j0_at_elongations=j0e,
        amplitude_ratios=j0e / j0e[0],
        zero_length_time=a / b,
        zero_length_ratio=1.0 / j0e[0],
        intervals=np.diff(np.append(te, a / b)),
        passage_z=zp,
        passage_lengths=lp,
        passage_times=(a - lp) / b,
    )


# --- the fuller model: released from rest at length L -----------------------------------


def from_rest_cylinder(nu: int, z: Array, z0: float) -> Array:
    """Y_2(z0) J_ν(z) - J_2(z0) Y_ν(z): ν = 1 gives θ·z (up to a constant), ν = 2 gives dθ/dz.

    The cylinder function of the pendulum released from rest at z0 = 2√(gL)/b.
    """
    from scipy.special import jv, yv

    return np.asarray(yv(2, z0) * jv(nu, z) - jv(2, z0) * yv(nu, z), dtype=float)


def _bracketed_zeros(f: Callable[[Array], Array], grid: Array) -> Array:
    """All sign changes of f on the grid, each refined by vectorised bisection to full precision.

    Width 0.05 halved 64 times is below any ulp of z; once a halving moves no end (each
    bracket is two neighbouring floats, or a zero was hit), every later one computes the same
    midpoints and moves none either: the bisection stops there, with the ends 64 halvings
    give (about 45 halvings for z below 40, so a third fewer evaluations of f)."""
    values = f(grid)
    idx = np.nonzero(np.signbit(values[:-1]) != np.signbit(values[1:]))[0]
    lo, hi = grid[idx].copy(), grid[idx + 1].copy()
    flo = values[idx]
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        left = np.signbit(fm) == np.signbit(flo)
        new_lo, new_hi = np.where(left, mid, lo), np.where(left, hi, mid)
        if np.array_equal(new_lo, lo) and np.array_equal(new_hi, hi):
            break  # a fixed point: the remaining halvings change nothing
        lo, hi, flo = new_lo, new_hi, np.where(left, fm, flo)
    return np.asarray(0.5 * (lo + hi), dtype=float)


@dataclass(frozen=True)
class FromRestModel:
    """Eq. (9) solved exactly for a pendulum released from rest at length L, shortening at b."""

    speed: float
    length: float
    g: float
    floor: float  # lowest length considered (m)
    elongation_lengths: Array  # the release (t = 0) first
    elongation_times: Array
    amplitude_ratios: Array  # θ/θ(0) at each elongation
    passage_lengths: Array
    passage_times: Array
    singular_weight: float  # J_2(z0)/Y_2(z0): 0 only when b is one of Lecornu's speeds


def _from_rest_zeros(z0: float, z_floor: float) -> tuple[Array, Array]:
    """Elongations (the release z0 first) and vertical passages between z_floor and z0."""
    grid = np.arange(z_floor, z0, 0.05)
    if grid.size < 2:
        grid = np.array([z_floor, z0])
    grid = grid[grid < z0 - 1e-3]  # z0 itself is a zero of the elongation function
    ze = (
        _bracketed_zeros(lambda z: from_rest_cylinder(2, z, z0), grid)[::-1]
        if grid.size > 1
        else np.empty(0)
    )
    zp = _bracketed_zeros(lambda z: from_rest_cylinder(1, z, z0), np.append(grid, z0))[::-1]
    return np.concatenate(([z0], ze)), zp


def from_rest_model(
    speed: float | None = None,
    length: float | None = None,
    g: float | None = None,
    floor_fraction: float = 1e-3,
) -> FromRestModel:
    """Released from rest at L: u = √x [Y_2(z0) J_1(z) - J_2(z0) Y_1(z)], z0 = 2√(gL)/b.

    dθ/dt = 0 at t = 0 fixes the combination (d(C_1(z)/z)/dz = -C_2(z)/z for any cylinder
    function); elongations are the zeros of Y_2(z0)J_2(z) - J_2(z0)Y_2(z) below z0, vertical
    passages those of Y_2(z0)J_1(z) - J_2(z0)Y_1(z). Unless J_2(z0) = 0 (Lecornu's condition)
    the Y_1 part makes θ grow like 1/l as l → 0, so everything stops at ``floor_fraction``·L.
    """
    from scipy.special import jv, yv

    b, a, gg, z0 = check_example(speed, length, g)
    frac = real_in_range("floor_fraction", floor_fraction, *FLOOR_RANGE)
    floor = frac * a
    ze, zp = _from_rest_zeros(z0, 2.0 * math.sqrt(gg * floor) / b)
    c = b * b / (4.0 * gg)
    theta = from_rest_cylinder(1, ze, z0) / ze
    le, lp = c * ze**2, c * zp**2
    le[0] = a  # the release: exactly L, t = 0 (c·z0² only rounds to it)
    return FromRestModel(
        speed=b,
        length=a,
        g=gg,
        floor=floor,
        elongation_lengths=le,
        elongation_times=(a - le) / b,
        amplitude_ratios=theta / theta[0],
        passage_lengths=lp,
        passage_times=(a - lp) / b,
        singular_weight=float(jv(2, z0) / yv(2, z0)),
    )


def theta_curves(m: ExampleModel, t: Array) -> tuple[Array, Array]:
    """θ/θ0 against t of solution (10) (θ0 at its first listed elongation) and of the motion
    released from rest at t = 0 (NaN before the release)."""
    from scipy.special import j1

    length = m.length - m.speed * t
    z = 2 * np.sqrt(m.g * length) / m.speed
    theta10 = 2 * j1(z) / z / m.j0_at_elongations[0]
    z0 = 2 * math.sqrt(m.g * m.length) / m.speed
    start = from_rest_cylinder(1, np.array([z0]), z0)[0] / z0
    with np.errstate(invalid="ignore"):
        theta_rest = np.where(t >= 0, from_rest_cylinder(1, z, z0) / z / start, np.nan)
    return np.asarray(theta10, dtype=float), theta_rest


# --- direct integration of eq. (3) ------------------------------------------------------


@dataclass(frozen=True)
class Integration:
    elongation_times: Array
    elongation_angles: Array  # θ at each elongation (radians), the release first
    passage_times: Array
    end_time: float
    end_length: float
    end_theta: float
    max_abs_theta: float


def _shortening_rhs(
    b: float, a: float, g: float, nonlinear: bool
) -> Callable[[float, Array], list[float]]:
    """Eq. (3) with l = a - bt as a first-order system in (θ, θ')."""
    force: Callable[[float], float] = math.sin if nonlinear else (lambda th: th)

    def rhs(t: float, y: Array) -> list[float]:
        return [y[1], (2.0 * b * y[1] - g * force(y[0])) / (a - b * t)]

    return rhs


def _elongation_event(t: float, y: Array) -> float:
    return float(y[1])


def _passage_event(t: float, y: Array) -> float:
    return float(y[0])


def integrate_shortening(
    speed: float | None,
    length: float | None,
    g: float | None,
    theta0: float,
    *,
    nonlinear: bool = False,
    rtol: float = 1e-10,
    floor_fraction: float = 1e-3,
    max_z0: float = MAX_Z0_ODE,
) -> Integration:
    """Eq. (3) with l = L - bt, from rest at θ0 (radians), up to l = floor_fraction·L.

    (L - bt) θ'' - 2b θ' + g sin θ = 0 (or g θ, the linear equation). The equation is singular
    at l = 0, hence the floor. Events: dθ/dt = 0 (elongations), θ = 0 (vertical passages).
    """
    from scipy.integrate import solve_ivp

    b, a, gg, _ = check_example(speed, length, g, max_z0=max_z0)
    th0 = real_in_range("theta0", theta0, 1e-12, math.pi - 1e-6, "rad")
    tol = real_in_range("rtol", rtol, 1e-13, 1e-3)
    frac = real_in_range("floor_fraction", floor_fraction, *FLOOR_RANGE)
    t_end = a * (1.0 - frac) / b
    sol = solve_ivp(
        _shortening_rhs(b, a, gg, nonlinear),
        (0.0, t_end),
        [th0, 0.0],
        method="DOP853",
        rtol=tol,
        atol=tol * th0 * 1e-3,
        events=(_elongation_event, _passage_event),
    )
    if sol.status != 0:
        raise PendcliError(f"integration of eq. (3) failed: {sol.message}")
    after_release = sol.t_events[0] > 1e-9 * t_end  # ω = 0 at t = 0 is prepended below
    return Integration(
        elongation_times=np.concatenate(([0.0], sol.t_events[0][after_release])),
        elongation_angles=np.concatenate(([th0], sol.y_events[0][:, 0][after_release])),
        passage_times=sol.t_events[1],
        end_time=float(sol.t[-1]),
        end_length=a - b * float(sol.t[-1]),
        end_theta=float(sol.y[0][-1]),
        max_abs_theta=float(np.max(np.abs(sol.y[0]))),
    )


def elongation_times(
    speed: float | None,
    length: float | None,
    g: float | None,
    method: str = "bessel",
    rtol: float = 1e-10,
    *,
    floor_fraction: float = 1e-3,
) -> Array:
    """Times (s) of the successive elongations of the shortening pendulum released from rest.

    Length ``length`` at t = 0, shortening at ``speed``, small oscillations (eq. (3) linear).
    ``"bessel"``: the exact solution of (9) (:func:`from_rest_model`; ``rtol`` unused, the
    zeros are found to full precision); ``"ode"``: solve_ivp on eq. (3) with events, tolerance
    ``rtol``. Both start with t = 0 and stop at the length ``floor_fraction``·length.
    """
    if method == "bessel":
        return from_rest_model(speed, length, g, floor_fraction).elongation_times
    if method == "ode":
        return integrate_shortening(
            speed, length, g, 1e-3, rtol=rtol, floor_fraction=floor_fraction
        ).elongation_times
    raise invalid_value("method", method, "one of bessel, ode")


# --- the constants -0,13, 3π/32 and 6,47 from the exact solution ---------------------------


@cache
def lengthening_from_vertical(p: float) -> tuple[float, float]:
    """τ_e, τ_1: elongation and next vertical passage, in units √(a/g), of the lengthening
    pendulum vertical at t = 0 (length a), p = b/√(ga); exact Bessel solution of (9).

    θ·z ∝ Y1(z0) J1(z) - J1(z0) Y1(z) with z = 2√(gl)/b; the elongation is the first zero of
    the same combination of J2, Y2 after z0, the next vertical passage that of J1, Y1. Double
    precision suffices: the roots are found to ~1e-15 relative, and the coefficients below
    divide by p² = 1e-6 at most, leaving ~1e-8 (checked against mpmath at 30 digits in tests).
    """
    from scipy.optimize import brentq
    from scipy.special import jv, yv

    z0 = 2.0 / p
    j1, y1 = jv(1, z0), yv(1, z0)
    # For z0 >= 500 the roots sit within 0.01 of z0 + π/2 and z0 + π (Hankel asymptotics).
    ze = brentq(lambda z: jv(2, z) * y1 - yv(2, z) * j1, z0 + 0.5, z0 + 2.6, xtol=1e-15 * z0)
    z1 = brentq(lambda z: jv(1, z) * y1 - yv(1, z) * j1, z0 + 2.0, z0 + 4.3, xtol=1e-15 * z0)
    return p * (ze - z0) * (ze + z0) / 4, p * (z1 - z0) * (z1 + z0) / 4


def half_oscillation_coefficient_exact(ps: Sequence[float] = EXTRAPOLATION_PS) -> float:
    """c in T = (π/2)√(l/g) + c b/g (vertical passage to elongation), from the exact solution."""
    vals = [(lengthening_from_vertical(p)[0] - math.pi / 2) / p for p in ps]
    return float(richardson(vals, ps))


def period_b2_coefficient_exact(ps: Sequence[float] = EXTRAPOLATION_PS) -> float:
    """c2 in t = π√(a/g) + π²b/(4g) + c2 b²/(g√(ag)) (printed 3π/32), from the exact solution."""
    vals = []
    for p in ps:
        tau = lengthening_from_vertical(p)[1]
        vals.append((tau - math.pi - math.pi**2 * p / 4) / p**2)
    return float(richardson(vals, ps))


def mean_pendulum_coefficient_exact(ps: Sequence[float] = EXTRAPOLATION_PS) -> float:
    """D in π√(l_mean/g) - t = D b²/(g√(ag)) (after (28)), from the exact solution."""
    vals = []
    for p in ps:
        tau = lengthening_from_vertical(p)[1]
        vals.append((math.pi * math.sqrt(1 + p * tau / 2) - tau) / p**2)
    return float(richardson(vals, ps))
