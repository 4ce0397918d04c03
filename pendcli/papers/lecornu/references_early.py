"""Lecornu (1894), lines 1–698: the references the printed forms are checked against (issue 19).

Each ``reference_*`` returns a :class:`~pendcli.core.printed_check.Reference` mapping ledger
symbols (``tables/equations/lecornu.toml`` [symbols]) to exact expressions taken from what the
printed formula rests on: the bob's equations in x, y (lines 34–40), the chain rule of
l = a + bt, the exact solutions of (9) (u = √x Z₁(2√x), Z₁ = J₁ or Y₁), the definitions
(C = A + B/(φ₀φ'₀), ψ, γ, p), the solution of (27) by undetermined coefficients; never a
second copy of the formula the row prints. The ``check_*`` functions are the independent
checks of the rows added here (sympy identities, mpmath quadrature and root finding).

sympy and mpmath are imported inside the functions (start-up stays fast).
"""

from __future__ import annotations

import itertools
from functools import cache
from typing import Any

from pendcli.core.ledger_check import EquationCheck
from pendcli.papers.taylor import taylor

__all__ = [
    "check_bob_equations",
    "check_chain_rule",
    "check_curvature",
    "check_elongation_lengths",
    "check_eq16",
    "check_half_period_root",
    "check_integral_solution",
    "check_quadrature_identities",
    "check_quarter_time",
    "check_riccati",
    "check_second_form",
    "check_shortening",
    "check_table_amplitudes",
    "check_table_intervals",
    "check_table_j0",
    "check_table_j1_roots",
    "check_table_lengths",
    "check_table_speeds",
    "check_table_times",
    "check_table_vertical_lengths",
    "check_theta_in_time",
    "check_x_is_xi",
    "reference_at_beta",
    "reference_bessel_general",
    "reference_bessel_past_alpha_prime",
    "reference_bessel_past_beta",
    "reference_bessel_switches",
    "reference_cartesian",
    "reference_cartesian_uniform",
    "reference_chain_rule",
    "reference_compound",
    "reference_cr_note",
    "reference_curvature",
    "reference_elongation_lengths",
    "reference_elongation_root",
    "reference_eq27",
    "reference_eq27_from_9",
    "reference_graphical",
    "reference_initial_data",
    "reference_integral_solution",
    "reference_large_lambda",
    "reference_motion_in_l",
    "reference_phi_prime_series",
    "reference_phi_series",
    "reference_psi",
    "reference_quadrature",
    "reference_quarter_oscillation",
    "reference_quarter_time",
    "reference_riccati",
    "reference_root_epsilon",
    "reference_shortening",
    "reference_slow_exact",
    "reference_slow_pendulum",
    "reference_slow_vertical",
    "reference_small_angle",
    "reference_successive_elongations",
    "reference_u_of_x",
    "reference_x_is_xi",
    "reference_zero_length",
]


def _symbols(*names: str) -> Any:
    import sympy as sp

    return [sp.Symbol(n, real=True) for n in names]


def _reference(exact: dict[str, Any], what: str, **kw: Any) -> Any:
    from pendcli.core.printed_check import Reference

    return Reference(exact, what=what, **kw)


# --- § I: the equation of motion ------------------------------------------------------------


@cache
def _bob_accelerations() -> tuple[Any, Any, dict[str, Any]]:
    """ẍ, ÿ of x = l sin θ, y = l cos θ (line 34) for any l(t), θ(t), in the ledger's
    derivative symbols; and the symbols themselves."""
    import sympy as sp

    t, length, dl, d2l, theta, dtheta, d2theta = _symbols(
        "t", "l", "dl_dt", "d2l_dt2", "theta", "dtheta_dt", "d2theta_dt2"
    )
    big_l, big_theta = sp.Function("L")(t), sp.Function("Theta")(t)
    jets = {
        big_l.diff(t, 2): d2l,
        big_theta.diff(t, 2): d2theta,
        big_l.diff(t): dl,
        big_theta.diff(t): dtheta,
    }

    def in_symbols(expr: Any) -> Any:
        return expr.subs(jets).subs({big_l: length, big_theta: theta})

    ax = in_symbols((big_l * sp.sin(big_theta)).diff(t, 2))
    ay = in_symbols((big_l * sp.cos(big_theta)).diff(t, 2))
    names = {"l": length, "dl_dt": dl, "d2l_dt2": d2l, "theta": theta, "d2theta_dt2": d2theta}
    return ax, ay, names


def _cartesian_exact(uniform: bool) -> dict[str, Any]:
    """From lines 34–40: θ'' solved from x ÿ − y ẍ − g x = 0 (line 44, itself from 38 and 40),
    the tension from x ẍ + y ÿ = −T l + g y; with ``uniform``, l = a + bt (line 62)."""
    # a fresh dict of the shared expressions: eight rows cite it, each solve costs 0.4 s
    return dict(_cartesian_items(uniform))


@cache
def _cartesian_items(uniform: bool) -> tuple[tuple[str, Any], ...]:
    import sympy as sp

    a, b, t, g, ten = _symbols("a", "b", "t", "g", "Ten")
    ax, ay, s = _bob_accelerations()
    length, theta = s["l"], s["theta"]
    if uniform:  # the general items with the law substituted: one solve and simplify, not two
        law = {length: a + b * t, s["dl_dt"]: b, s["d2l_dt2"]: 0}
        return tuple((k, v.subs(law, simultaneous=True)) for k, v in _cartesian_items(False))
    x, y = length * sp.sin(theta), length * sp.cos(theta)
    # (38), (40): ẍ = −T x/l, ÿ = g − T y/l; eliminating T gives line 44
    d2theta = sp.solve(sp.expand(x * ay - y * ax - g * x), s["d2theta_dt2"])[0]
    tension = sp.simplify((g * y - (x * ax + y * ay)) / length)
    exact = {
        "d2theta_dt2": d2theta,
        "Ten": tension,
        "xc": x,
        "yc": y,
        "d2xc_dt2": -ten * x / length,
        "d2yc_dt2": g - ten * y / length,
    }
    return tuple(exact.items())


def reference_cartesian() -> Any:
    """Lines 34–44: x = l sin θ, y = l cos θ and the bob's equations (38), (40)."""
    return _reference(_cartesian_exact(False), "x = l sin θ, y = l cos θ and (38), (40)")


def reference_cartesian_uniform() -> Any:
    """The same with l = a + bt (line 62): the source of (3) and (4)."""
    return _reference(_cartesian_exact(True), "(38), (40) with l = a + bt")


def _chain_rule() -> dict[str, Any]:
    """l = a + bt: dθ/dt, d²θ/dt² of θ(t) = Θ(a + bt) by the chain rule (sympy)."""
    import sympy as sp

    a, b, t, dtheta_dl, d2theta_dl2 = _symbols("a", "b", "t", "dtheta_dl", "d2theta_dl2")
    of_t = sp.Function("Theta")(a + b * t)
    jet = {1: dtheta_dl, 2: d2theta_dl2}  # Θ's derivatives at l = a + bt

    def in_l(expr: Any) -> Any:
        return expr.replace(
            lambda e: isinstance(e, sp.Subs), lambda e: jet[e.expr.derivative_count]
        )

    return {"dtheta_dt": in_l(of_t.diff(t)), "d2theta_dt2": in_l(of_t.diff(t, 2))}


def reference_chain_rule() -> Any:
    """Line 72: the chain rule of l = a + bt."""
    return _reference(_chain_rule(), "the chain rule of l = a + bt")


def reference_motion_in_l() -> Any:
    """(3) in the variable l: θ'' of (3) by the chain rule, t = (l − a)/b."""
    import sympy as sp

    a, b, length, dtheta_dl = _symbols("a", "b", "l", "dtheta_dl")
    d2theta_dt2 = _cartesian_exact(True)["d2theta_dt2"].subs(
        a + sp.Symbol("b", real=True) * sp.Symbol("t", real=True), length
    )
    dtheta_dt = sp.Symbol("dtheta_dt", real=True)
    exact = {
        "d2theta_dl2": (d2theta_dt2 / b**2).subs(dtheta_dt, b * dtheta_dl),
        "t": (length - a) / b,
    }
    return _reference(exact, "(3) in l by the chain rule")


