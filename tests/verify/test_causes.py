"""Causes: every row that does not agree or hold says why, and each cause is checked against
a computation, not taken on trust.

* ``rounding`` / ``truncation``: the recomputed value rounded / chopped at the printed
  precision is the printed value.
* ``propagated``: the number uses an input that is itself a slip (or carries one), named in
  ``from``; with those inputs at what his own procedure gives for them, the number's procedure
  no longer gives his digits (the slip is what it carries). Sources exist, no cycle.
* ``arithmetic-slip``: his printed inputs do not give the printed value; his own part of the
  error is the larger.
* ``input-rounding``: his procedure on his printed inputs gives his digits, and the truth
  does not: the distance is the inputs' rounding (tests/verify/test_claims_own_procedure.py checks
  six such numbers against mpmath).
* The formula (42) inherits the wrong pk³ term of (41): checked by deriving (42) from (41)
  with sympy, once from the printed (41) and once from the (41) solved here.
"""

from __future__ import annotations

import re
from fractions import Fraction

import pytest
from helpers.evaluated import committed_claims, committed_formulas

from pendcli.base.errors import PendcliError
from pendcli.data.tables import load_paper_table
from pendcli.papers.registry import PAPERS, paper
from pendcli.verify.causes import (
    CAUSES,
    ROOT_CAUSES,
    SLIP_CAUSES,
    Procedure,
    chops_to,
    rounds_to,
    split_error,
)
from pendcli.verify.claims import (
    ClaimRow,
    FormulaRow,
    cause_tally,
    with_causes,
)


@pytest.fixture(scope="module")
def claims() -> dict[str, dict[str, ClaimRow]]:
    return {key: {r.id: r for r in committed_claims(key)} for key in PAPERS}


@pytest.fixture(scope="module")
def formulas() -> dict[str, dict[str, FormulaRow]]:
    return {key: {r.id: r for r in committed_formulas(key)} for key in PAPERS}


def _procedures(key: str) -> dict[str, Procedure]:
    builder = paper(key).author_procedures
    return dict(builder()) if builder is not None else {}


def _rows_with(claims: dict[str, dict[str, ClaimRow]], cause: str) -> list[tuple[str, ClaimRow]]:
    """Every claim row (its cause as computed or as the table gives it) with ``cause``."""
    found = [(key, r) for key in PAPERS for r in claims[key].values() if r.cause == cause]
    assert found, f"no row has cause {cause}: the test would check nothing"
    return found


def _printed(key: str) -> dict[str, float]:
    return {c.id: c.number.value for c in load_paper_table(key).claims}


def _number(key: str, claim_id: str):
    return load_paper_table(key).claim(claim_id).number


# --- every disagreement has a cause; the graph is sound -----------------------------------


@pytest.mark.parametrize("key", PAPERS)
def test_every_claim_that_does_not_agree_has_a_cause(claims, key):
    missing = [r.id for r in claims[key].values() if r.verdict != "agrees" and r.cause is None]
    assert missing == []


@pytest.mark.parametrize("key", PAPERS)
def test_an_agreeing_claim_has_no_cause_or_its_rounding(claims, key):
    odd = [
        (r.id, r.cause)
        for r in claims[key].values()
        if r.verdict == "agrees" and r.cause not in (None, "rounding", "truncation")
    ]
    assert odd == []


@pytest.mark.parametrize("key", PAPERS)
def test_every_failing_formula_has_a_cause_and_a_holding_one_none(formulas, key):
    rows = formulas[key].values()
    assert [r.id for r in rows if r.verdict == "fails" and r.cause is None] == []
    assert [r.id for r in rows if r.verdict == "holds" and r.cause is not None] == []


def _graph_problems(rows: dict[str, ClaimRow] | dict[str, FormulaRow]) -> list[str]:
    problems = []
    for row in rows.values():
        if row.cause not in (None, *CAUSES):
            problems.append(f"{row.id}: unknown cause {row.cause!r}")
        if (row.cause == "propagated") != bool(row.cause_from):
            problems.append(f"{row.id}: 'from' without propagated, or propagated without it")
        for source in row.cause_from:
            if source not in rows:
                problems.append(f"{row.id}: source {source} does not exist")
            elif rows[source].cause is None:
                problems.append(f"{row.id}: source {source} has no cause")
    return problems


