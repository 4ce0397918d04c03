"""Lecornu, § II, lines 420-676: the references the printed forms of the integral's tail
(lines 420-460), the asymptotic solution (20)-(24) and its passages and elongations (lines
466-563) and the slowly varying pendulum's hierarchy and mean pendulum (lines 624-676) are
judged against (verify/printed_check); the other references of lines 1-698 are kept by
the other section modules (see references.py).

Each ``reference_*`` maps ledger symbols (tables/equations/lecornu.toml [symbols]) to exact
expressions: (20) and its derivatives, the phase of (22) at a passage, an identity between
integrals judged by its derivative in a limit; never a copy of the formula the row prints.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.papers.lecornu.references_base import cited, reference, symbols, zero_start_forced


def _upper_limit_derivative(name: str, lower: Any) -> Any:
    """The transform of an identity between integrals ∫_lower^h (a function of their common
    upper limit h = ``name``): its h-derivative plus κ times its value at h = lower (κ a
    fresh symbol the random points sample): both vanish if and only if the identity holds,
    and neither needs an integral done."""
    h = sp.Symbol(name, real=True)
    kappa = sp.Symbol("kappa_aux", real=True)

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
    aa, x = symbols("aa", "x")
    eps = sp.Symbol("eps_", positive=True)
    return reference(
        {"aa": 1 / eps, "x": eps**2 * x},
        "the a-derivative, a = 1/ε, a√x fixed",
        transform=lambda residual: residual.diff(aa),
    )


@cache
def reference_small_p_series() -> Any:
    """Line 440: an identity between integrals ∫_(2a√x)^h, judged by its h-derivative (the
    integrands at p = h) and its value at h = 2a√x; the exponential's series is truncated
    as printed, so h is scaled by ε (through ε: the terms 1/p, 1, p of the integrands)."""
    aa, hh, x = symbols("aa", "hh", "x")
    eps = sp.Symbol("eps_", positive=True)
    return reference(
        {"hh": eps * hh},
        "the h-derivative and the value at h = 2a√x, h -> εh",
        transform=_upper_limit_derivative("hh", 2 * aa * sp.sqrt(x)),
    )


@cache
def reference_small_x() -> Any:
    """Lines 448-460 as x -> 0: u = C x (π/(4√x))[cos α J1(2√x) − sin α Y1(2√x)] (the
    second (18) in closed form; J1, Y1 by their series at 0, through the terms that do not
    vanish with x), θ = u/l with C = (b²/g)k (line 406); x and l scaled by ε. Each residual
    must stay finite as ε -> 0+: the parts that grow as x -> 0 (1/x, log x) must agree, a
    finite remainder (the text's « nombre fini », F) is free."""
    x, length, alpha, big_c, k, b, g = symbols("x", "l", "alpha", "C", "k", "b", "g")
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
    return reference(exact, "the second (18) in closed form, x -> εx")


@cache
def reference_quarter_power() -> Any:
    """Lines 466-499: v = x^p cos 2√x, w = x^p sin 2√x (lines 470, 490), u = Av + Bw ((20),
    « la fonction u, définie par l'équation (20) »), their derivatives by sympy, and p = 1/4,
    the exponent the text fixes at line 468 before it differentiates."""
    x, big_a, big_b = symbols("x", "A", "B")
    quarter = sp.Rational(1, 4)
    v = x**quarter * sp.cos(2 * sp.sqrt(x))
    w = x**quarter * sp.sin(2 * sp.sqrt(x))
    u = big_a * v + big_b * w
    exact = {"v": v, "w": w, "u": u, "p": quarter, "dv_dx": v.diff(x)}
    exact.update({"d2v_dx2": v.diff(x, 2), "d2w_dx2": w.diff(x, 2), "d2u_dx2": u.diff(x, 2)})
    return reference(exact, "v, w, u = Av + Bw with p = 1/4, differentiated")


def _twenty(x: Any) -> Any:
    """(20): u = A x^(1/4) cos 2√x + B x^(1/4) sin 2√x (p = 1/4, line 468)."""
    big_a, big_b = symbols("A", "B")
    root = 2 * sp.sqrt(x)
    return x ** sp.Rational(1, 4) * (big_a * sp.cos(root) + big_b * sp.sin(root))


@cache
def reference_eq21_from_20() -> Any:
    """(21): θ = u/l (line 110) with u of (20) at x = gl/b²."""
    length, b, g = symbols("l", "b", "g")
    return reference({"theta": _twenty(g * length / b**2) / length}, "(20), θ = u/l, x = gl/b²")


def _twenty_two_constants() -> dict[str, Any]:
    """A, B of (20)-(21) through the « deux nouvelles constantes » R, φ of (22):
    A cos X + B sin X = (b²/g)^(1/4) R sin(X − φ) for every X."""
    b, g, big_r, phi = symbols("b", "g", "R", "phi")
    big_a, big_b = symbols("A", "B")
    scale = (b**2 / g) ** sp.Rational(1, 4) * big_r
    return {big_a: -scale * sp.sin(phi), big_b: scale * sp.cos(phi)}


@cache
def reference_eq22_from_21() -> Any:
    """(22): (21) with A, B written through R, φ."""
    length, b, g = symbols("l", "b", "g")
    theta = _twenty(g * length / b**2) / length
    return reference({"theta": theta.subs(_twenty_two_constants())}, "(21) with A, B from R, φ")


def _phase_at(length: Any, zero: Any) -> Any:
    """φ for which (22)'s sine argument (2/b)√(gl) − φ equals ``zero`` at ``length``."""
    b, g = symbols("b", "g")
    return 2 / b * sp.sqrt(g * length) - zero


@cache
def reference_vertical_passages() -> Any:
    """(23): θ of (22) vanishes where its sine's argument is a multiple λπ of π."""
    length, lam = symbols("l", "lam")
    return reference({"phi": _phase_at(length, lam * sp.pi)}, "(22) = 0 at l: argument λπ")


@cache
def reference_next_passage() -> Any:
    """Lines 519-527: the first passage at l, its argument λπ (λ = m, line 519), l' the
    length of the next ((22) = 0 with argument (λ + 1)π); b scaled by ε (π²b²/(4gl)
    neglected), through ε."""
    length, b, g, lam = symbols("l", "b", "g", "lam")
    eps = sp.Symbol("eps_", positive=True)
    phi = _phase_at(length, lam * sp.pi)
    following = b**2 / (4 * g) * (phi + (lam + 1) * sp.pi) ** 2  # (22)'s argument (λ + 1)π
    exact = {"lp": following.subs(b, eps * b), "b": eps * b, "mm": lam}
    exact["phi"] = phi.subs(b, eps * b)
    return reference(exact, "(22) = 0 at l and l', b -> εb")


def _elongation_tangent(length: Any) -> Any:
    """tg of (22)'s argument X at an elongation: dθ/dl = R l^(-3/4)(X' cos X − 3 sin X/(4l))
    vanishes (sympy's derivative of (22), its cos X and sin X coefficients)."""
    big_r, phi = symbols("R", "phi")
    arc = sp.Symbol("X_aux", real=True)
    ell = sp.Symbol("l_aux", positive=True)
    argument = _phase_at(ell, 0) - phi
    theta = big_r * ell ** sp.Rational(-3, 4) * sp.sin(argument)
    slope = sp.expand(theta.diff(ell).subs(argument, arc))
    tangent = -slope.coeff(sp.cos(arc)) / slope.coeff(sp.sin(arc))
    return tangent.subs(ell, length)


@cache
def reference_elongation_condition() -> Any:
    """Line 535: the φ for which l is an elongation of (22): X = arctg of the tangent found."""
    (length,) = symbols("l")
    phi = _phase_at(length, sp.atan(_elongation_tangent(length)))
    return reference({"phi": phi}, "dθ/dl = 0 for θ of (22)")


@cache
def reference_elongation_arc() -> Any:
    """(24): the same arc written (2λ + 1)π/2 − arctg(1/tangent) (λ an integer), b scaled
    by ε (b/√(gl) small), through ε²."""
    length, lam, b = symbols("l", "lam", "b")
    eps = sp.Symbol("eps_", positive=True)
    arc = (2 * lam + 1) * sp.pi / 2 - sp.atan(1 / _elongation_tangent(length))
    phi = _phase_at(length, arc).subs(b, eps * b)
    return reference({"phi": phi, "b": eps * b}, "dθ/dl = 0, b -> εb")


@cache
def reference_variation_of_constants() -> Any:
    """Lines 624-634: u0 the general solution A sin γt + B cos γt of u0'' + γ²u0 = 0, and
    u1, u2 the solutions of u_n'' + γ²u_n = −γt u_(n−1)'' that start at 0 with zero slope
    (line 628), by undetermined coefficients."""
    t, gamma, big_a, big_b = symbols("t", "gamma", "A", "B")
    tau = sp.Symbol("tau_aux", real=True)  # γt: the hierarchy is then free of γ
    parts = [big_a * sp.sin(tau) + big_b * sp.cos(tau)]
    for n in (1, 2):
        forcing = sp.expand(-tau * parts[-1].diff(tau, 2))
        parts.append(zero_start_forced(forcing, tau, 2 * n))
    names = ("u0", "u1", "u2")
    exact = {name: part.subs(tau, gamma * t) for name, part in zip(names, parts, strict=True)}
    return reference(exact, "the hierarchy of (27) solved by undetermined coefficients")


@cache
def reference_mean_pendulum() -> Any:
    """Lines 666-676: t the period of (27)'s solution to p² (reference_root_epsilon, through
    p²), l = a + bt/2 the length at t/2 (line 666); the printed decimals roundings."""
    root = cited("reference_root_epsilon")
    (a,) = symbols("a")
    exact = dict(root.exact)
    exact["l"] = a + exact["b"] * exact["t"] / 2
    return reference(exact, "the root of (27)'s solution, l = a + bt/2")
