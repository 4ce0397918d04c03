"""The planar pendulum of finite amplitude: exact period and elongation times up to 180°.

Context: Lecornu (1894), section on finite oscillations, eq. (38), keeps k³ and neglects k⁴,
k = sin(θ0/2), and remarks that "for a pendulum oscillating through 180°, that is reaching
the horizontal at each elongation" (amplitude θ0 = 90°) k⁴ is only 0.25.  This module gives
the exact period T = 4 √(l/g) K(k²) that such remarks are measured against, and carries it to
the other extreme, θ0 → 180° (the upright position), where T grows like 4 √(l/g) ln(4/k').

Methods for K(m), m = k² = sin²(θ0/2), complementary modulus k'² = 1 - m = cos²(θ0/2):

* ``"agm"``: K = π / (2 AGM(1, k')), with k' = cos(θ0/2) = sin((180° - θ0)/2) computed from
  the exact complement 180° - θ0 (Sterbenz), so nothing is lost as θ0 → 180°.
* ``"ellipkm1"``: scipy.special.ellipkm1(k'²), the same accurate k'².
* ``"ellipk"``: scipy.special.ellipk(m) with m rounded to a double: the usual call, which
  loses every digit as m → 1 (1 - m is then known to one ulp of 1, i.e. not at all).
* ``"quad"``: scipy.integrate.quad of dφ/√(1 - m sin²φ) (φ from 0 to π/2).
* ``"series"``: T/T0 = Σ_j [(2j)!/(2^(2j) j!²)]² k^(2j), truncated after ``order`` terms in k²;
  order 1 keeps k² (error O(k⁴), Lecornu's level).

Amplitudes are in degrees, as in the papers (θ0 = 20°), which also makes 180° exact.
"""

from __future__ import annotations

import math

from pendcli.core.errors import PendcliError

__all__ = [
    "G_STANDARD",
    "METHODS",
    "agm_ellipk",
    "complementary_modulus",
    "elongation_times",
    "modulus_squared",
    "period",
    "period_ratio",
    "series_period_ratio",
]

G_STANDARD = 9.80665  # m/s², the conventional standard gravity (any g > 0 may be passed)
METHODS = ("agm", "ellipkm1", "ellipk", "quad", "series")


def _check_amplitude(amplitude: float) -> float:
    if isinstance(amplitude, bool) or not isinstance(amplitude, (int, float)):
        raise PendcliError(f"amplitude must be a real number of degrees, got {amplitude!r}")
    amplitude = abs(float(amplitude))
    if not math.isfinite(amplitude) or amplitude > 180.0:
        raise PendcliError(
            f"amplitude = {amplitude}° is out of range; valid range is 0 <= |amplitude| < 180°"
        )
    if amplitude == 180.0:
        raise PendcliError(
            "amplitude = 180° is the unstable upright equilibrium: the period is infinite; "
            "valid range is 0 <= |amplitude| < 180°"
        )
    return amplitude


def complementary_modulus(amplitude: float) -> float:
    """k' = cos(θ0/2), accurate to ~1 ulp even as θ0 → 180° (degrees in, exact complement)."""
    amplitude = _check_amplitude(amplitude)
    if amplitude <= 90.0:
        return math.cos(math.radians(amplitude) / 2)
    # 180 - θ0 is exact for θ0 in [90, 180] (Sterbenz), so cos(θ0/2) = sin((180-θ0)/2) keeps
    # every digit where cos of a rounded θ0/2 near 90° would keep only the absolute ones.
    return math.sin(math.radians(180.0 - amplitude) / 2)


def modulus_squared(amplitude: float) -> tuple[float, float]:
    """(m, 1 - m) = (sin²(θ0/2), cos²(θ0/2)), each with its own relative accuracy."""
    amplitude = _check_amplitude(amplitude)
    kc = complementary_modulus(amplitude)
    k = (
        math.sin(math.radians(amplitude) / 2)
        if amplitude <= 90.0
        else math.cos(math.radians(180.0 - amplitude) / 2)
    )
    return k * k, kc * kc


