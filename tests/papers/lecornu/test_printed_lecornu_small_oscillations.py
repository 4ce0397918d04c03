"""Lecornu, lines 1-698: each status computed from the printed form against its reference
(the section tables of pendcli/papers/lecornu/references_*.py) is the recorded one, and an
edit of a printed form (one coefficient, or a misprint set to its reading) is refused, naming
the row; the references and the formula checks that measure § II's orders agree with an
independent computation (mpmath, scipy, the exact Bessel solution of (9))."""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from functools import cache
from pathlib import Path
from types import MappingProxyType
from typing import Any

import pytest
from helpers.ledgers import committed_ledger, committed_row
from helpers.mutations import altered_ledger

from pendcli.data.ledger_rows import Ledger, LedgerRow
from pendcli.data.printed import Formula, parse_formula
from pendcli.papers.lecornu import (
    references,
)
from pendcli.papers.lecornu.formulas_slow import slow_row, slow_rows
from pendcli.papers.registry import paper
from pendcli.verify.claims import FormulaRow
from pendcli.verify.ledger_references import builders, cited_reference, verify_printed
from pendcli.verify.printed_check import judged
from pendcli.verify.printed_verdict import computed_status

ROOT = Path(__file__).resolve().parents[3]
TABLES = ROOT / "tables"
LAST_LINE = 698
REFERENCES = paper("lecornu").references()


def _early_rows() -> list[LedgerRow]:
    return [r for r in committed_ledger("lecornu").rows if r.lines and r.lines[0] <= LAST_LINE]


def test_each_section_table_gives_its_builders_to_the_paper_and_each_is_cited() -> None:
    """Every builder of every section module is the paper's, under its own name, and cited by
    a row of the ledger (no dead reference); that no name is in two modules is test_layout's."""
    cited = {r.reference for r in committed_ledger("lecornu").rows if r.reference}
    for module in references.SECTIONS:
        for name, builder in builders(module).items():
            assert REFERENCES[name] is builder is getattr(module, name), name
            assert name in cited, name


def _altered(old: str, new: str) -> tuple[dict[str, LedgerRow], dict[str, str]]:
    """The rows of the ledger with one edit (tests/helpers/mutations.py), and its [symbols]."""
    ledger = altered_ledger("lecornu", old, new)
    return {r.id: r for r in ledger.rows}, dict(ledger.symbols)


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        # (5): 2 dθ/dl -> 3 dθ/dl
        (
            "lecornu.eq.5",
            "'l*d2theta_dl2 + 2*dtheta_dl + g/b**2*sin(theta) = 0'",
            "'l*d2theta_dl2 + 3*dtheta_dl + g/b**2*sin(theta) = 0'",
        ),
        # (2): the centrifugal term l θ'² -> 2 l θ'²
        ("lecornu.eq.2", "+ l*dtheta_dt**2 - d2l_dt2", "+ 2*l*dtheta_dt**2 - d2l_dt2"),
        # (17): B φ ∫ -> 2 B φ ∫
        ("lecornu.eq.17", "u = A*varphi + B*varphi*Integral", "u = A*varphi + 2*B*varphi*Integral"),
        # (21): −B/φ' -> +B/φ'
        (
            "lecornu.eq.21",
            "'u = C*varphi - B/dvarphi_dx",
            "'u = C*varphi + B/dvarphi_dx",
        ),
        # (10): 3x³/(1·2·3)² -> 4x³/(1·2·3)²
        ("lecornu.eq.10", "+ 3*x**3/(1*2*3)**2", "+ 4*x**3/(1*2*3)**2"),
        # (25): ¾ pγt -> ½ pγt
        (
            "lecornu.eq.25",
            "'theta = rho*(1 - 3/4*p*r*t)*sin(gamma*t - psi)",
            "'theta = rho*(1 - 1/2*p*r*t)*sin(gamma*t - psi)",
        ),
        # (30): 2 dθ/dz -> dθ/dz
        ("lecornu.eq.30", "+ 2*dtheta_dzt +", "+ dtheta_dzt +"),
        # line 555: −3b/(4g) -> −5b/(4g)
        (
            "lecornu.result.quarter_time",
            "- 3*b/(4*g) + pi**2*b/(16*g)'",
            "- 5*b/(4*g) + pi**2*b/(16*g)'",
        ),
        # line 656: 3pπ/8 -> 5pπ/8 in the final ε
        ("lecornu.result.epsilon_steps", "= p/4*(pi**2 + 3*p*pi/8)'", "= p/4*(pi**2 + 5*p*pi/8)'"),
    ],
)
def test_a_changed_coefficient_is_refused(row_id: str, old: str, new: str) -> None:
    rows, symbols = _altered(old, new)
    computed, problem = verify_printed(rows[row_id], symbols, REFERENCES)
    assert problem is not None and problem.startswith(f"recorded {rows[row_id].status}, but")
    assert computed is not None and not computed.startswith(rows[row_id].status)


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        # (28) printed with its reading's 2γ³t³
        ("lecornu.eq.28", "(2*gamma**2*t**3 - 3*gamma*t)", "(2*gamma**3*t**3 - 3*gamma*t)"),
        # ψ defined as the reading φ − 2/p
        (
            "lecornu.result.psi_definition",
            "printed = 'psi = 2/p - phi'",
            "printed = 'psi = phi - 2/p'",
        ),
        # the integration by parts with φ'' in its first integrand
        (
            "lecornu.result.integration_by_parts",
            "- Integral(dvarphi_dx/(varphi*dvarphi_dx**2), (x, x0, x))",
            "- Integral(d2varphi_dx2/(varphi*dvarphi_dx**2), (x, x0, x))",
        ),
    ],
)
def test_a_misprint_printed_as_its_reading_is_refused(row_id: str, old: str, new: str) -> None:
    rows, symbols = _altered(old, new)
    _, problem = verify_printed(rows[row_id], symbols, REFERENCES)
    assert problem is not None
    assert problem.startswith("recorded misprint, but the printed form gives holds")


