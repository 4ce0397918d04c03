"""Tisserand (1881): one check per checkable row of ``tables/equations/tisserand.toml``.

Derivation steps are verified exactly with sympy: the differentials (1), (2) against the
spherical pendulum's two first integrals, the substitution (3) into (4), (5), the expansions
before (6) and (7) as series in a scale x (u² = x·w, u0² = x·a, u1² = x·b), the three
integrals, the ellipse (17). The series in ψ and k't ((8), (11), (13), (15), (I), (II), (V))
are checked by the existing quadrature checks of ``formulas.py`` (observed orders), reused
through :func:`pendcli.core.ledger.check_from_formula_rows`. sympy is imported lazily.
"""

from __future__ import annotations

from functools import cache
from typing import Any

from pendcli.core.ledger import check_from_formula_rows
from pendcli.core.ledger_check import EquationCheck

ORDER = 3  # series in x kept through x² (fourth order in the angles)


@cache
def _formula_rows() -> tuple[Any, ...]:
    from pendcli.core.claims import shared_formula_rows
    from pendcli.papers.tisserand.formulas import formula_checks

    return tuple(shared_formula_rows("tisserand", formula_checks))


def _reuse(*ids: str) -> EquationCheck:
    return check_from_formula_rows(_formula_rows(), [f"tisserand.{i}" for i in ids])


def identity_check(difference: Any, what: str, method: str = "sympy") -> EquationCheck:
    """Holds when the difference simplifies to 0 (sympy)."""
    import sympy as sp

    zero = sp.simplify(difference) == 0
    return EquationCheck(
        holds=bool(zero),
        method=method,  # type: ignore[arg-type]
        detail=f"{what}: difference {'simplifies to 0' if zero else 'is not 0'}",
    )


@cache
def symbols() -> Any:
    """c, c0, c1 (cos θ, cos θ0, cos θ1), the scale x, w, a, b (u² = xw, u0² = xa, u1² = xb),
    ψ: the real sympy symbols every check here shares."""
    import sympy as sp

    return sp.symbols("c c0 c1 x w a b psi", real=True)


def energy_theta_dot_sq() -> Any:
    """θ'² from energy and angular momentum, apsides θ0, θ1 (c = cos θ), k = 1."""
    c, c0, c1, *_ = symbols()
    h2 = 2 * (1 - c0**2) * (1 - c1**2) / (c0 + c1)
    return 2 * (c - c0) + h2 * (1 / (1 - c0**2) - 1 / (1 - c**2))


def _big_p() -> Any:
    c, c0, c1, *_ = symbols()
    return 1 + c * c0 + c * c1 + c0 * c1


def eq_1() -> EquationCheck:
    """(1): k√2 dt = −sinθ √(cosθ0+cosθ1) dθ / √(...): θ'² against the first integrals."""
    c, c0, c1, *_ = symbols()
    printed = 2 * (c - c0) * (c1 - c) * _big_p() / ((1 - c**2) * (c0 + c1))
    return identity_check(printed - energy_theta_dot_sq(), "(θ')² from (1) − (θ')² from energy")


def eq_2() -> EquationCheck:
    """(2): dφ/dθ squared against h/sin²θ over θ' from the first integrals."""
    c, c0, c1, *_ = symbols()
    h2 = 2 * (1 - c0**2) * (1 - c1**2) / (c0 + c1)
    exact = h2 / (1 - c**2) ** 2 / energy_theta_dot_sq()
    printed = (1 - c0**2) * (1 - c1**2) / ((1 - c**2) * (c - c0) * (c1 - c) * _big_p())
    return identity_check(printed - exact, "(dφ/dθ)² from (2) − from the first integrals")


def _substitution_values(theta0: float, theta1: float, psi: float) -> dict[str, Any]:
    """cos θ, cos θ0, cos θ1 and dθ/dψ (exact derivative of (3)) at one point, 40 digits."""
    import sympy as sp

    t = sp.Symbol("t")
    u0, u1 = sp.sin(sp.Rational(str(theta0))), sp.sin(sp.Rational(str(theta1)))
    theta = sp.asin(sp.sqrt(u0**2 * sp.cos(t) ** 2 + u1**2 * sp.sin(t) ** 2))
    at = {t: sp.Rational(str(psi))}
    return {
        "c": sp.N(sp.cos(theta).subs(at), 40),
        "c0": sp.N(sp.cos(sp.Rational(str(theta0))), 40),
        "c1": sp.N(sp.cos(sp.Rational(str(theta1))), 40),
        "dtheta": sp.N(sp.diff(theta, t).subs(at), 40),
    }


