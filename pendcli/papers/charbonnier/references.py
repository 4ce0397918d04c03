"""Charbonnier (1908): the references the ledger's printed forms are checked against
(``reference = "<name>"`` in tables/equations/charbonnier.toml; core/printed_check).

Each maps ledger symbols to exact expressions obtained without the formula the row prints:
Newton's law in Cartesian coordinates for (1); the linearised (1) and its solution for (2),
(3); for the perturbation theory of n° 4-10, a perturbing function φ of a family with free
parameters (the random points choose them) and θ1 from the differential equation of first
order, solved by undetermined coefficients, never by the paper's integrals; the remarkable
points from that θ by a first-order Newton step; for n° 11-17 the resistance F(v) and θ1
from Duhamel's integral (left to quadrature). sympy is imported lazily.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache
from typing import Any

from pendcli.core.printed_check import Reference
from pendcli.papers.taylor import taylor

__all__ = [
    "reference_air",
    "reference_air_first_oscillation",
    "reference_air_points",
    "reference_amplitude_unchanged",
    "reference_angle_integrals",
    "reference_constant_resistance",
    "reference_differentiated",
    "reference_expansion",
    "reference_first_order",
    "reference_friction",
    "reference_friction_in_g_and_t",
    "reference_in",
    "reference_linear_perturbation",
    "reference_linearised",
    "reference_lowest_point",
    "reference_monomial",
    "reference_monomial_decay",
    "reference_monomial_parity",
    "reference_monomial_points",
    "reference_newton",
    "reference_period_unchanged",
    "reference_principal_motion",
    "reference_principal_turn",
    "reference_remarkable_points",
    "reference_sine_inverted",
    "reference_taylor",
    "reference_theta1_equation",
    "reference_turning_point",
    "reference_variation",
]


def _ledger(*names: str) -> list[Any]:
    import sympy as sp

    return [sp.Symbol(n, real=True) for n in names]


def _params(count: int, stem: str = "p") -> list[Any]:
    """Free parameters of a family (not ledger symbols): the random points choose them."""
    import sympy as sp

    return [sp.Symbol(f"{stem}{i}", real=True) for i in range(count)]


# --- n° 2-3: the pendulum --------------------------------------------------------------


def _rates() -> dict[Any, Any]:
    theta, dtheta, d2theta, ell, dell = _ledger("theta", "dtheta_dt", "d2theta_dt2", "l", "dl_dt")
    return {theta: dtheta, dtheta: d2theta, ell: dell}


def _total_derivative(rates: dict[Any, Any]) -> Callable[[Any], Any]:
    """d/dt of an expression in the ledger's symbols: ∂/∂t plus Σ ∂/∂s · (the rate of s)."""
    import sympy as sp

    (t,) = _ledger("t")

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
    import sympy as sp

    t, g, theta, dtheta, ell, dell = _ledger("t", "g", "theta", "dtheta_dt", "l", "dl_dt")
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


def reference_newton() -> Reference:
    """(1) and the theorem of moments: θ'' from Newton's law; d/dt a total derivative."""
    exact = {"d2theta_dt2": _newton_angular_acceleration()}
    return Reference(exact, transform=_total_derivative(_rates()), what="Newton's law")


def reference_linearised() -> Reference:
    """(2): (1) with l = l0 constant and small angles θ -> hθ, through h²; k² = g/l0."""
    import sympy as sp

    theta, ell, dell, l0, g = _ledger("theta", "l", "dl_dt", "l0", "g")
    h = sp.Symbol("h", positive=True)
    fixed = _newton_angular_acceleration().subs({ell: l0, dell: 0, theta: h * theta})
    exact = {"d2theta_dt2": fixed, "theta": h * theta, "k": sp.sqrt(g / l0)}
    return Reference(exact, scale=h, order=3, what="(1) linearised, to order 2 in θ")


@cache
def _principal_motion() -> tuple[Any, Any]:
    """θ0 solving (2) with θ(0) = −α, θ'(0) = 0 (sympy's dsolve), and its derivative."""
    import sympy as sp

    t, k, alpha = _ledger("t", "k", "alpha")
    kp = sp.Symbol("kp", positive=True)
    th = sp.Function("th")
    ode = sp.Eq(th(t).diff(t, 2) + kp**2 * th(t), 0)
    ics = {th(0): -alpha, th(t).diff(t).subs(t, 0): 0}
    solution = sp.dsolve(ode, th(t), ics=ics).rhs.subs(kp, k)
    return solution, sp.diff(solution, t)


