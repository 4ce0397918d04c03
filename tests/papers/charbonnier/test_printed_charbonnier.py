"""Charbonnier's ledger bound to its text: every status with a reference computed from the
printed form; a changed coefficient stops every row that holds holding; a misprint whose
printed form is its reading is refused; the slips found are verified by an independent
numeric method (mpmath quadrature, an ODE)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import mpmath
import pytest
from helpers.ledgers import committed_ledger, committed_row, row_ids
from helpers.mutations import altered_row

from pendcli.data.ledger_coverage import ledger_text_coverage
from pendcli.data.ledger_rows import LedgerRow
from pendcli.papers.registry import paper
from pendcli.verify.ledger_formulas import row_formula
from pendcli.verify.ledger_references import cited_reference, verify_printed

ROOT = Path(__file__).resolve().parents[3]
TABLES = ROOT / "tables"
# reference name -> builder, as the ledger reads them (Paper.references)
REFERENCES = paper("charbonnier").references()


def test_every_block_is_covered_and_every_formula_row_has_a_reference() -> None:
    coverage = ledger_text_coverage("charbonnier")
    assert (coverage.blocks, coverage.covered) == (86, 86)
    rows = committed_ledger("charbonnier").rows
    checked = [r for r in rows if r.status in ("holds", "misprint", "fails") and r.printed]
    assert all(r.reference for r in checked), [r.id for r in checked if not r.reference]
    for row in rows:
        if row.status in ("misprint", "fails"):
            assert row.wrong_term, row.id
            lines = (TABLES / "papers" / "charbonnier.txt").read_text("utf-8").splitlines()
            assert row.lines is not None
            span = "\n".join(lines[row.lines[0] - 1 : row.lines[1]])
            assert all(t in span for t in row.wrong_terms), f"{row.id}: {row.wrong_term!r}"


def _altered(row_id: str, old: str, new: str) -> tuple[LedgerRow, dict[str, str]]:
    """Row ``row_id`` with one edit within its own [[equation]] block
    (tests/helpers/mutations.py)."""
    return altered_row("charbonnier", row_id, old, new, within=row_id)


# (row, old, new): one coefficient, sign or argument of a numbered formula or a result
CHANGES = [
    ("charbonnier.eq.1", "2/l*dl_dt", "3/l*dl_dt"),  # the Coriolis term of (1)
    ("charbonnier.eq.1", "g*l*sin(theta) = 0;", "g*sin(theta) = 0;"),  # the moment
    ("charbonnier.eq.2", "k**2 = g/l0", "k**2 = g/(2*l0)"),
    ("charbonnier.eq.3", "dtheta_dt = k*alpha*sin(k*t)", "dtheta_dt = alpha*sin(k*t)"),
    # the cross-references of lines 74 and 91 (the reading record)
    ("charbonnier.result.formula-1-reduces-to-2", "k**2 = g/l0", "k**2 = g/(2*l0)"),
    ("charbonnier.result.integrating-2", "theta = -alpha*cos", "theta = alpha*cos"),
    ("charbonnier.result.period-and-top-speed", "T = pi/k", "T = 2*pi/k"),
    ("charbonnier.result.taylor-phi", "dtheta_1_dt*phi_thetap", "dtheta_1_dt*phi_theta"),
    ("charbonnier.result.order-system", "d2theta_2_dt2 + k**2", "d2theta_2_dt2 + 2*k**2"),
    ("charbonnier.result.principal-motion", "thetap_m = k*alpha", "thetap_m = k**2*alpha"),
    ("charbonnier.eq.q", "+ phi(t)/k = 0", "- phi(t)/k = 0"),
    ("charbonnier.result.variation-integrals", "N = -1/k", "N = 1/k"),
    ("charbonnier.result.theta1-solution", "k*theta_1 =", "theta_1 ="),
    # (4) with the integrals of its bracket swapped
    ("charbonnier.eq.4", "E_s(t)*cos(k*t) - E_c(t)*sin(k*t)", "E_c(t)*cos(k*t) - E_s(t)*sin(k*t)"),
    ("charbonnier.result.turning-time", "k*t = pi + epsilon", "k*t = pi - epsilon"),
    ("charbonnier.eq.6", "epsilon/(k**2*alpha)", "epsilon/(k*alpha)"),
    ("charbonnier.eq.7", "= -epsilon/k*E_s(pi)", "= epsilon/k*E_s(pi)"),
    ("charbonnier.eq.8", "E_c(pi/2)", "E_s(pi/2)"),
    ("charbonnier.result.arc-integrals", "1/(k**2*alpha*l0)*S(nu)", "1/(k*alpha*l0)*S(nu)"),
    ("charbonnier.result.es-in-speed", "1/k*1/(k*alpha*l0)**2", "1/(k*alpha*l0)**2"),
    ("charbonnier.result.period-unchanged", "E_c(pi) = 0", "E_s(pi) = 0"),
    ("charbonnier.result.height", "g*Delta_y = -tau", "g*Delta_y = tau"),
    ("charbonnier.result.recurrence", "n*I(n - 2, x)", "(n - 1)*I(n - 2, x)"),
    # the rows that hold read through the OCR's x for α (and λ for k): the reading table
    ("charbonnier.eq.5", "= k*x*sin(k*t) - epsilon", "= 2*k*x*sin(k*t) - epsilon"),
    ("charbonnier.result.general-solution", "dtheta_dt = k*x*sin(k*t)", "dtheta_dt = x*sin(k*t)"),
    ("charbonnier.result.turning-time-repeated", "lam*t = pi + epsilon", "lam*t = pi - epsilon"),
    ("charbonnier.result.ec-integral", "(x*l0)**n*k**(n - 1)", "(x*l0)**n*k**n"),
    ("charbonnier.result.es-integral", "k**(n - 1)*(x**n", "k**(n - 2)*(x**n"),
    ("charbonnier.result.friction-count", "P = x/2*g/b0", "P = x/3*g/b0"),
    ("charbonnier.result.delta-alpha-closed", "(x*g*T/pi)**n*2*", "(x*g*T/pi)**n*3*"),
    ("charbonnier.result.delta-alpha-closed", "(x*g*T/pi)**n*pi", "(x*g*T/pi)**n*2"),
    ("charbonnier.result.lowest-point", "*k**(n - 3)", "*k**(n - 2)"),
    ("charbonnier.result.in-pi", "Ipi_even = 2*", "Ipi_even = pi*"),
    ("charbonnier.result.delta-alpha", "k**(n - 2)", "k**(n - 1)"),
]


@pytest.mark.parametrize(("row_id", "old", "new"), CHANGES)
def test_a_changed_coefficient_stops_a_row_holding(row_id: str, old: str, new: str) -> None:
    row, symbols = _altered(row_id, old, new)
    computed, problem = verify_printed(row, symbols, REFERENCES)
    assert problem is not None and problem.startswith("recorded holds, but the printed form")
    assert computed is not None and not computed.startswith("holds")


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        ("charbonnier.eq.9", "-epsilon*E_c(pi/2)'", "-epsilon*E_s(pi/2)'"),
        ("charbonnier.result.ec-monomial", "*k**(n + 1)*x**n", "*k**(n - 1)*x**n"),
        (
            "charbonnier.result.integration-by-parts",
            "n*Integral(cos(x)*sin(x)**(n - 1)",
            "n*Integral(cos(x)**2*sin(x)**(n - 1)",
        ),
        ("charbonnier.result.lowest-speed-air", "*E(pi/2)'", "*E_s(pi/2)'"),
    ],
)
def test_a_misprint_whose_printed_form_is_its_reading_is_refused(
    row_id: str, old: str, new: str
) -> None:
    row, symbols = _altered(row_id, old, new)
    _, problem = verify_printed(row, symbols, REFERENCES)
    assert problem is not None
    assert problem.startswith("recorded misprint, but the printed form gives holds")


def test_n13_with_the_e_c_of_9_as_printed_fails_too() -> None:
    """(9) corrected carried to n° 13: with E_c(π/2), (9) as printed, the printed form fails
    and only the E_s reading holds."""
    old, new = "-c/l0*E(pi/2)'", "-c/l0*E_c(pi/2)'"
    row, symbols = _altered("charbonnier.result.lowest-speed-air", old, new)
    computed, problem = verify_printed(row, symbols, REFERENCES)
    assert problem is None
    assert computed is not None and computed.startswith("misprint: the printed form fails")


# --- the slips, verified by a second, numeric method -------------------------------------


def test_the_integration_by_parts_needs_cos_squared() -> None:
    """n° 15, line 455: I_n = −cos x sinⁿx + n∫cos x sin^(n−1)x dx is false (n = 2, 3, x = 1),
    with cos² x it holds (mpmath quadrature)."""
    with mpmath.workdps(30):
        for n in (2, 3):
            x = mpmath.mpf(1)
            i_n = mpmath.quad(lambda y, m=n: mpmath.sin(y) ** (m + 1), [0, x])
            head = -mpmath.cos(x) * mpmath.sin(x) ** n
            printed = head + n * mpmath.quad(
                lambda y, m=n: mpmath.cos(y) * mpmath.sin(y) ** (m - 1), [0, x]
            )
            read = head + n * mpmath.quad(
                lambda y, m=n: mpmath.cos(y) ** 2 * mpmath.sin(y) ** (m - 1), [0, x]
            )
            assert abs(read - i_n) < mpmath.mpf(10) ** -25
            assert abs(printed - i_n) > mpmath.mpf(10) ** -2


def test_e_c_is_an_integral_in_the_angular_speed() -> None:
    """n° 8, line 229: E_c(t) = ∫₀ᵗ φ cos ks ds equals (1/(k²α))∫₀^θ' φ dθ' (θ' = kα sin ks on
    the first quarter), not (1/(k²α))∫₀^θ φ dθ'; φ(s) = 1 + s², k = 1.3, α = 0.4, t = 0.7."""
    k, alpha, t = mpmath.mpf("1.3"), mpmath.mpf("0.4"), mpmath.mpf("0.7")
    phi = lambda s: 1 + s**2  # noqa: E731
    e_c = mpmath.quad(lambda s: phi(s) * mpmath.cos(k * s), [0, t])
    time_at = lambda w: mpmath.asin(w / (k * alpha)) / k  # noqa: E731
    speed = k * alpha * mpmath.sin(k * t)
    angle = -alpha * mpmath.cos(k * t)
    read = mpmath.quad(lambda w: phi(time_at(w)), [0, speed]) / (k**2 * alpha)
    # the printed upper limit, the angle θ (negative on the first quarter), in place of θ'
    printed = mpmath.quad(lambda w: phi(time_at(w)), [0, angle]) / (k**2 * alpha)
    assert abs(read - e_c) < 1e-12
    assert abs(printed - e_c) > 0.1 * abs(e_c)