# ψ in the first quarter, where θ falls from θ0: the sign convention of the printed roots.
POINTS = ((0.7, 0.3, 0.4), (1.1, 0.2, 1.3), (0.05, 0.04, 0.9))


def _at_points(printed: Any, exact: Any, what: str) -> EquationCheck:
    worst = 0.0
    for point in POINTS:
        v = _substitution_values(*point)
        p, e = printed(v), exact(v)
        worst = max(worst, float(abs(p - e) / abs(e)))
    return EquationCheck(
        holds=worst < 1e-30,
        method="sympy",
        detail=f"{what}, exact derivative of (3) at 3 points, 40 digits: max rel. {worst:.1e}",
    )


def result_dtheta_dpsi() -> EquationCheck:
    """dθ/√((cosθ−cosθ0)(cosθ1−cosθ)) = −√((cosθ+cosθ0)(cosθ+cosθ1))/(u√(1−u²)) dψ."""
    import sympy as sp

    def printed(v: dict[str, Any]) -> Any:
        c, c0, c1 = v["c"], v["c0"], v["c1"]
        u = sp.sqrt(1 - c**2)
        return -sp.sqrt((c + c0) * (c + c1)) / (u * c) * sp.sqrt((c - c0) * (c1 - c))

    return _at_points(printed, lambda v: v["dtheta"], "dθ/dψ printed against (3)")


def eq_4() -> EquationCheck:
    """(4): k√2 dt/dψ from (1) and (3)."""
    import sympy as sp

    def from_1(v: dict[str, Any]) -> Any:
        c, c0, c1 = v["c"], v["c0"], v["c1"]
        root = sp.sqrt((c - c0) * (c1 - c) * (1 + c * c0 + c * c1 + c0 * c1))
        return -sp.sqrt(1 - c**2) * sp.sqrt(c0 + c1) * v["dtheta"] / root

    def printed(v: dict[str, Any]) -> Any:
        c, c0, c1 = v["c"], v["c0"], v["c1"]
        big = sp.sqrt((c + c0) * (c + c1) * (c0 + c1))
        return big / (c * sp.sqrt(1 + c * c0 + c * c1 + c0 * c1))

    return _at_points(printed, from_1, "k√2 dt/dψ of (4) against (1) with (3)")


def eq_5() -> EquationCheck:
    """(5): dφ/dψ from (2) and (3)."""
    import sympy as sp

    def from_2(v: dict[str, Any]) -> Any:
        c, c0, c1 = v["c"], v["c0"], v["c1"]
        u0u1 = sp.sqrt((1 - c0**2) * (1 - c1**2))
        root = sp.sqrt((c - c0) * (c1 - c) * (1 + c * c0 + c * c1 + c0 * c1))
        return -u0u1 * v["dtheta"] / (sp.sqrt(1 - c**2) * root)

    def printed(v: dict[str, Any]) -> Any:
        c, c0, c1 = v["c"], v["c0"], v["c1"]
        u0u1 = sp.sqrt((1 - c0**2) * (1 - c1**2))
        big = sp.sqrt((c + c0) * (c + c1)) / sp.sqrt(1 + c * c0 + c * c1 + c0 * c1)
        return u0u1 / ((1 - c**2) * c) * big

    return _at_points(printed, from_2, "dφ/dψ of (5) against (2) with (3)")


# --- series in the scale x: u² = x w, u0² = x a, u1² = x b -------------------------------


def cosines() -> tuple[Any, Any, Any]:
    """cos θ, cos θ0, cos θ1 in the scale x: √(1 − xw), √(1 − xa), √(1 − xb)."""
    import sympy as sp

    _, _, _, x, w, a, b, _ = symbols()
    return sp.sqrt(1 - x * w), sp.sqrt(1 - x * a), sp.sqrt(1 - x * b)


def series_in_x(expr: Any, order: int = ORDER) -> Any:
    """expr's Taylor series in the scale x about 0, through x^(order − 1), expanded.

    Each coefficient is the exact n-th derivative at x = 0 over n!, a rational function of
    a, b, w put in lowest terms (every √(1 − x·) is 1 there); much faster than sympy's
    ``series`` on these nested roots, and the same polynomial. An expression not analytic
    at x = 0 gives an infinite coefficient, so a check on it cannot hold."""
    import sympy as sp

    x = symbols()[3]
    terms, derivative = [], expr
    for n in range(order):
        terms.append(sp.cancel(derivative.subs(x, 0)) * x**n / sp.factorial(n))
        if n + 1 < order:
            derivative = sp.diff(derivative, x)
    return sp.expand(sp.Add(*terms))