def reference_principal_motion() -> Reference:
    """(3), n° 3 and n° 6: θ0 from (2); T its first return to rest after t = 0; θ'_m its
    speed where θ'' = 0; v = l0 θ' (n° 11) and dv/dt."""
    import sympy as sp

    t, k, l0 = _ledger("t", "k", "l0")
    theta, speed = _principal_motion()
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


# --- n° 4-7: the expansion in ε and the equation of θ1 ------------------------------------


def _phi_polynomial() -> Any:
    """A perturbing function φ(θ, θ', t) of the family p0 + p1θ + p2θ' + p3θθ' + p4θ² + p5tθ'
    (a Taylor series of any φ through its second terms, and more)."""
    import sympy as sp

    p = _params(6)
    a, b, c = sp.symbols("a b c", real=True)
    body = p[0] + p[1] * a + p[2] * b + p[3] * a * b + p[4] * a**2 + p[5] * c * b
    return sp.Lambda((a, b, c), body)


@cache
def _orders() -> dict[str, Any]:
    """(119) with θ = θ0 + εθ1 + ε²θ2 (125): each θj'' from the coefficient of εʲ."""
    import sympy as sp

    t, k, eps = _ledger("t", "k", "epsilon")
    phi = _phi_polynomial()
    th = _ledger("theta_0", "theta_1", "theta_2")
    dth = _ledger("dtheta_0_dt", "dtheta_1_dt", "dtheta_2_dt")
    d2 = _ledger("d2theta_0_dt2", "d2theta_1_dt2", "d2theta_2_dt2")
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


def reference_expansion() -> Reference:
    """n° 5: (119) with (125), the θj'' from ε⁰, ε¹, ε², compared through ε²."""
    (eps,) = _ledger("epsilon")
    exact = {k: v for k, v in _orders().items() if k != "varphi"}
    return Reference(exact, scale=eps, order=3, what="(119) with (125), through ε²")


def reference_taylor() -> Reference:
    """n° 5, Taylor's formula: φ along θ = θ0 + εθ1 + ε²θ2, compared through ε."""
    (eps,) = _ledger("epsilon")
    return Reference(_orders(), scale=eps, order=2, what="φ(θ0 + εθ1 + …), through ε")


def reference_theta1_equation() -> Reference:
    """n° 7: the equation of θ1 (ε¹ of (119)) with θ0, θ0' of (3) put in φ."""
    theta0, speed0 = _principal_motion()
    th0, dth0 = _ledger("theta_0", "dtheta_0_dt")
    value = _orders()["d2theta_1_dt2"].subs({th0: theta0, dth0: speed0}, simultaneous=True)
    return Reference(
        {"phi": _phi_polynomial(), "d2theta_1_dt2": value}, what="(3) in θ1's equation"
    )


# --- n° 7-10: θ1 for φ(t) = p0 + p1 exp(p2 t), the formulas (4)-(9) -----------------------


def _exp_trig(lam: Any, t: Any) -> tuple[Any, Any]:
    """(∫₀ᵗ e^{λs} sin ks ds, ∫₀ᵗ e^{λs} cos ks ds), the textbook antiderivatives."""
    import sympy as sp

    (k,) = _ledger("k")
    grow, norm = sp.exp(lam * t), lam**2 + k**2
    sine = (grow * (lam * sp.sin(k * t) - k * sp.cos(k * t)) + k) / norm
    cosine = (grow * (lam * sp.cos(k * t) + k * sp.sin(k * t)) - lam) / norm
    return sine, cosine


