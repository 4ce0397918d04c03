"""Charbonnier 1908: the integrals I_n(x) = ∫_0^x sin^(n+1) t dt and their table at x = π.

P. Charbonnier, « Sur la théorie des perturbations du pendule », Nouvelles annales de
mathématiques, 4e série, t. 8 (1908), p. 145-162 (seed 002_a39831d5a7e646cb.txt).

Reproduced here: section III, no. 15, the recurrence ``(n+1) I_n = -cos x sin^n x + n I_(n-2)``
with ``I_0 = 1 - cos x`` and ``I_(-1) = x``, the closed forms at x = π
``I_n(π) = 2·(2·4…n)/(1·3·5…(n+1))`` (n even) and ``π·(1·3·5…n)/(2·4·6…(n+1))`` (n odd),
and the printed table for n = 0..5 (plus I_0(π) = 2 and I_(-1)(π) = π stated in the text).

Methods (no assumption on g or units is needed: these are pure numbers):

* :func:`integral_pi_exact`: Charbonnier's own recurrence at x = π in exact rational
  arithmetic, I_n(π) = q·2 or q·π with q rational.
* :func:`integral_pi`: I_n(π) = B(1/2, (n+2)/2) in double precision, to a few ulp for every
  n >= -1 up to 10^12: the exact rational for n < 60, else √(π/m)·exp(-S(m)), m = (n+2)/2,
  with S the asymptotic series of log Γ(m+½)/Γ(m) whose coefficients come from Bernoulli
  numbers. (scipy.special.beta(0.5, m) loses up to 6 digits for m ~ 10^3..10^6.)
* :func:`integral`: I_n(x) for any real x, by exact reduction to [0, π] (the remainder kept as
  a double-double) and the incomplete beta function ½ B(sin²x; (n+2)/2, ½) at 40 digits, since
  rounding sin²x to a double alone costs (n+2)/2 ulp: < 0.5 ulp measured for n <= 10^4
  (against a positive series) and up to n = 10^12 near π/2 (against mpmath at 80 digits).
* :func:`integral_fast`: the same in double precision with scipy's betainc plus a first-order
  correction for the rounding of sin²x (~10 µs; scipy's own betainc error remains).
* :func:`integral_recurrence`: the printed recurrence in floating point, as Charbonnier
  would compute it. Exact at x = π; at small x it subtracts nearly equal numbers.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache

from pendcli.core.claims import Recomputed
from pendcli.core.errors import PendcliError

__all__ = [
    "MAX_N",
    "MAX_X",
    "integral",
    "integral_fast",
    "integral_pi",
    "integral_pi_exact",
    "integral_recurrence",
    "printed_closed_form",
    "recompute",
]

MAX_N = 10**12  # beyond this m**-1 terms are below 1e-12 ulp anyway, but n must stay an exact int
MAX_X = 1.0e6  # |x| accepted by integral(); reduction mod π is exact, the cost is the count q
_EXACT_BELOW = 60  # n below which I_n(π) is the exact rational, correctly rounded
_PI_LOW = math.sin(math.pi)  # π - math.pi: the part of π a double cannot hold (~1.22e-16)


def _check_n(n: int) -> int:
    if isinstance(n, bool) or not isinstance(n, int):
        raise PendcliError(f"n must be an integer >= -1, got {n!r}")
    if not -1 <= n <= MAX_N:
        raise PendcliError(f"n = {n} is out of range; valid range is -1 <= n <= {MAX_N:.0e}")
    return n


@cache
def integral_pi_exact(n: int) -> tuple[Fraction, int]:
    """I_n(π) = q·π**p exactly (p is 0 or 1), by Charbonnier's recurrence I_n = n/(n+1) I_(n-2)."""
    _check_n(n)
    if n > 100_000:
        raise PendcliError(f"exact I_n(π) is limited to n <= 100000 (got {n}); use integral_pi")
    # Iterate (not recurse) so large n do not exhaust the stack.
    q = Fraction(1) if n % 2 else Fraction(2)  # I_(-1)(π) = π, I_0(π) = 2
    for k in range(2 if n % 2 == 0 else 1, n + 1, 2):
        q *= Fraction(k, k + 1)
    return q, n % 2


