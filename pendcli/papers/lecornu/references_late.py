"""Lecornu, lines 699-1135 (§ III from (30), § IV): the references the statuses are computed
from (core/printed_check), and the checks of the rows added to cover that text.

Each ``reference_*`` maps ledger symbols (tables/equations/lecornu.toml [symbols]) to exact
expressions: the equation of motion, the preceding equation, a definition, a solution
computed here; never a copy of the formula the row prints. Each ``result_*`` is the
independent check (``check = ...``) of a row added for issue 19: numeric (mpmath at high
precision, quadrature, an ODE) where the reference is symbolic.

Part of :mod:`pendcli.papers.lecornu.equations` (which re-exports these names).
"""

from __future__ import annotations

from functools import cache
from typing import Any

from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.lecornu.equations_common import equation_check
from pendcli.papers.taylor import taylor

__all__ = [
    "reference_31",
    "reference_amplitude_series",
    "reference_area_theorem",
    "reference_beta_delta",
    "reference_cn_solution",
    "reference_conical_cartesian",
    "reference_conical_l_form",
    "reference_conical_phases",
    "reference_conical_polar",
    "reference_conical_small",
    "reference_eps_reduced",
    "reference_eps_split",
    "reference_eq3_in_u",
    "reference_eq37",
    "reference_eq39",
    "reference_eq40",
    "reference_eq41",
    "reference_eq42",
    "reference_eq42_prime",
    "reference_eq43",
    "reference_identity",
    "reference_k3_neglected",
    "reference_lambda_substitution",
    "reference_omega_pair",
    "reference_ordinary_pendulum",
    "reference_osculating",
    "reference_phase_derivatives",
    "reference_plane_angles",
    "reference_polar_angle",
    "reference_polar_trajectory",
    "reference_primitive_angles",
    "reference_printed_41",
    "reference_rotated_phases",
    "reference_rotated_planes",
    "reference_s_coefficients",
    "reference_slow_length",
    "reference_slow_pair",
    "reference_small_theta",
    "reference_t_equals_t_prime",
    "result_amplitude_series_numeric",
    "result_area_small_angle",
    "result_cn_numeric",
    "result_conical_cartesian_numeric",
    "result_conical_polar_numeric",
    "result_conical_small_angles_numeric",
    "result_delta_solution_numeric",
    "result_inverse_square_length",
    "result_k3_neglected_numeric",
    "result_k4_examples",
    "result_lambda_numeric",
    "result_osculating_numeric",
    "result_polar_angle_numeric",
    "result_polar_trajectory_numeric",
    "result_rotated_planes_numeric",
    "result_s_quadratures_numeric",
    "result_trajectory_after_52",
    "result_zero_initial_speed_numeric",
]


def _symbols(*names: str) -> list[Any]:
    import sympy as sp

    return [sp.Symbol(n, real=True) for n in names]


def _reference(exact: dict[str, Any], what: str, **kw: Any) -> Any:
    from pendcli.core.printed_check import Reference

    return Reference(exact, what=what, **kw)


# --- § IV, the conical pendulum in rectangular coordinates (lines 940-984) ---------------


def _conical_state() -> dict[str, Any]:
    """The motion of lines 942-946 (x'' = −Tx/l, y'' = −Ty/l, z'' = −Tz/l + g) at a state
    (x, y, z, x', y', z'); r = √(x² + y²), its derivatives by the chain rule along the motion,
    c = x y' − y x' (the constant the area theorem names)."""
    import sympy as sp

    x, y, z, dx, dy, _dz, tn, length, g = _symbols(
        "X", "Y", "Z", "dX_dt", "dY_dt", "dZ_dt", "Tn", "l", "g"
    )
    d2x, d2y, d2z = -tn * x / length, -tn * y / length, -tn * z / length + g
    rates = {x: dx, y: dy, dx: d2x, dy: d2y}

    def along(f: Any) -> Any:
        return sp.Add(*(sp.diff(f, s) * v for s, v in rates.items()))

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
    return _reference(_conical_state(), "x'' = −Tx/l, y'' = −Ty/l, z'' = −Tz/l + g")


@cache
def reference_conical_polar() -> Any:
    """r = l sin θ, z = l cos θ (lines 988-990) and their derivatives along t (l, θ varying);
    the printed d/dt(l² dθ/dt) by the chain rule."""
    import sympy as sp

    length, theta, dl, dth, d2th = _symbols("l", "theta", "dl_dt", "dtheta_dt", "d2theta_dt2")
    d2l = sp.Symbol("d2l_dt2", real=True)  # any l(t): the identity of line 992 needs no l'' = 0
    rates = {length: dl, theta: dth, dl: d2l, dth: d2th}

    def along(f: Any) -> Any:
        return sp.Add(*(sp.diff(f, s) * v for s, v in rates.items()))

    r, z = length * sp.sin(theta), length * sp.cos(theta)
    exact = {"r": r, "Z": z, "d2r_dt2": along(along(r)), "d2Z_dt2": along(along(z))}
    time = {"l": dl, "theta": dth, "dtheta_dt": d2th, "dl_dt": d2l}
    return _reference(exact, "r = l sin θ, z = l cos θ", rates={"t": time})


@cache
def reference_eq43() -> Any:
    """(43) from lines 984-992: r z'' − z r'' − g r + c² z/r³ = 0 with r = l sin θ,
    z = l cos θ, solved for θ'' (l = a + bt, l'' = 0); the printed d/dt by the chain rule."""
    import sympy as sp

    a, b, t, dth = _symbols("a", "b", "t", "dtheta_dt")
    second = _eq43_second_derivative(a + b * t)
    rates = {"t": {"l": b, "theta": dth, "dtheta_dt": second}}
    domain = {"theta": (sp.Rational(3, 10), sp.Rational(12, 10))}
    return _reference({"l": a + b * t}, "lines 984-992, l = a + bt", rates=rates, domain=domain)


def result_conical_cartesian_numeric() -> EquationCheck:
    """Lines 942-984 numerically: the motion x'' = −Tx/l, y'' = −Ty/l, z'' = −Tz/l + g, the
    tension T = g z + v² that keeps x² + y² + z² = l² (l = 1, g = 9.81), integrated by
    mpmath's Taylor ODE solver; along it x y' − y x' stays c, and r'' (differentiated
    numerically from the solution) satisfies r'' + Tr/l − c²/r³ = 0 and the eliminated
    r z'' − z r'' − g r + c² z/r³ = 0."""
    import mpmath

    with mpmath.workdps(25):
        g = mpmath.mpf("9.81")

        def rhs(_t: Any, s: list[Any]) -> list[Any]:
            x, y, z, vx, vy, vz = s
            tn = g * z + vx**2 + vy**2 + vz**2
            return [vx, vy, vz, -tn * x, -tn * y, -tn * z + g]

        theta = mpmath.mpf("0.6")
        start = [mpmath.sin(theta), 0, mpmath.cos(theta), 0, mpmath.mpf("1.7"), 0]
        solution = mpmath.odefun(rhs, 0, start)
        c0 = start[0] * start[4]
        worst = mpmath.mpf(0)
        for when in (mpmath.mpf("0.3"), mpmath.mpf("0.7")):
            state = solution(when)
            x, y, z, vx, vy, vz = state
            tn, d2z = g * z + vx**2 + vy**2 + vz**2, rhs(when, state)[5]
            r, c = mpmath.hypot(x, y), x * vy - y * vx
            d2r = mpmath.diff(
                lambda s: mpmath.hypot(*solution(s)[:2]), when, 2, h=mpmath.mpf("1e-6")
            )
            worst = max(
                worst,
                abs(c - c0),
                abs(d2r + tn * r - c**2 / r**3),
                abs(r * d2z - z * d2r - g * r + c**2 * z / r**3),
            )
    return equation_check(
        worst < 1e-8,
        "numeric",
        "mpmath ODE of the rod-constrained motion: c conserved, the r-equation and the "
        f"eliminated equation of lines 978-984 hold to {float(worst):.1e}",
    )


def result_conical_polar_numeric() -> EquationCheck:
    """Line 992 numerically: for l(t) = 1 + t/3 + t²/5 and θ(t) = 0.4 + sin t/2 (any l, θ),
    z r'' − r z'' with r = l sin θ, z = l cos θ against d(l²θ')/dt, both differentiated by
    mpmath at 30 digits."""
    import mpmath

    with mpmath.workdps(30):

        def length(t: Any) -> Any:
            return 1 + t / 3 + t**2 / 5

        def theta(t: Any) -> Any:
            return mpmath.mpf("0.4") + mpmath.sin(t) / 2

        worst = mpmath.mpf(0)
        for t in (mpmath.mpf("0.2"), mpmath.mpf("1.1")):
            r2 = mpmath.diff(lambda s: length(s) * mpmath.sin(theta(s)), t, 2)
            z2 = mpmath.diff(lambda s: length(s) * mpmath.cos(theta(s)), t, 2)
            lhs = length(t) * mpmath.cos(theta(t)) * r2 - length(t) * mpmath.sin(theta(t)) * z2
            rhs = mpmath.diff(lambda s: length(s) ** 2 * mpmath.diff(theta, s), t)
            worst = max(worst, abs(lhs - rhs))
    return equation_check(
        worst < 1e-15,
        "numeric",
        f"z r'' − r z'' = d(l²θ')/dt for a varying l(t), θ(t): differ by {float(worst):.1e}",
    )


def _along(rates: dict[Any, Any]) -> Any:
    import sympy as sp

    def along(f: Any) -> Any:
        return sp.Add(*(sp.diff(f, s) * v for s, v in rates.items()))

    return along


@cache
def reference_area_theorem() -> Any:
    """(44) from the area theorem of line 954: c = x y' − y x' with x = r cos φ,
    y = r sin φ, r = l sin θ (l, θ, φ varying)."""
    import sympy as sp

    length, theta, phi, dl, dth, dphi = _symbols(
        "l", "theta", "phi", "dl_dt", "dtheta_dt", "dphi_dt"
    )
    along = _along({length: dl, theta: dth, phi: dphi})
    r = length * sp.sin(theta)
    x, y = r * sp.cos(phi), r * sp.sin(phi)
    return _reference({"c": x * along(y) - y * along(x)}, "c = x y' − y x', r = l sin θ")


def _eq43_second_derivative(length: Any) -> Any:
    """θ'' from (43) (the eliminated equation of line 984 in θ, reference_eq43) at a length
    ``length`` with l' = b, l'' = 0."""
    import sympy as sp

    g, c, b = _symbols("g", "c", "b")
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
    import sympy as sp

    length, b, dth = _symbols("l", "b", "dtheta_dt")
    second = _eq43_second_derivative(length)
    exact = {"d2theta_dt2": second, "dtheta_dl": dth / b, "d2theta_dl2": second / b**2}
    domain = {"theta": (sp.Rational(3, 10), sp.Rational(12, 10))}
    return _reference(exact, "(43), l = a + bt", domain=domain)