@cache
def _family() -> dict[str, Any]:
    """φ(t) = p0 + p1 e^{p2 t} + p3 e^{p4 t}; θ1 solving θ1'' + k²θ1 + φ = 0, θ1(0) = θ1'(0) = 0 by
    undetermined coefficients; M, N the coordinates of (θ1, θ1'/k) on (cos kt, sin kt);
    M', N' solved from (p) and θ1's equation; E_s, E_c as functions of the time."""
    import sympy as sp

    t, k = _ledger("t", "k")
    p0, p1, p2, p3, p4 = _params(5)
    s = sp.Symbol("s", real=True)
    phi = sp.Lambda(s, p0 + p1 * sp.exp(p2 * s) + p3 * sp.exp(p4 * s))
    particular = (
        -p0 / k**2 - p1 * sp.exp(p2 * t) / (p2**2 + k**2) - p3 * sp.exp(p4 * t) / (p4**2 + k**2)
    )
    start, slope = particular.subs(t, 0), sp.diff(particular, t).subs(t, 0)
    theta1 = particular - start * sp.cos(k * t) - slope / k * sp.sin(k * t)
    speed1 = sp.diff(theta1, t)
    (e_s0, e_c0), (e_s1, e_c1), (e_s2, e_c2) = (_exp_trig(lam, s) for lam in (0, p2, p4))
    m, n, dm, dn = _ledger("M", "N", "dM_dt", "dN_dt")
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
    import sympy as sp

    return sp.diff(expr, t) + sum(sp.diff(expr, v) * r for v, r in rates.items())


def reference_first_order() -> Reference:
    """n° 7-8: θ = θ0 + εθ1 with θ1 from its differential equation; E_s, E_c of the time."""
    (eps,) = _ledger("epsilon")
    family = _family()
    theta0, speed0 = _principal_motion()
    exact = {k: v for k, v in family.items() if k != "dtheta_1_dt_of_MN"}
    exact["theta"] = theta0 + eps * family["theta_1"]
    exact["dtheta_dt"] = exact["thetap"] = speed0 + eps * family["dtheta_1_dt"]
    return Reference(exact, what="θ1 solving its equation for φ = p0 + p1 e^{p2 t}")


def reference_differentiated() -> Reference:
    """n° 7: θ1 = M cos kt + N sin kt differentiated, M' cos kt + N' sin kt set to 0 by (p)."""
    exact = {"dtheta_1_dt": _family()["dtheta_1_dt_of_MN"]}
    return Reference(exact, what="(175) differentiated under (p)")


def reference_variation() -> Reference:
    """n° 7: M', N' solved from (p) and θ1's equation; M and N from the solution θ1."""
    names = ("phi", "M", "N", "dM_dt", "dN_dt")
    exact = {k: v for k, v in _family().items() if k in names}
    return Reference(exact, what="(p) and θ1's equation solved for M', N'")


# --- n° 9: the remarkable points, from θ = θ0 + εθ1 by one Newton step in ε -------------


def _points(theta1: Any, speed1: Any) -> dict[str, Any]:
    """The turning time t* = π/k + ετ1 (θ' = 0), the lowest point t0 = π/(2k) + εσ1 (θ = 0),
    the amplitude θ(t*) and the speed θ'(t0), to first order in ε, for a given θ1, θ1'."""
    import sympy as sp

    t, k, alpha, eps = _ledger("t", "k", "alpha", "epsilon")
    theta0, speed0 = _principal_motion()
    turn, low = sp.pi / k, sp.pi / (2 * k)
    tau = -speed1.subs(t, turn) / sp.diff(speed0, t).subs(t, turn)
    sigma = -theta1.subs(t, low) / speed0.subs(t, low)
    amplitude = theta0.subs(t, turn) + eps * theta1.subs(t, turn)  # θ0'(t*) = 0: no τ term
    speed = speed0.subs(t, low) + eps * speed1.subs(t, low)  # θ0''(t0) = 0: no σ term
    return {
        "turning": turn + eps * tau,
        "lowest": low + eps * sigma,
        "Delta_T": eps * tau,
        "Delta_T_half": eps * sigma,
        "theta_m": amplitude,
        "Delta_alpha": amplitude - alpha,
        "thetap_m": speed,
        "Delta_thetap_m": speed - speed0.subs(t, low),
    }


def _phase(function: Any) -> Any:
    """E of the time -> E of kt, as (6)-(9) write E_c(π), E_c(π/2)."""
    import sympy as sp

    (k,) = _ledger("k")
    u = sp.Symbol("u", real=True)
    return sp.Lambda(u, function(u / k))


def _family_points() -> dict[str, Any]:
    family = _family()
    exact = _points(family["theta_1"], family["dtheta_1_dt"])
    exact.update({"E_s": _phase(family["E_s"]), "E_c": _phase(family["E_c"])})
    return exact


