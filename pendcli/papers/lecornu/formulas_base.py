"""What Lecornu's formula checks share: his reduced variables' sweeps and the row maker.

The checks (:mod:`pendcli.papers.lecornu.formulas`, ``formulas_chapter3``,
``formulas_conical``) compare his formulas with solve_ivp on his equations in the reduced
variables τ = γt = t√(g/a) and p = b/√(ga) (his (32)), over these sweeps of p.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from pendcli.verify.claims import FormulaRow
from pendcli.verify.formula_engine import Integrator, Study, make_row

__all__ = [
    "GRID_2PI",
    "PAPER",
    "PI",
    "P_PARAM",
    "P_PERIOD_SWEEP",
    "P_SWEEP",
    "Array",
    "Solution",
    "formula_row",
]

Array = np.ndarray
Solution = Callable[[Any], Array]  # the dense output of Integrator.solve

PAPER = "lecornu"
P_SWEEP = (0.032, 0.016, 0.008, 0.004, 0.002)  # p = b/√(ga)
# The period's residual turns out O(p⁴) with a small coefficient: larger p keep it measurable.
P_PERIOD_SWEEP = (0.1, 0.07, 0.05, 0.035, 0.025)
PI = math.pi
P_PARAM = "p = b/√(ga) = 0.032 … 0.002"
GRID_2PI = 401  # points of the grids 0 ≤ γt ≤ 2π on which residuals are maximised


def formula_row(
    id_: str, source: str, published: str, study: Study, ref: Integrator, **kw: Any
) -> FormulaRow:
    return make_row(
        id=f"{PAPER}.{id_}",
        paper=PAPER,
        source=source,
        published=published,
        study=study,
        reference=ref.label,
        **kw,
    )
