"""Charbonnier (1908), part I (« Établissement des formules générales »), n° 2-8: the
references of the rows of lines 62-229, from the equation of motion (1) to the general
formulas (4), (5) and the integrals E_s, E_c in θ, θ'.

Each builder maps ledger symbols to exact expressions obtained without the formula the row
prints: Newton's law in Cartesian coordinates for (1); the linearised (1) and its solution
(sympy's dsolve) for (2), (3); for the perturbation theory of n° 4-8, a perturbing function φ
of a family with free parameters (the random points choose them) and θ1 from its differential
equation of first order, solved by undetermined coefficients, never by the paper's integrals.
:func:`ledger_symbols`, :func:`free_parameters`, :func:`principal_motion`,
:func:`exponential_family` and :func:`integrand_along` are shared with n° 9-17.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache
from typing import Any

import sympy as sp

from pendcli.data.printed import ledger_symbols
from pendcli.papers.taylor import taylor
from pendcli.verify.printed_check import Reference


def free_parameters(count: int, stem: str = "p") -> list[Any]:
    """Free parameters of a family (not ledger symbols): the random points choose them."""
    return [sp.Symbol(f"{stem}{i}", real=True) for i in range(count)]


# --- n° 2-3: the pendulum and its principal motion (lines 44-107) -------------------------


def _rates() -> dict[Any, Any]:
    names = ("theta", "dtheta_dt", "d2theta_dt2", "l", "dl_dt")
    theta, dtheta, d2theta, ell, dell = ledger_symbols(*names)
    return {theta: dtheta, dtheta: d2theta, ell: dell}


def _total_derivative(rates: dict[Any, Any]) -> Callable[[Any], Any]:
    """d/dt of an expression in the ledger's symbols: ∂/∂t plus Σ ∂/∂s · (the rate of s)."""
    (t,) = ledger_symbols("t")

    def d(expr: Any) -> Any:
        return sp.diff(expr, t) + sum(sp.diff(expr, s) * rate for s, rate in rates.items())

    def each(derivative: Any) -> Any:
        expr = derivative.expr
        for variable, count in derivative.variable_count:
            if variable != t:
                return derivative
            for _ in range(count):
                expr = d(expr)
        return expr

    def transform(expr: Any) -> Any:
        return expr.replace(lambda e: isinstance(e, sp.Derivative), each)

    return transform


@cache
def _newton_angular_acceleration() -> Any:
    """θ'' from Newton's law in Cartesian coordinates (x = l sin θ, y = −l cos θ, gravity
    (0, −g), the tension along the thread): the acceleration along e_θ = (cos θ, sin θ)
    equals −g sin θ."""
    t, g, theta, dtheta, ell, dell = ledger_symbols("t", "g", "theta", "dtheta_dt", "l", "dl_dt")
    th, length = sp.Function("th")(t), sp.Function("L")(t)
    x, y = length * sp.sin(th), -length * sp.cos(th)
    along = sp.expand(
        sp.diff(x, t, 2) * sp.cos(th) + sp.diff(y, t, 2) * sp.sin(th) + g * sp.sin(th)
    )
    second = sp.diff(th, t, 2)
    slope = along.coeff(second)  # the equation is linear in θ''
    solution = -(along - slope * second) / slope
    jets = {sp.diff(length, t): dell, sp.diff(th, t): dtheta}
    return solution.subs(jets).subs({length: ell, th: theta})


# (1), n° 2, lines 62-68: the theorem of moments divided by l²
def reference_newton() -> Reference:
    """(1) and the theorem of moments: θ'' from Newton's law; d/dt a total derivative."""
    exact = {"d2theta_dt2": _newton_angular_acceleration()}
    return Reference(exact, transform=_total_derivative(_rates()), what="Newton's law")