def reference_remarkable_points() -> Reference:
    """n° 9: ΔT, θ_m, Δα, ΔT_½, Δθ'_m from θ = θ0 + εθ1, compared through ε."""
    (eps,) = _ledger("epsilon")
    exact = {k: v for k, v in _family_points().items() if k not in ("turning", "lowest")}
    return Reference(exact, scale=eps, order=2, what="θ0 + εθ1 at its turning and lowest points")


def reference_turning_point() -> Reference:
    """n° 9, 1°-2°: t is the turning time t* (θ' = 0 near kt = π), through ε."""
    (eps,) = _ledger("epsilon")
    exact = _family_points()
    exact["t"] = exact["turning"]
    return Reference(exact, scale=eps, order=2, what="the turning time of θ0 + εθ1")


def reference_lowest_point() -> Reference:
    """n° 9, 3°: t is the time of the lowest point (θ = 0 near kt = π/2), through ε."""
    (eps,) = _ledger("epsilon")
    exact = _family_points()
    exact["t"] = exact["lowest"]
    return Reference(exact, scale=eps, order=2, what="the lowest point of θ0 + εθ1")


def reference_sine_inverted() -> Reference:
    """n° 9, 1°: kt from sin kt = −εE_c(π)/(kα) inverted exactly (kt near π), through ε²."""
    import sympy as sp

    k, alpha, eps = _ledger("k", "alpha", "epsilon")
    exact = _family_points()
    exact["t"] = (sp.pi + sp.asin(eps / (k * alpha) * exact["E_c"](sp.pi))) / k
    return Reference(exact, scale=eps, order=3, what="the sine relation inverted, through ε²")


def _family_constrained(key: str) -> dict[str, Any]:
    """The φ of the family for which the first-order ``key`` (ΔT or Δα) vanishes: p3 solved."""
    import sympy as sp

    (eps,) = _ledger("epsilon")
    p3 = _params(4)[3]
    exact = _family_points()
    first = sp.expand(exact[key] / eps)  # linear in p3
    value = -first.subs(p3, 0) / first.coeff(p3)

    def constrained(v: Any) -> Any:
        if isinstance(v, sp.Lambda):
            return sp.Lambda(v.args[0], v.expr.subs(p3, value))
        return v.subs(p3, value)

    return {k: constrained(v) for k, v in exact.items()}


def reference_period_unchanged() -> Reference:
    """n° 9, 1°: the φ of the family whose period is unchanged (ΔT = 0 at first order)."""
    return Reference(_family_constrained("Delta_T"), what="φ with ΔT = 0")


def reference_amplitude_unchanged() -> Reference:
    """n° 9, 2°: the φ of the family whose amplitude is unchanged (Δα = 0 at first order)."""
    return Reference(_family_constrained("Delta_alpha"), what="φ with Δα = 0")


def _integrand_along(variables: dict[str, Callable[[Any], Any]]) -> Callable[[Any], Any]:
    """In an integral over one of ``variables``, the quantities the integrand names as
    functions of the motion (the time t, the speed ν) written in that variable."""
    import sympy as sp

    def each(integral: Any) -> Any:
        (variable, *bounds), *rest = integral.limits
        if rest or variable.name not in variables:
            return integral
        swap = variables[variable.name](variable)
        return sp.Integral(integral.function.subs(swap), (variable, *bounds))

    def transform(expr: Any) -> Any:
        return expr.replace(lambda e: isinstance(e, sp.Integral), each)

    return transform


def reference_angle_integrals() -> Reference:
    """n° 8: E_s, E_c of the time against integrals in θ, θ' (t the time of the first quarter
    of the principal motion at that angle, speed); φ of the family."""
    import sympy as sp

    t, k, alpha = _ledger("t", "k", "alpha")
    theta0, speed0 = _principal_motion()
    family = _family()
    exact = {"phi": family["phi"], "E_s": family["E_s"], "E_c": family["E_c"]}
    exact.update({"theta": theta0, "thetap": speed0})
    along = {
        # |…| under the roots, ≥ 0 on the interval: no complex value at the quadrature's
        # nodes that round past one of its ends
        "theta": lambda v: {t: sp.atan2(sp.sqrt(sp.Abs(alpha**2 - v**2)), -v) / k},
        "thetap": lambda v: {t: sp.atan2(v, sp.sqrt(sp.Abs(k**2 * alpha**2 - v**2))) / k},
    }
    domain = {"alpha": (sp.Rational(1, 2), sp.Integer(1))}
    return Reference(exact, domain=domain, transform=_integrand_along(along), what="θ0 of (3)")