def _small_conical_u() -> Any:
    """(43) for small θ (sin θ -> θ, cos θ -> 1) with θ = u/l, d/dt = b d/dl, solved for
    d²u/dl²: a function of (u, l)."""
    import sympy as sp

    length, b, g, c = _symbols("l", "b", "g", "c")
    u = sp.Function("u")(length)
    theta = u / length
    motion = b**2 * sp.diff(length**2 * sp.diff(theta, length), length)
    motion += g * length * theta - c**2 / (length**2 * theta**3)
    second = sp.solve(motion, sp.diff(u, length, 2))[0]
    return second.subs(u, sp.Symbol("uc", real=True))


@cache
def reference_conical_small() -> Any:
    """Lines 1010-1016: (43) for small angles with θ = u/l, x = gl/b², u = v√(bc/g)."""
    import sympy as sp

    length, b, g, c, x, v = _symbols("l", "b", "g", "c", "x", "v")
    scale = sp.sqrt(b * c / g)
    d2u_dx2 = (b**2 / g) ** 2 * _small_conical_u().subs(length, b**2 * x / g)
    exact = {
        "d2uc_dx2": d2u_dx2,
        "d2v_dx2": d2u_dx2.subs(sp.Symbol("uc", real=True), v * scale) / scale,
    }
    return _reference(exact, "(43) for small θ, θ = u/l, x = gl/b²")


# --- § IV, (46)-(52) and the trajectory (lines 1052-1135) --------------------------------


@cache
def reference_omega_pair() -> Any:
    """Lines 1054-1062: ω1 = ω/√A, ω2 = √A ω(∫dx/ω² + B) (written Iw for ∫dx/ω²), their
    x-derivatives by the chain rule with dIw/dx = 1/ω², and v of line 1050."""
    import sympy as sp

    omega, domega, big_a, big_b, iw = _symbols("omega", "domega_dx", "A45", "B45", "Iw")
    along = _along({omega: domega, iw: 1 / omega**2})
    w1 = omega / sp.sqrt(big_a)
    w2 = sp.sqrt(big_a) * omega * (iw + big_b)
    v = sp.sqrt(omega**2 / big_a + big_a * omega**2 * (iw + big_b) ** 2)
    exact = {"omega1": w1, "omega2": w2, "domega1_dx": along(w1), "domega2_dx": along(w2)}
    return _reference({**exact, "v": v}, "ω1, ω2 of line 1054")


def _plane_angles() -> dict[str, Any]:
    """θi = K ωi(x)/l (line 1070), K = √(bc/g), x = gl/b², l = a + bt, ωi solutions of (9)
    (xω'' + ω = 0) tied by (46); θi' and θi'' by the chain rule in t (dx/dt = g/b)."""
    import sympy as sp

    a, b, g, c, t = _symbols("a", "b", "g", "c", "t")
    w1, w2, dw1 = _symbols("omega1", "omega2", "domega1_dx")
    length = a + b * t
    x = g * length / b**2
    dw2 = (1 + w2 * dw1) / w1  # (46) solved for ω2'
    rates = {t: 1, w1: dw1 * g / b, w2: dw2 * g / b, dw1: -w1 / x * g / b}
    rates[sp.Symbol("dw2", real=True)] = 0
    along = _along(rates)
    big_k = sp.sqrt(b * c / g)
    out: dict[str, Any] = {"l": length}
    for name, w in (("theta1", w1), ("theta2", w2)):
        angle = big_k * w / length
        out[name], out[f"d{name}_dt"] = angle, along(angle)
        out[f"d2{name}_dt2"] = along(along(angle))
    return out


@cache
def reference_plane_angles() -> Any:
    """(48), (49): θi = K ωi(x)/l with ωi solving (9) and (46)."""
    return _reference(_plane_angles(), "θi = √(bc/g) ωi(gl/b²)/l, (9), (46)")


@cache
def reference_polar_angle() -> Any:
    """Lines 1084-1086: θ1 = θ cos φ, θ2 = θ sin φ (φ the polar angle of (θ1, θ2)), and c
    from (49): c = l²(θ1θ2' − θ2θ1'), θ and φ varying."""
    import sympy as sp

    theta, phi, dth, dphi, length = _symbols("theta", "phi", "dtheta_dt", "dphi_dt", "l")
    along = _along({theta: dth, phi: dphi})
    one, two = theta * sp.cos(phi), theta * sp.sin(phi)
    c = length**2 * (one * along(two) - two * along(one))
    return _reference({"theta1": one, "theta2": two, "c": c}, "θ1 = θ cos φ, θ2 = θ sin φ, (49)")


@cache
def _first_order_correction() -> Any:
    """The O(p) part of the solution of (48) in u = γt, (1 + pu)θ'' + 2pθ' + θ = 0, about
    ρ sin(u − ψ): θ1'' + θ1 = ρ(u sin(u − ψ) − 2 cos(u − ψ)), solved by the ansatz
    (a1u² + a2u) cos(u − ψ) + (b1u² + b2u) sin(u − ψ) (no free oscillation added)."""
    import sympy as sp

    u, rho, psi = _symbols("u", "rho", "psi")
    a1, a2, b1, b2 = sp.symbols("a1 a2 b1 b2")
    w = sp.Symbol("w", real=True)  # the phase u − ψ, d/du acting on u and w alike

    def d(f: Any) -> Any:
        return f.diff(u) + f.diff(w)

    zero = rho * sp.sin(w)
    guess = (a1 * u**2 + a2 * u) * sp.cos(w) + (b1 * u**2 + b2 * u) * sp.sin(w)
    residual = sp.expand(d(d(guess)) + guess + u * d(d(zero)) + 2 * d(zero))
    equations = [residual.coeff(f).coeff(u, n) for f in (sp.cos(w), sp.sin(w)) for n in (0, 1)]
    solved = sp.solve(equations, [a1, a2, b1, b2], dict=True)[0]
    phase = {w: u - psi}
    return zero.subs(phase), guess.subs(solved).subs(phase)


def _slow_solution(rho: Any, psi: Any, u: Any) -> Any:
    import sympy as sp

    zero, first = _first_order_correction()
    names = dict(zip(("u", "rho", "psi"), _symbols("u", "rho", "psi"), strict=True))
    p = sp.Symbol("p", real=True)
    at = {names["u"]: u, names["rho"]: rho, names["psi"]: psi}
    return zero.subs(at, simultaneous=True) + p * first.subs(at, simultaneous=True)


@cache
def reference_slow_pair() -> Any:
    """(50): θi the O(p) solution of (48) about ρi sin(γt − ψi) (γ = √(g/a))."""

    t, gamma, p = _symbols("t", "gamma", "p")
    exact = {}
    for i in ("1", "2"):
        rho, psi = _symbols(f"rho{i}", f"psi{i}")
        exact[f"theta{i}"] = _slow_solution(rho, psi, gamma * t)
    return _reference(exact, "(48) to O(p)", scale=p, order=2)


@cache
def reference_conical_phases() -> Any:
    """(51): c = l²(θ1θ2' − θ2θ1') from (49) with θi of (50) at t = 0 (l = a), γ = √(g/a)."""
    import sympy as sp

    t, gamma, a, g = _symbols("t", "gamma", "a", "g")
    pair = reference_slow_pair().exact
    one, two = pair["theta1"], pair["theta2"]
    wronskian = (one * two.diff(t) - two * one.diff(t)).subs(t, 0)
    root = sp.sqrt(g / a)
    exact = {"c": sp.expand(a**2 * wronskian).subs(gamma, root), "gamma": root}
    return _reference(exact, "(49) at t = 0 with (50)")


@cache
def reference_rotated_phases() -> Any:
    """(52): the O(p) solutions about ρ1 cos u and ρ2 sin u (ψ1 = −π/2, ψ2 = 0, u = γt,
    the phases chosen at line 1110), and c from (49) at t = 0 as for (51)."""
    import sympy as sp

    u, p, rho1, rho2, a, g = _symbols("u", "p", "rho1", "rho2", "a", "g")
    one = _slow_solution(rho1, -sp.pi / 2, u)
    two = _slow_solution(rho2, sp.Integer(0), u)
    wronskian = (one * two.diff(u) - two * one.diff(u)).subs(u, 0)  # per unit of γ
    exact = {"theta1": one, "theta2": two, "x": one, "y": two}
    exact["c"] = sp.expand(a**2 * sp.sqrt(g / a) * wronskian)
    return _reference(exact, "(48) to O(p), ψ1 = −π/2, ψ2 = 0", scale=p, order=2)


@cache
def reference_rotated_planes() -> Any:
    """Line 1108: the planes turned by ω; each θi = ρi sin(u − ψi) written Im(Zi e^{iu}),
    Zi = ρi e^{−iψi}: Z1' = Z1 cos ω + Z2 sin ω, Z2' = −Z1 sin ω + Z2 cos ω."""
    import sympy as sp

    rho1, rho2, psi1, psi2, omega = _symbols("rho1", "rho2", "psi1", "psi2", "omega")
    z1 = rho1 * (sp.cos(psi1) - sp.I * sp.sin(psi1))
    z2 = rho2 * (sp.cos(psi2) - sp.I * sp.sin(psi2))
    turned = (z1 * sp.cos(omega) + z2 * sp.sin(omega), -z1 * sp.sin(omega) + z2 * sp.cos(omega))
    exact = {}
    for i, z in zip("12", turned, strict=True):
        exact[f"rho{i}p"] = sp.Abs(z)
        exact[f"psi{i}p"] = -sp.arg(z)
    return _reference(exact, "the axes turned by ω")


def result_conical_small_angles_numeric() -> EquationCheck:
    """Line 1012 numerically: for an arbitrary u(x) = 0.3 + sin(x)/5, θ = u/l at x = gl/b²,
    (43) for small angles written in l, b² d(l² dθ/dl)/dl + g l θ − c²/(l²θ³), equals
    (g² l/b²)(u'' + u/x − b²c²/(g²u³)); derivatives by mpmath at 30 digits."""
    import mpmath

    with mpmath.workdps(30):
        b, g, c = mpmath.mpf("0.7"), mpmath.mpf("9.81"), mpmath.mpf("0.2")

        def u(x: Any) -> Any:
            return mpmath.mpf("0.3") + mpmath.sin(x) / 5

        def theta(length: Any) -> Any:
            return u(g * length / b**2) / length

        worst = mpmath.mpf(0)
        for length in (mpmath.mpf("0.4"), mpmath.mpf("1.3")):
            x = g * length / b**2
            inner = mpmath.diff(lambda s: s**2 * mpmath.diff(theta, s), length)
            motion = b**2 * inner + g * length * theta(length)
            motion -= c**2 / (length**2 * theta(length) ** 3)
            printed = mpmath.diff(u, x, 2) + u(x) / x - b**2 * c**2 / (g**2 * u(x) ** 3)
            worst = max(worst, abs(motion - g**2 * length / b**2 * printed))
    return equation_check(
        worst < 1e-15,
        "numeric",
        f"(43) for small θ, θ = u/l, x = gl/b², against line 1012: differ by {float(worst):.1e}",
    )


