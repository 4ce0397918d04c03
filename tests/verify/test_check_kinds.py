"""The kinds of check a ledger row declares: the rule that picks one, the refusal of a row whose
declared kind is not the one its reference calls for, of a reference whose parameters make no
kind, of a ``measured`` naming no formula check, and the agreement of the engine's verdicts
with the formula checks that measure the same rows against a fuller model."""

from __future__ import annotations

import dataclasses

import pytest
import sympy as sp
from helpers.evaluated import committed_formulas
from helpers.ledgers import committed_ledger, committed_row
from helpers.mutations import judged_after_edit

from pendcli.base.errors import PendcliError
from pendcli.data.printed import Formula
from pendcli.papers.registry import paper
from pendcli.verify.check_kinds import KINDS, kind_called_for, kind_problem
from pendcli.verify.ledger_evaluation import measured
from pendcli.verify.ledger_references import reference_table
from pendcli.verify.printed_check import Reference, formula_passes
from pendcli.verify.printed_numeric import Numbers

x, s = sp.symbols("x s", real=True)
EQUATION = Formula("x = 1", ((x, sp.Integer(1)),))
RELATION = Formula("x > 0", ((None, sp.StrictGreaterThan(x, 0)),))


@pytest.mark.parametrize(
    ("formula", "reference", "kind"),
    [
        (EQUATION, Numbers(values=[1]), "digits"),
        (EQUATION, Reference(exact={}, each_case=({"x": 1},)), "cases"),
        (EQUATION, Reference(exact={}, scale=s, bounded=True), "limit"),
        (EQUATION, Reference(exact={}, scale=s, order=2, rounded=True), "decimal"),
        (RELATION, Reference(exact={}, scale=s, order=2), "inequality"),
        (EQUATION, Reference(exact={}, scale=s, order=2), "series"),
        (EQUATION, Reference(exact={}), "identity"),
    ],
)
def test_the_rule_picks_the_first_kind_that_applies(formula, reference, kind) -> None:
    assert kind in KINDS
    assert kind_called_for(formula, reference) == kind
    assert kind_problem(kind, formula, reference) is None
    other = next(k for k in KINDS if k != kind)
    assert kind_problem(other, formula, reference) == (
        f"kind {other!r} is declared, but its reference and printed form make it {kind!r}"
    )


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        ({"order": 2}, "an order needs a scale"),
        ({"orders": {"x": 2}}, "an order needs a scale"),
        ({"bounded": True}, "bounded needs a scale and takes no order"),
        ({"bounded": True, "scale": s, "order": 2}, "bounded needs a scale and takes no order"),
        ({"scale": s}, "a scale needs an order (or bounded)"),
        ({"scale": s, "bounded": True, "rounded": True}, "bounded and rounded exclude each other"),
        ({"each_case": ({"x": 1},), "conditions": (None,)}, "each_case and conditions exclude"),
    ],
)
def test_a_reference_whose_parameters_make_no_kind_is_refused(parameters, message) -> None:
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        Reference(exact={}, **parameters)


def test_a_declared_kind_other_than_the_references_is_refused_naming_the_row() -> None:
    row_id = "lecornu.eq.25"  # a series in p
    assert committed_row(row_id).kind == "series"
    computed, problem = judged_after_edit(
        reference_table(paper("lecornu")), row_id, 'kind = "series"', 'kind = "inequality"', row_id
    )
    assert computed == (
        "no status the ledger may record: kind 'inequality' is declared, but its reference and "
        "printed form make it 'series'"
    )
    assert problem is not None and problem.startswith("recorded holds, but the printed form")


def test_every_kind_decides_some_row_of_the_ledgers() -> None:
    used = {r.kind for key in ("tisserand", "lecornu", "charbonnier") for r in
            committed_ledger(key).rows}  # fmt: skip
    assert set(KINDS) <= used


def test_a_measured_name_that_is_no_formula_check_is_refused_naming_the_row() -> None:
    row = dataclasses.replace(committed_row("lecornu.eq.26"), measured=("no_such_check",))
    with pytest.raises(PendcliError, match=r"lecornu.eq.26: measured names no formula check "):
        measured(row, [])


def test_a_reference_symbol_with_other_assumptions_is_refused_not_a_second_unknown() -> None:
    g = sp.Symbol("g", positive=True)  # the ledger's g is real, not positive
    formula = Formula("x = g", ((x, sp.Symbol("g", real=True)),))
    with pytest.raises(PendcliError, match=r"the symbol\(s\) g enter twice"):
        formula_passes(formula, Reference(exact={"x": g}))


def test_the_formula_checks_a_row_names_agree_with_its_status() -> None:
    """An independent method: each measured formula check integrates the fuller model (an ODE,
    a quadrature), where the engine judged the printed form symbolically. A row that holds
    has every measured check holding. A failing or misprinted row's checks measure its
    printed form (they fail) or its reading or correction (they hold): its status says whose
    later work carries the slip (tables/README.md, Blame), not which form a check measures."""
    for key in ("tisserand", "lecornu", "charbonnier"):
        rows = [r for r in committed_ledger(key).rows if r.measured]
        assert paper(key).formula_checks is not None
        formulas = {f.id: f for f in committed_formulas(key)}  # once per process
        for row in rows:
            verdicts = {formulas[f"{key}.{name}"].verdict for name in row.measured or ()}
            if row.status == "holds":
                assert verdicts == {"holds"}, row.id