@cache
def _linear_perturbation() -> dict[str, Any]:
    """φ = p1θ + p2θ' + p3: θ'' + k²θ + εφ = 0 solved exactly (constant coefficients),
    θ(0) = −α, θ'(0) = 0, and its series through ε; E_s, E_c with φ along θ0 (quadrature)."""
    import sympy as sp

    t, k, alpha, eps = _ledger("t", "k", "alpha", "epsilon")
    _, p1, p2, p3 = _params(4)
    shift = -eps * p3 / (k**2 + eps * p1)
    omega = sp.sqrt(k**2 + eps * p1 - eps**2 * p2**2 / 4)
    a = -alpha - shift
    b = eps * p2 / 2 * a / omega
    theta = sp.exp(-eps * p2 * t / 2) * (a * sp.cos(omega * t) + b * sp.sin(omega * t)) + shift
    first = taylor(theta, eps, 2)  # analytic in ε: sp.series through ε, 20x cheaper
    theta0, speed0 = _principal_motion()
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


def reference_linear_perturbation() -> Reference:
    """n° 8: the exact solution of the perturbed equation for φ = p1θ + p2θ' + p3, through ε."""
    return Reference(_linear_perturbation(), what="the exact solution for a linear φ, through ε")


# --- n° 11-17: the resistance of the air F(v), θ1 by Duhamel's integral (quadrature) ----


def _resisted(force: Any, phase: bool) -> dict[str, Any]:
    """θ1, the E's and the remarkable points for the resistance ``force`` (a Lambda of v),
    φ(t) = F(l0 θ0'(t)), ε = c/l0 (n° 12)."""
    import sympy as sp

    t, k, l0, c, eps = _ledger("t", "k", "l0", "c", "epsilon")
    theta0, speed0 = _principal_motion()
    w = sp.Symbol("w_", real=True)
    phi = force(l0 * speed0.subs(t, w))
    theta1 = sp.Integral(-phi * sp.sin(k * (t - w)) / k, (w, 0, t))
    speed1 = sp.Integral(-phi * sp.cos(k * (t - w)), (w, 0, t))
    u = sp.Symbol("u", real=True)
    end = u / k if phase else u
    exact = {k_: v.subs(eps, c / l0) for k_, v in _points(theta1, speed1).items()}
    exact.update(
        {
            "F": force,
            "E_s": sp.Lambda(u, sp.Integral(phi * sp.sin(k * w), (w, 0, end))),
            "E_c": sp.Lambda(u, sp.Integral(phi * sp.cos(k * w), (w, 0, end))),
            "theta": theta0 + c / l0 * theta1,
            "dtheta_dt": speed0 + c / l0 * speed1,
            "g": k**2 * l0,
        }
    )
    return exact


def _air_force() -> Any:
    import sympy as sp

    q0, q1, q2 = _params(3, "q")
    v = sp.Symbol("v_", real=True)
    return sp.Lambda(v, q0 + q1 * v + q2 * v**2)


def _air(phase: bool) -> dict[str, Any]:
    import sympy as sp

    t, k, alpha, l0, c = _ledger("t", "k", "alpha", "l0", "c")
    theta0, speed0 = _principal_motion()
    force = _air_force()
    exact = _resisted(force, phase)
    v = force.args[0][0]
    w = sp.Symbol("w_", real=True)
    speed = l0 * speed0.subs(t, w)
    exact.update(
        {
            "S": sp.Lambda(v, sp.integrate(force.expr, (v, 0, v))),
            "nu": l0 * speed0,
            "nu_m": l0 * k * alpha,
            "s": l0 * theta0,
            "sigma": l0 * alpha,
            "tau": c * sp.Integral(force(speed) * speed, (w, 0, sp.pi / k)),
        }
    )
    amplitude = exact["Delta_alpha"]
    exact.update(
        {
            "Delta_z": amplitude,
            "Delta_y": l0 / 2 * ((alpha + amplitude) ** 2 - alpha**2),
            "Delta_sigma": l0 * amplitude,
        }
    )
    return exact


def _along_the_arc() -> Callable[[Any], Any]:
    """ν at the arc s of the principal motion: ν² + k²s² = k²σ² (the energy of (2))."""
    import sympy as sp

    k, sigma, nu = _ledger("k", "sigma", "nu")
    # |…| under the root, ≥ 0 on the arc: the quadrature's nodes may round past its ends
    return _integrand_along({"s": lambda v: {nu: k * sp.sqrt(sp.Abs(sigma**2 - v**2))}})