@cache
def reference_lambda_substitution() -> Any:
    """Lines 1018-1042: v = λω with ω a solution of (9) (ω'' = −ω/x) and v of (45):
    v', v'' by the product rule (sympy), λ'' from (45), A the value of the first integral."""
    import sympy as sp

    x, lam, omega, dlam, domega = _symbols("x", "lam", "omega", "dlam_dx", "domega_dx")
    q = sp.Symbol("q", real=True)  # λ''
    along = _along({lam: dlam, omega: domega, dlam: q, domega: -omega / x})
    v = lam * omega
    dv, d2v = along(v), along(along(v))
    motion = sp.expand(d2v + v / x - 1 / v**3)  # (45)
    second = -motion.subs(q, 0) / motion.coeff(q)
    exact = {"v": v, "dv_dx": dv, "d2v_dx2": d2v.subs(q, second), "d2lam_dx2": second}
    exact["d2omega_dx2"] = -omega / x
    exact["A45"] = (omega**2 * dlam) ** 2 + 1 / lam**2
    rates = {"x": {"lam": dlam, "omega": domega, "dlam_dx": second, "domega_dx": -omega / x}}
    return _reference(exact, "(45), (9), v = λω", rates=rates)


@cache
def reference_primitive_angles() -> Any:
    """(47): θ = (v/l)√(bc/g), θi = (ωi/l)√(bc/g) (lines 1066-1070) with v = √(ω1² + ω2²)
    (line 1062)."""
    import sympy as sp

    w1, w2, length, b, c, g = _symbols("omega1", "omega2", "l", "b", "c", "g")
    big_k = sp.sqrt(b * c / g) / length
    exact = {"theta": sp.sqrt(w1**2 + w2**2) * big_k, "theta1": w1 * big_k, "theta2": w2 * big_k}
    return _reference(exact, "lines 1062-1070")


@cache
def reference_small_theta() -> Any:
    """θ scaled by ε (a series in the angle): line 1088's « pour le degré d'approximation
    adopté », θ² neglected beside 1."""
    import sympy as sp

    theta = sp.Symbol("theta", real=True)
    scale = sp.Symbol("epsilon", positive=True)
    return _reference({"theta": scale * theta}, "θ -> εθ", scale=scale, order=4)


@cache
def reference_slow_length() -> Any:
    """l = a + bt with b = pγa (p = b/√(ga), γ = √(g/a)): a series in p."""

    a, t, gamma, p = _symbols("a", "t", "gamma", "p")
    exact = {"l": a + p * gamma * a * t, "b": p * gamma * a}
    return _reference(exact, "l = a + bt, b = pγa", scale=p, order=2)


def result_lambda_numeric() -> EquationCheck:
    """Lines 1018-1062 numerically: v solves (45) (mpmath ODE from x = 1, v = 1.1,
    v' = 0.3); ω = √x J1(2√x) solves (9); λ = v/ω; the first integral
    A = (ω²λ')² + 1/λ² is the same at x = 1.5 and 3, and λ² = 1/A + A(∫dx/ω² + B)² with B
    fixed at x = 2 holds at x = 3 (quadrature)."""
    import mpmath

    with mpmath.workdps(20):
        solution = mpmath.odefun(lambda x, s: [s[1], -s[0] / x + 1 / s[0] ** 3], 1, [1.1, 0.3])

        def omega(x: Any) -> Any:
            return mpmath.sqrt(x) * mpmath.besselj(1, 2 * mpmath.sqrt(x))

        def lam(x: Any) -> Any:
            return solution(x)[0] / omega(x)

        def invariant(x: Any) -> Any:
            v, dv = solution(x)
            dlam = (dv * omega(x) - v * mpmath.diff(omega, x)) / omega(x) ** 2
            return (omega(x) ** 2 * dlam) ** 2 + 1 / lam(x) ** 2

        big_a = invariant(mpmath.mpf(2))
        drift = abs(invariant(mpmath.mpf("1.5")) - big_a) + abs(invariant(mpmath.mpf(3)) - big_a)
        big_b = mpmath.sqrt(big_a * lam(2) ** 2 - 1) / big_a
        three = mpmath.quad(lambda x: 1 / omega(x) ** 2, [2, 3]) + big_b
        misfit = abs(lam(3) ** 2 - (1 / big_a + big_a * three**2))
        ninth = abs(mpmath.diff(omega, 2, 2) * 2 + omega(2))  # (9): xω'' + ω = 0
    worst = max(drift, misfit, ninth)
    return equation_check(
        worst < 1e-10,
        "numeric",
        f"(45) by mpmath's ODE solver, ω = √x J1(2√x): A constant to {float(drift):.1e}, "
        f"λ² = 1/A + A(∫dx/ω² + B)² to {float(misfit):.1e}",
    )


def result_polar_angle_numeric() -> EquationCheck:
    """Lines 1084-1086, 1118 numerically: for θ(t) = 0.3 + t/5, φ(t) = t + t²/3 (any),
    θ1 = θ cos φ, θ2 = θ sin φ give θ1θ2' − θ2θ1' = θ²φ' and tg φ = θ2/θ1 (mpmath)."""
    import mpmath

    with mpmath.workdps(30):

        def theta(t: Any) -> Any:
            return mpmath.mpf("0.3") + t / 5

        def phi(t: Any) -> Any:
            return t + t**2 / 3

        def one(t: Any) -> Any:
            return theta(t) * mpmath.cos(phi(t))

        def two(t: Any) -> Any:
            return theta(t) * mpmath.sin(phi(t))

        t = mpmath.mpf("0.4")
        wronskian = one(t) * mpmath.diff(two, t) - two(t) * mpmath.diff(one, t)
        worst = abs(wronskian - theta(t) ** 2 * mpmath.diff(phi, t))
        worst = max(worst, abs(mpmath.tan(phi(t)) - two(t) / one(t)))
    return equation_check(
        worst < 1e-20, "numeric", f"θ1θ2' − θ2θ1' = θ²φ', tg φ = θ2/θ1: {float(worst):.1e}"
    )


def result_area_small_angle() -> EquationCheck:
    """Line 1088: l²θ²φ' = c is (44), l² sin²θ φ' = c, with θ² neglected beside 1: the
    relative difference 1 − sin²θ/θ² falls as θ² (observed order, mpmath)."""
    import mpmath

    angles = (0.2, 0.1, 0.05)
    gaps = [1 - mpmath.sin(x) ** 2 / mpmath.mpf(x) ** 2 for x in angles]
    order = float(mpmath.log(gaps[1] / gaps[2]) / mpmath.log(2))
    return equation_check(
        abs(order - 2) < 0.05,
        "numeric",
        f"1 − sin²θ/θ² at θ = 0.2, 0.1, 0.05: {', '.join(f'{float(g):.2e}' for g in gaps)} "
        f"(order {order:.2f}: the two agree to θ²)",
        observed_order=order,
        claimed_order=2,
    )


def result_inverse_square_length() -> EquationCheck:
    """Line 1102: 1/(a + bt)² = (1/a²)(1 − 2pγt) to first order in p (b = pγa), judged
    on the residual's observed order over the p sweep (γt = 1)."""
    from pendcli.papers.lecornu.equations_common import P_SWEEP, judged_series

    residuals = [abs(1 / (1 + p) ** 2 - (1 - 2 * p)) for p in P_SWEEP]
    return judged_series(residuals, 2, "1/(a + bt)² − (1/a²)(1 − 2pγt), a = γt = 1")


def result_rotated_planes_numeric() -> EquationCheck:
    """Line 1108 numerically: the turned components θ1' = θ1 cos ω + θ2 sin ω,
    θ2' = −θ1 sin ω + θ2 cos ω of θi = ρi sin(u − ψi), their amplitude and phase read by
    quadrature over a period (mpmath), give 2ρ1'ρ2' cos(ψ2' − ψ1') as printed."""
    import mpmath

    rho1, rho2, psi1, psi2, om = 0.8, 0.3, 0.4, -0.9, 0.35
    with mpmath.workdps(20):

        def turned(u: Any) -> tuple[Any, Any]:
            one, two = rho1 * mpmath.sin(u - psi1), rho2 * mpmath.sin(u - psi2)
            c, s = mpmath.cos(om), mpmath.sin(om)
            return one * c + two * s, -one * s + two * c

        def amplitude_phase(index: int) -> tuple[Any, Any]:
            # ρ sin(u − ψ) = ρ cos ψ sin u − ρ sin ψ cos u
            sine = mpmath.quad(lambda u: turned(u)[index] * mpmath.sin(u), [0, 2 * mpmath.pi])
            cosine = mpmath.quad(lambda u: turned(u)[index] * mpmath.cos(u), [0, 2 * mpmath.pi])
            return mpmath.hypot(sine, cosine) / mpmath.pi, mpmath.atan2(-cosine, sine)

        (r1, p1), (r2, p2) = amplitude_phase(0), amplitude_phase(1)
        left = 2 * r1 * r2 * mpmath.cos(p2 - p1)
        right = (rho2**2 - rho1**2) * mpmath.sin(2 * om)
        right += 2 * rho1 * rho2 * mpmath.cos(psi2 - psi1) * mpmath.cos(2 * om)
        gap = abs(left - right)
    return equation_check(
        gap < 1e-15,
        "numeric",
        f"line 1108 by quadrature of the turned components: {float(gap):.1e}",
    )


def result_trajectory_after_52() -> EquationCheck:
    """Line 1126 as read, (x/ρ1)² + (y/ρ2)² − 1 = −(3p/2) arctg(ρ1y/(ρ2x)), against the two
    components of (3) linearised (scipy ODE, the initial values of (52) at u = 0) for
    ρ1 = 1, ρ2 = 0.4, u in (0, 1.4]; the printed argument ρ2y/(ρ1x) leaves an O(p⁰) residual."""
    import numpy as np

    from pendcli.papers.lecornu.equations_common import P_SWEEP, judged_series, linear_reduced_ode

    rho1, rho2 = 1.0, 0.4
    grid = np.linspace(0.05, 1.4, 200)
    one = linear_reduced_ode(P_SWEEP, (1.0,) * 5, tuple(-0.75 * p for p in P_SWEEP), 1.4)(grid)
    two = linear_reduced_ode(P_SWEEP, (0.0,) * 5, (1.0,) * 5, 1.4)(grid)
    read, printed = [], []
    for j, p in enumerate(P_SWEEP):
        x, y = rho1 * one[j], rho2 * two[j]
        left = (x / rho1) ** 2 + (y / rho2) ** 2 - 1
        read.append(float(np.max(np.abs(left + 1.5 * p * np.arctan2(rho1 * y, rho2 * x)))))
        printed.append(float(np.max(np.abs(left + 1.5 * p * np.arctan2(rho2 * y, rho1 * x)))))
    check = judged_series(read, 2, "line 1126 as read (ρ1y/(ρ2x))")
    return equation_check(
        check.holds and printed[-1] > 100 * read[-1],
        "numeric",
        f"{check.detail}; as printed (ρ2y/(ρ1x)) the residual at p = {P_SWEEP[-1]} is "
        f"{printed[-1]:.2e}",
        observed_order=check.observed_order,
        claimed_order=2,
    )


