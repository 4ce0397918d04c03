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

from pendcli.core.ledger_check import EquationCheck, check_from_formula_rows
from pendcli.core.tables import on_table_change
from pendcli.papers.identities import simplified, vanishes_identically
from pendcli.papers.taylor import degree_in, taylor
from pendcli.papers.tisserand.references_numeric import *  # noqa: F403  (n19: lines 192-202)

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
    zero = vanishes_identically(difference)
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
    derivative = simplified(sp.diff(printed, psi) - integrand)
    at_zero = simplified(printed.subs(psi, 0))
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
    """(8): kt and φ as series in ψ (quadrature checks of formulas.py); also the check of
    (11), φ' = φ − φ1, and of (12), whose bracket is (8)'s ψ-coefficient (one computation,
    cited by the three rows)."""
    return _reuse("k_prime", "eq8_kt_sin2psi", "eq8_kt_sin4psi", "eq8_phi_psi", "eq8_phi_sin2psi")


def result_psi_before_13() -> EquationCheck:
    """ψ = k't − (u0²−u1²)(3/32 + 11(u0²+u1²)/256) sin 2ψ − (u0²−u1²)²(35/4096) sin 4ψ."""
    return _reuse("psi_in_psi_sin4psi")


def eq_II() -> EquationCheck:
    """(II): ψ as a series in k't; also the check of (13)'s reading (the one computation
    both rows cite)."""
    return _reuse("II_sin2", "II_sin4")


def result_second_approximation() -> EquationCheck:
    """ψ = k't − (3/32)(u0²−u1²) sin 2k't: the leading terms of (II)."""
    return _reuse("II_sin2")


def eq_15() -> EquationCheck:
    """(15): φ' = (3/8)u0u1k''t + u0u1(u0²−u1²)(17/512) sin 2k't; also the check of (14),
    whose k'' is the rate of φ''s secular term (the one computation both rows cite)."""
    return _reuse("k_second", "V_sin2")


def eq_I() -> EquationCheck:
    """(I), read with k = √(g/l): k' to sixth order, k'' to fourth (quadrature checks)."""
    return _reuse("k_prime", "k_second")


def eq_10() -> EquationCheck:
    """(10), « d'où »: the tangent of (9)'s φ1 = arctan((u1/u0) tan ψ)."""
    import sympy as sp

    *_, a, b, psi = symbols()
    phi1 = sp.atan(sp.sqrt(b) / sp.sqrt(a) * sp.tan(psi))  # (9), u0 = √a, u1 = √b
    return identity_check(sp.tan(phi1) - sp.sqrt(b) / sp.sqrt(a) * sp.tan(psi), "tan φ1 of (9)")


def result_eccentric_anomaly() -> EquationCheck:
    """Line 156, « L'angle ψ est l'anomalie excentrique, ainsi que le montre l'équation (10) »:
    with (3) and (16) the projection is (ρ0 cos ψ, ρ1 sin ψ) in the moving frame."""
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


def _claims_agree(ids: tuple[str, ...]) -> EquationCheck:
    """The claims of tables/published/tisserand.toml named by ``ids``, as pendcli judges them
    against their recomputation (the printed precision of each)."""
    from pendcli.core.tables import tables_dir

    rows = _judged_claims(str(tables_dir()))
    chosen = [rows[i] for i in ids]
    parts = [f"{r.id} printed {r.published}: {r.verdict}" for r in chosen]
    return EquationCheck(
        holds=all(r.verdict == "agrees" for r in chosen),
        method="numeric",
        detail="claims " + "; ".join(parts),
    )


@cache
def _judged_claims(tables: str) -> dict[str, Any]:
    # once per tables folder (cleared when a table changes): two rows cite the example's
    # claims, and each recomputation integrates the conical motion twice
    from pendcli.papers.registry import evaluate

    return {r.id: r for r in evaluate("tisserand")}


on_table_change(_judged_claims.cache_clear)


def result_numerical_application() -> EquationCheck:
    """ψ and φ' for θ0 = 30', θ1 = 15': the three coefficients, as the claims of
    tables/published/tisserand.toml judge them against their recomputation."""
    return _claims_agree(NUMERICAL_APPLICATION)


