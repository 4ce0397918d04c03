"""A claim's verdict that turns on an unstated assumption carries the condition, and a
procedure's finishing rule is data: each against an independent computation (mpmath)."""

from __future__ import annotations

import mpmath
import pytest
from helpers.evaluated import committed_claims

from pendcli.base.errors import PendcliError
from pendcli.data.numbers import parse_printed
from pendcli.verify.causes import Judged, Procedure, own_verdicts

B, LENGTH = "0.35", "1"


@pytest.fixture(scope="module")
def lecornu_across_g():  # type: ignore[no-untyped-def]
    return {r.id: r for r in committed_claims("lecornu")}


def _time_3(g: mpmath.mpf) -> mpmath.mpf:
    """The third elongation's time (1 − (b²/4g)·j²)/b, j the third zero of J_2 from the top."""
    j = mpmath.besseljzero(2, 3)
    b = mpmath.mpf(B)
    return (mpmath.mpf(LENGTH) - b**2 / (4 * g) * j**2) / b


def test_the_coefficient_and_its_row_turn_at_the_same_g(lecornu_across_g) -> None:  # type: ignore[no-untyped-def]
    """0,00313 agrees for g <= 9.8 and is one unit off above, in the claim as in ledger row
    (16); its cause above is the row's status."""
    from helpers.ledgers import committed_row

    row = lecornu_across_g["lecornu.coefficient_b2_4g"]
    assert row.condition is not None and row.condition.startswith(
        "agrees for g <= 9.8, last-digit for g > 9.8 (assumption g: from 9.78 to 9.83"
    )
    ledger = committed_row("lecornu.eq.16")
    assert ledger.condition == "g <= 9.80" and row.cause == ledger.status == "misprint"
    from fractions import Fraction

    # b²/(4g) at 9,80 is exactly 0,003125: half up to 0,00313
    assert Fraction(B) ** 2 / (4 * Fraction("9.80")) == Fraction("0.003125")


def test_the_1_66_turns_where_mpmath_says(lecornu_across_g) -> None:  # type: ignore[no-untyped-def]
    """1,66: last-digit at the tables' 9,81, agrees above the g where the time reaches
    1,655 (found here by mpmath's root finder, never typed)."""
    with mpmath.workdps(30):
        g = mpmath.findroot(lambda g: _time_3(g) - mpmath.mpf("1.655"), mpmath.mpf("9.82"))
    row = lecornu_across_g["lecornu.example.time.3"]
    assert row.condition is not None, row
    bound = float(row.condition.split("g <= ", 1)[1].split(",", 1)[0])
    assert bound == pytest.approx(float(g), abs=1e-4)
    assert row.condition.startswith("last-digit for g <= ") and "agrees for g > " in row.condition


def test_a_claim_that_never_turns_has_no_condition(lecornu_across_g) -> None:  # type: ignore[no-untyped-def]
    for claim_id in ("lecornu.j0_at_j2_zeros.1", "lecornu.deviation.2", "lecornu.j2_zeros.1"):
        assert lecornu_across_g[claim_id].condition is None, claim_id


def test_faithful_only_if_chopped_is_said_so(lecornu_across_g) -> None:  # type: ignore[no-untyped-def]
    """−0,130 for his J₀(5,14) = −0,13079 (mpmath): rounded it is −0,131, chopped −0,130; his
    procedure rounds, so the verdict is conditional, not a bare faithful."""
    with mpmath.workdps(30):
        his = mpmath.besselj(0, mpmath.mpf("5.14"))
        assert mpmath.nint(his * 1000) == -131 and int(his * 1000) == -130
    assert lecornu_across_g["lecornu.j0_at_j2_zeros.1"].procedure_verdict == "faithful if chopped"


def test_the_finishing_rule_is_data() -> None:
    """A made-up 0,13 from 0,1349 (rounds to 0,13) and 0,139 (chops to 0,13): faithful or
    conditional by the procedure's rule; a chopped rule needs the text's words. From an input
    printed 1,0 (0,95 to 1,05), 0,141·z finishes to 0,13 only below z = 0,957: faithful if he
    kept more digits of z than he printed."""
    claims = {"z": Judged(parse_printed("1,000"), 1.0), "n": Judged(parse_printed("0,13"), 0.2)}
    for value, rounding, said, verdict in (
        (0.1349, "rounded", "", "faithful"),
        (0.139, "rounded", "", "faithful if chopped"),
        (0.139, "chopped", "je néglige", "faithful"),
        (0.1251, "chopped", "je néglige", "faithful if rounded"),
        (0.15, "rounded", "", "slip"),
    ):
        procedure = Procedure(("z",), lambda z, v=value: v * z, "v·z", rounding, said)
        assert own_verdicts(claims, {"n": procedure})["n"].verdict == verdict, (value, rounding)
    coarse = {**claims, "z": Judged(parse_printed("1,0"), 1.0)}
    procedure = Procedure(("z",), lambda z: 0.141 * z, "0,141·z")
    assert own_verdicts(coarse, {"n": procedure})["n"].verdict == "faithful if he kept more digits"
    assert own_verdicts(claims, {"n": procedure})["n"].verdict == "slip"  # z printed 1,000
    with pytest.raises(PendcliError, match="quotes the text's words"):
        Procedure(("z",), lambda z: z, "z", "chopped")