# --- § III from (30): the fast shortening, in powers of s = g/b (lines 699-732) ----------


def _s_coefficients() -> tuple[Any, list[Any]]:
    """(30), z θ'' + 2θ' + s sin θ = 0, with θ = U + Vs + Ws² (line 702): the coefficients
    of s⁰, s¹, s² of its left side (a series in s), in the ledger's symbols."""
    import sympy as sp

    s, z = _symbols("s", "z")
    names = ("U", "dU_dz", "d2U_dz2", "V", "dV_dz", "d2V_dz2", "W", "dW_dz", "d2W_dz2")
    u, du, d2u, v, dv, d2v, w, dw, d2w = _symbols(*names)
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
    s, coefficients = _s_coefficients()
    exact = {}
    for name, coefficient in zip(("U", "V", "W"), coefficients, strict=True):
        (second,) = _symbols(f"d2{name}_dz2")
        exact[second.name] = -coefficient.subs(second, 0) / coefficient.coeff(second)
    return _reference(exact, "(30) with θ = u + vs + ws²", scale=s, order=3)


@cache
def _series_31() -> Any:
    """θ = α + vs + ws² for β = 0 (u = α): v, w solved from the coefficient equations
    (z²v')' = −z sin α, (z²w')' = −z v cos α with v = v' = w = w' = 0 at z0, by sympy
    integration of rational functions of z."""
    import sympy as sp

    s, z, z0, alpha = _symbols("s", "z", "z0", "alpha")
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
    import sympy as sp

    theta, _ = _series_31()
    domain = {"z": (sp.Rational(1, 10), sp.Rational(9, 10)), "z0": (1, 2)}
    return _reference({"theta": theta}, "(30) through s², β = 0", domain=domain)


@cache
def reference_polar_trajectory() -> Any:
    """Line 730: (31) without its s² term at z = l/b, and A, B, C its coefficients of l⁰,
    l¹, l⁻¹ (computed; θ then holds only if no other power of l occurs)."""
    import sympy as sp

    s, z, alpha, length, b = _symbols("s", "z", "alpha", "l", "b")
    _, v = _series_31()
    theta = sp.expand(alpha + s * v.subs(z, length / b))
    exact = {"theta": theta}
    for name, power in (("A31", 0), ("B31", 1), ("C31", -1)):
        exact[name] = theta.coeff(length, power)
    return _reference(exact, "(31) to order s at z = l/b")


# --- § III, the slow lengthening: (32)-(38) (lines 734-816) -------------------------------


def _eq3_in_u(b: Any) -> dict[str, Any]:
    """(3), (a + bt)θ'' + 2bθ' + g sin θ = 0, solved for θ'' and written in u = √(g/a)t:
    dθ/du = θ'√(a/g), d²θ/du² = θ''a/g; u and p = b/√(ga) from line 736."""
    import sympy as sp

    a, g, t, theta, dth = _symbols("a", "g", "t", "theta", "dtheta_dt")
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
    (b,) = _symbols("b")
    return _reference(_eq3_in_u(b), "(3) in u = √(g/a)t, p = b/√(ga)")


@cache
def reference_ordinary_pendulum() -> Any:
    """(33): (3) with b = 0 (p = 0), in u."""
    import sympy as sp

    return _reference(_eq3_in_u(sp.Integer(0)), "(3) with b = 0, in u")


@cache
def reference_cn_solution() -> Any:
    """(34)-(35), lines 754-764: the textbook solution of (33) with amplitude θ0,
    sin(θ/2) = k cd v = k cn v/dn v (k = sin(θ0/2), v = u + C), written with φ = am v:
    cn v = cos φ, sn v = sin φ, dn v = √(1 − k² sin²φ); d/du = dn v · d/dφ."""
    import sympy as sp

    k, phi = _symbols("k", "phi")
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
    return _reference(exact, "sin(θ/2) = k cd v, the solution of (33)")


def result_cn_numeric() -> EquationCheck:
    """(35) and lines 756-764 numerically with mpmath's Jacobi functions (k = 0.6, v = 0.7):
    θ = 2 arctg((k/k') cn v) solves (33), its derivatives are the printed ones, and it
    depends on u + C only (∂θ/∂C = ∂θ/∂u)."""
    import mpmath

    with mpmath.workdps(30):
        k = mpmath.mpf("0.6")
        kp = mpmath.sqrt(1 - k**2)

        def theta(u: Any, c: Any = 0) -> Any:
            return 2 * mpmath.atan(k / kp * mpmath.ellipfun("cn", u + c, m=k**2))

        v = mpmath.mpf("0.7")
        sn, cn, dn = (mpmath.ellipfun(n, v, m=k**2) for n in ("sn", "cn", "dn"))
        first, second = mpmath.diff(theta, v), mpmath.diff(theta, v, 2)
        gaps = (
            abs(second + mpmath.sin(theta(v))),
            abs(first + 2 * k * kp * sn * dn / (kp**2 + k**2 * cn**2)),
            abs(second + 2 * k * kp * cn / dn**2),
            abs(mpmath.diff(lambda c: theta(v - mpmath.mpf("0.2"), c), mpmath.mpf("0.2")) - first),
        )
    worst = max(gaps)
    return equation_check(
        worst < 1e-20, "numeric", f"mpmath cn, sn, dn at k = 0.6, v = 0.7: {float(worst):.1e}"
    )


def _partial_chain() -> Any:
    """The total u-derivative of a function of (u, k(u), C(u)), from its partial
    derivatives (th_u, th_k, th_C, th_uu, th_uk, th_uC), with dC/du from (36)."""
    import sympy as sp

    names = ("theta", "th_u", "th_k", "th_C", "th_uu", "th_uk", "th_uC", "dk_du", "dC_du")
    theta, th_u, th_k, th_c, th_uu, th_uk, th_uc, dk, dc = _symbols(*names)
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
    return _reference(
        {"dtheta_du": first, "d2theta_du2": second, "dC_du": osculating}, "the chain rule, (36)"
    )


@cache
def reference_eq37() -> Any:
    """(37): dk/du, dC/du solved from (32), written with lines 770-774, and (36); the
    printed remark θ_uu + sin θ = 0 (the partial θ solves (33))."""
    import sympy as sp

    total, _, (theta, th_u, dc) = _partial_chain()
    p, u, th_k, th_c, th_uu = _symbols("p", "u", "th_k", "th_C", "th_uu")
    (dk,) = _symbols("dk_du")
    first, second = total(theta), total(th_u)
    motion = second + sp.sin(theta) + p * (u * second + 2 * first)
    motion = motion.subs(sp.sin(theta), -th_uu)
    solved = sp.solve([motion, th_k * dk + th_c * dc], [dk, dc], dict=True)[0]
    return _reference({"dk_du": solved[dk], "dC_du": solved[dc]}, "(32), (36)")


@cache
def _amplitude_series() -> Any:
    """am u through k³: u = F(φ, k) = ∫₀^φ dφ/√(1 − k² sin²φ), its integrand's series in
    k integrated, then inverted as φ = u + k² c(u) (c solved from the k² coefficient)."""
    import sympy as sp

    k, phi, u = _symbols("k", "phi", "u")
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
    import sympy as sp

    k, u = _symbols("k", "u")
    am = _amplitude_series()
    kp = sp.sqrt(1 - k**2)
    exact = {
        "phi": am,
        "cnu": sp.cos(am),
        "kp": kp,
        "theta": 2 * sp.atan(k / kp * sp.cos(am)),
        "fu": 9 * sp.cos(u) - sp.cos(3 * u) + 12 * u * sp.sin(u),
    }
    return _reference(exact, "am u through k³, (35) at C = 0", scale=k, order=4)


def result_amplitude_series_numeric() -> EquationCheck:
    """Lines 786-816 numerically: θ = 2 arctg((k/k') cn u) (mpmath's Jacobi cn) against
    2k cos u + (k³/24)(9 cos u + 12u sin u − cos 3u) at u = 1.3 for k = 0.08, 0.04, 0.02:
    the difference falls as k⁵ (θ is odd in k: no k⁴ term), within the printed « erreur de
    l'ordre k⁴ »."""
    import mpmath

    u = mpmath.mpf("1.3")
    residuals = []
    with mpmath.workdps(30):
        for k in (mpmath.mpf("0.08"), mpmath.mpf("0.04"), mpmath.mpf("0.02")):
            exact = 2 * mpmath.atan(k / mpmath.sqrt(1 - k**2) * mpmath.ellipfun("cn", u, m=k**2))
            series = 2 * k * mpmath.cos(u)
            series += k**3 / 24 * (9 * mpmath.cos(u) + 12 * u * mpmath.sin(u) - mpmath.cos(3 * u))
            residuals.append(abs(exact - series))
        order = float(mpmath.log(residuals[1] / residuals[2]) / mpmath.log(2))
    shown = ", ".join(f"{float(r):.2e}" for r in residuals)
    return equation_check(
        order > 3.7,
        "numeric",
        f"θ − (38) at u = 1.3, k = 0.08, 0.04, 0.02: {shown}"
        f" (observed order {order:.2f}; claimed: error of order k⁴)",
        observed_order=order,
        claimed_order=4,
    )


# --- § III, (39)-(42'): the perturbation of (38) by the lengthening (lines 818-934) -------


def _u_symbols() -> list[Any]:
    return _symbols("u", "k", "p")


def _forced_solution(source: Any) -> Any:
    """The solution of y'' + y = source with y(0) = y'(0) = 0, source a sum of uⁿ cos mu,
    uⁿ sin mu (m = 1, 3): undetermined coefficients (n <= 4), solved by sympy."""
    import sympy as sp
    from sympy.simplify.fu import TR8

    (u,) = _symbols("u")
    unknowns, guess = [], sp.Integer(0)
    for n in range(5):
        for m in (1, 3):
            a, b = sp.symbols(f"a{n}_{m} b{n}_{m}")
            unknowns += [a, b]
            guess += a * u**n * sp.cos(m * u) + b * u**n * sp.sin(m * u)
    residual = sp.expand(TR8(sp.expand(guess.diff(u, 2) + guess - source)))
    equations = [
        residual.coeff(f(m * u)).coeff(u, n)
        for n in range(6)
        for m in (1, 3)
        for f in (sp.cos, sp.sin)
    ]
    equations += [guess.subs(u, 0), guess.diff(u).subs(u, 0)]
    solved = sp.solve(equations, unknowns, dict=True)[0]
    return sp.expand(guess.subs(solved).subs({c: 0 for c in unknowns}))


