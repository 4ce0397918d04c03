"""Lecornu (1894), § II, the slowly varying pendulum, lines 462-688: the elongations of the
asymptotic form (22)-(24), the table after (26) and the solution of (27) to p².

Each builder maps ledger symbols to exact expressions: (22) with l = a + bt, (23) and (24)
solved for the next elongation, the zeros of (26), (27) solved by undetermined coefficients;
never a second copy of the formula the row prints. The builders of lines 466-539 and 559-563
((20)-(24) in l, the passages, the condition of an elongation) are in references_late.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.papers.lecornu.references_base import phi_of, reference, symbols, zero_start_forced
from pendcli.papers.taylor import taylor
from pendcli.verify.printed_check import Reference


def reference_elongation_lengths() -> Any:
    """Lines 541-547: l from (23) and φ from (24) written at l'' (exact, no approximation)."""
    b, g, lpp, lam = symbols("b", "g", "lpp", "lam")
    phi = 2 / b * sp.sqrt(g * lpp) - (2 * lam + 1) * sp.pi / 2 + 3 * b / (4 * sp.sqrt(g * lpp))
    length = b**2 / (4 * g) * (phi + lam * sp.pi) ** 2
    return reference({"phi": phi, "l": length}, "(23) at l, (24) at l''")


def _quarter_oscillation(scale: Any) -> dict[str, Any]:
    """Lines 549-555: from a vertical at l ((23): φ = (2/b)√(gl) − λπ) to the next elongation
    l'' ((24) solved exactly: y = √(gl'') is the larger root of 2y/b + 3b/(4y) = (2/b)√(gl) + π/2),
    with b scaled by ``scale`` (b²/(gl) small)."""
    b, g, length = symbols("b", "g", "l")
    small_b = scale * b
    k = 2 / small_b * sp.sqrt(g * length) + sp.pi / 2
    y = (k * small_b + sp.sqrt(k**2 * small_b**2 - 6 * small_b**2)) / 4
    return {"lpp": y**2 / g, "b": small_b}


def reference_quarter_oscillation() -> Any:
    """Line 551, through ε⁰ (the orders 1/ε and 1)."""
    eps = sp.Symbol("eps_", positive=True)
    return reference(_quarter_oscillation(eps), "(23), (24) solved for l''")


@cache
def _table_26() -> dict[str, Any]:
    """The instants of the table after (26), first order in p: tv1, te1, tv2, te2, tv3."""
    a, b, g = symbols("a", "b", "g")
    tau, p = sp.symbols("tau p", real=True)
    theta = (1 - sp.Rational(3, 4) * p * tau) * sp.sin(tau) - p * tau**2 / 4 * sp.cos(tau)
    rate = sp.diff(theta, tau)
    r, speed = sp.sqrt(g / a), b / sp.sqrt(g * a)
    out = {}
    for name, f, start in (
        ("tv1", theta, 0),
        ("te1", rate, sp.pi / 2),
        ("tv2", theta, sp.pi),
        ("te2", rate, 3 * sp.pi / 2),
        ("tv3", theta, 2 * sp.pi),
    ):
        at = {p: 0, tau: start}
        step = -sp.diff(f, p).subs(at) / sp.diff(f, tau).subs(at)  # the root's dτ/dp at p = 0
        out[name] = sp.expand((start + speed * sp.simplify(step)) / r)
    return out


def reference_largest_length() -> Any:
    """Line 565: the quarter period (π/2)√(l/g) of the ordinary pendulum of the largest
    length of the oscillation, l = a + b·tv2 at its end (the second vertical position), less
    the duration of each half of it (te1 − tv1 ascending, tv2 − te1 descending) from the
    table after (26), to first order in b."""
    a, b, g = symbols("a", "b", "g")
    times = _table_26()
    largest = a + b * times["tv2"]  # l = a + bt at the end of the oscillation
    quarter = sp.pi / 2 * sp.sqrt(largest / g)
    # its Taylor polynomial in b through b¹ (sympy's series of the root takes ~1.5 s)
    quarter = quarter.subs(b, 0) + b * sp.diff(quarter, b).subs(b, 0)
    exact = {
        "dasc": quarter - (times["te1"] - times["tv1"]),
        "ddesc": quarter - (times["tv2"] - times["te1"]),
    }
    return Reference(exact, what="quarter period at the largest length, first order in b")


def reference_amplitude_factor() -> Any:
    """Lines 569-573: θ of (22) (asymptotic), R l^(-3/4) sin((2/b)√(gl) − φ), at an
    elongation, where (24) gives the phase (2λ + 1)π/2 − 3b/(4√(gl)) (λ = 0: |θ| is the same
    for every λ). The first equality is exact (through b⁷); « en négligeant le carré de
    b/√(gl) », the second through b¹."""
    big_r, length, b, g = symbols("R", "l", "b", "g")
    phase = sp.pi / 2 - 3 * b / (4 * sp.sqrt(g * length))  # (24) with λ = 0
    theta = big_r * length ** sp.Rational(-3, 4) * sp.sin(phase)
    return Reference(
        {"theta": theta},
        what="(22) at the phase (24) of an elongation",
    )  # fmt: skip


def reference_successive_elongations() -> Any:
    """Line 577: l' = l + bπ√(l/g), the length half a period later (line 523); line 579:
    θ' = θ (l/l')^(3/4), the amplitude of (22) at an elongation, ∝ l^(-3/4) (lines 569-577);
    b scaled by ε (b/√(gl) small), through ε."""
    eps = sp.Symbol("eps_", positive=True)
    b, g, length, theta = symbols("b", "g", "l", "theta")
    later = length + eps * b * sp.pi * sp.sqrt(length / g)
    exact = {"lp": later, "thetap": theta * (length / later) ** sp.Rational(3, 4), "b": eps * b}
    return reference(exact, "l' = l + bπ√(l/g), the amplitude ∝ l^(-3/4) at l and l'")


def _slow_exact(psi_value: Any) -> dict[str, Any]:
    """(22) with l = a + bt (line 583), γ = √(g/a), p = b/√(ga) (line 585), R = ρa^(3/4)
    (line 589) and φ = 2/p + ψ, i.e. ψ the phase of sin(γt − ψ) as (25) uses it."""
    a, g, t, rho, p = symbols("a", "g", "t", "rho", "p")
    gamma = sp.sqrt(g / a)
    b = p * sp.sqrt(g * a)
    length = a + b * t
    phi = 2 / p + psi_value
    big_r = rho * a ** sp.Rational(3, 4)
    # (2/b)√(gl) − φ = (2/p)(√(1 + pγt) − 1) − ψ, rationalised so that its series in p exists
    argument = 2 * gamma * t / (sp.sqrt(1 + p * gamma * t) + 1) - psi_value
    theta = big_r * length ** sp.Rational(-3, 4) * sp.sin(argument)
    return {"theta": theta, "gamma": gamma, "r": gamma, "b": b, "R": big_r, "phi": phi}


def reference_slow_exact() -> Any:
    """(22) in t, exactly (lines 581-587); line 597, the footnote to (25): the 1894 note's
    formula against (22) (as for (25)), with k = p and ω = ψ + p/8."""
    psi, p = symbols("psi", "p")
    exact = _slow_exact(psi)
    exact.update({"k": p, "omega": psi + p / 8})
    return reference(exact, "(22) with l = a + bt, γ, p, R")


def reference_psi() -> Any:
    """Lines 593-595: ψ as the phase of (22)'s sine at t = 0 once written sin(γt − ψ): −(2/p −
    φ)."""
    a, g, p, phi = symbols("a", "g", "p", "phi")
    b = p * sp.sqrt(g * a)
    argument_at_0 = 2 / b * sp.sqrt(g * a) - phi  # (22)'s argument at l = a
    return reference({"psi": -argument_at_0}, "the phase of (22) at t = 0")


def reference_slow_vertical() -> Any:
    """(26), line 601: (22) with the pendulum vertical at t = 0 (line 599), ψ = 0."""
    return reference(_slow_exact(0), "(22) vertical at t = 0")


def reference_table_26() -> Any:
    """Lines 603-610: the zeros of θ and dθ/dt of (26), first order in p = b/√(ga)."""
    return Reference(_table_26(), what="the zeros of θ and θ' of (26), first order in p")


def reference_eq27_from_9() -> Any:
    """(27), line 618: (9) in t, x = (1 + pγt)/p² (line 614), so d²u/dx² = (p/γ)² d²u/dt², with
    (9)'s d²u/dx² = −u/x."""
    p, gamma, t, u = symbols("p", "gamma", "t", "u")
    x = (1 + p * gamma * t) / p**2
    return reference({"d2u_dt2": (gamma / p) ** 2 * (-u / x), "r": gamma}, "(9) in t")


