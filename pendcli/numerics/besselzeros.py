"""Positive zeros j_(ν,s) of the Bessel functions J_1 and J_2, several ways.

Lecornu needs the zeros of J_2 (the elongations, his eq. (15)) and of J_1 (the vertical
passages) below 20, which he found by interpolation in Lommel's tables; his power series
(10)/(11) are the other route he mentions for arguments beyond the tables. This module gives
the zeros for any index up to :data:`MAX_COUNT`, with the method named:

``"scipy"``
    ``scipy.special.jn_zeros`` (Zhang & Jin's JYZO).
``"mcmahon"``
    McMahon's asymptotic expansion (DLMF 10.21.19, five terms through β^-9) evaluated in
    double-double for the leading term β = (s + ν/2 - 1/4)π, so that large zeros come out
    correctly rounded; poor for the first few indices (truncation error).
``"mcmahon-newton"``
    McMahon start, then Halley steps on ``scipy.special.jv``, vectorised; accurate where
    ``jv`` is (small and moderate arguments).
``"mpmath"``
    ``mpmath.besseljzero`` at 30 digits, one zero at a time: the slow reference.
``"series"``
    the ascending power series of J_1 and J_2 (DLMF 10.2.2) summed in double precision
    (:func:`ascending_series`; Lecornu's (10) and (13) are these sums), with bracketed root
    finding.
    Summing an alternating series whose terms reach ~I_ν(z) for a result of size ~J_ν(z) loses
    log10(I_ν/|J_ν'|) digits; the method refuses zeros whose predicted error exceeds
    :data:`SERIES_MAX_ERROR` (see :func:`series_error_bound`).
``"auto"``
    the first :data:`AUTO_SWITCH` - 1 zeros from mpmath (each computed once, when first
    asked for: about 0.45 ms a zero), ``mcmahon`` above, where its truncation error is below
    2e-6 ulp (:func:`mcmahon_truncation_bound`; alone it is correctly rounded from s = 16 on).
    Measured: correctly rounded at every index checked against mpmath, up to 10^7.

:func:`bessel_zeros_at` gives the zeros of any array of indices, and :func:`iter_bessel_zeros`
the first ``count`` in chunks of bounded size (what the CLI streams).

Accuracy and timing are measured in ``tests/numerics/test_besselzeros.py`` and
``tests/papers/lecornu/test_lecornu_extremes.py`` against mpmath at 30 digits.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from pendcli.base.errors import PendcliError, either, invalid_value, out_of_range

__all__ = [
    "AUTO_SWITCH",
    "MAX_COUNT",
    "METHODS",
    "MPMATH_MAX_COUNT",
    "ORDERS",
    "SCIPY_MAX_COUNT",
    "SERIES_MAX_ERROR",
    "ascending_series",
    "bessel_zeros",
    "bessel_zeros_at",
    "check_zeros_request",
    "iter_bessel_zeros",
    "mcmahon_truncation_bound",
    "series_error_bound",
    "series_max_count",
    "series_safe_limit",
]

METHODS: tuple[str, ...] = ("auto", "scipy", "mcmahon", "mcmahon-newton", "mpmath", "series")
ORDERS: tuple[int, ...] = (1, 2)
MAX_COUNT = 10_000_000  # 80 MB of float64; McMahon itself is valid for any index
AUTO_SWITCH = 32  # below this index "auto" takes mpmath's zeros (see module docstring)
SERIES_MAX_ERROR = 1e-6  # largest predicted absolute error of a zero the series may return
# mpmath takes 3.6 ms a zero here (20,000 zeros: 73 s measured); 2,000 is about 8 s, the most
# a reference run should take. Larger counts: "auto" is correctly rounded (see above).
MPMATH_MAX_COUNT = 2_000
# scipy's jn_zeros finds every zero from the first, holding four arrays of them (the zeros of
# J, J', Y, Y'): no chunk can start later. 10^6 zeros: 32 MB of them and ~2 s; 10^7 is 320 MB.
SCIPY_MAX_COUNT = 1_000_000

_PI_HI = math.pi
_PI_LO = 1.2246467991473532e-16  # π - math.pi (exact to ~1e-32): the second word of π
_SPLIT = 134217729.0  # 2**27 + 1, Dekker's splitter for exact products in double


def check_zeros_request(order: int, count: int, method: str) -> None:
    """Raise :class:`PendcliError` naming the valid range unless the request is valid."""
    if isinstance(order, bool) or not isinstance(order, (int, np.integer)) or order not in ORDERS:
        raise PendcliError(f"order must be {either(ORDERS)}, got {order!r}", "order")
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)):
        raise PendcliError(f"count must be an integer 1 <= count <= {MAX_COUNT}, got {count!r}")
    if not 1 <= count <= MAX_COUNT:
        raise out_of_range("count", f"{count}", f"1 <= count <= {MAX_COUNT}")
    if method not in METHODS:
        raise invalid_value("method", method, f"one of {', '.join(METHODS)}")
    if method == "mpmath" and count > MPMATH_MAX_COUNT:
        raise PendcliError(
            f"count: {count} is too large for method 'mpmath' (about 4 ms a zero); "
            f"expected 1 <= count <= {MPMATH_MAX_COUNT} (method auto is correctly "
            "rounded at any count)"
        )
    if method == "series":
        _check_series_count(int(order), int(count))
    if method == "scipy" and count > SCIPY_MAX_COUNT:
        raise PendcliError(
            f"count: {count} is too large for method 'scipy' (it holds every zero at once, "
            f"32 bytes each); expected 1 <= count <= {SCIPY_MAX_COUNT} (method auto is "
            "correctly rounded and computed in bounded memory at any count)"
        )


def bessel_zeros(order: int, count: int, method: str = "auto") -> np.ndarray:
    """The first ``count`` positive zeros of J_order (order 1 or 2), as a float64 array."""
    check_zeros_request(order, count, method)
    order, count = int(order), int(count)
    if method == "scipy":
        from scipy.special import jn_zeros

        return np.asarray(jn_zeros(order, count), dtype=float)
    if method == "mcmahon":
        return _mcmahon(order, np.arange(1, count + 1, dtype=float))
    if method == "mcmahon-newton":
        return _halley(order, _mcmahon(order, np.arange(1, count + 1, dtype=float)))
    if method == "mpmath":
        return _mpmath_zeros(order, count)
    if method == "series":
        return _series_zeros(order, count)
    # auto
    zeros = _mcmahon(order, np.arange(1, count + 1, dtype=float))
    head = min(count, AUTO_SWITCH - 1)
    zeros[:head] = _mpmath_head(order, head)
    return zeros


# Methods whose zero of index s depends on s alone: any slice of indices can be asked for.
_ELEMENTWISE = ("auto", "mcmahon", "mcmahon-newton")
CHUNK = 1 << 16  # zeros per chunk of iter_bessel_zeros: ~0.5 MB a temporary array


def bessel_zeros_at(order: int, indices: np.ndarray | int, method: str = "auto") -> np.ndarray:
    """The zeros j_(ν,s) for an array of indices s >= 1 (any shape, any order of indices).

    Bit for bit the values :func:`bessel_zeros` gives at the same indices: the methods
    ``auto``, ``mcmahon`` and ``mcmahon-newton`` treat each index alone; the others compute
    the first max(s) zeros and pick.
    """
    s = np.asarray(indices)
    if s.size == 0:
        return np.empty(s.shape)
    if not np.issubdtype(s.dtype, np.integer):
        raise PendcliError(f"zero indices must be integers, got dtype {s.dtype}")
    top = int(s.max())
    if int(s.min()) < 1:
        raise out_of_range("index", int(s.min()), "index >= 1")
    check_zeros_request(order, min(top, MAX_COUNT) if method in _ELEMENTWISE else top, method)
    order = int(order)
    if method not in _ELEMENTWISE:
        return bessel_zeros(order, top, method)[s - 1]
    zeros = _mcmahon(order, s.astype(float))
    if method == "mcmahon-newton":
        return _halley(order, zeros)
    if method == "auto":
        head = s < AUTO_SWITCH
        if head.any():
            zeros[head] = _mpmath_head(order, int(s[head].max()))[s[head] - 1]
    return zeros


def iter_bessel_zeros(
    order: int, count: int, method: str = "auto", chunk: int = CHUNK
) -> Iterator[np.ndarray]:
    """The first ``count`` zeros in consecutive chunks of at most ``chunk``: memory bounded
    whatever the count for the element-wise methods; the others compute every zero at once
    (their counts are bounded: :data:`SCIPY_MAX_COUNT`, :data:`MPMATH_MAX_COUNT`, the series'
    safe range) and give them in chunks too, so a writer never formats more than a chunk.

    The request is checked at the call, before any chunk is asked for.
    """
    check_zeros_request(order, count, method)
    starts = range(1, int(count) + 1, chunk)
    if method not in _ELEMENTWISE:  # computed at once (its count bounded), given in chunks:
        zeros = bessel_zeros(order, count, method)  # a writer formats one chunk at a time
        return (zeros[a - 1 : a - 1 + chunk] for a in starts)
    return (
        bessel_zeros_at(order, np.arange(a, min(a + chunk, int(count) + 1)), method) for a in starts
    )


# order -> the zeros j_(order,1..k) computed so far by _mpmath_head (k < AUTO_SWITCH)
_HEAD: dict[int, np.ndarray] = {}


def _mpmath_head(order: int, upto: int = AUTO_SWITCH - 1) -> np.ndarray:
    """The first ``upto`` (< AUTO_SWITCH) zeros, correctly rounded (mpmath, 30 digits).

    Halley on scipy's jv is only faithful there (up to 1.1 ulp measured: jv's own error near
    a zero), and McMahon's truncation error exceeds half an ulp below s ~ 16. Each zero is
    computed once per process and only when an index up to it is asked for: the claims need
    the first seven, and mpmath takes ~0.45 ms a zero (plus ~0.015 s to import).
    """
    upto = min(upto, AUTO_SWITCH - 1)
    known = _HEAD.get(order, np.empty(0))
    if known.size < upto:
        more = _mpmath_zeros(order, upto, start=known.size + 1)
        known = np.concatenate([known, more])
        known.flags.writeable = False
        _HEAD[order] = known
    return known[:upto]


# --- McMahon ---------------------------------------------------------------------------


def _two_prod(a: np.ndarray, b: float) -> tuple[np.ndarray, np.ndarray]:
    """a*b = p + e exactly (Dekker): p the rounded product, e its rounding error."""
    p = a * b
    a_big = _SPLIT * a
    a_hi = a_big - (a_big - a)
    a_lo = a - a_hi
    b_big = _SPLIT * b
    b_hi = b_big - (b_big - b)
    b_lo = b - b_hi
    e = ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo
    return p, e


def _mcmahon_coefficients(order: int) -> tuple[float, float, float, float, float]:
    """c1, c3, c5, c7, c9 of McMahon's expansion β - j_(ν,s) = Σ c_k (8β)^-k (DLMF 10.21.19)."""
    mu = 4.0 * order * order
    c1 = mu - 1.0
    c3 = 4.0 * (mu - 1.0) * (7.0 * mu - 31.0) / 3.0
    c5 = 32.0 * (mu - 1.0) * (83.0 * mu**2 - 982.0 * mu + 3779.0) / 15.0
    c7 = (
        64.0 * (mu - 1.0) * (6949.0 * mu**3 - 153855.0 * mu**2 + 1585743.0 * mu - 6277237.0) / 105.0
    )
    c9 = (
        512.0
        * (mu - 1.0)
        * (
            70197.0 * mu**4
            - 2479316.0 * mu**3
            + 48010494.0 * mu**2
            - 512062548.0 * mu
            + 2092163573.0
        )
        / 315.0
    )
    return c1, c3, c5, c7, c9