@cache
def _slow_finite() -> dict[str, Any]:
    """ω of (38), F of (39) and its k, k³ coefficients A, B, β and δ solved with zero
    initial values ((40) split in powers of k), θ = ω + p(kβ + k³δ)."""
    import sympy as sp

    u, k, p = _u_symbols()
    f = 9 * sp.cos(u) + 12 * u * sp.sin(u) - sp.cos(3 * u)
    omega = 2 * k * sp.cos(u) + k**3 / 24 * f
    forcing = sp.expand(-(u * omega.diff(u, 2) + 2 * omega.diff(u)))
    big_a, big_b = forcing.coeff(k, 1), forcing.coeff(k, 3)
    beta = _forced_solution(big_a)
    delta = _forced_solution(big_b + 2 * beta * sp.cos(u) ** 2)
    theta = omega + p * (k * beta + k**3 * delta)
    return {
        "f": f,
        "omega": omega,
        "F": forcing,
        "A": big_a,
        "B": big_b,
        "beta": beta,
        "delta": delta,
        "theta": theta,
    }


@cache
def reference_eq39() -> Any:
    """(39): (32) with θ = ω + pε, ω a solution of (33) (ω'' = −sin ω): ε'' solved from
    (32) exactly, compared at order p⁰; F its definition (line 824)."""
    import sympy as sp

    u, _, p = _u_symbols()
    omega, domega, eps, deps = _symbols("omega", "domega_du", "eps", "deps_du")
    q = sp.Symbol("q", real=True)
    d2omega = -sp.sin(omega)
    theta, first, second = omega + p * eps, domega + p * deps, d2omega + p * q
    motion = sp.expand(second + sp.sin(theta) + p * (u * second + 2 * first))
    solved = -motion.subs(q, 0) / motion.coeff(q)
    exact = {"d2eps_du2": solved, "d2omega_du2": d2omega, "F": -(u * d2omega + 2 * domega)}
    return _reference(exact, "(32) with θ = ω + pε", scale=p, order=1)


@cache
def reference_eq40() -> Any:
    """(40): (39) with ω of (38) (F computed from it), A and B its k and k³ coefficients,
    f and its derivatives from (38); a series in k through k³."""
    import sympy as sp

    u, k, _ = _u_symbols()
    (eps,) = _symbols("eps")
    chain = _slow_finite()
    exact = {
        "d2eps_du2": chain["F"] - eps * sp.cos(chain["omega"]),
        "A40": chain["A"],
        "B40": chain["B"],
        "fu": chain["f"],
        "dfu": chain["f"].diff(u),
        "d2fu": chain["f"].diff(u, 2),
    }
    return _reference(exact, "(39) with ω of (38)", scale=k, order=4)


@cache
def reference_eps_split() -> Any:
    """Lines 836-856: ε = α + kβ + k²γ + k³δ (line 838) in (40); the second derivatives
    solved from its k⁰ … k³ coefficients (A, B kept as names); α = γ = 0, the solutions
    with zero initial values of α'' + α = 0 and γ'' + γ = 2α cos²u."""
    import sympy as sp

    u, k, _ = _u_symbols()
    names = ("alpha_e", "beta_e", "gamma_e", "delta_e")
    parts = _symbols(*names)
    seconds = _symbols(*(f"d2{n[:-2]}_du2" for n in names))
    big_a, big_b = _symbols("A40", "B40")
    eps = sum(k**n * x for n, x in enumerate(parts))
    d2eps = sum(k**n * x for n, x in enumerate(seconds))
    left = sp.expand(d2eps + (1 - 2 * k**2 * sp.cos(u) ** 2) * eps - big_a * k - big_b * k**3)
    exact: dict[str, Any] = {"eps": eps}
    for n, second in enumerate(seconds):
        coefficient = left.coeff(k, n)
        exact[second.name] = -coefficient.subs(second, 0) / coefficient.coeff(second)
    return _reference(exact, "(40), ε split in powers of k")


@cache
def reference_eps_reduced() -> Any:
    """Lines 850-856: as reference_eps_split, with α = γ = 0."""
    split = reference_eps_split()
    zero = {sp_name: 0 for sp_name in ("alpha_e", "gamma_e")}
    import sympy as sp

    exact = {
        n: sp.sympify(v, strict=True).subs({sp.Symbol(m, real=True): 0 for m in zero})
        for n, v in split.exact.items()
    }
    return _reference({**exact, **zero}, "(40) split, α = γ = 0")


@cache
def reference_beta_delta() -> Any:
    """Lines 858-880: β and δ solved with zero initial values, A and B computed from (38),
    f and its derivatives, β'' and δ'' those of the solutions."""
    u, _, _ = _u_symbols()
    chain = _slow_finite()
    exact = {
        "beta_e": chain["beta"],
        "delta_e": chain["delta"],
        "A40": chain["A"],
        "B40": chain["B"],
        "fu": chain["f"],
        "dfu": chain["f"].diff(u),
        "d2fu": chain["f"].diff(u, 2),
        "d2delta_du2": chain["delta"].diff(u, 2),
        "d2beta_du2": chain["beta"].diff(u, 2),
    }
    return _reference(exact, "β, δ solved from (40) with zero initial values")


@cache
def reference_eq41() -> Any:
    """(41) and lines 888-900: θ = ω + p(kβ + k³δ) solved here; its value and slope at
    u = π/2; rg = √(g/a) (the text's r)."""
    import sympy as sp

    u, _, _ = _u_symbols()
    theta = _slow_finite()["theta"]
    slope = theta.diff(u)
    exact = {
        "theta": theta,
        "theta_pi2": theta.subs(u, sp.pi / 2),
        "dtheta_du_pi2": slope.subs(u, sp.pi / 2),
    }
    (rg,) = _symbols("rg")
    exact["dtheta_dt_pi2"] = rg * exact["dtheta_du_pi2"]
    return _reference(exact, "θ = ω + p(kβ + k³δ) solved from (38)-(40)")


@cache
def _half_oscillation() -> Any:
    """γT = π/2 − θ/θ_u at u = π/2 (line 904) for θ of reference_eq41: the series in p to
    first order, each part in k through k² (the orders (42) keeps), as a function of a, g,
    b, k (γ = √(g/a), p = b/√(ga))."""
    import sympy as sp

    _, k, p = _u_symbols()
    a, g, b = _symbols("a", "g", "b")
    exact = reference_eq41().exact
    ratio = exact["theta_pi2"] / exact["dtheta_du_pi2"]
    in_p = taylor(ratio, p, 2)
    kept = sum(taylor(sp.expand(in_p.coeff(p, n)), k, 3) * p**n for n in (0, 1))
    gamma = sp.sqrt(g / a)
    return sp.expand((sp.pi / 2 - kept).subs(p, b / sp.sqrt(g * a)) / gamma)


@cache
def reference_eq42() -> Any:
    """(42): the half-oscillation computed from θ of (41) as solved here (line 904)."""
    return _reference({"T": _half_oscillation()}, "π/2γ − θ/θ' at u = π/2, θ solved here")


@cache
def reference_eq42_prime() -> Any:
    """(42'): (42) with k = sin(θ0/2), through θ0²."""
    import sympy as sp

    k, theta0 = _symbols("k", "theta0")
    half = _half_oscillation().subs(k, sp.sin(theta0 / 2))
    kept = taylor(half, theta0, 3)
    return _reference({"T": kept}, "(42) with k = sin(θ0/2), through θ0²")


@cache
def reference_t_equals_t_prime() -> Any:
    """Lines 918-932: T (and each T' of the same half-oscillation, reversed) the duration
    of (42) at k = 0, l = a + bT; b scaled by ε (first order in b)."""
    import sympy as sp

    k, a, b = _symbols("k", "a", "b")
    scale = sp.Symbol("epsilon", positive=True)
    duration = _half_oscillation().subs(k, 0).subs(b, scale * b)
    exact = {"b": scale * b, "T": duration, "Tp": duration, "l": a + scale * b * duration}
    return _reference(exact, "(42) at k = 0, to first order in b", scale=scale, order=2)


@cache
def reference_identity() -> Any:
    """No substitution: the formula is an identity in its own symbols (checked at random
    rational points)."""
    return _reference({}, "an identity")


@cache
def reference_phase_derivatives() -> Any:
    """Line 782: θ of (35) is a function G(u + C, k): its partial derivatives."""
    import sympy as sp

    u, c, k = _symbols("u", "C", "k")
    big_g = sp.Function("G")(u + c, k)
    exact = {
        "th_u": big_g.diff(u),
        "th_C": big_g.diff(c),
        "th_uu": big_g.diff(u, 2),
        "th_uC": big_g.diff(u, c),
    }
    return _reference(exact, "θ = G(u + C, k)")


@cache
def reference_k3_neglected() -> Any:
    """Lines 888-892: the O(p) solution of (48) in u (as for (50)) at ψ = 3p/4 − π/2."""
    import sympy as sp

    u, p, rho = _symbols("u", "p", "rho")
    theta = _slow_solution(rho, 3 * p / 4 - sp.pi / 2, u)
    return _reference({"theta": theta}, "(48) to O(p), ψ = 3p/4 − π/2", scale=p, order=2)


def result_k3_neglected_numeric() -> EquationCheck:
    """Lines 888-892 numerically: (1 + pu)θ'' + 2pθ' + θ = 0 (scipy ODE) from the initial
    values of (25) at ψ = 3p/4 − π/2, against ρ cos u + (pρ/4)(u² sin u − 3u cos u + 3 sin u)
    (ρ = 1, u in [0, 2π]): the residual falls as p²."""
    import numpy as np

    from pendcli.papers.lecornu.equations_common import P_SWEEP, judged_series, linear_reduced_ode

    grid = np.linspace(0, 2 * np.pi, 300)
    starts, slopes = [], []
    for p in P_SWEEP:
        psi = 0.75 * p - np.pi / 2
        starts.append(-np.sin(psi))  # (25) at t = 0
        slopes.append(np.cos(psi) + 0.75 * p * np.sin(psi))
    solved = linear_reduced_ode(P_SWEEP, tuple(starts), tuple(slopes), 2 * np.pi)(grid)
    c, s = np.cos(grid), np.sin(grid)
    residuals = []
    for j, p in enumerate(P_SWEEP):
        printed = c + p / 4 * (grid**2 * s - 3 * grid * c + 3 * s)
        residuals.append(float(np.max(np.abs(solved[j] - printed))))
    return judged_series(residuals, 2, "line 890 against (3) linearised")


