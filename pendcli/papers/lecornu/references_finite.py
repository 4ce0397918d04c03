"""Lecornu, § III « Étude des oscillations finies », lines 699-816: the references the
printed forms of (30)-(38) are judged against (verify/printed_check): the fast shortening in
powers of s = g/b ((30), (31), lines 699-732), then the slow lengthening in u = γt, p =
b/√(ga) ((32)-(38), lines 734-816).

Each ``reference_*`` maps ledger symbols (tables/equations/lecornu.toml [symbols]) to exact
expressions: the equation of motion, the preceding equation, a definition, a solution
computed here; never a copy of the formula the row prints.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.papers.lecornu.references_base import reference, symbols
from pendcli.papers.taylor import taylor

# --- § III from (30): the fast shortening, in powers of s = g/b (lines 699-732) ----------


def _s_coefficients() -> tuple[Any, list[Any]]:
    """(30), z θ'' + 2θ' + s sin θ = 0, with θ = U + Vs + Ws² (line 702): the coefficients
    of s⁰, s¹, s² of its left side (a series in s), in the ledger's symbols."""
    s, z = symbols("s", "z")
    names = ("U", "dU_dz", "d2U_dz2", "V", "dV_dz", "d2V_dz2", "W", "dW_dz", "d2W_dz2")
    u, du, d2u, v, dv, d2v, w, dw, d2w = symbols(*names)
    theta, dtheta, d2theta = (
        u + v * s + w * s**2,
        du + dv * s + dw * s**2,
        d2u + d2v * s + d2w * s**2,
    )
    left = z * d2theta + 2 * dtheta + s * sp.sin(theta)
    series = sp.expand(taylor(left, s, 3))
    return s, [series.coeff(s, n) for n in range(3)]


@cache
def reference_s_coefficients() -> Any:
    """Lines 704-714: u'', v'', w'' solved from the s⁰, s¹, s² coefficients of (30) with
    θ = u + vs + ws² (each coefficient is linear in its second derivative)."""
    coefficients = _s_coefficients()[1]
    exact = {}
    for name, coefficient in zip(("U", "V", "W"), coefficients, strict=True):
        (second,) = symbols(f"d2{name}_dz2")
        exact[second.name] = -coefficient.subs(second, 0) / coefficient.coeff(second)
    return reference(exact, "(30) with θ = u + vs + ws²")


def _zero_start_double_quadrature(forcing: Any, z: Any, z0: Any) -> Any:
    """The solution of z y'' + 2y' = f (that is (z²y')' = z f) with y(z0) = y'(z0) = 0:
    y = ∫_z0^z dz/z² ∫_z0^z z f dz (sympy integrals, left unevaluated)."""
    return sp.Integral(sp.Integral(z * forcing, (z, z0, z)) / z**2, (z, z0, z))


def _coefficient_transform(residual: Any) -> Any:
    """Lines 716-722 (``U = …``, ``V = …``, ``W = …``): the residual y − Y(z) of the
    coefficient y of s⁰, s, s² becomes D(y) − D(Y) + κ1 (y − Y)(z0) + κ2 (y − Y)'(z0),
    D = z d²/dz² + 2 d/dz, with D(y) and the values at z0 from lines 710-716: D(u) = 0,
    D(v) = −sin u, D(w) = −v cos u, v = w = v' = w' = 0 at z0 (u's values there are its
    free constants α, β). Both vanish if and only if Y solves y's problem."""
    z, z0, alpha, beta = symbols("z", "z0", "alpha", "beta")
    big_u, big_v, big_w = symbols("U", "V", "W")
    kappa1, kappa2 = symbols("kappa1_aux", "kappa2_aux")
    u = alpha + beta / z  # the general solution of z u'' + 2u' = 0: (z²u')' = 0
    v = -_zero_start_double_quadrature(sp.sin(u), z, z0)
    operator = {big_u: sp.S.Zero, big_v: -sp.sin(u), big_w: -v * sp.cos(u)}
    (name,) = [s for s in operator if residual.has(s)]
    solution = name - residual  # Y(z)

    def empty(e: Any) -> bool:
        return isinstance(e, sp.Integral) and e.limits[0][1] == e.limits[0][2]

    def at_start(f: Any) -> Any:
        return f.subs(z, z0).replace(empty, lambda e: sp.S.Zero)

    first = solution.diff(z)
    gap = operator[name] - (z * first.diff(z) + 2 * first)
    if name != big_u:  # v, w start at 0 with zero slope
        gap += kappa1 * at_start(solution) + kappa2 * at_start(first)
    return sp.expand(gap)  # the integrals, atoms here, cancel term by term


