"""I_n(π) = ∫_0^π sin^(n+1) t dt = √π Γ(m)/Γ(m+½), m = (n+2)/2, correctly rounded.

Correctly rounded means the double nearest the exact value, for every n:

* n < :data:`SERIES_FROM`: Wallis' exact forms, I_(2k)(π) = 2·4^k/((2k+1)·C(2k, k)) (a
  rational, rounded once by integer division) and I_(2k-1)(π) = π·C(2k, k)/4^k (rounded once
  between two rational bounds of π, which must round alike).
* n >= :data:`SERIES_FROM`: √(π/m)·exp(-S(m)), S the asymptotic series of
  log Γ(m+½) - log Γ(m) - ½ log m, in double-double arithmetic (< 2^-81 relative); its
  result is accepted only if every number within :data:`DD_BOUND` of it rounds to the same
  double (Ziv's test), else mpmath decides at 160 and 240 bits (~1 n in 10^5 or fewer).

The double-double kernel is written once for Python floats and numpy arrays alike
(:func:`integral_pi_array` is the vector entry point).  π comes from Machin's formula in
integers, so this module needs neither mpmath nor a typed-in constant on its fast paths.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from fractions import Fraction
from functools import cache
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError, out_of_range

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

__all__ = [
    "DD_BOUND",
    "MAX_N",
    "SERIES_FROM",
    "bernoulli",
    "check_n",
    "integral_pi",
    "integral_pi_array",
    "log_gamma_ratio_fractions",
    "pi_bounds",
    "round_exact",
    "series_dd",
    "wallis_rational",
]

MAX_N = 10**15  # m = (n+2)/2 must stay an exact double (n < 2^53); 1e15 is a round limit
SERIES_FROM = 200  # m >= 101: 9 series terms leave < 4e-35 (the first omitted one)
SERIES_TERMS = 9
DD_BOUND = 2.0**-72  # accepted relative error of the double-double value; measured < 2^-81
_SPLITTER = 134217729.0  # 2^27 + 1: Dekker's split of a double into two 26-bit halves
_PI_BITS = 256

# The double-double kernel takes a float or a numpy array (typed Any): it uses only +, -, *, /
# and a square root, so one code path serves integral_pi and integral_pi_array alike.


# ----------------------------------------------------------------- exact: π and Wallis


@cache
def pi_bounds(bits: int = _PI_BITS) -> tuple[Fraction, Fraction]:
    """lo < π < hi, hi - lo = 2^(3-bits), from Machin's π = 16 atan(1/5) - 4 atan(1/239)."""
    guard = bits + 16
    one = 1 << guard

    def atan_inv(x: int) -> int:  # Σ (-1)^k one/((2k+1) x^(2k+1)), each term off by < 1
        total, power, k = 0, one // x, 0
        while power:
            total += power // (2 * k + 1) if k % 2 == 0 else -(power // (2 * k + 1))
            power //= x * x
            k += 1
        return total

    scaled = (16 * atan_inv(5) - 4 * atan_inv(239)) >> 16  # error well under 1 unit of 2^-bits
    return Fraction(scaled - 4, 1 << bits), Fraction(scaled + 4, 1 << bits)


def wallis_rational(n: int) -> tuple[Fraction, int]:
    """I_n(π) = q·π**p exactly (p = n mod 2), from Wallis' binomial forms, n >= -1."""
    if n % 2 == 0:
        k = n // 2
        return Fraction(2 * 4**k, (2 * k + 1) * math.comb(2 * k, k)), 0
    k = (n + 1) // 2
    return Fraction(math.comb(2 * k, k), 4**k), 1


def _round_times_pi(q: Fraction) -> float:
    """The double nearest q·π: rounded between two bounds of π, tightened until they agree."""
    bits = _PI_BITS
    while True:
        lo, hi = pi_bounds(bits)
        low, high = float(q * lo), float(q * hi)  # Fraction -> float rounds correctly
        if low == high:
            return low
        bits *= 2  # q·π within 2^-250 of a midpoint: never met, but decided, not guessed


def round_exact(q: Fraction, p: int) -> float:
    """q·π**p (p = 0 or 1) correctly rounded."""
    return _round_times_pi(q) if p else float(q)


@cache
def _small_table() -> tuple[float, ...]:
    """Correctly rounded I_n(π) for n = -1 .. SERIES_FROM - 1 (index n + 1)."""
    return tuple(round_exact(*wallis_rational(n)) for n in range(-1, SERIES_FROM))