def result_displacement() -> EquationCheck:
    """Line 202: with l = 0,5 m the periodic term 2'42'' sin 2k't of φ' moves the bob by at
    most a fifth of a millimetre (the claim tisserand.example.displacement, an upper bound)."""
    return _claims_agree(("tisserand.example.displacement",))


def result_resal_rate() -> EquationCheck:
    """Line 180, « k'' diffère peu de l'unité; donc le grand axe tourne avec la vitesse
    angulaire (3/8)u0u1 »: k'' is a rate, k'' = (8/3)b0·k' (b0 the mean of
    (dφ/dψ − u0u1/u²)/(u0u1), k' = k/a0, a0 the mean of k dt/dψ), so it is a number near 1
    only in the unit of time 1/k; it is k''/k' that differs little from unity. Quadrature of
    (4), (5) (formulas.py) at the paper's example, θ0 = 30°, θ1 = 15°."""
    import math

    from pendcli.core.tables import load_paper_table
    from pendcli.papers.tisserand.formulas import series_coefficients

    table = load_paper_table("tisserand")
    theta0, theta1 = (math.radians(table.constant(n)) for n in ("theta0", "theta1"))
    found = series_coefficients(theta0, theta1)
    ratio = 8 / 3 * float(found["b"][0])  # k''/k'
    u0, u1 = math.sin(theta0), math.sin(theta1)
    leading = 1 + 9 * (u0**2 + u1**2) / 32
    return EquationCheck(
        holds=False,
        method="numeric",
        detail=f"at θ0 = 30°, θ1 = 15°: k'' = {ratio:.4f} k' = {ratio / found['a'][0]:.4f} k,"
        " a rate (T⁻¹), not a number: « diffère peu de l'unité » holds for k''/k' only",
        corrected=f"k''/k' = {ratio:.4f} (1 + 9(u0²+u1²)/32 = {leading:.4f}); the axis turns at "
        "(3/8)u0u1k'' ≈ (3/8)u0u1k', i.e. (3/8)u0u1 per unit of k't",
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


# --- the motion as exact series in the angles, for the series rows (8) to (15), (I), (II) ---
# The scale s multiplies u, u0, u1 (the angles' order); W stands for u² / s². k dt/dψ and
# u²·dφ/dψ/(u0u1) come from (4) and (5) by truncated binomial series (cos θ = √(1 − s²W)),
# then u² = u0² cos²ψ + u1² sin²ψ (3) and an exact term-by-term integration in ψ give kt(ψ)
# and φ(ψ); k' and k'' are the rates their secular terms define ((12), and the k'' that makes
# the secular term of φ' equal (3/8)u0u1k''t). Nothing here is a printed coefficient.


@cache
def series_symbols() -> Any:
    """s (the scale), W (u²/s²), C (cos 2ψ), ψ, u0, u1, g, l: the ledger's real symbols."""
    import sympy as sp

    s = sp.Symbol("s", positive=True)
    return (
        s,
        sp.Symbol("W", real=True),
        sp.Symbol("C", real=True),
        *_ledger_symbols("psi", "u0", "u1", "g", "l"),
    )


@cache
def _ring() -> Any:
    """Sparse polynomials over ℚ in s, W, u0, u1 (sympy's ``ring``: fast products)."""
    import sympy as sp

    return sp.ring("s W u0 u1", sp.QQ)


def _truncated(poly: Any, n: int) -> Any:
    """``poly`` (of the ring) with the powers s**n and above dropped."""
    ring = _ring()[0]
    return ring({m: c for m, c in poly.terms() if m[0] < n})


def _binomial(p: Any, alpha: Any, n: int) -> Any:
    """(1 + p)**alpha through s**(n − 1), p of the ring without constant term."""
    import sympy as sp

    ring = _ring()[0]
    total, term, j = ring.one, ring.one, 1
    while True:
        term = _truncated(term * p, n)
        if not term:
            return total
        total += term * sp.QQ.from_sympy(sp.binomial(alpha, j))
        j += 1


@cache
def _differentials(n: int) -> tuple[Any, Any]:
    """k dt/dψ from (4) and u²·(1/(u0u1)) dφ/dψ from (5), through s**(n − 1), in s, W, u0, u1."""
    import sympy as sp

    _, s, big_w, u0, u1 = _ring()
    half = sp.Rational(1, 2)
    c, c0, c1 = (_binomial(-(s**2) * v, half, n) for v in (big_w, u0**2, u1**2))
    quarter = _truncated((1 + c * c0 + c * c1 + c0 * c1) * sp.QQ(1, 4) - 1, n)
    eighth = _truncated((c + c0) * (c + c1) * (c0 + c1) * sp.QQ(1, 8) - 1, n)
    pair = _truncated((c + c0) * (c + c1) * sp.QQ(1, 4) - 1, n)
    inverse_c = _binomial(c - 1, -1, n)
    square = _truncated((1 + eighth) * _binomial(quarter, -1, n), n)  # (4) squared over 2
    k_dt_dpsi = _truncated(_binomial(square - 1, half, n) * inverse_c, n)
    u2_dphi = _truncated(_binomial(pair, half, n) * _binomial(quarter, -half, n) * inverse_c, n)
    return k_dt_dpsi, u2_dphi


def _integral_in_psi(expr: Any) -> Any:
    """∫₀^ψ expr dψ for expr a polynomial in C = cos 2ψ: each Cᵐ by its Fourier sum."""
    import sympy as sp

    _, _, big_c, psi, *_ = series_symbols()
    total = sp.Integer(0)
    for (m,), coefficient in sp.Poly(sp.expand(expr), big_c).terms():
        for j in range(m + 1):  # Cᵐ = 2⁻ᵐ Σ_j binom(m, j) cos(2(m − 2j)ψ)
            freq = 2 * abs(m - 2 * j)
            part = psi if freq == 0 else sp.sin(freq * psi) / freq
            total += coefficient * sp.binomial(m, j) * part / 2**m
    return sp.expand(total)


@cache
def motion_series(n: int) -> dict[str, Any]:
    """kt(ψ), φ'(ψ) = φ − φ1 and their secular coefficients A (kt = Aψ + …) and P, from (4),
    (5) and (3), through s**(n − 1)."""
    import sympy as sp

    s, big_w, big_c, psi, u0, u1, *_ = series_symbols()
    names = (s, big_w, u0, u1)
    k_dt_dpsi = _differentials(n)[0].as_expr(*names)
    # u²·dφ/dψ/(u0u1) − 1 is divisible by u² = s²W: the 1/u² coefficient is exactly 1 (line 78)
    quotient, remainder = divmod(_differentials(n + 2)[1] - 1, _ring()[1] ** 2 * _ring()[2])
    if remainder:
        raise ValueError("u²·dφ/dψ/(u0u1) − 1 is not divisible by u²")
    u2 = (u0**2 + u1**2) / 2 + (u0**2 - u1**2) / 2 * big_c  # (3) over s²
    kt = _integral_in_psi(k_dt_dpsi.subs(big_w, u2))
    rest = quotient.as_expr(*names).subs(big_w, u2)
    phip = sp.expand(s**2 * u0 * u1 * _integral_in_psi(rest))
    return {"kt": kt, "phip": phip, "A": kt.coeff(psi, 1), "P": phip.coeff(psi, 1)}


def reference_motion(n: int, what: str, orders: dict[str, int] | None = None) -> Any:
    """The exact motion (4), (5), (3) through s**(n − 1): t, φ, φ1, φ', k' (12), k'' (the rate
    of φ' over (3/8)u0u1), k = √(g/l), θ0, θ1 and u0, u1 scaled by s."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    s, _, _, psi, u0, u1, g, length = series_symbols()
    series = motion_series(n)
    k = sp.sqrt(g / length)
    phi1 = sp.atan(u1 / u0 * sp.tan(psi))
    kp = k / series["A"]
    exact = {
        "k": k,
        "t": series["kt"] / k,
        "phi1": phi1,
        "phip": series["phip"],
        "phi": phi1 + series["phip"],
        "kp": kp,
        "kpp": kp * series["P"] / (sp.Rational(3, 8) * s**2 * u0 * u1),
        "theta0": sp.asin(s * u0),
        "theta1": sp.asin(s * u1),
        "u0": s * u0,
        "u1": s * u1,
    }
    return Reference(exact, scale=s, order=n, what=what, orders=orders or {})


def _below(expr: Any, n: int) -> Any:
    """``expr`` expanded, the terms of degree n and above in the scale s dropped."""
    import sympy as sp

    s = series_symbols()[0]
    keep = [t for t in sp.Add.make_args(sp.expand(expr)) if degree_in(t, s) < n]
    return sp.Add(*keep)


def _shifted(periodic: Any, delta: Any, n: int) -> Any:
    """``periodic``(ψ) = Σ c_m sin(2mψ) at ψ = τ + δ (δ = O(s²)): its Taylor series in δ,
    through s**(n − 1)."""
    import sympy as sp

    psi, tau = series_symbols()[3], sp.Symbol("tau", real=True)
    total, power = sp.Integer(0), sp.Integer(1)
    for j in range((n + 1) // 2):
        derivative = sp.diff(periodic, psi, j).subs(psi, tau) if j else periodic.subs(psi, tau)
        total += _below(derivative * power / sp.factorial(j), n)
        power = _below(power * delta, n)
    return _below(total, n)


@cache
def motion_in_kpt(n: int) -> dict[str, Any]:
    """ψ and φ' as series in τ = k't, through s**(n − 1): kt(ψ)/A = ψ + Q(ψ) (12) inverted by
    the fixed point ψ = τ − Q(ψ), each pass exact one order (s²) further."""
    import sympy as sp

    s, _, _, psi, *_ = series_symbols()
    tau = sp.Symbol("tau", real=True)
    series = motion_series(n)
    inverse_a = _below(taylor(1 / series["A"], s, n), n)
    periodic = _below((series["kt"] - series["A"] * psi) * inverse_a, n)
    delta = sp.Integer(0)
    for _ in range((n + 1) // 2):
        delta = -_shifted(periodic, delta, n)
    phip_periodic = series["phip"] - series["P"] * psi
    phip = _below(series["P"] * (tau + delta) + _shifted(phip_periodic, delta, n), n)
    return {"psi": tau + delta, "phip": phip, "tau": tau}


def reference_in_kpt(n: int, what: str, orders: dict[str, int] | None = None) -> Any:
    """The exact motion as functions of τ = k't (t = τ/k'), through s**(n − 1)."""
    from pendcli.core.printed_check import Reference

    base = reference_motion(n, what, orders)
    in_tau = motion_in_kpt(n)
    exact = dict(base.exact)
    exact.update(psi=in_tau["psi"], phip=in_tau["phip"], t=in_tau["tau"] / base.exact["kp"])
    del exact["phi"], exact["phi1"]  # functions of ψ: not needed in τ
    return Reference(exact, scale=base.scale, order=n, what=what, orders=orders or {})


def reference_motion_order_4() -> Any:
    """The exact motion through the fourth order in the angles: (8), (11), the line before
    (13), (13), (II), (15) are compared with it."""
    return reference_motion(5, "(4), (5), (3) to order 4")


def reference_motion_order_2() -> Any:
    """The exact motion through the second order: (14), printed to the second order."""
    return reference_motion(3, "(4), (5), (3) to order 2")


def reference_summary() -> Any:
    """(I): k' through the sixth order, k'' through the fourth, as line 158 announces."""
    return reference_motion(7, "(4), (5), (3): k' to order 6, k'' to order 4", {"kpp": 5})


