"""Charbonnier (1908): one check per checkable row of ``tables/equations/charbonnier.toml``.

The derivation of §§ 2-8 is verified exactly with sympy ((1) from the theorem of moments,
(2) and (3), the variation of constants (q), (4) and (5) with a generic φ(t)); the
consequences (6)-(9) and the results of §§ 13-17 are checked by the existing ODE and
quadrature checks of ``formulas.py`` (observed orders), reused through
:func:`pendcli.core.ledger.check_from_formula_rows`. sympy is imported lazily.
"""

from __future__ import annotations

from functools import cache
from typing import Any

from pendcli.core.ledger_check import EquationCheck, check_from_formula_rows
from pendcli.papers.identities import vanishes_identically


@cache
def _formula_rows() -> tuple[Any, ...]:
    from pendcli.core.claims import shared_formula_rows
    from pendcli.papers.charbonnier.formulas import formula_checks

    return tuple(shared_formula_rows("charbonnier", formula_checks))


def _reuse(*ids: str) -> EquationCheck:
    return check_from_formula_rows(_formula_rows(), [f"charbonnier.{i}" for i in ids])


def _identity(difference: Any, what: str) -> EquationCheck:
    zero = vanishes_identically(difference)
    return EquationCheck(
        holds=bool(zero),
        method="sympy",
        detail=f"{what}: difference {'simplifies to 0' if zero else 'is not 0'}",
    )


def eq_1() -> EquationCheck:
    """(1): d/dt(l² θ') + g l sin θ = 0 divided by l²."""
    import sympy as sp

    t, g = sp.symbols("t g", positive=True)
    theta, ell = sp.Function("theta")(t), sp.Function("l")(t)
    moments = sp.diff(ell**2 * sp.diff(theta, t), t) + g * ell * sp.sin(theta)
    printed = (
        sp.diff(theta, t, 2)
        + 2 / ell * sp.diff(ell, t) * sp.diff(theta, t)
        + g / ell * sp.sin(theta)
    )
    return _identity(moments / ell**2 - printed, "theorem of moments / l² − (1)")


def eq_2() -> EquationCheck:
    """(2): (1) with l = l0 constant and sin θ → θ (k² = g/l0); the dropped term is O(θ³)."""
    import sympy as sp

    t, g, l0, k, q = sp.symbols("t g l0 k q", positive=True)
    theta = sp.Function("theta")(t)
    sine = sp.series(sp.sin(q), q, 0, 3).removeO()  # sin q = q + O(q³)
    linear = sp.diff(theta, t, 2) + g / l0 * sine.subs(q, theta)  # (1) with dl/dt = 0
    linear = linear.subs(g, k**2 * l0)
    return _identity(linear - (sp.diff(theta, t, 2) + k**2 * theta), "linearised (1) − (2)")


@cache  # n° 6 (result_principal_motion) cites it again
def eq_3() -> EquationCheck:
    """(3): θ = −α cos kt solves (2) with θ(0) = −α, θ'(0) = 0; θ' = kα sin kt."""
    import sympy as sp

    t, k, alpha = sp.symbols("t k alpha", positive=True)
    theta = -alpha * sp.cos(k * t)
    residual = sp.diff(theta, t, 2) + k**2 * theta
    rest = sp.diff(theta, t) - k * alpha * sp.sin(k * t)
    start = (theta.subs(t, 0) + alpha) ** 2 + sp.diff(theta, t).subs(t, 0) ** 2
    return _identity(residual**2 + rest**2 + start, "ODE, derivative and initial values")


def variation_of_constants() -> tuple[Any, ...]:
    """θ1 = M cos kt + N sin kt with M, N from the paper's integrals, φ generic."""
    import sympy as sp

    t, s, k = sp.symbols("t s k", positive=True)
    phi = sp.Function("phi")
    e_s = sp.Integral(phi(s) * sp.sin(k * s), (s, 0, t))
    e_c = sp.Integral(phi(s) * sp.cos(k * s), (s, 0, t))
    theta1 = (e_s * sp.cos(k * t) - e_c * sp.sin(k * t)) / k
    return t, k, phi, e_s, e_c, theta1


def eq_q() -> EquationCheck:
    """(q): with (p) imposed, (2)+φ gives −M' sin kt + N' cos kt + φ/k = 0."""
    import sympy as sp

    t, k = sp.symbols("t k", positive=True)
    m, n, phi = sp.Function("M")(t), sp.Function("N")(t), sp.Function("phi")(t)
    theta1 = m * sp.cos(k * t) + n * sp.sin(k * t)
    first = -k * m * sp.sin(k * t) + k * n * sp.cos(k * t)  # θ1' once (p) holds
    equation = sp.diff(first, t) + k**2 * theta1 + phi
    q = -sp.diff(m, t) * sp.sin(k * t) + sp.diff(n, t) * sp.cos(k * t) + phi / k
    return _identity(equation - k * q, "θ1'' + k²θ1 + φ − k·(q)")