def _mcmahon_terms(order: int, beta: np.ndarray) -> np.ndarray:
    """β - j_(ν,s): the sum of McMahon's correction terms (DLMF 10.21.19, through (8β)^-9)."""
    c1, c3, c5, c7, c9 = _mcmahon_coefficients(order)
    w = 1.0 / (8.0 * beta)
    w2 = w * w
    # Horner in w² from the smallest term, so the sum is accurate to its last bit.
    return w * (c1 + w2 * (c3 + w2 * (c5 + w2 * (c7 + w2 * c9))))


def _mcmahon(order: int, s: np.ndarray) -> np.ndarray:
    """McMahon's expansion with β = (s + ν/2 - 1/4)π carried in two words (double-double).

    β's rounding alone would cost up to an ulp at large s; keeping π's second word and the
    product's rounding error makes the final single addition the only rounding.
    """
    n = s + 0.5 * order - 0.25  # a quarter-integer: exact in double
    hi, err = _two_prod(n, _PI_HI)
    lo = err + n * _PI_LO
    return hi + (lo - _mcmahon_terms(order, hi))


def mcmahon_truncation_bound(order: int, s: np.ndarray | int) -> np.ndarray:
    """Size of the first omitted McMahon term, a rough bound on the truncation error.

    The coefficient of (8β)^-11 is not used; its size is estimated by the ratio of the last
    two kept coefficients (the expansion is asymptotic, so this is a guide, not a proof; the
    tests measure the actual error against mpmath).
    """
    s = np.asarray(s, dtype=float)
    beta = (s + 0.5 * order - 0.25) * math.pi
    *_, c7, c9 = _mcmahon_coefficients(order)
    ratio = abs(c9 / c7)
    return np.abs(c9) * ratio / (8.0 * beta) ** 11


