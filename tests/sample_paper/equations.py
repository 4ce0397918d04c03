"""The sample paper's one equation check."""

from __future__ import annotations

import math

from pendcli.core.ledger_check import EquationCheck
from pendcli.core.tables import paper_constant


def eq_1() -> EquationCheck:
    """(1): T = 2π√(l/g) is the limit of the exact period 4K(sin²(θ0/2))√(l/g) as θ0 → 0
    (scipy's complete elliptic integral, an independent computation)."""
    from scipy.special import ellipk

    scale = math.sqrt(paper_constant("sample", "length") / paper_constant("sample", "g"))
    amplitude = 1e-4  # rad: the exact period differs from (1) by θ0²/16 ≈ 6e-10
    exact = 4 * float(ellipk(math.sin(amplitude / 2) ** 2)) * scale
    rel = abs(exact - 2 * math.pi * scale) / exact
    return EquationCheck(
        holds=rel < 1e-8,
        method="numeric",
        detail=f"exact period at θ0 = 1e-4 rad against (1): relative difference {rel:.1e}",
    )