def agm_ellipk(kc: float, iterations: int | None = None) -> tuple[float, int]:
    """K from the arithmetic-geometric mean of 1 and k'; (K, iterations used)."""
    a, b = 1.0, kc
    used = 0
    limit = iterations if iterations is not None else 60
    while used < limit:
        if iterations is None and abs(a - b) <= 4e-16 * a:
            break
        a, b = 0.5 * (a + b), math.sqrt(a * b)
        used += 1
    return math.pi / (a + b), used  # π / (2·AGM), AGM ≈ (a + b)/2 once converged


def series_period_ratio(amplitude: float, order: int) -> float:
    """T/T0 = Σ_(j<=order) [(2j-1)!!/(2j)!!]² k^(2j): the classical series in k² = sin²(θ0/2)."""
    if isinstance(order, bool) or not isinstance(order, int) or order < 0:
        raise PendcliError(f"order must be an integer >= 0, got {order!r}")
    m, _ = modulus_squared(amplitude)
    total, coeff, power = 1.0, 1.0, 1.0
    for j in range(1, order + 1):
        coeff *= (2 * j - 1) / (2 * j)
        power *= m
        total += coeff * coeff * power
    return total


def period_ratio(
    amplitude: float, method: str = "agm", *, order: int = 8, epsrel: float = 1.49e-8
) -> float:
    """T/T0 = (2/π) K(sin²(θ0/2)), T0 = 2π√(l/g), by the named method (see module docstring)."""
    amplitude = _check_amplitude(amplitude)
    if method not in METHODS:
        raise PendcliError(f"method = {method!r} is not known; valid methods: {', '.join(METHODS)}")
    if amplitude == 0.0:
        return 1.0
    if method == "series":
        return series_period_ratio(amplitude, order)
    m, m1 = modulus_squared(amplitude)
    if method == "agm":
        k_value, _ = agm_ellipk(complementary_modulus(amplitude))
    elif method == "ellipkm1":
        from scipy.special import ellipkm1

        k_value = float(ellipkm1(m1))
    elif method == "ellipk":
        from scipy.special import ellipk

        # The usual call, m formed the usual way: 1 - m is then only known to ~1e-16 absolute.
        k_value = float(ellipk(math.sin(math.radians(amplitude) / 2) ** 2))
    else:
        import warnings

        from scipy.integrate import IntegrationWarning, quad

        with warnings.catch_warnings():  # near 180° quad warns of the log peak; error is measured
            warnings.simplefilter("ignore", IntegrationWarning)
            k_value = quad(
                lambda phi: 1.0 / math.sqrt(m1 + m * math.cos(phi) ** 2),
                0.0,
                0.5 * math.pi,
                epsabs=0.0,
                epsrel=epsrel,
                limit=200,
            )[0]
    return 2.0 * k_value / math.pi


def period(
    amplitude: float,
    length: float = 1.0,
    g: float = G_STANDARD,
    method: str = "agm",
    **options,
) -> float:
    """The exact period T = 4 √(l/g) K(sin²(θ0/2)) in seconds (θ0 in degrees, l in m)."""
    _check_positive("length", length)
    _check_positive("g", g)
    return 2.0 * math.pi * math.sqrt(length / g) * period_ratio(amplitude, method, **options)


def elongation_times(
    amplitude: float,
    count: int = 4,
    length: float = 1.0,
    g: float = G_STANDARD,
    method: str = "agm",
) -> list[float]:
    """Times of the first ``count`` elongations after release at rest from θ0: j·T/2, j >= 1."""
    if isinstance(count, bool) or not isinstance(count, int) or not 1 <= count <= 10_000:
        raise PendcliError(f"count = {count!r} is out of range; valid range is 1..10000")
    half = 0.5 * period(amplitude, length, g, method)
    return [j * half for j in range(1, count + 1)]


def _check_positive(name: str, value: float) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise PendcliError(f"{name} must be a positive real number, got {value!r}")
    if not (math.isfinite(value) and value > 0):
        raise PendcliError(f"{name} = {value} is out of range; valid range is {name} > 0")
