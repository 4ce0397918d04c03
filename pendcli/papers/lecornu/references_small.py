"""Lecornu (1894), § II, Étude des oscillations infiniment petites, lines 118-256: the path's
graphical equation, φ = √x J₁(2√x) and its series (10), (11), the elongations (12)-(14) and
the roots of J₁ and J₂ (the printed numbers of lines 206-256 are in references_numeric).

Each builder maps ledger symbols to exact expressions: the exact solutions of (9), their
roots found numerically (mpmath, 40 digits); never a second copy of the formula the row prints.
"""

from __future__ import annotations

import itertools
from typing import Any

import mpmath
import sympy as sp

from pendcli.papers.lecornu.references_base import (
    cylinder,
    float40,
    mpmath_str,
    phi_of,
    reference,
    roots_of,
    scan_roots,
    symbols,
)


def _trajectory(zl: Any, cl: Any) -> Any:
    """The bob's path u(z) (lines 124, 134): a solution of (9) with x = z/c, here
    √x J₁(2√x) + √x Y₁(2√x) (both kinds, so neither special case)."""
    x = zl / cl
    return phi_of(x, "j") + phi_of(x, "y")


def reference_graphical() -> Any:
    """Lines 124-130: x = z/c in (9), u(z) exact; h the ordinate at z = 0 of the tangent at (z,
    u)."""
    zl, cl, at = symbols("zl", "cl", "Z_")
    u = _trajectory(zl, cl)
    slope = u.diff(zl)
    tangent = u + slope * (at - zl)
    h = tangent.subs(at, 0)
    exact = {"u": u, "du_dzl": slope, "d2u_dzl2": u.diff(zl, 2), "h": h, "dh_dzl": h.diff(zl)}
    return reference(exact, "the exact path u(z) of (9), x = z/c, and its tangent")


def reference_inflection() -> Any:
    """Line 138: the exact path u(z) of (9) (x = z/c, _trajectory) at each of its first four
    zeros (the passages through the vertical, found by a scan, mpmath): its u''."""
    zl, cl = symbols("zl", "cl")
    u = _trajectory(zl, cl)
    zeros = roots_of("path", "zero", 0.2, 60)[:4]
    cases = tuple({"zl": cl * float40(x)} for x in zeros)
    exact = {"u": u, "du_dzl": u.diff(zl), "d2u_dzl2": u.diff(zl, 2)}
    return reference(exact, "the path u(z) of (9) at its zeros", each_case=cases)


def reference_curvature() -> Any:
    """Lines 140-142: the curvature of the exact path at small slopes (« au même degré
    d'approximation », line 140): κ = d²u/dz², u(z) of (9) with x = z/c; θ = u/z (l = z, line
    134)."""
    zl, cl = symbols("zl", "cl")
    u = _trajectory(zl, cl)
    kappa = u.diff(zl, 2)
    at_c = (kappa / u).subs(zl, cl)  # the constant K of κ = K u, if there were one
    exact = {"u": u, "kappa": kappa, "d2u_dzl2": kappa, "theta": u / zl, "K": at_c}
    return reference(exact, "the exact path's u''")


def reference_step_of_h() -> Any:
    """Line 130: the variation Δh of h = u − z du/dz (line 128) over a step Δz of the exact
    path u(z) (x = z/c, φ of (10)), Δz scaled by ε: « sensiblement » is through ε¹."""
    eps = sp.Symbol("eps_", positive=True)
    zl, cl, step = symbols("zl", "cl", "Deltaz")
    u = phi_of(zl / cl)
    h = u - zl * u.diff(zl)
    exact = {"u": u, "Deltaz": eps * step, "Deltah": h.subs(zl, zl + eps * step) - h}
    return reference(exact, "h of the path at z and z + Δz")


