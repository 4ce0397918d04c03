"""The sample paper's one reference: what its equation (1) is judged against."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def reference_small_period() -> Any:
    """(1) against the exact period 4K(sin²(θ0/2))√(l/g) of the pendulum released at θ0: its
    expansion in θ0 must agree with T = 2π√(l/g) through θ0⁰."""
    import sympy as sp

    from pendcli.data.printed import ledger_symbols
    from pendcli.verify.printed_check import Reference

    l, g = ledger_symbols("l", "g")  # the ledger's symbols: same names, same assumptions
    theta0 = sp.Symbol("theta0", positive=True)
    exact = 4 * sp.elliptic_k(sp.sin(theta0 / 2) ** 2) * sp.sqrt(l / g)
    return Reference(exact={"T": exact}, scale=theta0, order=1, what="the exact period")


REFERENCES: dict[str, Callable[[], Any]] = {"reference_small_period": reference_small_period}