def test_the_speed_at_the_lowest_point_is_e_s_by_the_ode() -> None:
    """(9) and n° 13, 3°: integrate θ'' + k²θ + (c/l0)F(l0θ') = 0 (F = v², scipy, tight
    tolerances) to the lowest point θ = 0; (θ' − kα)/(c/l0) there is −E_s(π/2), not −E_c(π/2)."""
    import numpy as np
    from scipy.integrate import quad, solve_ivp

    k, alpha, l0, c = 1.0, 0.2, 1.0, 1e-5
    force = lambda v: v * v  # noqa: E731
    phi = lambda s: force(k * alpha * l0 * np.sin(k * s))  # noqa: E731

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        return [y[1], -(k**2) * y[0] - c / l0 * force(l0 * y[1])]

    lowest = lambda _t, y: y[0]  # noqa: E731
    lowest.terminal, lowest.direction = True, 1  # type: ignore[attr-defined]
    run = solve_ivp(rhs, (0, 10), [-alpha, 0.0], rtol=1e-12, atol=1e-14, events=lowest)
    shift = (run.y_events[0][0][1] - k * alpha) / (c / l0)
    e_s = quad(lambda s: phi(s) * np.sin(k * s), 0, np.pi / (2 * k), epsabs=1e-14)[0]
    e_c = quad(lambda s: phi(s) * np.cos(k * s), 0, np.pi / (2 * k), epsabs=1e-14)[0]
    assert abs(shift + e_s) < 1e-3 * e_s
    assert abs(shift + e_c) > 0.1 * e_c


