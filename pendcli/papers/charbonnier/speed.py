"""Charbonnier's speed/accuracy families: I_n(π), I_n(x) and the amplitude lost per swing.

Each family (:class:`~pendcli.run.tradeoff_engine.Family`) has a reference from an independent
I_n(π) = B(½, (n+2)/2) and the positive hypergeometric series of I_n(x), both with mpmath at
50 digits (no beta-function code of pendcli), and the loss per swing by mpmath's ODE solver
at 40 digits.  The methods measured are pendcli's own (:mod:`pendcli.papers.charbonnier.model`)
and the textbook ones a reader might try instead (the printed products as floats, scipy's
beta and gammaln, the naive betainc call, adaptive quadrature).

:func:`integral_with_choice_checked` is what ``pendcli charbonnier integral --tol/--method``
runs: the cheapest method the published table ``tables/tradeoff/integral_{pi,x}.csv`` says
meets ``tol``, or the forced one.  A forced method is refused outside its measured domain
(the products beyond their overflow, quadrature beyond :data:`QUAD_MAX_N`) and carries a
warning where its estimated error exceeds :data:`WARN_ABOVE` (the recurrence's running
rounding-error bound, gammaln's cancellation, the asymptotic series' first omitted term).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cache, partial
from typing import Any

from pendcli.base.errors import PendcliError, invalid_value, out_of_range
from pendcli.run.tradeoff_engine import Candidate, Family, choose, measured_points

__all__ = [
    "FAMILIES",
    "INTEGRAL_METHODS",
    "QUAD_MAX_N",
    "WARN_ABOVE",
    "asymptotic_pi",
    "exact_rational",
    "gammaln_ratio",
    "integral_by_method",
    "integral_by_method_checked",
    "integral_with_choice",
    "integral_with_choice_checked",
    "naive_betainc",
    "printed_products",
    "products_max_n",
    "quad_power",
    "reference_integral_pi",
    "reference_integral_x",
    "reference_loss",
    "scipy_beta",
]


# ---------------------------------------------------------------------------------------------
# References (mpmath, independent of pendcli's integral code)


def reference_integral_pi(n: int) -> Any:
    """I_n(π) = B(½, (n+2)/2) by mpmath at 50 digits."""
    import mpmath

    with mpmath.workdps(50):
        return mpmath.beta(mpmath.mpf(1) / 2, mpmath.mpf(n + 2) / 2)


def reference_integral_x(problem: tuple[int, float]) -> Any:
    """The positive hypergeometric series at 50 digits, independent of any beta-function code.

    I_n(x) = sin^(n+2)x cos x/(n+2) · Σ_k Π_(j<k) (n+3+2j)/(n+4+2j) sin^(2k)x  (x <= π/2; all
    terms positive), and I_n(x) = B(½, (n+2)/2) - I_n(π - x) beyond π/2.
    """
    import mpmath

    n, x = problem
    with mpmath.workdps(50):
        xm = mpmath.mpf(x)
        if 2 * xm > mpmath.pi:
            full = mpmath.beta(mpmath.mpf(1) / 2, mpmath.mpf(n + 2) / 2)
            return full - _series_0_half(n, mpmath.pi - xm)
        return _series_0_half(n, xm)


def _series_0_half(n: int, x: Any) -> Any:
    import mpmath

    s, c = mpmath.sin(x), mpmath.cos(x)
    u = s * s
    term, total, k = mpmath.mpf(1), mpmath.mpf(0), n + 3
    tiny = mpmath.mpf(10) ** -52
    while term > total * tiny:
        total += term
        term = term * u * k / (k + 1)
        k += 2
    return s ** (n + 2) * c / (n + 2) * total


def reference_loss(problem: tuple[int, float]) -> Any:
    """Δα/α per swing for resistance b_n v^n, (n, β), by mpmath's ODE solver at 40 digits."""
    from pendcli.papers.charbonnier.resistance import relative_loss_exact

    n, beta = problem
    return relative_loss_exact(beta, n, digits=40)


