"""Charbonnier's integrals I_n(x) = ∫_0^x sin^(n+1) t dt (no. 15), by every method pendcli uses.

* :func:`integral_pi_rational` / :func:`integral_pi_exact`: Charbonnier's recurrence at x = π
  in exact rational arithmetic, I_n(π) = q·2 or q·π with q rational (uncached / cached).
* :func:`printed_closed_form`: the printed products of evens over odds, as printed.
* :func:`integral_pi` / :func:`integral_pi_array`: I_n(π) = B(½, (n+2)/2) correctly rounded
  for every n from -1 to 10^15 (:mod:`.wallis`: exact Wallis rationals for n < 200, else the
  asymptotic series of log Γ(m+½)/Γ(m) in double-double arithmetic, m = (n+2)/2).
  (scipy.special.beta(0.5, m) loses up to 6 digits for m ~ 10^3..10^6.)
* :func:`integral`: I_n(x) for any real x, by exact reduction to [0, π] (the remainder kept as
  a double-double) and the incomplete beta function ½ B(sin²x; (n+2)/2, ½) at 40 digits, since
  rounding sin²x to a double alone costs (n+2)/2 ulp: < 0.5 ulp measured for n <= 10^4
  (against a positive series) and up to n = 10^12 near π/2 (against mpmath at 80 digits).
* :func:`integral_fast`: the same in double precision with scipy's betainc plus a first-order
  correction for the rounding of sin²x (~10 µs; scipy's own betainc error remains).
* :func:`integral_recurrence`: the printed recurrence in floating point, as Charbonnier
  would compute it. Exact at x = π; at small x it subtracts nearly equal numbers
  (:func:`integral_recurrence_with_error` carries a bound on the damage).
* :func:`integral_pi_sequence`, :func:`printed_closed_form_sequence`,
  :func:`integral_recurrence_sequence`: the same for n = -1..N in one pass, one step per n
  (what ``charbonnier table`` shows; restarting each row from n = 0 cost O(N²)).

No value of g or unit enters: these are pure numbers.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from fractions import Fraction
from functools import cache

from pendcli.base.errors import PendcliError, out_of_range
from pendcli.papers.charbonnier.wallis import (
    MAX_N,
    SERIES_FROM,
    bernoulli,
    check_n,
    integral_pi,
    integral_pi_array,
    log_gamma_ratio_fractions,
)

__all__ = [
    "EXACT_BELOW",
    "MAX_EXACT_N",
    "MAX_N",
    "MAX_X",
    "RECURRENCE_MAX_N",
    "bernoulli",
    "check_inputs",
    "exact_text",
    "integral",
    "integral_fast",
    "integral_method",
    "integral_pi",
    "integral_pi_array",
    "integral_pi_exact",
    "integral_pi_rational",
    "integral_pi_sequence",
    "integral_recurrence",
    "integral_recurrence_sequence",
    "integral_recurrence_with_error",
    "log_gamma_ratio_coefficients",
    "log_gamma_ratio_fractions",
    "printed_closed_form",
    "printed_closed_form_sequence",
]

RECURRENCE_MAX_N = 10**7  # n/2 Python steps: about a second at the limit
MAX_X = 1.0e6  # |x| accepted by integral(); reduction mod π is exact, the cost is the count q
MAX_EXACT_N = 100_000  # exact rationals beyond this cost seconds and megabytes
EXACT_BELOW = SERIES_FROM  # n below which integral_pi rounds the exact Wallis rational
_PI_LOW = math.sin(math.pi)  # π - math.pi: the part of π a double cannot hold (~1.22e-16)
_MP_DIGITS = 40  # working digits of the general-x path; measured < 0.5 ulp for n <= 10^4
_LOG_TINY = -1075 * math.log(2.0)  # log of half the smallest subnormal: below it, 0


def check_inputs(n: int, x: float) -> tuple[int, float]:
    """(n, float(x)) if -1 <= n <= MAX_N is an integer and x is real with |x| <= MAX_X."""
    return check_n(n), _check_x(x)


def _check_x(x: float) -> float:
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise PendcliError(f"x must be a real number, got {x!r}")
    x = float(x)
    if not math.isfinite(x) or abs(x) > MAX_X:
        raise out_of_range("x", f"{x}", f"-{MAX_X:.0e} <= x <= {MAX_X:.0e}")
    return x


# ----------------------------------------------------------------- I_n(π): exact and printed


def integral_pi_rational(n: int) -> tuple[Fraction, int]:
    """I_n(π) = q·π**p exactly (p is 0 or 1), by Charbonnier's recurrence I_n = n/(n+1) I_(n-2).

    Uncached (O(n) Fraction steps each call): :func:`integral_pi_exact` is the cached form.
    """
    check_n(n)
    if n > MAX_EXACT_N:
        raise PendcliError(
            f"exact I_n(π) is limited to n <= {MAX_EXACT_N} (got {n}); use integral_pi"
        )
    # Iterate (not recurse) so large n do not exhaust the stack.
    q = Fraction(1) if n % 2 else Fraction(2)  # I_(-1)(π) = π, I_0(π) = 2
    for k in range(2 if n % 2 == 0 else 1, n + 1, 2):
        q *= Fraction(k, k + 1)
    return q, n % 2


@cache
def integral_pi_exact(n: int) -> tuple[Fraction, int]:
    """:func:`integral_pi_rational`, cached (the table and the claims ask for the same n)."""
    return integral_pi_rational(n)


def printed_closed_form(n: int) -> tuple[Fraction, int]:
    """The printed general formula as printed: products of evens over odds (no recurrence)."""
    check_n(n)
    if n == -1:
        return Fraction(1), 1
    if n % 2 == 0:  # 2·(2·4…n)/(1·3·5…(n+1))
        num = math.prod(range(2, n + 1, 2))
        den = math.prod(range(1, n + 2, 2))
        return Fraction(2 * num, den), 0
    num = math.prod(range(1, n + 1, 2))  # π·(1·3·5…n)/(2·4·6…(n+1))
    den = math.prod(range(2, n + 2, 2))
    return Fraction(num, den), 1


def integral_pi_sequence(n_max: int) -> Iterator[tuple[int, Fraction, int]]:
    """(n, q, p) with I_n(π) = q·π**p exactly, n = -1..n_max: one recurrence step per n.

    Both parities' exact states are carried from row to row (:func:`integral_pi_rational`
    restarts from n = 0 for each n, O(n²) in all).
    """
    check_n(n_max)
    state = [Fraction(2), Fraction(1)]  # I_0(π) = 2, I_(-1)(π) = π: the even and odd chains
    yield -1, state[1], 1
    for n in range(n_max + 1):
        if n > 0:
            state[n % 2] *= Fraction(n, n + 1)
        yield n, state[n % 2], n % 2


def printed_closed_form_sequence(n_max: int) -> Iterator[tuple[int, int, int, int]]:
    """(n, numerator, denominator, p) of the printed products, unreduced, n = -1..n_max.

    I_n(π) = (numerator/denominator)·π**p; each product gains one factor per row.
    """
    check_n(n_max)
    yield -1, 1, 1, 1
    even = [2, 1]  # 2·(2·4…n), 1·3·5…(n+1)
    odd = [1, 1]  # 1·3·5…n, 2·4·6…(n+1)
    for n in range(n_max + 1):
        products = odd if n % 2 else even
        if n > 0:
            products[0] *= n
        products[1] *= n + 1
        yield n, products[0], products[1], n % 2


def exact_text(q: Fraction, p: int) -> str:
    """q·π**p as text: ``2``, ``π/2``, ``16/15``, ``3π/8``."""
    base = "π" if p else ""
    num = base if (q.numerator == 1 and base) else f"{q.numerator}{base}"
    return num if q.denominator == 1 else f"{num}/{q.denominator}"


# ----------------------------------------------------------------- I_n(π) in floating point


@cache
def log_gamma_ratio_coefficients(terms: int = 12) -> tuple[float, ...]:
    """:func:`.wallis.log_gamma_ratio_fractions` rounded to doubles (c_1, c_3, c_5, ...)."""
    return tuple(float(c) for c in log_gamma_ratio_fractions(terms))


# ----------------------------------------------------------------- I_n(x), 0 <= x <= π


def _two_sum(a: float, b: float) -> tuple[float, float]:
    """a + b = hi + lo exactly (Knuth's error-free transformation)."""
    hi = a + b
    bb = hi - a
    return hi, (a - (hi - bb)) + (b - bb)


def _pi_minus(x: float, x_lo: float = 0.0) -> tuple[float, float]:
    """π - (x + x_lo) as a double-double; math.pi - x is exact (Sterbenz) for π/2 <= x <= π."""
    return _two_sum(math.pi - x, _PI_LOW - x_lo)


def _negligible(n: int, x: float) -> float | None:
    """0 or I_n(π) when I_n(x) is below the smallest subnormal or its tail negligible, else None.

    I_n(y) <= y sin^(n+1) y for y <= π/2 (the integrand grows on [0, y]): below the smallest
    subnormal the answer is 0, and a tail below 1e-20 of I_n(π) leaves I_n(π) unchanged.
    Deciding this first also keeps mpmath away from values it cannot bound.
    """
    near = x if x <= 0.5 * math.pi else math.pi - x
    log_bound = math.log(near) + (n + 1) * math.log(math.sin(near)) if near > 0 else -math.inf
    if x <= 0.5 * math.pi and log_bound < _LOG_TINY:
        return 0.0
    if x > 0.5 * math.pi and log_bound < math.log(integral_pi(n)) - 46.0:
        return integral_pi(n)
    return None


def _integral_0_pi(n: int, x: float, x_lo: float = 0.0) -> float:
    """I_n(x + x_lo) for 0 <= x + x_lo <= π (a double-double argument), to < 1 ulp.

    I_n(x) = ½ B(sin²x; a, ½), a = (n+2)/2, behaves like (sin²x)^a: rounding sin²x to a double
    costs a ulp (300 ulp at n = 1000), and scipy's own betainc loses up to ~200 ulp at large a
    (measured, see pendcli.run.stability).  So sin²x and the incomplete beta function are evaluated
    at 40 digits (mpmath's hypergeometric series; 0.2..2 ms) and rounded once.  For x > π/2,
    I_n(x) = B(a, ½) - ½ B(sin²x; a, ½) has no cancellation (the difference is >= half).
    """
    if x == 0.0 and x_lo == 0.0:
        return 0.0
    if n == -1:
        return x + x_lo
    if n == 0:
        # 1 - cos x without its cancellation at small x; x_lo enters through dI/dx = sin x.
        return 2.0 * math.sin(0.5 * x) ** 2 + x_lo * math.sin(x)
    shortcut = _negligible(n, x)
    if shortcut is not None:
        return shortcut
    import mpmath

    with mpmath.workdps(_MP_DIGITS):
        t = mpmath.mpf(x) + mpmath.mpf(x_lo)
        a = mpmath.mpf(n + 2) / 2
        part = mpmath.betainc(a, 0.5, 0, mpmath.sin(t) ** 2) / 2
        if 2 * t <= mpmath.pi:
            return float(part)
        return float(mpmath.beta(a, 0.5) - part)


# ----------------------------------------------------------------- the fast double path


@cache
def _extended_sin_available() -> bool:
    import numpy as np

    return bool(np.finfo(np.longdouble).nmant >= 60)  # x87 80-bit (63 bits); double elsewhere


def _square_rounding_error(x: float, x_lo: float, rounded: float, cosine: bool) -> float:
    """sin²(x + x_lo) (or cos²) minus its double ``rounded``, to ~3 significant digits or better.

    Only this small difference δ is needed beyond double precision: the correction δ·dI/du is
    itself ~a·1e-16 relative, so δ to 1e-3 relative leaves < 1 ulp.  long double (x87, 64-bit
    mantissa) gives δ to 2^-11 relative in ~5 µs; mpmath is the portable fallback (~40 µs).
    """
    if _extended_sin_available():
        import numpy as np

        t = np.longdouble(x) + np.longdouble(x_lo)
        f = np.cos(t) if cosine else np.sin(t)
        return float(f * f - np.longdouble(rounded))
    import mpmath

    with mpmath.workprec(130):
        tm = mpmath.mpf(x) + mpmath.mpf(x_lo)
        fm = mpmath.cos(tm) if cosine else mpmath.sin(tm)
        return float(fm * fm - mpmath.mpf(rounded))


def integral_fast(n: int, x: float) -> float:
    """I_n(x), 0 <= x <= π, in ~10 µs: scipy's betainc plus a first-order rounding correction.

    The correction δ·dI/du (u = sin²x rounded, δ = the exact sin²x minus u, dI/du =
    ½ u^(a-1) (1-u)^(-½)) removes the a-fold amplification of the rounding of sin²x; what
    remains is scipy.special.betainc's own error (up to ~200 ulp at n ~ 1000, measured).
    """
    check_n(n)
    x = float(x)
    if not 0.0 <= x <= math.pi:
        raise out_of_range("x", f"{x}", "0 <= x <= π", " for integral_fast")
    if n <= 0 or x == 0.0:
        return _integral_0_pi(n, x)
    full = integral_pi(n)
    if x > 0.5 * math.pi:
        rest, rest_lo = _pi_minus(x)
        return full - _fast_half(n, rest, rest_lo, full)
    return _fast_half(n, x, 0.0, full)


def _fast_half(n: int, x: float, x_lo: float, full: float) -> float:
    """I_n(x + x_lo), 0 <= x <= π/2, from betainc on sin²x (or betaincc on cos²x near π/2)."""
    from scipy.special import betainc, betaincc

    a = 0.5 * (n + 2)
    s, c = math.sin(x), math.cos(x)
    if s <= c:
        u = s * s
        if u == 0.0:
            return 0.0
        value = 0.5 * full * float(betainc(a, 0.5, u))
        delta = _square_rounding_error(x, x_lo, u, cosine=False)
        return value + delta * 0.5 * math.exp((a - 1.0) * math.log(u) - 0.5 * math.log1p(-u))
    v = c * c
    value = 0.5 * full * float(betaincc(0.5, a, v))
    if v == 0.0:
        return value
    delta = _square_rounding_error(x, x_lo, v, cosine=True)
    return value - delta * 0.5 * math.exp((a - 1.0) * math.log1p(-v) - 0.5 * math.log(v))


# ----------------------------------------------------------------- I_n(x), any real x


def integral(n: int, x: float = math.pi) -> float:
    """I_n(x) = ∫_0^x sin^(n+1) t dt for integer n >= -1 and real |x| <= 1e6."""
    check_n(n)
    x = _check_x(x)
    if n == -1:
        return x
    if 0.0 <= x <= math.pi:
        return _integral_0_pi(n, x)
    if x < 0:
        # sin^(n+1)(-t) = (-1)^(n+1) sin^(n+1) t, so I_n(-x) = (-1)^n I_n(x).
        value = integral(n, -x)
        return value if n % 2 == 0 else -value
    return _integral_beyond_pi(n, x)


def _integral_beyond_pi(n: int, x: float) -> float:
    """I_n(x) for π < x <= 1e6: whole half-periods plus the remainder r, 0 <= r < π."""
    q, r, r_lo = _reduce_mod_pi(x)
    # Over [jπ, (j+1)π] the integrand is (-1)^(j(n+1)) sin^(n+1) of the base half-period.
    full = integral_pi(n)
    if (n + 1) % 2 == 0:  # even power: every half-period adds I_n(π)
        return q * full + _integral_0_pi(n, r, r_lo)
    # odd power: the half-periods alternate; the last partial one has sign (-1)^q.
    if q % 2 == 0:
        return _integral_0_pi(n, r, r_lo)
    # I_n(π) - I_n(r) = ∫_r^π = I_n(π - r): no cancellation when r is near π.
    if r <= 0.5 * math.pi:
        return full - _integral_0_pi(n, r, r_lo)
    return _integral_0_pi(n, *_pi_minus(r, r_lo))


def _reduce_mod_pi(x: float) -> tuple[int, float, float]:
    """x = qπ + r with 0 <= r < π, computed at 50 digits; r returned as a double-double."""
    import mpmath

    with mpmath.workdps(50):
        xm = mpmath.mpf(x)
        q = int(mpmath.floor(xm / mpmath.pi))
        r = xm - q * mpmath.pi
        r_hi = float(r)
        return q, r_hi, float(r - r_hi)


def integral_method(n: int, x: float) -> str:
    """Which branch :func:`integral` takes, for display."""
    if n == -1:
        return "I_(-1)(x) = x"
    if n == 0:
        return "I_0(x) = 2 sin²(x/2)"
    reduced = "" if 0 <= x <= math.pi else "exact reduction to [0, π], then "
    if x == math.pi or (x > 0 and x % math.pi == 0):
        inner = (
            "exact Wallis rational, correctly rounded"
            if n < EXACT_BELOW
            else "asymptotic series of Γ(m+½)/Γ(m) in double-double, correctly rounded"
        )
        return reduced + f"I_n(π): {inner}"
    return reduced + "incomplete beta ½ B(sin²x; (n+2)/2, ½) at 40 digits (mpmath)"


# ----------------------------------------------------------------- the printed recurrence


def _recurrence_too_long(n: int) -> PendcliError:
    return out_of_range(
        "n", f"{n}", f"-1 <= n <= {RECURRENCE_MAX_N:.0e}", " for the recurrence (n/2 steps)"
    )


def integral_recurrence(n: int, x: float = math.pi) -> float:
    """Charbonnier's recurrence in double precision, exactly as printed (I_0 = 1 - cos x)."""
    check_n(n)
    if n > RECURRENCE_MAX_N:
        raise _recurrence_too_long(n)
    c, s = math.cos(x), math.sin(x)
    if n == -1:
        return x
    prev = 1.0 - c if n % 2 == 0 else x  # I_0 or I_(-1)
    k = 0 if n % 2 == 0 else -1
    while k < n:
        k += 2
        prev = (-c * s**k + k * prev) / (k + 1)
    return prev


def integral_recurrence_sequence(n_max: int, x: float = math.pi) -> list[float]:
    """:func:`integral_recurrence` for n = -1..n_max at once (index n + 1), the same operations.

    Both parity chains are carried from row to row: n_max/2 steps each, not n²/4 in all.
    """
    check_n(n_max)
    if n_max > RECURRENCE_MAX_N:
        raise _recurrence_too_long(n_max)
    c, s = math.cos(x), math.sin(x)
    chains = [1.0 - c, x]  # I_0, I_(-1)
    out = [x, chains[0]][: n_max + 2]
    for k in range(1, n_max + 1):
        chains[k % 2] = (-c * s**k + k * chains[k % 2]) / (k + 1)
        out.append(chains[k % 2])
    return out


def integral_recurrence_with_error(n: int, x: float = math.pi) -> tuple[float, float]:
    """(:func:`integral_recurrence`, a running bound on its absolute rounding error).

    Each step adds a few roundings of its two terms, and the bound carried from I_(n-2) is
    scaled by n/(n+1) as the value is; I_0 = 1 - cos x starts with cos x's rounding, all of
    which remains when I_n(x) is tiny (small x): the bound then exceeds the value itself.
    """
    check_n(n)
    if n > RECURRENCE_MAX_N:
        raise _recurrence_too_long(n)
    eps = 2.0**-53
    c, s = math.cos(x), math.sin(x)
    if n == -1:
        return x, 0.0
    prev, err = (1.0 - c, 2 * eps) if n % 2 == 0 else (x, 0.0)
    k = 0 if n % 2 == 0 else -1
    while k < n:
        k += 2
        term = c * s**k
        prev = (-term + k * prev) / (k + 1)
        # cos x, sin x rounded (s**k then carries k of them), then 4 roundings of the step
        err = (k * err + eps * ((k + 3) * abs(term) + 4 * k * abs(prev))) / (k + 1)
    return prev, err
