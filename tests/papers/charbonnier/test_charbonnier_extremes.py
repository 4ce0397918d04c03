"""Charbonnier's I_n and first-order amplitude loss far outside the printed range.

References are independent of the code under test: I_n(π) = B(½, (n+2)/2) from mpmath's gamma
functions at 50 digits; I_n(x) from the positive hypergeometric series written out here at 50
digits (no beta-function code); the amplitude loss from closed forms (n = 0, 1, 2) written
out here and from direct ODE integration.
"""

from __future__ import annotations

import math
from functools import cache

import mpmath
import pytest

from pendcli.base.errors import PendcliError
from pendcli.papers.charbonnier import model as ch
from pendcli.papers.charbonnier import resistance as cr

pytestmark = pytest.mark.extremes


# The references are pure functions of (n, x), kept once computed (an mpf is immutable): the
# grid's values serve both its own test and the bounds over it (test_integral_fast_bounded_on_grid
# and the recurrence's error bound read 40 of the same points again).
@cache
def ref_pi(n: int):
    with mpmath.workdps(50):
        return (
            mpmath.gamma(mpmath.mpf(1) / 2)
            * mpmath.gamma(mpmath.mpf(n + 2) / 2)
            / (mpmath.gamma(mpmath.mpf(n + 3) / 2))
        )


def series_0_half(n: int, x):
    """∫_0^x sin^(n+1) = sin^(n+2)x cos x/(n+2) Σ_k Π_(j<k) (n+3+2j)/(n+4+2j) sin^(2k)x."""
    s, c = mpmath.sin(x), mpmath.cos(x)
    u = s * s
    term, total, k = mpmath.mpf(1), mpmath.mpf(0), n + 3
    tiny = mpmath.mpf(10) ** -55
    while term > total * tiny:
        total += term
        term = term * u * k / (k + 1)
        k += 2
    return s ** (n + 2) * c / (n + 2) * total


@cache
def ref_x(n: int, x: float):
    """I_n(x) for any real x: reduction mod π and the sign rules done in mpmath."""
    with mpmath.workdps(60):
        xm = mpmath.mpf(x)
        sign = 1
        if xm < 0:
            xm, sign = -xm, (1 if n % 2 == 0 else -1)
        q = int(mpmath.floor(xm / mpmath.pi))
        r = xm - q * mpmath.pi
        full = ref_pi(n)

        def base(t):  # ∫_0^t sin^(n+1), 0 <= t <= π
            return (
                full - series_0_half(n, mpmath.pi - t)
                if 2 * t > mpmath.pi
                else (series_0_half(n, t))
            )

        if n % 2 == 1:  # even power: every half-period adds I_n(π)
            value = q * full + base(r)
        else:  # odd power: half-periods cancel in pairs; the partial one carries (-1)^q
            value = base(r) if q % 2 == 0 else full - base(r)
        return sign * value


def ulps(value: float, reference) -> float:
    with mpmath.workdps(60):
        return float(abs(mpmath.mpf(value) - reference) / math.ulp(float(reference)))


N_PI = [-1, 0, 1, 2, 5, 59, 60, 61, 100, 199, 200, 999, 1837, 10**4, 10**5, 10**7, 10**9, 10**12]
N_PI += [10**15]


@pytest.mark.parametrize("n", N_PI)
def test_integral_pi_correctly_rounded_up_to_1e15(n):
    assert ulps(ch.integral_pi(n), ref_pi(n)) <= 0.5 + 1e-3


GRID = [
    (n, x)
    for n in (1, 10, 100, 1000, 10**4)
    for x in (1e-3, 0.3, 1.0, 1.4, 2.0, 3.0, 3.14)
    if not (n == 10**4 and x in (1e-3, 0.3, 1.0, 2.0, 3.0, 3.14))  # underflow / cheap refs
] + [(5, 1.3), (100, 1.5), (10, 10.0), (11, 10.0), (3, -2.5), (4, -2.5), (50, 1000.0)]