# ---------------------------------------------------------------------------------------------
# Methods a reader might use instead of pendcli's


def asymptotic_pi(n: int, terms: int) -> float:
    """√(π/m)·exp(-S) with S truncated to ``terms`` terms (the Charbonnier series)."""
    from pendcli.papers.charbonnier.model import log_gamma_ratio_coefficients

    m = (n + 2) / 2
    inv = 1.0 / m
    s = 0.0
    for c in reversed(log_gamma_ratio_coefficients()[:terms]):
        s = s * inv * inv + c
    return math.sqrt(math.pi * inv) * math.exp(-s * inv)


def quad_power(n: int, x: float, epsrel: float) -> tuple[float, int]:
    """∫_0^x sin^(n+1) t dt by scipy's adaptive quadrature: (value, integrand evaluations)."""
    import warnings

    from scipy.integrate import IntegrationWarning, quad

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IntegrationWarning)
        value, _, info = quad(
            lambda t: math.sin(t) ** (n + 1),
            0.0,
            x,
            epsabs=0.0,
            epsrel=epsrel,
            limit=200,
            full_output=1,
        )[:3]
    return value, int(info["neval"])


def printed_products(n: int) -> float:
    """The printed closed form (no. 15) evaluated as printed: each product as a float."""
    if n == -1:
        return math.pi
    if n % 2 == 0:
        return 2.0 * float(math.prod(range(2, n + 1, 2))) / float(math.prod(range(1, n + 2, 2)))
    return math.pi * float(math.prod(range(1, n + 1, 2))) / float(math.prod(range(2, n + 2, 2)))


def scipy_beta(n: int) -> float:
    """scipy.special.beta(½, (n+2)/2)."""
    from scipy.special import beta

    return float(beta(0.5, (n + 2) / 2))


def gammaln_ratio(n: int) -> float:
    """exp(gammaln(½) + gammaln(m) - gammaln(m + ½)), m = (n+2)/2."""
    from scipy.special import gammaln

    m = (n + 2) / 2
    return math.exp(gammaln(0.5) + gammaln(m) - gammaln(m + 0.5))


def exact_rational(n: int) -> float:
    """The exact rational of Charbonnier's recurrence, rounded (uncached: times the arithmetic)."""
    from pendcli.papers.charbonnier.model import integral_pi_rational

    q, p = integral_pi_rational(n)
    return float(q) * math.pi if p else float(q)


def naive_betainc(n: int, x: float) -> float:
    """The textbook call: ½ B(a,½) betainc(a, ½, sin²x), sin²x rounded, no correction."""
    from scipy.special import beta, betainc

    a = 0.5 * (n + 2)
    full = float(beta(a, 0.5))
    if x <= 0.5 * math.pi:
        return 0.5 * full * float(betainc(a, 0.5, math.sin(x) ** 2))
    return full - 0.5 * full * float(betainc(a, 0.5, math.sin(x) ** 2))


def _integral_pi(n: int) -> float:
    from pendcli.papers.charbonnier.model import integral_pi

    return integral_pi(n)


def _recurrence_pi(n: int) -> float:
    from pendcli.papers.charbonnier.model import integral_recurrence

    return integral_recurrence(n, math.pi)


# ---------------------------------------------------------------------------------------------
# --method and --tol of `pendcli charbonnier integral`


_PI_ONLY: dict[str, Callable[[int, dict[str, str]], float]] = {
    "exact-rational": lambda n, o: exact_rational(n),
    "products": lambda n, o: printed_products(n),
    "scipy-beta": lambda n, o: scipy_beta(n),
    "gammaln": lambda n, o: gammaln_ratio(n),
    "asymptotic": lambda n, o: asymptotic_pi(n, int(o.get("terms", "12"))),
    "integral_pi": lambda n, o: _integral_pi(n),
}
INTEGRAL_METHODS = ("recurrence", "quad", "fast", "pendcli", "betainc", *_PI_ONLY)