def _bernoulli(count: int) -> list[Fraction]:
    """B_0..B_count (B_1 = -1/2), from the standard recurrence."""
    b = [Fraction(1)]
    for m in range(1, count + 1):
        b.append(-sum(math.comb(m + 1, k) * b[k] for k in range(m)) / (m + 1))
    return b


@cache
def _log_gamma_ratio_coefficients(terms: int = 12) -> tuple[float, ...]:
    """Coefficients c_k of log Γ(m+½)/Γ(m) = ½ log m + Σ c_k m^(-k), k = 1, 3, 5, ...

    From log Γ(z+a) ~ (z+a-½)log z - z + ½ log 2π + Σ (-1)^(k+1) B_(k+1)(a) / (k(k+1) z^k)
    with B_j(½) = (2^(1-j) - 1) B_j: c_k = (2^-k - 2) B_(k+1) / (k(k+1)) for odd k.
    """
    bern = _bernoulli(2 * terms + 1)
    coeffs = []
    for k in range(1, 2 * terms, 2):
        coeffs.append(float((Fraction(1, 2**k) - 2) * bern[k + 1] / (k * (k + 1))))
    return tuple(coeffs)


def integral_pi(n: int) -> float:
    """I_n(π) = ∫_0^π sin^(n+1) t dt = B(½, (n+2)/2), to a few ulp for -1 <= n <= 10^12."""
    _check_n(n)
    if n < _EXACT_BELOW:
        q, p = integral_pi_exact(n)
        return float(q) * math.pi if p else float(q)
    m = (n + 2) / 2
    inv = 1.0 / m
    inv2 = inv * inv
    # S = Σ c_k m^-k over odd k, summed from the smallest term; m >= 30.5 makes 12 terms ample.
    s = 0.0
    coeffs = _log_gamma_ratio_coefficients()
    for c in reversed(coeffs):
        s = s * inv2 + c
    s *= inv
    return math.sqrt(math.pi * inv) * math.exp(-s)


def _two_sum(a: float, b: float) -> tuple[float, float]:
    """a + b = hi + lo exactly (Knuth's error-free transformation)."""
    hi = a + b
    bb = hi - a
    return hi, (a - (hi - bb)) + (b - bb)


def _pi_minus(x: float, x_lo: float = 0.0) -> tuple[float, float]:
    """π - (x + x_lo) as a double-double; math.pi - x is exact (Sterbenz) for π/2 <= x <= π."""
    return _two_sum(math.pi - x, _PI_LOW - x_lo)


@cache
def _extended_sin_available() -> bool:
    import numpy as np

    return np.finfo(np.longdouble).nmant >= 60  # x87 80-bit (63 bits); plain double elsewhere


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
        t = mpmath.mpf(x) + mpmath.mpf(x_lo)
        f = mpmath.cos(t) if cosine else mpmath.sin(t)
        return float(f * f - mpmath.mpf(rounded))


_MP_DIGITS = 40  # working digits of the general-x path; measured < 0.5 ulp for n <= 10^4
_LOG_TINY = -1075 * math.log(2.0)  # log of half the smallest subnormal: below it, 0