@pytest.mark.parametrize(("n", "x"), GRID)
def test_integral_general_x_within_two_ulp(n, x):
    reference = ref_x(n, x)
    if abs(float(reference)) < 1e-290:  # subnormal or below: only an absolute error means much
        assert abs(ch.integral(n, x) - float(reference)) <= 1e-300
        return
    assert ulps(ch.integral(n, x), reference) <= 2.0


def test_rounding_sin2_is_the_loss_and_the_correction_removes_it():
    """The naive call loses ~a ulp; integral_fast's δ·pdf correction takes most of it back."""
    from pendcli.papers.charbonnier.speed import naive_betainc

    n, x = 10**4, 1.4
    reference = ref_x(n, x)
    naive = ulps(naive_betainc(n, x), reference)
    fast = ulps(ch.integral_fast(n, x), reference)
    assert naive > 1000  # measured 7e4 ulp
    assert fast < 50  # what is left is scipy's own betainc error
    assert ulps(ch.integral(n, x), reference) <= 1.0


def test_integral_fast_bounded_on_grid():
    worst = max(
        ulps(ch.integral_fast(n, x), ref_x(n, x))
        for n, x in GRID
        if 0 <= x <= math.pi and abs(float(ref_x(n, x))) > 1e-290
    )
    assert worst < 500  # scipy's betainc at large a; measured up to ~370 ulp at (1000, 0.7)


def test_recurrence_exact_at_pi_but_breaks_at_small_x():
    for n in (1, 10, 1001, 10**5):
        assert float(abs(ch.integral_recurrence(n, math.pi) - ref_pi(n)) / ref_pi(n)) < 1e-13
    # at small x it subtracts nearly equal numbers: garbage, not a few lost digits
    rel = float(abs(ch.integral_recurrence(100, 0.5) - ref_x(100, 0.5)) / ref_x(100, 0.5))
    assert rel > 1.0
    rel_ok = float(abs(ch.integral_recurrence(10, 2.0) - ref_x(10, 2.0)) / ref_x(10, 2.0))
    assert rel_ok < 1e-12


def test_printed_products_overflow_as_floats():
    from pendcli.papers.charbonnier.speed import printed_products

    assert ulps(printed_products(150), ref_pi(150)) < 4
    with pytest.raises(OverflowError):
        printed_products(400)


def test_scipy_beta_loses_digits_where_integral_pi_does_not():
    from scipy.special import beta

    n = 10**4
    scipy_err = float(abs(beta(0.5, (n + 2) / 2) - ref_pi(n)) / ref_pi(n))
    assert scipy_err > 1e-13  # measured 9e-12 (scipy 1.17)
    assert ulps(ch.integral_pi(n), ref_pi(n)) <= 1.0


@pytest.mark.parametrize(
    ("n", "x"), [(10**15 + 1, math.pi), (5, math.inf), (5, math.nan), (-2, 1.0), (5, 2e6)]
)
def test_out_of_range_is_one_line_error(n, x):
    with pytest.raises(PendcliError) as info:
        ch.integral(n, x)
    assert "\n" not in str(info.value)


# --- Charbonnier's first-order amplitude loss (no. 16) -------------------------------------


def closed_form_loss(beta: float, n: int):
    """(α1 - α)/α for y'' + y + β y'^n = 0 over one swing, n = 0, 1, 2 (written out here)."""
    with mpmath.workdps(40):
        b = mpmath.mpf(beta)
        if n == 0:
            return -2 * b
        if n == 1:
            return mpmath.exp(-b * mpmath.pi / (2 * mpmath.sqrt(1 - b * b / 4))) - 1
        c = -mpmath.exp(-2 * b) * (1 / (2 * b) + 1 / (4 * b * b))
        y1 = mpmath.findroot(
            lambda y: c * mpmath.exp(-2 * b * y) - y / (2 * b) + 1 / (4 * b * b), 1 - 4 * b / 3
        )
        return y1 - 1