def eq_4() -> EquationCheck:
    """(4): θ1 = (E_s cos kt − E_c sin kt)/k solves θ1'' + k²θ1 + φ(t) = 0, θ1(0) = θ1'(0) = 0."""
    import sympy as sp

    t, k, phi, *_, theta1 = variation_of_constants()
    residual = sp.diff(theta1, t, 2) + k**2 * theta1 + phi(t)
    # doit: the integrals over [0, 0] are 0 at once, which simplify otherwise spends 0.2 s on
    start = (theta1.subs(t, 0) ** 2 + sp.diff(theta1, t).subs(t, 0) ** 2).doit()
    return _identity(residual + start, "first-order equation for θ1, φ generic")


def eq_5() -> EquationCheck:
    """(5), read with kα for the printed kx: θ' is the derivative of (4)."""
    import sympy as sp

    t, k, _phi, e_s, e_c, theta1 = variation_of_constants()
    reading = -(e_s * sp.sin(k * t) + e_c * sp.cos(k * t))
    return _identity(sp.diff(theta1, t) - reading, "d/dt of (4)'s bracket − (5)'s bracket")


def eq_6() -> EquationCheck:
    """(6): ΔT = ε E_c(π)/(k²α)."""
    return _reuse("eq6.linear_damping", "eq6.periodic_force")


def eq_7() -> EquationCheck:
    """(7): Δα = −ε E_s(π)/k."""
    return _reuse("eq7.linear_damping", "eq7.periodic_force")


def eq_8() -> EquationCheck:
    """(8): ΔT_½ = ε E_c(π/2)/(k²α)."""
    return _reuse("eq8.linear_damping", "eq8.periodic_force")


def eq_9() -> EquationCheck:
    """(9): Δθ'_m = −ε E_c(π/2) (found: −ε E_s(π/2))."""
    return _reuse("eq9.linear_damping", "eq9.periodic_force")


def result_general_solution() -> EquationCheck:
    """§ 8: (4), (5) against the direct solution of the perturbed equation."""
    return _reuse("eq4_5.linear_damping", "eq4_5.periodic_force", "eq4_5.friction")


def result_period_unchanged() -> EquationCheck:
    """§ 13: the resistance of the air leaves the period unchanged, ΔT = 0."""
    return _reuse("delta_T_zero")


def result_recurrence() -> EquationCheck:
    """§ 15: (n+1) I_n = −cos x sinⁿx + n I_{n−2}, I_n = ∫₀^x sin^{n+1}x dx (n = 1..6)."""
    import sympy as sp

    x, y = sp.symbols("x y", positive=True)
    # I_n of n is I_(n−2) of n + 2: eight integrals (powers 0..7), not twelve
    powers = {m: sp.integrate(sp.sin(y) ** m, (y, 0, x)) for m in range(8)}
    worst = []
    for n in range(1, 7):
        i_n, i_m = powers[n + 1], powers[n - 1]
        worst.append(sp.simplify((n + 1) * i_n - (-sp.cos(x) * sp.sin(x) ** n + n * i_m)))
    zero = all(w == 0 for w in worst)
    return EquationCheck(
        holds=zero,
        method="sympy",
        detail=f"exact integrals for n = 1..6: differences {worst}",
    )


def result_in_pi() -> EquationCheck:
    """§ 15: I_n(π) = 2·(2·4…n)/(1·3…(n+1)) (n even), π·(1·3…n)/(2·4…(n+1)) (n odd)."""
    return _reuse("I_pi.closed_form_even", "I_pi.closed_form_odd")


def result_ec_monomial() -> EquationCheck:
    """§ 15: E_c = B_n/(n+1) k^{n+1} αⁿ l0ⁿ sin^{n+1} kt."""
    return _reuse("E_c.closed_form")


def result_delta_alpha() -> EquationCheck:
    """§ 16: Δα = −(b_n/g)(αgT/π)ⁿ I_n(π), n = 0..5."""
    return _reuse(*(f"delta_alpha.n{n}" for n in range(6)))


def result_friction_count() -> EquationCheck:
    """§ 16: P = αg/(2b0) simple oscillations until the pendulum stops (n = 0)."""
    return _reuse("friction_count")