def _integral_0_pi(n: int, x: float, x_lo: float = 0.0) -> float:
    """I_n(x + x_lo) for 0 <= x + x_lo <= π (a double-double argument), to < 1 ulp.

    I_n(x) = ½ B(sin²x; a, ½), a = (n+2)/2, behaves like (sin²x)^a: rounding sin²x to a double
    costs a ulp (300 ulp at n = 1000), and scipy's own betainc loses up to ~200 ulp at large a
    (measured, see pendcli.stability).  So sin²x and the incomplete beta function are evaluated
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
    # I_n(y) <= y sin^(n+1) y for y <= π/2 (the integrand grows on [0, y]): below the smallest
    # subnormal the answer is 0, and a tail below 1e-20 of I_n(π) leaves I_n(π) unchanged.
    # Deciding this first also keeps mpmath away from values it cannot bound.
    near = x if x <= 0.5 * math.pi else math.pi - x
    log_bound = math.log(near) + (n + 1) * math.log(math.sin(near)) if near > 0 else -math.inf
    if x <= 0.5 * math.pi and log_bound < _LOG_TINY:
        return 0.0
    if x > 0.5 * math.pi and log_bound < math.log(integral_pi(n)) - 46.0:
        return integral_pi(n)
    import mpmath

    with mpmath.workdps(_MP_DIGITS):
        t = mpmath.mpf(x) + mpmath.mpf(x_lo)
        a = mpmath.mpf(n + 2) / 2
        part = mpmath.betainc(a, 0.5, 0, mpmath.sin(t) ** 2) / 2
        if 2 * t <= mpmath.pi:
            return float(part)
        return float(mpmath.beta(a, 0.5) - part)


def integral_fast(n: int, x: float) -> float:
    """I_n(x), 0 <= x <= π, in ~10 µs: scipy's betainc plus a first-order rounding correction.

    The correction δ·dI/du (u = sin²x rounded, δ = the exact sin²x minus u, dI/du =
    ½ u^(a-1) (1-u)^(-½)) removes the a-fold amplification of the rounding of sin²x; what
    remains is scipy.special.betainc's own error (up to ~200 ulp at n ~ 1000, measured).
    """
    _check_n(n)
    x = float(x)
    if not 0.0 <= x <= math.pi:
        raise PendcliError(f"x = {x} is out of range for integral_fast; valid range is 0 <= x <= π")
    if n <= 0 or x == 0.0:
        return _integral_0_pi(n, x)
    from scipy.special import betainc, betaincc

    full = integral_pi(n)
    if x > 0.5 * math.pi:
        rest, rest_lo = _pi_minus(x)
        return full - _fast_half(n, rest, rest_lo, full, betainc, betaincc)
    return _fast_half(n, x, 0.0, full, betainc, betaincc)


def _fast_half(n, x, x_lo, full, betainc, betaincc) -> float:
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


def integral(n: int, x: float = math.pi) -> float:
    """I_n(x) = ∫_0^x sin^(n+1) t dt for integer n >= -1 and real |x| <= 1e6."""
    _check_n(n)
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise PendcliError(f"x must be a real number, got {x!r}")
    x = float(x)
    if not math.isfinite(x) or abs(x) > MAX_X:
        raise PendcliError(
            f"x = {x} is out of range; valid range is -{MAX_X:.0e} <= x <= {MAX_X:.0e}"
        )
    if n == -1:
        return x
    if 0.0 <= x <= math.pi:
        return _integral_0_pi(n, x)
    if x < 0:
        # sin^(n+1)(-t) = (-1)^(n+1) sin^(n+1) t, so I_n(-x) = (-1)^n I_n(x).
        value = integral(n, -x)
        return value if n % 2 == 0 else -value
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


def integral_recurrence(n: int, x: float = math.pi) -> float:
    """Charbonnier's recurrence in double precision, exactly as printed (I_0 = 1 - cos x)."""
    _check_n(n)
    if n > 10**7:
        raise PendcliError(f"the recurrence costs n/2 steps; n = {n} is over the limit 10^7")
    c, s = math.cos(x), math.sin(x)
    if n == -1:
        return x
    prev = 1.0 - c if n % 2 == 0 else x  # I_0 or I_(-1)
    k = 0 if n % 2 == 0 else -1
    while k < n:
        k += 2
        prev = (-c * s**k + k * prev) / (k + 1)
    return prev


def printed_closed_form(n: int) -> tuple[Fraction, int]:
    """The printed general formula as printed: products of evens over odds (no recurrence)."""
    _check_n(n)
    if n == -1:
        return Fraction(1), 1
    if n % 2 == 0:  # 2·(2·4…n)/(1·3·5…(n+1))
        num = math.prod(range(2, n + 1, 2))
        den = math.prod(range(1, n + 2, 2))
        return Fraction(2 * num, den), 0
    num = math.prod(range(1, n + 1, 2))  # π·(1·3·5…n)/(2·4·6…(n+1))
    den = math.prod(range(2, n + 2, 2))
    return Fraction(num, den), 1