def test_an_incomplete_correction_of_the_general_rule_is_refused() -> None:
    """The general rule's correction without the switch point's + 1/(φ1φ'1) term fails."""
    old = "Integral(varphi**(-2), (x, x0, x1)) + 1/(varphi1*varphip1) - 1/(varphik*varphipk)"
    new = "Integral(varphi**(-2), (x, x0, x1)) - 1/(varphik*varphipk)"
    rows, symbols = _altered(old, new)
    _, problem = verify_printed(rows["lecornu.result.general_constants"], symbols, REFERENCES)
    assert problem is not None and "and so does its fails" in problem


def _number(expr: Any, **values: Any) -> Any:
    """A reference's sympy expression at ``values`` (by symbol name), as an mpmath number."""
    import mpmath

    names = {s.name: s for s in expr.free_symbols}
    return mpmath.mpf(str(expr.subs({names[n]: v for n, v in values.items()}).evalf(40)))


def test_the_curvature_reference_is_the_paths_and_refutes_the_claim() -> None:
    """Lines 140-142: the reference's κ = u'' of the exact path (x = z/c) agrees with the
    curvature u''/(1 + u'²)^(3/2) of that path at small slopes taken by mpmath (Bessel
    functions and numerical derivatives, c = 1); κ/u changes along the path while κz/u stays
    −1/c, so « proportionnellement à l'écart horizontal » fails, as the engine finds."""
    import mpmath

    exact = cited_reference(paper("lecornu"), "reference_curvature").exact
    scale = mpmath.mpf("1e-6")  # small slopes

    def u(z: Any) -> Any:
        root = mpmath.sqrt(z)
        return scale * root * (mpmath.besselj(1, 2 * root) + mpmath.bessely(1, 2 * root))

    # 15 digits: κ agrees with its value at 30 digits to 2e-16 and κz/u + 1 (1e-14 to 1e-12,
    # the slopes' part) to its third digit, against bounds of 1e-9; at 30 digits mpmath's
    # first numerical derivative of Y₁ took 0.3 s of CPU (its coefficients at that precision)
    with mpmath.workdps(15):
        per_u = []
        for z in (mpmath.mpf("0.9"), mpmath.mpf("2.3"), mpmath.mpf("4.1")):
            kappa = mpmath.diff(u, z, 2) / (1 + mpmath.diff(u, z) ** 2) ** 1.5 / scale
            assert abs(kappa - _number(exact["kappa"], zl=z, cl=1)) < 1e-9 * abs(kappa)
            per_u.append(kappa / (u(z) / scale))
            assert abs(kappa * z / (u(z) / scale) + 1) < 1e-9
    assert max(per_u) - min(per_u) > 0.5
    row = committed_row("lecornu.result.curvature_proportional")
    computed, problem = verify_printed(
        row, committed_ledger("lecornu").symbols_for(row), REFERENCES
    )
    # fails: it restates line 134's « proportionnel à u », which the curvature carries
    # (lecornu.result.second_derivative_proportional; tables/README.md, Blame)
    assert problem is None and computed is not None and computed.startswith("fails:")


