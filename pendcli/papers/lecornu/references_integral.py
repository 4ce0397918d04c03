"""Lecornu (1894), § II, lines 382-460: the definite-integral solution of (9) (the second
(18), (19)), the functions v, w and the identities between integrals it rests on.

Each builder maps ledger symbols to exact expressions or states how an integral identity is
judged (by quadrature, or as a solution of (9)); never a second copy of the formula the row
prints. The § II builders of lines 424-460 (tail_expansion, small_p_series, small_x) are in
references_late.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from pendcli.papers.lecornu.references_base import reference, symbols
from pendcli.verify.printed_check import Reference


def _solves_nine(variable: str, to_x: Any = None) -> Any:
    """A transform: the printed right side F of ``variable = F`` (the residual is variable − F)
    judged as a solution of (9), x F'' + F = 0 (differentiated under ∫ by sympy); ``to_x``:
    (l, (b²/g)x) when F is θ(l), so that u = θl is tried."""
    (x,) = symbols("x")

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
    return reference({}, "(9), x u'' + u = 0", transform=_solves_nine("u"))


def reference_integral_solution() -> Any:
    """Lines 386-402: v, w as the integrals they are set to (line 388, 392), u = C(v + w sin α);
    their second derivatives in x taken under the integral sign (sympy)."""
    x, alpha, omega, big_c = symbols("x", "alpha", "omega", "C")
    half = (omega, 0, sp.pi / 2)
    v = x * sp.Integral(sp.cos(2 * sp.sqrt(x) * sp.cos(omega) + alpha) * sp.sin(omega) ** 2, half)
    w = x * sp.Integral(sp.exp(-2 * sp.sqrt(x) * sp.tan(omega)) / sp.cos(omega) ** 3, half)
    u = big_c * (v + w * sp.sin(alpha))
    exact = {"v": v, "w": w, "u": u, "d2v_dx2": v.diff(x, 2), "d2w_dx2": w.diff(x, 2)}
    exact["d2u_dx2"] = u.diff(x, 2)
    return reference(exact, "v, w of lines 388, 392, differentiated under ∫")


def reference_integral_19() -> Any:
    """(19) of line 406: θl, with l = (b²/g)x (line 112), solves (9)."""
    b, g, x, length = symbols("b", "g", "x", "l")
    transform = _solves_nine("theta", (length, b**2 / g * x))
    return reference({}, "(9) for u = θl, l = (b²/g)x", transform=transform)


def reference_c_equals_4_over_pi() -> Any:
    """Lines 408-412: φ = √x J₁(2√x), the series (10); C the ratio of the two limits the text
    takes at x = 0, lim φ/x over lim ∫₀^(π/2) cos(2√x cos ω) sin²ω dω (sympy)."""
    x, omega = symbols("x", "omega")
    varphi = sp.sqrt(x) * sp.besselj(1, 2 * sp.sqrt(x))
    integral = sp.integrate(sp.sin(omega) ** 2, (omega, 0, sp.pi / 2))  # the integrand at x = 0
    constant = sp.limit(varphi / x, x, 0, "+") / integral
    return Reference({"varphi": varphi, "C": constant}, what="(10) and its limit at x = 0")


def reference_identity() -> Any:
    """No substitution: the formula is an identity in its own symbols, judged at random points;
    lines 416-434, identities between definite integrals, by quadrature alone (a, here aa, a
    fixed number above 1; h, here hh, above 2a√x and below 3, line 442); lines 804-806,
    cos³u in cos 3u and cos u."""
    return reference({}, "an identity in its own symbols (integrals by quadrature)")


def reference_large_lambda() -> Any:
    """Line 422: (1 + λ²)^(1/2) for large λ: λ = 1/ε, through ε³."""
    eps = sp.Symbol("eps_", positive=True)
    return reference({"lam": 1 / eps}, "λ = 1/ε")