# ----------------------------------------------------------------- the asymptotic series


def bernoulli(count: int) -> list[Fraction]:
    """B_0..B_count (B_1 = -1/2), from the standard recurrence."""
    b = [Fraction(1)]
    for m in range(1, count + 1):
        total = sum((math.comb(m + 1, k) * b[k] for k in range(m)), Fraction(0))
        b.append(-total / (m + 1))
    return b


@cache
def log_gamma_ratio_fractions(terms: int = 12) -> tuple[Fraction, ...]:
    """Exact c_k of log Γ(m+½)/Γ(m) = ½ log m + Σ c_k m^(-k), k = 1, 3, 5, ...

    From log Γ(z+a) ~ (z+a-½)log z - z + ½ log 2π + Σ (-1)^(k+1) B_(k+1)(a) / (k(k+1) z^k)
    with B_j(½) = (2^(1-j) - 1) B_j: c_k = (2^-k - 2) B_(k+1) / (k(k+1)) for odd k.
    """
    bern = bernoulli(2 * terms + 1)
    return tuple(
        (Fraction(1, 2**k) - 2) * bern[k + 1] / (k * (k + 1)) for k in range(1, 2 * terms, 2)
    )


# ----------------------------------------------------------------- double-double kernel


def _two_sum(a: Any, b: Any) -> tuple[Any, Any]:
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _fast_two_sum(a: Any, b: Any) -> tuple[Any, Any]:  # needs |a| >= |b|
    s = a + b
    return s, b - (s - a)


def _two_prod(a: Any, b: Any) -> tuple[Any, Any]:
    """a·b = p + e exactly (Dekker; no fma in Python)."""
    p = a * b
    t = _SPLITTER * a
    ah = t - (t - a)
    al = a - ah
    t = _SPLITTER * b
    bh = t - (t - b)
    bl = b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _dd_mul(ah: Any, al: Any, bh: Any, bl: Any) -> tuple[Any, Any]:
    p, e = _two_prod(ah, bh)
    return _fast_two_sum(p, e + (ah * bl + al * bh))


def _dd_add(ah: Any, al: Any, bh: Any, bl: Any) -> tuple[Any, Any]:  # no cancellation in our uses
    s, e = _two_sum(ah, bh)
    return _fast_two_sum(s, e + (al + bl))


