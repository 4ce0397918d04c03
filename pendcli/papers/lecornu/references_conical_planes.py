"""Lecornu, § IV « Pendule conique de longueur variable », lines 1064-1135: the references
the printed forms of (47)-(52), the theorem of line 1094 (two plane pendulums, against the bob's
motion in space), the trace of the pendulum and its homothety after half a turn are judged
against (verify/printed_check).

Each ``reference_*`` maps ledger symbols (tables/equations/lecornu.toml [symbols]) to exact
expressions: the angles in the two planes from (9) and (46), the O(p) solution of (48)
solved here by undetermined coefficients, definitions; never a copy of the formula the row
prints. :func:`first_order_solution` is also § III's (line 890).
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.papers.lecornu.references_base import derivative_along, reference, symbols


@cache
def reference_primitive_angles() -> Any:
    """(47): θ = (v/l)√(bc/g), θi = (ωi/l)√(bc/g) (lines 1066-1070) with v = √(ω1² + ω2²)
    (line 1062)."""
    w1, w2, length, b, c, g = symbols("omega1", "omega2", "l", "b", "c", "g")
    big_k = sp.sqrt(b * c / g) / length
    exact = {"theta": sp.sqrt(w1**2 + w2**2) * big_k, "theta1": w1 * big_k, "theta2": w2 * big_k}
    return reference(exact, "lines 1062-1070")


def _plane_angles() -> dict[str, Any]:
    """θi = K ωi(x)/l (line 1070), K = √(bc/g), x = gl/b², l = a + bt, ωi solutions of (9)
    (xω'' + ω = 0) tied by (46); θi' and θi'' by the chain rule in t (dx/dt = g/b)."""
    a, b, g, c, t = symbols("a", "b", "g", "c", "t")
    w1, w2, dw1 = symbols("omega1", "omega2", "domega1_dx")
    length = a + b * t
    x = g * length / b**2
    dw2 = (1 + w2 * dw1) / w1  # (46) solved for ω2'
    rates = {t: 1, w1: dw1 * g / b, w2: dw2 * g / b, dw1: -w1 / x * g / b}
    rates[sp.Symbol("dw2", real=True)] = 0
    along = derivative_along(rates)
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
    return reference(_plane_angles(), "θi = √(bc/g) ωi(gl/b²)/l, (9), (46)")


@cache
def reference_polar_angle() -> Any:
    """Lines 1084-1086: θ1 = θ cos φ, θ2 = θ sin φ (φ the polar angle of (θ1, θ2)), and c
    from (49): c = l²(θ1θ2' − θ2θ1'), θ and φ varying."""
    theta, phi, dth, dphi, length = symbols("theta", "phi", "dtheta_dt", "dphi_dt", "l")
    along = derivative_along({theta: dth, phi: dphi})
    one, two = theta * sp.cos(phi), theta * sp.sin(phi)
    c = length**2 * (one * along(two) - two * along(one))
    return reference({"theta1": one, "theta2": two, "c": c}, "θ1 = θ cos φ, θ2 = θ sin φ, (49)")


@cache
def reference_small_theta() -> Any:
    """θ scaled by ε (a series in the angle): line 1088's « pour le degré d'approximation
    adopté », θ² neglected beside 1."""
    theta = sp.Symbol("theta", real=True)
    scale = sp.Symbol("epsilon", positive=True)
    return reference({"theta": scale * theta}, "θ -> εθ")


@cache
def _first_order_correction() -> Any:
    """The O(p) part of the solution of (48) in u = γt, (1 + pu)θ'' + 2pθ' + θ = 0, about
    ρ sin(u − ψ): θ1'' + θ1 = ρ(u sin(u − ψ) − 2 cos(u − ψ)), solved by the ansatz
    (a1u² + a2u) cos(u − ψ) + (b1u² + b2u) sin(u − ψ) (no free oscillation added)."""
    u, rho, psi = symbols("u", "rho", "psi")
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


