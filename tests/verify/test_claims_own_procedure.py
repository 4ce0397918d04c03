"""Two verdicts for every printed number: against the truth, and against his own procedure.

Six numbers the author got exactly right from correctly rounded inputs (-0,130; +6,19;
-47,62; 1,66; 2,63; 3,66) are recomputed here with mpmath:
his procedure on his printed inputs (read from tables/published, never retyped), finished by
rounding half up or chopping at the printed place, gives his digits; each printed input is the
exact value correctly rounded; and the truth (exact zeros, exact lengths) does not give them.
Each must then be ``faithful`` with cause ``input-rounding``: neither a slip nor propagated.
A ``propagated`` row must name a source that carries a slip, and the README's counts of the
causes must be the code's.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from decimal import ROUND_DOWN, ROUND_HALF_UP, Decimal
from pathlib import Path

import mpmath
import pytest
from helpers.evaluated import committed_claims, committed_formulas

from pendcli.base.errors import PendcliError
from pendcli.data.numbers import parse_printed
from pendcli.data.tables import load_paper_table
from pendcli.data.vocabulary import SLIP_CAUSES
from pendcli.papers.registry import PAPERS, paper
from pendcli.verify.causes import Judged, Procedure, own_verdicts, rule_cause
from pendcli.verify.claims import ClaimRow, cause_tally, with_own_verdicts

README = Path(__file__).resolve().parents[2] / "docs" / "findings.md"


@pytest.fixture(scope="module")
def claims() -> dict[str, dict[str, ClaimRow]]:
    return {key: {r.id: r for r in committed_claims(key)} for key in PAPERS}


# --- the six numbers, against an independent recomputation ------------------------------


def _p(name: str) -> mpmath.mpf:
    """A printed value of Lecornu's table, exactly as printed."""
    return mpmath.mpf(str(load_paper_table("lecornu").claim(f"lecornu.{name}").number.value))


def _c(name: str) -> mpmath.mpf:
    return mpmath.mpf(str(load_paper_table("lecornu").constant(name)))


def _zero(order: int, k: int) -> mpmath.mpf:
    return mpmath.besseljzero(order, k)


def _j0(z: mpmath.mpf) -> mpmath.mpf:
    return mpmath.besselj(0, z)


def _length(k: int) -> mpmath.mpf:
    """The exact length (16) at the k-th zero of J_2: (b²/4g) j_(2,k)²."""
    return _c("speed") ** 2 / (4 * _c("g")) * _zero(2, k) ** 2


# claim -> (his procedure on his printed inputs, the truth, {input: its exact value})
Case = tuple[Callable[[], mpmath.mpf], Callable[[], mpmath.mpf], dict[str, Callable[[], object]]]
SIX: dict[str, Case] = {
    "j0_at_j2_zeros.1": (
        lambda: _j0(_p("j2_zeros.1")),
        lambda: _j0(_zero(2, 1)),
        {"j2_zeros.1": lambda: _zero(2, 1)},
    ),
    "deviation.5": (
        lambda: _p("j0_at_j2_zeros.1") / _p("j0_at_j2_zeros.5"),
        lambda: _j0(_zero(2, 1)) / _j0(_zero(2, 5)),
        {"j0_at_j2_zeros.5": lambda: _j0(_zero(2, 5)), "j2_zeros.1": lambda: _zero(2, 1)},
    ),
    "deviation.zero_length": (
        lambda: 1 / _p("j0_at_j2_zeros.5"),
        lambda: 1 / _j0(_zero(2, 5)),
        {"j0_at_j2_zeros.5": lambda: _j0(_zero(2, 5))},
    ),
    "example.time.3": (
        lambda: (_c("length") - _p("example.length.3")) / _c("speed"),
        lambda: (_c("length") - _length(3)) / _c("speed"),
        {"example.length.3": lambda: _length(3)},
    ),
    "example.time.5": (
        lambda: (_c("length") - _p("example.length.5")) / _c("speed"),
        lambda: (_c("length") - _length(1)) / _c("speed"),
        {"example.length.5": lambda: _length(1)},
    ),
    "x_bound": (
        lambda: _p("j1_zeros.6") ** 2 / 4,
        lambda: _zero(1, 1) ** 2 / 4,
        {"j1_zeros.6": lambda: _zero(1, 1)},
    ),
}


def _finishes(value: object, decimals: int) -> set[Decimal]:
    """``value`` rounded half up and chopped at ``decimals`` places."""
    exact = Decimal(mpmath.nstr(value, 30, strip_zeros=False))
    place = Decimal(1).scaleb(-decimals)
    return {exact.quantize(place, ROUND_HALF_UP), exact.quantize(place, ROUND_DOWN)}


def _printed_decimal(name: str) -> tuple[Decimal, int]:
    number = load_paper_table("lecornu").claim(f"lecornu.{name}").number
    assert number.decimals is not None
    return Decimal(repr(number.value)).quantize(
        Decimal(1).scaleb(-number.decimals)
    ), number.decimals