def _first_zero_of_27(p: Any) -> Any:
    """γt at the first zero after t = 0 of (27)'s solution with u(0) = 0, from the exact
    solution of (9): u ∝ √x [J₁(z0)Y₁(z) − Y₁(z0)J₁(z)], z = 2√x = (2/p)√(1 + pγt) (mpmath)."""
    import mpmath

    z0 = 2 / p
    j0, y0 = mpmath.besselj(1, z0), mpmath.bessely(1, z0)
    z1 = mpmath.findroot(lambda z: j0 * mpmath.bessely(1, z) - y0 * mpmath.besselj(1, z), z0 + 3)
    return (p**2 * z1**2 / 4 - 1) / p


def test_the_root_of_27_falls_on_the_references_epsilon_to_the_third_order() -> None:
    """Lines 642-664: the reference's ε (the root of (27)'s solution to p², by undetermined
    coefficients) against the first zero of the exact Bessel solution: their difference falls
    as p⁴ (the p³ term vanishes), as lecornu.period_second_order measures with solve_ivp."""
    import mpmath

    epsilon = cited_reference(paper("lecornu"), "reference_root_epsilon").exact["epsilon"]
    ps = [mpmath.mpf(v) for v in ("0.04", "0.02", "0.01", "0.005")]
    # 20 digits: the three orders as at 30 to 8 digits (3.96498, 3.98219, 3.99102), in 60 %
    # of the CPU (Bessel functions at 30 digits pay for their coefficients at that precision)
    with mpmath.workdps(20):
        gaps = [_first_zero_of_27(p) - mpmath.pi - _number(epsilon, p=p) for p in ps]
        orders = [mpmath.log(a / b) / mpmath.log(2) for a, b in itertools.pairwise(gaps)]
    assert all(3.7 < o < 4.3 for o in orders), orders


@cache  # the committed ledger's three studies, integrated once (0.3 s), read by five tests
def _committed_formula_rows() -> Mapping[str, FormulaRow]:
    return MappingProxyType(_formula_rows())


def _formula_rows(ledger: Ledger | None = None) -> dict[str, FormulaRow]:
    return {r.id: r for r in slow_rows(ledger=ledger)}


def test_the_quarter_time_study_is_the_rows_reference_solved_in_closed_form() -> None:
    """lecornu.quarter_time finds l'' by findroot of (24); the row's reference writes l'' in
    closed form (the larger root of a quadratic in √(gl'')): both give the same residuals."""
    import mpmath

    row = _committed_formula_rows()["lecornu.quarter_time"]
    lpp = cited_reference(paper("lecornu"), "reference_quarter_oscillation").exact["lpp"]
    ((left, right),) = _printed("lecornu.result.quarter_time")
    with mpmath.workdps(30):
        for q, residual in row.residuals:
            at = {"b": mpmath.mpf(q), "g": 1, "l": 1}
            exact = _number(lpp, eps_=1, **at)
            printed = _number(left - right, lpp=exact, **at)
            assert abs(abs(printed) - residual) < 1e-12 * residual, q
    assert row.verdict == "holds" and row.observed_order is not None
    assert 2.9 < row.observed_order < 3.1  # the b² term vanishes