def reference_air() -> Reference:
    """n° 12: θ, θ' and E_s, E_c (of the time) for F(v) = q0 + q1v + q2v², ε = c/l0."""
    return Reference(_air(phase=False), transform=_along_the_arc(), what="F = q0 + q1v + q2v²")


def reference_air_points() -> Reference:
    """n° 13: the remarkable points for F(v) = q0 + q1v + q2v² (E of kt), through c."""
    (c,) = _ledger("c")
    exact = _air(phase=True)
    return Reference(
        exact,
        scale=c,
        order=2,
        domain=_positive_air_domain(),
        transform=_along_the_arc(),
        what="F in the air",
    )


def _monomial(phase: bool, power: Any = None) -> dict[str, Any]:
    """F(v) = B_n vⁿ, b_n = cB_n (n° 14), I_n its definition; n on the grid of halves
    floor(2n)/2, so that the powers of the random rationals stay short numbers."""
    import sympy as sp

    c, n, big, k, l0 = _ledger("c", "n", "B_n", "k", "l0")
    grid = sp.floor(2 * n) / 2
    v = sp.Symbol("v_", real=True)
    # |v|: v ≥ 0 on the first oscillation, and the quadrature's nodes may round past its ends
    force = sp.Lambda(v, big * sp.Abs(v) ** (grid if power is None else power))
    exact = _resisted(force, phase)
    exact.update({"I": _in_definition(), "n": grid, "b_n": c * big, "b0": c * big})
    exact.update({"T": sp.pi / k, "Delta_x": exact["Delta_alpha"]})
    exact["Delta_v_m"] = l0 * exact["Delta_thetap_m"]
    return exact


def _monomial_domain() -> dict[str, tuple[Any, Any]]:
    """Values of order 1 (kαl0 near 1), so that B_n(kαl0)ⁿ is far above the tolerance."""
    import sympy as sp

    half, one, two = sp.Rational(1, 2), sp.Integer(1), sp.Integer(2)
    return {
        "n": (one, sp.Integer(4)),
        "alpha": (half, one),
        "l0": (one, two),
        "k": (half, one),
        "B_n": (half, one),
        "c": (half, one),
    }


def reference_monomial() -> Reference:
    """n° 15: E_s, E_c (of the time) for F(v) = B_n vⁿ."""
    return Reference(_monomial(phase=False), domain=_monomial_domain(), what="F = B_n vⁿ")


def reference_monomial_points() -> Reference:
    """n° 16-17: Δα, ΔT_½, Δv_m for F(v) = B_n vⁿ (E of kt), through c."""

    (c,) = _ledger("c")
    exact, domain = _monomial(phase=True), _monomial_domain()
    return Reference(exact, scale=c, order=2, domain=domain, what="F = B_n vⁿ")


def reference_friction() -> Reference:
    """n° 16: n = 0, F = B_0: the count P = α/|Δα| of simple oscillations until rest."""
    exact = _monomial(phase=True, power=0)
    exact["P"] = _ledger("alpha")[0] / (-exact["Delta_alpha"])
    return Reference(
        exact,
        domain=_monomial_domain(),
        what="α over the loss of amplitude per oscillation, F = B_0",
    )


def _in_definition() -> Any:
    """I_n(x) = ∫₀^x sin^{n+1} y dy, x in [0, π] (|sin|: the nodes may round past π)."""
    import sympy as sp

    y = sp.Symbol("y_", real=True)
    m, x = sp.symbols("m_ x_", real=True)
    return sp.Lambda((m, x), sp.Integral(sp.Abs(sp.sin(y)) ** (m + 1), (y, 0, x)))


def reference_in() -> Reference:
    """n° 15: I_n = ∫₀^x sin^{n+1} x dx, its definition (quadrature)."""
    import sympy as sp

    exact = {"I": _in_definition()}
    return Reference(exact, domain={"n": (sp.Integer(2), sp.Integer(5))}, what="I_n's definition")


# --- d19: the closed forms of n° 16, 2° and the prose of n° 3, 12, 13, 15, 16 ------------