def _has_cycle(rows: dict[str, ClaimRow] | dict[str, FormulaRow]) -> bool:
    state: dict[str, int] = {}  # 1 on the current path, 2 done

    def visit(node: str) -> bool:
        if state.get(node) == 1:
            return True
        if state.get(node) == 2 or node not in rows:
            return False
        state[node] = 1
        found = any(visit(s) for s in rows[node].cause_from)
        state[node] = 2
        return found

    return any(visit(n) for n in rows)


@pytest.mark.parametrize("key", PAPERS)
def test_sources_exist_have_causes_and_form_no_cycle(claims, formulas, key):
    for rows in (claims[key], formulas[key]):
        assert _graph_problems(rows) == []
        assert not _has_cycle(rows)


def test_cycle_and_missing_source_are_caught():
    def row(i, cause, sources=()):
        return FormulaRow(i, "p", "", "", "", "fails", 2, 1, "", (), cause, tuple(sources))

    cyclic = {"a": row("a", "propagated", ["b"]), "b": row("b", "propagated", ["a"])}
    assert _has_cycle(cyclic)
    dangling = {"a": row("a", "propagated", ["z"]), "b": row("b", None)}
    assert _graph_problems(dangling) == ["a: source z does not exist"]


# --- each cause against the computation ---------------------------------------------------


# No claim has the cause rounding: a printed number that is the truth rounded agrees, and a
# number that agrees has no cause (test_a_number_that_agrees_with_the_truth_has_no_cause).


def test_truncation_is_the_recomputed_value_chopped(claims):
    for key, row in _rows_with(claims, "truncation"):
        number = _number(key, row.id)
        assert chops_to(number, row.recomputed), row.id
        assert not rounds_to(number, row.recomputed), row.id


def _his_figure(key: str, claim_id: str, row: ClaimRow) -> float:
    """What he would have printed for a source: his own procedure on his printed inputs, or
    the recomputed value where no procedure of his is known."""
    procedures = _procedures(key)
    if claim_id in procedures:
        return procedures[claim_id](_printed(key))
    return row.recomputed


def test_propagated_carries_a_slip_that_decides_its_digits(claims):
    """Every source it names carries a slip; with those sources at the figures his own
    procedure gives for them, the number's procedure no longer gives his printed digits."""
    for key, row in _rows_with(claims, "propagated"):
        procedure, number = _procedures(key)[row.id], _number(key, row.id)
        assert row.cause_from and set(row.cause_from) <= set(procedure.inputs), row.id
        rows = claims[key]
        for source in row.cause_from:
            s = rows[source]
            assert s.procedure_verdict == "slip" or s.cause in ("propagated", *SLIP_CAUSES), source
        mended = _printed(key) | {i: _his_figure(key, i, rows[i]) for i in row.cause_from}
        value = procedure(mended)
        assert not rounds_to(number, value) and not chops_to(number, value), (row.id, value)


def test_arithmetic_slip_is_not_what_his_own_inputs_give(claims):
    for key, row in _rows_with(claims, "arithmetic-slip"):
        if row.id not in _procedures(key):
            continue  # a slip the table records, with its evidence in the note
        procedure, number = _procedures(key)[row.id], _number(key, row.id)
        split = split_error(number, procedure, _printed(key), row.recomputed)
        assert not rounds_to(number, split.author) and not chops_to(number, split.author)
        assert row.procedure_verdict == "slip", row.id
        assert row.verdict != "agrees"


def test_a_slip_hidden_behind_a_right_input_is_not_called_propagated():
    """A made-up value 0,94 computed as (1 - l)/0,35 from l = 0,68 (which gives 0,914):
    the procedure splits its error into a small inherited part and a large own part."""
    from pendcli.data.numbers import parse_printed

    procedure = Procedure(("l",), lambda length: (1 - length) / 0.35)
    split = split_error(parse_printed("0,94"), procedure, {"l": 0.68}, 0.9045)
    assert float(Fraction(32, 35)) == pytest.approx(split.author)
    assert not split.inherited_dominates
    fine = split_error(parse_printed("0,91"), procedure, {"l": 0.68}, 0.9045)
    assert fine.own == 0.0