# --- Halley on scipy.special.jv --------------------------------------------------------


def _halley(order: int, x: np.ndarray, steps: int = 3) -> np.ndarray:
    """Refine zeros of J_ν by Halley's method on scipy.special.jv, all at once.

    At a zero J'' = -J'/x (Bessel's equation with J = 0), so Halley's step is
    δ = -f/f' / (1 - f f''/(2 f'^2)) with f'' from the equation. Three steps from McMahon's
    start (error < 1e-3 even at s = 1) reach the fixed point; extra steps only cost time.
    """
    from scipy.special import jv

    x = np.array(x, dtype=float, copy=True)
    nu = float(order)
    for _ in range(steps):
        f = jv(nu, x)
        fp = 0.5 * (jv(nu - 1.0, x) - jv(nu + 1.0, x))
        fpp = -fp / x - (1.0 - (nu / x) ** 2) * f
        newton = f / fp
        x = x - newton / (1.0 - 0.5 * newton * fpp / fp)
    return x


# --- mpmath reference ------------------------------------------------------------------


def _mpmath_zeros(order: int, count: int, dps: int = 30, start: int = 1) -> np.ndarray:
    """The zeros of indices ``start`` to ``count`` (each found alone by mpmath.besseljzero)."""
    import mpmath

    with mpmath.workdps(dps):
        return np.array([float(mpmath.besseljzero(order, k)) for k in range(start, count + 1)])