def test_a_bare_expression_is_refused_not_skipped() -> None:
    """A printed part that is neither an equation nor a relation claims nothing the engine
    can judge: the formula is refused, where it once passed unjudged."""
    ok, why = formula_passes(Formula("x + 1", ((None, x + 1),)), Reference(exact={}))
    assert not ok and why == "x + 1: neither an equation nor a relation, nothing to judge"


@pytest.mark.parametrize("share", [sp.Rational(1, 25), sp.Rational(1, 40)])
def test_an_inequality_false_on_a_small_part_of_its_domain_is_refused(share) -> None:
    """x > 1/10 + share/10 over x in (1/10, 1/5) is false on the share `share` of the domain
    (the engine's points are fixed by its seed: three of them missed a 4 % part)."""
    low, high = sp.Rational(1, 10), sp.Rational(1, 5)
    relation = sp.StrictGreaterThan(x, low + share * (high - low))
    reference = Reference(exact={}, domain={"x": (low, high)})
    ok, why = formula_passes(Formula("x > c", ((None, relation),)), reference)
    assert not ok and "the margin is" in why, why
    wide = sp.StrictGreaterThan(x, low - share)
    assert formula_passes(Formula("x > c", ((None, wide),)), reference)[0]


# --- the kind's parameters as ledger keys ------------------------------------------------


def test_a_rows_keys_are_parsed_exactly_and_put_in_place_of_the_references() -> None:
    from pendcli.verify.check_kinds import parse_parameters, with_parameters

    entry = {"scale": "eps", "order": 3, "domain": {"x": ["1/3", 0.5], "y": [-1, 2]}}
    parameters = parse_parameters("row", "series", entry)
    eps = sp.Symbol("eps", positive=True)  # the reference's own scale, not a second unknown
    own = Reference(exact={"x": eps * x}, domain={"x": (0, 1), "z": (1, 2)})
    given = with_parameters(own, parameters)
    assert given.scale is eps and given.order == 3 and given.exact == own.exact
    third, half = sp.Rational(1, 3), sp.Rational(1, 2)
    assert given.domain == {"x": (third, half), "y": (-1, 2), "z": (1, 2)}
    assert all(isinstance(v, sp.Rational) for n in "xy" for v in given.domain[n])
    # a reading and the cases are judged for the same row: they take its keys too
    nested = with_parameters(Reference(exact={}, reading=own, cases=(own,)), parameters)
    assert nested.reading.order == 3 and nested.cases[0].scale is eps


def test_a_series_judged_through_the_rows_order_not_the_references() -> None:
    """x = 1 + eps against x = 1 + eps + eps**2: holds through order 2, not through 3; the
    order comes from the row (a model and two rows citing it with their own)."""
    from pendcli.verify.check_kinds import parse_parameters, with_parameters

    eps = sp.Symbol("eps", real=True)
    model = Reference(exact={"x": 1 + eps + eps**2})
    printed = Formula("x = 1 + eps", ((x, 1 + eps),))
    for order, holds in ((2, True), (3, False)):
        keys = parse_parameters("row", "series", {"scale": "eps", "order": order})
        assert formula_passes(printed, with_parameters(model, keys))[0] is holds


@pytest.mark.parametrize(
    ("kind", "entry", "says"),
    [
        ("identity", {"order": 2}, "kind 'identity' takes no 'order'"),
        ("digits", {"domain": {"x": [0, 1]}}, "kind 'digits' takes no 'domain'"),
        ("series", {"scale": "1eps", "order": 1}, "'scale' must be a symbol name"),
        ("series", {"scale": "e", "order": True}, "'order' must be a non-negative integer"),
        ("series", {"scale": "e", "order": 1, "orders": {"x": -1}}, "'orders' must be"),
        ("limit", {"bounded": True}, "'bounded' needs a 'scale'"),
        ("limit", {"scale": "e", "bounded": False}, "true or absent"),
        ("cases", {"cases": ["a"], "each_case": [{"x": 1}]}, "exclude each other"),
        ("cases", {"each_case": [{"x": "pi"}]}, "is not a number"),
        ("identity", {"domain": {"x": [1, 1]}}, "bounds reversed or empty"),
        ("identity", {"domain": {"x": [0, 1, 2]}}, "bounds must be [low, high]"),
    ],
)
def test_meaningless_keys_are_one_line_naming_the_row(kind: str, entry: dict, says: str) -> None:
    from pendcli.verify.check_kinds import parse_parameters

    with pytest.raises(PendcliError) as error:
        parse_parameters("ledger.toml: a.eq.1", kind, entry)
    assert str(error.value).startswith("ledger.toml: a.eq.1: ") and says in str(error.value)
    assert "\n" not in str(error.value)