def _unknown_method(method: str) -> PendcliError:
    return invalid_value("method", method, f"one of {', '.join(INTEGRAL_METHODS)}")


# Domains measured against mpmath at 50 digits
# (tests/papers/charbonnier/test_charbonnier_extremes.py re-measures them): adaptive quadrature
# (epsrel 1e-10) keeps a relative error <= 2e-10 up to n = 7e4 on 4000 x in (π/2, π]; from n = 1e5
# it misses the peak of width ~1/√n at some x (1.87, 2.39, 2.77) and returns 0, at x = π from n =
# 1e7.  The limit keeps a factor 3 below the first failure.
QUAD_MAX_N = 3 * 10**4
WARN_ABOVE = 1e-10  # an estimated relative error above this is reported on stderr


@cache
def products_max_n() -> int:
    """The largest n for which the printed products as floats (and every smaller n's) work.

    Measured by calling :func:`printed_products` upward until float() of a product overflows.
    """
    n = 0
    while True:
        try:
            printed_products(n + 1)
        except OverflowError:
            return n
        n += 1


def _refuse_outside_domain(n: int, x: float, method: str) -> None:
    """PendcliError for an input where the method is known to fail (not merely lose digits)."""
    if method == "products" and n > products_max_n():
        raise out_of_range(
            "n",
            f"{n}",
            f"-1 <= n <= {products_max_n()} "
            "(measured: beyond, the integer products overflow a double)",
            " for method products",
        )
    if method == "quad" and n > QUAD_MAX_N:
        raise out_of_range(
            "n",
            f"{n}",
            f"-1 <= n <= {QUAD_MAX_N:.0e} "
            "(measured: beyond, it misses the peak of sin^(n+1) and returns ~0)",
            " for method quad",
        )


def _estimated_error(n: int, x: float, method: str, setting: str) -> tuple[float, float]:
    """(value, estimated relative error) for the methods whose error can be estimated."""
    from scipy.special import gammaln

    from pendcli.papers.charbonnier import model

    if method == "recurrence":
        value, bound = model.integral_recurrence_with_error(n, x)
        # a bound as large as the value leaves no digit, not even the sign: say so (inf)
        return value, bound / abs(value) if bound < abs(value) else math.inf
    if method == "gammaln":  # exp of a difference of two rounded values of size ~m log m
        m = (n + 2) / 2
        return gammaln_ratio(n), 2.0**-53 * (abs(gammaln(m)) + abs(gammaln(m + 0.5)))
    terms = int(dict(kv.split("=", 1) for kv in setting.split(",") if "=" in kv).get("terms", 12))
    # asymptotic: the first omitted term of S (exp(-S) ~ 1, so it is a relative error)
    omitted = model.log_gamma_ratio_coefficients(terms + 1)[terms]
    return asymptotic_pi(n, terms), abs(omitted) * ((n + 2) / 2) ** -(2 * terms + 1)


def _warning(n: int, x: float, method: str, error: float) -> str | None:
    if not error > WARN_ABOVE:  # also catches nan
        return None
    why = {
        "recurrence": "the printed recurrence subtracts nearly equal numbers at this x",
        "gammaln": "gammaln(m) - gammaln(m+½) cancels at large m",
        "asymptotic": "the asymptotic series is truncated too early at this n",
    }[method]
    size = (
        "its estimated rounding error exceeds the value itself, so no digit (not even the sign)"
        " can be trusted"
        if math.isinf(error)
        else f"estimated relative error {error:.1e}"
    )
    return (
        f"method {method} is unreliable at (n, x) = ({n}, {x:g}): {size} ({why}); "
        "the default method (no --method) is accurate here"
    )