def reference_construction() -> Any:
    """Line 132, the construction drawn in coordinates (z abscissa, u ordinate): P = (0, h) on
    the u-axis, M = (z, u), A = (z, 0), B = (z, −c), Q = P moved by Δz towards B's side,
    S = AP ∩ BQ, P' = SM ∩ (u-axis); Δh is the ordinate of P' less h (sympy geometry)."""
    zl, u, h, cl, step = symbols("zl", "u", "h", "cl", "Deltaz")
    pa, pb = sp.Point(zl, 0), sp.Point(zl, -cl)
    pp, pq, pm = sp.Point(0, h), sp.Point(0, h - step), sp.Point(zl, u)
    (ps,) = sp.Line(pa, pp).intersection(sp.Line(pb, pq))
    (pp2,) = sp.Line(ps, pm).intersection(sp.Line(sp.Point(0, 0), sp.Point(0, 1)))
    return reference({"Deltah": sp.simplify(pp2.y - h)}, "the construction of line 132")


def reference_projections() -> Any:
    """Line 134: the rod's projections y = l cos θ, x = l sin θ (line 34) for a small angle
    (θ scaled by ε, through ε¹), c = b²/g and z = cx (line 124), u = θl (line 112)."""
    eps = sp.Symbol("eps_", positive=True)
    length, theta, b, g = symbols("l", "theta", "b", "g")
    small = eps * theta
    exact = {
        "theta": small,
        "yc": length * sp.cos(small),
        "xc": length * sp.sin(small),
        "x": g * length / b**2,
        "zl": length,  # z = cx with c = b²/g, x = gl/b²
        "u": small * length,
    }
    return reference(exact, "the rod's projections at small θ")


def reference_at_elongations() -> Any:
    """Lines 152, 204: the elongations of (10)'s motion, where θ ∝ φ/x is stationary:
    d(J₁(2√x)/√x)/dx = −J₂(2√x)/x, so x = j₂,ₖ²/4 (mpmath.besseljzero, the first five),
    z = 2√x = j₂,ₖ, ξ = x; h = φ − xφ' (line 128 with x = z/c: the ordinate of the tangent
    over c); l = (b²/g)ξ, b and g from 1/10 to 2 (units left free)."""
    x, xi, b, g = symbols("x", "xi", "b", "g")
    phi = phi_of(x)
    with mpmath.workdps(40):
        zeros = [mpmath.besseljzero(2, k) for k in range(1, 6)]
        cases = tuple(
            {"x": float40(j**2 / 4), "xi": float40(j**2 / 4), "z": float40(j)} for j in zeros
        )
    exact = {"h": phi - x * phi.diff(x), "l": b**2 * xi / g}
    return reference(exact, "the elongations of θl = φ (J₂ = 0)", each_case=cases)


def _between(exact: dict[str, Any], low: Any, high: Any) -> Any:
    """A transform: an identity with an indefinite integral ∫f dz (true up to a constant)
    judged between two points, r(high) − r(low), each ∫f dz read as ∫_low^high f dz; the
    reference's ``exact`` is substituted first (an integral's coefficient must not depend on
    z, or a term F(low) is left and the residual is not a number)."""

    def transform(expr: Any) -> Any:
        names = {s.name: s for s in expr.free_symbols}
        expr = expr.subs({names[n]: v for n, v in exact.items() if n in names}, simultaneous=True)
        indefinite = [i for i in expr.atoms(sp.Integral) if len(i.limits[0]) == 1]
        for number, integral in enumerate(indefinite):
            variable = integral.limits[0][0]
            antiderivative = sp.Function(f"F{number}_")
            expr = expr.subs(integral, antiderivative(variable))
            expr = expr.subs(variable, high) - expr.subs(variable, low)
            definite = sp.Integral(integral.function, (variable, low, high))
            expr = expr.subs(antiderivative(high), antiderivative(low) + definite)
        return expr

    return transform