def result_s_quadratures_numeric() -> EquationCheck:
    """Lines 716-722 numerically (α = 0.3, β = 0.2, z0 = 1, at z = 1.5): the nested
    quadratures v, w (scipy quad; w's applied to −v cos u) against the solutions of
    v''z + 2v' = −sin u, w''z + 2w' = −v cos u with v = v' = w = w' = 0 at z0 (scipy ODE,
    rtol 1e-12)."""
    import math

    from scipy.integrate import quad, solve_ivp

    alpha, beta, z0, z = 0.3, 0.2, 1.0, 1.5

    def u(x: float) -> float:
        return alpha + beta / x

    def rhs(x: float, s: list[float]) -> list[float]:
        v, dv, _w, dw = s
        return [dv, (-2 * dv - math.sin(u(x))) / x, dw, (-2 * dw - v * math.cos(u(x))) / x]

    ode = solve_ivp(rhs, (z0, z), [0, 0, 0, 0], rtol=1e-12, atol=1e-14, dense_output=True)

    def nested(f: Any, x: float) -> float:
        return quad(lambda y: quad(lambda w: w * f(w), z0, y)[0] / y**2, z0, x)[0]

    v = -nested(lambda x: math.sin(u(x)), z)
    w = nested(lambda x: -math.cos(u(x)) * ode.sol(x)[0], z)
    worst = max(abs(v - ode.y[0, -1]), abs(w - ode.y[2, -1]))
    return equation_check(
        worst < 1e-9, "numeric", f"nested quadratures against the ODE at z = 1.5: {worst:.1e}"
    )


def result_polar_trajectory_numeric() -> EquationCheck:
    """Line 730 numerically: (31) without its s² term at z = l/b, fitted by A + Bl + C/l
    through three lengths (mpmath), reproduces a fourth exactly (α = 0.4, s = 0.05,
    z0 = 2, b = 0.7)."""
    import mpmath

    alpha, s, z0, b = mpmath.mpf("0.4"), mpmath.mpf("0.05"), mpmath.mpf(2), mpmath.mpf("0.7")
    with mpmath.workdps(30):

        def theta(length: Any) -> Any:
            z = length / b
            return alpha - s * mpmath.sin(alpha) / (2 * z) * (z - z0) ** 2

        lengths = [mpmath.mpf(x) for x in ("0.3", "0.8", "1.1")]
        matrix = mpmath.matrix([[1, x, 1 / x] for x in lengths])
        a, bb, c = mpmath.lu_solve(matrix, mpmath.matrix([theta(x) for x in lengths]))
        x = mpmath.mpf("0.55")
        gap = abs(theta(x) - (a + bb * x + c / x))
    return equation_check(
        gap < 1e-25, "numeric", f"A + Bl + C/l through three lengths, at a fourth: {float(gap):.1e}"
    )


def result_delta_solution_numeric() -> EquationCheck:
    """Line 880 numerically: δ'' + δ = B + 2β cos²u (B as line 872 expands it, β of line 860)
    solved by scipy's ODE solver (rtol 1e-12) from δ = δ' = 0; at u = 1.5 the printed 32δ
    differs, the corrected 64δ agrees."""
    import math

    from scipy.integrate import solve_ivp

    def source(u: float) -> float:
        c, s, c3, s3 = math.cos(u), math.sin(u), math.cos(3 * u), math.sin(3 * u)
        big_b = -(-12 * u**2 * s + 39 * u * c + 6 * s + 9 * u * c3 + 6 * s3) / 24
        beta = (u**2 * s - 3 * u * c + 3 * s) / 2
        return big_b + 2 * beta * c**2

    u = 1.5
    ode = solve_ivp(lambda x, y: [y[1], source(x) - y[0]], (0, u), [0, 0], rtol=1e-12, atol=1e-14)
    delta = float(ode.y[0, -1])
    c, s, c3, s3 = math.cos(u), math.sin(u), math.cos(3 * u), math.sin(3 * u)
    printed = (-4 * u**3 * c + 11 * u**2 * s - u * c - u**2 * s3 - 3 * u * c3 + 4 * s) / 32
    corrected = -8 * u**3 * c - 50 * u**2 * s - 66 * u * c - 2 * u**2 * s3 + 6 * u * c3
    corrected = (corrected + 87 * s - 9 * s3) / 64
    good = abs(corrected - delta)
    return equation_check(
        abs(printed - delta) < 1e-9,
        "numeric",
        f"δ(1.5) = {delta:.9f} by the ODE; printed {printed:.9f}, corrected {corrected:.9f} "
        f"(differs by {good:.1e})",
        corrected="64δ = −8u³ cos u − 50u² sin u − 66u cos u − 2u² sin 3u + 6u cos 3u "
        "+ 87 sin u − 9 sin 3u"
        if good < 1e-9
        else None,
    )


def result_osculating_numeric() -> EquationCheck:
    """Lines 770-774 numerically: for Θ(u, k, C) = k² eᵘ + Cu (any function),
    k(u) = 0.5 + sin(u)/3 and C(u) solving (36), C' = −Θ_k k'/Θ_C (by quadrature from
    u = 1), the total dθ/du is ∂Θ/∂u and d²θ/du² is Θ_uu + Θ_uk k' + Θ_uC C' (mpmath)."""
    import mpmath

    with mpmath.workdps(30):

        def k_of(u: Any) -> Any:
            return mpmath.mpf("0.5") + mpmath.sin(u) / 3

        def c_rate(u: Any) -> Any:
            dk = mpmath.cos(u) / 3
            return -2 * k_of(u) * mpmath.exp(u) * dk / u  # Θ_k = 2k eᵘ, Θ_C = u

        def c_of(u: Any) -> Any:
            return mpmath.mpf("0.2") + mpmath.quad(c_rate, [1, u])

        def theta(u: Any) -> Any:
            return k_of(u) ** 2 * mpmath.exp(u) + c_of(u) * u

        u = mpmath.mpf("1.4")
        k, dk = k_of(u), mpmath.cos(u) / 3
        th_u, th_uu = k**2 * mpmath.exp(u) + c_of(u), k**2 * mpmath.exp(u)
        th_uk, th_uc = 2 * k * mpmath.exp(u), mpmath.mpf(1)
        chain = th_uu + th_uk * dk + th_uc * c_rate(u)
        worst = max(abs(mpmath.diff(theta, u) - th_u), abs(mpmath.diff(theta, u, 2) - chain))
    return equation_check(
        worst < 1e-15, "numeric", f"the chain rule with (36), mpmath: {float(worst):.1e}"
    )


K4_EXAMPLES = (
    "lecornu.k4.theta20",
    "lecornu.k4.theta20_below_one_thousandth",
    "lecornu.k4.swing180",
)


def result_k4_examples() -> EquationCheck:
    """Line 816: k⁴ = sin⁴(θ0/2) is 0,00091 (< 1/1000) for θ0 = 20° and 0,25 for a swing of
    180°, as the claims of tables/published/lecornu.toml judge them against their
    recomputation."""
    from pendcli.papers.registry import evaluate

    rows = {r.id: r for r in evaluate("lecornu")}
    chosen = [rows[i] for i in K4_EXAMPLES]
    parts = [f"{r.id} printed {r.published}: {r.verdict}" for r in chosen]
    return equation_check(
        all(r.verdict == "agrees" for r in chosen), "numeric", "claims " + "; ".join(parts)
    )


@cache
def reference_printed_41() -> Any:
    """Line 886's « Cette formule donne dθ/dt = 0 pour t = 0 »: (41) as the ledger
    transcribes it (row lecornu.eq.41), its u-derivative at u = 0 (dθ/dt = γ dθ/du)."""
    import sympy as sp

    from pendcli.core.ledger import load_ledger
    from pendcli.core.printed import parse_formula

    ledger = load_ledger("lecornu")
    row = next(r for r in ledger.rows if r.id == "lecornu.eq.41")
    assert row.printed is not None
    ((_, theta),) = parse_formula(row.id, row.printed, ledger.symbols_for(row)).equations
    (u,) = _symbols("u")
    return _reference({"dtheta_du0": sp.diff(theta, u).subs(u, 0)}, "(41) as printed")


def result_zero_initial_speed_numeric() -> EquationCheck:
    """Line 886: (41) as the ledger transcribes it, evaluated by mpmath and differentiated
    numerically at u = 0 (k = 0.3, p = 0.05): dθ/du = 0."""
    import mpmath
    import sympy as sp

    from pendcli.core.ledger import load_ledger
    from pendcli.core.printed import parse_formula

    ledger = load_ledger("lecornu")
    row = next(r for r in ledger.rows if r.id == "lecornu.eq.41")
    assert row.printed is not None
    ((_, theta),) = parse_formula(row.id, row.printed, ledger.symbols_for(row)).equations
    u, k, p = _u_symbols()
    function = sp.lambdify((u, k, p), theta, modules="mpmath")
    with mpmath.workdps(30):
        slope = mpmath.diff(lambda x: function(x, mpmath.mpf("0.3"), mpmath.mpf("0.05")), 0)
    return equation_check(
        abs(slope) < 1e-25, "numeric", f"dθ/du of (41) at u = 0 by mpmath: {float(slope):.1e}"
    )


# --- b19: lines 420-676 (§ II, the integral's tail, (20)-(24), the slowly varying pendulum) --
# (appended here for issue 19; lines 1-698 are otherwise in references_early.py)

__all__ += [
    "check_small_p_integrals",
    "check_tail_expansion",
    "reference_elongation_arc",
    "reference_elongation_condition",
    "reference_eq21_from_20",
    "reference_eq22_from_21",
    "reference_mean_pendulum",
    "reference_next_passage",
    "reference_small_p_series",
    "reference_tail_expansion",
    "reference_vertical_passages",
    "reference_vertical_to_elongation",
]


def _upper_limit_derivative(name: str, lower: Any) -> Any:
    """The transform of an identity between integrals ∫_lower^h (a function of their common
    upper limit h = ``name``): its h-derivative plus κ times its value at h = lower (κ a
    fresh symbol the random points sample): both vanish if and only if the identity holds,
    and neither needs an integral done."""
    import sympy as sp

    h = sp.Symbol(name, real=True)
    kappa = sp.Symbol("kappa_b19", real=True)

    def empty(e: Any) -> bool:
        return isinstance(e, sp.Integral) and e.limits[0][1] == e.limits[0][2]

    def transform(residual: Any) -> Any:
        at_lower = residual.subs(h, lower).replace(empty, lambda e: sp.S.Zero)
        return residual.diff(h) + kappa * at_lower

    return transform


@cache
def reference_tail_expansion() -> Any:
    """Lines 426-428: identities between integrals ∫_a^∞ (a the text's fixed number above 1,
    aa here), judged by their a-derivative (the integrands at λ = a; both sides vanish as
    a → ∞); the root's series in 1/a with a√x, the weight's argument, held fixed:
    a = 1/ε, x -> ε²x, through ε⁶."""
    import sympy as sp

    aa, x = _symbols("aa", "x")
    eps = sp.Symbol("eps_", positive=True)
    return _reference(
        {"aa": 1 / eps, "x": eps**2 * x},
        "the a-derivative, a = 1/ε, a√x fixed",
        transform=lambda residual: residual.diff(aa),
        scale=eps,
        order=7,
    )


