"""Charbonnier (1908), part III (« Cas d'une résistance monome »), n° 14-17, and the constant
resistance of n° 13, 1°: the references of the rows of lines 376 and 429-534, for
F(v) = B_n vⁿ.

θ1 and the remarkable points come from Duhamel's integral as in part II
(:func:`.references_resisting.resisted`); I_n(x) from its definition, ∫₀^x sinⁿ⁺¹y dy, by
quadrature, never from the recurrence or the products the paper prints. The printed I_n(π) in
closed form (lines 486-489) use double factorials, ``factorial2(n)`` for 2·4…n or 1·3·5…n,
under the names of their columns (``Ipi_even``, ``Ipi_odd``), each judged against an mpmath
quadrature of I_n(π) at the integers of its parity.
"""

from __future__ import annotations

from typing import Any

import mpmath
import sympy as sp

from pendcli.papers.charbonnier.references_general import ledger_symbols
from pendcli.papers.charbonnier.references_resisting import resisted
from pendcli.verify.printed_check import Reference

# the integers at which each closed form of I_n(π) (lines 486-489) is judged
EVEN = (0, 2, 4, 6, 8)
ODD = (1, 3, 5, 7, 9)


def _monomial(phase: bool, power: Any = None) -> dict[str, Any]:
    """F(v) = B_n vⁿ, b_n = cB_n (n° 14), I_n its definition; n on the grid of halves
    floor(2n)/2, so that the powers of the random rationals stay short numbers."""
    c, n, big, k, l0 = ledger_symbols("c", "n", "B_n", "k", "l0")
    grid = sp.floor(2 * n) / 2
    v = sp.Symbol("v_", real=True)
    # |v|: v ≥ 0 on the first oscillation, and the quadrature's nodes may round past its ends
    force = sp.Lambda(v, big * sp.Abs(v) ** (grid if power is None else power))
    exact = resisted(force, phase)
    exact.update({"I": _in_definition(), "n": grid, "b_n": c * big, "b0": c * big})
    exact.update({"T": sp.pi / k, "Delta_x": exact["Delta_alpha"]})
    exact["Delta_v_m"] = l0 * exact["Delta_thetap_m"]
    return exact


# n° 13, 1°, line 376: E_c(π) = 0 and ΔT = 0 for a constant resistance (n = 0 of n° 14);
# n° 16, 1°, lines 512-518: the count P of simple oscillations until rest (n = 0)
def reference_constant_resistance() -> Reference:
    """n° 13, 1°: ΔT and E_c(π) for a constant resistance F = B_0 (E of kt), through c; n° 16:
    the count P = α/|Δα| of simple oscillations until rest."""
    exact = _monomial(phase=True, power=0)
    exact["P"] = ledger_symbols("alpha")[0] / (-exact["Delta_alpha"])
    return Reference(exact, what="F = B_0, P = α over the loss of amplitude per oscillation")


# n° 14, line 421: b_n vⁿ named the acceleration of the resistance
def reference_monomial_acceleration() -> Reference:
    """n° 14: the acceleration of the resistance along the arc, cF(v) (n° 11, line 299), for
    F(v) = B_n vⁿ (line 419), with b_n = cB_n."""
    c, big, v, n = ledger_symbols("c", "B_n", "v", "n")
    exact = {"a_arc": c * big * v**n, "b_n": c * big}
    return Reference(exact, what="cF(v) for F = B_n vⁿ")


# n° 14, lines 425-427: the corrections of the monomials added
def reference_corrections_add() -> Reference:
    """n° 14: Δα of F = B_0 + B_1v + B_2v² and the Δα of each monomial apart (Delta_x_0,
    Delta_x_1, Delta_x_2), each from Duhamel's integral (E of kt), through c."""
    b0, b1, b2 = ledger_symbols("B_0", "B_1", "B_2")
    v = sp.Symbol("v_", real=True)
    terms = (b0, b1 * sp.Abs(v), b2 * v**2)
    whole = resisted(sp.Lambda(v, sp.Add(*terms)), phase=True)["Delta_alpha"]
    exact = {"Delta_x": whole}
    for index, term in enumerate(terms):
        exact[f"Delta_x_{index}"] = resisted(sp.Lambda(v, term), phase=True)["Delta_alpha"]
    return Reference(exact, what="F = B_0 + B_1v + B_2v²")