@pytest.mark.parametrize("name", list(SIX))
def test_a_number_faithful_to_rounded_inputs_is_not_a_slip(claims, name):
    his, truth, inputs = SIX[name]
    printed, decimals = _printed_decimal(name)
    with mpmath.workdps(30):
        assert printed in _finishes(his(), decimals)  # his digits follow from his inputs
        assert printed not in _finishes(truth(), decimals)  # and the truth does not give them
        for source, exact in inputs.items():  # each input is the exact value rounded
            value, places = _printed_decimal(source)
            assert value == Decimal(mpmath.nstr(exact(), 30)).quantize(
                Decimal(1).scaleb(-places), ROUND_HALF_UP
            ), source
        # his procedures round: a value that only chopped gives his digits is faithful on
        # that condition (−0,130 for his −0,13079; 3,66 for his 3,6672), never bare
        exact = Decimal(mpmath.nstr(his(), 30, strip_zeros=False))
        rounded = exact.quantize(Decimal(1).scaleb(-decimals), ROUND_HALF_UP) == printed
    row = claims["lecornu"][f"lecornu.{name}"]
    assert row.verdict != "agrees"
    own = "faithful" if rounded else "faithful if chopped"
    assert (row.procedure_verdict, row.cause, row.cause_from) == (own, "input-rounding", ())


def test_the_slips_and_the_numbers_that_carry_one():
    """Who slipped: 0,94 and +0,072 are his own slips; the intervals from 0,94 and
    -3,45 carry one (-3,45 is faithful only to digits of +0,072 he did not print); -1,27,
    whose inputs carry none, is a slip of his own."""
    rows = {r.id.split(".", 1)[1]: r for r in committed_claims("lecornu")}
    carried = {k for k, r in rows.items() if r.cause == "propagated"}
    assert carried == {"example.interval.1", "example.interval.2", "deviation.4"}
    assert rows["deviation.4"].cause_from == ("lecornu.j0_at_j2_zeros.2",)
    assert rows["deviation.4"].procedure_verdict == "faithful if he kept more digits"
    assert (rows["deviation.2"].cause, rows["deviation.2"].procedure_verdict) == (
        "arithmetic-slip",
        "slip",
    )


# --- the rule, on made-up numbers ----------------------------------------------------------


def _judged(printed: str, truth: float, cause: str | None = None) -> Judged:
    return Judged(parse_printed(printed), truth, cause)


def test_the_rule_tells_a_rounded_input_from_a_slip():
    """A made-up number 0,20 = 2·z from z printed 0,10 (truth 0,104): faithful to a rounded
    input, then the same with z a slip (the table's arithmetic-slip): propagated from z."""
    double = {"n": Procedure(("z",), lambda z: 2 * z, "2z")}
    rounded = {"z": _judged("0,10", 0.104), "n": _judged("0,20", 0.208)}
    own = own_verdicts(rounded, double)["n"]
    assert (own.verdict, own.cause, own.cause_from) == ("faithful", "input-rounding", ())
    slipped = rounded | {"z": _judged("0,10", 0.104, "arithmetic-slip")}
    own = own_verdicts(slipped, double)["n"]
    assert (own.verdict, own.cause, own.cause_from) == ("faithful", "propagated", ("z",))
    assert rule_cause(parse_printed("0,25"), 0.208, 0.20, ()) == ("arithmetic-slip", ())
    assert rule_cause(parse_printed("0,20"), 0.204, 0.20, ()) == (None, ())  # agrees


def test_a_cause_written_for_a_number_with_a_procedure_is_refused():
    table = load_paper_table("lecornu")
    rows = committed_claims("lecornu")
    entries = tuple(
        dataclasses.replace(c, cause="propagated", cause_from=("lecornu.example.length.3",))
        if c.id == "lecornu.example.time.3"
        else c
        for c in table.claims
    )
    procedures = paper("lecornu").author_procedures
    assert procedures is not None
    with pytest.raises(PendcliError, match=r"lecornu\.example\.time\.3: its cause is computed"):
        with_own_verdicts(dataclasses.replace(table, claims=entries), rows, procedures())


# --- propagated names a slip ---------------------------------------------------------------


@pytest.mark.parametrize("key", PAPERS)
def test_no_propagated_row_names_a_source_without_a_slip(claims, key):
    formulas = {r.id: r for r in committed_formulas(key)}
    for rows in (claims[key], formulas):
        for row in rows.values():
            if row.cause != "propagated":
                continue
            assert row.cause_from, row.id
            for source in row.cause_from:
                s = rows[source]
                slip = getattr(s, "procedure_verdict", None) == "slip"
                assert slip or s.cause in ("propagated", *SLIP_CAUSES), (row.id, source)


# --- the README's counts are the code's ----------------------------------------------------


def test_readme_counts_of_causes_are_the_codes(claims):
    from pendcli.run.reproduce import ReproduceResult
    from tools.docs import causes_section

    text = README.read_text(encoding="utf-8")
    shown = text.split("<!-- causes:start -->\n", 1)[1].split("\n<!-- causes:end -->", 1)[0]
    result = ReproduceResult(papers=PAPERS, claims={k: list(claims[k].values()) for k in PAPERS})
    assert shown == causes_section(result)
    tally = cause_tally(claims["lecornu"].values())
    assert f"`propagated`, carrying an earlier slip: {tally.propagated} (" in shown
    slips = tally.roots["arithmetic-slip"]
    assert f"`arithmetic-slip`, slips of his own: {slips} (" in shown