def reference_small_angle() -> Any:
    """(5) (from (3) and the chain rule) with sin θ ≈ θ: θ scaled by ε, through ε¹."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    theta, dtheta_dl = _symbols("theta", "dtheta_dl")
    base = reference_motion_in_l().exact
    d2 = base["d2theta_dl2"].subs({theta: eps * theta, dtheta_dl: eps * dtheta_dl})
    exact = {"theta": eps * theta, "dtheta_dl": eps * dtheta_dl, "d2theta_dl2": d2}
    return _reference(exact, "(5) to first order in θ", scale=eps, order=2)


def reference_riccati() -> Any:
    """(7) with θ = e^∫z dl (θ' = zθ, θ'' = (z' + z²)θ), then z = v − 1/l."""
    import sympy as sp

    length, g, b, theta, zr, vr, dzr = _symbols("l", "g", "b", "theta", "zr", "vr", "dzr_dl")
    # (7), l θ'' + 2θ' + (g/b²)θ = 0, with θ' = zθ and θ'' = (z' + z²)θ
    eq7 = length * (dzr + zr**2) * theta + 2 * zr * theta + g / b**2 * theta
    dz = sp.solve(eq7, dzr)[0]
    dv = dz.subs(zr, vr - 1 / length) - sp.diff(-1 / length, length)
    return _reference({"dzr_dl": dz, "dvr_dl": dv}, "(7) with θ = exp ∫z dl, z = v − 1/l")


# --- § II: the Bessel solutions of (9) ------------------------------------------------------


def _phi(x: Any, kind: str = "j") -> Any:
    """√x Z₁(2√x): Z₁ = J₁ (φ, (10)) or Y₁ (the second solution of (9))."""
    import sympy as sp

    bessel = sp.besselj if kind == "j" else sp.bessely
    return sp.sqrt(x) * bessel(1, 2 * sp.sqrt(x))


def _general_u(x: Any, x0: Any, big_a: Any, big_b: Any) -> Any:
    """The solution of (9) whose value and slope at x0 are Aφ0 and Aφ'0 + B/φ0 (line 348),
    written in the independent basis √x J₁(2√x), √x Y₁(2√x)."""
    c1, c2 = _basis_coefficients(x0, big_a, big_b)
    return c1 * _phi(x, "j") + c2 * _phi(x, "y")


def _basis_coefficients(x0: Any, big_a: Any, big_b: Any) -> tuple[Any, Any]:
    """_general_u's coefficients of √x J₁(2√x) and √x Y₁(2√x) (the Wronskian at x0)."""
    import sympy as sp

    s = sp.Dummy("s", positive=True)
    j, y = _phi(s, "j"), _phi(s, "y")
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
    x, x0, big_a, big_b = _symbols("x", "x0", "A", "B")
    u = _general_u(x, x0, big_a, big_b)
    phi = _phi(x)
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
        (where,) = _symbols(f"x{point}")
        exact[f"varphi{point}"] = phi.subs(x, where)
        exact[f"varphip{point}"] = phi.diff(x).subs(x, where)
    return tuple(exact.items())


def _u_over_phi_at(point: str) -> Any:
    """A new constant of (17)-type at ``point``: u/φ there (the form u = A'φ + … at x = x_j)."""
    import sympy as sp

    x, where = _symbols("x", point)
    exact = _bessel_exact()
    return sp.Mul(exact["u"], 1 / exact["varphi"]).subs(x, where)


def reference_bessel_general() -> Any:
    """(17)–(22) between x0 and x in (1/10, 1/2), where φ and φ' have no root."""
    return _reference(_bessel_exact(), "u of (9) from its value and slope at x0, √x J₁, √x Y₁")


def reference_bessel_past_beta() -> Any:
    """(17'), A': x0 in (3/2, 18/5) (between the roots 1.446 of φ' and 3.670 of φ), x1 and x
    past β = 3.670 and below the next root 7.618 of φ'; A' = u(x1)/φ(x1)."""
    import sympy as sp

    exact = _bessel_exact({"Ap": _u_over_phi_at("x1")})
    domain = {
        "x0": (sp.Rational(3, 2), sp.Rational(18, 5)),
        "x1": (sp.Rational(37, 10), sp.Rational(15, 2)),
        "x": (sp.Rational(37, 10), sp.Rational(15, 2)),
    }
    return _reference(exact, "u of (9); A' = u/φ at x1 (line 316)", domain=domain)


def reference_bessel_past_alpha_prime() -> Any:
    """(21'), C': as above, and x2, x past α' = 7.618, below the root 12.31 of φ;
    C' = (u + B/φ')/φ at x2 (the form (21') at x = x2)."""
    import sympy as sp

    x, x2, big_b = _symbols("x", "x2", "B")
    exact = _bessel_exact()
    c_prime = ((exact["u"] + big_b / exact["dvarphi_dx"]) / exact["varphi"]).subs(x, x2)
    exact["Cp"] = c_prime
    exact["Ap"] = _u_over_phi_at("x1")
    domain = {
        "x0": (sp.Rational(3, 2), sp.Rational(18, 5)),
        "x1": (sp.Rational(37, 10), sp.Rational(15, 2)),
        "x2": (sp.Rational(77, 10), sp.Rational(122, 10)),
        "x": (sp.Rational(77, 10), sp.Rational(122, 10)),
    }
    return _reference(exact, "u of (9); C' = (u + B/φ')/φ at x2 (line 326)", domain=domain)


def reference_bessel_switches() -> Any:
    """The general rule (lines 330–342): x0 in (1/10, 1/2), before every root; x, x_k in
    (37/10, 15/2), past φ' = 0 at 1.446 and φ = 0 at 3.670; x_h and the switch point x1 in
    (3/2, 18/5), between them."""
    import sympy as sp

    domain = {
        "x0": (sp.Rational(1, 10), sp.Rational(1, 2)),
        "x": (sp.Rational(37, 10), sp.Rational(15, 2)),
        "xk": (sp.Rational(37, 10), sp.Rational(15, 2)),
        "xh": (sp.Rational(3, 2), sp.Rational(18, 5)),
        "x1": (sp.Rational(3, 2), sp.Rational(18, 5)),
    }
    return _reference(_bessel_exact(), "u of (9) across the roots of φ' and φ", domain=domain)


def reference_u_of_x() -> Any:
    """(9) from (7): u = θl, x = gl/b², d²u/dx² = (b²/g)²(lθ'' + 2θ') with θ'' from (7)."""
    import sympy as sp

    length, g, b, theta, dtheta = _symbols("l", "g", "b", "theta", "dtheta_dl")
    d2theta = sp.solve(length * sp.Symbol("q_") + 2 * dtheta + g / b**2 * theta, sp.Symbol("q_"))[0]
    exact = {
        "u": theta * length,
        "x": g * length / b**2,
        "d2u_dx2": (b**2 / g) ** 2 * (length * d2theta + 2 * dtheta),
    }
    return _reference(exact, "(7) with u = θl, l = (b²/g)x")


def _trajectory(zl: Any, cl: Any) -> Any:
    """The bob's path u(z) (lines 124, 134): a solution of (9) with x = z/c, here
    √x J₁(2√x) + √x Y₁(2√x) (both kinds, so neither special case)."""
    x = zl / cl
    return _phi(x, "j") + _phi(x, "y")


def reference_graphical() -> Any:
    """x = z/c in (9): u(z) exact; h the ordinate at z = 0 of the tangent at (z, u)."""

    zl, cl, at = _symbols("zl", "cl", "Z_")
    u = _trajectory(zl, cl)
    slope = u.diff(zl)
    tangent = u + slope * (at - zl)
    h = tangent.subs(at, 0)
    exact = {"u": u, "du_dzl": slope, "d2u_dzl2": u.diff(zl, 2), "h": h, "dh_dzl": h.diff(zl)}
    return _reference(exact, "the exact path u(z) of (9), x = z/c, and its tangent")


def reference_curvature() -> Any:
    """The curvature of the exact path at small slopes (« au même degré d'approximation »,
    line 140): κ = d²u/dz², u(z) of (9) with x = z/c; θ = u/z (l = z, line 134)."""
    zl, cl = _symbols("zl", "cl")
    u = _trajectory(zl, cl)
    kappa = u.diff(zl, 2)
    at_c = (kappa / u).subs(zl, cl)  # the constant K of κ = K u, if there were one
    exact = {"u": u, "kappa": kappa, "theta": u / zl, "K": at_c}
    return _reference(exact, "the exact path's u''")


def _phi_series(order: int) -> Any:
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    (x,) = _symbols("x")
    exact = {"x": eps * x, "varphi": _phi(eps * x), "dvarphi_dx": _phi(x).diff(x).subs(x, eps * x)}
    return _reference(exact, "φ = √x J₁(2√x)", scale=eps, order=order)


def reference_phi_series() -> Any:
    """φ = √x J₁(2√x) (the text's own identification, line 160), x scaled by ε, through ε⁴."""
    return _phi_series(5)


def reference_phi_prime_series() -> Any:
    """The same through ε³, the last term (11) prints."""
    return _phi_series(4)


def reference_zero_length() -> Any:
    """z = 2√x → 0 (x scaled by ε², z by ε): the limit is the ε⁰ term."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    x, z = _symbols("x", "z")
    return _reference(
        {"x": eps**2 * x, "z": eps * z, "varphi": _phi(eps**2 * x)},
        "J₁ near 0",
        scale=eps,
        order=1,
    )


def reference_compound() -> Any:
    """Line 84, l' = l + R²/l, with l = a + bt; bt/a small: b scaled by ε, through ε¹."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    a, b, t, rg = _symbols("a", "b", "t", "Rg")
    length = a + eps * b * t
    return _reference(
        {"lp": length + rg**2 / length, "b": eps * b}, "l' = l + R²/l", scale=eps, order=2
    )


# --- § II, the slowly varying pendulum ------------------------------------------------------


def _forced_oscillator(rhs: Any, tau: Any, degree: int) -> Any:
    """The solution of U'' + U = rhs(τ) with U(0) = U'(0) = 0, rhs a polynomial in τ times
    cos τ, sin τ: undetermined coefficients (a polynomial of ``degree`` on each), solved
    linearly."""
    import sympy as sp

    a = sp.symbols(f"a0:{degree + 1}")
    c = sp.symbols(f"c0:{degree + 1}")
    trial = sum(a[k] * tau**k for k in range(degree + 1)) * sp.cos(tau) + sum(
        c[k] * tau**k for k in range(degree + 1)
    ) * sp.sin(tau)
    residual = sp.expand(trial.diff(tau, 2) + trial - rhs)
    equations = []
    for trig in (sp.cos(tau), sp.sin(tau)):
        part = sp.Poly(residual.coeff(trig), tau)
        equations.extend(part.all_coeffs())
    equations += [trial.subs(tau, 0), trial.diff(tau).subs(tau, 0)]
    solution = sp.solve(equations, [*a, *c], dict=True)[0]
    return sp.expand(trial.subs(solution).subs({k: 0 for k in (*a, *c)}))