# n° 2, lines 54 and 60: the speed of M, the moment of its velocity about O, the moment of
# the weight
def reference_moments() -> Reference:
    """n° 2: M at x = l sin θ, y = −l cos θ, the length l and the angle θ both functions of t:
    its speed v_M, the component v_n of its velocity along the normal to the thread (θ
    increasing), the moment h_M = x y' − y x' of its velocity about O, and the magnitude G_M of
    the moment of the weight (0, −g) about O (per unit mass, as the text's g and gl sin θ)."""
    theta, dtheta, ell, dell, g = ledger_symbols("theta", "dtheta_dt", "l", "dl_dt", "g")
    x, y = ell * sp.sin(theta), -ell * sp.cos(theta)
    rates = {theta: dtheta, ell: dell}
    dx, dy = (sum(sp.diff(z, s) * r for s, r in rates.items()) for z in (x, y))
    exact = {
        "v_M": sp.sqrt(dx**2 + dy**2),
        "v_n": dx * sp.cos(theta) + dy * sp.sin(theta),
        "h_M": x * dy - y * dx,
        "G_M": sp.Abs(x * (-g) - y * 0),
    }
    return Reference(exact, what="M in Cartesian coordinates, l and θ varying")


# n° 3, lines 72 (sin θ replaced by θ) and 77-81 ((2), k² = g/l0)
def reference_linearised() -> Reference:
    """(2): (1) with l = l0 constant and small angles θ -> hθ, through h²; k² = g/l0."""
    theta, ell, dell, l0, g = ledger_symbols("theta", "l", "dl_dt", "l0", "g")
    h = sp.Symbol("h", positive=True)
    fixed = _newton_angular_acceleration().subs({ell: l0, dell: 0, theta: h * theta})
    exact = {"d2theta_dt2": fixed, "theta": h * theta, "k": sp.sqrt(g / l0)}
    return Reference(exact, what="(1) linearised, to order 2 in θ")


@cache
def principal_motion() -> tuple[Any, Any]:
    """θ0 solving (2) with θ(0) = −α, θ'(0) = 0 (sympy's dsolve), and its derivative."""
    t, k, alpha = ledger_symbols("t", "k", "alpha")
    kp = sp.Symbol("kp", positive=True)
    th = sp.Function("th")
    ode = sp.Eq(th(t).diff(t, 2) + kp**2 * th(t), 0)
    ics = {th(0): -alpha, th(t).diff(t).subs(t, 0): 0}
    solution = sp.dsolve(ode, th(t), ics=ics).rhs.subs(kp, k)
    return solution, sp.diff(solution, t)


# (3), n° 3, line 93; T and θ'_m, lines 97-105; θ0 again in n° 6, lines 145-157; the speed
# v = l0 θ' of n° 12, 3°, lines 339-347
def reference_principal_motion() -> Reference:
    """(3), n° 3 and n° 6: θ0 from (2); T its first return to rest after t = 0; θ'_m its
    speed where θ'' = 0; v = l0 θ' (n° 11) and dv/dt."""
    t, k, l0 = ledger_symbols("t", "k", "l0")
    theta, speed = principal_motion()
    kp = sp.Symbol("kp", positive=True)
    rest = sp.solve(speed.subs(k, kp), t)
    first = min((r for r in rest if r.is_positive), key=lambda r: float(r.subs(kp, 1)))
    (top,) = [r for r in sp.solve(sp.diff(speed, t).subs(k, kp), t) if r.is_positive][:1]
    exact = {
        "theta": theta,
        "dtheta_dt": speed,
        "theta_0": theta,
        "dtheta_0_dt": speed,
        "T": first.subs(kp, k),
        "thetap_m": speed.subs(t, top.subs(kp, k)),
        "nu": l0 * speed,
        "dnu_dt": l0 * sp.diff(speed, t),
    }
    return Reference(exact, what="the solution of (2) with θ(0) = −α, θ'(0) = 0")


# n° 3, line 107: the principal motion, started at −α, at +α at the end T of the oscillation
def reference_principal_turn() -> Reference:
    """n° 3: the principal motion at the end of the simple oscillation, t = T (θ0' = 0 again),
    T found as in reference_principal_motion."""
    (t,) = ledger_symbols("t")
    base = reference_principal_motion()
    at_end = {t: base.exact["T"]}
    exact = {"theta": base.exact["theta"].subs(at_end), "t": base.exact["T"]}
    return Reference(exact, what="θ0 at T")


# --- n° 4-7: the expansion in ε and the equation of θ1 (lines 109-165) --------------------