def reference_area() -> Any:
    """Lines 144-152: the path u(z) of (10)'s motion (x = z/c), h the ordinate of its tangent
    at z = 0 (line 126); h = (1/c)∫u dz judged between z1 and any z (_between); the cases: two
    pairs of consecutive elongations (h = 0 at both) and a pair with the same h ≠ 0 (the
    second point found by a scan for h(z2) = h(z1))."""
    zl, cl, zl1 = symbols("zl", "cl", "zl1")
    u = phi_of(zl / cl)  # J₁ only: the quadratures of Y₁ cost seconds
    exact = {"u": u, "h": u - zl * u.diff(zl)}
    elongations = roots_of("bessel", "tangent", 0.5, 40)[:3]
    first = elongations[0] + (elongations[1] - elongations[0]) / 3
    exact_path, coarse_path = cylinder("bessel")

    def level(x: Any, pair: Any = exact_path) -> Any:
        value, slope = pair(x)
        return value - x * slope

    with mpmath.workdps(40):
        target = level(first)
    second = scan_roots(
        lambda x: level(x) - target,
        lambda x: level(x, coarse_path) - float(target),
        float(elongations[1]),
        40,
        800,
    )[0]
    pairs = [*itertools.pairwise(elongations), (first, second)]
    cases = tuple({"zl1": cl * float40(p), "zl2": cl * float40(q)} for p, q in pairs)
    return reference(
        exact, "the path u(z) of (10)'s motion", each_case=cases, transform=_between(exact, zl1, zl)
    )


def _phi_series(order: int) -> Any:
    eps = sp.Symbol("eps_", positive=True)
    (x,) = symbols("x")
    exact = {
        "x": eps * x,
        "varphi": phi_of(eps * x),
        "dvarphi_dx": phi_of(x).diff(x).subs(x, eps * x),
    }
    return reference(exact, "φ = √x J₁(2√x)")


def reference_phi_series() -> Any:
    """(10), line 158: φ = √x J₁(2√x) (the text's own identification, line 160), x scaled by ε,
    through ε⁴."""
    return _phi_series(5)


def _elongation_roots(count: int) -> list[Any]:
    """x at the first elongations of (10)'s motion: where θ ∝ φ/x is stationary, i.e.
    φ − xφ' = 0 (φ = √x J₁(2√x), φ' = J₀(2√x)), x > 0, by a scan (mpmath)."""
    return roots_of("bessel", "tangent", 0.5, 100)[:count]


def reference_elongations_of_12() -> Any:
    """(12) and lines 170-178 at the first three elongations of θl = φ (θ = gφ/(b²x)
    stationary, _elongation_roots): dθ = θ'(x)dx, dl/dx = b²/g."""
    x, b, g = symbols("x", "b", "g")
    phi = phi_of(x)
    theta = g * phi / (b**2 * x)
    exact = {
        "varphi": phi,
        "dvarphi_dx": phi.diff(x),
        "theta": theta,
        "dtheta": sp.diff(theta, x),
        "l": b**2 * x / g,
        "dl_dx": b**2 / g,
    }
    cases = tuple({"x": float40(r)} for r in _elongation_roots(3))
    return reference(exact, "the elongations of θl = φ", each_case=cases)


def reference_eq13() -> Any:
    """Lines 182-188: (12)'s condition φ/x − φ' = 0 with φ = √x J₁(2√x), then divided by x
    (« en divisant par x »), x scaled by ε through ε² (the terms printed)."""
    eps = sp.Symbol("eps_", positive=True)
    (x,) = symbols("x")
    condition = phi_of(x) / x - phi_of(x).diff(x)
    exact = {"x": eps * x}
    return reference(exact, "(12) with φ = √x J₁(2√x)", conditions=(condition, condition / x))


def reference_first_member_13() -> Any:
    """Line 196: the first member of (13) as (13) is derived, (φ/x − φ')/x with
    φ = √x J₁(2√x); x scaled by ε, through ε²."""
    eps = sp.Symbol("eps_", positive=True)
    (x,) = symbols("x")
    member = ((phi_of(x) / x - phi_of(x).diff(x)) / x).subs(x, eps * x)
    exact = {"x": eps * x, "m13": member}
    return reference(exact, "(12) divided by x")


def _elongation_root() -> Any:
    """The first x > 0 where θ ∝ φ/x = J₁(2√x)/√x is stationary (mpmath, 40 digits, the
    derivative taken analytically: d/dx J₁(2√x)/√x = J₁'(2√x)/x − J₁(2√x)/(2x√x))."""
    with mpmath.workdps(40):

        def slope(x: Any) -> Any:
            root = mpmath.sqrt(x)
            return mpmath.besselj(1, 2 * root, derivative=1) / x - mpmath.besselj(1, 2 * root) / (
                2 * x * root
            )

        return mpmath.findroot(slope, 6.5)


