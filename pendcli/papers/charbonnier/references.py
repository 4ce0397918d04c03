"""Charbonnier (1908): the references the ledger's printed forms are checked against
(``reference = "<name>"`` in tables/equations/charbonnier.toml; core/printed_check), one
module per part of the paper, and :data:`REFERENCES`, the table of them the ledger reads
(``Paper.references``).

Each maps ledger symbols to exact expressions obtained without the formula the row prints:

* part I, « Établissement des formules générales »: n° 2-8 (lines 44-229) in
  :mod:`.references_general` (Newton's law for (1), the solution of (2) for (3), θ1 from its
  differential equation for a perturbation φ of a family with free parameters, solved by
  undetermined coefficients), n° 9 (lines 231-287) in :mod:`.references_points` (the
  remarkable points of θ0 + εθ1 by one Newton step in ε);
* part II, « Le mouvement du pendule dans un milieu résistant », n° 11-13 (lines 299-413), in
  :mod:`.references_resisting` (the resistance F(v), θ1 by Duhamel's integral, left to
  quadrature);
* part III, « Cas d'une résistance monome », n° 14-17 (lines 415-534), and the constant
  resistance of n° 13, 1°, in :mod:`.references_monomial` (F = B_n vⁿ; I_n(x) from its
  definition, by quadrature).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from pendcli.papers.charbonnier.references_general import (
    reference_angle_integrals,
    reference_arc_acceleration,
    reference_differentiated,
    reference_expansion,
    reference_first_order,
    reference_linear_perturbation,
    reference_linearised,
    reference_moments,
    reference_newton,
    reference_principal_motion,
    reference_principal_turn,
    reference_taylor,
    reference_theta1_equation,
    reference_variation,
)
from pendcli.papers.charbonnier.references_monomial import (
    reference_constant_resistance,
    reference_corrections_add,
    reference_friction,
    reference_friction_in_g_and_t,
    reference_in,
    reference_in_pi,
    reference_monomial,
    reference_monomial_acceleration,
    reference_monomial_parity,
    reference_monomial_points,
)
from pendcli.papers.charbonnier.references_points import (
    reference_amplitude_unchanged,
    reference_lowest_point,
    reference_period_unchanged,
    reference_remarkable_points,
    reference_sine_inverted,
    reference_turning_point,
)
from pendcli.papers.charbonnier.references_resisting import (
    reference_air,
    reference_air_points,
    reference_resistance_sense,
)

if TYPE_CHECKING:
    from collections.abc import Callable

__all__ = ["REFERENCES"]

# Every reference the ledger cites, by its name there, in the order of the paper's lines.
REFERENCES: dict[str, Callable[[], Any]] = {
    # part I, n° 2-3: the pendulum and its principal motion
    "reference_moments": reference_moments,
    "reference_newton": reference_newton,
    "reference_linearised": reference_linearised,
    "reference_principal_motion": reference_principal_motion,
    "reference_principal_turn": reference_principal_turn,
    # n° 4-7: the expansion in ε and the equation of θ1
    "reference_arc_acceleration": reference_arc_acceleration,
    "reference_expansion": reference_expansion,
    "reference_taylor": reference_taylor,
    "reference_theta1_equation": reference_theta1_equation,
    "reference_differentiated": reference_differentiated,
    "reference_variation": reference_variation,
    # n° 7-8: θ1 and the general formulas (4), (5)
    "reference_first_order": reference_first_order,
    "reference_linear_perturbation": reference_linear_perturbation,
    "reference_angle_integrals": reference_angle_integrals,
    # n° 9: the remarkable points, (6)-(9)
    "reference_turning_point": reference_turning_point,
    "reference_sine_inverted": reference_sine_inverted,
    "reference_remarkable_points": reference_remarkable_points,
    "reference_period_unchanged": reference_period_unchanged,
    "reference_amplitude_unchanged": reference_amplitude_unchanged,
    "reference_lowest_point": reference_lowest_point,
    # part II, n° 11-13: the resistance of the air
    "reference_resistance_sense": reference_resistance_sense,
    "reference_air": reference_air,
    "reference_air_points": reference_air_points,
    "reference_constant_resistance": reference_constant_resistance,
    # part III, n° 14-17: the monomial resistance and I_n
    "reference_monomial_acceleration": reference_monomial_acceleration,
    "reference_corrections_add": reference_corrections_add,
    "reference_monomial": reference_monomial,
    "reference_monomial_points": reference_monomial_points,
    "reference_in": reference_in,
    "reference_in_pi": reference_in_pi,
    "reference_friction_in_g_and_t": reference_friction_in_g_and_t,
    "reference_friction": reference_friction,
    "reference_monomial_parity": reference_monomial_parity,
}