def sum_q_r() -> tuple[Any, Any, Any]:
    """S = u²+u0²+u1², Q = u⁴+u0⁴+u1⁴, R = u²u0²+u²u1²+u0²u1² in the scale x."""
    _, _, _, x, w, a, b, _ = symbols()
    return x * (w + a + b), x**2 * (w**2 + a**2 + b**2), x**2 * (w * a + w * b + a * b)


def _quarter_sum() -> Any:
    c, c0, c1 = cosines()
    return (1 + c * c0 + c * c1 + c0 * c1) / 4


def _eighth_product() -> Any:
    c, c0, c1 = cosines()
    return (c + c0) * (c + c1) * (c0 + c1) / 8


def result_expansion_sum() -> EquationCheck:
    """(1/4)(1 + cosθcosθ0 + ...) = 1 − S/4 − Q/16 + R/16 + ..."""
    s, q, r = sum_q_r()
    return identity_check(
        series_in_x(_quarter_sum()) - (1 - s / 4 - q / 16 + r / 16), "series to x²"
    )


def result_expansion_product() -> EquationCheck:
    """(1/8)(cosθ+cosθ0)(cosθ+cosθ1)(cosθ0+cosθ1) = 1 − S/2 − Q/16 + 3R/16 + ..."""
    s, q, r = sum_q_r()
    printed = 1 - s / 2 - q / 16 + 3 * r / 16
    return identity_check(series_in_x(_eighth_product()) - printed, "series to x²")


def square_from_4() -> Any:
    """(k dt/dψ √(1−u²))², from (4): half of product/sum = eighth product / quarter sum."""
    return _eighth_product() / _quarter_sum()


def result_square_from_4() -> EquationCheck:
    """« La formule (5) donnera » (k dt/dψ √(1−u²))² = 1 − S/4 − Q/16 − ...: from (4)."""
    s, q, _ = sum_q_r()
    found = identity_check(series_in_x(square_from_4()) - (1 - s / 4 - q / 16), "from (4), to x²")
    return EquationCheck(
        holds=found.holds,
        method="cross-reference",
        detail=f"(k dt/dψ √(1−u²))² is the square of (4) over 2: {found.detail}; (5) has no dt",
    )


def result_sqrt() -> EquationCheck:
    """k dt/dψ √(1−u²) = 1 − S/8 − 5Q/128 − R/64 + ..."""
    import sympy as sp

    s, q, r = sum_q_r()
    printed = 1 - s / 8 - 5 * q / 128 - r / 64
    return identity_check(series_in_x(sp.sqrt(square_from_4())) - printed, "series to x²")


def eq_6() -> EquationCheck:
    """(6): k dt/dψ = 1 − (u0²+u1²)/8 − 5(u0⁴+u1⁴)/128 − u0²u1²/64 + (3/8 − 5(u0²+u1²)/64)u²
    + 35u⁴/128 + ..."""
    import sympy as sp

    _, _, _, x, w, a, b, _ = symbols()
    c, _, _ = cosines()
    exact = sp.sqrt(square_from_4()) / c
    printed = (
        1
        - x * (a + b) / 8
        - 5 * x**2 * (a**2 + b**2) / 128
        - x**2 * a * b / 64
        + (sp.Rational(3, 8) - 5 * x * (a + b) / 64) * x * w
        + sp.Rational(35, 128) * x**2 * w**2
    )
    return identity_check(series_in_x(exact) - printed, "series of (4) to x²")


def dphi_over_u0u1() -> Any:
    """(1/(u0u1)) dφ/dψ from (5), in the scale x."""
    import sympy as sp

    x, w = symbols()[3:5]
    c, c0, c1 = cosines()
    return sp.sqrt((c + c0) * (c + c1)) / (x * w * c * sp.sqrt(4 * _quarter_sum()))


def eq_7() -> EquationCheck:
    """(7): (1/(u0u1)) dφ/dψ = 3/8 − (u0²+u1²)/32 + 1/u² + 35u²/128 + ..."""
    import sympy as sp

    _, _, _, x, w, a, b, _ = symbols()
    printed = sp.Rational(3, 8) - x * (a + b) / 32 + 1 / (x * w) + sp.Rational(35, 128) * x * w
    # The Laurent series of (5) to x: the Taylor series of u²·(5) to x², over u².
    laurent = series_in_x(x * w * dphi_over_u0u1()) / (x * w)
    return identity_check(sp.expand(laurent) - printed, "Laurent series of (5) to x")


