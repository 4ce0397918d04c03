"""Lecornu (1894), § II, lines 258-380: the general integral (17)-(22) of (9), its continuation
past the roots of φ and φ' ((17'), (21'), the general rule), the initial constants and the
limit at zero length.

Each builder maps ledger symbols to exact expressions: the solution of (9) with given value
and slope at x0, written in the basis √x J₁(2√x), √x Y₁(2√x); never a second copy of the
formula the row prints.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import mpmath
import sympy as sp

from pendcli.papers.lecornu.references_base import float40, phi_of, reference, roots_of, symbols


def _general_u(x: Any, x0: Any, big_a: Any, big_b: Any) -> Any:
    """The solution of (9) whose value and slope at x0 are Aφ0 and Aφ'0 + B/φ0 (line 348),
    written in the independent basis √x J₁(2√x), √x Y₁(2√x)."""
    c1, c2 = _basis_coefficients(x0, big_a, big_b)
    return c1 * phi_of(x, "j") + c2 * phi_of(x, "y")


def _basis_coefficients(x0: Any, big_a: Any, big_b: Any) -> tuple[Any, Any]:
    """_general_u's coefficients of √x J₁(2√x) and √x Y₁(2√x) (the Wronskian at x0)."""
    s = sp.Dummy("s", positive=True)
    j, y = phi_of(s, "j"), phi_of(s, "y")
    dj, dy = j.diff(s), y.diff(s)
    at = {s: x0}
    u0 = big_a * j.subs(at)
    du0 = big_a * dj.subs(at) + big_b / j.subs(at)
    wronskian = (j * dy - dj * y).subs(at)
    c1 = (u0 * dy.subs(at) - du0 * y.subs(at)) / wronskian
    c2 = (du0 * j.subs(at) - u0 * dj.subs(at)) / wronskian
    return c1, c2


def _bessel_exact(switch: dict[str, Any] | None = None) -> dict[str, Any]:
    """u, u', φ, φ', φ'' and the values φ_j, φ'_j at the named points; C = A + B/(φ0φ'0)."""
    # a fresh dict of the shared expressions (seven rows cite them), then the switches
    exact = dict(_bessel_items())
    exact.update(switch or {})
    return exact


@cache
def _bessel_items() -> tuple[tuple[str, Any], ...]:
    x, x0, big_a, big_b = symbols("x", "x0", "A", "B")
    u = _general_u(x, x0, big_a, big_b)
    phi = phi_of(x)
    exact = {
        "u": u,
        "du_dx": u.diff(x),
        "d2u_dx2": u.diff(x, 2),
        "varphi": phi,
        "dvarphi_dx": phi.diff(x),
        "d2varphi_dx2": phi.diff(x, 2),
        "C": big_a + big_b / (phi * phi.diff(x)).subs(x, x0),
    }
    for point in ("0", "1", "2", "k", "h"):
        (where,) = symbols(f"x{point}")
        exact[f"varphi{point}"] = phi.subs(x, where)
        exact[f"varphip{point}"] = phi.diff(x).subs(x, where)
    return tuple(exact.items())


def _u_over_phi_at(point: str) -> Any:
    """A new constant of (17)-type at ``point``: u/φ there (the form u = A'φ + … at x = x_j)."""
    x, where = symbols("x", point)
    exact = _bessel_exact()
    return sp.Mul(exact["u"], 1 / exact["varphi"]).subs(x, where)


def reference_bessel_general() -> Any:
    """(17)-(22), lines 262-310, between x0 and x in (1/10, 1/2), where φ and φ' have no root."""
    return reference(_bessel_exact(), "u of (9) from its value and slope at x0, √x J₁, √x Y₁")


def reference_monotone_as_cited() -> Any:
    """Line 276, « L'équation (10) montre »: what (10) gives, φ = √x J₁(2√x) and φ', between the
    roots 3.670 and 12.31 of φ; it says nothing of u or u', so the sign of d(u/φ)/dx is not fixed by
    it. The reading is judged against (20) (u' solved from it)."""
    x, u, du, big_b, phi_s, dphi_s = symbols("x", "u", "du_dx", "B", "varphi", "dvarphi_dx")
    phi = phi_of(x)
    exact = {"varphi": phi, "dvarphi_dx": phi.diff(x)}
    rates = {"x": {"u": du, "varphi": dphi_s}}
    q = sp.Symbol("q_")
    eq20 = (q * phi_s - u * dphi_s) / phi_s**2 - big_b / phi_s**2  # (20), d/dx by the rates
    solved = sp.solve(eq20, q)[0].subs({phi_s: phi, dphi_s: phi.diff(x)}, simultaneous=True)
    # u' solved from (20) takes any sign: u over (-1, 1) beside the row's domain
    reading = reference({**exact, "du_dx": solved}, "(20)", rates=rates, domain={"u": (-1, 1)})
    return reference(exact, "(10)", rates=rates, reading=reading)