def test_the_amplitude_study_agrees_with_scipys_cylinder_functions() -> None:
    """lecornu.amplitude_factor (mpmath at 30 digits) against the same elongations and
    amplitudes in double precision (scipy's jv, yv and brentq): the residuals agree."""
    from scipy.optimize import brentq
    from scipy.special import jv, yv

    delta = 0.3
    row = _committed_formula_rows()["lecornu.amplitude_factor"]
    ((_, factor), *_) = _printed("lecornu.result.amplitude_factor")
    for q, residual in row.residuals:

        def c(nu: int, z: float) -> float:
            return math.cos(delta) * jv(nu, z) + math.sin(delta) * yv(nu, z)

        z = brentq(lambda w: c(2, w), 2 / q - 0.5, 2 / q + 0.5, xtol=1e-14)
        amplitude = abs(c(1, z)) * math.sqrt(math.pi * z / 2)
        printed = float(_number(factor, R=1, g=1, l=1, b=2 / z))
        assert abs(abs(amplitude - printed) - residual) < 1e-11, q
    assert row.verdict == "holds" and row.observed_order is not None
    assert 1.9 < row.observed_order < 2.1


@pytest.mark.parametrize(
    ("formula_id", "old", "new"),
    [
        # line 555: −3b/(4g) -> −5b/(4g): the residual is then of order b
        ("lecornu.quarter_time", "- 3*b/(4*g) + pi**2*b/(16*g)'", "- 5*b/(4*g) + pi**2*b/(16*g)'"),
        # line 573: a term of the first order in b/√(gl) added to the factor
        ("lecornu.amplitude_factor", "theta = R*cos(3*b/", "theta = R*(1 - b/sqrt(g*l))*cos(3*b/"),
        # (25): ¾ pγt -> ½ pγt
        ("lecornu.eq25", "'theta = rho*(1 - 3/4*p*r*t)", "'theta = rho*(1 - 1/2*p*r*t)"),
    ],
)
def test_a_measured_study_reads_the_printed_form_and_fails_an_edit(
    formula_id: str, old: str, new: str
) -> None:
    row_id = {"lecornu.quarter_time": "lecornu.result.quarter_time",
              "lecornu.amplitude_factor": "lecornu.result.amplitude_factor",
              "lecornu.eq25": "lecornu.eq.25"}[formula_id]  # fmt: skip
    # the edited study alone: the other two read other rows, which the edit leaves alone
    edited = altered_ledger("lecornu", old, new, within=row_id)
    changed = slow_row(formula_id.split(".", 1)[1], ledger=edited)
    assert changed.id == formula_id and changed.verdict == "fails", changed.note
    assert _committed_formula_rows()[formula_id].verdict == "holds"


def _printed(row_id: str) -> tuple[tuple[Any, Any], ...]:
    row = committed_row(row_id)
    assert row.printed is not None
    return parse_formula(
        row.id, row.printed, committed_ledger("lecornu").symbols_for(row)
    ).equations