def _monomial_case(power: Any) -> Reference:
    """Δα of F(v) = B_n vⁿ for the exponent ``power`` (n itself set to it), through c."""
    (c,) = _ledger("c")
    exact = _monomial(phase=True, power=power)
    exact["n"] = power
    return Reference(exact, scale=c, order=2, domain=_monomial_domain(), what="F = B_n vⁿ")


def reference_monomial_parity() -> Reference:
    """n° 16, 2°: the first formula (« pour n pair ») against Δα of F = B_n vⁿ for n = 0, 2, 4,
    the second (« pour n impair ») for n = 1, 3, 5 (2·floor(n) − 2 and 2·floor(n) − 1 at the
    random n in [1, 4)); Δα from Duhamel's integral, never from I_n(π)."""
    import sympy as sp

    (n,) = _ledger("n")
    even, odd = _monomial_case(2 * sp.floor(n) - 2), _monomial_case(2 * sp.floor(n) - 1)
    return Reference(
        odd.exact,
        scale=odd.scale,
        order=odd.order,
        domain=odd.domain,
        what="F = B_n vⁿ, n even then n odd",
        cases=(even, odd),
    )


def reference_air_first_oscillation() -> Reference:
    """n° 12, 3°: E_s of the time on the first simple oscillation (0 < kt < π), F = q0 + q1v +
    q2v² with positive q's (F > 0, as n° 11 assumes)."""
    import sympy as sp

    base = reference_air()
    domain = {"t": (sp.Rational(1, 10), sp.Integer(3)), "k": (sp.Rational(1, 2), sp.Integer(1))}
    domain.update(_positive_air_domain())
    return Reference(base.exact, domain=domain, transform=base.transform, what=base.what)


def _positive_air_domain() -> dict[str, tuple[Any, Any]]:
    """The range over which n° 12-13's signs are asserted: an amplitude, a length and a
    resistance F = q0 + q1v + q2v² with positive q's (as n° 11 assumes), a small c."""
    import sympy as sp

    positive = (sp.Rational(1, 10), sp.Rational(1, 2))
    domain = dict.fromkeys(("alpha", "l0", "q0", "q1", "q2"), positive)
    domain.update(k=(sp.Rational(1, 2), sp.Integer(1)), c=(sp.Rational(1, 100), sp.Rational(1, 20)))
    return domain


def reference_friction_in_g_and_t() -> Reference:
    """n° 16, 1°: Δα for n = 0 (F = B_0) written in g and T (k = π/T, l0 = gT²/π²), so that
    its derivatives in α and in T say whether it depends on them; through c."""
    import sympy as sp

    c, k, l0, g, big_t = _ledger("c", "k", "l0", "g", "T")
    exact = _monomial(phase=True, power=0)
    in_g_t = {k: sp.pi / big_t, l0: g * big_t**2 / sp.pi**2}
    shift = exact["Delta_alpha"].subs(in_g_t, simultaneous=True)
    return Reference(
        {"Delta_x": shift},
        scale=c,
        order=2,
        domain={"c": (sp.Rational(1, 2), sp.Integer(1))},
        what="Δα of F = B_0 in g and T",
    )


def reference_monomial_decay() -> Reference:
    """n° 16, 1°: Δα of F = B_n vⁿ for n in [1, 4) with c small (c < 1/10), so that one simple
    oscillation keeps a positive fraction of the amplitude; through c."""
    import sympy as sp

    base = reference_monomial_points()
    domain = {**base.domain, "c": (sp.Rational(1, 100), sp.Rational(1, 20))}
    return Reference(base.exact, scale=base.scale, order=base.order, domain=domain, what=base.what)


def reference_constant_resistance() -> Reference:
    """n° 13, 1°: ΔT and E_c(π) for a constant resistance F = B_0 (E of kt), through c."""
    (c,) = _ledger("c")
    exact = _monomial(phase=True, power=0)
    return Reference(exact, scale=c, order=2, domain=_monomial_domain(), what="F = B_0")


def reference_principal_turn() -> Reference:
    """n° 3: the principal motion at the end of the simple oscillation, t = T (θ0' = 0 again),
    T found as in reference_principal_motion."""
    import sympy as sp

    (t,) = _ledger("t")
    base = reference_principal_motion()
    at_end = {t: base.exact["T"]}
    exact = {"theta": base.exact["theta"].subs(at_end), "t": base.exact["T"]}
    return Reference(exact, domain={"alpha": (sp.Rational(1, 10), sp.Integer(1))}, what="θ0 at T")
