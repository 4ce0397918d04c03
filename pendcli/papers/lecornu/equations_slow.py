"""Lecornu, II (end): slow variation, (25)-(29). The study of (25) is the formula check
lecornu.eq25 (:mod:`pendcli.papers.lecornu.formulas_slow`); its residuals are taken from there
by the check of (50) (:mod:`pendcli.papers.lecornu.equations_conical`).

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

from pendcli.papers.lecornu.formulas_slow import eq25_residuals

__all__ = ["eq25_residuals"]
