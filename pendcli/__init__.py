"""pendcli: regenerate the numerical claims of three historical papers on the pendulum.

The Python API (every name in ``__all__``, each documented)::

    >>> import pendcli
    >>> pendcli.integral_pi(3)            # Charbonnier's I_3(π) = ∫₀^π sin⁴ = 3π/8
    1.1780972450961724
    >>> pendcli.integral_pi_exact(3)      # 3/8 · π**1, exactly
    ExactIntegral(rational=Fraction(3, 8), pi_power=1)
    >>> pendcli.bessel_zeros(1, 2)        # Lecornu's zeros of J1
    array([3.83170597, 7.01558667])
    >>> rows = pendcli.reproduce(paper="charbonnier").claims["charbonnier"]

The functions (``help(pendcli.api)`` documents each):

    reproduce(paper=None, formulas=True, equations=False) -> ReproduceResult
        every printed number of a paper (default: all three) recomputed and judged
    check(tables=None) -> list[Drift]
        every table regenerated and compared with the committed ones (empty: all hold)
    integral_pi(n) -> float, integral_pi_exact(n) -> ExactIntegral
        Charbonnier's I_n(π), correctly rounded, and exactly (a rational times π^0 or π^1)
    bessel_zeros(order, count, method="auto") -> numpy array
        the first zeros of J_1 or J_2 (Lecornu's)
    period(amplitude, length=1.0, g=None) -> float, period_ratio(amplitude, method="agm")
        the exact period of the planar pendulum, in seconds, and its ratio T/T0

Names load on first use (PEP 562): ``import pendcli`` imports none of scipy, mpmath, sympy
or matplotlib, and ``pendcli --help`` stays instant.

Layout: :mod:`pendcli.base`, :mod:`pendcli.data`, :mod:`pendcli.verify` (printed numbers, verdicts,
published tables, the claim and formula engines, errors), :mod:`pendcli.output` (one renderer per
output format, knowing nothing of pendulums), :mod:`pendcli.numerics` (Bessel zeros, planar and
spherical pendulum done exactly), :mod:`pendcli.papers` (one package per paper: its model, claims,
formulas, figures and speed/accuracy families) and :mod:`pendcli.cli`, a thin adapter.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from pendcli.api import (
        ExactIntegral,
        bessel_zeros,
        check,
        integral_pi,
        integral_pi_exact,
        period,
        period_ratio,
        reproduce,
    )
    from pendcli.base.errors import PendcliError
    from pendcli.papers.registry import PAPERS
    from pendcli.run.regression import Drift
    from pendcli.run.reproduce import ReproduceResult

# name -> the module that defines it (imported on first access)
_LAZY = {
    "ExactIntegral": "pendcli.api",
    "bessel_zeros": "pendcli.api",
    "check": "pendcli.api",
    "integral_pi": "pendcli.api",
    "integral_pi_exact": "pendcli.api",
    "period": "pendcli.api",
    "period_ratio": "pendcli.api",
    "reproduce": "pendcli.api",
    "PAPERS": "pendcli.papers.registry",
    "PendcliError": "pendcli.base.errors",
    "Drift": "pendcli.run.regression",
    "ReproduceResult": "pendcli.run.reproduce",
}

__all__ = [
    "PAPERS",
    "Drift",
    "ExactIntegral",
    "PendcliError",
    "ReproduceResult",
    "__version__",
    "bessel_zeros",
    "check",
    "integral_pi",
    "integral_pi_exact",
    "period",
    "period_ratio",
    "reproduce",
]


def __getattr__(name: str) -> object:
    # The version has one source, pyproject.toml, read through the installed metadata.
    if name == "__version__":
        from importlib.metadata import version

        return version("pendcli")
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value  # later lookups (and doc tools reading __dict__) find it
        return value
    raise AttributeError(f"module 'pendcli' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
