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

from pendcli.papers.lecornu.equations_general import (
    eq_17,
    eq_17_prime,
    eq_18,
    eq_19,
    eq_20,
    eq_21,
    eq_21_prime,
    eq_22,
    result_constant_a_prime,
    result_constant_c_prime,
    result_general_constants,
    result_initial_constants,
    result_integration_by_parts,
    result_limit_u_at_zero,
    result_one_vertical_between_j1_zeros,
    result_u_at_roots,
    result_xref_monotone,
)
from pendcli.papers.lecornu.equations_integral import (
    eq_18_integral,
    eq_19_integral,
    eq_20_asymptotic,
    eq_21_asymptotic,
    eq_22_asymptotic,
    eq_23,
    eq_24,
    result_amplitude_factor,
    result_c_equals_4_over_pi,
    result_elongation_condition,
    result_elongation_ratio,
    result_largest_length_comparison,
    result_oscillation_time_increase,
    result_small_x_asymptotics,
    result_vertical_to_elongation,
)
from pendcli.papers.lecornu.equations_motion import (
    eq_1,
    eq_2,
    eq_3,
    eq_4,
    eq_5,
    eq_6,
    eq_7,
    eq_8,
    eq_9,
    result_compound_expansion,
    result_compound_pendulum,
)
from pendcli.papers.lecornu.equations_slow import (
    eq_25,
    eq_26,
    eq_27,
    eq_28,
    eq_29,
    result_cr_note_formula,
    result_mean_pendulum,
    result_period_second_order,
    result_perturbation_hierarchy,
    result_psi_definition,
    result_table_26,
)
from pendcli.papers.lecornu.equations_small import (
    eq_10,
    eq_11,
    eq_12,
    eq_13,
    eq_14,
    eq_15,
    eq_16,
    result_amplitude_j0,
    result_area_theorem,
    result_curvature_proportional,
    result_eq13_is_j2,
    result_graphical_equation,
    result_inflection_at_vertical,
    result_roots_interlace,
    result_zero_length_limit,
)
from pendcli.papers.lecornu.references_early import *  # noqa: F403 (issue 19, lines 1-698)
from pendcli.papers.lecornu.references_numeric import *  # noqa: F403  (n19: lines 206-256)
from pendcli.papers.lecornu.references_small import *  # noqa: F403  (n19: lines 565-610)

__all__ = [
    "eq_1",
    "eq_2",
    "eq_3",
    "eq_4",
    "eq_5",
    "eq_6",
    "eq_7",
    "eq_8",
    "eq_9",
    "eq_10",
    "eq_11",
    "eq_12",
    "eq_13",
    "eq_14",
    "eq_15",
    "eq_16",
    "eq_17",
    "eq_17_prime",
    "eq_18",
    "eq_18_integral",
    "eq_19",
    "eq_19_integral",
    "eq_20",
    "eq_20_asymptotic",
    "eq_21",
    "eq_21_asymptotic",
    "eq_21_prime",
    "eq_22",
    "eq_22_asymptotic",
    "eq_23",
    "eq_24",
    "eq_25",
    "eq_26",
    "eq_27",
    "eq_28",
    "eq_29",
    "result_amplitude_factor",
    "result_amplitude_j0",
    "result_area_theorem",
    "result_c_equals_4_over_pi",
    "result_compound_expansion",
    "result_compound_pendulum",
    "result_constant_a_prime",
    "result_constant_c_prime",
    "result_cr_note_formula",
    "result_curvature_proportional",
    "result_elongation_condition",
    "result_elongation_ratio",
    "result_eq13_is_j2",
    "result_general_constants",
    "result_graphical_equation",
    "result_inflection_at_vertical",
    "result_initial_constants",
    "result_integration_by_parts",
    "result_largest_length_comparison",
    "result_limit_u_at_zero",
    "result_mean_pendulum",
    "result_one_vertical_between_j1_zeros",
    "result_oscillation_time_increase",
    "result_period_second_order",
    "result_perturbation_hierarchy",
    "result_psi_definition",
    "result_roots_interlace",
    "result_small_x_asymptotics",
    "result_table_26",
    "result_u_at_roots",
    "result_vertical_to_elongation",
    "result_xref_monotone",
    "result_zero_length_limit",
]