def integral_by_method(n: int, x: float, method: str, setting: str = "") -> float:
    """I_n(x) by a named method of the tradeoff tables (what ``--method`` selects)."""
    return integral_by_method_checked(n, x, method, setting)[0]


def integral_by_method_checked(
    n: int, x: float, method: str, setting: str = ""
) -> tuple[float, str | None]:
    """(I_n(x), a warning or None) by a named method, refused outside its measured domain."""
    from pendcli.papers.charbonnier import model

    n, x = model.check_inputs(n, x)  # what the default method accepts, every method accepts
    _refuse_outside_domain(n, x, method)
    opts = dict(kv.split("=", 1) for kv in setting.split(",") if "=" in kv)
    if method in ("recurrence", "gammaln", "asymptotic"):
        if method != "recurrence" and x != math.pi:
            raise PendcliError(f"method {method!r} computes I_n(π) only; got x = {x}")
        value, error = _estimated_error(n, x, method, setting)
        return value, _warning(n, x, method, error)
    if method == "quad":
        if not 0.0 <= x <= math.pi:
            raise PendcliError(f"x = {x}: method quad takes 0 <= x <= π")
        return quad_power(n, x, float(opts.get("epsrel", "1e-10")))[0], None
    if method == "fast":
        return model.integral_fast(n, x), None
    if method in ("mpmath-40", "pendcli"):
        return model.integral(n, x), None
    if method in _PI_ONLY:
        if x != math.pi:
            raise PendcliError(f"method {method!r} computes I_n(π) only; got x = {x}")
        return _PI_ONLY[method](n, opts), None
    if method == "betainc":
        return naive_betainc(n, x), None
    raise _unknown_method(method)


def integral_with_choice(
    n: int, x: float, tol: float | None = None, method: str | None = None
) -> tuple[float, str]:
    """(value, label) of :func:`integral_with_choice_checked`, its warning dropped."""
    value, label, _ = integral_with_choice_checked(n, x, tol=tol, method=method)
    return value, label


def integral_with_choice_checked(
    n: int, x: float, tol: float | None = None, method: str | None = None
) -> tuple[float, str, str | None]:
    """I_n(x) by a forced ``method`` or by the cheapest one meeting ``tol``.

    Returns (value, label, warning or None).  The choice reads the published table of family
    integral_pi (x = π) or integral_x; outside the range that table measured (n beyond its
    largest n, x outside [0, π]) the measured errors say nothing, so the default Charbonnier
    ``integral`` is used and the label says why.
    """
    from pendcli.papers.charbonnier import model

    if method is not None:
        if method not in INTEGRAL_METHODS:
            raise _unknown_method(method)
        value, warning = integral_by_method_checked(n, x, method)
        return value, f"{method} (forced by --method)", warning
    if tol is None:
        raise PendcliError("give --tol or --method")
    name = "integral_pi" if x == math.pi else "integral_x"
    chosen = choose(name, tol, measured_points(_BY_NAME[name]))
    n_max = max(p if isinstance(p, int) else p[0] for p in _BY_NAME[name].problems)
    if n > n_max or not 0.0 <= x <= math.pi:
        return (
            model.integral(n, x),
            f"{model.integral_method(n, x)} (default: (n, x) outside the range measured in "
            f"tables/tradeoff/{name}.csv, n <= {n_max}, 0 <= x <= π)",
            None,
        )
    value, warning = integral_by_method_checked(n, x, chosen.method, chosen.setting)
    return (
        value,
        f"{chosen.method} ({chosen.setting}): cheapest with measured worst error "
        f"{chosen.error:.1e} <= tol {tol:g} in {name}, {chosen.seconds:.1e} s/evaluation",
        warning,
    )


# ---------------------------------------------------------------------------------------------
# Candidates


def _epsrels(quick: bool) -> tuple[float, ...]:
    return (1e-2, 1e-6, 1e-12) if quick else (1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13)