# --- the rows of the prose and of the remarks between the numbered formulas ---------------
# (row, old, new): one coefficient, sign, argument or relation of what the row prints

PROSE_CHANGES = [
    ("charbonnier.result.sine-to-arc", "= theta + ...", "= 2*theta + ..."),
    ("charbonnier.result.rise-equals-descent", "theta = alpha", "theta = -alpha"),
    (
        "charbonnier.result.expanded-equation",
        "+ epsilon*k**2*theta_1 +",
        "+ 2*epsilon*k**2*theta_1 +",
    ),
    (
        "charbonnier.result.theta1-equation-principal",
        "k*alpha*sin(k*t), t)",
        "2*k*alpha*sin(k*t), t)",
    ),
    ("charbonnier.result.theta1-derivative", "-k*M*sin(k*t)", "k*M*sin(k*t)"),
    ("charbonnier.result.turning-time-inversion", "pi + epsilon", "pi + 2*epsilon"),
    ("charbonnier.result.period-condition", "E_c(pi)", "E_c(pi/2)"),
    ("charbonnier.result.amplitude", "alpha - epsilon/k", "alpha - 2*epsilon/k"),
    ("charbonnier.result.amplitude-condition", "E_s(pi)", "E_s(pi/2)"),
    ("charbonnier.result.lowest-time", "k*t = pi/2 + epsilon", "k*t = pi/2 - epsilon"),
    ("charbonnier.result.resisted-motion", "c/(l0*k)*", "2*c/(l0*k)*"),
    (
        "charbonnier.result.resisted-integrals",
        "F(k*alpha*l0*sin(k*t))*sin(k*t)",
        "F(2*k*alpha*l0*sin(k*t))*sin(k*t)",
    ),
    ("charbonnier.result.speed", "dnu_dt = k**2*alpha", "dnu_dt = k*alpha"),
    ("charbonnier.result.amplitude-air", "-c/(k*l0)", "-c/(k**2*l0)"),
    ("charbonnier.result.work-total", "= -tau/", "= tau/"),
    ("charbonnier.result.lowest-air", "c/(k**4*alpha**2", "c/(k**3*alpha**2"),
    ("charbonnier.result.i0-i-1", "= 1 - cos(x)", "= 2 - cos(x)"),
    ("charbonnier.result.i-at-pi", "I(-1, pi) = pi", "I(-1, pi) = pi/2"),
    ("charbonnier.result.work-positive", "E_s(t) > 0", "E_s(t) < 0"),
    ("charbonnier.result.es-symmetry", "= 2*E_s(pi/2)", "= 3*E_s(pi/2)"),
    ("charbonnier.result.es-symmetry", "E_s(pi) > 0", "E_s(pi) < 0"),
    ("charbonnier.result.period-constant-resistance", "E_c(pi)", "E_c(pi/2)"),
    ("charbonnier.result.lowest-air-signs", "Delta_T_half > 0", "Delta_T_half < 0"),
    ("charbonnier.result.lowest-air-signs", "Delta_thetap_m < 0", "Delta_thetap_m > 0"),
    ("charbonnier.result.ec-pi-monomial", "E_c(pi)", "E_c(pi/2)"),
    ("charbonnier.result.friction-independent", "Delta_x, alpha", "Delta_x, g"),
    ("charbonnier.result.infinite-count", "<= 0", ">= 0"),
    ("charbonnier.result.infinite-count", "1 + Delta_x/alpha > 0", "1 + Delta_x/alpha < 0"),
    # the claims of the sentences of lines 54-500
    # (tests/papers/charbonnier/test_prose_charbonnier.py: the slips)
    ("charbonnier.result.moment-of-velocity", "h_M = l**2*dtheta_dt", "h_M = l*dtheta_dt"),
    ("charbonnier.result.moment-of-weight", "g*l*sin(theta)", "g*l*cos(theta)"),
    ("charbonnier.result.es-pi-nonzero", "E_s(pi) > 0", "E_s(pi) < 0"),
    ("charbonnier.result.monomial-acceleration", "b_n*v**n", "b_n*v**(n + 1)"),
    ("charbonnier.result.corrections-add", "+ Delta_x_2'", "+ 2*Delta_x_2'"),
    ("charbonnier.result.recurrence-table-even", "5*I(4, x) = ", "4*I(4, x) = "),
    ("charbonnier.result.recurrence-table-odd", "4*I(3, x) = ", "3*I(3, x) = "),
    ("charbonnier.result.in-pi-table", "2*2*4/(1*3*5)", "2*2*4/(1*3*7)"),
    ("charbonnier.result.diminution-of-amplitude", "Delta_x < 0", "Delta_x > 0"),
]


