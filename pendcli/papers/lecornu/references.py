"""Lecornu's references by name: what each ledger row's printed form is judged against.

One module per section of the memoir builds them; this one gathers their public
reference_* and numbers_* functions in the order of the text. No name is given by two sections
(tests/test_layout.py): a later table would silently replace an earlier builder.

* § I, the equation of motion (and the shortening pendulum, lines 690-698): references_motion
* § II, small oscillations, lines 118-256: references_small; its example's numbers,
  lines 206-256: references_numeric; the general solution, lines 258-380:
  references_general; its integrals, lines 382-460: references_integral; the asymptotic
  forms, lines 420-676: references_asymptotic; slow variation, lines 462-688:
  references_slow
* § III, finite oscillations, lines 699-816: references_finite; their perturbation, lines
  818-934: references_perturbed
* § IV, the conical pendulum, lines 940-1062: references_conical; its planes, lines
  1064-1135: references_conical_planes
* the judgements a sentence puts on a scale (« extrêmement faible », line 248):
  references_prose
"""

from __future__ import annotations

from pendcli.papers.lecornu import (
    references_asymptotic,
    references_conical,
    references_conical_planes,
    references_finite,
    references_general,
    references_integral,
    references_motion,
    references_numeric,
    references_perturbed,
    references_prose,
    references_slow,
    references_small,
)
from pendcli.verify.ledger_references import builders

# the sections' modules, in the order of the text
SECTIONS = (
    references_motion,
    references_small,
    references_numeric,
    references_general,
    references_integral,
    references_asymptotic,
    references_slow,
    references_finite,
    references_perturbed,
    references_conical,
    references_conical_planes,
    references_prose,
)

# every builder the sections define, by its name (verify/ledger_references.builders)
REFERENCES = builders(*SECTIONS)