def test_lecornu_coefficient_is_his_value_of_g():
    """0,00313 = b²/(4g) rounds only for g <= 9,8; 9.81 is assumed: the gap is g, 0.1 %."""
    from pendcli.papers.lecornu.claims import recompute

    number = _number("lecornu", "lecornu.coefficient_b2_4g")
    speed = Fraction(str(load_paper_table("lecornu").constant("speed")))
    lowest = Fraction(str(number.value)) - Fraction(str(number.resolution)) / 2
    g_max = speed**2 / (4 * lowest)  # exact: 0,1225/0,0125 = 9,8
    assert g_max == Fraction(98, 10)
    value = recompute(g=float(g_max) * (1 - 1e-9))["lecornu.coefficient_b2_4g"].value
    assert rounds_to(number, value)
    assert abs(float(g_max) / load_paper_table("lecornu").constant("g") - 1) < 2e-3


@pytest.mark.parametrize("key", PAPERS)
def test_a_misprinted_or_misderived_formula_comes_with_the_right_one(formulas, key):
    """A misprint or a derivation error is a claim that a corrected formula was found."""
    rows = [r for r in formulas[key].values() if r.cause in ("misprint", "derivation-error")]
    assert [r.id for r in rows if r.recomputed == r.published] == []


# --- formulas: (42) inherits the pk³ term of (41) --------------------------------------------


def _quarter_period_coefficients(delta):
    """(c0, c2) in ∂T/∂p = c0 + c2 k², T the time from the elongation to the vertical, from
    θ = 2k cos u + k³θ3 (38) and ∂θ/∂p = kβ + k³δ (41): ∂T/∂p = −ε(K)/θ'(K).

    θ' is k times (−2 sin u + k²θ3'), and K = π/2 (1 + k²/4): ∂T/∂p is g(x) = G(K(x), x),
    x = k², G(u, x) = −(β + xδ)/(−2 sin u + xθ3'), so c0 = G(π/2, 0) and, by the chain rule,
    c2 = g'(0) = ∂G/∂x + (π/8) ∂G/∂u at (π/2, 0): both exact (sympy differentiation, of G
    before u is replaced by K(x), which makes the derivative in x four times as costly)."""
    import sympy as sp

    u, x = sp.symbols("u x", real=True)
    theta3 = (9 * sp.cos(u) + 12 * u * sp.sin(u) - sp.cos(3 * u)) / 24
    beta = (u**2 * sp.sin(u) - 3 * u * sp.cos(u) + 3 * sp.sin(u)) / 2
    slope_over_k = -2 * sp.sin(u) + x * sp.diff(theta3, u)
    g = -(beta + x * delta(u, beta, theta3)) / slope_over_k
    at = {u: sp.pi / 2, x: 0}
    c2 = sp.diff(g, x).subs(at) + sp.diff(g, u).subs(at) * sp.pi / 8
    return sp.simplify(g.subs(at)), sp.simplify(c2)


def _printed_delta(u, beta, theta3):
    import sympy as sp

    s, c = sp.sin(u), sp.cos(u)
    terms = -4 * u**3 * c + 11 * u**2 * s - u * c - u**2 * sp.sin(3 * u) - 3 * u * sp.cos(3 * u)
    return (terms + 4 * s) / 32