def _phi_polynomial() -> Any:
    """A perturbing function φ(θ, θ', t) of the family p0 + p1θ + p2θ' + p3θθ' + p4θ² + p5tθ'
    (a Taylor series of any φ through its second terms, and more)."""
    p = free_parameters(6)
    a, b, c = sp.symbols("a b c", real=True)
    body = p[0] + p[1] * a + p[2] * b + p[3] * a * b + p[4] * a**2 + p[5] * c * b
    return sp.Lambda((a, b, c), body)


# n° 4, line 113: the acceleration the perturbing force gives M along the arc
def reference_arc_acceleration() -> Reference:
    """n° 4: a_arc, the acceleration the perturbing force gives M along the arc (counted in
    the sense that lowers θ, as gravity's in (1)), from the motion along the arc of the small
    oscillations of constant length l0 (n° 3), l0 θ'' = −g θ − a_arc, with θ'' from the
    perturbed equation of line 119, φ of a family with free parameters."""
    theta, dtheta, t, k, eps, l0 = ledger_symbols("theta", "dtheta_dt", "t", "k", "epsilon", "l0")
    phi = _phi_polynomial()
    angular = -(k**2) * theta - eps * phi(theta, dtheta, t)
    g = k**2 * l0
    exact = {"phi": phi, "g": g, "a_arc": -l0 * angular - g * theta}
    return Reference(exact, what="the motion along the arc, l0θ'' = −gθ − a_arc")


@cache
def _orders() -> dict[str, Any]:
    """(119) with θ = θ0 + εθ1 + ε²θ2 (125): each θj'' from the coefficient of εʲ."""
    t, k, eps = ledger_symbols("t", "k", "epsilon")
    phi = _phi_polynomial()
    th = ledger_symbols("theta_0", "theta_1", "theta_2")
    dth = ledger_symbols("dtheta_0_dt", "dtheta_1_dt", "dtheta_2_dt")
    d2 = ledger_symbols("d2theta_0_dt2", "d2theta_1_dt2", "d2theta_2_dt2")
    theta = sum(eps**j * th[j] for j in range(3))
    speed = sum(eps**j * dth[j] for j in range(3))
    equation = sum(eps**j * d2[j] for j in range(3)) + k**2 * theta
    equation = sp.expand(equation + eps * phi(theta, speed, t))
    exact: dict[str, Any] = {}
    for j in range(3):
        (value,) = sp.solve(equation.coeff(eps, j), d2[j])
        exact[d2[j].name] = value
    a, b, c = sp.symbols("a b c", real=True)
    at0 = {a: th[0], b: dth[0], c: t}
    exact["phi"] = phi
    exact["phi_theta"] = sp.diff(phi.expr, a).subs(at0, simultaneous=True)
    exact["phi_thetap"] = sp.diff(phi.expr, b).subs(at0, simultaneous=True)
    exact["varphi"] = phi(theta, speed, t)
    return exact


# n° 5, lines 129-131 (the expanded equation), 133-135 (Taylor's formula for φ) and 137-139
# (the system of the orders)
def reference_expansion() -> Reference:
    """n° 5: (119) with (125), the θj'' from ε⁰, ε¹, ε², and φ along θ = θ0 + εθ1 + ε²θ2
    (Taylor's formula), compared through ε² (φ's through ε, as its row says)."""
    return Reference(_orders(), what="(119) with (125), through ε²")


# n° 7, lines 163-165: θ1's equation with the principal motion put in φ
def reference_theta1_equation() -> Reference:
    """n° 7: the equation of θ1 (ε¹ of (119)) with θ0, θ0' of (3) put in φ."""
    theta0, speed0 = principal_motion()
    th0, dth0 = ledger_symbols("theta_0", "dtheta_0_dt")
    value = _orders()["d2theta_1_dt2"].subs({th0: theta0, dth0: speed0}, simultaneous=True)
    return Reference(
        {"phi": _phi_polynomial(), "d2theta_1_dt2": value}, what="(3) in θ1's equation"
    )


# --- n° 7-8: θ1 for φ(t) = p0 + p1 exp(p2 t) + p3 exp(p4 t), the formulas (4), (5) ---------