def first_order_solution(rho: Any, psi: Any, u: Any) -> Any:
    """θ through O(p) of (48) in u = γt about ρ sin(u − ψ): ρ sin(u − ψ) + p θ1 with θ1
    solved here (_first_order_correction), at the given ρ, ψ, u."""
    zero, first = _first_order_correction()
    names = dict(zip(("u", "rho", "psi"), symbols("u", "rho", "psi"), strict=True))
    p = sp.Symbol("p", real=True)
    at = {names["u"]: u, names["rho"]: rho, names["psi"]: psi}
    return zero.subs(at, simultaneous=True) + p * first.subs(at, simultaneous=True)


@cache
def reference_slow_pair() -> Any:
    """(50): θi the O(p) solution of (48) about ρi sin(γt − ψi) (γ = √(g/a))."""
    t, gamma = symbols("t", "gamma")
    exact = {}
    for i in ("1", "2"):
        rho, psi = symbols(f"rho{i}", f"psi{i}")
        exact[f"theta{i}"] = first_order_solution(rho, psi, gamma * t)
    return reference(exact, "(48) to O(p)")


@cache
def reference_slow_length() -> Any:
    """l = a + bt with b = pγa (p = b/√(ga), γ = √(g/a)): a series in p."""
    a, t, gamma, p = symbols("a", "t", "gamma", "p")
    exact = {"l": a + p * gamma * a * t, "b": p * gamma * a}
    return reference(exact, "l = a + bt, b = pγa")


@cache
def reference_conical_phases() -> Any:
    """(51): c = l²(θ1θ2' − θ2θ1') from (49) with θi of (50) at t = 0 (l = a), γ = √(g/a)."""
    t, gamma, a, g = symbols("t", "gamma", "a", "g")
    pair = reference_slow_pair().exact
    one, two = pair["theta1"], pair["theta2"]
    wronskian = (one * two.diff(t) - two * one.diff(t)).subs(t, 0)
    root = sp.sqrt(g / a)
    exact = {"c": sp.expand(a**2 * wronskian).subs(gamma, root), "gamma": root}
    return reference(exact, "(49) at t = 0 with (50)")


@cache
def reference_rotated_phases() -> Any:
    """(52): the O(p) solutions about ρ1 cos u and ρ2 sin u (ψ1 = −π/2, ψ2 = 0, u = γt,
    the phases chosen at line 1110), and c from (49) at t = 0 as for (51)."""
    u, rho1, rho2, a, g = symbols("u", "rho1", "rho2", "a", "g")
    one = first_order_solution(rho1, -sp.pi / 2, u)
    two = first_order_solution(rho2, sp.Integer(0), u)
    wronskian = (one * two.diff(u) - two * one.diff(u)).subs(u, 0)  # per unit of γ
    exact = {"theta1": one, "theta2": two, "x": one, "y": two}
    exact["c"] = sp.expand(a**2 * sp.sqrt(g / a) * wronskian)
    return reference(exact, "(48) to O(p), ψ1 = −π/2, ψ2 = 0")


@cache
def reference_rotated_planes() -> Any:
    """Line 1108: the planes turned by ω; each θi = ρi sin(u − ψi) written Im(Zi e^{iu}),
    Zi = ρi e^{−iψi}: Z1' = Z1 cos ω + Z2 sin ω, Z2' = −Z1 sin ω + Z2 cos ω."""
    rho1, rho2, psi1, psi2, omega = symbols("rho1", "rho2", "psi1", "psi2", "omega")
    z1 = rho1 * (sp.cos(psi1) - sp.I * sp.sin(psi1))
    z2 = rho2 * (sp.cos(psi2) - sp.I * sp.sin(psi2))
    turned = (z1 * sp.cos(omega) + z2 * sp.sin(omega), -z1 * sp.sin(omega) + z2 * sp.cos(omega))
    exact = {}
    for i, z in zip("12", turned, strict=True):
        exact[f"rho{i}p"] = sp.Abs(z)
        exact[f"psi{i}p"] = -sp.arg(z)
    return reference(exact, "the axes turned by ω")