@pytest.mark.parametrize(("row_id", "old", "new"), PROSE_CHANGES)
def test_a_changed_coefficient_stops_a_prose_row_holding(row_id: str, old: str, new: str) -> None:
    row, symbols = _altered(row_id, old, new)
    computed, problem = verify_printed(row, symbols, REFERENCES)
    assert problem is not None and problem.startswith("recorded holds, but the printed form")
    assert computed is not None and not computed.startswith("holds")


def test_every_holds_row_has_a_mutation() -> None:
    """The engine's verdict is every row's status: each row that holds is edited by one case
    of the two lists of changed coefficients above, which it must then refuse."""
    holds = {r.id for r in committed_ledger("charbonnier").rows if r.status == "holds"}
    mutated = {row_id for row_id, _, _ in (*CHANGES, *PROSE_CHANGES)}
    assert holds - mutated == set()


def _misprint_ids() -> list[str]:
    return row_ids("charbonnier", lambda e: e.get("status") == "misprint" and "reference" in e)


@pytest.mark.parametrize("row_id", _misprint_ids())
def test_every_misprint_printed_as_its_reading_is_refused(row_id: str) -> None:
    row = committed_row(row_id)
    symbols = dict(committed_ledger("charbonnier").symbols)
    read = dataclasses.replace(row, printed=row.reading_formula)
    _, problem = verify_printed(read, symbols, REFERENCES)
    assert problem is not None
    assert problem.startswith("recorded misprint, but the printed form gives holds"), problem


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        ("charbonnier.result.e-angle-integrals", "(thetap, 0, thetap)", "(thetap, 0, 2*thetap)"),
        ("charbonnier.eq.9", "-epsilon*E_s(pi/2)", "-2*epsilon*E_s(pi/2)"),
        ("charbonnier.result.ec-monomial", "k**(n - 1)*alpha**n", "k**n*alpha**n"),
    ],
)
def test_a_changed_coefficient_of_a_reading_is_refused(row_id: str, old: str, new: str) -> None:
    row, symbols = _altered(row_id, old, new)
    _, problem = verify_printed(row, symbols, REFERENCES)
    assert problem is not None and problem.startswith("recorded misprint, but the printed form")


