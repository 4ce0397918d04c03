"""Charbonnier's references: REFERENCES is exactly the table the ledger cites; (5) and (9) as
the engine judges them against the reference of their rows; the reference of (4), (5) against
an independent integration of θ1's equation (scipy's solve_ivp) and quadratures (mpmath)."""

from __future__ import annotations

import dataclasses

import mpmath
import pytest
from helpers.ledgers import committed_ledger, committed_row

from pendcli.papers.charbonnier.references import REFERENCES
from pendcli.papers.registry import paper
from pendcli.verify.ledger_formulas import row_formula
from pendcli.verify.ledger_references import cited_reference, verify_printed
from pendcli.verify.printed_check import judged


def test_the_table_holds_every_reference_the_ledger_cites_and_no_other() -> None:
    cited = {r.reference for r in committed_ledger("charbonnier").rows if r.reference}
    assert cited - set(REFERENCES) == set(), "cited by a row, missing from REFERENCES"
    assert set(REFERENCES) - cited == set(), "in REFERENCES, cited by no row"
    assert all(name == builder.__name__ for name, builder in REFERENCES.items())
    assert paper("charbonnier").references() == REFERENCES


def test_9_as_printed_fails_and_its_reading_holds() -> None:
    """(9) prints −ε E_c(π/2) where θ0 + εθ1 at its lowest point gives −ε E_s(π/2): the
    engine finds the printed form false and the reading true against the reference; a
    misprint, since n° 17 computes with E_s(π/2) (tables/README.md, Blame)."""
    row = committed_row("charbonnier.eq.9")
    assert row.reading_formula is not None and "E_s(pi/2)" in row.reading_formula
    computed, problem = verify_printed(
        row, committed_ledger("charbonnier").symbols_for(row), REFERENCES
    )
    assert problem is None
    assert computed is not None
    assert computed.startswith("misprint: the printed form fails (")
    assert "misprint form holds" in computed


def test_the_derivative_of_4_has_the_minus_sign_of_5() -> None:
    """(5) read with kα: θ' = kα sin kt − ε(E_s sin kt + E_c cos kt) holds against θ1 solved
    by undetermined coefficients; with + before ε it does not."""
    row = committed_row("charbonnier.eq.5")
    read = row.read("printed")  # the OCR's x read as α (the reading table)
    assert read is not None and "k*alpha*sin" in read and read.count("- epsilon*(") == 1
    symbols = committed_ledger("charbonnier").symbols_for(row)
    reference = cited_reference(paper("charbonnier"), row.reference or "", row.id)
    assert judged(row_formula(row.id, read, symbols), reference)[0]
    plus = read.replace("- epsilon*(", "+ epsilon*(")
    assert not judged(row_formula(row.id, plus, symbols), reference)[0]
    # and the engine refuses (5) printed with the sign changed
    flipped = dataclasses.replace(row, printed=plus)
    computed, _ = verify_printed(flipped, symbols, REFERENCES)
    assert computed is not None and not computed.startswith(("holds", "misprint"))


def test_the_reference_of_4_and_5_solves_theta1s_equation() -> None:
    """θ1, θ1' of reference_first_order (undetermined coefficients) against scipy's solve_ivp
    of θ1'' + k²θ1 + φ(t) = 0 from θ1(0) = θ1'(0) = 0, and its E_s(t), E_c(t) against mpmath
    quadratures of ∫₀ᵗ φ(s) sin ks ds, ∫₀ᵗ φ(s) cos ks ds; φ = p0 + p1 e^(p2 t) + p3 e^(p4 t)."""
    import numpy as np
    import sympy as sp
    from scipy.integrate import solve_ivp

    from pendcli.papers.charbonnier.references_general import free_parameters, ledger_symbols

    exact = cited_reference(paper("charbonnier"), "reference_first_order").exact
    t, k = ledger_symbols("t", "k")
    values = dict(zip((k, *free_parameters(5)), (1.3, 0.7, -0.4, 0.3, 0.25, -0.8), strict=True))
    ex = {name: exact[name].subs(values) for name in ("theta_1", "dtheta_1_dt")}
    phi = sp.lambdify(t, exact["phi"](t).subs(values), "mpmath")

    def rhs(time: float, y: np.ndarray) -> list[float]:
        return [y[1], -(1.3**2) * y[0] - float(phi(time))]

    times = [0.4, 1.1, 2.5]
    run = solve_ivp(rhs, (0, 3), [0.0, 0.0], t_eval=times, rtol=1e-12, atol=1e-14)
    for i, time in enumerate(times):
        for row, name in enumerate(("theta_1", "dtheta_1_dt")):
            assert abs(float(ex[name].subs(t, time)) - run.y[row][i]) < 1e-9, (name, time)
    with mpmath.workdps(30):
        for name, trig in (("E_s", mpmath.sin), ("E_c", mpmath.cos)):
            built = exact[name](t).subs(values)
            for time in times:
                quad = mpmath.quad(lambda s, f=trig: phi(s) * f(mpmath.mpf("1.3") * s), [0, time])
                assert abs(float(built.subs(t, time)) - quad) < 1e-12, (name, time)


@pytest.mark.parametrize("shift", ["c*cos(k*t)", "c*sin(k*t)"])
def test_a_theta1_with_wrong_initial_values_is_refused(shift: str) -> None:
    """θ1 + c cos kt and θ1 + (c/k) sin kt still solve θ1's equation; only the initial values
    tell them apart: (4) printed with that term added stops holding."""
    row = committed_row("charbonnier.eq.4")
    assert row.printed is not None and row.printed.endswith("*sin(k*t))")
    wrong = dataclasses.replace(row, printed=f"{row.printed} + epsilon*{shift}")
    symbols = committed_ledger("charbonnier").symbols_for(row)
    assert "c" in symbols  # a ledger symbol, left free by the reference: any value
    computed, problem = verify_printed(wrong, symbols, REFERENCES)
    assert problem is not None and problem.startswith("recorded holds, but the printed form")
    assert computed is not None and not computed.startswith("holds")