def _solved_delta(u, beta, theta3):
    """δ from the variational equation ε'' + cos θ ε = −(uθ'' + 2θ') at order k³, at rest.

    Solved exactly by undetermined coefficients: the forcing is a sum of uⁿ sin(mu), uⁿ cos(mu)
    (m = 1, 3; after product-to-sum), so δ = Σ (a uⁿ sin mu + b uⁿ cos mu), n ≤ 4; the residual's
    coefficients and the two initial conditions are linear in a, b (sympy linsolve). The
    solution of the initial-value problem is unique, so any δ found this way is the one."""
    import sympy as sp
    from sympy.simplify.fu import TR8

    forcing = 2 * sp.cos(u) ** 2 * beta - (u * sp.diff(theta3, u, 2) + 2 * sp.diff(theta3, u))
    waves = (sp.sin(u), sp.cos(u), sp.sin(3 * u), sp.cos(3 * u))
    unknowns = sp.symbols("a0:20")
    trial = sum(a * u ** (i % 5) * waves[i // 5] for i, a in enumerate(unknowns))
    residual = sp.expand(TR8(sp.diff(trial, u, 2) + trial - forcing))
    equations = [*sp.Poly(residual, u, *waves).coeffs(), trial.subs(u, 0)]
    equations.append(sp.diff(trial, u).subs(u, 0))
    (solution,) = sp.linsolve(equations, unknowns)
    delta = trial.subs(dict(zip(unknowns, solution, strict=True)))
    assert delta.free_symbols == {u}, "the initial-value problem left a coefficient free"
    return delta


def test_eq42_inherits_eq41(formulas):
    """From the printed (41), (42)'s printed (2π² + 1)/16 follows (the author was consistent);
    from the solved (41), the coefficient the numerical solution found."""
    import sympy as sp

    c0, c2 = _quarter_period_coefficients(_printed_delta)
    assert sp.simplify(c0 - (sp.pi**2 / 4 + 3) / 4) == 0
    assert sp.simplify(c2 - (2 * sp.pi**2 + 1) / 16) == 0
    _, c2_solved = _quarter_period_coefficients(_solved_delta)
    row = formulas["lecornu"]["lecornu.eq42_terms_in_b"]
    assert row.cause == "propagated" and row.cause_from == ("lecornu.eq41_terms_in_p",)
    found = re.search(r"coefficient of bk²/g is ([0-9.]+)", row.note)
    assert found, row.note
    assert float(c2_solved) == pytest.approx(float(found.group(1)), abs=1e-5)  # 6 digits fitted
    assert sp.simplify(c2_solved - (48 - sp.pi**2) / 64) == 0  # the term the row identified
    assert "(48 − π²)/64" in row.recomputed


# --- the tally --------------------------------------------------------------------------------


def _claim(i: str, verdict: str, cause: str | None, sources: tuple[str, ...] = ()) -> ClaimRow:
    return ClaimRow(
        i, "p", "", "", "", "1", 1.0, 1.0, verdict, 0.0, 0.0, 17.0, None, "", "", cause, sources
    )


def test_tally_counts_roots_apart_from_what_they_carry():
    rows = [
        _claim("z", "agrees", "rounding"),
        _claim("a", "discrepant", "arithmetic-slip"),
        _claim("b", "discrepant", "propagated", ("a", "z")),
        _claim("c", "last-digit", "propagated", ("z",)),
        _claim("d", "truncated", "truncation"),
        _claim("e", "discrepant", None),
        _claim("f", "agrees", None),
    ]
    tally = cause_tally(rows)
    assert tally.roots == {
        c: {"arithmetic-slip": 1, "truncation": 1}.get(c, 0) for c in ROOT_CAUSES
    }
    assert (tally.root_total, tally.propagated, tally.unexplained) == (2, 2, 1)
    assert tally.edges == (("a", "b"), ("z", "b"), ("z", "c"))


def test_tally_of_lecornu_separates_slips_from_what_they_carry(claims):
    tally = cause_tally(claims["lecornu"].values())
    discrepant = [r for r in claims["lecornu"].values() if r.verdict == "discrepant"]
    assert tally.unexplained == 0
    assert tally.roots["arithmetic-slip"] < len(discrepant)
    assert ("lecornu.example.time.2", "lecornu.example.interval.2") in tally.edges


def test_with_causes_refuses_unknown_rows_and_causes():
    row = FormulaRow("x", "p", "", "", "", "fails", 2, 1, "")
    assert with_causes([row], {"x": ("misprint", ())})[0].cause == "misprint"
    for bad in (
        {"y": ("misprint", ())},
        {"x": ("typo", ())},
        {"x": ("propagated", ())},
        {"x": ("misprint", ("x",))},
    ):
        with pytest.raises(PendcliError):
            with_causes([row], bad)


def test_a_number_that_agrees_with_the_truth_has_no_cause() -> None:
    """A cause says why a printed number disagrees: one that agrees has none (the rule of
    tables/README.md), though its note may say how he rounded it."""
    from pendcli.papers.registry import PAPERS

    with_cause = [
        r.id for key in PAPERS for r in committed_claims(key) if r.verdict == "agrees" and r.cause
    ]
    assert with_cause == []
