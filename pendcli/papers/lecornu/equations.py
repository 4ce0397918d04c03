"""Lecornu (1894): one check per checkable row of ``tables/equations/lecornu.toml``.

L. Lecornu, « Mémoire sur le pendule de longueur variable » (``tables/papers/lecornu.txt``).
Every function named ``eq_*`` or ``result_*`` is pure, takes no argument and returns an
:class:`~pendcli.core.ledger_check.EquationCheck` for the form its ledger row checks (the
printed form, or the evident reading of a misprint). Methods:

* sympy: a derivation step verified exactly (a substitution, a series to the stated order,
  a solution of a linear ODE by undetermined coefficients, a coefficient extraction);
* numeric: against an independent solution: mpmath Bessel/Struve/elliptic functions and
  quadrature, scipy ``solve_ivp`` of (3) or (32) with the observed order of the residual
  (the formula engine's :class:`~pendcli.core.formula_engine.Study` and ``judge``), or the
  existing formula checks of :mod:`pendcli.papers.lecornu.formulas`;
* cross-reference: a statement citing another formula, re-derived from the formula cited.

sympy, scipy and mpmath are imported inside the functions (start-up stays fast); the
expensive pieces are cached.
"""

from __future__ import annotations

from pendcli.papers.lecornu.equations_conical import (
    eq_43,
    eq_44,
    eq_45,
    eq_46,
    eq_47,
    eq_48,
    eq_49,
    eq_50,
    eq_51,
    eq_52,
    result_conical_general_integral,
    result_conical_linear_form,
)
from pendcli.papers.lecornu.equations_finite import (
    eq_30,
    eq_31,
    eq_32,
    eq_33,
    eq_34,
    eq_35,
    eq_37,
    eq_38,
    eq_39,
    eq_40,
    eq_41,
    eq_42,
    eq_42_prime,
    homothety_check,
    result_delta_rhs,
    result_s_expansion,
    result_t_equals_t_prime,
    result_two_beta_cos2,
)
from pendcli.papers.lecornu.references_late import *  # noqa: F403  (l19b: lines 699-1135)

__all__ = [
    "eq_30",
    "eq_31",
    "eq_32",
    "eq_33",
    "eq_34",
    "eq_35",
    "eq_37",
    "eq_38",
    "eq_39",
    "eq_40",
    "eq_41",
    "eq_42",
    "eq_42_prime",
    "eq_43",
    "eq_44",
    "eq_45",
    "eq_46",
    "eq_47",
    "eq_48",
    "eq_49",
    "eq_50",
    "eq_51",
    "eq_52",
    "homothety_check",
    "result_conical_general_integral",
    "result_conical_linear_form",
    "result_delta_rhs",
    "result_s_expansion",
    "result_t_equals_t_prime",
    "result_two_beta_cos2",
]