def exact_text(q: Fraction, p: int) -> str:
    base = "π" if p else ""
    num = base if (q.numerator == 1 and base) else f"{q.numerator}{base}"
    return num if q.denominator == 1 else f"{num}/{q.denominator}"


def integral_method(n: int, x: float) -> str:
    """Which branch :func:`integral` takes, for display."""
    if n == -1:
        return "I_(-1)(x) = x"
    if n == 0:
        return "I_0(x) = 2 sin²(x/2)"
    reduced = "" if 0 <= x <= math.pi else "exact reduction to [0, π], then "
    if x == math.pi or (x > 0 and x % math.pi == 0):
        inner = "exact rational" if n < _EXACT_BELOW else "asymptotic series of Γ(m+½)/Γ(m)"
        return reduced + f"I_n(π): {inner}"
    return reduced + "incomplete beta ½ B(sin²x; (n+2)/2, ½) at 40 digits (mpmath)"


def recompute() -> dict[str, Recomputed]:
    """Every printed I_n(π), n = -1..5 (no. 15), recomputed."""
    out: dict[str, Recomputed] = {}
    for n in range(-1, 6):
        q, p = integral_pi_exact(n)
        value = integral_pi(n)
        out[f"charbonnier.I_pi.n{n}"] = Recomputed(
            value=value,
            method="recurrence in exact rationals; B(1/2,(n+2)/2) in floating point",
            note=f"Exact value {exact_text(q, p)}.",
        )
    return out


def plot_table(path, n_max: int = 5) -> None:
    """I_n(π) against n on log-log axes, printed entries marked, with the √(2π/n) asymptote."""
    from pendcli.core.plotting import new_figure
    from pendcli.core.tables import load_paper_table

    n_max = max(n_max, 40)
    ns = list(range(-1, n_max + 1))
    values = [integral_pi(n) for n in ns]
    printed = [
        c for c in load_paper_table("charbonnier").claims if c.id.startswith("charbonnier.I_pi.n")
    ]
    with new_figure(path) as (_fig, ax):
        ax.plot(
            [n + 2 for n in ns], values, "-", color="tab:blue", lw=1.2, label="recomputed I_n(π)"
        )
        ax.plot(
            [int(c.id.rsplit("n", 1)[1]) + 2 for c in printed],
            [c.number.value for c in printed],
            "o",
            mfc="none",
            color="tab:red",
            ms=8,
            label="printed (Charbonnier 1908, no. 15)",
        )
        ax.plot(
            [n + 2 for n in ns],
            [math.sqrt(2 * math.pi / (n + 2)) for n in ns],
            ":",
            color="gray",
            label="asymptote √(2π/(n+2))",
        )
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n + 2")
        ax.set_ylabel("I_n(π) = ∫₀^π sin^(n+1) x dx")
        ax.set_title("Charbonnier's I_n(π): printed entries and recomputation")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()


def table_rows(n_max: int = 5) -> list[dict]:
    """n = -1..n_max: printed (n <= 5), the printed closed form, the recurrence, the beta form."""
    from pendcli.core.tables import load_paper_table

    if isinstance(n_max, bool) or not isinstance(n_max, int) or not -1 <= n_max <= 10_000:
        raise PendcliError(f"--n-max = {n_max} is out of range; valid range is -1..10000")
    printed = {c.id: c for c in load_paper_table("charbonnier").claims}
    rows = []
    for n in range(-1, n_max + 1):
        q, p = integral_pi_exact(n)
        closed_q, closed_p = printed_closed_form(n)
        entry = printed.get(f"charbonnier.I_pi.n{n}")
        rows.append(
            {
                "n": n,
                "published": entry.published if entry else "",
                "exact": exact_text(q, p),
                "closed_form_matches_recurrence": (closed_q, closed_p) == (q, p),
                "recurrence_float": integral_recurrence(n, math.pi),
                "beta": integral_pi(n),
            }
        )
    return rows


def figures(outdir) -> list:
    """The report's Charbonnier figures: I_n(π) against n, printed entries marked."""
    from pathlib import Path

    path = Path(outdir) / "charbonnier-In-pi.png"
    plot_table(path, n_max=200)
    return [path]