# n° 15, 1°, lines 429-433 and 435 (E_c), 2°, lines 439-444 (E_s)
def reference_monomial() -> Reference:
    """n° 15: E_s, E_c (of the time) for F(v) = B_n vⁿ."""
    return Reference(_monomial(phase=False), what="F = B_n vⁿ")


# n° 15, 1°, line 437 (E_c(π) = 0); n° 16, lines 502-510 (Δα); n° 17, lines 530-534
# (ΔT_½, Δv_m)
def reference_monomial_points() -> Reference:
    """n° 16-17: Δα, ΔT_½, Δv_m for F(v) = B_n vⁿ (E of kt), through c."""
    return Reference(_monomial(phase=True), what="F = B_n vⁿ")


def _in_definition() -> Any:
    """I_n(x) = ∫₀^x sin^{n+1} y dy, x in [0, π] (|sin|: the nodes may round past π)."""
    y = sp.Symbol("y_", real=True)
    m, x = sp.symbols("m_ x_", real=True)
    return sp.Lambda((m, x), sp.Integral(sp.Abs(sp.sin(y)) ** (m + 1), (y, 0, x)))


# n° 15, 2°: the integration by parts, lines 452-457; the recurrence, 459-461; I_0 and
# I_(-1), 463-469; I_0(π) = 2, I_(-1)(π) = π and −cos π sinⁿπ = 0, 480-482
def reference_in() -> Reference:
    """n° 15: I_n = ∫₀^x sin^{n+1} x dx, its definition (quadrature)."""
    exact = {"I": _in_definition()}
    return Reference(exact, what="I_n's definition")


# n° 15, 2°, lines 486-489: I_n(π) in closed form, n even and n odd
def reference_in_pi() -> Reference:
    """I_n(π) at the even and odd n, for the two columns of lines 486-489: the residual's
    squares summed over the integers of the column's parity (0 only if each one is)."""
    n = sp.Symbol("n", real=True)
    columns = {sp.Symbol("Ipi_even", real=True): EVEN, sp.Symbol("Ipi_odd", real=True): ODD}

    def quadrature(k: int) -> Any:
        with mpmath.workdps(30):
            value = mpmath.quad(lambda x: mpmath.sin(x) ** (k + 1), [0, mpmath.pi])
        return sp.Float(value, 30)

    def at_the_integers(residual: Any) -> Any:
        # the column the residual is of names the integers its formula is printed for
        for name, integers in columns.items():
            if residual.has(name):
                return sp.Add(*(residual.subs({name: quadrature(k), n: k}) ** 2 for k in integers))
        return residual

    return Reference(
        {}, what="∫₀^π sinⁿ⁺¹x dx (mpmath quadrature) at n = 0…9", transform=at_the_integers
    )


# n° 16, 1°, line 512: for n = 0 the loss Δα depends on neither α nor T
def reference_friction_in_g_and_t() -> Reference:
    """n° 16, 1°: Δα for n = 0 (F = B_0) written in g and T (k = π/T, l0 = gT²/π²), so that
    its derivatives in α and in T say whether it depends on them; through c."""
    k, l0, g, big_t = ledger_symbols("k", "l0", "g", "T")
    exact = _monomial(phase=True, power=0)
    in_g_t = {k: sp.pi / big_t, l0: g * big_t**2 / sp.pi**2}
    shift = exact["Delta_alpha"].subs(in_g_t, simultaneous=True)
    return Reference({"Delta_x": shift}, what="Δα of F = B_0 in g and T")


def _monomial_case(power: Any) -> Reference:
    """Δα of F(v) = B_n vⁿ for the exponent ``power`` (n itself set to it), through c."""
    exact = _monomial(phase=True, power=power)
    exact["n"] = power
    return Reference(exact, what="F = B_n vⁿ")


# n° 16, 2°, lines 522-526: Δα with I_n(π) in closed form, n even and n odd
def reference_monomial_parity() -> Reference:
    """n° 16, 2°: the first formula (« pour n pair ») against Δα of F = B_n vⁿ for n = 0, 2, 4,
    the second (« pour n impair ») for n = 1, 3, 5 (2·floor(n) − 2 and 2·floor(n) − 1 at the
    random n in [1, 4)); Δα from Duhamel's integral, never from I_n(π)."""
    (n,) = ledger_symbols("n")
    even, odd = _monomial_case(2 * sp.floor(n) - 2), _monomial_case(2 * sp.floor(n) - 1)
    return Reference(odd.exact, what="F = B_n vⁿ, n even then n odd", cases=(even, odd))