def reference_elongation_root() -> Any:
    """(14), lines 196-202: x = ξ, the first elongation (where d(φ/x)/dx = 0, found numerically), z
    = 2√ξ."""
    xi = sp.Float(mpmath_str(_elongation_root()), 40)
    return reference({"x": xi, "z": 2 * sp.sqrt(xi)}, "the first root of d(φ/x)/dx = 0")


def reference_roots_interlace() -> Any:
    """Lines 204-206 at the five elongations below z = 20 (_elongation_roots, z = 2√ξ) and
    the roots of J₁ around each (mpmath.besseljzero)."""
    roots = _elongation_roots(5)
    with mpmath.workdps(40):
        j1 = [mpmath.besseljzero(1, k) for k in range(1, 7)]
        z = [2 * mpmath.sqrt(r) for r in roots]
    cases = tuple(
        {"z": float40(z[k]), "zeta1": float40(j1[k]), "zeta2": float40(j1[k + 1])} for k in range(5)
    )
    return reference({}, "the elongations and the roots of J₁", each_case=cases)


def reference_amplitude_j0() -> Any:
    """Lines 234-236: θ = φ/l at the maxima, the same elongations (φ − xφ' = 0, i.e. J₂(z) = 0
    with z = 2√x, where 2J₁(z)/z = J₀(z)); l = (b²/g)x; lengths in metres (the memoir's φ is
    a pure number « multipliée par une constante arbitraire », line 160, here one metre)."""
    x, b, g = symbols("x", "b", "g")
    phi = phi_of(x)
    exact = {
        "varphi": phi,
        "theta": g * phi / (b**2 * x),
        "l": b**2 * x / g,
        "z": 2 * sp.sqrt(x),
        "metre": sp.Integer(1),
    }
    cases = tuple({"x": float40(r)} for r in _elongation_roots(3))
    return reference(exact, "θl = φ of (10) at its elongations", each_case=cases)


def reference_zero_length() -> Any:
    """Line 242: z = 2√x → 0 (x scaled by ε², z by ε): the limit is the ε⁰ term."""
    eps = sp.Symbol("eps_", positive=True)
    x, z = symbols("x", "z")
    return reference({"x": eps**2 * x, "z": eps * z, "varphi": phi_of(eps**2 * x)}, "J₁ near 0")


def reference_series_of_nine() -> Any:
    """Line 160: the solution of (9) analytic at 0 with u(0) = 0, u'(0) = 1 (the first term of
    (10)), by its own recursion n(n − 1)aₙ = −aₙ₋₁ (sympy rationals), x scaled by ε, through
    ε⁵; not Bessel's function, which the row's printed form names."""
    eps = sp.Symbol("eps_", positive=True)
    (x,) = symbols("x")
    terms, coefficient = [], sp.Integer(1)
    for n in range(1, 8):
        if n > 1:
            coefficient = -coefficient / (n * (n - 1))
        terms.append(coefficient * (eps * x) ** n)
    exact = {"x": eps * x, "varphi": sp.Add(*terms)}
    return reference(exact, "(9)'s solution by its recursion")


def reference_speed_at_one_metre() -> Any:
    """Line 214: ξ = gl/b² (line 194) for the pendulum « ayant un mètre de longueur », l one
    metre (a length, kept a symbol); b, g positive."""
    b, g, metre = symbols("b", "g", "metre")
    return reference({"xi": g * metre / b**2}, "ξ = gl/b² at l = 1 m")


def reference_angular_speed_at_zero_length() -> Any:
    """Line 230: dθ/dt of (10)'s motion, θ = (g/b²)·φ/x times one metre (the memoir's φ carries
    a length, line 160), dθ/dt = b dθ/dl = (g/b) dθ/dx, at x → 0 (sympy's limit)."""
    x, b, g, metre = symbols("x", "b", "g", "metre")
    theta = metre * g * phi_of(x) / (b**2 * x)
    rate = sp.limit((g / b) * theta.diff(x), x, 0, "+")
    return reference({"dtheta_dt": rate}, "dθ/dt of (10)'s motion at l = 0")