@cache
def _eq27_solution() -> tuple[Any, Any, Any]:
    """(27) with u(0) = 0, u'(0) = γ to p² (line 638): u0 = sin γt and, in τ = γt (line 626),
    u_n'' + u_n = −τ u_(n−1)'', u_n(0) = u_n'(0) = 0 (line 628)."""
    import sympy as sp

    t, gamma, p = _symbols("t", "gamma", "p")
    tau = sp.Dummy("tau")
    parts = [sp.sin(tau)]
    for n in (1, 2):
        parts.append(_forced_oscillator(-tau * parts[-1].diff(tau, 2), tau, 2 * n))
    u = sum(part * p**k for k, part in enumerate(parts)).subs(tau, gamma * t)
    return u, t, p


def reference_eq27() -> Any:
    """(28) against (27) solved to p² (γ kept); for (29), θ = u/(1 + pγt) to p² (line 678,
    the constant factor a dropped)."""
    import sympy as sp

    u, t, p = _eq27_solution()
    (gamma,) = _symbols("gamma")
    theta = sp.expand(taylor(u / (1 + p * gamma * t), p, 3))
    return _reference({"uA": u, "theta": theta}, "(27) solved to p²", scale=p, order=3)


def _slow_exact(psi_value: Any) -> dict[str, Any]:
    """(22) with l = a + bt (line 583), γ = √(g/a), p = b/√(ga) (line 585), R = ρa^(3/4)
    (line 589) and φ = 2/p + ψ, i.e. ψ the phase of sin(γt − ψ) as (25) uses it."""
    import sympy as sp

    a, g, t, rho, p = _symbols("a", "g", "t", "rho", "p")
    gamma = sp.sqrt(g / a)
    b = p * sp.sqrt(g * a)
    length = a + b * t
    phi = 2 / p + psi_value
    big_r = rho * a ** sp.Rational(3, 4)
    # (2/b)√(gl) − φ = (2/p)(√(1 + pγt) − 1) − ψ, rationalised so that its series in p exists
    argument = 2 * gamma * t / (sp.sqrt(1 + p * gamma * t) + 1) - psi_value
    theta = big_r * length ** sp.Rational(-3, 4) * sp.sin(argument)
    return {"theta": theta, "gamma": gamma, "r": gamma, "b": b, "R": big_r, "phi": phi}


def reference_slow_pendulum() -> Any:
    """(22) in t, to first order in p (lines 581–595)."""
    (psi,) = _symbols("psi")
    (p,) = _symbols("p")
    return _reference(_slow_exact(psi), "(22) with l = a + bt, γ, p, ρ", scale=p, order=2)


def reference_slow_exact() -> Any:
    """(22) in t, exactly (lines 581-587)."""
    (psi,) = _symbols("psi")
    return _reference(_slow_exact(psi), "(22) with l = a + bt, γ, p, R")


def reference_slow_vertical() -> Any:
    """The same with the pendulum vertical at t = 0 (line 599): ψ = 0."""
    (p,) = _symbols("p")
    return _reference(_slow_exact(0), "(22) vertical at t = 0", scale=p, order=2)


def reference_psi() -> Any:
    """ψ as the phase of (22)'s sine at t = 0 once written sin(γt − ψ): −(2/p − φ)."""
    import sympy as sp

    a, g, p, phi = _symbols("a", "g", "p", "phi")
    b = p * sp.sqrt(g * a)
    argument_at_0 = 2 / b * sp.sqrt(g * a) - phi  # (22)'s argument at l = a
    return _reference({"psi": -argument_at_0}, "the phase of (22) at t = 0")


# --- checks of the rows added for issue 19 --------------------------------------------------


def check_bob_equations() -> EquationCheck:
    """Lines 42–48: with x = l sin θ, y = l cos θ, x ÿ − y ẍ = −d(l²θ')/dt for every l(t),
    θ(t); so line 44 is line 48 (sympy)."""
    import sympy as sp

    t = sp.Symbol("t")
    length, theta = sp.Function("l")(t), sp.Function("theta")(t)
    x, y = length * sp.sin(theta), length * sp.cos(theta)
    lhs = x * y.diff(t, 2) - y * x.diff(t, 2)
    areal = (length**2 * theta.diff(t)).diff(t)
    ok = sp.simplify(lhs + areal) == 0 and sp.simplify(x * sp.Symbol("g") - x * sp.Symbol("g")) == 0
    from pendcli.papers.lecornu.equations_common import equation_check

    return equation_check(ok, "sympy", "x ÿ − y ẍ + d(l²θ')/dt simplifies to 0, and gx = gl sin θ")


def check_chain_rule() -> EquationCheck:
    """Line 72: θ(t) = Θ(a + bt) gives θ' = bΘ', θ'' = b²Θ'' (sympy, Θ arbitrary)."""
    import sympy as sp

    from pendcli.papers.lecornu.equations_common import equation_check

    a, b, t, s = sp.symbols("a b t s")
    big = sp.Function("Theta")
    theta = big(a + b * t)
    at = {s: a + b * t}
    first = sp.simplify(theta.diff(t) - b * big(s).diff(s).subs(at))
    second = sp.simplify(theta.diff(t, 2) - b**2 * big(s).diff(s, 2).subs(at))
    return equation_check(
        first == 0 and second == 0,
        "sympy",
        "dθ/dt − b dθ/dl and d²θ/dt² − b² d²θ/dl² simplify to 0 for θ(t) = Θ(a + bt)",
    )


def check_riccati() -> EquationCheck:
    """Line 102 (and (8)) numerically: θ from (7) by an ODE solve, z = θ'/θ, then the residual
    of dz/dl + z² + 2z/l + g/(b²l) by finite differences (mpmath, 30 digits)."""
    import mpmath

    with mpmath.workdps(30):
        k = mpmath.mpf(3) / 2  # g/b² in 1/m
        f = mpmath.odefun(lambda x, y: [y[1], -(2 * y[1] + k * y[0]) / x], 1, [1, 0])
        worst = mpmath.mpf(0)
        for length in (mpmath.mpf("1.3"), mpmath.mpf("2.2"), mpmath.mpf("3.1")):

            def z(x: Any) -> Any:
                theta, dtheta = f(x)
                return dtheta / theta

            dz = mpmath.diff(z, length)
            residual = dz + z(length) ** 2 + 2 * z(length) / length + k / length
            v = z(length) + 1 / length
            dv = dz - 1 / length**2
            residual8 = dv + v**2 + k / length
            worst = max(worst, abs(residual), abs(residual8))
    from pendcli.papers.lecornu.equations_common import equation_check

    return equation_check(
        worst < 1e-6,
        "numeric",
        f"θ of (7) by mpmath.odefun from l = 1: "
        f"the residuals of line 102 and of (8) are at most {float(worst):.1e}",
    )


def _elongation_root() -> Any:
    """The first x > 0 where θ ∝ φ/x = J₁(2√x)/√x is stationary (mpmath, 40 digits, the
    derivative taken analytically: d/dx J₁(2√x)/√x = J₁'(2√x)/x − J₁(2√x)/(2x√x))."""
    import mpmath

    with mpmath.workdps(40):

        def slope(x: Any) -> Any:
            root = mpmath.sqrt(x)
            return mpmath.besselj(1, 2 * root, derivative=1) / x - mpmath.besselj(1, 2 * root) / (
                2 * x * root
            )

        return mpmath.findroot(slope, 6.5)


def mpmath_str(value: Any) -> str:
    import mpmath

    return mpmath.nstr(value, 40)


def reference_elongation_root() -> Any:
    """x = ξ, the first elongation (where d(φ/x)/dx = 0, found numerically), z = 2√ξ."""
    import sympy as sp

    xi = sp.Float(mpmath_str(_elongation_root()), 40)
    return _reference({"x": xi, "z": 2 * sp.sqrt(xi)}, "the first root of d(φ/x)/dx = 0")


def reference_x_is_xi() -> Any:
    """Line 112, x = gl/b², at the elongation x = ξ."""
    g, length, b = _symbols("g", "l", "b")
    return _reference({"xi": g * length / b**2}, "x = gl/b² at x = ξ")


def reference_at_beta() -> Any:
    """u of (9) at β, the first root of φ (β = j₁,₁²/4: φ = √x J₁(2√x))."""
    import mpmath
    import sympy as sp

    with mpmath.workdps(30):
        beta = sp.Float(str(mpmath.besseljzero(1, 1) ** 2 / 4), 30)
    (x,) = _symbols("x")
    exact = {k: v.subs(x, beta) for k, v in _bessel_exact().items()}
    return _reference(exact, "u of (9) at the root β = 3.670 of φ")