def result_inverse_square_one() -> EquationCheck:
    """The coefficient of 1/u² in (7) is 1 to every order: u²·(1/(u0u1)) dφ/dψ → 1 as u → 0."""
    import sympy as sp

    x, w = symbols()[3:5]
    limit = sp.limit(x * w * dphi_over_u0u1(), w, 0)
    return identity_check(limit - 1, "exact limit of u²·(5)/(u0u1) at u = 0, u0, u1 symbolic")


def _integral_check(printed: Any, integrand: Any, what: str) -> EquationCheck:
    import sympy as sp

    psi = symbols()[7]
    derivative = sp.simplify(sp.diff(printed, psi) - integrand)
    at_zero = sp.simplify(printed.subs(psi, 0))
    zero = derivative == 0 and at_zero == 0
    return EquationCheck(
        holds=bool(zero),
        method="sympy",
        detail=f"{what}: d/dψ of the right side minus the integrand = {derivative}, "
        f"value at ψ = 0: {at_zero}",
    )


def _u2() -> Any:
    import sympy as sp

    *_, a, b, psi = symbols()
    return a * sp.cos(psi) ** 2 + b * sp.sin(psi) ** 2  # a = u0², b = u1²


def result_integral_inverse_square() -> EquationCheck:
    """∫₀^ψ dψ/u² = arctan((u1/u0) tan ψ)/(u0u1)."""
    import sympy as sp

    *_, a, b, psi = symbols()
    u0, u1 = sp.Symbol("u0", positive=True), sp.Symbol("u1", positive=True)
    printed = sp.atan(u1 / u0 * sp.tan(psi)) / (u0 * u1)
    integrand = 1 / _u2().subs({a: u0**2, b: u1**2})
    return _integral_check(printed, integrand, "∫dψ/u²")


def result_integral_u2() -> EquationCheck:
    """∫₀^ψ u² dψ = (u0²+u1²)ψ/2 + (u0²−u1²) sin 2ψ/4."""
    import sympy as sp

    *_, a, b, psi = symbols()
    printed = (a + b) * psi / 2 + (a - b) * sp.sin(2 * psi) / 4
    return _integral_check(printed, _u2(), "∫u² dψ")


def result_integral_u4() -> EquationCheck:
    """∫₀^ψ u⁴ dψ = (3(u0⁴+u1⁴)+2u0²u1²)ψ/8 + (u0⁴−u1⁴) sin 2ψ/4 + (u0²−u1²)² sin 4ψ/32."""
    import sympy as sp

    *_, a, b, psi = symbols()
    printed = (
        (3 * (a**2 + b**2) + 2 * a * b) * psi / 8
        + (a**2 - b**2) * sp.sin(2 * psi) / 4
        + (a - b) ** 2 * sp.sin(4 * psi) / 32
    )
    return _integral_check(printed, _u2() ** 2, "∫u⁴ dψ")


def eq_8() -> EquationCheck:
    """(8): kt and φ as series in ψ (quadrature checks of formulas.py)."""
    return _reuse("k_prime", "eq8_kt_sin2psi", "eq8_kt_sin4psi", "eq8_phi_psi", "eq8_phi_sin2psi")


def eq_11() -> EquationCheck:
    """(11): φ' = φ − φ1, the non-arctan part of (8)."""
    return _reuse("eq8_phi_psi", "eq8_phi_sin2psi")


def result_psi_before_13() -> EquationCheck:
    """ψ = k't − (u0²−u1²)(3/32 + 11(u0²+u1²)/256) sin 2ψ − (u0²−u1²)²(35/4096) sin 4ψ."""
    return _reuse("psi_in_psi_sin4psi")


def eq_13() -> EquationCheck:
    """(13), read with sin 4k't for the printed sin² 4k't (as (II) prints it)."""
    return _reuse("II_sin2", "II_sin4")


def eq_II() -> EquationCheck:
    """(II): ψ as a series in k't."""
    return _reuse("II_sin2", "II_sin4")


def result_second_approximation() -> EquationCheck:
    """ψ = k't − (3/32)(u0²−u1²) sin 2k't: the leading terms of (II)."""
    return _reuse("II_sin2")