@pytest.mark.parametrize("n", [0, 1, 2])
@pytest.mark.parametrize("beta", [1e-4, 1e-2, 0.3])
def test_ode_matches_closed_forms(n, beta):
    ode = cr.relative_loss_ode(beta, n, rtol=1e-12).relative_loss
    assert ode == pytest.approx(float(closed_form_loss(beta, n)), rel=1e-8)


@pytest.mark.parametrize("n", [1, 2])
def test_first_order_limit_is_where_the_error_reaches_one_percent(n):
    lim = cr.first_order_limit(n)
    beta = lim["beta"]
    exact = closed_form_loss(beta, n)
    error = float(abs(cr.relative_loss_first_order(beta, n) - exact) / abs(exact))
    assert error == pytest.approx(0.01, rel=0.02)
    # and the formula is better than 1% below that β, worse above
    for factor, below in ((0.5, True), (2.0, False)):
        b = beta * factor
        e = float(abs(cr.relative_loss_first_order(b, n) - closed_form_loss(b, n)))
        assert (e / abs(float(closed_form_loss(b, n))) < 0.01) is below


def test_friction_formula_exact_and_limits():
    assert cr.relative_loss_first_order(0.4, 0) == pytest.approx(-0.8, rel=1e-15)
    assert cr.relative_loss_ode(0.4, 0, rtol=1e-12).relative_loss == pytest.approx(-0.8, rel=1e-9)
    with pytest.raises(PendcliError):
        cr.relative_loss_ode(1.0, 0)
    with pytest.raises(PendcliError):
        cr.relative_loss_ode(3.0, 1)  # overdamped: no second elongation


@pytest.mark.parametrize("g", [9.81, 3.7])
def test_physical_formula_matches_the_first_printed_form_and_the_dimensionless_one(g):
    """Δα = -(b_n/g)(αgT/π)^n I_n(π) (what the code evaluates) equals the first printed form
    -b_n k^(n-2) α^n l0^(n-1) I_n(π), here for n = 2 (k^0 = 1, I_2(π) = 4/3 by hand), and
    -β I_n(π) α with β = b_n v_m^n/(gα), v_m = kαl0."""
    length, alpha, b2 = 0.8, 0.1, 0.02
    by_hand = -b2 * alpha**2 * length * 4 / 3
    assert cr.amplitude_loss_first_order(b2, 2, alpha, length, g) == pytest.approx(
        by_hand, rel=1e-14
    )
    v_m = alpha * math.sqrt(g * length)
    beta = b2 * v_m**2 / (g * alpha)
    assert alpha * cr.relative_loss_first_order(beta, 2) == pytest.approx(by_hand, rel=1e-14)


@pytest.mark.parametrize(
    ("n", "x"),
    [(10**6, 1.5707), (10**9, 1.5707), (10**9, 1.5708), (10**12, 1.5708), (10**15, 1.5707963)],
)
def test_huge_n_near_half_pi(n, x):
    """Beyond the positive series' reach: mpmath's incomplete beta at 80 digits (twice the
    working precision of the code under test)."""
    with mpmath.workdps(80):
        a = mpmath.mpf(n + 2) / 2
        part = mpmath.betainc(a, 0.5, 0, mpmath.sin(mpmath.mpf(x)) ** 2) / 2
        reference = part if 2 * x <= math.pi else mpmath.beta(a, 0.5) - part
    assert ulps(ch.integral(n, x), reference) <= 1.0


def test_underflow_and_negligible_tail_are_exact():
    """I_n(x) below half the smallest subnormal is 0; a tail below 1e-20 leaves I_n(π)."""
    assert ch.integral(10**5, 1.0) == 0.0
    assert ch.integral(10**12, 1.5707) == 0.0  # sin^(n+1) < 1e-700 there
    for n in (10**5, 10**12):
        assert ch.integral(n, 2.0) == ch.integral_pi(n)