# --- the rows of lines 1-420 whose status is computed from their printed form ---------------


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        # line 48: g l sin θ -> 2 g l sin θ
        ("lecornu.result.areal_form", "t) + g*l*sin(theta) = 0'", "t) + 2*g*l*sin(theta) = 0'"),
        # line 138: the slope, not u'', vanishes at the vertical
        ("lecornu.result.inflection_at_vertical", "'u = 0; d2u_dzl2 = 0'", "'u = 0; du_dzl = 0'"),
        # line 146: h = (2/c)∫u dz
        ("lecornu.result.area_theorem", "'h = 1/cl*Integral(u, zl)", "'h = 2/cl*Integral(u, zl)"),
        # (12): φ/x = 2φ'
        (
            "lecornu.eq.12",
            "b**2/g*theta = dvarphi_dx; varphi/x = dvarphi_dx'",
            "b**2/g*theta = dvarphi_dx; varphi/x = 2*dvarphi_dx'",
        ),
        # (13): 3·4x² -> 3·5x²
        (
            "lecornu.eq.13",
            "+ 3*4*x**2/(1*2*3*4)**2 - ... = 0'",
            "+ 3*5*x**2/(1*2*3*4)**2 - ... = 0'",
        ),
        # line 204: within a fortieth of the interval of the mean (the first root is 9 % off)
        (
            "lecornu.result.roots_interlace",
            "(zeta1 + zeta2)/2 - z < (zeta2 - zeta1)/4'",
            "(zeta1 + zeta2)/2 - z < (zeta2 - zeta1)/40'",
        ),
        # line 286: twice through the vertical
        ("lecornu.result.one_vertical_between_j1_zeros", "nvert = 1'", "nvert = 2'"),
        # line 286: l = (b²/g)z1² (the 4 lost)
        (
            "lecornu.result.one_vertical_between_j1_zeros",
            "'l1 = b**2/(4*g)*zeta1**2",
            "'l1 = b**2/g*zeta1**2",
        ),
        # line 376: the limit −2/q²
        ("lecornu.result.limit_u_at_zero", "lim0 = -1/q**2", "lim0 = -2/q**2"),
        # line 378: the limit of u, +B/q²
        ("lecornu.result.limit_u_at_zero", "ulim = -B/q**2", "ulim = B/q**2"),
        # line 370: φ/p² ∫dx/x² = φ/p²[1/x0 + 1/x]
        ("lecornu.result.limit_u_at_zero", "*(1/x0 - 1/x)", "*(1/x0 + 1/x)"),
        # (18) of line 384: cos(3√x cos ω + α)
        (
            "lecornu.eq.18.definite-integral",
            "u = C*x*(Integral(cos(2*sqrt(x)",
            "u = C*x*(Integral(cos(3*sqrt(x)",
        ),
    ],
)
def test_to_line_420_a_changed_coefficient_is_refused(row_id: str, old: str, new: str) -> None:
    rows, symbols = _altered(old, new)
    computed, problem = verify_printed(rows[row_id], symbols, REFERENCES)
    assert problem is not None and problem.startswith(f"recorded {rows[row_id].status}, but")
    assert computed is not None and not computed.startswith(rows[row_id].status)


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        # (6) printed with its reading's d²/dl²
        (
            "lecornu.eq.6",
            "printed = 'Derivative(theta*l, t, 2)",
            "printed = 'Derivative(theta*l, l, 2)",
        ),
        # (19) of line 406 printed with its reading's dω/cos³ω
        (
            "lecornu.eq.19.definite-integral",
            "tan(omega))/cos(omega)**2, (omega, 0, pi/2)))'",
            "tan(omega))/cos(omega)**3, (omega, 0, pi/2)))'",
        ),
    ],
)
def test_to_line_420_a_misprint_printed_as_its_reading_is_refused(
    row_id: str, old: str, new: str
) -> None:
    rows, symbols = _altered(old, new)
    _, problem = verify_printed(rows[row_id], symbols, REFERENCES)
    assert problem is not None
    assert problem.startswith("recorded misprint, but the printed form gives holds")


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        # the compound pendulum corrected with 3bθ' for 2bθ'
        (
            "lecornu.result.compound_pendulum",
            "d2theta_dt2 = -2*b*dtheta_dt - g*sin(theta)'",
            "d2theta_dt2 = -3*b*dtheta_dt - g*sin(theta)'",
        ),
        # the first member of (13) corrected to J2(2√x)/x²
        ("lecornu.result.eq13_is_j2", "besselj(2, 2*sqrt(x))/x'", "besselj(2, 2*sqrt(x))/x**2'"),
    ],
)
def test_to_line_420_a_wrong_reading_is_refused(row_id: str, old: str, new: str) -> None:
    # misprints since nothing later carries them (tables/README.md, Blame): their reading
    rows, symbols = _altered(old, new)
    _, problem = verify_printed(rows[row_id], symbols, REFERENCES)
    assert problem is not None and "and so does its misprint" in problem