def series_error_bound(order: int, z: float | np.ndarray) -> np.ndarray:
    """Predicted absolute error of a zero of J_ν found from Lecornu's double-precision series.

    The series' terms add up in absolute value to I_ν(z) (the modified Bessel function), so
    rounding leaves an error ~ ε·I_ν(z) in J_ν; near a zero this moves the root by
    ε·I_ν(z)/|J_ν'(z)| with |J_ν'| ~ √(2/(πz)) (the envelope).
    """
    from scipy.special import iv

    z = np.asarray(z, dtype=float)
    eps = np.finfo(float).eps
    return eps * iv(order, z) / np.sqrt(2.0 / (math.pi * z))


def series_safe_limit(order: int, max_error: float = SERIES_MAX_ERROR) -> float:
    """The argument z where :func:`series_error_bound` reaches ``max_error``."""
    from scipy.optimize import brentq

    return float(brentq(lambda z: series_error_bound(order, z) - max_error, 1.0, 200.0))


def series_max_count(order: int) -> int:
    """How many zeros of J_order Lecornu's series gives within :data:`SERIES_MAX_ERROR`: those
    below :func:`series_safe_limit` by half a unit (McMahon's guesses; zeros are more than π
    apart, so only the first limit/π + 2 are guessed)."""
    limit = series_safe_limit(order)
    guesses = _mcmahon(order, np.arange(1, int(limit / math.pi) + 3, dtype=float))
    return int(np.searchsorted(guesses, limit - 0.5))


def _check_series_count(order: int, count: int) -> None:
    allowed = series_max_count(order)
    if count > allowed:
        raise PendcliError(
            f"count: {count} is beyond the safe range of Lecornu's series for J_{order}: "
            f"cancellation makes zeros above z = {series_safe_limit(order):.1f} err by more "
            f"than {SERIES_MAX_ERROR:g}; expected 1 <= count <= {allowed} "
            "(use method 'auto' beyond)"
        )


def _series_zeros(order: int, count: int) -> np.ndarray:
    from scipy.optimize import brentq

    _check_series_count(order, count)  # before count guesses are made (10^7: 700 MB)
    guesses = _mcmahon(order, np.arange(1, count + 1, dtype=float))

    def f(x: float) -> float:
        return float(ascending_series(order, x))

    out = np.empty(count)
    for i, z in enumerate(guesses):
        # McMahon is within 0.02 of every zero (worst at s = 1); zeros are π apart.
        lo, hi = (z - 0.4) ** 2 / 4.0, (z + 0.4) ** 2 / 4.0
        x = brentq(f, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=200)
        out[i] = 2.0 * math.sqrt(x)
    return out


def ascending_series(order: int, x: float | np.ndarray) -> np.ndarray:
    """The ascending series of J_1 or J_2 (DLMF 10.2.2) in double precision, in x = z²/4.

    order 1: Σ_(n>=1) (-1)^(n-1) n x^n/(n!)² = √x J_1(2√x);
    order 2: Σ_(k>=0) (-1)^k x^k/(k!(k+2)!) = J_2(2√x)/x.
    Summed term by term until the terms no longer change the sum (at most 400 terms); the
    cancellation this suffers for large x is what :func:`series_error_bound` predicts.
    """
    x = np.asarray(x, dtype=float)
    if order == 1:
        term = x.copy()  # n = 1
        total = term.copy()
        for n in range(2, 400):
            # t_n / t_(n-1) = -x n / ((n-1) n²) = -x / ((n-1) n)
            term = -term * x / ((n - 1) * n)
            new = total + term
            if np.all(new == total):
                break
            total = new
        return total
    term = np.full_like(x, 0.5)  # k = 0: 1/(0! 2!)
    total = term.copy()
    for k in range(1, 400):
        term = -term * x / (k * (k + 2))
        new = total + term
        if np.all(new == total):
            break
        total = new
    return total
