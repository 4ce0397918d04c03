"""Charbonnier's equation checks can fail: (9) as printed is refuted, altered forms too."""

from __future__ import annotations

import sympy as sp

from pendcli.papers.charbonnier import equations as eq


def test_9_as_printed_fails_and_its_correction_is_computed() -> None:
    found = eq.eq_9()
    assert not found.holds
    assert found.corrected is not None and "E_s(π/2)" in found.corrected


def test_the_derivative_of_4_has_the_minus_sign_of_5() -> None:
    t, k, _phi, e_s, e_c, theta1 = eq.variation_of_constants()
    wrong = e_s * sp.sin(k * t) + e_c * sp.cos(k * t)
    assert sp.simplify(sp.diff(theta1, t) - wrong) != 0


def test_4_with_the_bracket_signs_swapped_does_not_solve_the_equation() -> None:
    t, k, phi, e_s, e_c, _ = eq.variation_of_constants()
    swapped = (e_c * sp.cos(k * t) - e_s * sp.sin(k * t)) / k
    residual = sp.diff(swapped, t, 2) + k**2 * swapped + phi(t)
    assert sp.simplify(residual) != 0


def test_every_check_named_in_the_ledger_exists() -> None:
    from ledgers import committed_ledger

    for row in committed_ledger("charbonnier").rows:
        if row.check is not None:
            assert callable(getattr(eq, row.check)), row.id