@cache
def reference_small_p_series() -> Any:
    """Line 440: an identity between integrals ∫_(2a√x)^h, judged by its h-derivative (the
    integrands at p = h) and its value at h = 2a√x; the exponential's series is truncated
    as printed, so h is scaled by ε (through ε: the terms 1/p, 1, p of the integrands)."""
    import sympy as sp

    aa, hh, x = _symbols("aa", "hh", "x")
    eps = sp.Symbol("eps_", positive=True)
    return _reference(
        {"hh": eps * hh},
        "the h-derivative and the value at h = 2a√x, h -> εh",
        transform=_upper_limit_derivative("hh", 2 * aa * sp.sqrt(x)),
        scale=eps,
        order=2,
    )


def _twenty(x: Any) -> Any:
    """(20): u = A x^(1/4) cos 2√x + B x^(1/4) sin 2√x (p = 1/4, line 468)."""
    import sympy as sp

    big_a, big_b = _symbols("A", "B")
    root = 2 * sp.sqrt(x)
    return x ** sp.Rational(1, 4) * (big_a * sp.cos(root) + big_b * sp.sin(root))


@cache
def reference_eq21_from_20() -> Any:
    """(21): θ = u/l (line 110) with u of (20) at x = gl/b²."""
    length, b, g = _symbols("l", "b", "g")
    return _reference({"theta": _twenty(g * length / b**2) / length}, "(20), θ = u/l, x = gl/b²")


def _twenty_two_constants() -> dict[str, Any]:
    """A, B of (20)-(21) through the « deux nouvelles constantes » R, φ of (22):
    A cos X + B sin X = (b²/g)^(1/4) R sin(X − φ) for every X."""
    import sympy as sp

    b, g, big_r, phi = _symbols("b", "g", "R", "phi")
    big_a, big_b = _symbols("A", "B")
    scale = (b**2 / g) ** sp.Rational(1, 4) * big_r
    return {big_a: -scale * sp.sin(phi), big_b: scale * sp.cos(phi)}


@cache
def reference_eq22_from_21() -> Any:
    """(22): (21) with A, B written through R, φ."""
    length, b, g = _symbols("l", "b", "g")
    theta = _twenty(g * length / b**2) / length
    return _reference({"theta": theta.subs(_twenty_two_constants())}, "(21) with A, B from R, φ")


def _phase_at(length: Any, zero: Any) -> Any:
    """φ for which (22)'s sine argument (2/b)√(gl) − φ equals ``zero`` at ``length``."""
    import sympy as sp

    b, g = _symbols("b", "g")
    return 2 / b * sp.sqrt(g * length) - zero


@cache
def reference_vertical_passages() -> Any:
    """(23): θ of (22) vanishes where its sine's argument is a multiple λπ of π."""
    import sympy as sp

    length, lam = _symbols("l", "lam")
    return _reference({"phi": _phase_at(length, lam * sp.pi)}, "(22) = 0 at l: argument λπ")


@cache
def reference_next_passage() -> Any:
    """Lines 519-527: the first passage at l, its argument λπ (λ = m, line 519), l' the
    length of the next ((22) = 0 with argument (λ + 1)π); b scaled by ε (π²b²/(4gl)
    neglected), through ε."""
    import sympy as sp

    length, b, g, lam = _symbols("l", "b", "g", "lam")
    eps = sp.Symbol("eps_", positive=True)
    phi = _phase_at(length, lam * sp.pi)
    following = b**2 / (4 * g) * (phi + (lam + 1) * sp.pi) ** 2  # (22)'s argument (λ + 1)π
    exact = {"lp": following.subs(b, eps * b), "b": eps * b, "mm": lam}
    exact["phi"] = phi.subs(b, eps * b)
    return _reference(
        exact,
        "(22) = 0 at l and l', b -> εb",
        scale=eps,
        order=2,
    )


def _elongation_tangent(length: Any) -> Any:
    """tg of (22)'s argument X at an elongation: dθ/dl = R l^(-3/4)(X' cos X − 3 sin X/(4l))
    vanishes (sympy's derivative of (22), its cos X and sin X coefficients)."""
    import sympy as sp

    big_r, phi = _symbols("R", "phi")
    arc = sp.Symbol("X_b19", real=True)
    ell = sp.Symbol("l_b19", positive=True)
    argument = _phase_at(ell, 0) - phi
    theta = big_r * ell ** sp.Rational(-3, 4) * sp.sin(argument)
    slope = sp.expand(theta.diff(ell).subs(argument, arc))
    tangent = -slope.coeff(sp.cos(arc)) / slope.coeff(sp.sin(arc))
    return tangent.subs(ell, length)


@cache
def reference_elongation_condition() -> Any:
    """Line 535: the φ for which l is an elongation of (22): X = arctg of the tangent found."""
    import sympy as sp

    (length,) = _symbols("l")
    phi = _phase_at(length, sp.atan(_elongation_tangent(length)))
    return _reference({"phi": phi}, "dθ/dl = 0 for θ of (22)")


@cache
def reference_elongation_arc() -> Any:
    """(24): the same arc written (2λ + 1)π/2 − arctg(1/tangent) (λ an integer), b scaled
    by ε (b/√(gl) small), through ε²."""
    import sympy as sp

    length, lam, b = _symbols("l", "lam", "b")
    eps = sp.Symbol("eps_", positive=True)
    arc = (2 * lam + 1) * sp.pi / 2 - sp.atan(1 / _elongation_tangent(length))
    phi = _phase_at(length, arc).subs(b, eps * b)
    return _reference({"phi": phi, "b": eps * b}, "dθ/dl = 0, b -> εb", scale=eps, order=3)


@cache
def reference_vertical_to_elongation() -> Any:
    """Lines 559-563: (l'' − l)/b, the time from the vertical at l to the next elongation
    l'' ((23), (24) solved for l'', as for line 555), through b; the printed decimal 0,13
    a rounding."""
    from pendcli.papers.lecornu.references_early import reference_quarter_time

    quarter = reference_quarter_time()
    return _reference(
        dict(quarter.exact),
        "(23), (24) solved for l'', decimals rounded",
        scale=quarter.scale,
        order=quarter.order,
        rounded=True,
    )


@cache
def reference_mean_pendulum() -> Any:
    """Lines 666-676: t the period of (27)'s solution to p² (reference_root_epsilon, through
    p²), l = a + bt/2 the length at t/2 (line 666); the printed decimals roundings."""
    from pendcli.papers.lecornu.references_early import reference_root_epsilon

    root = reference_root_epsilon()
    (a,) = _symbols("a")
    exact = dict(root.exact)
    exact["l"] = a + exact["b"] * exact["t"] / 2
    return _reference(
        exact,
        "the root of (27)'s solution, l = a + bt/2",
        scale=root.scale,
        order=root.order,
        rounded=True,
    )


def check_tail_expansion() -> EquationCheck:
    """Lines 426-428 numerically (mpmath.quad at x = 0,2, a = 1,3): ∫_a^∞ e^(−2λ√x)(1 + λ²)^½
    against ∫ e λ + ½∫ e/λ + ∫ e(−1/(8λ³) + 1/(16λ⁵)) (what remains is the series' next
    term, ≤ 5/(128·6a⁶)), and the last integral below (1/8)∫dλ/λ³ = 1/(16a²)."""
    import mpmath

    with mpmath.workdps(20):
        x, a = mpmath.mpf("0.2"), mpmath.mpf("1.3")

        def weighted(f: Any) -> Any:
            weight = 2 * mpmath.sqrt(x)
            return mpmath.quad(lambda s: mpmath.exp(-weight * s) * f(s), [a, mpmath.inf])

        whole = weighted(lambda s: mpmath.sqrt(1 + s**2))
        last = weighted(lambda s: -1 / (8 * s**3) + 1 / (16 * s**5))
        split = weighted(lambda s: s) + weighted(lambda s: 1 / s) / 2 + last
        gap, bound = abs(whole - split), mpmath.quad(lambda s: 1 / s**3, [a, mpmath.inf]) / 8
        ok = gap < 5 / (128 * 6 * a**6) and abs(last) < bound
        ok = ok and abs(bound - 1 / (16 * a**2)) < 1e-18
    return equation_check(
        bool(ok),
        "numeric",
        f"quad: the split misses {float(gap):.1e} (the next term's bound "
        f"{float(5 / (128 * 6 * a**6)):.1e}); |last| = {float(abs(last)):.2e} < 1/(16a²) = "
        f"{float(bound):.2e}",
    )


def check_small_p_integrals() -> EquationCheck:
    """Lines 440-446 numerically (mpmath.quad at x = 0,2, a = 1,3, h = 2,5, with the whole
    series: the integrand (e^(−p) − 1 + p)/p for « p/(1·2) − p²/(1·2·3) + … »):
    ∫e^(−p)dp/p = log h − log(2a√x) − h + 2a√x + that integral, which lies below
    ∫p dp/2 = h²/4 − a²x."""
    import mpmath

    with mpmath.workdps(20):
        x, a, h = mpmath.mpf("0.2"), mpmath.mpf("1.3"), mpmath.mpf("2.5")
        low = 2 * a * mpmath.sqrt(x)
        rest = mpmath.quad(lambda q: (mpmath.exp(-q) - 1 + q) / q, [low, h])
        left = mpmath.quad(lambda q: mpmath.exp(-q) / q, [low, h])
        gap = abs(left - (mpmath.log(h) - mpmath.log(low) - h + low + rest))
        half = mpmath.quad(lambda q: q / 2, [low, h])
        ok = gap < 1e-18 and rest < half and abs(half - (h**2 / 4 - a**2 * x)) < 1e-18
    return equation_check(
        bool(ok),
        "numeric",
        f"quad: line 440 to {float(gap):.1e}; the rest {float(rest):.4f} < ∫p dp/2 = "
        f"{float(half):.4f} = h²/4 − a²x",
    )


__all__ += ["reference_quarter_power", "reference_variation_of_constants"]


@cache
def reference_quarter_power() -> Any:
    """Lines 466-499: v = x^p cos 2√x, w = x^p sin 2√x (lines 470, 490), u = Av + Bw ((20),
    « la fonction u, définie par l'équation (20) »), their derivatives by sympy, and p = 1/4,
    the exponent the text fixes at line 468 before it differentiates."""
    import sympy as sp

    x, big_a, big_b = _symbols("x", "A", "B")
    quarter = sp.Rational(1, 4)
    v = x**quarter * sp.cos(2 * sp.sqrt(x))
    w = x**quarter * sp.sin(2 * sp.sqrt(x))
    u = big_a * v + big_b * w
    exact = {"v": v, "w": w, "u": u, "p": quarter, "dv_dx": v.diff(x)}
    exact.update({"d2v_dx2": v.diff(x, 2), "d2w_dx2": w.diff(x, 2), "d2u_dx2": u.diff(x, 2)})
    return _reference(exact, "v, w, u = Av + Bw with p = 1/4, differentiated")