@cache
def _eq27_parts() -> tuple[list[Any], Any]:
    """(27)'s solution with u(0) = 0, u'(0) = γ, in τ = γt (line 626), by powers of p to p²
    (line 638): u0 = sin τ and u_n'' + u_n = −τ u_(n−1)'', u_n(0) = u_n'(0) = 0 (line 628)."""
    tau = sp.Dummy("tau")
    parts = [sp.sin(tau)]
    for n in (1, 2):
        parts.append(zero_start_forced(-tau * parts[-1].diff(tau, 2), tau, 2 * n))
    return parts, tau


@cache
def _eq27_solution() -> tuple[Any, Any, Any]:
    """(27)'s solution to p² (:func:`_eq27_parts`) in t: u = Σ p^n u_n(γt)."""
    t, gamma, p = symbols("t", "gamma", "p")
    parts, tau = _eq27_parts()
    u = sum(part * p**k for k, part in enumerate(parts)).subs(tau, gamma * t)
    return u, t, p


def reference_eq27() -> Any:
    """(28), (29), lines 640 and 682: (28) against (27) solved to p² (γ kept); for (29), θ = u/(1 +
    pγt) to p² (line 678, the constant factor a dropped)."""
    u, t, p = _eq27_solution()
    (gamma,) = symbols("gamma")
    theta = sp.expand(taylor(u / (1 + p * gamma * t), p, 3))
    return reference({"uA": u, "theta": theta}, "(27) solved to p²")


