"""The shortcuts of pendcli/papers/charbonnier/equations.py must still reject what is false."""

from __future__ import annotations

import pytest

sp = pytest.importorskip("sympy")

from pendcli.papers.charbonnier import equations as eq  # noqa: E402


def test_eq_4_holds() -> None:
    assert eq.eq_4().holds


def test_eq_4_rejects_a_solution_with_wrong_initial_values(monkeypatch) -> None:
    """θ1 + c cos kt still solves the ODE; only the initial values, whose integrals over
    [0, 0] eq_4 evaluates at once, tell it apart."""
    t, k, phi, e_s, e_c, theta1 = eq.variation_of_constants()
    c = sp.Symbol("c", positive=True)
    wrong = (t, k, phi, e_s, e_c, theta1 + c * sp.cos(k * t))
    monkeypatch.setattr(eq, "variation_of_constants", lambda: wrong)
    assert not eq.eq_4().holds


def test_theta1_for_a_constant_force_by_sympy_integrate() -> None:
    """Independent of the generic φ: for φ = 1, θ1 = (cos kt − 1)/k², by sympy's integrate."""
    t, k, phi, *_, theta1 = eq.variation_of_constants()
    concrete = theta1.replace(phi, sp.Lambda(sp.Symbol("u"), 1)).doit()
    assert sp.simplify(concrete - (sp.cos(k * t) - 1) / k**2) == 0
    assert concrete.subs(t, 0) == 0 and sp.diff(concrete, t).subs(t, 0) == 0