def _exp_trig(lam: Any, t: Any) -> tuple[Any, Any]:
    """(∫₀ᵗ e^{λs} sin ks ds, ∫₀ᵗ e^{λs} cos ks ds), the textbook antiderivatives."""
    (k,) = ledger_symbols("k")
    grow, norm = sp.exp(lam * t), lam**2 + k**2
    sine = (grow * (lam * sp.sin(k * t) - k * sp.cos(k * t)) + k) / norm
    cosine = (grow * (lam * sp.cos(k * t) + k * sp.sin(k * t)) - lam) / norm
    return sine, cosine


@cache
def exponential_family() -> dict[str, Any]:
    """φ(t) = p0 + p1 e^{p2 t} + p3 e^{p4 t}; θ1 solving θ1'' + k²θ1 + φ = 0, θ1(0) = θ1'(0) = 0 by
    undetermined coefficients; M, N the coordinates of (θ1, θ1'/k) on (cos kt, sin kt);
    M', N' solved from (p) and θ1's equation; E_s, E_c as functions of the time."""
    t, k = ledger_symbols("t", "k")
    p0, p1, p2, p3, p4 = free_parameters(5)
    s = sp.Symbol("s", real=True)
    phi = sp.Lambda(s, p0 + p1 * sp.exp(p2 * s) + p3 * sp.exp(p4 * s))
    particular = (
        -p0 / k**2 - p1 * sp.exp(p2 * t) / (p2**2 + k**2) - p3 * sp.exp(p4 * t) / (p4**2 + k**2)
    )
    start, slope = particular.subs(t, 0), sp.diff(particular, t).subs(t, 0)
    theta1 = particular - start * sp.cos(k * t) - slope / k * sp.sin(k * t)
    speed1 = sp.diff(theta1, t)
    (e_s0, e_c0), (e_s1, e_c1), (e_s2, e_c2) = (_exp_trig(lam, s) for lam in (0, p2, p4))
    m, n, dm, dn = ledger_symbols("M", "N", "dM_dt", "dN_dt")
    rates = {m: dm, n: dn}
    theta_mn = m * sp.cos(k * t) + n * sp.sin(k * t)
    speed_mn = _derivative_in(theta_mn, t, rates)
    condition_p = speed_mn - speed_mn.subs({dm: 0, dn: 0})
    speed_p = speed_mn - condition_p
    equation = _derivative_in(speed_p, t, rates) + k**2 * theta_mn + phi(t)
    solved = sp.solve([condition_p, equation], [dm, dn], dict=True)[0]
    return {
        "phi": phi,
        "E_s": sp.Lambda(s, p0 * e_s0 + p1 * e_s1 + p3 * e_s2),
        "E_c": sp.Lambda(s, p0 * e_c0 + p1 * e_c1 + p3 * e_c2),
        "theta_1": theta1,
        "dtheta_1_dt": speed1,
        "d2theta_1_dt2": sp.diff(speed1, t),
        "M": theta1 * sp.cos(k * t) - speed1 / k * sp.sin(k * t),
        "N": theta1 * sp.sin(k * t) + speed1 / k * sp.cos(k * t),
        "dM_dt": solved[dm],
        "dN_dt": solved[dn],
        "dtheta_1_dt_of_MN": speed_p,
    }


def _derivative_in(expr: Any, t: Any, rates: dict[Any, Any]) -> Any:
    return sp.diff(expr, t) + sum(sp.diff(expr, v) * r for v, r in rates.items())


# n° 7, lines 179-181: θ1' of θ1 = M cos kt + N sin kt under the condition (p)
def reference_differentiated() -> Reference:
    """n° 7: θ1 = M cos kt + N sin kt differentiated, M' cos kt + N' sin kt set to 0 by (p)."""
    exact = {"dtheta_1_dt": exponential_family()["dtheta_1_dt_of_MN"]}
    return Reference(exact, what="(175) differentiated under (p)")


# (q), n° 7, line 189, and M, N as integrals, lines 191-201
def reference_variation() -> Reference:
    """n° 7: M', N' solved from (p) and θ1's equation; M and N from the solution θ1."""
    names = ("phi", "M", "N", "dM_dt", "dN_dt")
    exact = {k: v for k, v in exponential_family().items() if k in names}
    return Reference(exact, what="(p) and θ1's equation solved for M', N'")