@cache
def reference_coefficient_solutions() -> Any:
    """Lines 716-722: u, v, w judged as solutions of the equations of lines 710-714 with the
    initial values of line 716 (the differential operator applied by sympy to the printed
    integrals; nothing integrated)."""
    return reference(
        {}, "lines 710-716: z y'' + 2y' and the values at z0", transform=_coefficient_transform
    )


@cache
def _series_31() -> Any:
    """θ = α + vs + ws² for β = 0 (u = α): v, w solved from the coefficient equations
    (z²v')' = −z sin α, (z²w')' = −z v cos α with v = v' = w = w' = 0 at z0, by sympy
    integration of rational functions of z."""
    s, z, z0, alpha = symbols("s", "z", "z0", "alpha")
    zeta = sp.Symbol("zeta", positive=True)

    def solve(source: Any) -> Any:
        # z v'' + 2v' = f  <=>  (z² v')' = z f
        slope = sp.integrate((zeta * source.subs(z, zeta)), (zeta, z0, z)) / z**2
        return sp.integrate(slope.subs(z, zeta), (zeta, z0, z))

    v = sp.simplify(solve(-sp.sin(alpha)))
    w = solve(-v * sp.cos(alpha))
    return alpha + v * s + w * s**2, v


@cache
def reference_31() -> Any:
    """(31): θ through s² for β = 0, solved from (30) (lines 708-714)."""
    theta, _ = _series_31()
    return reference({"theta": theta}, "(30) through s², β = 0")


@cache
def reference_polar_trajectory() -> Any:
    """Line 730: (31) without its s² term at z = l/b, and A, B, C its coefficients of l⁰,
    l¹, l⁻¹ (computed; θ then holds only if no other power of l occurs)."""
    s, z, alpha, length, b = symbols("s", "z", "alpha", "l", "b")
    _, v = _series_31()
    theta = sp.expand(alpha + s * v.subs(z, length / b))
    exact = {"theta": theta}
    for name, power in (("A31", 0), ("B31", 1), ("C31", -1)):
        exact[name] = theta.coeff(length, power)
    return reference(exact, "(31) to order s at z = l/b")


# --- § III, the slow lengthening: (32)-(38) (lines 734-816) -------------------------------


def _eq3_in_u(b: Any) -> dict[str, Any]:
    """(3), (a + bt)θ'' + 2bθ' + g sin θ = 0, solved for θ'' and written in u = √(g/a)t:
    dθ/du = θ'√(a/g), d²θ/du² = θ''a/g; u and p = b/√(ga) from line 736."""
    a, g, t, theta, dth = symbols("a", "g", "t", "theta", "dtheta_dt")
    second = -(2 * b * dth + g * sp.sin(theta)) / (a + b * t)
    return {
        "d2theta_du2": second * a / g,
        "dtheta_du": dth * sp.sqrt(a / g),
        "u": sp.sqrt(g / a) * t,
        "p": b / sp.sqrt(g * a),
    }


@cache
def reference_eq3_in_u() -> Any:
    """(32) from (3) in the variables of line 736."""
    (b,) = symbols("b")
    return reference(_eq3_in_u(b), "(3) in u = √(g/a)t, p = b/√(ga)")


@cache
def reference_ordinary_pendulum() -> Any:
    """(33): (3) with b = 0 (p = 0), in u."""
    return reference(_eq3_in_u(sp.Integer(0)), "(3) with b = 0, in u")


@cache
def reference_cn_solution() -> Any:
    """(34)-(35), lines 754-764: the textbook solution of (33) with amplitude θ0,
    sin(θ/2) = k cd v = k cn v/dn v (k = sin(θ0/2), v = u + C), written with φ = am v:
    cn v = cos φ, sn v = sin φ, dn v = √(1 − k² sin²φ); d/du = dn v · d/dφ."""
    k, phi = symbols("k", "phi")
    dn = sp.sqrt(1 - k**2 * sp.sin(phi) ** 2)
    theta = 2 * sp.asin(k * sp.cos(phi) / dn)
    first = sp.diff(theta, phi) * dn
    exact = {
        "theta": theta,
        "theta0": 2 * sp.asin(k),
        "kp": sp.sqrt(1 - k**2),
        "cnv": sp.cos(phi),
        "snv": sp.sin(phi),
        "dnv": dn,
        "dtheta_du": first,
        "d2theta_du2": sp.diff(first, phi) * dn,
    }
    return reference(exact, "sin(θ/2) = k cd v, the solution of (33)")


