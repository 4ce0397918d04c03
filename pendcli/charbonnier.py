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
* :func:`integral`: I_n(x) for any real x, by exact reduction to [0, π], the symmetry
  sin(π - t) = sin t and the regularised incomplete beta function, choosing the form whose
  argument (sin²x or cos²x) is the small one so no digits are lost near 0, π/2 or π.
* :func:`integral_recurrence`: the printed recurrence in floating point, as Charbonnier
  would compute it. Exact at x = π; at small x it subtracts nearly equal numbers.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache

from pendcli.claims import Recomputed
from pendcli.errors import PendcliError

__all__ = [
    "MAX_N",
    "MAX_X",
    "integral",
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


def _integral_0_pi(n: int, x: float) -> float:
    """I_n(x) for 0 <= x <= π (x a double taken as exact)."""
    if x == 0.0:
        return 0.0
    if n == -1:
        return x
    if n == 0:
        return 2.0 * math.sin(0.5 * x) ** 2  # 1 - cos x without its cancellation at small x
    full = integral_pi(n)
    if x > 0.5 * math.pi:
        # ∫_0^x = I_n(π) - ∫_0^(π-x), with π - x carried to beyond double precision.
        rest = (math.pi - x) + _PI_LOW
        return full - _integral_0_pi(n, rest) if rest > 0 else full
    from scipy.special import betainc, betaincc

    a = 0.5 * (n + 2)
    s = math.sin(x)
    c = math.cos(x)
    # ∫_0^x sin^(n+1) = ½ I_n(π) · I_(sin²x)(a, ½); use whichever of sin²x, cos²x is small.
    if s * s <= c * c:
        ratio = float(betainc(a, 0.5, s * s))
    else:
        ratio = float(betaincc(0.5, a, c * c))
    return 0.5 * full * ratio


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
    q, r = _reduce_mod_pi(x)
    # Over [jπ, (j+1)π] the integrand is (-1)^(j(n+1)) sin^(n+1) of the base half-period.
    full = integral_pi(n)
    if (n + 1) % 2 == 0:  # even power: every half-period adds I_n(π)
        return q * full + _integral_0_pi(n, r)
    # odd power: the half-periods alternate; the last partial one has sign (-1)^q.
    if q % 2 == 0:
        return _integral_0_pi(n, r)
    # I_n(π) - I_n(r) = ∫_r^π = I_n(π - r): no cancellation when r is near π.
    return _integral_0_pi(n, _pi_minus(r))


def _pi_minus(r: float) -> float:
    return (math.pi - r) + _PI_LOW


def _reduce_mod_pi(x: float) -> tuple[int, float]:
    """x = qπ + r with 0 <= r < π, computed exactly (50 digits) then rounded once."""
    import mpmath

    with mpmath.workdps(50):
        xm = mpmath.mpf(x)
        q = int(mpmath.floor(xm / mpmath.pi))
        r = xm - q * mpmath.pi
        return q, float(r)


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
    """The printed general formula evaluated as printed: products of evens over odds (no recurrence)."""
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
    return reduced + "regularised incomplete beta (scipy.special.betainc/betaincc)"


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
    from pendcli.plotting import new_figure
    from pendcli.tables import load_paper_table

    n_max = max(n_max, 40)
    ns = list(range(-1, n_max + 1))
    values = [integral_pi(n) for n in ns]
    printed = [
        c for c in load_paper_table("charbonnier").claims if c.id.startswith("charbonnier.I_pi.n")
    ]
    with new_figure(path) as (fig, ax):
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
    from pendcli.tables import load_paper_table

    _check_n(n_max)
    if n_max > 10_000:
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