def reference_in_kpt_order_4() -> Any:
    """The exact motion in τ = k't through the fourth order: (13), (II), (15)."""
    return reference_in_kpt(5, "(4), (5), (3) in k't, to order 4")


def reference_first_approximation() -> Any:
    """« dans une première approximation »: ψ through the first order (its sin 2k't term is
    of the second), φ' through the third (its periodic term is of the fourth)."""
    return reference_in_kpt(5, "(4), (5), (3): ψ to order 1, φ' to order 3", {"psi": 2, "phip": 4})


def reference_second_approximation() -> Any:
    """« Deuxième approximation »: ψ and φ' through the third order."""
    return reference_in_kpt(4, "(4), (5), (3) in k't, to order 3")


# --- references for the differentials (1), (2), (4), (5), (7) and the line after (7) -------


def _first_integrals(theta: Any, k: Any) -> tuple[Any, Any]:
    """θ'² and h (the areal constant sin²θ φ') of the spherical pendulum with apsides θ0, θ1:
    energy θ'² + sin²θ φ'² = 2E + 2k² cos θ and sin²θ φ' = h, E and h² fixed by θ' = 0 at θ0
    and at θ1 (solved here, not typed)."""
    import sympy as sp

    energy, h2 = sp.symbols("E h2")
    fixed = dict(zip((energy, h2), _apsidal_constants(k), strict=True))
    theta_dot_sq = 2 * energy + 2 * k**2 * sp.cos(theta) - h2 / sp.sin(theta) ** 2
    return theta_dot_sq.subs(fixed), sp.sqrt(fixed[h2])


