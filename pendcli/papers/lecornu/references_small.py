"""Lecornu (1894), § II, lines 565-610: references for the printed forms of rows checked as
identities by the printed-form engine (issue 19, helper n19).

* lines 603-610, the table after (26): the zeros of θ (vertical positions) and of dθ/dt
  (elongations) of (26), θ = ρ(1 − ¾prt) sin rt − (ρpr²t²/4) cos rt, to the first order in
  p = b/√(ga) (r = √(g/a)), by a Newton step from the roots of sin rt and cos rt (sympy);
* line 565, the comparison with the largest length: the quarter period of the ordinary
  pendulum of the largest length of the oscillation, l = a + bt at its end (the second
  vertical position), minus the durations of its two halves from that table, to first order
  in b.

sympy is imported inside the functions (start-up stays fast).
"""

from __future__ import annotations

from functools import cache
from typing import Any

__all__ = [
    "reference_amplitude_factor",
    "reference_c_equals_4_over_pi",
    "reference_largest_length",
    "reference_table_26",
]


def _symbols(*names: str) -> Any:
    import sympy as sp

    return [sp.Symbol(n, real=True) for n in names]


@cache
def _table_26() -> dict[str, Any]:
    """The instants of the table after (26), first order in p: tv1, te1, tv2, te2, tv3."""
    import sympy as sp

    a, b, g = _symbols("a", "b", "g")
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


def reference_table_26() -> Any:
    """Lines 603-610: the zeros of θ and dθ/dt of (26), first order in p = b/√(ga)."""
    from pendcli.core.printed_check import Reference

    return Reference(_table_26(), what="the zeros of θ and θ' of (26), first order in p")


def reference_largest_length() -> Any:
    """Line 565: the quarter period (π/2)√(l/g) of the ordinary pendulum of the largest
    length of the oscillation, l = a + b·tv2 at its end (the second vertical position), less
    the duration of each half of it (te1 − tv1 ascending, tv2 − te1 descending) from the
    table after (26), to first order in b."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    a, b, g = _symbols("a", "b", "g")
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


def reference_c_equals_4_over_pi() -> Any:
    """Lines 408-412: φ = √x J₁(2√x), the series (10); C the ratio of the two limits the text
    takes at x = 0, lim φ/x over lim ∫₀^(π/2) cos(2√x cos ω) sin²ω dω (sympy)."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    x, omega = _symbols("x", "omega")
    varphi = sp.sqrt(x) * sp.besselj(1, 2 * sp.sqrt(x))
    integral = sp.integrate(sp.sin(omega) ** 2, (omega, 0, sp.pi / 2))  # the integrand at x = 0
    constant = sp.limit(varphi / x, x, 0, "+") / integral
    return Reference({"varphi": varphi, "C": constant}, what="(10) and its limit at x = 0")


def reference_amplitude_factor() -> Any:
    """Lines 569-573: θ of (22) (asymptotic), R l^(-3/4) sin((2/b)√(gl) − φ), at an
    elongation, where (24) gives the phase (2λ + 1)π/2 − 3b/(4√(gl)) (λ = 0: |θ| is the same
    for every λ). The first equality is exact (through b⁷); « en négligeant le carré de
    b/√(gl) », the second through b¹."""
    import sympy as sp

    from pendcli.core.printed_check import Reference

    big_r, length, b, g = _symbols("R", "l", "b", "g")
    phase = sp.pi / 2 - 3 * b / (4 * sp.sqrt(g * length))  # (24) with λ = 0
    theta = big_r * length ** sp.Rational(-3, 4) * sp.sin(phase)
    domain = {"b": (sp.Rational(1, 100), sp.Rational(1, 20))}  # b small against √(gl)
    return Reference(
        {"theta": theta}, scale=b, order=2, orders={"theta": 8}, domain=domain,
        what="(22) at the phase (24) of an elongation",
    )  # fmt: skip