def test_the_closed_forms_are_judged_per_parity() -> None:
    """n° 16, 2°: the even formula is wrong for odd n and the odd one for even n (I_1(π) =
    π/2 against the even rule's 2·1/2 = 1), so a parity-blind reference would refuse them."""
    from pendcli.verify.printed_check import formula_passes

    ledger = committed_ledger("charbonnier")
    row = next(r for r in ledger.rows if r.id == "charbonnier.result.delta-alpha-closed")
    assert row.printed is not None and "x*g*T" in row.printed  # the OCR's x, read as α
    read = row_formula(row.id, row.read("printed") or "", dict(ledger.symbols))
    both = cited_reference(paper("charbonnier"), "reference_monomial_parity")
    assert formula_passes(read, both)[0]
    swapped = dataclasses.replace(both, cases=both.cases[::-1])
    assert not formula_passes(read, swapped)[0]


def test_friction_has_a_finite_count_by_the_same_formula() -> None:
    """n° 16, 1°: the formula that says P is infinite for n ≥ 1 fails for n = 0 (F = B_0),
    where Δα/α = −2b0/(gα) grows as α falls and P = αg/(2b0) is finite."""
    from pendcli.verify.printed_check import formula_passes

    ledger = committed_ledger("charbonnier")
    row = next(r for r in ledger.rows if r.id == "charbonnier.result.infinite-count")
    assert row.printed is not None
    printed = row_formula(row.id, row.printed, dict(ledger.symbols))
    charbonnier = paper("charbonnier")
    assert formula_passes(
        printed, cited_reference(charbonnier, "reference_monomial_points", row.id)
    )[0]
    friction = "charbonnier.result.friction-count"
    constant = cited_reference(charbonnier, "reference_constant_resistance", friction)
    assert not formula_passes(printed, constant)[0]


def test_the_closed_forms_against_an_ode() -> None:
    """n° 16, 2° by a second, numeric method: θ'' + k²θ + (c/l0)B_n(l0θ')ⁿ = 0 integrated over
    one simple oscillation (scipy, tight tolerances; θ' > 0 there); the loss of amplitude over
    c against −(b_n/g)(αgT/π)ⁿ times 2·(2·4…n)/(1·3·5…(n+1)) (n even) or
    π·(1·3·5…n)/(2·4·6…(n+1)) (n odd), for n = 0..4."""
    import math

    import numpy as np
    from scipy.integrate import solve_ivp

    k, alpha, l0, c, big = 1.1, 0.3, 1.0, 1e-6, 1.0
    g, period = k * k * l0, math.pi / k
    for n in range(5):

        def rhs(_t: float, y: np.ndarray, m: int = n) -> list[float]:
            return [y[1], -(k**2) * y[0] - c / l0 * big * (l0 * max(y[1], 0.0)) ** m]

        stop = lambda _t, y: y[1]  # noqa: E731
        stop.terminal, stop.direction = True, -1  # type: ignore[attr-defined]
        run = solve_ivp(rhs, (0, 10), [-alpha, 0.0], rtol=1e-12, atol=1e-15, events=stop)
        shift = (run.y_events[0][0][0] - alpha) / c
        top = math.prod(range(1 if n % 2 else 2, n + 1, 2))
        bottom = math.prod(range(2 if n % 2 else 1, n + 2, 2))
        closed = -(big / g) * (alpha * g * period / math.pi) ** n * (math.pi if n % 2 else 2)
        closed *= top / bottom
        assert abs(shift - closed) < 1e-3 * abs(closed), (n, shift, closed)
