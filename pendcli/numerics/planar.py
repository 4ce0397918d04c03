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

:func:`period_ratio` and :func:`period` also take an array of amplitudes (any shape) and
return an array: the same arithmetic element-wise in numpy (AGM iterated until every element
has converged, each stopping where the scalar loop would), so 10^5 periods cost milliseconds.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, overload

from pendcli.base.errors import PendcliError, invalid_value, out_of_range

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import ArrayLike, NDArray

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
        raise out_of_range("amplitude", f"{amplitude}°", "0 <= |amplitude| < 180°")
    if amplitude == 180.0:
        raise PendcliError(
            "amplitude = 180° is the unstable upright equilibrium: the period is infinite; "
            "expected 0 <= |amplitude| < 180°"
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


@overload
def period_ratio(
    amplitude: float, method: str = ..., *, order: int = ..., epsrel: float = ...
) -> float: ...
@overload
def period_ratio(
    amplitude: np.ndarray | list[float] | tuple[float, ...],
    method: str = ...,
    *,
    order: int = ...,
    epsrel: float = ...,
) -> NDArray[np.float64]: ...
def period_ratio(
    amplitude: Any, method: str = "agm", *, order: int = 8, epsrel: float = 1.49e-8
) -> Any:
    """T/T0 = (2/π) K(sin²(θ0/2)), T0 = 2π√(l/g), by the named method (see module docstring).

    An array (or list) of amplitudes gives an array of ratios.
    """
    if method not in METHODS:
        raise invalid_value("method", method, f"one of {', '.join(METHODS)}")
    if _is_array(amplitude):
        return _period_ratio_array(amplitude, method, order, epsrel)
    amplitude = _check_amplitude(amplitude)
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
    amplitude: Any,
    length: float = 1.0,
    g: float = G_STANDARD,
    method: str = "agm",
    **options: Any,
) -> Any:
    """The exact period T = 4 √(l/g) K(sin²(θ0/2)) in seconds (θ0 in degrees, l in m); an
    array of amplitudes gives an array of periods."""
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
        raise out_of_range("count", f"{count!r}", "1..10000")
    half = 0.5 * period(amplitude, length, g, method)
    return [j * half for j in range(1, count + 1)]


def _check_positive(name: str, value: float) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise PendcliError(f"{name} must be a positive real number, got {value!r}")
    if not (math.isfinite(value) and value > 0):
        raise out_of_range(name, value, f"{name} > 0")


# --- arrays of amplitudes ------------------------------------------------------------------


def _is_array(value: object) -> bool:
    return type(value).__module__ == "numpy" or isinstance(value, list | tuple)


def _check_amplitudes(amplitudes: ArrayLike) -> NDArray[np.float64]:
    """|θ0| as a float array, or the scalar check's one-line error for its first bad value."""
    import numpy as np

    raw = np.asarray(amplitudes)
    if raw.dtype.kind not in "iuf":
        raise PendcliError(f"amplitudes must be real numbers of degrees, got dtype {raw.dtype}")
    values = np.abs(raw.astype(float))
    bad = ~(values < 180.0)  # NaN, infinities and 180° and beyond
    if bad.any():
        _check_amplitude(float(values[bad].flat[0]))  # raises, in the scalar words
    return values


def _period_ratio_array(
    amplitudes: ArrayLike, method: str, order: int, epsrel: float
) -> NDArray[np.float64]:
    """:func:`period_ratio` element-wise, with the scalar path's formulas and accuracy."""
    import numpy as np

    a = _check_amplitudes(amplitudes)
    near = a > 90.0
    # the exact complement 180 - θ0 above 90°, as in complementary_modulus and modulus_squared
    half = np.radians(np.where(near, 180.0 - a, a)) / 2
    kc = np.where(near, np.sin(half), np.cos(half))
    k = np.where(near, np.cos(half), np.sin(half))
    if method == "agm":
        k_value = _agm_ellipk_array(kc)
    elif method == "ellipkm1":
        from scipy.special import ellipkm1

        k_value = ellipkm1(kc * kc)
    elif method == "ellipk":
        from scipy.special import ellipk

        k_value = ellipk(np.sin(np.radians(a) / 2) ** 2)
    elif method == "series":
        return _series_array(k * k, order)
    else:
        flat = [period_ratio(float(x), "quad", epsrel=epsrel) for x in a.ravel()]
        return np.asarray(flat).reshape(a.shape)
    return np.where(a == 0.0, 1.0, 2.0 * k_value / math.pi)


def _agm_ellipk_array(kc: NDArray[np.float64]) -> NDArray[np.float64]:
    """K = π/(2 AGM(1, k')) element-wise; each element stops where :func:`agm_ellipk` would."""
    import numpy as np

    b = np.array(kc, dtype=float).ravel()
    a = np.ones_like(b)
    todo = np.flatnonzero(np.abs(a - b) > 4e-16 * a)
    for _ in range(60):
        if todo.size == 0:
            break
        at, bt = a[todo], b[todo]
        at, bt = 0.5 * (at + bt), np.sqrt(at * bt)
        a[todo], b[todo] = at, bt
        todo = todo[np.abs(at - bt) > 4e-16 * at]  # only those not yet converged go on
    return (math.pi / (a + b)).reshape(np.shape(kc))


def _series_array(m: NDArray[np.float64], order: int) -> NDArray[np.float64]:
    import numpy as np

    if isinstance(order, bool) or not isinstance(order, int) or order < 0:
        raise PendcliError(f"order must be an integer >= 0, got {order!r}")
    total, coeff, power = np.ones_like(m), 1.0, np.ones_like(m)
    for j in range(1, order + 1):
        coeff *= (2 * j - 1) / (2 * j)
        power = power * m
        total = total + coeff * coeff * power
    return total
