"""Proving a difference identically zero, cheapest exact test first.

``sympy.simplify`` is the costliest step of most equation checks (seconds on a large
residual); but a difference that vanishes as a rational function of its atoms (sin θ,
√(1 − c²), L(t), ... taken as independent letters) is proved zero by ``cancel`` alone, and
one that vanishes once sin²w = 1 − cos²w is used by a polynomial reduction, exactly and in
milliseconds; one whose value at a point allowed by its symbols' assumptions is, to 30
digits, not 0 is not identically 0 (simplify's 0 would be a wrong answer). Only what they
leave goes to ``simplify``. A zero found so is a zero
``simplify`` finds (the same exact identities), so no verdict changes; a difference that is
not zero still gets the full ``simplify``. sympy is imported lazily.
"""

from __future__ import annotations

from typing import Any


def vanishes_identically(difference: Any, expand_first: bool = False) -> bool:
    """True when ``difference`` is identically 0: ``cancel`` of its ``together`` form, the
    reduction by sin² + cos² = 1, else ``simplify`` (of the expanded form with
    ``expand_first``, else of ``difference`` as given, as the callers' checks did before)."""
    import sympy as sp

    # cancel, not expand then cancel: expanding the rational residual of Tisserand's (2)
    # first costs 1.2 s, cancelling it as it stands 0.05 s
    if sp.cancel(sp.together(difference)) == 0 or _zero_by_pythagoras(difference):
        return True
    if nonzero_at_a_point(difference):  # what simplify cannot make 0 either, in milliseconds
        return False
    return bool(sp.simplify(sp.expand(difference) if expand_first else difference) == 0)


def simplified(difference: Any) -> Any:
    """``sympy.simplify(difference)``, or 0 at once when :func:`vanishes_identically` proves
    it zero without simplify (for a check that prints the simplified difference)."""
    import sympy as sp

    if sp.cancel(sp.together(difference)) == 0 or _zero_by_pythagoras(difference):
        return sp.Integer(0)
    return sp.simplify(difference)


def _zero_by_pythagoras(difference: Any) -> bool:
    """The numerator of ``difference``, its sines and cosines of sums and multiples expanded,
    is 0 modulo sin²w + cos²w − 1 for each argument w: every sinⁿw (n ≥ 2) written
    sin^(n mod 2)w (1 − cos²w)^(n div 2), then expanded (a canonical form of a polynomial in
    sin w, cos w modulo that identity)."""
    import sympy as sp

    if not difference.has(sp.sin):
        return False
    # expand_trig first: sin 2ψ, sin(t − ψ) become polynomials in sin and cos of ψ and t
    numerator = sp.expand(sp.expand_trig(sp.numer(sp.together(difference))))
    reduced = numerator.replace(
        lambda e: e.is_Pow and isinstance(e.base, sp.sin) and e.exp.is_Integer and e.exp >= 2,
        lambda e: e.base ** (e.exp % 2) * (1 - sp.cos(e.base.args[0]) ** 2) ** (e.exp // 2),
    )
    return bool(sp.expand(reduced) == 0)


def nonzero_at_a_point(difference: Any) -> bool:
    """True when ``difference`` is provably not 0 at one point: every symbol, function value
    and derivative (independent at a point, for a function left generic) a distinct positive
    rational that its assumptions allow, and sympy's evalf (error-tracked, ``strict``) then
    not 0. False when it cannot tell (an integral or other unevaluated atom, a pole, 0)."""
    import sympy as sp
    from sympy.core.function import AppliedUndef

    if difference.has(sp.Integral, sp.Sum, sp.Piecewise, sp.Subs):
        return False
    jets = [d for d in difference.atoms(sp.Derivative) if isinstance(d.expr, AppliedUndef)]
    atoms = [*jets, *difference.atoms(AppliedUndef), *difference.free_symbols]
    point = {a: sp.Rational(7 + 3 * i, 11 + 2 * i) for i, a in enumerate(sorted(atoms, key=str))}
    if any(_disallowed(value, atom) for atom, value in point.items()):
        return False
    try:
        value = difference.xreplace(point)
        if value.free_symbols or value.has(sp.Derivative, AppliedUndef, sp.zoo, sp.nan):
            return False
        number = sp.N(value, 30, strict=True)
    except (sp.core.evalf.PrecisionExhausted, ValueError, TypeError, ZeroDivisionError):
        return False
    return bool(number.is_number and abs(number) > sp.Float(10) ** -20)


def _disallowed(value: Any, atom: Any) -> bool:
    """``value`` breaks one of ``atom``'s assumptions (an integer symbol, a negative one)."""
    facts = getattr(atom, "assumptions0", {})
    return any(getattr(value, f"is_{name}", None) is not truth for name, truth in facts.items())