def eq_14() -> EquationCheck:
    """(14): k'' = k'(1 + 9(u0²+u1²)/32): the leading terms of (I)'s k''."""
    return _reuse("k_second")


def eq_15() -> EquationCheck:
    """(15): φ' = (3/8)u0u1k''t + u0u1(u0²−u1²)(17/512) sin 2k't."""
    return _reuse("k_second", "V_sin2")


def eq_V() -> EquationCheck:
    """(V): the same as (15)."""
    return _reuse("k_second", "V_sin2")


def eq_I() -> EquationCheck:
    """(I), read with k = √(g/l): k' to sixth order, k'' to fourth (quadrature checks)."""
    return _reuse("k_prime", "k_second")


def eq_10() -> EquationCheck:
    """(10) with (3) and (16): the projection is (ρ0 cos ψ, ρ1 sin ψ), ψ the eccentric anomaly."""
    import sympy as sp

    *_, psi = symbols()
    r0, r1 = sp.symbols("rho0 rho1", positive=True)
    rho_sq = r0**2 * sp.cos(psi) ** 2 + r1**2 * sp.sin(psi) ** 2  # (3) times l², (16)
    tan_phi1 = r1 / r0 * sp.tan(psi)  # (10)
    cos_sq = 1 / (1 + tan_phi1**2)
    return identity_check(
        rho_sq * cos_sq - (r0 * sp.cos(psi)) ** 2,
        "ρ² cos² φ1 − (ρ0 cos ψ)²",
    )


def eq_III() -> EquationCheck:
    """(III) repeats (10)."""
    found = eq_10()
    return EquationCheck(found.holds, "cross-reference", f"(III) is (10): {found.detail}")


def _tan_sq_phi1() -> Any:
    """tan²φ1 = (u1²/u0²)(u0²−u²)/(u²−u1²): (10) squared with the tan²ψ of (3)."""
    *_, w, a, b, _ = symbols()
    return b / a * (a - w) / (w - b)


def result_tan_sq_psi() -> EquationCheck:
    """tan²ψ = (u0²−u²)/(u²−u1²), from (3)."""
    import sympy as sp

    *_, a, b, psi = symbols()
    w = _u2()
    return identity_check((a - w) / (w - b) - sp.tan(psi) ** 2, "(u0²−u²)/(u²−u1²) − tan²ψ")


def result_tan_sq_phi1() -> EquationCheck:
    """tan²φ1, read as (u1²/u0²)(u0²−u²)/(u²−u1²) (the OCR flattens the two fractions)."""
    import sympy as sp

    *_, a, b, psi = symbols()
    w = _u2()
    exact = (sp.sqrt(b) / sp.sqrt(a) * sp.tan(psi)) ** 2  # (10) squared
    return identity_check(_tan_sq_phi1().subs(symbols()[4], w) - exact, "reading − (10)²")


def result_tan_sq_phi1_rho() -> EquationCheck:
    """The same in ρ = lu (16): (ρ1²/ρ0²)(ρ0²−ρ²)/(ρ²−ρ1²)."""
    import sympy as sp

    *_, w, a, b, _ = symbols()
    ell = sp.Symbol("l", positive=True)
    in_rho = (ell**2 * b) / (ell**2 * a) * (ell**2 * a - ell**2 * w) / (ell**2 * w - ell**2 * b)
    return identity_check(in_rho - _tan_sq_phi1(), "the ρ form − the u form")


def eq_17() -> EquationCheck:
    """(17): 1/ρ² = cos²φ1/ρ0² + sin²φ1/ρ1², from tan²φ1 (ρ² = l²u²)."""
    *_, w, a, b, _ = symbols()
    t2 = _tan_sq_phi1()
    cos_sq, sin_sq = 1 / (1 + t2), t2 / (1 + t2)
    return identity_check(cos_sq / a + sin_sq / b - 1 / w, "cos²φ1/u0² + sin²φ1/u1² − 1/u²")


# --- rows for the display formulas issue 19 found without a row ---------------------------


def result_cos_series() -> EquationCheck:
    """cos θ = 1 − u²/2 − u⁴/8 − … with u = sin θ (and the same for θ0, θ1): the series of
    √(1 − u²), compared exactly through u⁴."""
    import sympy as sp

    u = sp.Symbol("u", real=True)
    printed = 1 - u**2 / 2 - u**4 / 8
    exact = sp.series(sp.sqrt(1 - u**2), u, 0, 6).removeO()
    return identity_check(exact - printed, "√(1−u²) through u⁴ − (1 − u²/2 − u⁴/8)")


