"""Charbonnier (1908): the references the ledger's printed forms are checked against
(``reference = "<name>"`` in tables/equations/charbonnier.toml; verify/printed_check), one
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

from pendcli.papers.charbonnier import references_general as general
from pendcli.papers.charbonnier import references_monomial as monomial
from pendcli.papers.charbonnier import references_points as points
from pendcli.papers.charbonnier import references_resisting as resisting
from pendcli.verify.ledger_references import builders

# Every builder the ledger cites, by its name there (verify/ledger_references.builders).
REFERENCES = builders(general, points, resisting, monomial)