def test_the_difference_figure_shows_both_verdicts(lecornu_across_g) -> None:  # type: ignore[no-untyped-def]
    """Each bar's fill follows its verdict against his procedure (a slip crossed, faithful if
    chopped hatched, none dotted), and a legend names colours and fills; the title names no
    colour."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    from pendcli.papers.lecornu import figures

    fig, ax = plt.subplots()
    try:
        figures.draw_printed_minus_recomputed(ax, lecornu_across_g, 9.81)
        ids = [cid for _, group in figures.GROUPS for cid in group]
        bars = [bar for container in ax.containers for bar in container]
        hatches = {"slip": "xx", "faithful if chopped": "//", None: "..", "faithful": ""}
        hatches["faithful if he kept more digits"] = "--"
        for bar, cid in zip(bars, ids, strict=True):
            own = lecornu_across_g[cid].procedure_verdict
            assert (bar.get_hatch() or "") == hatches[None if own is None else str(own)], cid
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert "truth: discrepant" in labels and any(t.startswith("own: a slip") for t in labels)
        assert "green" not in ax.get_title() and "red" not in ax.get_title()
    finally:
        plt.close(fig)


def test_every_conditional_row_and_its_claims_turn_at_one_bound(lecornu_across_g) -> None:  # type: ignore[no-untyped-def]
    """A ledger row whose verdict turns on g and the claims that print its numbers (its
    reference's ``published``) turn at the same bound, the row's status on the assumption's
    far side being the claims' cause there: the same number, the same verdict."""
    from helpers.ledgers import committed_ledger

    from pendcli.papers.registry import paper

    references = paper("lecornu").references()
    checked = 0
    for row in committed_ledger("lecornu").rows:
        if row.condition is None or row.reference is None:
            continue
        bound = float(row.condition.split()[-1])
        for entry in references[row.reference]().published:
            if entry is None:
                continue
            claim = lecornu_across_g[entry[0]]
            assert claim.condition is not None, claim.id
            claim_bound = float(claim.condition.split(" <= ", 1)[1].split(",", 1)[0])
            assert claim_bound == pytest.approx(bound, abs=1e-4), claim.id
            assert claim.cause == row.status, claim.id
            checked += 1
    assert checked >= 1


def _printed(claim_id: str) -> tuple[mpmath.mpf, mpmath.mpf]:
    """A printed number of Lecornu's table and half a unit of its last printed place."""
    from pendcli.data.tables import load_paper_table

    number = load_paper_table("lecornu").claim(claim_id).number
    return mpmath.mpf(number.value), mpmath.mpf(number.resolution) / 2


def test_a_ratio_faithful_only_with_digits_he_kept(lecornu_across_g) -> None:  # type: ignore[no-untyped-def]
    """−3,45 = his J₀(8,41)/J₀(17,96): the printed +0,072 and −0,021 give −3,43, but his
    J₀(17,96) unrounded (mpmath) with a numerator anywhere that prints +0,072 reaches −3,45;
    −1,27 = J₀(14,80)/J₀(17,96) is reached by none of his own digits (both J₀ faithful: their
    unrounded values give −1,30), so it stays a slip of his. Every printed number is read
    from the table."""
    with mpmath.workdps(30):
        first = mpmath.besselj(0, _printed("lecornu.j2_zeros.5")[0])
        numerator, half = _printed("lecornu.j0_at_j2_zeros.2")
        ratio, ratio_half = _printed("lecornu.deviation.4")
        low, high = (numerator - half) / first, (numerator + half) / first
        reach = (min(low, high), max(low, high))  # his digits of +0,072 over his J₀(17,96)
        assert reach[0] <= ratio + ratio_half and ratio - ratio_half <= reach[1]
        printed_ratio = numerator / _printed("lecornu.j0_at_j2_zeros.5")[0]
        assert abs(printed_ratio - ratio) > ratio_half  # the printed inputs do not
        unrounded = mpmath.besselj(0, _printed("lecornu.j2_zeros.4")[0]) / first
        deviation_2, half_2 = _printed("lecornu.deviation.2")
        assert abs(unrounded - deviation_2) > 4 * half_2  # his unrounded J₀ give −1,30
    rows = lecornu_across_g
    assert rows["lecornu.deviation.4"].procedure_verdict == "faithful if he kept more digits"
    assert rows["lecornu.deviation.4"].cause == "propagated"
    assert rows["lecornu.deviation.2"].procedure_verdict == "slip"