@cache
def _constants() -> tuple[float, float, float, float, tuple[float, ...]]:
    """√π and c_3 = 1/192 as double-doubles, and c_5, c_7, ... as doubles."""
    lo, _ = pi_bounds()
    scale = 1 << _PI_BITS
    root = Fraction(math.isqrt(lo.numerator * scale // lo.denominator * scale), scale)
    sqrt_pi_hi = float(root)
    coeffs = log_gamma_ratio_fractions(SERIES_TERMS)
    assert coeffs[0] == Fraction(-1, 8)  # c_1: the exact scaling below relies on it
    c3_hi = float(coeffs[1])
    rest = tuple(float(c) for c in coeffs[2:])
    return sqrt_pi_hi, float(root - Fraction(sqrt_pi_hi)), c3_hi, float(coeffs[1] - c3_hi), rest


def series_dd(m: Any, sqrt: Callable[[Any], Any]) -> tuple[Any, Any]:
    """√π Γ(m)/Γ(m+½) = √(π/m) exp(-S(m)) as a double-double, m >= SERIES_FROM/2 + 1."""
    sp_hi, sp_lo, c3_hi, c3_lo, rest = _constants()
    inv_hi = 1.0 / m
    p, e = _two_prod(m, inv_hi)
    inv_lo = ((1.0 - p) - e) / m  # 1 - p is exact (Sterbenz)
    inv2_hi, inv2_lo = _dd_mul(inv_hi, inv_lo, inv_hi, inv_lo)
    inv3_hi, inv3_lo = _dd_mul(inv2_hi, inv2_lo, inv_hi, inv_lo)
    tail: Any = 0.0
    for c in reversed(rest):  # c_5 m^-5 + ...: below 2e-13 relative, a double suffices
        tail = tail * inv2_hi + c
    # t = -S = m^-1/8 - c_3 m^-3 - tail·m^-5 (c_1 = -1/8: the scaling is exact)
    t_hi, t_lo = _dd_mul(c3_hi, c3_lo, inv3_hi, inv3_lo)
    t_hi, t_lo = _dd_add(0.125 * inv_hi, 0.125 * inv_lo, -t_hi, -t_lo - tail * inv3_hi * inv2_hi)
    # exp(t) = 1 + t + t²/2 + t³(1/6 + t/24 + ...); t <= 1.3e-3, so t³·(...) <= 4e-10 in double
    sq_hi, sq_lo = _dd_mul(t_hi, t_lo, t_hi, t_lo)
    cube = t_hi * sq_hi * _exp_tail(t_hi)
    e_hi, e_lo = _dd_add(t_hi, t_lo, 0.5 * sq_hi, 0.5 * sq_lo + cube)
    e_hi, e_lo = _dd_add(1.0, 0.0, e_hi, e_lo)
    num_hi, num_lo = _dd_mul(sp_hi, sp_lo, e_hi, e_lo)
    # divide by √m = s_hi + s_lo, s_lo from the exact residual m - s_hi²
    s_hi = sqrt(m)
    p, e = _two_prod(s_hi, s_hi)
    s_lo = ((m - p) - e) / (2.0 * s_hi)
    q1 = num_hi / s_hi
    p, e = _two_prod(q1, s_hi)
    q2 = (((num_hi - p) - e) + num_lo - q1 * s_lo) / s_hi
    return _fast_two_sum(q1, q2)


def _exp_tail(t: Any) -> Any:
    """1/6 + t/24 + t²/120 + ... (to t^6/9!: the next term is < 1e-32 for t <= 1.3e-3)."""
    total: Any = 0.0
    for k in range(9, 2, -1):
        total = total * t + 1.0 / math.factorial(k)
    return total


def _rounds_alike(hi: Any, lo: Any) -> Any:
    """True where every number within DD_BOUND·|hi| of hi + lo rounds to hi (Ziv's test)."""
    bound = abs(hi) * DD_BOUND
    return (hi + (lo + bound) == hi) & (hi + (lo - bound) == hi)


def _mpmath_rounded(n: int) -> float:
    """The rare undecided case: mpmath's beta at 160 and 240 bits must round alike."""
    import mpmath

    values = []
    for prec in (160, 240):
        with mpmath.workprec(prec):
            values.append(float(mpmath.beta(mpmath.mpf(1) / 2, mpmath.mpf(n + 2) / 2)))
    if values[0] != values[1]:  # pragma: no cover - needs I_n(π) within 2^-150 of a midpoint
        raise PendcliError(f"I_n(π) for n = {n} could not be rounded correctly")
    return values[0]


# ----------------------------------------------------------------- entry points


def check_n(n: int) -> int:
    """``n`` if it is an integer with -1 <= n <= MAX_N, else a one-line PendcliError."""
    if isinstance(n, bool) or not isinstance(n, int):
        raise PendcliError(f"n must be an integer >= -1, got {n!r}")
    if not -1 <= n <= MAX_N:
        raise out_of_range("n", f"{n}", f"-1 <= n <= {MAX_N:.0e}")
    return n


def integral_pi(n: int) -> float:
    """I_n(π) = B(½, (n+2)/2), correctly rounded, for integer -1 <= n <= 10^15 (~1-10 µs)."""
    check_n(n)
    if n < SERIES_FROM:
        return _small_table()[n + 1]
    hi, lo = series_dd((n + 2) / 2, math.sqrt)
    return hi if _rounds_alike(hi, lo) else _mpmath_rounded(n)


def integral_pi_array(ns: npt.ArrayLike) -> np.ndarray:
    """:func:`integral_pi` for an array of integer n (any shape), correctly rounded."""
    import numpy as np

    arr = np.asarray(ns)
    if arr.dtype == bool or not np.issubdtype(arr.dtype, np.integer):
        raise PendcliError(f"n must be an array of integers >= -1, got dtype {arr.dtype}")
    if arr.size and (arr.min() < -1 or arr.max() > MAX_N):
        bad = arr.min() if arr.min() < -1 else arr.max()
        raise out_of_range("n", f"{bad}", f"-1 <= n <= {MAX_N:.0e}")
    flat = arr.astype(np.int64).ravel()
    out = np.empty(flat.shape, dtype=np.float64)
    small = flat < SERIES_FROM
    out[small] = np.asarray(_small_table())[flat[small] + 1]
    large = np.flatnonzero(~small)
    if large.size:
        hi, lo = series_dd((flat[large] + 2) / 2.0, np.sqrt)
        out[large] = hi
        for i in np.flatnonzero(~_rounds_alike(hi, lo)):
            out[large[i]] = _mpmath_rounded(int(flat[large[i]]))
    return out.reshape(arr.shape)
