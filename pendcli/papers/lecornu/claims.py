"""Lecornu: the pendulum whose length varies in proportion to time, l = a + bt.

L. Lecornu, « Mémoire sur le pendule de longueur variable » (after the note of 15 January
1894 in the Comptes rendus; the OCR carries no journal header; seed 001_8a46a810516a7d16.txt).

Reproduced here, section II (small oscillations):

* eq. (9) x u'' + u = 0 with θl = u, l = (b²/g) x, whose solution bounded at zero length is
  φ = √x J_1(2√x) (series (10)); elongations where J_2(z) = 0 (eqs. (12)-(14), z = 2√x),
  vertical passages where J_1(z) = 0;
* the zeros (15) of J_2 below 20, the speeds √(g l/ξ) (ξ = z²/4) that make a 1 m pendulum
  follow (10), the coefficient b²/(4g) of (16) for b = 0,35 m/s, the lengths, times and
  intervals of the elongations, J_0 at the zeros of J_2, the successive deviations, the
  zeros of J_1 and their lengths, the bound (3,83)²/4;
* the constants -0,13 (time from a vertical passage to the next elongation) and 6,47
  (mean-pendulum comparison, after (28)), and k⁴ in section III.

Methods. The author's model (the linear equation, solution (10)) is done exactly with
scipy.special and :mod:`pendcli.numerics.besselzeros`; each derived table is also recomputed by the
author's own procedure from his printed, rounded intermediate values (given in the notes), so a
carried rounding can be told from a slip. Where a fuller model answers a question about a claim
it fills ``Recomputed.exact``:

* the example released from rest at 1 m with b = 0,35 m/s exactly (the author's words,
  « abandonné sans impulsion »): the general solution of (9), u ∝ √x [Y_2(z₀)J_1(z) -
  J_2(z₀)Y_1(z)], checked against solve_ivp on eq. (3);
* the coefficients -0,13 and 6,47 from the exact Bessel solution, extrapolated to b → 0.

Assumptions: g = 9.81 m/s² (not printed; Paris g is 9.809, see :data:`G_PARIS`); lengths in
metres, times in seconds; the example's pendulum is 1 m long at t = 0 and shortens at
0,35 m/s, so t = (1 - l)/b (the author's 2,86 s = 1/0,35 fixes this origin).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np

from pendcli.core.claims import Recomputed
from pendcli.core.errors import PendcliError
from pendcli.numerics.besselzeros import bessel_zeros, lecornu_series

__all__ = [
    "EXAMPLE_LENGTH",
    "EXAMPLE_SPEED",
    "G_PARIS",
    "ExampleModel",
    "G",
    "best_g",
    "elongation_times",
    "example_model",
    "example_rows",
    "figures",
    "from_rest_model",
    "g_sensitivity",
    "half_oscillation_coefficient_exact",
    "integrate_shortening",
    "mean_pendulum_coefficient_exact",
    "ode_check",
    "period_b2_coefficient_exact",
    "plot_example",
    "recompute",
    "series_cancellation",
    "zero_length_behaviour",
]

G = 9.81  # m/s²: not printed by Lecornu; the usual value of his time, close to Paris's
# Paris (48°50' N, ~60 m): international gravity formula 1930 minus the free-air term.
G_PARIS = (
    9.780490
    * (
        1
        + 0.0052884 * math.sin(math.radians(48.836)) ** 2
        - 0.0000059 * math.sin(math.radians(2 * 48.836)) ** 2
    )
    - 3.086e-6 * 60
)
EXAMPLE_SPEED = 0.35  # m/s, « Adoptons, par exemple, 0^m,35 »
EXAMPLE_LENGTH = 1.0  # m, « un pendule ayant un mètre de longueur à l'instant initial »
TABLE_LIMIT = 20.0  # « de 0 à 20 (les tables ne vont pas plus loin) »

SPEED_RANGE = (1e-3, 1e3)  # m/s
LENGTH_RANGE = (1e-3, 1e3)  # m
G_RANGE = (0.1, 100.0)  # m/s²
MAX_Z0 = 2.0e4  # 2√(gL)/b: about 6000 oscillations; beyond, lists get silly and slow
MAX_Z0_ODE = 1.0e3  # the ODE method integrates every oscillation: keep it to ~300
FLOOR_RANGE = (1e-9, 0.5)  # length floor as a fraction of the initial length


# --- input checks -----------------------------------------------------------------------


def _real(name: str, value: object, lo: float, hi: float, unit: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise PendcliError(
            f"{name} must be a real number in [{lo:g}, {hi:g}] {unit}, got {value!r}"
        )
    v = float(value)
    if not math.isfinite(v) or not lo <= v <= hi:
        raise PendcliError(
            f"{name} = {v!r} is out of range; valid range is {lo:g} <= {name} <= {hi:g} {unit}"
        )
    return v


def _check_example(speed: float, length: float, g: float, max_z0: float = MAX_Z0):
    b = _real("speed", speed, *SPEED_RANGE, "m/s")
    a = _real("length", length, *LENGTH_RANGE, "m")
    gg = _real("g", g, *G_RANGE, "m/s²")
    z0 = 2.0 * math.sqrt(gg * a) / b
    if z0 > max_z0:
        raise PendcliError(
            f"speed = {b:g} m/s is too slow for length {a:g} m (2√(gL)/b = {z0:.3g} > {max_z0:g} "
            f"oscillation phases); valid range is speed >= {2 * math.sqrt(gg * a) / max_z0:.3g} m/s"
        )
    return b, a, gg, z0


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
    elongation_z: np.ndarray  # zeros of J_2, descending (the order the pendulum meets them)
    elongation_lengths: np.ndarray
    elongation_times: np.ndarray
    j0_at_elongations: np.ndarray
    amplitude_ratios: np.ndarray  # θ/θ0 at each elongation; θ0 at the first one listed
    zero_length_time: float
    zero_length_ratio: float  # θ/θ0 in the limit l → 0
    intervals: np.ndarray  # between successive elongations, the last one up to l = 0
    passage_z: np.ndarray  # zeros of J_1, descending
    passage_lengths: np.ndarray
    passage_times: np.ndarray


def example_model(
    speed: float = EXAMPLE_SPEED, length: float = EXAMPLE_LENGTH, g: float = G
) -> ExampleModel:
    """The author's example (eqs. (10), (15), (16)) for any speed b, initial length L and g.

    Listed: the elongations of (10) from the one nearest the release length L (the author
    chooses b so that L is one, then rounds b, so the nearest may lie a little above L) down
    to zero length, and every vertical passage below the next zero of J_1 above that
    elongation (the author lists the J_1 zeros up to 20, one of them before the release).
    A speed so fast that no elongation of (10) lies near or below L is refused.
    """
    from scipy.special import j0

    b, a, gg, z_release = _check_example(speed, length, g)
    count = int(z_release / math.pi) + 3
    z2 = bessel_zeros(2, count)
    # Zeros are ~π apart: at most one lies within π/2 above z_release (the rounded-b case).
    if z2[0] > z_release + math.pi / 2:
        fastest = 2 * math.sqrt(gg * a) / (z2[0] - math.pi / 2)
        raise PendcliError(
            f"speed = {b:g} m/s is too fast for length {a:g} m: solution (10) has no elongation "
            f"below the release; valid range is speed <= {fastest:.4g} m/s "
            "(see `pendcli lecornu zero-length` for fast shortening)"
        )
    first = int(np.argmin(np.abs(z2 - z_release)))
    ze = z2[: first + 1][::-1]
    z1 = bessel_zeros(1, count + 1)
    zp = z1[: int(np.searchsorted(z1, ze[0])) + 1][::-1]
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


def _cross(nu: int, z: np.ndarray, z0: float) -> np.ndarray:
    """Y_2(z0) J_ν(z) - J_2(z0) Y_ν(z): ν = 1 gives θ·z (up to a constant), ν = 2 gives dθ/dz."""
    from scipy.special import jv, yv

    return yv(2, z0) * jv(nu, z) - jv(2, z0) * yv(nu, z)


def _bracketed_zeros(f, grid: np.ndarray) -> np.ndarray:
    """All sign changes of f on the grid, each refined by vectorised bisection to full precision."""
    values = f(grid)
    idx = np.nonzero(np.signbit(values[:-1]) != np.signbit(values[1:]))[0]
    lo, hi = grid[idx].copy(), grid[idx + 1].copy()
    flo = values[idx]
    for _ in range(64):  # width 0.05 halved 64 times is below any ulp of z
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        left = np.signbit(fm) == np.signbit(flo)
        lo = np.where(left, mid, lo)
        flo = np.where(left, fm, flo)
        hi = np.where(left, hi, mid)
    return 0.5 * (lo + hi)


@dataclass(frozen=True)
class FromRestModel:
    """Eq. (9) solved exactly for a pendulum released from rest at length L, shortening at b."""

    speed: float
    length: float
    g: float
    floor: float  # lowest length considered (m)
    elongation_lengths: np.ndarray  # the release (t = 0) first
    elongation_times: np.ndarray
    amplitude_ratios: np.ndarray  # θ/θ(0) at each elongation
    passage_lengths: np.ndarray
    passage_times: np.ndarray
    singular_weight: float  # J_2(z0)/Y_2(z0): 0 only when b is one of Lecornu's speeds


def from_rest_model(
    speed: float = EXAMPLE_SPEED,
    length: float = EXAMPLE_LENGTH,
    g: float = G,
    floor_fraction: float = 1e-3,
) -> FromRestModel:
    """Released from rest at L: u = √x [Y_2(z0) J_1(z) - J_2(z0) Y_1(z)], z0 = 2√(gL)/b.

    dθ/dt = 0 at t = 0 fixes the combination (d(C_1(z)/z)/dz = -C_2(z)/z for any cylinder
    function); elongations are the zeros of Y_2(z0)J_2(z) - J_2(z0)Y_2(z) below z0, vertical
    passages those of Y_2(z0)J_1(z) - J_2(z0)Y_1(z). Unless J_2(z0) = 0 (Lecornu's condition)
    the Y_1 part makes θ grow like 1/l as l → 0, so everything stops at ``floor_fraction``·L.
    """
    b, a, gg, z0 = _check_example(speed, length, g)
    frac = _real("floor_fraction", floor_fraction, *FLOOR_RANGE, "")
    floor = frac * a
    z_floor = 2.0 * math.sqrt(gg * floor) / b
    grid = np.arange(z_floor, z0, 0.05)
    if grid.size < 2:
        grid = np.array([z_floor, z0])
    grid = grid[grid < z0 - 1e-3]  # z0 itself is a zero of the elongation function
    ze = _bracketed_zeros(lambda z: _cross(2, z, z0), grid)[::-1] if grid.size > 1 else np.empty(0)
    zp = _bracketed_zeros(lambda z: _cross(1, z, z0), np.append(grid, z0))[::-1]
    ze = np.concatenate(([z0], ze))
    c = b * b / (4.0 * gg)
    theta = _cross(1, ze, z0) / ze
    le, lp = c * ze**2, c * zp**2
    le[0] = a  # the release: exactly L, t = 0 (c·z0² only rounds to it)
    from scipy.special import jv, yv

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


# --- direct integration of eq. (3) ------------------------------------------------------


@dataclass(frozen=True)
class Integration:
    elongation_times: np.ndarray
    elongation_angles: np.ndarray  # θ at each elongation (radians), the release first
    passage_times: np.ndarray
    end_time: float
    end_length: float
    end_theta: float
    max_abs_theta: float


def integrate_shortening(
    speed: float,
    length: float,
    g: float,
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

    b, a, gg, _ = _check_example(speed, length, g, max_z0=max_z0)
    th0 = _real("theta0", theta0, 1e-12, math.pi - 1e-6, "rad")
    tol = _real("rtol", rtol, 1e-13, 1e-3, "")
    frac = _real("floor_fraction", floor_fraction, *FLOOR_RANGE, "")
    t_end = a * (1.0 - frac) / b
    force = math.sin if nonlinear else (lambda th: th)

    def rhs(t, y):
        return [y[1], (2.0 * b * y[1] - gg * force(y[0])) / (a - b * t)]

    def elongation(t, y):
        return y[1]

    def passage(t, y):
        return y[0]

    sol = solve_ivp(
        rhs,
        (0.0, t_end),
        [th0, 0.0],
        method="DOP853",
        rtol=tol,
        atol=tol * th0 * 1e-3,
        events=(elongation, passage),
    )
    if sol.status != 0:
        raise PendcliError(f"integration of eq. (3) failed: {sol.message}")
    te = sol.t_events[0]
    te = te[te > 1e-9 * t_end]  # the release itself (ω = 0 at t = 0) is prepended below
    angles = sol.y_events[0][: len(sol.t_events[0])][:, 0][sol.t_events[0] > 1e-9 * t_end]
    return Integration(
        elongation_times=np.concatenate(([0.0], te)),
        elongation_angles=np.concatenate(([th0], angles)),
        passage_times=sol.t_events[1],
        end_time=float(sol.t[-1]),
        end_length=a - b * float(sol.t[-1]),
        end_theta=float(sol.y[0][-1]),
        max_abs_theta=float(np.max(np.abs(sol.y[0]))),
    )


def elongation_times(
    speed: float,
    length: float,
    g: float,
    method: str = "bessel",
    rtol: float = 1e-10,
    *,
    floor_fraction: float = 1e-3,
) -> np.ndarray:
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
    raise PendcliError(f"method {method!r} is unknown; choose one of bessel, ode")


def ode_check(
    speed: float = EXAMPLE_SPEED,
    length: float = EXAMPLE_LENGTH,
    g: float = G,
    amplitudes_deg: tuple[float, ...] = (1.0, 5.0),
    floor_fraction: float = 0.02,
) -> list[dict]:
    """Bessel elongation times against solve_ivp (linear, and sin θ at the given amplitudes)."""
    bessel = from_rest_model(speed, length, g, floor_fraction)
    linear = integrate_shortening(speed, length, g, 1e-3, rtol=1e-11, floor_fraction=floor_fraction)
    nonlinear = {
        amp: integrate_shortening(
            speed,
            length,
            g,
            math.radians(amp),
            nonlinear=True,
            rtol=1e-11,
            floor_fraction=floor_fraction,
        )
        for amp in amplitudes_deg
    }
    rows = []
    n = min(len(bessel.elongation_times), len(linear.elongation_times))
    for k in range(n):
        row = {
            "k": k,
            "length_m": float(bessel.elongation_lengths[k]),
            "t_bessel_s": float(bessel.elongation_times[k]),
            "t_ode_linear_s": float(linear.elongation_times[k]),
            "linear_minus_bessel_s": float(linear.elongation_times[k] - bessel.elongation_times[k]),
            "ratio_bessel": float(bessel.amplitude_ratios[k]),
            "ratio_ode_linear": float(linear.elongation_angles[k] / linear.elongation_angles[0]),
        }
        for amp, res in nonlinear.items():
            shift = (
                float(res.elongation_times[k] - bessel.elongation_times[k])
                if k < len(res.elongation_times)
                else None
            )
            row[f"sin_shift_{amp:g}deg_s"] = shift
            row[f"theta_{amp:g}deg_at_elongation_deg"] = (
                float(np.degrees(res.elongation_angles[k]))
                if k < len(res.elongation_angles)
                else None
            )
        rows.append(row)
    return rows


def zero_length_behaviour(
    speed: float = EXAMPLE_SPEED,
    length: float = EXAMPLE_LENGTH,
    g: float = G,
    floors: tuple[float, ...] = (1e-2, 1e-3, 1e-4, 1e-5, 1e-6),
) -> list[dict]:
    """|θ|max/θ0 of the linear motion from rest as the length floor goes to 0, ODE and Bessel.

    For a speed other than Lecornu's (J_2(z0) ≠ 0) the Y_1 part of the solution grows like
    1/l: the ratio times the floor tends to a constant. At l → 0 the linear model itself has
    no meaning (the author's remark after (17)); this shows how fast it leaves it.
    """
    from scipy.special import jv, yv

    b, a, gg, z0 = _check_example(speed, length, g, max_z0=MAX_Z0_ODE)
    rows = []
    for frac in floors:
        res = integrate_shortening(b, a, gg, 1e-6, rtol=1e-10, floor_fraction=frac)
        z = 2.0 * math.sqrt(gg * frac * a) / b
        theta_end = (yv(2, z0) * jv(1, z) - jv(2, z0) * yv(1, z)) / z
        theta_start = (yv(2, z0) * jv(1, z0) - jv(2, z0) * yv(1, z0)) / z0
        rows.append(
            {
                "floor_m": frac * a,
                "max_ratio_ode": res.max_abs_theta / 1e-6,
                "end_ratio_ode": abs(res.end_theta) / 1e-6,
                "end_ratio_bessel": float(abs(theta_end / theta_start)),
                "end_ratio_times_length": float(abs(theta_end / theta_start)) * frac * a,
            }
        )
    return rows


# --- the constants -0,13 and 6,47 from the exact solution -------------------------------


@cache
def _lengthening_from_vertical(p: float) -> tuple[float, float]:
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


def _richardson(values, ps):
    """Extrapolate f(p) = f0 + f1 p + f2 p² + ... to p = 0 from p, p/2, p/4."""
    f1, f2, f3 = values
    r1, r2 = 2 * f2 - f1, 2 * f3 - f2
    return (4 * r2 - r1) / 3


def half_oscillation_coefficient_exact(ps=(0.004, 0.002, 0.001)) -> float:
    """c in T = (π/2)√(l/g) + c b/g (vertical passage to elongation), from the exact solution."""
    vals = [(_lengthening_from_vertical(p)[0] - math.pi / 2) / p for p in ps]
    return float(_richardson(vals, ps))


def period_b2_coefficient_exact(ps=(0.004, 0.002, 0.001)) -> float:
    """c2 in t = π√(a/g) + π²b/(4g) + c2 b²/(g√(ag)) (printed 3π/32), from the exact solution."""
    vals = []
    for p in ps:
        tau = _lengthening_from_vertical(p)[1]
        vals.append((tau - math.pi - math.pi**2 * p / 4) / p**2)
    return float(_richardson(vals, ps))


def mean_pendulum_coefficient_exact(ps=(0.004, 0.002, 0.001)) -> float:
    """D in π√(l_mean/g) - t = D b²/(g√(ag)) (after (28)), from the exact solution."""
    vals = []
    for p in ps:
        tau = _lengthening_from_vertical(p)[1]
        vals.append((math.pi * math.sqrt(1 + p * tau / 2) - tau) / p**2)
    return float(_richardson(vals, ps))


# --- Lecornu's series in double precision ------------------------------------------------


def series_cancellation(zs=(2, 5, 10, 15, 20, 25, 30, 35, 40)) -> list[dict]:
    """J_1 and J_2 from Lecornu's series (10)/(13) in double precision against mpmath."""
    import mpmath as mp

    from pendcli.numerics.besselzeros import series_error_bound

    rows = []
    with mp.workdps(40):
        for z in zs:
            x = z * z / 4.0
            for order in (1, 2):
                s = float(lecornu_series(order, x))
                value = s * 2 / z if order == 1 else s * x  # J_1 = 2φ/z, J_2 = x·(13)
                exact = mp.besselj(order, z)
                rows.append(
                    {
                        "order": order,
                        "z": float(z),
                        "series": value,
                        "mpmath": float(exact),
                        "abs_error_of_J": float(abs(value - exact)),
                        "sum_abs_terms_I": float(mp.besseli(order, z)),
                        "zero_error_bound": float(series_error_bound(order, float(z))),
                    }
                )
    return rows


# --- g ------------------------------------------------------------------------------------


def _g_dependent_ids() -> list[str]:
    ids = [f"lecornu.speed.{k}" for k in range(1, 6)]
    ids += ["lecornu.coefficient_b2_4g"]
    ids += [f"lecornu.example.length.{k}" for k in range(1, 6)]
    ids += [f"lecornu.example.time.{k}" for k in range(1, 6)]
    ids += [f"lecornu.example.interval.{k}" for k in range(1, 6)]
    ids += [f"lecornu.j1_lengths.{k}" for k in range(1, 7)]
    return ids


def _g_values(g: float) -> dict[str, float]:
    m = example_model(EXAMPLE_SPEED, EXAMPLE_LENGTH, g)
    z2 = bessel_zeros(2, 5)
    out = {f"lecornu.speed.{k + 1}": 2 * math.sqrt(g * EXAMPLE_LENGTH) / z2[k] for k in range(5)}
    out["lecornu.coefficient_b2_4g"] = m.coefficient
    for k in range(5):
        out[f"lecornu.example.length.{k + 1}"] = float(m.elongation_lengths[k])
        out[f"lecornu.example.time.{k + 1}"] = float(m.elongation_times[k])
        out[f"lecornu.example.interval.{k + 1}"] = float(m.intervals[k])
    for k in range(6):
        out[f"lecornu.j1_lengths.{k + 1}"] = float(m.passage_lengths[k])
    return out


def g_sensitivity(gs=(9.78, 9.80, G_PARIS, 9.81, 9.83)) -> list[dict]:
    """Each g-dependent claim recomputed at several g, with its verdict and d(value)/dg."""
    from pendcli.core.tables import load_paper_table
    from pendcli.core.verdict import judge

    table = {c.id: c for c in load_paper_table("lecornu").claims}
    per_g = {g: _g_values(g) for g in gs}
    h = 1e-4
    up, down = _g_values(G + h), _g_values(G - h)
    rows = []
    for cid in _g_dependent_ids():
        entry = table[cid]
        row = {
            "id": cid,
            "published": entry.published,
            "d_value_dg": (up[cid] - down[cid]) / (2 * h),
        }
        for g in gs:
            v = per_g[g][cid]
            row[f"g={g:.4f}"] = v
            row[f"verdict g={g:.4f}"] = judge(entry.number, v, entry.comparison).verdict.value
        rows.append(row)
    return rows


def best_g(lo: float = 9.70, hi: float = 9.90, step: float = 0.0005) -> dict:
    """The g that best reproduces the g-dependent printed figures (not used for verdicts).

    Score: Σ ((recomputed - printed)/u)² over the g-dependent claims, u the printed last
    unit; also the g range where the most claims agree.
    """
    from pendcli.core.tables import load_paper_table
    from pendcli.core.verdict import Verdict, judge

    table = {c.id: c for c in load_paper_table("lecornu").claims}
    ids = _g_dependent_ids()
    gs = np.round(np.arange(lo, hi + step / 2, step), 6)
    scores, agree = [], []
    for g in gs:
        vals = _g_values(float(g))
        scores.append(
            sum(((vals[i] - table[i].number.value) / table[i].number.resolution) ** 2 for i in ids)
        )
        agree.append(sum(judge(table[i].number, vals[i]).verdict is Verdict.AGREES for i in ids))
    scores, agree = np.array(scores), np.array(agree)
    best = int(np.argmin(scores))
    most = agree.max()
    where = gs[agree == most]
    return {
        "best_g_least_squares": float(gs[best]),
        "score_at_best": float(scores[best]),
        "score_at_9.81": float(
            sum(
                ((_g_values(G)[i] - table[i].number.value) / table[i].number.resolution) ** 2
                for i in ids
            )
        ),
        "most_agreeing": int(most),
        "of": len(ids),
        "g_range_most_agreeing": (float(where.min()), float(where.max())),
        "agreeing_at_9.81": int(
            sum(judge(table[i].number, _g_values(G)[i]).verdict is Verdict.AGREES for i in ids)
        ),
    }


# --- the claims -------------------------------------------------------------------------


def _fmt(v: float, nd: int = 4) -> str:
    return f"{v:.{nd}f}"


def _chop(v: float, decimals: int) -> float:
    f = 10.0**decimals
    return math.copysign(math.floor(abs(v) * f + 1e-9) / f, v)


def _printed_values(prefix: str, count: int) -> np.ndarray:
    """The printed values of claims ``prefix1..prefixN`` (or ``prefix`` alone), in table order."""
    from pendcli.core.tables import load_paper_table

    claims = {c.id: c.number.value for c in load_paper_table("lecornu").claims}
    ids = (
        [prefix]
        if count == 1 and prefix in claims
        else [f"{prefix}{k}" for k in range(1, count + 1)]
    )
    return np.array([claims[i] for i in ids])


def recompute(g: float = G) -> dict[str, Recomputed]:
    """Every printed number of section II (and k⁴ of III), recomputed; see the module doc."""
    from scipy.special import j0

    out: dict[str, Recomputed] = {}
    z2 = bessel_zeros(2, 6)
    z1 = bessel_zeros(1, 7)
    # His printed intermediates, read from the published table, for "the author's procedure".
    printed_z2 = _printed_values("lecornu.j2_zeros.", 5)  # (15)
    printed_z1 = _printed_values("lecornu.j1_zeros.", 6)
    printed_coefficient = _printed_values("lecornu.coefficient_b2_4g", 1)[0]  # 0,00313
    b = EXAMPLE_SPEED
    # The printed example has five elongations: the release (1 m, b = 0,35) must stay nearest
    # the fifth zero of J2, i.e. 2√g/b between the midpoints around j_(2,5).
    g_low = (b * (z2[3] + z2[4]) / 4) ** 2
    g_high = (b * (z2[4] + z2[5]) / 4) ** 2
    if not (isinstance(g, (int, float)) and math.isfinite(g) and g_low < g < g_high):
        raise PendcliError(
            f"g = {g!r} m/s² changes the structure of the printed example (no longer five "
            f"elongations from 1 m at 0,35 m/s); valid range for the claims is "
            f"{g_low:.3f} < g < {g_high:.3f}"
        )

    out["lecornu.j2_zeros.count_below_20"] = Recomputed(
        float(np.sum(z2 < TABLE_LIMIT)),
        method="zeros of J_2 (pendcli.numerics.besselzeros, auto) below 20",
        note=f"The sixth zero is {z2[5]:.4f}, just beyond the table's end.",
    )
    for k in range(5):
        z = float(z2[k])
        out[f"lecornu.j2_zeros.{k + 1}"] = Recomputed(
            z,
            method="j_(2,k), correctly rounded (mpmath head of bessel_zeros)",
            note=f"Exact {z:.5f}: rounded {round(z, 2):.2f}, truncated {_chop(z, 2):.2f}.",
        )
    for k in range(5):
        v = 2 * math.sqrt(g * EXAMPLE_LENGTH) / z2[k]
        vp = 2 * math.sqrt(g * EXAMPLE_LENGTH) / printed_z2[k]
        out[f"lecornu.speed.{k + 1}"] = Recomputed(
            float(v),
            method="√(g l/ξ), ξ = z²/4, l = 1 m: 2√g/j_(2,k)",
            note=f"Author's procedure (printed z) gives {vp:.4f}.",
        )
    coef = b * b / (4 * g)
    out["lecornu.coefficient_b2_4g"] = Recomputed(
        coef,
        method="b²/(4g), b = 0,35 m/s",
        note=(
            f"Rounds to 0,00313 only if g <= {b * b / (4 * 0.003125):.3f} "
            f"(g = 9.80 gives exactly 0,003125); with g = {g:g} it is {coef:.6f}."
        ),
    )

    m = example_model(b, EXAMPLE_LENGTH, g)
    rest = from_rest_model(b, EXAMPLE_LENGTH, g, floor_fraction=1e-3)
    printed_lengths = _printed_values("lecornu.example.length.", 5)
    author_len = printed_coefficient * printed_z2[::-1] ** 2
    author_times = (1.0 - printed_lengths) / b
    for k in range(5):
        out[f"lecornu.example.length.{k + 1}"] = Recomputed(
            float(m.elongation_lengths[k]),
            exact=float(rest.elongation_lengths[k]) if k < len(rest.elongation_lengths) else None,
            method="(b²/4g) j_(2,k)², b = 0,35 m/s (eq. (16))",
            note=(
                f"Author's procedure 0,00313·z² (printed z) gives {author_len[k]:.4f}; "
                f"with l = (z/17,96)² (1 m at the first elongation) "
                f"{(printed_z2[::-1][k] / printed_z2[-1]) ** 2:.4f}."
            ),
        )
    for k in range(5):
        out[f"lecornu.example.time.{k + 1}"] = Recomputed(
            float(m.elongation_times[k]),
            exact=float(rest.elongation_times[k]) if k < len(rest.elongation_times) else None,
            method="(1 m - l_k)/b, b = 0,35 m/s",
            note=f"Author's procedure (1 - printed l)/0,35 gives {author_times[k]:.4f}.",
        )
    out["lecornu.example.time_zero_length"] = Recomputed(
        m.zero_length_time,
        method="1 m / b",
        note=(
            "With the exact speed that makes 1 m an elongation, "
            f"b = 2√g/j_(2,5) = {2 * math.sqrt(g) / z2[4]:.5f} m/s, it would be "
            f"{z2[4] / (2 * math.sqrt(g)):.4f} s."
        ),
    )
    author_intervals = np.diff(np.append(author_times, 1.0 / b))
    rest_intervals = np.diff(rest.elongation_times)
    for k in range(5):
        out[f"lecornu.example.interval.{k + 1}"] = Recomputed(
            float(m.intervals[k]),
            exact=float(rest_intervals[k]) if k < 4 and k < len(rest_intervals) else None,
            method="differences of the elongation times, the last up to l = 0",
            note=f"Differences of his own (printed-length) times give {author_intervals[k]:.4f}.",
        )

    printed_j0 = _printed_values("lecornu.j0_at_j2_zeros.", 5)
    for k in range(5):
        out[f"lecornu.j0_at_j2_zeros.{k + 1}"] = Recomputed(
            float(j0(z2[k])),
            method="J_0(j_(2,k)) (scipy.special.j0)",
            note=f"J_0 at the printed z = {printed_z2[k]:.2f} is {float(j0(printed_z2[k])):.5f}.",
        )
    # Printed deviations -1,27 ... +6,19 correspond to z = 14,80 ... 5,14; θ0 at z = 17,96.
    for k, zi in enumerate((3, 2, 1, 0)):
        lo = abs(printed_j0[zi]) - 0.0005
        hi = abs(printed_j0[zi]) + 0.0005
        out[f"lecornu.deviation.{k + 2}"] = Recomputed(
            float(j0(z2[zi]) / j0(z2[4])),
            exact=float(rest.amplitude_ratios[k + 1])
            if k + 1 < len(rest.amplitude_ratios)
            else None,
            method="J_0(j_(2,k))/J_0(j_(2,5))",
            note=(
                "Author's procedure, ratio of his printed J_0: "
                f"{printed_j0[zi] / printed_j0[4]:.3f}; "
                f"his 3-decimal J_0 allow |ratio| in [{lo / 0.0215:.2f}, {hi / 0.0205:.2f}]."
            ),
        )
    # At x = 1e-20 the next term of φ(x)/x, -x/2, is far below double precision: the limit.
    limit = float(lecornu_series(1, 1e-20) / 1e-20)
    out["lecornu.deviation.zero_length"] = Recomputed(
        float(limit / j0(z2[4])),
        method="lim 2J_1(z)/z = 1 over J_0(j_(2,5))",
        note=(
            f"Author's procedure 1/({printed_j0[4]:+.3f}) = {1 / printed_j0[4]:.2f}. "
            "Released from rest at 1 m with "
            "b = 0,35 m/s exactly (not the speed 2√g/j_(2,5) = "
            f"{2 * math.sqrt(g) / z2[4]:.5f} that satisfies his condition) the solution has a "
            f"Y_1 part (weight J_2(z0)/Y_2(z0) = {rest.singular_weight:.2e}) and θ grows like "
            "1/l: no finite limit."
        ),
    )
    out["lecornu.limit_2j1_over_z"] = Recomputed(
        limit,
        method="φ(x)/x from series (10) at x = 1e-20 (= 2J_1(z)/z, z → 0)",
    )
    for k in range(6):
        z = float(z1[5 - k])
        out[f"lecornu.j1_zeros.{k + 1}"] = Recomputed(
            z,
            method="j_(1,k), correctly rounded",
            note=f"Exact {z:.5f}: rounded {round(z, 2):.2f}, truncated {_chop(z, 2):.2f}.",
        )
    author_j1_len = printed_coefficient * printed_z1**2
    for k in range(6):
        out[f"lecornu.j1_lengths.{k + 1}"] = Recomputed(
            float(m.passage_lengths[k]),
            method="(b²/4g) j_(1,k)², b = 0,35 m/s (eq. (16))",
            note=f"Author's procedure 0,00313·z² (printed z) gives {author_j1_len[k]:.4f}.",
        )
    out["lecornu.x_bound"] = Recomputed(
        float(z1[0] ** 2 / 4),
        method="j_(1,1)²/4",
        note=f"From the printed 3,83: 3,83²/4 = {3.83**2 / 4:.5f}.",
    )
    c_half = (math.pi**2 - 12) / 16
    out["lecornu.half_oscillation_coefficient"] = Recomputed(
        c_half,
        exact=half_oscillation_coefficient_exact(),
        method="(π² - 12)/16, the printed expression",
        note="The exact column: the exact Bessel solution, time from a vertical passage to the "
        "next elongation, extrapolated to b → 0.",
    )
    d_printed = math.pi * (7 * math.pi**2 - 3) / 32
    d_exact = mean_pendulum_coefficient_exact()
    out["lecornu.mean_pendulum_coefficient"] = Recomputed(
        d_printed,
        exact=d_exact,
        method="π(7π² - 3)/32, the printed expression",
        note=(
            f"The printed expression is {d_printed:.4f}. The exact solution extrapolated to "
            f"b → 0 gives {d_exact:.4f} = π(π² - 3)/32 = {math.pi * (math.pi**2 - 3) / 32:.4f}: "
            "the expansion of π√(l/g) has π³/32, not 7π³/32, in its b² term. His period's "
            f"3π/32 = {3 * math.pi / 32:.5f} is right (exact solution: "
            f"{period_b2_coefficient_exact():.5f})."
        ),
    )
    out["lecornu.k4.theta20"] = Recomputed(
        math.sin(math.radians(20) / 2) ** 4, method="sin⁴(θ0/2), θ0 = 20°"
    )
    out["lecornu.k4.theta20_below_one_thousandth"] = Recomputed(
        math.sin(math.radians(20) / 2) ** 4, method="sin⁴(θ0/2), θ0 = 20°, against the bound"
    )
    out["lecornu.k4.swing180"] = Recomputed(
        math.sin(math.radians(90) / 2) ** 4,
        method="sin⁴(θ0/2), θ0 = 90° (a swing of 180°, to the horizontal)",
    )
    return out


# --- example tables and plots ---------------------------------------------------------------


def example_rows(
    speed: float = EXAMPLE_SPEED, length: float = EXAMPLE_LENGTH, g: float = G
) -> tuple[list[dict], list[dict], list[dict]]:
    """Rows for `pendcli lecornu example`: elongations, vertical passages, summary."""
    m = example_model(speed, length, g)
    rest = from_rest_model(speed, length, g)
    elong = []
    for k in range(len(m.elongation_z)):
        row = {
            "k": k + 1,
            "z": float(m.elongation_z[k]),
            "length_m": float(m.elongation_lengths[k]),
            "time_s": float(m.elongation_times[k]),
            "j0": float(m.j0_at_elongations[k]),
            "ratio": float(m.amplitude_ratios[k]),
            "from_rest_length_m": None,
            "from_rest_time_s": None,
            "from_rest_ratio": None,
        }
        if k < len(rest.elongation_times):
            row["from_rest_length_m"] = float(rest.elongation_lengths[k])
            row["from_rest_time_s"] = float(rest.elongation_times[k])
            row["from_rest_ratio"] = float(rest.amplitude_ratios[k])
        elong.append(row)
    passages = []
    rest_after = rest.passage_times
    for k in range(len(m.passage_z)):
        t = float(m.passage_times[k])
        # the from-rest passage matching this one: same order counted from the release
        j = k - int(np.sum(m.passage_times < 0))
        passages.append(
            {
                "k": k + 1,
                "z": float(m.passage_z[k]),
                "length_m": float(m.passage_lengths[k]),
                "time_s": t,
                "from_rest_time_s": float(rest_after[j]) if 0 <= j < len(rest_after) else None,
            }
        )
    summary = [
        {"quantity": "b²/(4g), eq. (16)", "value": m.coefficient, "unit": "m"},
        {"quantity": "time at zero length L/b", "value": m.zero_length_time, "unit": "s"},
        {
            "quantity": "θ/θ0 at zero length, solution (10)",
            "value": m.zero_length_ratio,
            "unit": "",
        },
        {
            "quantity": "speed making L an elongation, 2√(gL)/j_2 nearest",
            "value": 2 * math.sqrt(m.g * m.length) / float(m.elongation_z[0]),
            "unit": "m/s",
        },
        {
            "quantity": "from rest: weight of the singular part J_2(z0)/Y_2(z0)",
            "value": rest.singular_weight,
            "unit": "",
        },
        {
            "quantity": "from rest: elongations listed down to the floor",
            "value": rest.floor,
            "unit": "m",
        },
    ]
    return elong, passages, summary


def _theta_curves(m: ExampleModel, rest: FromRestModel, t: np.ndarray):
    """θ/θ0 of solution (10) (θ0 at its first listed elongation) and of the from-rest motion."""
    from scipy.special import j1

    length = m.length - m.speed * t
    z = 2 * np.sqrt(m.g * length) / m.speed
    theta10 = 2 * j1(z) / z / m.j0_at_elongations[0]
    z0 = 2 * math.sqrt(m.g * m.length) / m.speed
    with np.errstate(invalid="ignore"):
        theta_rest = np.where(
            t >= 0, _cross(1, z, z0) / z / (_cross(1, np.array([z0]), z0)[0] / z0), np.nan
        )
    return theta10, theta_rest


def plot_example(
    path: str | Path, speed: float = EXAMPLE_SPEED, length: float = EXAMPLE_LENGTH, g: float = G
) -> Path:
    """θ/θ0 against time for solution (10) and for the release from rest, events marked."""
    from pendcli.core.plotting import new_figure

    m = example_model(speed, length, g)
    rest = from_rest_model(speed, length, g, floor_fraction=0.02)
    t = np.linspace(min(0.0, float(m.passage_times[0])), m.zero_length_time * (1 - 0.02), 4000)
    theta10, theta_rest = _theta_curves(m, rest, t)
    with new_figure(path, size=(8.0, 4.8)) as (_fig, ax):
        ax.plot(t, theta10, color="0.3", lw=1.0, label="solution (10)")
        ax.plot(t, theta_rest, color="C1", lw=0.8, ls="--", label="released from rest at t = 0")
        ax.plot(m.elongation_times, m.amplitude_ratios, "o", color="C0", label="elongations (10)")
        ax.plot(
            m.passage_times,
            0 * m.passage_times,
            "|",
            color="C0",
            ms=14,
            mew=2,
            label="vertical passages (10)",
        )
        ax.set_yscale("symlog", linthresh=1.0)
        ax.set_xlabel(
            f"t (s), L = {m.length:g} m at t = 0, shortening at {m.speed:g} m/s, g = {m.g:g}"
        )
        ax.set_ylabel("θ/θ0 (symlog)")
        ax.legend(fontsize=7, loc="lower left")
    return Path(path)


# --- figures ------------------------------------------------------------------------------

_VERDICT_COLOURS = {"agrees": "C2", "truncated": "C1", "last-digit": "C1"}


def figures(outdir: str | Path) -> list[Path]:
    """(1) θ/θ0 of the example against time, published and recomputed elongations and vertical
    passages marked; (2) printed minus recomputed, in units of the printed last digit."""
    from pendcli.core.claims import evaluate_paper
    from pendcli.core.plotting import new_figure

    outdir = Path(outdir)
    m = example_model()
    rows = {r.id: r for r in evaluate_paper("lecornu")}
    paths = []

    rest = from_rest_model(floor_fraction=0.02)
    t = np.linspace(m.passage_times[0] - 0.05, m.zero_length_time * (1 - 1e-6), 4000)
    theta, theta_rest = _theta_curves(m, rest, t)
    path1 = outdir / "lecornu_example_theta.png"
    with new_figure(path1, size=(8.0, 4.8)) as (_fig, ax):
        ax.plot(t, theta, color="0.3", lw=1.0, label="solution (10), b = 0,35 m/s, g = 9.81")
        ax.plot(
            t,
            theta_rest,
            color="C1",
            lw=0.8,
            ls="--",
            label="released from rest at 1 m (exact column)",
        )
        ax.plot(
            m.elongation_times, m.amplitude_ratios, "o", color="C0", label="elongations, recomputed"
        )
        pub_t = [rows[f"lecornu.example.time.{k}"].published_value for k in range(1, 6)]
        pub_r = [1.0] + [rows[f"lecornu.deviation.{k}"].published_value for k in range(2, 6)]
        ax.plot(pub_t, pub_r, "x", color="C3", ms=9, mew=2, label="elongations, printed")
        ax.plot([m.zero_length_time], [m.zero_length_ratio], "o", color="C0", mfc="none")
        ax.plot(
            [rows["lecornu.example.time_zero_length"].published_value],
            [rows["lecornu.deviation.zero_length"].published_value],
            "x",
            color="C3",
            ms=9,
            mew=2,
        )
        ax.plot(
            m.passage_times,
            np.zeros_like(m.passage_times),
            "|",
            color="C0",
            ms=14,
            mew=2,
            label="vertical passages, recomputed",
        )
        pub_lp = [rows[f"lecornu.j1_lengths.{k}"].published_value for k in range(1, 7)]
        ax.plot(
            (1 - np.array(pub_lp)) / EXAMPLE_SPEED,
            np.zeros(6),
            "+",
            color="C3",
            ms=12,
            mew=1.5,
            label="vertical passages from printed lengths",
        )
        ax.set_yscale("symlog", linthresh=1.0)
        ax.set_xlabel("t (s), pendulum 1 m long at t = 0, shortening at 0,35 m/s")
        ax.set_ylabel("θ/θ0 (symlog)")
        ax.set_title("Lecornu's example: elongations and vertical passages")
        ax.axhline(0, color="0.8", lw=0.5)
        ax.legend(fontsize=7, loc="lower left")
    paths.append(path1)

    groups = [
        ("lengths", [f"lecornu.example.length.{k}" for k in range(1, 6)]),
        (
            "times",
            [f"lecornu.example.time.{k}" for k in range(1, 6)]
            + ["lecornu.example.time_zero_length"],
        ),
        ("intervals", [f"lecornu.example.interval.{k}" for k in range(1, 6)]),
        ("J1 lengths", [f"lecornu.j1_lengths.{k}" for k in range(1, 7)]),
        ("J0", [f"lecornu.j0_at_j2_zeros.{k}" for k in range(1, 6)]),
    ]
    from pendcli.core.numbers import parse_printed

    path2 = outdir / "lecornu_printed_minus_recomputed.png"
    bars = []  # (x, difference in printed units, verdict, label), groups one slot apart
    spans = []
    x = 0
    for name, ids in groups:
        start = x
        for cid in ids:
            r = rows[cid]
            printed = parse_printed(r.published)
            d = (r.published_value - r.recomputed) / printed.resolution
            bars.append((x, d, r.verdict, f"{r.published_value:.{printed.decimals}f}"))
            x += 1
        spans.append((name, start, x - 1))
        x += 1
    top = max(b[1] for b in bars) + 1.5
    bottom = min(min(b[1] for b in bars) - 0.5, -1.0)
    with new_figure(path2, size=(9.0, 4.5)) as (_fig, ax):
        for bx, d, verdict, _ in bars:
            ax.bar(bx, d, color=_VERDICT_COLOURS.get(verdict, "C3"))
        for name, start, end in spans:
            ax.text((start + end) / 2, top - 0.8, name, ha="center", fontsize=8)
        ax.axhspan(-0.5, 0.5, color="0.9", zorder=0)
        ax.set_xticks([b[0] for b in bars], [b[3] for b in bars], rotation=90, fontsize=7)
        ax.set_ylabel("(printed - recomputed) / last printed unit")
        ax.set_ylim(bottom, top)
        ax.set_title(
            "Lecornu's example, printed minus recomputed (g = 9.81): green agrees, "
            "orange truncated/last digit, red discrepant",
            fontsize=9,
        )
    paths.append(path2)
    return paths
