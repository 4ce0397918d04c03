"""Lecornu (1894): what the references of its section modules share (references.py lists
them). Here: sympy symbols named as the ledger's (``tables/equations/lecornu.toml``
[symbols]), the printed-form engine's Reference, φ of (10) and the second solution of (9),
√x Z₁(2√x) (Z₁ = J₁ or Y₁), the roots of the bob's path and of φ (a scan, refined by mpmath at
40 digits), the chain rule along given rates, a forced oscillator started at rest, and a
reference another module keeps, looked up in the paper's table.

scipy is imported inside the functions; sympy at the top (the table is read only to judge).
"""

from __future__ import annotations

from functools import cache
from typing import Any

import mpmath
import sympy as sp

from pendcli.data.printed import ledger_symbols as symbols
from pendcli.verify.printed_check import Reference

__all__ = [
    "cited",
    "cylinder",
    "derivative_along",
    "float40",
    "mpmath_str",
    "phi_of",
    "reference",
    "roots_of",
    "scan_roots",
    "symbols",
    "zero_start_forced",
]


def reference(exact: dict[str, Any], what: str, **kw: Any) -> Any:
    """The engine's Reference: ``exact`` values of ledger symbols, ``what`` they come from."""
    return Reference(exact, what=what, **kw)


def phi_of(x: Any, kind: str = "j") -> Any:
    """√x Z₁(2√x): Z₁ = J₁ (φ, (10)) or Y₁ (the second solution of (9))."""
    bessel = sp.besselj if kind == "j" else sp.bessely
    return sp.sqrt(x) * bessel(1, 2 * sp.sqrt(x))


def mpmath_str(value: Any) -> str:
    """An mpmath number written with 40 significant digits."""
    return mpmath.nstr(value, 40)


def float40(value: Any) -> Any:
    """An mpmath number as a sympy Float of 40 digits (a root the references substitute)."""
    return sp.Float(mpmath_str(value), 40)


def scan_roots(f: Any, coarse: Any, low: float, high: float, steps: int) -> list[Any]:
    """The roots of ``f`` (mpmath) in (low, high): a sign change of ``coarse`` (the same
    function in floats, numpy) on a grid of ``steps``, refined by a bracketing solver on
    ``f`` (mpmath, 40 digits)."""
    import numpy as np

    grid = np.linspace(low, high, steps + 1)
    values = coarse(grid)
    brackets = [(grid[k], grid[k + 1]) for k in range(steps) if values[k] * values[k + 1] < 0]
    with mpmath.workdps(40):
        return [mpmath.findroot(f, (mpmath.mpf(a), mpmath.mpf(b)), solver="anderson")
                for a, b in brackets]  # fmt: skip


def cylinder(kind: str) -> tuple[Any, Any]:
    """x -> √x Z₁(2√x) and its derivative Z₀(2√x) (Z = J, or J + Y: the path), in mpmath,
    and the pair in floats (scipy)."""
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


def roots_of(kind: str, which: str, low: float, high: float) -> list[Any]:
    """The roots in x of U (``which`` = "zero"), of h = U − xU' (the tangent through the
    point of suspension, "tangent"), of U' (the slope), for U = √x Z₁(2√x) (cylinder)."""
    exact, coarse = cylinder(kind)

    def pick(pair: tuple[Any, Any], x: Any) -> Any:
        value, slope = pair
        return {"zero": value, "tangent": value - x * slope, "slope": slope}[which]

    return scan_roots(
        lambda x: pick(exact(x), x), lambda x: pick(coarse(x), x), low, high, int(20 * high)
    )


def derivative_along(rates: dict[Any, Any]) -> Any:
    """The derivative along a motion: f -> Σ ∂f/∂s · rate(s), over the symbols of ``rates``."""

    def derivative(f: Any) -> Any:
        return sp.Add(*(sp.diff(f, s) * v for s, v in rates.items()))

    return derivative


@cache
def zero_start_forced(rhs: Any, tau: Any, degree: int, frequencies: tuple[int, ...] = (1,)) -> Any:
    """The solution of y'' + y = rhs(τ) with y(0) = y'(0) = 0, rhs a sum of polynomials in τ
    times cos mτ and sin mτ (m in ``frequencies``; products of them turned into sums, TR8):
    undetermined coefficients (a polynomial of ``degree`` on each), solved by sympy's linear
    solver (the solution is unique: no free oscillation starts at rest)."""
    from sympy.simplify.fu import TR8

    waves = [wave(m * tau) for m in frequencies for wave in (sp.cos, sp.sin)]
    unknowns: list[Any] = []
    trial = sp.Integer(0)
    for number, wave in enumerate(waves):
        coefficients = sp.symbols(f"c{number}_0:{degree + 1}")
        unknowns += coefficients
        trial += sum(c * tau**k for k, c in enumerate(coefficients)) * wave
    residual = sp.expand(TR8(sp.expand(trial.diff(tau, 2) + trial - rhs)))
    equations = [trial.subs(tau, 0), trial.diff(tau).subs(tau, 0)]
    for wave in waves:
        equations.extend(sp.Poly(residual.coeff(wave), tau).all_coeffs())
    (solution,) = sp.linsolve(equations, unknowns)
    return sp.expand(trial.subs(dict(zip(unknowns, solution, strict=True))))


def cited(name: str) -> Any:
    """The reference ``name`` of Lecornu's table (built when asked: a builder of another
    module, found by the name the ledger cites rather than by its file)."""
    from pendcli.papers.lecornu import PAPER

    assert PAPER.references is not None
    return PAPER.references()[name]()