@cache
def _apsidal_constants(k: Any) -> tuple[Any, Any]:
    """E and h² of :func:`_first_integrals`, solved from θ' = 0 at θ0 and at θ1."""
    import sympy as sp

    theta0, theta1 = _ledger_symbols("theta0", "theta1")
    energy, h2 = sp.symbols("E h2")

    def theta_dot_sq(angle: Any) -> Any:
        return 2 * energy + 2 * k**2 * sp.cos(angle) - h2 / sp.sin(angle) ** 2

    fixed = sp.solve([theta_dot_sq(theta0), theta_dot_sq(theta1)], [energy, h2], dict=True)[0]
    return fixed[energy], fixed[h2]


# θ0 the largest angle, θ1 the smallest, θ between; in (3)'s variables, ψ in the first
# quarter, where θ falls from θ0 (the sign convention of the printed roots).
def _domain_apsides() -> dict[str, Any]:
    import sympy as sp

    r = sp.Rational
    return {
        "theta0": (r(1, 2), r(4, 5)),
        "theta1": (r(1, 10), r(3, 10)),
        "theta": (r(7, 20), r(9, 20)),
        "u0": (r(1, 2), r(7, 10)),
        "u1": (r(1, 10), r(3, 10)),
        "psi": (r(1, 10), r(7, 5)),
    }