@pytest.mark.parametrize("g", [9.81, 2.0])
def test_perturbed_pendulum_matches_the_closed_form_for_any_g(g):
    """The formula checks' ODE for b_2 v² with ε = δ/(α l0) is y'' + y + δ y'² = 0 in
    τ = kt, y = θ/α: its relative amplitude change is the n = 2 closed form, whatever g
    (the table's g is an assumption the residuals do not depend on)."""
    import numpy as np

    from pendcli.papers.charbonnier.perturbation import CheckPendulum, measure, monomial
    from pendcli.verify.formula_engine import DEFAULT_INTEGRATOR

    p = CheckPendulum(g, 1.5, 0.2)
    phi, scale = monomial(p, 2)
    deltas = np.array([0.04, 0.01])
    events, _ = measure(p, phi, deltas * scale, DEFAULT_INTEGRATOR)
    for delta, theta_end, t_end in zip(deltas, events["theta_end"], events["t_end"], strict=True):
        assert (theta_end - p.alpha) / p.alpha == pytest.approx(
            float(closed_form_loss(delta, 2)), rel=1e-9
        )
        # ΔT = 0 to first order (no. 13): what is left is O(δ²) (measured 0.50·δ² .. 0.52·δ²)
        assert 0.4 * delta**2 < t_end * p.k - math.pi < 0.6 * delta**2


# --- the measured domains of `charbonnier integral --method` ---------------------


def test_recurrence_error_bound_covers_the_measured_error():
    """The running bound of integral_recurrence_with_error is never below the true error, and
    at most ~1e3 times it where digits are lost (so its warning is neither silent nor idle)."""
    for n in (1, 2, 10, 11, 100, 101, 1000):
        for x in (0.01, 0.1, 0.5, 1.0, 1.4, 2.0, 3.0, math.pi, 10.0):
            value, bound = ch.integral_recurrence_with_error(n, x)
            assert value == ch.integral_recurrence(n, x)
            reference = ref_x(n, x)
            if abs(float(reference)) < 1e-290:
                continue
            with mpmath.workdps(60):
                error = float(abs(mpmath.mpf(value) - reference))
            assert error <= bound, (n, x)
            assert bound <= 1e3 * max(error, 1e-16 * abs(float(reference))), (n, x)


def test_quad_domain_is_measured():
    """Up to QUAD_MAX_N quad (epsrel 1e-10) keeps 1e-10; beyond, it can lose the peak."""
    from pendcli.papers.charbonnier.speed import QUAD_MAX_N, quad_power

    for x in (0.5, 1.0, 1.4, 1.6, 1.87, 2.0, 2.39, 2.77, 3.0, 3.09, math.pi):
        reference = ref_x(QUAD_MAX_N, x)
        if abs(float(reference)) < 1e-290:
            continue
        value = quad_power(QUAD_MAX_N, x, 1e-10)[0]
        assert float(abs((value - reference) / reference)) < 1e-10, x
    for n, x in ((10**5, 1.87), (10**5, 2.39), (10**7, math.pi)):  # first failures measured
        value = quad_power(n, x, 1e-10)[0]
        assert float(abs((value - ref_x(n, x)) / ref_x(n, x))) > 0.5


def test_products_domain_is_where_they_overflow():
    from pendcli.papers.charbonnier.speed import printed_products, products_max_n

    limit = products_max_n()
    assert 250 < limit < 350  # (n/2)!-sized products pass 1.8e308 near n = 300
    assert ulps(printed_products(limit), ref_pi(limit)) <= 2.0
    for n in (limit + 1, limit + 2, 10 * limit):
        with pytest.raises(OverflowError):
            printed_products(n)


@pytest.mark.parametrize(
    ("n", "method", "warned"),
    [(10**12, "gammaln", True), (10**3, "gammaln", False), (1, "asymptotic", True),
     (30, "asymptotic", False)],
)  # fmt: skip
def test_estimated_errors_warn_where_the_measured_error_is_large(n, method, warned):
    from pendcli.papers.charbonnier.speed import WARN_ABOVE, integral_by_method_checked

    value, warning = integral_by_method_checked(n, math.pi, method)
    measured = float(abs((value - ref_pi(n)) / ref_pi(n)))
    assert (warning is not None) == warned
    assert measured > WARN_ABOVE if warned else measured < WARN_ABOVE