@cache
def reference_homothety() -> Any:
    """Lines 1128-1134: the trace (x, y) = (θ1, θ2) of (52) (as read: the O(p) solutions of
    (48) about ρ1 cos u, ρ2 sin u) lies on the ellipse of axes sρ1, sρ2 homothetic to the
    one of axes ρ1, ρ2, s = √((x/ρ1)² + (y/ρ2)²); after half a turn (u -> u + π) the ratio
    is s(u + π)/s(u). Through p."""
    u, rho1, rho2 = symbols("u", "rho1", "rho2")
    phases = reference_rotated_phases()
    one, two = phases.exact["theta1"], phases.exact["theta2"]
    size = sp.sqrt((one / rho1) ** 2 + (two / rho2) ** 2)
    exact = {"x": one, "y": two, "axis1": rho1 * size, "axis2": rho2 * size}
    exact["hom_ratio"] = size.subs(u, u + sp.pi) / size
    return reference(exact, "(48) to O(p), the ellipse through the trace")


@cache
def reference_composed_planes() -> Any:
    """Line 1094's theorem from the bob's motion in space (lines 942-946: x'' = −Tx/l,
    y'' = −Ty/l, z'' = −Tz/l + g, |r| = l = a + bt), not from (48): the angles θ1 = atan(x/z),
    θ2 = atan(y/z) of the rod's projections on the fixed vertical planes xz and yz, their
    rates along the motion (z and z' from the constraint, T from it differentiated twice:
    T l = g z + v² − b²), the horizontal state scaled by ε (small oscillations)."""
    a, b, g, t = symbols("a", "b", "g", "t")
    x, y, dx, dy = symbols("X", "Y", "dX_dt", "dY_dt")
    eps = sp.Symbol("eps_", positive=True)
    length = a + b * t
    z = sp.sqrt(length**2 - x**2 - y**2)
    dz = (length * b - x * dx - y * dy) / z
    tension = (g * z + dx**2 + dy**2 + dz**2 - b**2) / length
    along = derivative_along({t: 1, x: dx, y: dy, dx: -tension * x / length,
                              dy: -tension * y / length})  # fmt: skip
    small = {x: eps * x, y: eps * y, dx: eps * dx, dy: eps * dy}
    exact: dict[str, Any] = {"l": length}
    for name, horizontal in (("theta1", x), ("theta2", y)):
        angle = sp.atan(horizontal / z)
        rate = along(angle)
        for key, value in ((name, angle), (f"d{name}_dt", rate), (f"d2{name}_dt2", along(rate))):
            exact[key] = value.subs(small, simultaneous=True)
    what = "the bob's motion in space, the projections' angles, the horizontal state ~ ε"
    return reference(exact, what)


def reference_projection_length() -> Any:
    """Line 1096: the rod's projection on a vertical plane at the azimuth φ from it,
    l√(1 − sin²θ sin²φ), with θ small (θ -> εθ), through ε: « confondre la longueur du
    pendule avec sa projection »."""
    eps = sp.Symbol("eps_", positive=True)
    length, theta, phi = symbols("l", "theta", "phi")
    projection = length * sp.sqrt(1 - sp.sin(eps * theta) ** 2 * sp.sin(phi) ** 2)
    exact = {"lproj": projection, "theta": eps * theta}
    return reference(exact, "the projection of the rod, θ small")


def reference_rotation_angle() -> Any:
    """Line 1110: the ω that makes the new phase difference π/2, i.e. cancels
    2ρ'1ρ'2 cos(ψ'2 − ψ'1) = 2 Re(Z'1 conj Z'2) of the planes turned by ω (the model of
    reference_rotated_planes); the printed tangent of 2ω is judged as the condition
    (tan 2ω − X) = −2 Re(Z'1 conj Z'2)/((ρ1² − ρ2²) cos 2ω), the model's product normalised."""
    rho1, rho2, psi1, psi2, omega = symbols("rho1", "rho2", "psi1", "psi2", "omega")
    z1 = rho1 * (sp.cos(psi1) - sp.I * sp.sin(psi1))
    z2 = rho2 * (sp.cos(psi2) - sp.I * sp.sin(psi2))
    t1 = z1 * sp.cos(omega) + z2 * sp.sin(omega)
    t2 = -z1 * sp.sin(omega) + z2 * sp.cos(omega)
    product = sp.expand(2 * sp.re(sp.expand(t1 * sp.conjugate(t2))))
    condition = -product / ((rho1**2 - rho2**2) * sp.cos(2 * omega))
    return reference({}, "the planes turned by ω, the new phases in quadrature",
                          conditions=(condition,))  # fmt: skip