def _motion_in_theta(theta: Any, dtheta: Any) -> dict[str, Any]:
    """dt and dφ along the motion, from the first integrals (θ decreasing from θ0 at t = 0)."""
    import sympy as sp

    (k,) = _ledger_symbols("k")
    theta_dot_sq, h = _first_integrals(theta, k)
    dt = -dtheta / sp.sqrt(theta_dot_sq)
    return {"dt": dt, "dphi": h / sp.sin(theta) ** 2 * dt}


def reference_first_integrals() -> Any:
    """(1), (2): dt and dφ from the energy and areal integrals, apsides θ0 and θ1."""
    from pendcli.core.printed_check import Reference

    theta, dtheta = _ledger_symbols("theta", "dtheta")
    exact = _motion_in_theta(theta, dtheta)
    return Reference(exact, domain=_domain_apsides(), what="the first integrals")


def reference_first_integrals_in_psi() -> Any:
    """dθ, dt, dφ of the first integrals with θ, θ0, θ1 from (3): u = sin θ as a function of
    ψ, dθ its exact derivative times dψ (for the line after (3), (4), (5))."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    u0, u1, psi, dpsi = _ledger_symbols("u0", "u1", "psi", "dpsi")
    u = sp.sqrt(u0**2 * sp.cos(psi) ** 2 + u1**2 * sp.sin(psi) ** 2)
    theta = sp.asin(u)
    dtheta = sp.diff(theta, psi) * dpsi
    theta0, theta1 = _ledger_symbols("theta0", "theta1")
    apsides = {theta0: sp.asin(u0), theta1: sp.asin(u1)}
    exact = {n: e.subs(apsides) for n, e in _motion_in_theta(theta, dtheta).items()}
    exact.update(theta=theta, theta0=sp.asin(u0), theta1=sp.asin(u1), u=u, dtheta=dtheta)
    return Reference(exact, domain=_domain_apsides(), what="the first integrals with (3)")


def _dphi_from_5(n: int, scale_u0_u1: bool) -> dict[str, Any]:
    """u, u0, u1 scaled by s (u0, u1 only when ``scale_u0_u1``) and dφ from (5)."""
    import sympy as sp

    s = series_symbols()[0]
    u, u0, u1, dpsi = _ledger_symbols("u", "u0", "u1", "dpsi")
    v0, v1 = (s * u0, s * u1) if scale_u0_u1 else (u0, u1)
    c, c0, c1 = sp.sqrt(1 - s**2 * u**2), sp.sqrt(1 - v0**2), sp.sqrt(1 - v1**2)
    root = sp.sqrt((c + c0) * (c + c1)) / sp.sqrt(1 + c * c0 + c * c1 + c0 * c1)
    dphi = v0 * v1 * dpsi / (s**2 * u**2 * c) * root  # (5), with √(1 − u²) = cos θ
    return {"u": s * u, "u0": v0, "u1": v1, "dphi": dphi}


def reference_formula_5() -> Any:
    """(5) through the second order in the angles (its Laurent series in u, u0, u1): (7)."""
    from pendcli.core.printed_check import Reference

    return Reference(_dphi_from_5(3, True), scale=series_symbols()[0], order=3, what="(5)")


def reference_formula_5_near_u_zero() -> Any:
    """(5) with u0, u1 exact and u → 0 only: the 1/u² coefficient to every order in u0, u1
    (« si loin qu'on pousse les approximations »)."""
    from pendcli.core.printed_check import Reference

    exact = _dphi_from_5(3, False)
    return Reference(exact, scale=series_symbols()[0], order=0, what="(5) as u → 0")


def reference_formula_5_as_cited() -> Any:
    """« La formule (5) donnera »: what (5) gives (dφ, in the angles to order 4), which leaves
    dt undetermined; the reading is judged against (4), the formula that has dt."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    scale = sp.Symbol("x", positive=True)
    exact = _small_angles(scale)
    exact["dphi"] = _dphi_from_5(3, True)["dphi"].subs(series_symbols()[0], scale)
    return Reference(
        exact, scale=scale, order=6, what="(5), to order 4", reading=reference_differential_4()
    )


def reference_definition_9() -> Any:
    """(9): φ1 = arctan((u1/u0) tan ψ)."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    u0, u1, psi = _ledger_symbols("u0", "u1", "psi")
    return Reference({"phi1": sp.atan(u1 / u0 * sp.tan(psi))}, what="(9)")


def reference_resal() -> Any:
    """Line 180: k'' and the mean angular velocity of the major axis, dφ'/dt = k'·P (P the
    secular coefficient of φ' in ψ), k'' through the first order, the rate through the second."""
    from pendcli.core.printed_check import Reference

    base = reference_motion(3, "(4), (5), (3): k'' to order 1, dφ'/dt to order 2", {"kpp": 2})
    exact = {**base.exact, "dphip_dt": base.exact["kp"] * motion_series(3)["P"]}
    return Reference(exact, scale=base.scale, order=3, what=base.what, orders=base.orders)


# --- d19: the sentences that cite the formulas (lines 126, 154, 190) ----------------------


def reference_cited_in_kpt() -> Any:
    """Lines 126 and 154: the exact motion in τ = k't through the fourth order, with φ1 and
    φ = φ1 + φ' as functions of τ (φ1 = arctan((u1/u0) tan ψ) of (9), at the exact ψ(τ)), so
    that the formulas a sentence cites, ψ (13), φ' (15), tan φ1 (10), are judged at one time."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    base = reference_in_kpt_order_4()
    _, _, _, _, u0, u1, *_ = series_symbols()
    phi1 = sp.atan(u1 / u0 * sp.tan(base.exact["psi"]))
    exact = {**base.exact, "phi1": phi1, "phi": phi1 + base.exact["phip"]}
    return Reference(exact, scale=base.scale, order=base.order, what="(4), (5), (3) in k't")


def reference_third_approximation() -> Any:
    """Line 190: the exact motion in τ = k't through the fourth order, θ0 > θ1 (u0 > u1, the
    apsides' order), for the sign of φ''s periodic term."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    base = reference_in_kpt_order_4()
    r = sp.Rational
    # an inequality holds only over the range stated: small amplitudes (the scale s of the
    # series) and τ over (0, π) but its zero π/2, where the quotient is continued
    domain = {"u0": (r(1, 2), r(7, 10)), "u1": (r(1, 10), r(3, 10))}
    domain.update(s=(r(1, 100), r(1, 10)), tau=(r(1, 10), r(3)))
    return Reference(base.exact, scale=base.scale, order=base.order, domain=domain, what=base.what)