def reference_at_beta() -> Any:
    """Lines 276-284: u of (9) at β, the first root of φ (β = j₁,₁²/4: φ = √x J₁(2√x))."""
    with mpmath.workdps(30):
        beta = sp.Float(str(mpmath.besseljzero(1, 1) ** 2 / 4), 30)
    (x,) = symbols("x")
    exact = {k: v.subs(x, beta) for k, v in _bessel_exact().items()}
    return reference(exact, "u of (9) at the root β = 3.670 of φ")


def _vertical_count(x0: Any, big_a: Any, big_b: Any, low: Any, high: Any) -> int:
    """The sign changes, on 400 points strictly inside (low, high), of the solution of (9)
    with u = Aφ, u' = Aφ' + B/φ at x0 (as _general_u; in floats: the basis √x J₁(2√x),
    √x Y₁(2√x) and its derivative J₀, Y₀ by scipy, the coefficients by numpy)."""
    import numpy as np
    from scipy.special import jv, yv

    def basis(x: Any) -> Any:
        s = 2 * np.sqrt(x)
        return np.array([[np.sqrt(x) * jv(1, s), np.sqrt(x) * yv(1, s)], [jv(0, s), yv(0, s)]])

    start = float(x0)
    phi0, dphi0 = basis(start)[:, 0]
    data = [float(big_a) * phi0, float(big_a) * dphi0 + float(big_b) / phi0]
    c1, c2 = np.linalg.solve(basis(start), data)
    x = np.linspace(float(low), float(high), 402)[1:-1]
    values = c1 * basis(x)[0, 0] + c2 * basis(x)[0, 1]
    return int(np.sum(values[:-1] * values[1:] < 0))


def reference_one_vertical() -> Any:
    """Line 286 for three solutions of (9) (A, B at x0, B ≠ 0) and each of the first four
    pairs of consecutive roots α < β of φ (a scan of √x J₁(2√x), mpmath): l = (b²/g)x at
    α, β (line 112), z1, z2 the roots of J₁ (mpmath.besseljzero), nvert the sign changes of u
    between α and β."""
    b, g = symbols("b", "g")
    roots = roots_of("bessel", "zero", 1, 80)
    with mpmath.workdps(40):
        j1 = [mpmath.besseljzero(1, k) for k in range(1, 6)]
    solutions = [(sp.Rational(3, 10), 1, 1), (sp.Rational(5, 2), sp.Rational(-7, 10), 2),
                 (8, sp.Rational(1, 5), sp.Rational(-3, 10))]  # fmt: skip
    cases = []
    for k in range(4):
        alpha, beta = roots[k], roots[k + 1]
        for x0, big_a, big_b in solutions:
            cases.append({
                "zeta1": float40(j1[k]),
                "zeta2": float40(j1[k + 1]),
                "l1": b**2 / g * float40(alpha),
                "l2": b**2 / g * float40(beta),
                "nvert": sp.Integer(_vertical_count(x0, big_a, big_b, alpha, beta)),
            })  # fmt: skip
    return reference({}, "the zeros of u between the roots of φ", each_case=tuple(cases))


def reference_bessel_past_beta() -> Any:
    """(17'), A', lines 314-320: x0 in (3/2, 18/5) (between the roots 1.446 of φ' and 3.670 of φ),
    x1 and x past β = 3.670 and below the next root 7.618 of φ'; A' = u(x1)/φ(x1)."""
    exact = _bessel_exact({"Ap": _u_over_phi_at("x1")})
    return reference(exact, "u of (9); A' = u/φ at x1 (line 316)")


def reference_bessel_past_alpha_prime() -> Any:
    """(21'), C', lines 324-328: as above, and x2, x past α' = 7.618, below the root 12.31 of φ;
    C' = (u + B/φ')/φ at x2 (the form (21') at x = x2)."""
    x, x2, big_b = symbols("x", "x2", "B")
    exact = _bessel_exact()
    c_prime = ((exact["u"] + big_b / exact["dvarphi_dx"]) / exact["varphi"]).subs(x, x2)
    exact["Cp"] = c_prime
    exact["Ap"] = _u_over_phi_at("x1")
    return reference(exact, "u of (9); C' = (u + B/φ')/φ at x2 (line 326)")


def reference_initial_data() -> Any:
    """Lines 346-360: u = θl, x = gl/b² at t = 0 (l = a): u0 = aθ0, u'0 = (b²/g)(θ0 + a ω0/b) by the
    chain rule; A, B solved from u0 = Aφ0, u'0 = Aφ'0 + B/φ0 ((17), (18) at x0); C = A +
    B/(φ0φ'0)."""
    a, b, g, theta0, omega0, phi0, dphi0, big_a, big_b = symbols(
        "a", "b", "g", "theta0", "omega0", "varphi0", "varphip0", "A", "B"
    )
    u0 = a * theta0
    du0 = b**2 / g * (theta0 + a * omega0 / b)  # d(θl)/dx = (dl/dx)(θ + l dθ/dl)
    solved = sp.solve([u0 - big_a * phi0, du0 - big_a * dphi0 - big_b / phi0], [big_a, big_b])
    exact = {
        "u0": u0,
        "up0": du0,
        "A": solved[big_a],
        "B": solved[big_b],
        "C": solved[big_a] + solved[big_b] / (phi0 * dphi0),
    }
    return reference(exact, "the initial data θ0, ω0 at l = a")