@pytest.mark.parametrize(
    ("row_id", "old", "new"),
    [
        (
            "lecornu.result.compound_pendulum",
            "printed = '(a + Rg**2/a + b*(1 - Rg**2/a**2)*t)*d2theta_dt2 = -2*b*(1 - Rg**2/a**2)*",
            "printed = '(a + Rg**2/a + b*(1 - Rg**2/a**2)*t)*d2theta_dt2 = -2*b*",
        ),
        (
            "lecornu.result.eq13_is_j2",
            "printed = 'm13 = besselj(2, 2*sqrt(x))'",
            "printed = 'm13 = besselj(2, 2*sqrt(x))/x'",
        ),
    ],
)
def test_to_line_420_a_slip_printed_as_its_reading_is_refused(
    row_id: str, old: str, new: str
) -> None:
    rows, symbols = _altered(old, new)
    _, problem = verify_printed(rows[row_id], symbols, REFERENCES)
    assert problem is not None and problem.startswith(
        "recorded misprint, but the printed form gives holds"
    )


def _formula(text: str) -> Formula:
    symbols = committed_ledger("lecornu").symbols
    return parse_formula("test", text, dict(symbols))


def test_the_cross_reference_of_line_276_is_judged_against_both_equations() -> None:
    """What (10) gives leaves the sign of d(u/φ)/dx undetermined (u, u' free); (20) fixes it;
    citing (20) for the printed form too (no reading reference) makes the row hold."""
    from dataclasses import replace

    reference = cited_reference(paper("lecornu"), "reference_monotone_as_cited")
    claim = _formula("B*Derivative(u/varphi, x) > 0")
    ok, why = judged(claim, reference)
    assert not ok and "undetermined" in why and "du_dx" in why
    assert reference.reading is not None and judged(claim, reference.reading)[0]
    assert not judged(_formula("B*Derivative(u/varphi, x) < 0"), reference.reading)[0]
    as_20 = replace(reference.reading, reading=None)
    assert computed_status(claim, claim, None, as_20)[0] == "holds"


def test_an_inequality_needs_a_margin_and_a_range() -> None:
    import sympy as sp

    from pendcli.verify.printed_check import Reference

    at_two = Reference({"z": sp.Integer(2)})
    assert judged(_formula("z < 3"), at_two)[0]
    assert not judged(_formula("z < 2"), at_two)[0]  # strict: no margin
    assert judged(_formula("z <= 2"), at_two)[0]
    assert not judged(_formula("z >= 3"), at_two)[0]
    ranged = Reference({}, domain={"z": (sp.Integer(1), sp.Integer(2))})
    assert judged(_formula("z**2 < 4*z"), ranged)[0]
    assert not judged(_formula("z**2 < 4*z"), Reference({}))[0]  # z unbounded


def test_cases_substitute_into_the_exact_values_and_each_must_pass() -> None:
    import sympy as sp

    from pendcli.verify.printed_check import Reference

    z = sp.Symbol("z", real=True)
    roots = ({"z": sp.Integer(1)}, {"z": sp.Integer(2)})
    reference = Reference({"u": (z - 1) * (z - 2)}, each_case=roots)
    assert judged(_formula("u = 0"), reference)[0]
    ok, why = judged(_formula("u = 0"), Reference({"u": (z - 1) * (z - 3)}, each_case=roots))
    assert not ok and why.startswith("case 2 of 2")


def test_a_condition_is_judged_as_the_models_equation() -> None:
    """(12) with φ, φ' by their series (line 182) passes against its condition φ/x − φ', and
    the same printed equation as an identity (no condition) does not."""
    from dataclasses import replace

    reference = cited_reference(paper("lecornu"), "reference_eq13")
    line_182 = _formula(
        "1 - 2*x/(1*2)**2 + 3*x**2/(1*2*3)**2 - ... = 1 - x/1**2 + x**2/(1*2)**2 - ..."
    )
    assert judged(line_182, replace(reference, conditions=reference.conditions[:1]))[0]
    assert not judged(line_182, replace(reference, conditions=()))[0]