# n° 7, lines 203-209 (θ1 in E_s, E_c), (4) lines 213-219 and (5) line 221, n° 8
def reference_first_order() -> Reference:
    """n° 7-8: θ = θ0 + εθ1 with θ1 from its differential equation; E_s, E_c of the time."""
    (eps,) = ledger_symbols("epsilon")
    family = exponential_family()
    theta0, speed0 = principal_motion()
    exact = {k: v for k, v in family.items() if k != "dtheta_1_dt_of_MN"}
    exact["theta"] = theta0 + eps * family["theta_1"]
    exact["dtheta_dt"] = exact["thetap"] = speed0 + eps * family["dtheta_1_dt"]
    return Reference(exact, what="θ1 solving its equation for φ = p0 + p1 e^{p2 t}")


@cache
def _linear_perturbation() -> dict[str, Any]:
    """φ = p1θ + p2θ' + p3: θ'' + k²θ + εφ = 0 solved exactly (constant coefficients),
    θ(0) = −α, θ'(0) = 0, and its series through ε; E_s, E_c with φ along θ0 (quadrature)."""
    t, k, alpha, eps = ledger_symbols("t", "k", "alpha", "epsilon")
    _, p1, p2, p3 = free_parameters(4)
    shift = -eps * p3 / (k**2 + eps * p1)
    omega = sp.sqrt(k**2 + eps * p1 - eps**2 * p2**2 / 4)
    a = -alpha - shift
    b = eps * p2 / 2 * a / omega
    theta = sp.exp(-eps * p2 * t / 2) * (a * sp.cos(omega * t) + b * sp.sin(omega * t)) + shift
    first = taylor(theta, eps, 2)  # analytic in ε: sp.series through ε, 20x cheaper
    theta0, speed0 = principal_motion()
    w = sp.Symbol("w_", real=True)
    along = (p1 * theta0 + p2 * speed0 + p3).subs(t, w)
    u = sp.Symbol("u", real=True)
    return {
        "theta": first,
        "dtheta_dt": sp.diff(first, t),
        "thetap": sp.diff(first, t),
        "E_s": sp.Lambda(u, sp.Integral(along * sp.sin(k * w), (w, 0, u))),
        "E_c": sp.Lambda(u, sp.Integral(along * sp.cos(k * w), (w, 0, u))),
    }


# n° 8, lines 217-223: the general integral (4), (5) to first order in ε
def reference_linear_perturbation() -> Reference:
    """n° 8: the exact solution of the perturbed equation for φ = p1θ + p2θ' + p3, through ε."""
    return Reference(_linear_perturbation(), what="the exact solution for a linear φ, through ε")


def integrand_along(variables: dict[str, Callable[[Any], Any]]) -> Callable[[Any], Any]:
    """In an integral over one of ``variables``, the quantities the integrand names as
    functions of the motion (the time t, the speed ν) written in that variable."""

    def each(integral: Any) -> Any:
        (variable, *bounds), *rest = integral.limits
        if rest or variable.name not in variables:
            return integral
        swap = variables[variable.name](variable)
        return sp.Integral(integral.function.subs(swap), (variable, *bounds))

    def transform(expr: Any) -> Any:
        return expr.replace(lambda e: isinstance(e, sp.Integral), each)

    return transform


# n° 8, lines 225-229: E_s, E_c as integrals in θ and θ'
def reference_angle_integrals() -> Reference:
    """n° 8: E_s, E_c of the time against integrals in θ, θ' (t the time of the first quarter
    of the principal motion at that angle, speed); φ of the family."""
    t, k, alpha = ledger_symbols("t", "k", "alpha")
    theta0, speed0 = principal_motion()
    family = exponential_family()
    exact = {"phi": family["phi"], "E_s": family["E_s"], "E_c": family["E_c"]}
    exact.update({"theta": theta0, "thetap": speed0})
    along = {
        # |…| under the roots, ≥ 0 on the interval: no complex value at the quadrature's
        # nodes that round past one of its ends
        "theta": lambda v: {t: sp.atan2(sp.sqrt(sp.Abs(alpha**2 - v**2)), -v) / k},
        "thetap": lambda v: {t: sp.atan2(v, sp.sqrt(sp.Abs(k**2 * alpha**2 - v**2))) / k},
    }
    return Reference(exact, transform=integrand_along(along), what="θ0 of (3)")