def reference_limit_at_zero() -> Any:
    """Lines 364-380: φ = Mx (M = φ/x, line 364); p the mean value of line 370 (1/p² the mean
    of 1/M² under the weight 1/x² over (x, x0)); q its limit as x → 0, M(0) (the weight
    concentrates at 0); the limits of φ∫dx/φ² (the solution of (9) with value 0, slope 1/φ0
    at x0) and of u (_general_u) as x → 0, from the basis: √x J₁(2√x) → 0 and √x Y₁(2√x) →
    its sympy limit; θ = u/l, l = (b²/g)x."""
    x, x0, big_a, big_b, b, g, u = symbols("x", "x0", "A", "B", "b", "g", "u")
    s = sp.Dummy("s", positive=True)
    phi = phi_of(x)
    at_zero = sp.limit(phi_of(s, "y"), s, 0)
    mean = (1 / x0 - 1 / x) / sp.Integral(1 / phi_of(s) ** 2, (s, x0, x))
    exact = {
        "varphi": phi,
        "M": phi / x,
        "p": sp.sqrt(mean),
        "q": sp.limit(phi_of(s) / s, s, 0),
        "lim0": _basis_coefficients(x0, 0, 1)[1] * at_zero,
        "ulim": _basis_coefficients(x0, big_a, big_b)[1] * at_zero,
        "theta": u / (b**2 * x / g),
    }
    return reference(exact, "(9)'s solutions near x = 0")


def reference_hopital_at_beta() -> Any:
    """Line 280: the « vraie valeur » of ∫_(x0)^x dx/φ² over 1/φ as x → β, by L'Hôpital: the
    ratio of the two derivatives, taken by sympy for an unknown function φ(x) and written in
    the ledger's φ, φ' (lhop)."""
    x, x0, varphi, dvarphi = symbols("x", "x0", "varphi", "dvarphi_dx")
    f = sp.Function("f_")(x)
    top = sp.Integral(1 / f**2, (x, x0, x)).diff(x)
    bottom = (1 / f).diff(x)
    ratio = (top / bottom).subs(f.diff(x), dvarphi).subs(f, varphi)
    return reference({"lhop": sp.simplify(ratio)}, "L'Hôpital's ratio of ∫dx/φ² to 1/φ")


def reference_rolle() -> Any:
    """Line 282: φ' = J₀(2√x) at consecutive roots α, β of φ = √x J₁(2√x): x = j₁,ₖ²/4
    (mpmath.besseljzero), the first four pairs; φ' taken by sympy from φ."""
    (x,) = symbols("x")
    slope = phi_of(x).diff(x)
    with mpmath.workdps(40):
        roots = [mpmath.besseljzero(1, k) ** 2 / 4 for k in range(1, 6)]
    values = [slope.subs(x, float40(r)).evalf(30) for r in roots]
    cases = tuple({"dvarphi_alpha": values[k], "dvarphi_beta": values[k + 1]} for k in range(4))
    return reference({}, "φ' at consecutive roots of φ", each_case=cases)


def reference_kick_at_vertical() -> Any:
    """Line 258: the motion started by a lateral kick at the vertical, at the length of a root
    x1 of φ (u = 0, u' = 1 there): u = αφ + β√x Y₁(2√x) with α, β solved from those data
    (mpmath, 40 digits; d/dx √x Z₁(2√x) = Z₀(2√x)), at the next four roots of φ (j₁,ₖ²/4)."""
    with mpmath.workdps(40):
        roots = [mpmath.besseljzero(1, k) ** 2 / 4 for k in range(1, 6)]
        s = 2 * mpmath.sqrt(roots[0])
        rows = [
            [
                mpmath.sqrt(roots[0]) * mpmath.besselj(1, s),
                mpmath.sqrt(roots[0]) * mpmath.bessely(1, s),
            ],
            [mpmath.besselj(0, s), mpmath.bessely(0, s)],
        ]
        alpha, beta = mpmath.lu_solve(mpmath.matrix(rows), mpmath.matrix([0, 1]))

        def u(x: Any) -> Any:
            t = 2 * mpmath.sqrt(x)
            return mpmath.sqrt(x) * (alpha * mpmath.besselj(1, t) + beta * mpmath.bessely(1, t))

        cases = tuple({"u": float40(u(r))} for r in roots[1:])
    return reference({}, "the motion kicked at a root of φ, at the next roots", each_case=cases)


def reference_x_of_l() -> Any:
    """Lines 284, 344: x = gl/b², line 112's definition of x, solved for x; lines 190-194: the
    same at the elongation x = ξ."""
    length, g, b = symbols("l", "g", "b")
    return reference({"x": g * length / b**2, "xi": g * length / b**2}, "x = gl/b² (line 112)")