def result_first_approximation() -> EquationCheck:
    """ψ = k't, φ' = (3/8)u0u1k''t: (II) and (V) without their periodic terms (the sin 2k't
    term of ψ and the secular term of φ' are the quadrature checks' leading terms)."""
    return _reuse("II_sin2", "k_second")


NUMERICAL_APPLICATION = (
    "tisserand.example.psi_sin2",
    "tisserand.example.psi_sin4",
    "tisserand.example.phi_sin2",
)


def result_numerical_application() -> EquationCheck:
    """ψ and φ' for θ0 = 30', θ1 = 15': the three coefficients, as the claims of
    tables/published/tisserand.toml judge them against their recomputation."""
    from pendcli.papers.registry import evaluate

    rows = {r.id: r for r in evaluate("tisserand")}
    chosen = [rows[i] for i in NUMERICAL_APPLICATION]
    parts = [f"{r.id} printed {r.published}: {r.verdict}" for r in chosen]
    return EquationCheck(
        holds=all(r.verdict == "agrees" for r in chosen),
        method="numeric",
        detail="claims " + "; ".join(parts),
    )


# --- references for the statuses computed from the printed forms (core/printed_check) ------
# Each maps ledger symbols (tables/equations/tisserand.toml [symbols]) to exact expressions:
# the definition (3), the differential (4), the ellipse's definitions (9), (16); never a copy
# of the formula the row prints.


def _ledger_symbols(*names: str) -> Any:
    import sympy as sp

    return [sp.Symbol(n, real=True) for n in names]


def reference_definition_3() -> Any:
    """(3): u = √(u0² cos²ψ + u1² sin²ψ)."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    u0, u1, psi = _ledger_symbols("u0", "u1", "psi")
    u = sp.sqrt(u0**2 * sp.cos(psi) ** 2 + u1**2 * sp.sin(psi) ** 2)
    domain = {
        "u0": (sp.Rational(3, 10), sp.Rational(1, 2)),
        "u1": (sp.Rational(1, 20), sp.Rational(1, 4)),
    }
    return Reference({"u": u}, domain=domain, what="(3)")


def reference_ellipse() -> Any:
    """(3), (9) and (16): u as in (3), φ1 = arctan((u1/u0) tan ψ), ρ = lu, ρ0 = lu0, ρ1 = lu1."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    u0, u1, psi, length = _ledger_symbols("u0", "u1", "psi", "l")
    base = reference_definition_3()
    u = base.exact["u"]
    exact = {
        "u": u,
        "phi1": sp.atan(u1 / u0 * sp.tan(psi)),
        "rho": length * u,
        "rho0": length * u0,
        "rho1": length * u1,
    }
    return Reference(exact, domain=base.domain, what="(3), (9), (16)")


def _small_angles(scale: Any) -> dict[str, Any]:
    """u = sin θ, u0, u1 scaled by ``scale``: θ = arcsin(scale·u) and u -> scale·u."""
    import sympy as sp

    out: dict[str, Any] = {}
    for suffix in ("", "0", "1"):
        (u,) = _ledger_symbols(f"u{suffix}")
        out[f"theta{suffix}"] = sp.asin(scale * u)
        out[f"u{suffix}"] = scale * u
    return out


def reference_small_angles() -> Any:
    """cos θ = √(1 − u²) with u = sin θ: the series through the fourth order in the angles."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    scale = sp.Symbol("x", positive=True)
    return Reference(_small_angles(scale), scale=scale, order=6, what="u = sin θ, to order 4")


def reference_differential_4() -> Any:
    """(4), solved for dt, with u = sin θ: the series through the fourth order."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    scale = sp.Symbol("x", positive=True)
    exact = _small_angles(scale)
    k, dpsi = _ledger_symbols("k", "dpsi")
    c, c0, c1 = (sp.cos(exact[f"theta{s}"]) for s in ("", "0", "1"))
    total = 1 + c * c0 + c * c1 + c0 * c1
    product = (c + c0) * (c + c1) * (c0 + c1)
    root = sp.sqrt(1 - exact["u"] ** 2)
    exact["dt"] = dpsi / (k * sp.sqrt(2) * root) * sp.sqrt(product) / sp.sqrt(total)
    return Reference(exact, scale=scale, order=6, what="(4), to order 4")
