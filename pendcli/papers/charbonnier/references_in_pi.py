"""Charbonnier (1908), n° 15, lines 486-489: the reference for I_n(π) in closed form (issue
19, helper n19).

The printed « I_n(π) = 2·(2·4…n)/(1·3·5…(n+1)) » (n even) and « π·(1·3·5…n)/(2·4·6…(n+1)) »
(n odd) are written with double factorials, ``factorial2(n)`` for 2·4…n or 1·3·5…n, under
the names of their columns (``Ipi_even``, ``Ipi_odd``). Each is judged against the integral
I_n(π) = ∫₀^π sinⁿ⁺¹x dx itself (n° 15's definition of I_n, by mpmath quadrature) at the integers
of its parity n = 0…8 (even) or 1…9 (odd): the residual's squares summed over them, which
vanishes only if every one does. sympy is imported inside the functions.
"""

from __future__ import annotations

from typing import Any

__all__ = ["reference_in_pi"]

EVEN = (0, 2, 4, 6, 8)
ODD = (1, 3, 5, 7, 9)


def reference_in_pi() -> Any:
    """I_n(π) at the even and odd n, for the two columns of lines 486-489."""
    import mpmath
    import sympy as sp

    from pendcli.core.printed_check import Reference

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
