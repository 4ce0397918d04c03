"""Proving a difference identically zero, cheapest exact test first.

``sympy.simplify`` is the costliest step of most equation checks (seconds on a large
residual); but a difference that vanishes as a polynomial or rational function of its atoms
(sin θ, √(1 − c²), L(t), ... taken as independent letters) is proved zero by ``cancel`` alone,
exactly and in milliseconds. Only what they leave goes to ``simplify``. A
zero found by either is a zero ``simplify`` would find (it tries ``cancel`` itself), so no
verdict changes; a difference that is not zero still gets the full ``simplify``. sympy is
imported lazily.
"""

from __future__ import annotations

from typing import Any


def vanishes_identically(difference: Any, expand_first: bool = False) -> bool:
    """True when ``difference`` is identically 0: ``cancel`` of its ``together`` form, else
    ``simplify`` (of the expanded form with ``expand_first``, else of ``difference`` as
    given, as the callers' checks did before)."""
    import sympy as sp

    # cancel, not expand then cancel: expanding the rational residual of Tisserand's (2)
    # first costs 1.2 s, cancelling it as it stands 0.05 s
    if sp.cancel(sp.together(difference)) == 0:
        return True
    return bool(sp.simplify(sp.expand(difference) if expand_first else difference) == 0)