def result_lowest_point() -> EquationCheck:
    """§ 17: ΔT_½ = b_n(αl0)^{n−1}k^{n−3}/(n+1) and Δv_m = (k/2) l0 Δα."""
    return _reuse("delta_T_half", "delta_v_m")


@cache  # n° 6 (result_principal_motion) cites it again
def result_period_and_top_speed() -> EquationCheck:
    """n° 3: T = π/k, the first return of dθ/dt = kα sin kt to 0 after t = 0, and
    θ'_m = kα, its value at kt = π/2 where d²θ/dt² = k²α cos kt vanishes."""
    import sympy as sp

    t, k, alpha = sp.symbols("t k alpha", positive=True)
    speed = sp.diff(-alpha * sp.cos(k * t), t)
    stops = sp.solveset(speed, t, sp.Interval.open(0, 2 * sp.pi / k))
    first = min(stops) if stops.is_FiniteSet and stops else sp.nan
    top = speed.subs(t, sp.solve(sp.diff(speed, t), t)[0])
    return _identity((first - sp.pi / k) ** 2 + (top - k * alpha) ** 2, "T − π/k, θ'_m − kα")


def result_principal_motion() -> EquationCheck:
    """n° 6 repeats (3) for θ0 and n° 3's T = π/k, θ'_m = kα: both checks, cited."""
    parts = (eq_3(), result_period_and_top_speed())
    return EquationCheck(
        holds=all(p.holds for p in parts),
        method="sympy",
        detail="as (3) and n° 3: " + "; ".join(p.detail for p in parts),
    )


def result_delta_alpha_closed() -> EquationCheck:
    """n° 16, 2°: I_n(π) in −(b_n/g)(αgT/π)ⁿ I_n(π) replaced by the products of n° 15,
    2·(2·4…n)/(1·3·5…(n+1)) (n even), π·(1·3·5…n)/(2·4·6…(n+1)) (n odd), against an mpmath
    quadrature of ∫₀^π sin^(n+1) x dx for n = 0..7 (the common factor cancels)."""
    import mpmath

    worst = 0.0
    with mpmath.workdps(30):
        for n in range(8):
            odd = n % 2
            top = mpmath.fprod(range(1 if odd else 2, n + 1, 2))  # 1·3…n or 2·4…n
            bottom = mpmath.fprod(range(2 if odd else 1, n + 2, 2))  # 2·4…(n+1) or 1·3…(n+1)
            product = (mpmath.pi if odd else 2) * top / bottom
            quadrature = mpmath.quad(lambda x, m=n: mpmath.sin(x) ** (m + 1), [0, mpmath.pi])
            worst = max(worst, float(abs(product / quadrature - 1)))
    return EquationCheck(
        holds=worst < 1e-20,
        method="numeric",
        detail=f"the products against ∫₀^π sin^(n+1) for n = 0..7: worst relative gap {worst:.1e}",
    )


# --- the statuses computed from the printed forms (issue 19) ---------------------------
# ``reference = "reference_…"`` names a function of references.py (re-exported here, as the
# engine reads it from this module); ``check = "printed_<slug>"`` is the check of a row whose
# status rests on its printed form alone: the engine's verdict against that reference.


def printed_form_check(row_id: str) -> EquationCheck:
    """The check of ``row_id`` as its printed form earns it (core/printed_check)."""
    from pendcli.core.ledger import load_ledger, row_printed_status
    from pendcli.papers.charbonnier import _references

    ledger = load_ledger("charbonnier")
    row = next(r for r in ledger.rows if r.id == row_id)
    if row.reference is None:
        return EquationCheck(holds=False, method="sympy", detail=f"{row_id} has no reference")
    # the ledger's own computation of the row's status, shared (not done twice)
    status, why = row_printed_status(row, dict(ledger.symbols), _references())
    corrected = row.corrected_formula if status == "fails" else None
    holds = status in ("holds", "misprint")
    return EquationCheck(holds=holds, method="sympy", detail=why, corrected=corrected)


def __getattr__(name: str) -> Any:
    from pendcli.papers.charbonnier import references

    if name.startswith("reference_") and name in references.__all__:
        return getattr(references, name)
    if name == "reference_in_pi":  # n19: lines 486-489
        from pendcli.papers.charbonnier.references_in_pi import reference_in_pi

        return reference_in_pi
    if name.startswith("printed_"):
        row_id = "charbonnier.result." + name.removeprefix("printed_").replace("_", "-")
        return lambda: printed_form_check(row_id)
    raise AttributeError(name)
