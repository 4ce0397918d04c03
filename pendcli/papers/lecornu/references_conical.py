"""Lecornu, § IV « Pendule conique de longueur variable », lines 940-1062: the references
the printed forms of the conical pendulum's motion, (43)-(46) and the general integral of
(45) are judged against (verify/printed_check).

Each ``reference_*`` maps ledger symbols (tables/equations/lecornu.toml [symbols]) to exact
expressions: the equation of motion, the preceding equation, a definition, a solution
computed here (by sympy, or by mpmath's ODE solver for the general integral); never a copy
of the formula the row prints.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import mpmath
import sympy as sp

from pendcli.base.recent import Recent
from pendcli.papers.lecornu.references_base import derivative_along, reference, symbols

# --- § IV, the motion in rectangular and polar coordinates, (43)-(45) (lines 940-1016) ---


def _conical_state() -> dict[str, Any]:
    """The motion of lines 942-946 (x'' = −Tx/l, y'' = −Ty/l, z'' = −Tz/l + g) at a state
    (x, y, z, x', y', z'); r = √(x² + y²), its derivatives by the chain rule along the motion,
    c = x y' − y x' (the constant the area theorem names)."""
    x, y, z, dx, dy, _dz, tn, length, g = symbols(
        "X", "Y", "Z", "dX_dt", "dY_dt", "dZ_dt", "Tn", "l", "g"
    )
    d2x, d2y, d2z = -tn * x / length, -tn * y / length, -tn * z / length + g
    rates = {x: dx, y: dy, dx: d2x, dy: d2y}

    along = derivative_along(rates)

    r = sp.sqrt(x**2 + y**2)
    dr = along(r)
    return {
        "d2X_dt2": d2x,
        "d2Y_dt2": d2y,
        "d2Z_dt2": d2z,
        "r": r,
        "dr_dt": dr,
        "d2r_dt2": along(dr),
        "c": x * dy - y * dx,
    }


@cache
def reference_conical_cartesian() -> Any:
    """Lines 942-946, the motion in x, y, z, with r, r', r'' computed from it and c its
    constant of areas."""
    return reference(_conical_state(), "x'' = −Tx/l, y'' = −Ty/l, z'' = −Tz/l + g")


@cache
def reference_conical_polar() -> Any:
    """r = l sin θ, z = l cos θ (lines 988-990) and their derivatives along t (l, θ varying);
    the printed d/dt(l² dθ/dt) by the chain rule."""
    length, theta, dl, dth, d2th = symbols("l", "theta", "dl_dt", "dtheta_dt", "d2theta_dt2")
    d2l = sp.Symbol("d2l_dt2", real=True)  # any l(t): the identity of line 992 needs no l'' = 0
    rates = {length: dl, theta: dth, dl: d2l, dth: d2th}

    along = derivative_along(rates)

    r, z = length * sp.sin(theta), length * sp.cos(theta)
    exact = {"r": r, "Z": z, "d2r_dt2": along(along(r)), "d2Z_dt2": along(along(z))}
    time = {"l": dl, "theta": dth, "dtheta_dt": d2th, "dl_dt": d2l}
    return reference(exact, "r = l sin θ, z = l cos θ", rates={"t": time})


@cache
def reference_eq43() -> Any:
    """(43) from lines 984-992: r z'' − z r'' − g r + c² z/r³ = 0 with r = l sin θ,
    z = l cos θ, solved for θ'' (l = a + bt, l'' = 0); the printed d/dt by the chain rule."""
    a, b, t, dth = symbols("a", "b", "t", "dtheta_dt")
    second = _eq43_second_derivative(a + b * t)
    rates = {"t": {"l": b, "theta": dth, "dtheta_dt": second}}
    return reference({"l": a + b * t}, "lines 984-992, l = a + bt", rates=rates)


@cache
def reference_area_theorem() -> Any:
    """(44) from the area theorem of line 954: c = x y' − y x' with x = r cos φ,
    y = r sin φ, r = l sin θ (l, θ, φ varying)."""
    length, theta, phi, dl, dth, dphi = symbols(
        "l", "theta", "phi", "dl_dt", "dtheta_dt", "dphi_dt"
    )
    along = derivative_along({length: dl, theta: dth, phi: dphi})
    r = length * sp.sin(theta)
    x, y = r * sp.cos(phi), r * sp.sin(phi)
    return reference({"c": x * along(y) - y * along(x)}, "c = x y' − y x', r = l sin θ")


def _eq43_second_derivative(length: Any) -> Any:
    """θ'' from (43) (the eliminated equation of line 984 in θ, reference_eq43) at a length
    ``length`` with l' = b, l'' = 0."""
    g, c, b = symbols("g", "c", "b")
    d2th = sp.Symbol("q", real=True)
    polar = reference_conical_polar().exact
    subs = {sp.Symbol("dl_dt", real=True): b, sp.Symbol("d2l_dt2", real=True): 0}
    subs[sp.Symbol("d2theta_dt2", real=True)] = d2th
    r, z = polar["r"], polar["Z"]
    d2r, d2z = polar["d2r_dt2"].subs(subs), polar["d2Z_dt2"].subs(subs)
    motion = sp.expand(r * d2z - z * d2r - g * r + c**2 * z / r**3)
    solved = -motion.subs(d2th, 0) / motion.coeff(d2th)  # linear in θ''
    return solved.subs(sp.Symbol("l", real=True), length)


@cache
def reference_conical_l_form() -> Any:
    """Lines 1002-1008: θ'' from (43) with l' = b (l kept), and the derivatives in l,
    dθ/dl = θ'/b, d²θ/dl² = θ''/b²."""
    length, b, dth = symbols("l", "b", "dtheta_dt")
    second = _eq43_second_derivative(length)
    exact = {"d2theta_dt2": second, "dtheta_dl": dth / b, "d2theta_dl2": second / b**2}
    return reference(exact, "(43), l = a + bt")


def _small_conical_u() -> Any:
    """(43) for small θ (sin θ -> θ, cos θ -> 1) with θ = u/l, d/dt = b d/dl, solved for
    d²u/dl²: a function of (u, l)."""
    length, b, g, c = symbols("l", "b", "g", "c")
    u = sp.Function("u")(length)
    theta = u / length
    motion = b**2 * sp.diff(length**2 * sp.diff(theta, length), length)
    motion += g * length * theta - c**2 / (length**2 * theta**3)
    second = sp.solve(motion, sp.diff(u, length, 2))[0]
    return second.subs(u, sp.Symbol("uc", real=True))


@cache
def reference_conical_small() -> Any:
    """Lines 1010-1016: (43) for small angles with θ = u/l, x = gl/b², u = v√(bc/g)."""
    length, b, g, c, x, v = symbols("l", "b", "g", "c", "x", "v")
    scale = sp.sqrt(b * c / g)
    d2u_dx2 = (b**2 / g) ** 2 * _small_conical_u().subs(length, b**2 * x / g)
    exact = {
        "d2uc_dx2": d2u_dx2,
        "d2v_dx2": d2u_dx2.subs(sp.Symbol("uc", real=True), v * scale) / scale,
    }
    return reference(exact, "(43) for small θ, θ = u/l, x = gl/b²")


# --- § IV, v = λω, the general integral of (45) and ω1, ω2 (lines 1018-1062) -----------


@cache
def reference_lambda_substitution() -> Any:
    """Lines 1018-1042: v = λω with ω a solution of (9) (ω'' = −ω/x) and v of (45):
    v', v'' by the product rule (sympy), λ'' from (45), A the value of the first integral."""
    x, lam, omega, dlam, domega = symbols("x", "lam", "omega", "dlam_dx", "domega_dx")
    q = sp.Symbol("q", real=True)  # λ''
    along = derivative_along({lam: dlam, omega: domega, dlam: q, domega: -omega / x})
    v = lam * omega
    dv, d2v = along(v), along(along(v))
    motion = sp.expand(d2v + v / x - 1 / v**3)  # (45)
    second = -motion.subs(q, 0) / motion.coeff(q)
    exact = {"v": v, "dv_dx": dv, "d2v_dx2": d2v.subs(q, second), "d2lam_dx2": second}
    exact["d2omega_dx2"] = -omega / x
    exact["A45"] = (omega**2 * dlam) ** 2 + 1 / lam**2
    rates = {"x": {"lam": dlam, "omega": domega, "dlam_dx": second, "domega_dx": -omega / x}}
    return reference(exact, "(45), (9), v = λω", rates=rates)


@cache
def _conical_solution() -> dict[str, Any]:
    """A solution of (45) (mpmath's Taylor ODE solver at 30 digits from x = 1, v = 1.1,
    v' = 0.3), ω = √x J1(2√x) a solution of (9), λ = v/ω (line 1018), ∫dx/ω² from x = 2
    (quadrature), A the first integral (ω²λ')² + 1/λ² at x = 2 (line 1038) and B its second
    constant: √(Aλ² − 1)/A at x = 2 (line 1042 integrated from there)."""
    with mpmath.workdps(30):
        solution = mpmath.odefun(
            lambda x, s: [s[1], -s[0] / x + 1 / s[0] ** 3],
            1,
            [mpmath.mpf("1.1"), mpmath.mpf("0.3")],
        )

        def omega(x: Any) -> Any:
            return mpmath.sqrt(x) * mpmath.besselj(1, 2 * mpmath.sqrt(x))

        def lam(x: Any) -> Any:
            return solution(x)[0] / omega(x)

        def lam_slope(x: Any) -> Any:
            v, dv = solution(x)
            return (dv * omega(x) - v * mpmath.diff(omega, x)) / omega(x) ** 2

        two = mpmath.mpf(2)
        big_a = (omega(two) ** 2 * lam_slope(two)) ** 2 + 1 / lam(two) ** 2
        big_b = mpmath.sqrt(big_a * lam(two) ** 2 - 1) / big_a
    return {
        "v": lambda x: solution(x)[0],
        "omega": omega,
        "lam": lam,
        "A": big_a,
        "B": big_b,
        "Iw": lambda x: mpmath.quad(lambda s: 1 / omega(s) ** 2, [two, x]),
    }


@cache
def reference_conical_solution() -> Any:
    """Lines 1044-1052 against a solution of (45) computed numerically (mpmath ODE, 30
    digits): v, ω, λ, ∫dx/ω² as functions of x (sympy functions evaluated by mpmath), A and
    B from the state at x = 2; x drawn in (2, 3) (λ grows with ∫dx/ω² there: the branch of
    line 1042's square root)."""
    from sympy.utilities.lambdify import implemented_function

    (x,) = symbols("x")
    numeric = _conical_solution()

    def at_30_digits(f: Any) -> Any:
        # sympy's evalf calls an implemented function again at each precision it climbs to
        # (24 calls a point), each an ODE step and a quadrature: f's value is a function of
        # its 30-digit argument alone (mpmath's ODE solution steps from its fixed start
        # whatever was asked before), so each argument is computed once
        memo = Recent(256)

        def value(point: Any) -> Any:
            text = str(sp.Float(point, 30))
            found = memo.get(text)
            if found is None:
                with mpmath.workdps(30):
                    found = f(mpmath.mpf(text))
                memo.put(text, found)
            return found

        return value

    exact = {
        name: implemented_function(f"{name}_aux", at_30_digits(numeric[name]))(x)
        for name in ("v", "omega", "lam", "Iw")
    }
    exact["A45"] = sp.Float(mpmath.nstr(numeric["A"], 32), 30)
    exact["B45"] = sp.Float(mpmath.nstr(numeric["B"], 32), 30)
    return reference(exact, "a solution of (45) by mpmath's ODE solver")


@cache
def reference_omega_pair() -> Any:
    """Lines 1054-1062: ω1 = ω/√A, ω2 = √A ω(∫dx/ω² + B) (written Iw for ∫dx/ω²), their
    x-derivatives by the chain rule with dIw/dx = 1/ω², and v of line 1050."""
    omega, domega, big_a, big_b, iw = symbols("omega", "domega_dx", "A45", "B45", "Iw")
    along = derivative_along({omega: domega, iw: 1 / omega**2})
    w1 = omega / sp.sqrt(big_a)
    w2 = sp.sqrt(big_a) * omega * (iw + big_b)
    v = sp.sqrt(omega**2 / big_a + big_a * omega**2 * (iw + big_b) ** 2)
    exact = {"omega1": w1, "omega2": w2, "domega1_dx": along(w1), "domega2_dx": along(w2)}
    return reference({**exact, "v": v}, "ω1, ω2 of line 1054")
