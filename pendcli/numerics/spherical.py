"""The spherical (conical) pendulum done exactly: no small-amplitude series.

This is the fuller model behind the Tisserand claims (:mod:`pendcli.papers.tisserand`).
Units: time in 1/k with k = √(g/l), angles in radians, lengths in l. The bob swings
between the largest angle θ0 and the smallest θ1 from the downward vertical; at t = 0,
θ = θ0 and φ = 0.

Tisserand's variables (his eqs. (3), (9), (10)): ``sin²θ = u0² cos²ψ + u1² sin²ψ`` defines the
eccentric anomaly ψ (it grows by π per radial period T_r, from one end of the major axis to
the other), ``tan φ1 = (u1/u0) tan ψ`` and ``φ' = φ - φ1`` is the rotation of the major axis.
The quantities computed:

* ``k1 = k'/k``: mean motion of ψ, k' = π/T_r (ψ = k't + Σ b_n sin 2n k't);
* ``precession = Ω``: mean rate of φ' per unit k't (Resal: Ω ≈ (3/8) u0 u1);
* ``k2 = k''/k``, defined by Tisserand's (V): (3/8) u0 u1 k'' t = Ω k' t;
* ``psi_coeffs = (b_1, b_2, ...)`` and ``phi_coeffs = (c_1, c_2, ...)``: the Fourier sine
  coefficients of ψ - k't and of φ' - Ω k't in sin 2n k't (radians).

Two independent methods:

``quad``
    Tisserand's exact quadratures (4) and (5) in ψ. The integrands are analytic and π-periodic
    in ψ, so the trapezoidal rule (with FFT for the running integral t(ψ)) converges
    geometrically; the grid is doubled until the results are stable to ``rtol``. The
    integrands are written without cancellation (F - 1 through log1p/expm1, and
    dφ'/dψ = u0 u1 (c c0 + c c1 + c0 c1)/(c² D (H + 1)) after cancelling dφ1/dψ = u0 u1/u²
    analytically), which keeps them regular at θ1 = 0 (planar limit) and θ1 = θ0 (conical).
    The Fourier coefficients come from b_n = (1/nπ)∫_0^π (1 - dτ/dψ) cos 2nτ(ψ) dψ and
    c_n = (1/nπ)∫_0^π (dφ'/dψ - Ω dτ/dψ) cos 2nτ(ψ) dψ, τ = k't (integration by parts).
``ode``
    Direct integration of Newton's equations of the bob in 3-D Cartesian coordinates
    (r'' = -ẑ + (z - |r'|²) r, the rod tension keeping |r| = 1) with DOP853, over half a
    radial period (to the pericentre θ1, found as a root of r_h · v_h = 0), time symmetry
    giving the rest. ψ(t) is read off the state through definition (3) and the energy and
    area integrals; the Fourier integrals are taken on a uniform grid in t. Independent of
    the quadrature except for the coordinate definitions. It refuses the conical limit
    (no radial oscillation: ψ is undefined) and the near-planar limit (φ' is the difference
    of two angles that swing by π near the vertical, so the ODE's absolute error is
    amplified by θ0/θ1).
``elliptic``
    k', k'' and Ω only (no Fourier coefficients), from (1)-(2) reduced to complete elliptic
    integrals of the first and third kinds (Carlson's R_F and R_J, scipy.special): a third,
    closed-form check. Ω = (Δφ - π)/π cancels about log10(1/(u0 u1)) digits.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, NoReturn

import numpy as np

from pendcli.base.errors import PendcliError, invalid_value, out_of_range

__all__ = [
    "METHODS",
    "ConicalMotion",
    "check_amplitudes",
    "conical_limit",
    "exact_conical",
    "implicit_psi_coeffs",
    "integrands",
    "planar_limit_k1",
    "projected_path",
]

METHODS = ("quad", "ode", "elliptic")
_MAX_GRID = 2**22  # quadrature points per half period beyond which we give up
_MIN_PEAK_WIDTH = 1e-5  # narrowest peak of (4) the quadrature accepts (grid 2^21)
_ELLIPTIC_MIN_RATIO = 1e-6  # θ1/θ0 below which Π(n → 1, m) is refused
_QUAD_MAX_DEGREES = 89.999  # accepted for any θ1 (grid 2^18 at 89.99°, 2^21 at 89.999°)
# Limits of the ODE method, measured against the quadrature (agreement better than 1e-10):
_ODE_MIN_SPLIT = 1e-4  # (u0² - u1²)/u0² below which ψ read off the state is too noisy
_ODE_MIN_RATIO = 1e-3  # θ1/θ0 below which φ' near the vertical is lost in the ODE's error
_ODE_MAX_THETA0 = math.radians(89.99)  # beyond, 512 samples no longer resolve ψ(t) near θ0


@dataclass(frozen=True)
class ConicalMotion:
    """Mean motions and Fourier coefficients of the spherical pendulum (units of k, radians)."""

    theta0: float  # largest angle from the vertical (rad)
    theta1: float  # smallest angle (rad)
    k1: float  # k'/k: mean motion of ψ
    k2: float  # k''/k, Tisserand's (V): Ω k' = (3/8) u0 u1 k''
    precession: float  # Ω: mean rotation of the major axis per unit k't (rad/rad)
    psi_coeffs: tuple[float, ...]  # b_n: ψ - k't = Σ b_n sin 2n k't (rad)
    phi_coeffs: tuple[float, ...]  # c_n: φ' - Ω k't = Σ c_n sin 2n k't (rad)
    method: str
    grid: int = 0  # quadrature / sampling points used

    @property
    def radial_period(self) -> float:
        """k T_r: from one end of the major axis to the other (θ0 → θ1 → θ0)."""
        return math.pi / self.k1

    @property
    def apsidal_advance(self) -> float:
        """Rotation of the major axis per radial period, Δφ - π (rad)."""
        return math.pi * self.precession

    @property
    def precession_per_time(self) -> float:
        """Mean angular velocity of the major axis in units of k: dφ'/d(kt) = Ω k'/k."""
        return self.precession * self.k1


# Below this θ0 (radians) sin²θ0 heads for the subnormal range and the elliptic form divides
# by zero (found by the fuzz test at 1e-217°); no pendulum question lives down there.
THETA0_MIN = 1e-100


def check_amplitudes(theta0: float, theta1: float) -> tuple[float, float]:
    """Validate θ0, θ1 in radians: 1e-100 <= θ0 < π/2 and 0 <= θ1 <= θ0 (one-line errors)."""
    for name, value in (("theta0", theta0), ("theta1", theta1)):
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise PendcliError(f"{name} must be a real angle in radians, got {value!r}")
        if not math.isfinite(value):
            raise PendcliError(f"{name}: {value} is not finite; expected 0 < theta0 < 90°")
    theta0, theta1 = float(theta0), float(theta1)
    if not THETA0_MIN <= theta0 < 0.5 * math.pi:
        raise out_of_range(
            "theta0",
            f"{math.degrees(theta0):.10g}°",
            f"{math.degrees(THETA0_MIN):.2g}° ({THETA0_MIN:g} rad) <= theta0 < 90°",
        )
    if not 0.0 <= theta1 <= theta0:
        raise out_of_range(
            "theta1",
            f"{math.degrees(theta1):.10g}°",
            f"0 <= theta1 <= theta0 = {math.degrees(theta0):.10g}°",
        )
    return theta0, theta1


def exact_conical(
    theta0_rad: float,
    theta1_rad: float,
    method: str = "quad",
    rtol: float = 1e-14,
    harmonics: int = 3,
) -> ConicalMotion:
    """k', k'', Ω and the Fourier coefficients of the exact motion (see the module docstring).

    ``rtol`` is the target accuracy: the quadrature's grid is refined until successive results
    agree to ``rtol`` (relative for k', k'', Ω; absolute, in radians, for the coefficients);
    for the ODE it is DOP853's relative tolerance.
    """
    theta0, theta1 = check_amplitudes(theta0_rad, theta1_rad)
    if not (isinstance(harmonics, int) and 1 <= harmonics <= 20):
        raise out_of_range("harmonics", f"{harmonics!r}", "1..20")
    if not (isinstance(rtol, (int, float)) and 1e-15 <= rtol <= 1e-3):
        raise out_of_range("rtol", f"{rtol!r}", "1e-15..1e-3")
    if method == "quad":
        return _quadrature(theta0, theta1, harmonics, float(rtol))
    if method == "ode":
        return _ode(theta0, theta1, harmonics, float(rtol))
    if method == "elliptic":
        return _elliptic(theta0, theta1, harmonics)
    raise invalid_value("method", method, f"one of {', '.join(METHODS)}")


# ---------------------------------------------------------------- quadrature of (4)-(5)


def _half_versine(u2, c):
    """1 - cos θ = sin²θ/(1 + cos θ), without cancellation at small θ."""
    return u2 / (1.0 + c)


def _log_near_one(defect, value):
    """log(value) where value = 1 - defect, both known accurately: log1p(-defect) while the
    defect is small (small amplitudes), log(value) when value is small (θ near 90°)."""
    defect = np.asarray(defect, dtype=float)
    value = np.asarray(value, dtype=float)
    small = defect < 0.5
    return np.where(
        small, np.log1p(-np.where(small, defect, 0.0)), np.log(np.where(small, 1.0, value))
    )


def integrands(theta0: float, theta1: float, psi: np.ndarray):
    """F - 1 with F = k dt/dψ (eq. 4), and Q = (dφ'/dψ)/(u0 u1) (eq. 5 minus dφ1/dψ)."""
    u0, u1 = math.sin(theta0), math.sin(theta1)
    c0, c1 = math.cos(theta0), math.cos(theta1)
    cos2, sin2 = np.cos(psi) ** 2, np.sin(psi) ** 2
    u2 = u0 * u0 * cos2 + u1 * u1 * sin2  # eq. (3)
    # 1 - u² = c0² cos²ψ + c1² sin²ψ exactly: no cancellation when θ0 is near 90°.
    c = np.sqrt(c0 * c0 * cos2 + c1 * c1 * sin2)
    w = _half_versine(u2, c)
    a = _half_versine(u0 * u0, c0) + _half_versine(u1 * u1, c1)  # 2 - (c0 + c1)
    d = 1.0 + c * (c0 + c1) + c0 * c1  # 1 + cc0 + cc1 + c0c1
    # F = sqrt((c0+c1)/2) * sqrt((c+c0)(c+c1)/D) / c and (c+c0)(c+c1) = D - u²;
    # H = sqrt((c+c0)(c+c1)/D)/c is the factor of eq. (5).
    log_h = 0.5 * _log_near_one(u2 / d, (c + c0) * (c + c1) / d) - _log_near_one(w, c)
    log_a = 0.5 * _log_near_one(0.5 * a, 0.5 * (c0 + c1))
    f_minus_1 = np.expm1(log_a + log_h)
    h = np.exp(log_h)
    # H² - 1 = u²(c c0 + c c1 + c0 c1)/(c² D): the 1/u² of eq. (5) cancels dφ1/dψ = u0u1/u².
    q = (c * (c0 + c1) + c0 * c1) / (c * c * d * (h + 1.0))
    return f_minus_1, q


def _spectral(theta0: float, theta1: float, n: int, harmonics: int) -> ConicalMotion:
    u0u1 = math.sin(theta0) * math.sin(theta1)
    psi = np.arange(n) * (math.pi / n)
    f_minus_1, q = integrands(theta0, theta1, psi)
    a0 = 1.0 + float(f_minus_1.mean())  # k T_r / π
    g = f_minus_1 - f_minus_1.mean()  # periodic part of k dt/dψ
    # ∫_0^ψ g by FFT: the π-periodic g has harmonics e^{2imψ}.
    spectrum = np.fft.fft(g)
    m = np.fft.fftfreq(n, 1.0 / n)
    m[0] = 1.0
    integral_spec = spectrum / (2j * m)
    integral_spec[0] = 0.0
    if n % 2 == 0:
        integral_spec[n // 2] = 0.0
    running = np.fft.ifft(integral_spec).real
    running -= running[0]
    tau = psi + running / a0  # k't as a function of ψ
    dtau_minus_1 = g / a0
    q_mean = float(q.mean())
    omega = u0u1 * q_mean
    dphi_minus_omega_dtau = u0u1 * (q - q_mean) - omega * dtau_minus_1
    b, cc = [], []
    for k in range(1, harmonics + 1):
        cos_k = np.cos(2 * k * tau)
        b.append(-float(np.dot(dtau_minus_1, cos_k)) / (k * n))
        cc.append(float(np.dot(dphi_minus_omega_dtau, cos_k)) / (k * n))
    k1 = 1.0 / a0
    return ConicalMotion(
        theta0=theta0,
        theta1=theta1,
        k1=k1,
        k2=k1 * q_mean / 0.375,
        precession=omega,
        psi_coeffs=tuple(b),
        phi_coeffs=tuple(cc),
        method="quad",
        grid=n,
    )


def _converged(new: ConicalMotion, old: ConicalMotion, rtol: float) -> bool:
    rel = [(new.k1, old.k1), (new.k2, old.k2), (new.precession, old.precession)]
    if any(abs(x - y) > rtol * max(abs(x), 1e-300) for x, y in rel if x != y):
        return False
    coeffs = zip(new.psi_coeffs + new.phi_coeffs, old.psi_coeffs + old.phi_coeffs, strict=True)
    scale = max(abs(new.psi_coeffs[0]), abs(new.phi_coeffs[0]))
    # The integrands are known to ~eps·u0², which bounds the coefficients' noise floor
    # (the near-conical coefficients can be smaller than that).
    floor = 1e-15 * math.sin(new.theta0) ** 2
    return all(abs(x - y) <= max(rtol * scale, floor) for x, y in coeffs)


def _too_close_to_90(theta0: float) -> NoReturn:
    raise PendcliError(
        f"theta0 = {math.degrees(theta0):.10g}° is too close to 90° for the quadrature: the "
        f"integrand of (4) peaks like 1/cos θ0 (width cos θ0/sqrt(sin²θ0 - sin²θ1) < "
        f"{_MIN_PEAK_WIDTH:g}); expected theta0 <= {_QUAD_MAX_DEGREES}° "
        "(closer to 90° only when theta1 is near theta0)"
    )


def _quadrature(theta0: float, theta1: float, harmonics: int, rtol: float) -> ConicalMotion:
    # cos θ = sqrt(c0² + (u0² - u1²) sin²ψ): near θ0 = 90° the integrand of (4) has a peak of
    # width c0/sqrt(u0² - u1²) at ψ = 0, which 2^21 points resolve down to about 1e-5.
    split = (math.sin(theta0) - math.sin(theta1)) * (math.sin(theta0) + math.sin(theta1))
    if math.cos(theta0) < _MIN_PEAK_WIDTH * math.sqrt(split):
        _too_close_to_90(theta0)
    n = 16  # doubled until two grids agree: loose rtol costs few points
    previous = _spectral(theta0, theta1, n, harmonics)
    while n < _MAX_GRID:
        n *= 2
        current = _spectral(theta0, theta1, n, harmonics)
        if _converged(current, previous, max(rtol, 4e-16)):
            return current
        previous = current
    _too_close_to_90(theta0)


# ---------------------------------------------------------------- direct ODE integration


def _newton(_t, y):
    """r'' = -ẑ + λ r with the rod tension λ = z - |v|² (|r| = 1, units g = l = 1)."""
    x, yy, z, vx, vy, vz = y
    lam = (z - (vx * vx + vy * vy + vz * vz)) / (x * x + yy * yy + z * z)
    return [vx, vy, vz, lam * x, lam * yy, lam * z - 1.0]


def _initial_state(theta0: float, theta1: float) -> list[float]:
    """At θ0, moving horizontally, speed from the area integral sin²θ φ' = u0 u1 √(2/(c0+c1))."""
    u0, u1 = math.sin(theta0), math.sin(theta1)
    c0, c1 = math.cos(theta0), math.cos(theta1)
    return [u0, 0.0, -c0, 0.0, u1 * math.sqrt(2.0 / (c0 + c1)), 0.0]


def _check_ode(theta0: float, theta1: float) -> None:
    """Refuse the motions whose ψ or φ' the integrated state cannot resolve."""
    u0, u1 = math.sin(theta0), math.sin(theta1)
    split = (u0 - u1) * (u0 + u1)  # u0² - u1²
    if split < _ODE_MIN_SPLIT * u0 * u0 or theta1 == theta0:
        raise PendcliError(
            f"method 'ode' needs a radial oscillation: theta1 = {math.degrees(theta1):.10g}° is "
            f"(almost) theta0; the motion is conical and ψ is undefined (use method 'quad' or "
            f"conical_limit)"
        )
    if theta1 < _ODE_MIN_RATIO * theta0:
        raise PendcliError(
            f"method 'ode' cannot resolve φ' for theta1/theta0 = {theta1 / theta0:.3g} < "
            f"{_ODE_MIN_RATIO:g}: the bob passes so near the vertical that φ jumps by π "
            f"(near-planar motion); use method 'quad'"
        )
    if theta0 > _ODE_MAX_THETA0:
        raise PendcliError(
            f"method 'ode' is limited to theta0 <= {math.degrees(_ODE_MAX_THETA0):g}° "
            f"(got {math.degrees(theta0):.10g}°); use method 'quad'"
        )


class _Pericentre:
    """solve_ivp event: the radial velocity r_h·v_h turns positive (u decreasing → increasing)."""

    terminal = True
    direction = 1.0

    def __call__(self, _t: float, y: Sequence[float]) -> float:
        return y[0] * y[3] + y[1] * y[4]


def _half_radial_period(theta0: float, theta1: float, rtol: float) -> tuple[Any, float]:
    """(dense solution, time from θ0 to the pericentre θ1) of the Newtonian ODE (DOP853)."""
    from scipy.integrate import solve_ivp

    # DOP853 accepts no rtol below 100 eps; it clamps (with a warning) otherwise.
    rtol = max(rtol, 2.5e-14)
    sol = solve_ivp(
        _newton,
        (0.0, 8.0 * math.pi),
        _initial_state(theta0, theta1),
        method="DOP853",
        rtol=rtol,
        atol=rtol * 1e-3,
        events=_Pericentre(),
        dense_output=True,
    )
    if sol.status != 1 or len(sol.t_events[0]) == 0:  # pragma: no cover - defensive
        raise PendcliError(f"method 'ode' found no pericentre: {sol.message}")
    return sol, float(sol.t_events[0][0])


def _psi_and_phi(states: np.ndarray, theta0: float, theta1: float) -> tuple[np.ndarray, np.ndarray]:
    """ψ and φ' (definition (3)) read off the integrated states (x, y, z, vx, vy, vz)."""
    u0, u1 = math.sin(theta0), math.sin(theta1)
    c0, c1 = math.cos(theta0), math.cos(theta1)
    split = (u0 - u1) * (u0 + u1)
    x, y, z, vx, vy, _ = states
    norm2 = x * x + y * y + z * z
    u2 = (x * x + y * y) / norm2
    c = -z / np.sqrt(norm2)
    # Definition (3): cos 2ψ from u²; sin 2ψ from the radial velocity, through the energy and
    # area integrals: (u0²-u²)(u²-u1²) = (u θ')² (c0+c1)(c+c0)(c+c1) / (2D), u θ' = r_h·v_h / c.
    cos_2psi = (2.0 * u2 - u0 * u0 - u1 * u1) / split
    d = 1.0 + c * (c0 + c1) + c0 * c1
    radial = (x * vx + y * vy) / c
    sin_2psi = -2.0 * radial * np.sqrt((c0 + c1) * (c + c0) * (c + c1) / (2.0 * d)) / split
    psi = 0.5 * np.unwrap(np.arctan2(sin_2psi, cos_2psi))
    # φ' is the angle from the ellipse point (u0 cos ψ, u1 sin ψ) to the bob's projection.
    wx, wy = u0 * np.cos(psi), u1 * np.sin(psi)
    px, py = x / np.sqrt(norm2), y / np.sqrt(norm2)
    return psi, np.arctan2(wx * py - wy * px, wx * px + wy * py)


def _sine_coefficients(tau: np.ndarray, values: np.ndarray, harmonics: int) -> tuple[float, ...]:
    """(4/π) ∫_0^(π/2) values·sin 2kτ dτ, k = 1..harmonics, by the trapezoidal rule."""
    weights = np.full(len(tau), 1.0)
    weights[0] = weights[-1] = 0.5
    step = 0.5 * math.pi / (len(tau) - 1)
    return tuple(
        4.0 / math.pi * step * float(np.sum(weights * values * np.sin(2 * k * tau)))
        for k in range(1, harmonics + 1)
    )


def _ode(theta0: float, theta1: float, harmonics: int, rtol: float) -> ConicalMotion:
    _check_ode(theta0, theta1)
    sol, t_half = _half_radial_period(theta0, theta1, rtol)
    samples = 512
    tau = np.linspace(0.0, 0.5 * math.pi, samples + 1)
    psi, phi_prime = _psi_and_phi(sol.sol(tau * (2.0 * t_half / math.pi)), theta0, theta1)
    omega = float(phi_prime[-1]) / (0.5 * math.pi)
    k1 = 0.5 * math.pi / t_half
    return ConicalMotion(
        theta0=theta0,
        theta1=theta1,
        k1=k1,
        k2=omega * k1 / (0.375 * math.sin(theta0) * math.sin(theta1)),
        precession=omega,
        psi_coeffs=_sine_coefficients(tau, psi - tau, harmonics),
        phi_coeffs=_sine_coefficients(tau, phi_prime - omega * tau, harmonics),
        method="ode",
        grid=samples,
    )


# ---------------------------------------------------------------- complete elliptic integrals


def _elliptic(theta0: float, theta1: float, harmonics: int) -> ConicalMotion:
    """k' and Ω from (1)-(2) as complete elliptic integrals (Carlson's R_F, R_J).

    With z = cos θ = c0 + (c1 - c0) sin²s the square roots of (1)-(2) become 2 ds and
    D = 1 + c0c1 + z(c0 + c1) = A + B sin²s, so over half a radial period
    k t = √(2(c0+c1)) R_F(0, A, A+B) and, splitting 1/(1 - z²) into 1/(1-z) and 1/(1+z),
    φ = u0u1/√A [Π(n1, m)/(1 - c0) + Π(n2, m)/(1 + c0)], m = -B/A,
    n1 = (c1-c0)/(1-c0), n2 = -(c1-c0)/(1+c0). No Fourier coefficients: they are not
    complete integrals. Ω = (Δφ - π)/π loses about log10(1/(u0 u1)) digits to cancellation.
    """
    from scipy.special import elliprf, elliprj

    if theta1 < _ELLIPTIC_MIN_RATIO * theta0:
        raise PendcliError(
            f"method 'elliptic' cannot take theta1/theta0 = {theta1 / theta0:.3g} < "
            f"{_ELLIPTIC_MIN_RATIO:g}: Π(n, m) diverges as n → 1 (near-planar motion); "
            "use method 'quad'"
        )
    u0, u1 = math.sin(theta0), math.sin(theta1)
    c0, c1 = math.cos(theta0), math.cos(theta1)
    w0, w1 = u0 * u0 / (1.0 + c0), u1 * u1 / (1.0 + c1)  # 1 - c0, 1 - c1 without cancellation
    gap = (u0 - u1) * (u0 + u1) / (c0 + c1)  # c1 - c0
    a = 1.0 + c0 * c1 + c0 * (c0 + c1)
    b = gap * (c0 + c1)
    half_time = math.sqrt(2.0 * (c0 + c1)) * float(elliprf(0.0, a, a + b))
    # Π(n, m)/√A = R_F(0, A+B, A) + (n/3) A R_J(0, A+B, A, A(1-n)) by homogeneity.
    rf = float(elliprf(0.0, a + b, a))

    def third_kind(n: float, one_minus_n: float) -> float:
        return rf + n / 3.0 * a * float(elliprj(0.0, a + b, a, a * one_minus_n))

    n1, one_minus_n1 = gap / w0, w1 / w0
    n2 = -gap / (1.0 + c0)
    half_phi = u0 * u1 * (third_kind(n1, one_minus_n1) / w0 + third_kind(n2, 1.0 - n2) / (1.0 + c0))
    k1 = 0.5 * math.pi / half_time
    omega = (2.0 * half_phi - math.pi) / math.pi
    return ConicalMotion(
        theta0=theta0,
        theta1=theta1,
        k1=k1,
        k2=omega * k1 / (0.375 * u0 * u1),
        precession=omega,
        psi_coeffs=(),
        phi_coeffs=(),
        method="elliptic",
    )


# ---------------------------------------------------------------- closed-form limits


def conical_limit(theta0_rad: float) -> ConicalMotion:
    """θ1 = θ0: the conical pendulum, in closed form.

    The bob turns at φ̇ = k/√cos θ0; small radial oscillations about it have angular
    frequency k √((1 + 3 cos²θ0)/cos θ0), and ψ advances by π per radial period, so
    k'/k = √(1 + 3c²)/(2√c); per radial period φ advances π·2/√(1+3c²), so
    Ω = 2/√(1 + 3c²) - 1. There is no periodic term.
    """
    theta0, _ = check_amplitudes(theta0_rad, theta0_rad)
    c = math.cos(theta0)
    root = math.sqrt(1.0 + 3.0 * c * c)
    k1 = root / (2.0 * math.sqrt(c))
    # 2/root - 1 = (4 - root²)/(root (2 + root)) = 3 sin²θ0 /(root (2 + root)): no cancellation.
    omega = 3.0 * math.sin(theta0) ** 2 / (root * (2.0 + root))
    u2 = math.sin(theta0) ** 2
    return ConicalMotion(
        theta0=theta0,
        theta1=theta0,
        k1=k1,
        k2=omega * k1 / (0.375 * u2),
        precession=omega,
        psi_coeffs=(0.0,),
        phi_coeffs=(0.0,),
        method="closed form (conical pendulum)",
    )


def planar_limit_k1(theta0_rad: float) -> float:
    """θ1 = 0: k'/k = π/(k T_r) with T_r half the plane pendulum's period 4K(sin²(θ0/2))/k."""
    from scipy.special import ellipk

    theta0, _ = check_amplitudes(theta0_rad, 0.0)
    return math.pi / (2.0 * float(ellipk(math.sin(0.5 * theta0) ** 2)))


def implicit_psi_coeffs(theta0_rad: float, theta1_rad: float, harmonics: int = 2):
    """d_m in k't = ψ + Σ d_m sin 2mψ: the Fourier form of eq. (8) divided by k/k' (exact).

    Tisserand's unnumbered equation before (13) reads ψ = k't - d_1 sin 2ψ - d_2 sin 4ψ - ...
    with d_1 = (u0²-u1²)(3/32 + ...), d_2 = (u0²-u1²)² (35/4096 + ...).
    """
    theta0, theta1 = check_amplitudes(theta0_rad, theta1_rad)
    n = _quadrature(theta0, theta1, harmonics, 1e-14).grid
    psi = np.arange(n) * (math.pi / n)
    f_minus_1, _ = integrands(theta0, theta1, psi)
    a0 = 1.0 + f_minus_1.mean()
    # F = a0 + Σ A_m cos 2mψ, A_m = (2/n) Σ F_j cos 2mψ_j; ∫ gives A_m sin 2mψ /(2m).
    return tuple(
        float(2.0 / n * np.dot(f_minus_1, np.cos(2 * m * psi))) / (2 * m * a0)
        for m in range(1, harmonics + 1)
    )


def projected_path(theta0_rad: float, theta1_rad: float, kt: np.ndarray, rtol: float = 1e-12):
    """(x, y)/l of the bob at times k t (Cartesian ODE, as in method 'ode'), for drawing."""
    from scipy.integrate import solve_ivp

    theta0, theta1 = check_amplitudes(theta0_rad, theta1_rad)
    kt = np.asarray(kt, dtype=float)
    sol = solve_ivp(
        _newton,
        (0.0, float(kt.max())),
        _initial_state(theta0, theta1),
        method="DOP853",
        rtol=rtol,
        atol=1e-15,
        t_eval=kt,
    )
    return sol.y[0], sol.y[1]