def _integral_pi_candidates(quick: bool) -> list[Candidate]:
    terms = (0, 1, 3) if quick else (0, 1, 2, 3, 4, 6)
    out = [
        Candidate("integral_pi", "Wallis n<200, else double-double series", _integral_pi),
        Candidate("exact-rational", "Fraction, recurrence", exact_rational),
        Candidate("recurrence", "double, x = π: the Wallis-type product", _recurrence_pi),
        Candidate("products", "evens/odds as floats", printed_products),
        Candidate("scipy-beta", "beta(1/2, m)", scipy_beta),
        Candidate("gammaln", "exp(gammaln diff)", gammaln_ratio),
    ]
    out += [Candidate("asymptotic", f"terms={k}", partial(asymptotic_pi, terms=k)) for k in terms]
    out += [
        Candidate("quad", f"epsrel={e:.0e}", partial(quad_power, x=math.pi, epsrel=e))
        for e in _epsrels(quick)
    ]
    return out


def _quad_problem(problem: tuple[int, float], epsrel: float) -> tuple[float, int]:
    return quad_power(problem[0], problem[1], epsrel)


def _loss_ode(problem: tuple[int, float], rtol: float, method: str) -> tuple[float, int]:
    from pendcli.papers.charbonnier.resistance import relative_loss_ode

    r = relative_loss_ode(problem[1], problem[0], rtol=rtol, method=method)
    return r.relative_loss, r.evaluations


def _integral_x_candidates(quick: bool) -> list[Candidate]:
    from pendcli.papers.charbonnier import model

    out = [
        Candidate("pendcli", "mpmath betainc, 40 digits", lambda p: model.integral(*p)),
        Candidate("fast", "scipy betainc + δ·pdf", lambda p: model.integral_fast(*p)),
        Candidate("betainc", "scipy betainc, sin²x rounded", lambda p: naive_betainc(*p)),
        Candidate("recurrence", "double, upward", lambda p: model.integral_recurrence(*p)),
    ]
    out += [
        Candidate("quad", f"epsrel={e:.0e}", partial(_quad_problem, epsrel=e))
        for e in _epsrels(quick)
    ]
    return out


def _loss_candidates(quick: bool) -> list[Candidate]:
    from pendcli.papers.charbonnier.resistance import relative_loss_first_order

    rtols = (1e-3, 1e-8) if quick else (1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
    out = [
        Candidate(
            "first-order", "Charbonnier no. 16", lambda p: relative_loss_first_order(p[1], p[0])
        )
    ]
    for method in ("DOP853",) if quick else ("DOP853", "RK45", "LSODA"):
        out += [
            Candidate(f"ode-{method}", f"rtol={r:.0e}", partial(_loss_ode, rtol=r, method=method))
            for r in rtols
            if not (method == "RK45" and r < 1e-10)
        ]
    return out


FAMILIES: list[Family] = [
    Family(
        "integral_pi",
        "Charbonnier's I_n(π) = B(1/2, (n+2)/2), n = 3, 100, 3000",
        [3, 100, 3000],
        reference_integral_pi,
        _integral_pi_candidates,
        quick_problems=[3, 100],
    ),
    Family(
        "integral_x",
        "I_n(x) = ∫_0^x sin^(n+1) t dt, (n, x) = (10, .5), (100, .3), (1000, 1.4), (100, 2.5)",
        [(10, 0.5), (100, 0.3), (1000, 1.4), (100, 2.5)],
        reference_integral_x,
        _integral_x_candidates,
        quick_problems=[(10, 0.5), (100, 0.3)],
    ),
    Family(
        "charbonnier_loss",
        "amplitude lost per swing Δα/α, resistance b_n v^n, (n, β) = (1, 0.01), (2, 0.01)",
        [(1, 0.01), (2, 0.01)],
        reference_loss,
        _loss_candidates,
    ),
]
_BY_NAME = {f.name: f for f in FAMILIES}