@cache
def _epsilon_root() -> tuple[Any, Any]:
    """The root γt = π + ε of (27)'s solution to p² (not (28) as printed): ε = e1 p + e2 p².
    Each u_n(π + ε) by its Taylor polynomial about π to p^(2 − n) (ε is of order p), which is
    u(π + ε)'s to p², without differentiating the whole substituted sum."""
    parts, tau = _eq27_parts()
    (p,) = symbols("p")
    e1, e2 = sp.symbols("e1 e2")
    eps = e1 * p + e2 * p**2
    at_root = sp.expand(
        sum(
            p**n * part.diff(tau, j).subs(tau, sp.pi) * eps**j / sp.factorial(j)
            for n, part in enumerate(parts)
            for j in range(3 - n)
        )
    )
    first = sp.solve(at_root.coeff(p, 1), e1)[0]
    second = sp.solve(sp.expand(at_root.subs(e1, first)).coeff(p, 2), e2)[0]
    return sp.simplify(first * p + second * p**2), p


def reference_root_epsilon() -> Any:
    """Lines 642-664: ε the root of u = 0 near γt = π, t = (π + ε)/γ, γ = √(g/a),
    b = p√(ga); through p²."""
    eps, p = _epsilon_root()
    a, g = symbols("a", "g")
    exact = {
        "epsilon": eps,
        "t": (sp.pi + eps) / sp.sqrt(g / a),
        "gamma": sp.sqrt(g / a),
        "b": p * sp.sqrt(g * a),
    }
    return reference(exact, "the root of (27)'s solution near γt = π")


# --- the claims of the prose, lines 462-614 ---------------------------------------------------


def reference_sin_alpha_zero() -> Any:
    """Line 462, « dans le cas contraire […] la formule (10) »: (18) of line 384 with sin α = 0
    (α = 0), its integral as printed, beside φ = √x J₁(2√x) of (10) and the constant factor."""
    x, omega, big_c = symbols("x", "omega", "C")
    integral = sp.Integral(sp.cos(2 * sp.sqrt(x) * sp.cos(omega)) * sp.sin(omega) ** 2,
                           (omega, 0, sp.pi / 2))  # fmt: skip
    # the factor the sentence leaves unnamed, by Poisson's integral for J₁
    exact = {"u": big_c * x * integral, "varphi": phi_of(x), "Cp": big_c * sp.pi / 4}
    return reference(exact, "(18) of line 384 at α = 0, and φ of (10)")


def reference_large_x() -> Any:
    """Line 501: the equation of line 499, x u'' + (1 + 3/(16x))u = 0, solved for u'', with x
    large (x -> x/ε), through ε⁰: (9) is it with 3/(16x) neglected beside 1."""
    eps = sp.Symbol("eps_", positive=True)
    x, u = symbols("x", "u")
    big_x = x / eps
    exact = {"x": big_x, "d2u_dx2": -(1 + 3 / (16 * big_x)) * u / big_x}
    return reference(exact, "line 499's equation at large x")


def reference_elongation_difference_far() -> Any:
    """Line 579, « tend vers zéro à mesure que la longueur augmente »: θ' as in
    reference_successive_elongations, the length large (l -> l/ε²), through ε⁰."""
    eps = sp.Symbol("eps_", positive=True)
    b, g, length, theta = symbols("b", "g", "l", "theta")
    far = length / eps**2
    later = far + b * sp.pi * sp.sqrt(far / g)
    exact = {"thetap": theta * (far / later) ** sp.Rational(3, 4), "l": far}
    return reference(exact, "amplitude ∝ l^(-3/4), l large")


def reference_vertical_phase() -> Any:
    """Line 599: the pendulum vertical at t = 0 in (22), (2/b)√(ga) − φ = λπ (line 513 at
    l = a), so φ = 2/p − λπ, and ψ = φ − 2/p (lines 593-595 as read) = −λπ; λ = 0, 1, 2."""
    p, lam = symbols("p", "lam")
    exact = {"phi": 2 / p - lam * sp.pi, "psi": -lam * sp.pi}
    return reference(exact, "(22) vertical at t = 0")


def reference_x_in_t() -> Any:
    """Line 614: x = gl/b² (line 112's l = b²x/g) with l = a + bt, b = p√(ga), γ = √(g/a)."""
    a, g, t, p = symbols("a", "g", "t", "p")
    speed = p * sp.sqrt(g * a)
    length = a + speed * t
    exact = {"l": length, "b": speed, "x": g * length / speed**2, "gamma": sp.sqrt(g / a)}
    return reference(exact, "x = gl/b², l = a + bt")