def _partial_chain() -> Any:
    """The total u-derivative of a function of (u, k(u), C(u)), from its partial
    derivatives (th_u, th_k, th_C, th_uu, th_uk, th_uC), with dC/du from (36)."""
    names = ("theta", "th_u", "th_k", "th_C", "th_uu", "th_uk", "th_uC", "dk_du", "dC_du")
    theta, th_u, th_k, th_c, th_uu, th_uk, th_uc, dk, dc = symbols(*names)
    partial = {theta: (th_u, th_k, th_c), th_u: (th_uu, th_uk, th_uc)}

    def total(f: Any) -> Any:
        du, dkk, dcc = partial[f]
        return du + dkk * dk + dcc * dc

    osculating = sp.solve(th_k * dk + th_c * dc, dc)[0]  # (36)
    return total, osculating, (theta, th_u, dc)


@cache
def reference_osculating() -> Any:
    """Lines 770-774: dθ/du and d²θ/du² by the chain rule with (36)."""
    total, osculating, (theta, th_u, dc) = _partial_chain()
    first = total(theta).subs(dc, osculating)
    second = total(th_u).subs(dc, osculating)
    return reference(
        {"dtheta_du": first, "d2theta_du2": second, "dC_du": osculating}, "the chain rule, (36)"
    )


@cache
def reference_eq37() -> Any:
    """(37): dk/du, dC/du solved from (32), written with lines 770-774, and (36); the
    printed remark θ_uu + sin θ = 0 (the partial θ solves (33))."""
    total, _, (theta, th_u, dc) = _partial_chain()
    p, u, th_k, th_c, th_uu = symbols("p", "u", "th_k", "th_C", "th_uu")
    (dk,) = symbols("dk_du")
    first, second = total(theta), total(th_u)
    motion = second + sp.sin(theta) + p * (u * second + 2 * first)
    motion = motion.subs(sp.sin(theta), -th_uu)
    solved = sp.solve([motion, th_k * dk + th_c * dc], [dk, dc], dict=True)[0]
    return reference({"dk_du": solved[dk], "dC_du": solved[dc]}, "(32), (36)")


@cache
def reference_phase_derivatives() -> Any:
    """Line 782: θ of (35) is a function G(u + C, k): its partial derivatives."""
    u, c, k = symbols("u", "C", "k")
    big_g = sp.Function("G")(u + c, k)
    exact = {
        "th_u": big_g.diff(u),
        "th_C": big_g.diff(c),
        "th_uu": big_g.diff(u, 2),
        "th_uC": big_g.diff(u, c),
    }
    return reference(exact, "θ = G(u + C, k)")


@cache
def _amplitude_series() -> Any:
    """am u through k³: u = F(φ, k) = ∫₀^φ dφ/√(1 − k² sin²φ), its integrand's series in
    k integrated, then inverted as φ = u + k² c(u) (c solved from the k² coefficient)."""
    k, phi, u = symbols("k", "phi", "u")
    integrand = taylor(1 / sp.sqrt(1 - k**2 * sp.sin(phi) ** 2), k, 4)
    elliptic_f = sp.integrate(sp.expand(integrand), (phi, 0, phi))
    c = sp.Symbol("c")
    guess = u + k**2 * c
    residual = sp.expand(taylor(elliptic_f.subs(phi, guess) - u, k, 4))
    return guess.subs(c, sp.solve(residual.coeff(k, 2), c)[0])


@cache
def reference_amplitude_series() -> Any:
    """Lines 786-816: φ = am u through k³, cn u = cos am u, k' = √(1 − k²), θ = (35) at
    C = 0, f(u) its definition (line 814); a series in k through k³."""
    k, u = symbols("k", "u")
    am = _amplitude_series()
    kp = sp.sqrt(1 - k**2)
    exact = {
        "phi": am,
        "cnu": sp.cos(am),
        "kp": kp,
        "theta": 2 * sp.atan(k / kp * sp.cos(am)),
        "fu": 9 * sp.cos(u) - sp.cos(3 * u) + 12 * u * sp.sin(u),
    }
    return reference(exact, "am u through k³, (35) at C = 0")