def _zero_start_forced(rhs: Any, tau: Any, degree: int) -> Any:
    """The solution of y'' + y = rhs(τ) with y(0) = y'(0) = 0, rhs a polynomial in τ times
    cos τ and sin τ: undetermined coefficients (polynomials of ``degree``), solved by
    sympy's linear solver."""
    import sympy as sp

    a = sp.symbols(f"a0:{degree + 1}")
    c = sp.symbols(f"c0:{degree + 1}")
    trial = sum(a[k] * tau**k for k in range(degree + 1)) * sp.cos(tau)
    trial += sum(c[k] * tau**k for k in range(degree + 1)) * sp.sin(tau)
    residual = sp.expand(trial.diff(tau, 2) + trial - rhs)
    equations = [trial.subs(tau, 0), trial.diff(tau).subs(tau, 0)]
    for trig in (sp.cos(tau), sp.sin(tau)):
        equations.extend(sp.Poly(residual.coeff(trig), tau).all_coeffs())
    (solution,) = sp.linsolve(equations, [*a, *c])
    return sp.expand(trial.subs(dict(zip((*a, *c), solution, strict=True))))


@cache
def reference_variation_of_constants() -> Any:
    """Lines 624-634: u0 the general solution A sin γt + B cos γt of u0'' + γ²u0 = 0, and
    u1, u2 the solutions of u_n'' + γ²u_n = −γt u_(n−1)'' that start at 0 with zero slope
    (line 628), by undetermined coefficients."""
    import sympy as sp

    t, gamma, big_a, big_b = _symbols("t", "gamma", "A", "B")
    tau = sp.Symbol("tau_b19", real=True)  # γt: the hierarchy is then free of γ
    parts = [big_a * sp.sin(tau) + big_b * sp.cos(tau)]
    for n in (1, 2):
        forcing = sp.expand(-tau * parts[-1].diff(tau, 2))
        parts.append(_zero_start_forced(forcing, tau, 2 * n))
    names = ("u0", "u1", "u2")
    exact = {name: part.subs(tau, gamma * t) for name, part in zip(names, parts, strict=True)}
    return _reference(exact, "the hierarchy of (27) solved by undetermined coefficients")


__all__ += ["reference_homothety", "result_homothety_axes_numeric"]


@cache
def reference_homothety() -> Any:
    """Lines 1128-1134: the trace (x, y) = (θ1, θ2) of (52) (as read: the O(p) solutions of
    (48) about ρ1 cos u, ρ2 sin u) lies on the ellipse of axes sρ1, sρ2 homothetic to the
    one of axes ρ1, ρ2, s = √((x/ρ1)² + (y/ρ2)²); after half a turn (u -> u + π) the ratio
    is s(u + π)/s(u). Through p."""
    import sympy as sp

    u, rho1, rho2 = _symbols("u", "rho1", "rho2")
    phases = reference_rotated_phases()
    one, two = phases.exact["theta1"], phases.exact["theta2"]
    size = sp.sqrt((one / rho1) ** 2 + (two / rho2) ** 2)
    exact = {"x": one, "y": two, "axis1": rho1 * size, "axis2": rho2 * size}
    exact["hom_ratio"] = size.subs(u, u + sp.pi) / size
    return _reference(
        exact, "(48) to O(p), the ellipse through the trace", scale=phases.scale, order=phases.order
    )


def result_homothety_axes_numeric() -> EquationCheck:
    """Lines 1130-1134 numerically: the two components of (3) linearised (scipy ODE, the
    initial values of (52) at u = 0, ρ1 = 1, ρ2 = 0.4); the trace's size
    s = √((x/ρ1)² + (y/ρ2)²) against 1 − (3p/4) arctg(ρ1y/(ρ2x)) (the axes as read: residual
    O(p²)) and arctg(ρ2y/(ρ1x)) (as printed: O(p)), for u in (0, 1.4]; and s(u + π)/s(u) at
    u = 0.7 against 1 − 3pπ/4."""
    import numpy as np

    from pendcli.papers.lecornu.equations_common import P_SWEEP, judged_series, linear_reduced_ode

    rho1, rho2, end = 1.0, 0.4, 1.4 + np.pi
    grid = np.linspace(0.05, 1.4, 200)
    one = linear_reduced_ode(P_SWEEP, (1.0,) * 5, tuple(-0.75 * p for p in P_SWEEP), end)
    two = linear_reduced_ode(P_SWEEP, (0.0,) * 5, (1.0,) * 5, end)
    xs, ys = one(grid), two(grid)
    read, printed, ratios = [], [], []
    for j, p in enumerate(P_SWEEP):
        x, y = rho1 * xs[j], rho2 * ys[j]
        size = np.sqrt((x / rho1) ** 2 + (y / rho2) ** 2)
        read.append(float(np.max(np.abs(size - 1 + 0.75 * p * np.arctan2(rho1 * y, rho2 * x)))))
        printed.append(float(np.max(np.abs(size - 1 + 0.75 * p * np.arctan2(rho2 * y, rho1 * x)))))
        later = np.hypot(one(np.array([0.7 + np.pi]))[j], two(np.array([0.7 + np.pi]))[j])
        now = np.hypot(one(np.array([0.7]))[j], two(np.array([0.7]))[j])
        ratios.append(float(abs(later[0] / now[0] - (1 - 0.75 * np.pi * p))))
    check = judged_series(read, 2, "the axes as read (ρ1y/(ρ2x))")
    ratio = judged_series(ratios, 2, "s(u + π)/s(u) − (1 − 3pπ/4)")
    return equation_check(
        check.holds and ratio.holds and printed[-1] > 100 * read[-1],
        "numeric",
        f"{check.detail}; {ratio.detail}; as printed (ρ2y/(ρ1x)) the residual at "
        f"p = {P_SWEEP[-1]} is {printed[-1]:.2e}",
        observed_order=check.observed_order,
        claimed_order=2,
    )


__all__ += ["reference_coefficient_solutions"]


def _zero_start_double_quadrature(forcing: Any, z: Any, z0: Any) -> Any:
    """The solution of z y'' + 2y' = f (that is (z²y')' = z f) with y(z0) = y'(z0) = 0:
    y = ∫_z0^z dz/z² ∫_z0^z z f dz (sympy integrals, left unevaluated)."""
    import sympy as sp

    return sp.Integral(sp.Integral(z * forcing, (z, z0, z)) / z**2, (z, z0, z))


def _coefficient_transform(residual: Any) -> Any:
    """Lines 716-722 (``U = …``, ``V = …``, ``W = …``): the residual y − Y(z) of the
    coefficient y of s⁰, s, s² becomes D(y) − D(Y) + κ1 (y − Y)(z0) + κ2 (y − Y)'(z0),
    D = z d²/dz² + 2 d/dz, with D(y) and the values at z0 from lines 710-716: D(u) = 0,
    D(v) = −sin u, D(w) = −v cos u, v = w = v' = w' = 0 at z0 (u's values there are its
    free constants α, β). Both vanish if and only if Y solves y's problem."""
    import sympy as sp

    z, z0, alpha, beta = _symbols("z", "z0", "alpha", "beta")
    big_u, big_v, big_w = _symbols("U", "V", "W")
    kappa1, kappa2 = _symbols("kappa1_b19", "kappa2_b19")
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
    return _reference(
        {}, "lines 710-716: z y'' + 2y' and the values at z0", transform=_coefficient_transform
    )


__all__ += ["reference_conical_solution"]


@cache
def _conical_solution() -> dict[str, Any]:
    """A solution of (45) (mpmath's Taylor ODE solver at 30 digits from x = 1, v = 1.1,
    v' = 0.3), ω = √x J1(2√x) a solution of (9), λ = v/ω (line 1018), ∫dx/ω² from x = 2
    (quadrature), A the first integral (ω²λ')² + 1/λ² at x = 2 (line 1038) and B its second
    constant: √(Aλ² − 1)/A at x = 2 (line 1042 integrated from there)."""
    import mpmath

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
    import mpmath
    import sympy as sp
    from sympy.utilities.lambdify import implemented_function

    (x,) = _symbols("x")
    numeric = _conical_solution()

    def at_30_digits(f: Any) -> Any:
        def value(point: Any) -> Any:
            with mpmath.workdps(30):
                return f(mpmath.mpf(str(sp.Float(point, 30))))

        return value

    exact = {
        name: implemented_function(f"{name}_b19", at_30_digits(numeric[name]))(x)
        for name in ("v", "omega", "lam", "Iw")
    }
    exact["A45"] = sp.Float(mpmath.nstr(numeric["A"], 32), 30)
    exact["B45"] = sp.Float(mpmath.nstr(numeric["B"], 32), 30)
    domain = {"x": (sp.Integer(2), sp.Integer(3))}
    return _reference(exact, "a solution of (45) by mpmath's ODE solver", domain=domain)


__all__ += ["reference_small_x"]


@cache
def reference_small_x() -> Any:
    """Lines 448-460 as x -> 0: u = C x (π/(4√x))[cos α J1(2√x) − sin α Y1(2√x)] (the
    second (18) in closed form, lecornu.eq.18.definite-integral's check; J1, Y1 by their
    series at 0, through the terms that do not vanish with x), θ = u/l with
    C = (b²/g)k (line 406); x and l scaled by ε. Each residual must stay finite as ε -> 0+:
    the parts that grow as x -> 0 (1/x, log x) must agree, a finite remainder (the text's
    « nombre fini », F) is free."""
    import sympy as sp

    x, length, alpha, big_c, k, b, g = _symbols("x", "l", "alpha", "C", "k", "b", "g")
    eps = sp.Symbol("eps_", positive=True)

    def ratio(at: Any) -> Any:  # u/(Cx) of the second (18), through o(1) as x -> 0
        z = 2 * sp.sqrt(at)
        # DLMF 10.2.2 and 10.8.1: J1(z) = z/2 − z³/16 + …, Y1(z) = −2/(πz)
        # + (2/π) log(z/2) J1(z) − (z/(2π))(ψ(1) + ψ(2)) + O(z³ log z)
        j1 = z / 2 - z**3 / 16
        y1 = -2 / (sp.pi * z) + 2 / sp.pi * sp.log(z / 2) * j1
        y1 -= z / (2 * sp.pi) * (sp.polygamma(0, 1) + sp.polygamma(0, 2))
        return sp.pi / (4 * sp.sqrt(at)) * (sp.cos(alpha) * j1 - sp.sin(alpha) * y1)

    small = eps * x
    exact = {"x": small, "u": big_c * small * ratio(small), "l": eps * length}
    exact["theta"] = k * ratio(g * eps * length / b**2)
    domain = {"alpha": (sp.Rational(3, 10), sp.Rational(12, 10))}
    return _reference(
        exact, "the second (18) in closed form, x -> εx", scale=eps, domain=domain, bounded=True
    )