def reference_initial_data() -> Any:
    """u = θl, x = gl/b² at t = 0 (l = a): u0 = aθ0, u'0 = (b²/g)(θ0 + a ω0/b) by the chain
    rule; A, B solved from u0 = Aφ0, u'0 = Aφ'0 + B/φ0 ((17), (18) at x0); C = A + B/(φ0φ'0)."""
    import sympy as sp

    a, b, g, theta0, omega0, phi0, dphi0, big_a, big_b = _symbols(
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
    return _reference(exact, "the initial data θ0, ω0 at l = a")


def check_x_is_xi() -> EquationCheck:
    """Lines 192-194: l = (b²/g)ξ solved for b > 0 is √(gl/ξ) (sympy)."""
    import sympy as sp

    from pendcli.papers.lecornu.equations_common import equation_check

    length, b, g, xi = sp.symbols("l b g xi", positive=True)
    roots = sp.solve(sp.Eq(length, b**2 / g * xi), b)
    ok = len(roots) == 1 and sp.simplify(roots[0] - sp.sqrt(g * length / xi)) == 0
    return equation_check(ok, "sympy", f"l = (b²/g)ξ gives b = {roots}")


def _numeric_u(x0: Any, u0: Any, du0: Any) -> Any:
    """u of (9) from x0 by mpmath's Taylor ODE solver (independent of the Bessel forms)."""
    import mpmath

    return mpmath.odefun(lambda x, y: [y[1], -y[0] / x], x0, [u0, du0])


def check_second_form() -> EquationCheck:
    """Line 298 and (21): u = Cφ − B/φ' + Bφ∫dx/(xφ'²), C = A + B/(φ0φ'0), against u of (9)
    solved numerically from u0 = Aφ0, u'0 = Aφ'0 + B/φ0 (mpmath odefun and quad)."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    with mpmath.workdps(25):

        def phi(x: Any) -> Any:
            return mpmath.sqrt(x) * mpmath.besselj(1, 2 * mpmath.sqrt(x))

        def dphi(x: Any) -> Any:
            return mpmath.besselj(0, 2 * mpmath.sqrt(x))

        x0, big_a, big_b = mpmath.mpf("0.3"), mpmath.mpf("0.7"), mpmath.mpf("-0.4")
        u = _numeric_u(x0, big_a * phi(x0), big_a * dphi(x0) + big_b / phi(x0))
        big_c = big_a + big_b / (phi(x0) * dphi(x0))
        worst = mpmath.mpf(0)
        for x in (mpmath.mpf("0.6"), mpmath.mpf("1.1"), mpmath.mpf("1.4")):
            integral = mpmath.quad(lambda s: 1 / (s * dphi(s) ** 2), [x0, x])
            form = big_c * phi(x) - big_b / dphi(x) + big_b * phi(x) * integral
            worst = max(worst, abs(form - u(x)[0]))
    return equation_check(
        worst < 1e-12,
        "numeric",
        f"against (9) by mpmath.odefun from x0 = 0.3 to x = 1.4 (below "
        f"the root 1.446 of φ'): largest difference {float(worst):.1e}",
    )


def check_curvature() -> EquationCheck:
    """Lines 140-142: the curvature u''/(1 + u'²)^(3/2) of the path u(z) of (9) (x = z/c,
    u = ε(√x J₁ + √x Y₁)), by mpmath: κ/u is not constant along the path, κz/u is."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    with mpmath.workdps(25):
        c, eps = mpmath.mpf(1), mpmath.mpf("1e-6")

        def u(z: Any) -> Any:
            x = z / c
            root = mpmath.sqrt(x)
            return eps * root * (mpmath.besselj(1, 2 * root) + mpmath.bessely(1, 2 * root))

        def kappa(z: Any) -> Any:
            return mpmath.diff(u, z, 2) / (1 + mpmath.diff(u, z) ** 2) ** 1.5

        points = (mpmath.mpf("0.9"), mpmath.mpf("2.3"), mpmath.mpf("4.1"))
        per_u = [kappa(z) / u(z) for z in points]
        per_theta = [kappa(z) * z / u(z) for z in points]
    spread = max(per_u) - min(per_u)
    constant = max(abs(v + 1 / c) for v in per_theta)
    return equation_check(
        spread < 1e-9,
        "numeric",
        f"κ/u at z = 0.9, 2.3, 4.1 (c = 1): {', '.join(mpmath.nstr(v, 5) for v in per_u)}; "
        f"κz/u differs from −1/c by at most {float(constant):.1e}",
        corrected="κ ≈ −u/(cz) = −(g/b²)θ: proportional to the angle θ = u/z, not to u"
        if constant < 1e-9
        else "",
    )


def check_eq16() -> EquationCheck:
    """(16): ξ = z²/4 (z = 2√x, sympy), and b²/(4g) with the adopted b = 0,35 m/s (line 218)
    and the table's g (assumed 9,81, not printed), exact rationals, against the printed
    0,00313 m rounded half up at its five decimals; the g it would need is reported."""
    from fractions import Fraction

    import sympy as sp

    from pendcli.papers.lecornu.equations_common import equation_check
    from pendcli.papers.lecornu.model import constant, printed_number

    z = sp.Symbol("z", positive=True)
    identity = sp.simplify((z / 2) ** 2 - z**2 / 4) == 0  # x at z = 2√x
    b, g = Fraction(str(constant("speed"))), Fraction(str(constant("g")))
    number = printed_number("lecornu.coefficient_b2_4g")
    places = number.decimals or 0
    coefficient = b**2 / (4 * g)
    rounded = Fraction(int(coefficient * 10**places + Fraction(1, 2)), 10**places)
    printed = Fraction(number.text.replace(",", "."))
    g_max = b**2 / (4 * (printed - Fraction(1, 2 * 10**places)))
    return equation_check(
        identity and rounded == printed,
        "sympy",
        f"ξ = z²/4 exactly; b²/(4g) = {float(coefficient):.7f} for b = {float(b)}, "
        f"g = {float(g)}, which prints {float(rounded):.{places}f}; {number.text} needs "
        f"g ≤ {float(g_max):.4f}",
        corrected=f"{float(rounded):.{places}f} z²" if rounded != printed else "",
    )


def reference_cr_note() -> Any:
    """The 1894 note's formula against (22) (as for (25)), with k = p and ω = ψ + p/8."""
    (psi, p) = _symbols("psi", "p")
    exact = _slow_exact(psi)
    exact.update({"k": p, "omega": psi + p / 8})
    return _reference(exact, "(22) with k = p, ω = ψ + p/8", scale=p, order=2)


def reference_eq27_from_9() -> Any:
    """(9) in t: x = (1 + pγt)/p² (line 614), so d²u/dx² = (p/γ)² d²u/dt², with (9)'s
    d²u/dx² = −u/x."""
    p, gamma, t, u = _symbols("p", "gamma", "t", "u")
    x = (1 + p * gamma * t) / p**2
    return _reference({"d2u_dt2": (gamma / p) ** 2 * (-u / x), "r": gamma}, "(9) in t")


@cache
def _epsilon_root() -> tuple[Any, Any]:
    """The root γt = π + ε of (27)'s solution to p² (not (28) as printed): ε = e1 p + e2 p²."""
    import sympy as sp

    u, t, p = _eq27_solution()
    (gamma,) = _symbols("gamma")
    e1, e2 = sp.symbols("e1 e2")
    eps = e1 * p + e2 * p**2
    at_root = taylor(u.subs(t, (sp.pi + eps) / gamma), p, 3)
    first = sp.solve(sp.expand(at_root).coeff(p, 1), e1)[0]
    second = sp.solve(sp.expand(at_root.subs(e1, first)).coeff(p, 2), e2)[0]
    return sp.simplify(first * p + second * p**2), p


def reference_root_epsilon() -> Any:
    """Lines 642-664: ε the root of u = 0 near γt = π, t = (π + ε)/γ, γ = √(g/a),
    b = p√(ga); through p²."""
    import sympy as sp

    eps, p = _epsilon_root()
    a, g = _symbols("a", "g")
    exact = {
        "epsilon": eps,
        "t": (sp.pi + eps) / sp.sqrt(g / a),
        "gamma": sp.sqrt(g / a),
        "b": p * sp.sqrt(g * a),
    }
    return _reference(exact, "the root of (27)'s solution near γt = π", scale=p, order=3)


def reference_shortening() -> Any:
    """(3) with b → −b (line 694: « nous mettons en évidence le signe de b »), then z = a/b − t,
    s = g/b (line 696): dθ/dt = −dθ/dz, d²θ/dt² = d²θ/dz²."""
    a, b, t, g, zt, dtheta_dzt = _symbols("a", "b", "t", "g", "zt", "dtheta_dzt")
    import sympy as sp

    exact = _cartesian_exact(True)
    d2 = exact["d2theta_dt2"].subs(b, -b)  # θ'' of (3) for l = a − bt
    dtheta_dt = sp.Symbol("dtheta_dt", real=True)
    in_z = d2.subs({t: a / b - zt, dtheta_dt: -dtheta_dzt}, simultaneous=True)
    return _reference(
        {"d2theta_dt2": d2, "d2theta_dzt2": in_z, "s": g / b}, "(3) for l = a − bt, z = a/b − t"
    )


def reference_elongation_lengths() -> Any:
    """Lines 541-547: l from (23) and φ from (24) written at l'' (exact, no approximation)."""
    import sympy as sp

    b, g, lpp, lam = _symbols("b", "g", "lpp", "lam")
    phi = 2 / b * sp.sqrt(g * lpp) - (2 * lam + 1) * sp.pi / 2 + 3 * b / (4 * sp.sqrt(g * lpp))
    length = b**2 / (4 * g) * (phi + lam * sp.pi) ** 2
    return _reference({"phi": phi, "l": length}, "(23) at l, (24) at l''")


def check_elongation_lengths() -> EquationCheck:
    """Lines 543-547 numerically: for b = 0,1, g = 9,81, λ = 7, φ = 0,3, l from (23) and l''
    the root of (24) (mpmath.findroot); both printed right sides against (4g/b²)(l'' − l)."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    with mpmath.workdps(30):
        b, g, lam, phi = mpmath.mpf("0.1"), mpmath.mpf("9.81"), 7, mpmath.mpf("0.3")
        length = b**2 / (4 * g) * (phi + lam * mpmath.pi) ** 2
        eq24 = lambda y: (  # noqa: E731
            2 / b * mpmath.sqrt(g * y)
            - phi
            - (2 * lam + 1) * mpmath.pi / 2
            + 3 * b / (4 * mpmath.sqrt(g * y))
        )
        lpp = mpmath.findroot(eq24, length * 1.1)
        lhs = 4 * g / b**2 * (lpp - length)
        small = mpmath.pi / 2 - 3 * b / (4 * mpmath.sqrt(g * lpp))
        first = (lam * mpmath.pi + phi + small) ** 2 - (lam * mpmath.pi + phi) ** 2
        second = 2 * (lam * mpmath.pi + phi) * small + small**2
        worst = max(abs(lhs - first), abs(lhs - second))
    return equation_check(
        worst < 1e-20, "numeric", f"l'' by findroot of (24): differences at most {float(worst):.1e}"
    )


def _orders(errors: list[Any], ps: list[Any]) -> list[float]:
    import mpmath

    return [
        float(mpmath.log(errors[i] / errors[i + 1]) / mpmath.log(ps[i] / ps[i + 1]))
        for i in range(len(errors) - 1)
    ]


def check_theta_in_time() -> EquationCheck:
    """Lines 583-591: (22) at l = a + bt against the form in γ, p (equal) and the first-order
    form (its error falls as p², observed over p = 0,02 … 0,005; mpmath)."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    with mpmath.workdps(30):
        a, g, big_r, phi, t = (mpmath.mpf(v) for v in ("1", "9.81", "0.2", "0.4", "0.7"))
        gamma = mpmath.sqrt(g / a)
        exact_gap, errors, ps = (
            mpmath.mpf(0),
            [],
            [mpmath.mpf(v) for v in ("0.02", "0.01", "0.005")],
        )
        for p in ps:
            b = p * mpmath.sqrt(g * a)
            eq22 = (
                big_r
                * (a + b * t) ** -0.75
                * mpmath.sin(2 / b * mpmath.sqrt(g * (a + b * t)) - phi)
            )
            in_p = (
                big_r
                * a**-0.75
                * (1 + p * gamma * t) ** -0.75
                * mpmath.sin(2 / p * mpmath.sqrt(1 + p * gamma * t) - phi)
            )
            rho = big_r * a**-0.75
            first = (
                rho
                * (1 - 0.75 * p * gamma * t)
                * mpmath.sin(2 / p + gamma * t - p * gamma**2 * t**2 / 4 - phi)
            )
            exact_gap = max(exact_gap, abs(eq22 - in_p))
            errors.append(abs(eq22 - first))
        orders = _orders(errors, ps)
    return equation_check(
        exact_gap < 1e-25 and all(o > 1.8 for o in orders),
        "numeric",
        f"(22) = the γ, p form to {float(exact_gap):.0e}; the first-order form's error "
        f"{', '.join(f'{float(e):.1e}' for e in errors)}, observed order "
        f"{', '.join(f'{o:.2f}' for o in orders)} (claimed: through p)",
    )


def check_half_period_root() -> EquationCheck:
    """Lines 642-664: the first zero after t = 0 of (27)'s solution (mpmath.odefun from
    u(0) = 0, u'(0) = γ, γ = 1), against γt = π + pπ²/4 + 3p²π/32: the error falls as p³."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    ps = [mpmath.mpf(v) for v in ("0.04", "0.02", "0.01")]
    errors = []
    with mpmath.workdps(20):
        for p in ps:
            u = mpmath.odefun(lambda t, y, p=p: [y[1], -y[0] / (1 + p * t)], 0, [0, 1])
            root = mpmath.findroot(lambda t, u=u: u(t)[0], mpmath.pi * (1 + p))
            claimed = mpmath.pi + p * mpmath.pi**2 / 4 + 3 * p**2 * mpmath.pi / 32
            errors.append(abs(root - claimed))
        orders = _orders(errors, ps)
    return equation_check(
        all(o > 2.7 for o in orders),
        "numeric",
        f"zero of (27) by odefun: error of π + pπ²/4 + 3p²π/32 at p = 0.04, 0.02, 0.01: "
        f"{', '.join(f'{float(e):.1e}' for e in errors)}, observed order "
        f"{', '.join(f'{o:.2f}' for o in orders)} (claimed 3)",
        observed_order=min(orders),
    )


def check_shortening() -> EquationCheck:
    """Lines 694-698: (1) with l = a − bt gives (a − bt)θ'' − 2bθ' + g sin θ = 0; with
    z = a/b − t and s = g/b it is z θ_zz + 2θ_z + s sin θ = 0 (sympy, θ arbitrary)."""
    import sympy as sp

    from pendcli.papers.lecornu.equations_common import equation_check

    a, b, g, t, z = sp.symbols("a b g t z", positive=True)
    big = sp.Function("Theta")
    theta = big(a / b - t)
    length = a - b * t
    eq1 = length * theta.diff(t, 2) + 2 * length.diff(t) * theta.diff(t) + g * sp.sin(theta)
    printed = length * theta.diff(t, 2) - 2 * b * theta.diff(t) + g * sp.sin(theta)
    in_z = z * big(z).diff(z, 2) + 2 * big(z).diff(z) + g / b * sp.sin(big(z))
    ok = (
        sp.simplify(eq1 - printed) == 0
        and sp.simplify((eq1 / b).doit().subs(t, a / b - z).doit() - in_z) == 0
    )
    return equation_check(
        ok,
        "sympy",
        "(1) with l = a − bt minus line 694, and line 694 / b "
        "in z = a/b − t minus (30), simplify to 0",
    )


# --- the numerical tables of lines 206-256 (b = 0,35 m/s, a pendulum of 1 m at z = 17,96) ----
# Each printed value is judged against the value computed, to the printed decimals, rounded or
# chopped (line 210: « Je néglige les décimales qui suivent la seconde »).


def _matches(printed: float, value: Any, decimals: int) -> bool:
    import mpmath

    scale = mpmath.mpf(10) ** decimals
    rounded = mpmath.nint(value * scale) / scale
    chopped = (mpmath.floor(abs(value) * scale) / scale) * mpmath.sign(value)
    return any(abs(printed - float(v)) < 1e-9 for v in (rounded, chopped))


def _table_check(
    what: str, printed: list[float], computed: list[Any], decimals: int
) -> EquationCheck:
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    wrong = [(p, c) for p, c in zip(printed, computed, strict=True) if not _matches(p, c, decimals)]
    shown = ", ".join(mpmath.nstr(c, decimals + 2) for c in computed)
    corrected = ", ".join(f"{float(c):.{decimals}f}" for c in computed) if wrong else ""
    off = "; ".join(f"{p} printed, {float(c):.{decimals + 2}f} computed" for p, c in wrong)
    return equation_check(
        not wrong,
        "numeric",
        f"{what}: computed {shown}"
        + (
            f"; off: {off}"
            if wrong
            else "; every printed value is the computed one rounded or chopped"
        ),
        corrected=corrected,
    )


def _j2_roots() -> list[Any]:
    import mpmath

    return [mpmath.besseljzero(2, k) for k in range(1, 6)]


def check_table_speeds() -> EquationCheck:
    """Line 216: b = √(g/ξ) for l = 1 m, ξ = z²/4 at the five roots of J₂ (g = 9,81)."""
    import mpmath

    speeds = [mpmath.sqrt(mpmath.mpf("9.81") / (z**2 / 4)) for z in _j2_roots()]
    return _table_check("√(g/ξ) in m/s", [1.22, 0.74, 0.54, 0.42, 0.35], speeds, 2)


def check_table_lengths() -> EquationCheck:
    """Line 224: the lengths at the elongations, l = (z/17,96)² m by (16) with l = 1 m at the
    largest root (exact roots of J₂, mpmath)."""
    roots = _j2_roots()[::-1]
    lengths = [(z / roots[0]) ** 2 for z in roots]
    return _table_check("(z/z₅)² in m", [1, 0.68, 0.42, 0.22, 0.08], lengths, 2)


def check_table_times() -> EquationCheck:
    """Line 228: the instants (1 − l)/0,35 of the elongations, from the lengths as printed at
    line 224 (the text's own step); the exact roots give 0, 0,918, 1,661, 2,230, 2,624."""
    import mpmath

    from pendcli.papers.lecornu.model import constant

    lengths = [mpmath.mpf(str(v)) for v in _printed_column("example.length", range(1, 6))]
    times = [(1 - v) / mpmath.mpf(str(constant("speed"))) for v in lengths]
    printed = _printed_column("example.time", range(1, 6))
    return _table_check("(1 − l)/0,35 in s", printed, times, 2)


def _printed_column(prefix: str, keys: Any) -> list[Any]:
    """The printed values of claims ``lecornu.<prefix>.<key>``, read from the published
    table (a number the paper prints is never retyped)."""
    from pendcli.papers.lecornu.model import printed_number

    return [printed_number(f"lecornu.{prefix}.{k}").value for k in keys]


def check_table_intervals() -> EquationCheck:
    """Line 232: the intervals between the limit positions, the differences of the instants
    of line 228 and of the zero length (2,86 s, line 230), in exact rationals from the
    published table (the printed instants, never retyped)."""
    from fractions import Fraction
    from itertools import pairwise

    from pendcli.papers.lecornu.model import printed_number

    ids = [f"lecornu.example.time.{k}" for k in range(1, 6)] + ["lecornu.example.time_zero_length"]
    instants = [Fraction(f"{printed_number(i).value:.2f}") for i in ids]
    gaps = [later - sooner for sooner, later in pairwise(instants)]
    printed = [printed_number(f"lecornu.example.interval.{k}").value for k in range(1, 6)]
    return _table_check("differences of the printed instants in s", printed, gaps, 2)


def check_table_j0() -> EquationCheck:
    """Line 240: J₀ at the roots of (15) as printed (5,14 … 17,96), mpmath; at the exact roots
    J₀ is −0,1323, +0,0645, −0,0400, +0,0279, −0,0209."""
    import mpmath

    roots = _printed_column("j2_zeros", range(1, 6))
    values = [mpmath.besselj(0, mpmath.mpf(str(z))) for z in roots]
    return _table_check("J₀(z)", _printed_column("j0_at_j2_zeros", range(1, 6)), values, 3)


def check_table_amplitudes() -> EquationCheck:
    """Line 246: θ/θ0 = J₀(z)/J₀(17,96) at the elongations (line 236's θ = (g/b²)J₀(z)), and
    1/J₀(17,96) at zero length (line 242's limit 1), exact roots of J₂ (mpmath)."""
    import mpmath

    roots = _j2_roots()[::-1]
    base = mpmath.besselj(0, roots[0])
    ratios = [mpmath.besselj(0, z) / base for z in roots] + [1 / base]
    # the first entry, θ0/θ0 = 1, is the table's unit, not a claim
    printed = [1, *_printed_column("deviation", [2, 3, 4, 5, "zero_length"])]
    return _table_check("θ/θ0", printed, ratios, 2)


def check_table_j1_roots() -> EquationCheck:
    """Line 252: the roots of J₁ below 20, from the largest (mpmath.besseljzero)."""
    import mpmath

    roots = [mpmath.besseljzero(1, k) for k in range(6, 0, -1)]
    return _table_check("j₁,k", _printed_column("j1_zeros", range(1, 7)), roots, 2)


def check_table_vertical_lengths() -> EquationCheck:
    """Line 256: the lengths at the verticals « en vertu de (16) », 0,00313 z² m at the roots
    as printed at line 252."""
    import mpmath

    from pendcli.papers.lecornu.model import printed_number

    roots = [mpmath.mpf(str(v)) for v in _printed_column("j1_zeros", range(1, 7))]
    coefficient = mpmath.mpf(str(printed_number("lecornu.coefficient_b2_4g").value))
    lengths = [coefficient * z**2 for z in roots]
    printed = _printed_column("j1_lengths", range(1, 7))
    return _table_check("0,00313 z² in m", printed, lengths, 2)


def reference_integral_solution() -> Any:
    """Lines 386-402: v, w as the integrals they are set to (line 388, 392), u = C(v + w sin α);
    their second derivatives in x taken under the integral sign (sympy)."""
    import sympy as sp

    x, alpha, omega, big_c = _symbols("x", "alpha", "omega", "C")
    half = (omega, 0, sp.pi / 2)
    v = x * sp.Integral(sp.cos(2 * sp.sqrt(x) * sp.cos(omega) + alpha) * sp.sin(omega) ** 2, half)
    w = x * sp.Integral(sp.exp(-2 * sp.sqrt(x) * sp.tan(omega)) / sp.cos(omega) ** 3, half)
    u = big_c * (v + w * sp.sin(alpha))
    exact = {"v": v, "w": w, "u": u, "d2v_dx2": v.diff(x, 2), "d2w_dx2": w.diff(x, 2)}
    exact["d2u_dx2"] = u.diff(x, 2)
    return _reference(exact, "v, w of lines 388, 392, differentiated under ∫")


def reference_quadrature() -> Any:
    """Lines 416-434: identities between definite integrals, judged by quadrature alone;
    a (here aa) a fixed number above 1, h (here hh) above 2a√x and below 3 (line 442)."""
    import sympy as sp

    domain = {
        "aa": (sp.Rational(11, 10), sp.Rational(3, 2)),
        "hh": (sp.Rational(22, 10), sp.Rational(29, 10)),
        # x stated, not left to the default: an inequality holds only over a stated range
        # (line 442's: 2a√x < h, here at most 2·1,5·√0,5 = 2,12 < 2,2)
        "x": (sp.Rational(1, 10), sp.Rational(1, 2)),
    }
    return _reference({}, "quadrature", domain=domain)


def reference_large_lambda() -> Any:
    """Line 422: (1 + λ²)^(1/2) for large λ: λ = 1/ε, through ε³."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    return _reference({"lam": 1 / eps}, "λ = 1/ε", scale=eps, order=5)


def check_integral_solution() -> EquationCheck:
    """Lines 396-402 numerically: v, w by mpmath.quad, their second derivatives by
    mpmath.diff, at x = 0,3 and 0,8 with α = 0,4."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    with mpmath.workdps(20):
        alpha = mpmath.mpf("0.4")

        def v(x: Any) -> Any:
            def f(om: Any) -> Any:
                return mpmath.cos(2 * mpmath.sqrt(x) * mpmath.cos(om) + alpha) * mpmath.sin(om) ** 2

            return x * mpmath.quad(f, [0, mpmath.pi / 2])

        def w(x: Any) -> Any:
            # with λ = tg ω (line 418, itself checked below by quad)
            f = lambda s: mpmath.exp(-2 * s * mpmath.sqrt(x)) * mpmath.sqrt(1 + s**2)  # noqa: E731
            return x * mpmath.quad(f, [0, 1, mpmath.inf])

        worst = mpmath.mpf(0)
        for x in (mpmath.mpf("0.3"), mpmath.mpf("0.8")):
            rv = x * mpmath.diff(v, x, 2) + v(x) + mpmath.sqrt(x) / 2 * mpmath.sin(alpha)
            rw = x * mpmath.diff(w, x, 2) + w(x) - mpmath.sqrt(x) / 2
            worst = max(worst, abs(rv), abs(rw))
    return equation_check(
        worst < 1e-8,
        "numeric",
        f"x v'' + v + (√x/2) sin α and x w'' + w − √x/2 "
        f"by quad and diff at x = 0,3, 0,8: at most {float(worst):.1e}",
    )


def check_quadrature_identities() -> EquationCheck:
    """Lines 418, 430, 434 at x = 0,2, a = 1,3, h = 2,5 by mpmath.quad (independent of the
    engine's points)."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    with mpmath.workdps(20):
        x, a, h = mpmath.mpf("0.2"), mpmath.mpf("1.3"), mpmath.mpf("2.5")
        r = mpmath.sqrt(x)
        left = mpmath.quad(
            lambda om: mpmath.exp(-2 * r * mpmath.tan(om)) / mpmath.cos(om) ** 3,
            [0, mpmath.pi / 4, mpmath.pi / 2],
        )
        right = mpmath.quad(
            lambda s: mpmath.exp(-2 * s * r) * mpmath.sqrt(1 + s**2), [0, mpmath.inf]
        )
        moment = mpmath.quad(lambda s: mpmath.exp(-2 * s * r) * s, [a, mpmath.inf])
        closed = mpmath.exp(-2 * a * r) * (1 + 2 * a * r) / (4 * x)
        e1 = mpmath.quad(lambda s: mpmath.exp(-2 * s * r) / s, [a, mpmath.inf])
        split = mpmath.quad(lambda q: mpmath.exp(-q) / q, [2 * a * r, h]) + mpmath.e1(h)
        worst = max(abs(left - right), abs(moment - closed), abs(e1 - split))
    return equation_check(
        worst < 1e-12, "numeric", f"three identities by quad: at most {float(worst):.1e}"
    )


def _quarter_oscillation(scale: Any) -> dict[str, Any]:
    """Lines 549-555: from a vertical at l ((23): φ = (2/b)√(gl) − λπ) to the next elongation
    l'' ((24) solved exactly: y = √(gl'') is the larger root of 2y/b + 3b/(4y) = (2/b)√(gl) + π/2),
    with b scaled by ``scale`` (b²/(gl) small)."""
    import sympy as sp

    b, g, length = _symbols("b", "g", "l")
    small_b = scale * b
    k = 2 / small_b * sp.sqrt(g * length) + sp.pi / 2
    y = (k * small_b + sp.sqrt(k**2 * small_b**2 - 6 * small_b**2)) / 4
    return {"lpp": y**2 / g, "b": small_b}


def reference_quarter_oscillation() -> Any:
    """Line 551, through ε⁰ (the orders 1/ε and 1)."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    return _reference(_quarter_oscillation(eps), "(23), (24) solved for l''", scale=eps, order=1)


def reference_quarter_time() -> Any:
    """Line 555, through ε (the orders 1 and b)."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    return _reference(_quarter_oscillation(eps), "(23), (24) solved for l''", scale=eps, order=2)


def check_quarter_time() -> EquationCheck:
    """Lines 549-555: l'' by findroot of (24) from the vertical at l = 1 (g = 9,81); the error
    of π/2 √(l/g) − 3b/(4g) + π²b/(16g) for (l'' − l)/b falls as b² (mpmath)."""
    import mpmath

    from pendcli.papers.lecornu.equations_common import equation_check

    errors, bs = [], [mpmath.mpf(v) for v in ("0.02", "0.01", "0.005")]
    with mpmath.workdps(30):
        g, length = mpmath.mpf("9.81"), mpmath.mpf(1)
        for b in bs:
            k = 2 / b * mpmath.sqrt(g * length) + mpmath.pi / 2
            y = mpmath.findroot(lambda y, b=b, k=k: 2 * y / b + 3 * b / (4 * y) - k, mpmath.sqrt(g))
            exact = (y**2 / g - length) / b
            claimed = (
                mpmath.pi / 2 * mpmath.sqrt(length / g)
                - 3 * b / (4 * g)
                + mpmath.pi**2 * b / (16 * g)
            )
            errors.append(abs(exact - claimed))
        orders = _orders(errors, bs)
    return equation_check(
        all(o > 1.8 for o in orders),
        "numeric",
        f"errors {', '.join(f'{float(e):.1e}' for e in errors)} at b = 0,02 … 0,005, observed "
        f"order {', '.join(f'{o:.2f}' for o in orders)} (claimed: through b)",
        observed_order=min(orders),
    )


def reference_successive_elongations() -> Any:
    """Line 577: l' = l + bπ√(l/g), the length half a period later (line 523), b scaled by ε
    (b/√(gl) small), through ε."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    b, g, length = _symbols("b", "g", "l")
    exact = {"lp": length + eps * b * sp.pi * sp.sqrt(length / g), "b": eps * b}
    return _reference(exact, "l' = l + bπ√(l/g)", scale=eps, order=2)


# --- a19: the references of the rows of lines 1-420 that had none (issue 19) ----------------

__all__ += [
    "reference_amplitude_j0",
    "reference_area",
    "reference_areal",
    "reference_compound_motion",
    "reference_elongations_of_12",
    "reference_eq6",
    "reference_eq13",
    "reference_first_member_13",
    "reference_inflection",
    "reference_integral_18",
    "reference_integral_19",
    "reference_limit_at_zero",
    "reference_monotone_as_cited",
    "reference_one_vertical",
    "reference_roots_interlace",
]


def reference_areal() -> Any:
    """Line 48 from line 44: θ'' solved from x ÿ − y ẍ − g x = 0 (lines 34–40); the printed
    d/dt of l²θ' taken by the chain rule (l' = dl/dt, (θ')' = θ'')."""
    dl, dtheta, d2theta = _symbols("dl_dt", "dtheta_dt", "d2theta_dt2")
    rates = {"t": {"l": dl, "theta": dtheta, "dtheta_dt": d2theta}}
    return _reference(_cartesian_exact(False), "x ÿ − y ẍ − g x = 0 (line 44)", rates=rates)


def reference_eq6() -> Any:
    """(6) against (3): θ'' of (3) (written with l = a + bt) for a d²/dt², θ_ll of (3) in l
    (the chain rule) for a d²/dl²; l' = b. The printed d²/dt² gives lθ'' + 2bθ' = −g sin θ,
    not −(g/b²) sin θ."""

    a, b, t, length = _symbols("a", "b", "t", "l")
    dtheta, d2theta, dtheta_dl, d2theta_dl2 = _symbols(
        "dtheta_dt", "d2theta_dt2", "dtheta_dl", "d2theta_dl2"
    )
    exact = dict(reference_motion_in_l().exact)
    exact["d2theta_dt2"] = _cartesian_exact(True)["d2theta_dt2"].subs(a + b * t, length)
    rates = {
        "t": {"theta": dtheta, "dtheta_dt": d2theta, "l": b},
        "l": {"theta": dtheta_dl, "dtheta_dl": d2theta_dl2},
    }
    del exact["t"]  # (3)'s θ'' is written in l, so no t is left to substitute
    return _reference(exact, "(3), in t and in l", rates=rates)


def reference_compound_motion() -> Any:
    """Lines 92-94 against the compound pendulum itself: d/dt[(l² + R²)θ'] + g l sin θ = 0
    (moment of inertia l² + R² per unit mass, l = a + bt the distance of the centre of
    gravity), θ'' solved from it; bt/a small: b scaled by ε, through ε¹ (the order of the
    printed l' = a + R²/a + b(1 − R²/a²)t)."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    a, b, t, rg, g, theta, dtheta, q = _symbols(
        "a", "b", "t", "Rg", "g", "theta", "dtheta_dt", "q_"
    )
    length, rate = a + eps * b * t, eps * b
    motion = (length**2 + rg**2) * q + 2 * length * rate * dtheta + g * length * sp.sin(theta)
    d2theta = sp.solve(motion, q)[0]
    exact = {"b": rate, "d2theta_dt2": d2theta}
    return _reference(exact, "d/dt[(l² + R²)θ'] + g l sin θ = 0", scale=eps, order=2)


def _scan_roots(f: Any, coarse: Any, low: float, high: float, steps: int) -> list[Any]:
    """The roots of ``f`` (mpmath) in (low, high): a sign change of ``coarse`` (the same
    function in floats, numpy) on a grid of ``steps``, refined by a bracketing solver on
    ``f`` (mpmath, 40 digits)."""
    import mpmath
    import numpy as np

    grid = np.linspace(low, high, steps + 1)
    values = coarse(grid)
    brackets = [(grid[k], grid[k + 1]) for k in range(steps) if values[k] * values[k + 1] < 0]
    with mpmath.workdps(40):
        return [mpmath.findroot(f, (mpmath.mpf(a), mpmath.mpf(b)), solver="anderson")
                for a, b in brackets]  # fmt: skip


def _cylinder(kind: str) -> tuple[Any, Any]:
    """x -> √x Z₁(2√x) and its derivative Z₀(2√x) (Z = J, or J + Y: the path), in mpmath,
    and the pair in floats (scipy)."""
    import mpmath
    from scipy.special import jv, yv

    def z(order: int, s: Any) -> Any:
        value = mpmath.besselj(order, s)
        return value + mpmath.bessely(order, s) if kind == "path" else value

    def z_float(order: int, s: Any) -> Any:
        return jv(order, s) + yv(order, s) if kind == "path" else jv(order, s)

    def exact(x: Any) -> tuple[Any, Any]:
        s = 2 * mpmath.sqrt(x)
        return mpmath.sqrt(x) * z(1, s), z(0, s)

    def coarse(x: Any) -> tuple[Any, Any]:
        s = 2 * x**0.5
        return x**0.5 * z_float(1, s), z_float(0, s)

    return exact, coarse


def _roots_of(kind: str, which: str, low: float, high: float) -> list[Any]:
    """The roots in x of U (``which`` = "zero"), of h = U − xU' (the tangent through the
    point of suspension, "tangent"), of U' (the slope), for U = √x Z₁(2√x) (_cylinder)."""
    exact, coarse = _cylinder(kind)

    def pick(pair: tuple[Any, Any], x: Any) -> Any:
        value, slope = pair
        return {"zero": value, "tangent": value - x * slope, "slope": slope}[which]

    return _scan_roots(
        lambda x: pick(exact(x), x), lambda x: pick(coarse(x), x), low, high, int(20 * high)
    )


def _float40(value: Any) -> Any:
    import sympy as sp

    return sp.Float(mpmath_str(value), 40)


def reference_inflection() -> Any:
    """Line 138: the exact path u(z) of (9) (x = z/c, _trajectory) at each of its first four
    zeros (the passages through the vertical, found by a scan, mpmath): its u''."""
    zl, cl = _symbols("zl", "cl")
    u = _trajectory(zl, cl)
    zeros = _roots_of("path", "zero", 0.2, 60)[:4]
    cases = tuple({"zl": cl * _float40(x)} for x in zeros)
    exact = {"u": u, "du_dzl": u.diff(zl), "d2u_dzl2": u.diff(zl, 2)}
    return _reference(exact, "the path u(z) of (9) at its zeros", each_case=cases)


def _between(exact: dict[str, Any], low: Any, high: Any) -> Any:
    """A transform: an identity with an indefinite integral ∫f dz (true up to a constant)
    judged between two points, r(high) − r(low), each ∫f dz read as ∫_low^high f dz; the
    reference's ``exact`` is substituted first (an integral's coefficient must not depend on
    z, or a term F(low) is left and the residual is not a number)."""
    import sympy as sp

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
    import mpmath

    zl, cl, zl1 = _symbols("zl", "cl", "zl1")
    u = _phi(zl / cl)  # J₁ only: the quadratures of Y₁ cost seconds
    exact = {"u": u, "h": u - zl * u.diff(zl)}
    elongations = _roots_of("bessel", "tangent", 0.5, 40)[:3]
    first = elongations[0] + (elongations[1] - elongations[0]) / 3
    exact_path, coarse_path = _cylinder("bessel")

    def level(x: Any, pair: Any = exact_path) -> Any:
        value, slope = pair(x)
        return value - x * slope

    with mpmath.workdps(40):
        target = level(first)
    second = _scan_roots(
        lambda x: level(x) - target,
        lambda x: level(x, coarse_path) - float(target),
        float(elongations[1]),
        40,
        800,
    )[0]
    pairs = [*itertools.pairwise(elongations), (first, second)]
    cases = tuple({"zl1": cl * _float40(p), "zl2": cl * _float40(q)} for p, q in pairs)
    return _reference(
        exact, "the path u(z) of (10)'s motion", each_case=cases, transform=_between(exact, zl1, zl)
    )


def _elongation_roots(count: int) -> list[Any]:
    """x at the first elongations of (10)'s motion: where θ ∝ φ/x is stationary, i.e.
    φ − xφ' = 0 (φ = √x J₁(2√x), φ' = J₀(2√x)), x > 0, by a scan (mpmath)."""
    return _roots_of("bessel", "tangent", 0.5, 100)[:count]


def reference_elongations_of_12() -> Any:
    """(12) and lines 170-178 at the first three elongations of θl = φ (θ = gφ/(b²x)
    stationary, _elongation_roots): dθ = θ'(x)dx, dl/dx = b²/g."""
    import sympy as sp

    x, b, g = _symbols("x", "b", "g")
    phi = _phi(x)
    theta = g * phi / (b**2 * x)
    exact = {
        "varphi": phi,
        "dvarphi_dx": phi.diff(x),
        "theta": theta,
        "dtheta": sp.diff(theta, x),
        "l": b**2 * x / g,
        "dl_dx": b**2 / g,
    }
    cases = tuple({"x": _float40(r)} for r in _elongation_roots(3))
    return _reference(exact, "the elongations of θl = φ", each_case=cases)


def reference_amplitude_j0() -> Any:
    """Lines 234-236: θ = φ/l at the maxima, the same elongations (φ − xφ' = 0, i.e. J₂(z) = 0
    with z = 2√x, where 2J₁(z)/z = J₀(z)); l = (b²/g)x; lengths in metres (the memoir's φ is
    a pure number « multipliée par une constante arbitraire », line 160, here one metre)."""
    import sympy as sp

    x, b, g = _symbols("x", "b", "g")
    phi = _phi(x)
    exact = {
        "varphi": phi,
        "theta": g * phi / (b**2 * x),
        "l": b**2 * x / g,
        "z": 2 * sp.sqrt(x),
        "metre": sp.Integer(1),
    }
    cases = tuple({"x": _float40(r)} for r in _elongation_roots(3))
    return _reference(exact, "θl = φ of (10) at its elongations", each_case=cases)


def reference_eq13() -> Any:
    """Lines 182-188: (12)'s condition φ/x − φ' = 0 with φ = √x J₁(2√x), then divided by x
    (« en divisant par x »), x scaled by ε through ε² (the terms printed)."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    (x,) = _symbols("x")
    condition = _phi(x) / x - _phi(x).diff(x)
    exact = {"x": eps * x}
    return _reference(
        exact, "(12) with φ = √x J₁(2√x)", scale=eps, order=3, conditions=(condition, condition / x)
    )


def reference_first_member_13() -> Any:
    """Line 196: the first member of (13) as (13) is derived, (φ/x − φ')/x with
    φ = √x J₁(2√x); x scaled by ε, through ε²."""
    import sympy as sp

    eps = sp.Symbol("eps_", positive=True)
    (x,) = _symbols("x")
    member = ((_phi(x) / x - _phi(x).diff(x)) / x).subs(x, eps * x)
    exact = {"x": eps * x, "m13": member}
    return _reference(exact, "(12) divided by x", scale=eps, order=3)


def reference_roots_interlace() -> Any:
    """Lines 204-206 at the five elongations below z = 20 (_elongation_roots, z = 2√ξ) and
    the roots of J₁ around each (mpmath.besseljzero)."""
    import mpmath

    roots = _elongation_roots(5)
    with mpmath.workdps(40):
        j1 = [mpmath.besseljzero(1, k) for k in range(1, 7)]
        z = [2 * mpmath.sqrt(r) for r in roots]
    cases = tuple(
        {"z": _float40(z[k]), "zeta1": _float40(j1[k]), "zeta2": _float40(j1[k + 1])}
        for k in range(5)
    )
    return _reference({}, "the elongations and the roots of J₁", each_case=cases)


def reference_monotone_as_cited() -> Any:
    """« L'équation (10) montre »: what (10) gives, φ = √x J₁(2√x) and φ', between the roots
    3.670 and 12.31 of φ; it says nothing of u or u', so the sign of d(u/φ)/dx is not fixed by
    it. The reading is judged against (20) (u' solved from it)."""
    import sympy as sp

    x, u, du, big_b, phi_s, dphi_s = _symbols("x", "u", "du_dx", "B", "varphi", "dvarphi_dx")
    phi = _phi(x)
    exact = {"varphi": phi, "dvarphi_dx": phi.diff(x)}
    rates = {"x": {"u": du, "varphi": dphi_s}}
    domain = {"x": (sp.Rational(37, 10), sp.Rational(61, 5)), "B": (sp.Rational(1, 10), 1)}
    q = sp.Symbol("q_")
    eq20 = (q * phi_s - u * dphi_s) / phi_s**2 - big_b / phi_s**2  # (20), d/dx by the rates
    solved = sp.solve(eq20, q)[0].subs({phi_s: phi, dphi_s: phi.diff(x)}, simultaneous=True)
    reading = _reference(
        {**exact, "du_dx": solved}, "(20)", rates=rates, domain={**domain, "u": (-1, 1)}
    )
    return _reference(exact, "(10)", rates=rates, domain=domain, reading=reading)


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
    import mpmath
    import sympy as sp

    b, g = _symbols("b", "g")
    roots = _roots_of("bessel", "zero", 1, 80)
    with mpmath.workdps(40):
        j1 = [mpmath.besseljzero(1, k) for k in range(1, 6)]
    solutions = [(sp.Rational(3, 10), 1, 1), (sp.Rational(5, 2), sp.Rational(-7, 10), 2),
                 (8, sp.Rational(1, 5), sp.Rational(-3, 10))]  # fmt: skip
    cases = []
    for k in range(4):
        alpha, beta = roots[k], roots[k + 1]
        for x0, big_a, big_b in solutions:
            cases.append({
                "zeta1": _float40(j1[k]),
                "zeta2": _float40(j1[k + 1]),
                "l1": b**2 / g * _float40(alpha),
                "l2": b**2 / g * _float40(beta),
                "nvert": sp.Integer(_vertical_count(x0, big_a, big_b, alpha, beta)),
            })  # fmt: skip
    return _reference({}, "the zeros of u between the roots of φ", each_case=tuple(cases))


def reference_limit_at_zero() -> Any:
    """Lines 364-380: φ = Mx (M = φ/x, line 364); p the mean value of line 370 (1/p² the mean
    of 1/M² under the weight 1/x² over (x, x0)); q its limit as x → 0, M(0) (the weight
    concentrates at 0); the limits of φ∫dx/φ² (the solution of (9) with value 0, slope 1/φ0
    at x0) and of u (_general_u) as x → 0, from the basis: √x J₁(2√x) → 0 and √x Y₁(2√x) →
    its sympy limit; θ = u/l, l = (b²/g)x."""
    import sympy as sp

    x, x0, big_a, big_b, b, g, u = _symbols("x", "x0", "A", "B", "b", "g", "u")
    s = sp.Dummy("s", positive=True)
    phi = _phi(x)
    at_zero = sp.limit(_phi(s, "y"), s, 0)
    mean = (1 / x0 - 1 / x) / sp.Integral(1 / _phi(s) ** 2, (s, x0, x))
    exact = {
        "varphi": phi,
        "M": phi / x,
        "p": sp.sqrt(mean),
        "q": sp.limit(_phi(s) / s, s, 0),
        "lim0": _basis_coefficients(x0, 0, 1)[1] * at_zero,
        "ulim": _basis_coefficients(x0, big_a, big_b)[1] * at_zero,
        "theta": u / (b**2 * x / g),
    }
    return _reference(exact, "(9)'s solutions near x = 0")


def _solves_nine(variable: str, to_x: Any = None) -> Any:
    """A transform: the printed right side F of ``variable = F`` (the residual is variable − F)
    judged as a solution of (9), x F'' + F = 0 (differentiated under ∫ by sympy); ``to_x``:
    (l, (b²/g)x) when F is θ(l), so that u = θl is tried."""
    (x,) = _symbols("x")

    def transform(expr: Any) -> Any:
        names = {s.name: s for s in expr.free_symbols}
        f = names[variable] - expr
        if to_x is not None:
            old, new = to_x
            f = f.subs(old, new) * new
        return x * f.diff(x, 2) + f

    return transform


def reference_integral_18() -> Any:
    """(18) of line 384: its right side solves (9), x u'' + u = 0."""
    return _reference({}, "(9), x u'' + u = 0", transform=_solves_nine("u"))


def reference_integral_19() -> Any:
    """(19) of line 406: θl, with l = (b²/g)x (line 112), solves (9)."""
    b, g, x, length = _symbols("b", "g", "x", "l")
    transform = _solves_nine("theta", (length, b**2 / g * x))
    return _reference({}, "(9) for u = θl, l = (b²/g)x", transform=transform)
