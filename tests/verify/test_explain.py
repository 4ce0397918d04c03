"""How the author got his digits: each mechanism recomputed independently, the
coincidence estimate on targets whose answer is known, every wrong digit accounted for, and
the CLI (json shape, one-line errors).

Independent means: Decimal quantize for the roundings, mpmath at 50 digits for the Bessel
values and zeros, plain Fraction arithmetic written out here for the author's formulas, never
the search's own output.
"""

from __future__ import annotations

import json
from decimal import ROUND_DOWN, ROUND_HALF_UP, Decimal
from fractions import Fraction

import mpmath
import pytest
from helpers.cli import assert_clean_error, invoke
from helpers.evaluated import committed_claims

from pendcli.data.tables import load_paper_table
from pendcli.papers.registry import PAPERS, explanations
from pendcli.verify import bessel_tables as bt
from pendcli.verify import explain as ex

F = Fraction


def _decimal(x: Fraction, places: int, mode: str) -> Fraction:
    q = (Decimal(x.numerator) / Decimal(x.denominator)).quantize(Decimal(1).scaleb(-places), mode)
    return Fraction(q)


@pytest.fixture(scope="module")
def rows() -> dict[str, ex.ExplainedRow]:
    out = {}
    for key in PAPERS:
        verdicts = {r.id: (r.verdict, r.cause, r.published) for r in committed_claims(key)}
        out |= {r.id: r for r in ex.explain_rows(key, explanations(key), verdicts)}
    return out


def _printed(key: str, claim_id: str) -> Fraction:
    return ex.printed_fraction(load_paper_table(key).claim(claim_id).number)


# --- exact rounding, against Decimal --------------------------------------------------------


@pytest.mark.parametrize(
    "x", [F(64779375, 10**7), F(-13079, 10**5), F(3125, 10**6), F(5, 1000), F(-25, 1000)]
)
@pytest.mark.parametrize("places", [0, 1, 2, 3, 5])
def test_round_and_chop_match_decimal(x, places):
    assert ex.round_half_up(x, places) == _decimal(x, places, ROUND_HALF_UP)
    assert ex.chop(x, places) == _decimal(x, places, ROUND_DOWN)


def test_significant_figures():
    assert ex.significant_round(F(3845521, 10**4), 3) == 385  # 19,61² to 3 figures
    assert ex.significant_round(F(3845521, 10**4), 3, "chop") == 384
    assert ex.significant_round(F(31416, 10**4) ** 2, 4) == F(9870, 1000)
    assert ex.significant_round(F(-2, 1000), 2) == F(-2, 1000)


# --- slips on the result --------------------------------------------------------------------


def test_digit_slips_are_each_one_named_change():
    slips = dict((v, label) for label, v in ex.digit_slips(647))
    expected = {
        648, 646, 657, 637, 747, 547,  # carries: one digit ±1
        674, 467,  # adjacent digits transposed
        947,  # 6 for 9 (inverted type)
        47, 67, 64,  # a digit dropped
        6647, 6447, 6477,  # a digit doubled
        -647,  # the sign
    }  # fmt: skip
    assert set(slips) == expected
    assert "transposed" in slips[674] and "inverted" in slips[947] and "sign" in slips[-647]
    assert all(v != 647 for v in slips)


def test_a_carry_that_changes_the_digit_count_is_a_slip_too():
    values = {v for _, v in ex.digit_slips(99)}
    assert 109 in values and 89 in values and 66 not in values  # 99 -> 66 is two changes
    assert {v for _, v in ex.digit_slips(-130)} >= {-131, -129, -230, -30, 130, -103}


# --- constants and the hypothesis of π = 3,14 for 6,47 ------------------------------------


def test_six_forty_seven_is_pi_314_chopped(rows):
    """The hypothesis: π(7π² - 3)/32 with π = 3,14 is 6,4779, chopped 6,47."""
    pi = F(314, 100)
    value = pi * (7 * pi**2 - 3) / 32
    assert value == F(647793775, 10**8)  # 6,47793775
    assert _decimal(value, 2, ROUND_DOWN) == _printed(
        "lecornu", "lecornu.mean_pendulum_coefficient"
    )
    with mpmath.workdps(50):  # with π exact it prints 6,49: the printed 6,47 is not that
        exact = mpmath.pi * (7 * mpmath.pi**2 - 3) / 32
        assert mpmath.nstr(exact, 3) == "6.49"
    row = rows["lecornu.mean_pendulum_coefficient"]
    assert row.explanation is not None
    best = row.explanation.chains[0]
    labels = [s.label for s in best.steps if s.steps]
    assert labels == ["π = 3,14", "chopped (decimals dropped)"]
    assert best.value == value


def test_coefficient_needs_g_98_rounded_half_up(rows):
    b = F(35, 100)
    value = b**2 / (4 * F(98, 10))
    assert value == F(3125, 10**6)
    assert _decimal(value, 5, ROUND_HALF_UP) == _printed("lecornu", "lecornu.coefficient_b2_4g")
    assert rows["lecornu.coefficient_b2_4g"].explanation.mechanism == "g = 9,8"


def test_time_094_is_a_borrow_slip_but_not_beyond_coincidence(rows):
    length = _printed("lecornu", "lecornu.example.length.2")  # 0,68
    with_slip = (1 - length + F(1, 100)) / F(35, 100)
    assert _decimal(with_slip, 2, ROUND_HALF_UP) == F(94, 100)
    assert _decimal((1 - length) / F(35, 100), 2, ROUND_HALF_UP) == F(91, 100)
    row = rows["lecornu.example.time.2"]
    assert "borrow slip" in row.explanation.mechanism
    assert not row.explained
    assert row.cause_with_mechanism == (
        f"arithmetic-slip; mechanism unexplained ({row.explanation.coincidence:.0%} of random "
        "targets fit)"
    )


def test_length_121_from_a_square_kept_to_three_figures(rows):
    z = _printed("lecornu", "lecornu.j1_zeros.1")  # 19,61
    assert z * z == F(3845521, 10**4)
    square = F(385)  # 384,5521 to three figures
    assert abs(z * z - square) < F(1, 2)
    value = _printed("lecornu", "lecornu.coefficient_b2_4g") * square
    assert _decimal(value, 2, ROUND_HALF_UP) == F(121, 100)
    assert rows["lecornu.j1_lengths.1"].explanation.mechanism == "z² rounded to 3 figures"


# --- the Bessel tables, against mpmath -------------------------------------------------------


def _j(order: int, x: Fraction) -> Fraction:
    with mpmath.workdps(50):
        return Fraction(
            mpmath.nstr(mpmath.besselj(order, mpmath.mpf(x.numerator) / x.denominator), 40)
        )


@pytest.mark.parametrize(("x", "d"), [(F(84, 10), 3), (F(85, 10), 4), (F(1796, 100), 4)])
def test_table_entries_are_true_values_rounded(x, d):
    assert bt.table_entry(0, x, d) == _decimal(_j(0, x), d, ROUND_HALF_UP)


def test_reversed_interpolation_gives_0072():
    """J_0(8,41) from J_0(8,4), J_0(8,5) at 3 decimals, the correction with its sign reversed."""
    lo, hi = (_decimal(_j(0, F(k, 10)), 3, ROUND_HALF_UP) for k in (84, 85))
    reversed_value = lo - (hi - lo) * F(1, 10)
    assert _decimal(reversed_value, 3, ROUND_HALF_UP) == _printed(
        "lecornu", "lecornu.j0_at_j2_zeros.2"
    )
    reading = bt.TableReading(F(1, 10), 3, "reversed")
    assert reading.read(0, F(841, 100)) == reversed_value
    right = bt.TableReading(F(1, 10), 3, "linear").read(0, F(841, 100))
    assert right == lo + (hi - lo) * F(1, 10) and abs(right - _j(0, F(841, 100))) < F(1, 1000)


def test_table_zero_is_regula_falsi_on_rounded_entries():
    step, d = F(1, 10), 4
    f = [2 * _decimal(_j(1, x), d, ROUND_HALF_UP) - x * _decimal(_j(0, x), d, ROUND_HALF_UP)
         for x in (F(84, 10), F(85, 10))]  # fmt: skip
    expected = F(84, 10) + step * f[0] / (f[0] - f[1])
    with mpmath.workdps(30):
        true = Fraction(mpmath.nstr(mpmath.besseljzero(2, 2), 25))
    assert bt.table_zero(2, true, step, d) == expected
    assert abs(expected - true) < F(1, 1000)


def test_tisserand_first_coefficient_from_his_series():
    with mpmath.workdps(50):
        u1 = mpmath.sin(mpmath.radians(15))
        p0, p1 = mpmath.mpf(1) / 4, u1**2
        rad = -(p0 - p1) * (mpmath.mpf(3) / 32 + 11 * (p0 + p1) / 256)
        seconds = rad * 648000 / mpmath.pi
        expected = int(mpmath.nint(seconds))
    target = _printed("tisserand", "tisserand.example.psi_sin2") * 3600
    assert expected == target == -4053  # -1°7'33''


# --- the coincidence estimate on targets with a known answer -------------------------------


def _every_two_digit_number() -> ex.Computation:
    values = ex.Axis("n", tuple(ex.Option(str(k), F(k, 100), 0) for k in range(10, 100)))
    return ex.Computation("n/100", (values,), lambda c: c["n"], slips=False)


def test_a_space_producing_every_two_digit_number_gives_rate_one():
    e = ex.explain("test.all", _every_two_digit_number(), ex.decimal_target("0,47", 0.47, 2))
    assert e.coincidence == 1.0 and e.coincidence_near == 1.0
    assert not e.explained


def test_a_space_producing_one_number_gives_rate_one_in_ninety():
    one = ex.Axis("n", (ex.Option("0,47", F(47, 100), 0),))
    comp = ex.Computation("n", (one,), lambda c: c["n"], slips=False, chop_allowed=False)
    e = ex.explain("test.one", comp, ex.decimal_target("0,47", 0.47, 2))
    share = 1 / 90  # 10 ... 99: one target in ninety is 47
    sigma = (share * (1 - share) / ex.RANDOM_TARGETS) ** 0.5
    assert abs(e.coincidence - share) < 4 * sigma
    assert e.explained


def test_a_constructed_target_is_found_by_its_mechanism():
    """Build a printed number by a known chain (π = 22/7, π² chopped to 3 figures, rounded)
    and check the search returns that chain as the simplest."""
    pi = F(22, 7)
    square = _decimal(pi * pi, 2, ROUND_DOWN)  # 9,8775... chopped to 3 figures: 9,87
    assert square == F(987, 100)
    value = pi * (7 * square - 3) / 32
    printed = _decimal(value, 3, ROUND_HALF_UP)
    comp = ex.Computation(
        "π(7π² - 3)/32",
        (ex.constant_axis("π", F(314159265358979, 10**14), ex.PI_READINGS), ex.rounding_axis("π²")),
        lambda c: c["π"] * (7 * c["π²"](c["π"] ** 2) - 3) / 32,
    )
    e = ex.explain("test.built", comp, ex.decimal_target(str(float(printed)), float(printed), 3))
    labels = [s.label for s in e.chains[0].steps if s.steps]
    assert labels == ["π = 22/7", "π² chopped to 3 figures"]


def test_lookup_equals_a_fresh_search_on_random_targets():
    """The rate's lookup in the costs reached is the same search run on each random target."""
    row_comp = ex.Computation(
        "π(7π² - 3)/32",
        (ex.constant_axis("π", F(314159265358979, 10**14), ex.PI_READINGS), ex.rounding_axis("π²")),
        lambda c: c["π"] * (7 * c["π²"](c["π"] ** 2) - 3) / 32,
    )
    target = ex.decimal_target("6,47", 6.47, 2)
    costs = ex.scan(row_comp, target).costs
    for units in [*ex.random_targets(target, 40, seed=7), 647, 649, 648]:
        fresh = ex.scan(row_comp, ex.Target(str(units), units, target.unit))
        assert fresh.best_cost == costs.get(units)


def test_random_targets_keep_size_and_sign():
    target = ex.decimal_target("-1,27", -1.27, 2)
    drawn = ex.random_targets(target, 500, seed=1)
    assert all(-999 <= t <= -100 for t in drawn) and len(set(drawn)) > 300
    assert drawn == ex.random_targets(target, 500, seed=1)  # deterministic
    near = ex.random_targets(target, 500, seed=1, near=True)
    assert all(-139 <= t <= -115 for t in near)  # 127 ± 12 (10 %)


# --- every wrong digit accounted for -----------------------------------------------------


@pytest.mark.parametrize("key", PAPERS)
def test_every_row_that_does_not_agree_has_an_explanation_or_a_stated_search(rows, key):
    wrong = [r.id for r in committed_claims(key) if r.verdict != "agrees"]
    for claim_id in wrong:
        row = rows[claim_id]
        assert row.explanation is not None, f"{claim_id}: no computation declared"
        d = row.as_dict()
        assert d["searched"] and "chains" in d["searched"]
        assert (d["mechanism"] is None) == (d["coincidence"] is None)


def test_lecornu_has_22_rows_that_do_not_agree(rows):
    assert sum(1 for r in rows.values() if r.paper == "lecornu" and r.verdict != "agrees") == 22


def test_an_unexplained_row_says_what_was_searched(rows):
    row = rows["lecornu.deviation.3"]  # +1,86: nothing in the space gives it
    d = row.as_dict()
    assert d["mechanism"] is None and d["steps"] == [] and d["coincidence"] is None
    assert "J_0(11,62)/J_0(17,96)" in d["searched"] and "table" in d["searched"]
    assert d["cause"] == "arithmetic-slip; mechanism unexplained"


def test_the_threshold_decides_explained(rows):
    for row in rows.values():
        e = row.explanation
        if e is not None and e.coincidence is not None:
            assert e.explained == (e.coincidence <= ex.COINCIDENCE_THRESHOLD)


# --- the CLI -------------------------------------------------------------------------------


@pytest.fixture
def searched_once(rows, monkeypatch):
    """For the tests of the command's form: the search of each committed claim (``explain``)
    answers with what the module's ``rows`` found for it (the same search, on the same
    computation and target); the command still selects, orders and writes the rows."""
    search = ex.explain

    def served(claim_id, computation, target):
        row = rows.get(claim_id)
        if row is None or row.explanation is None:
            return search(claim_id, computation, target)
        return row.explanation

    monkeypatch.setattr(ex, "explain", served)


@pytest.mark.usefixtures("shared_claims", "searched_once")
def test_cli_json_shape():
    code, out, _ = invoke("explain", "-p", "lecornu", "-f", "json")
    assert code == 0
    doc = json.loads(out)
    assert set(doc) == {"explanations"}
    assert len(doc["explanations"]) == 22
    for e in doc["explanations"]:
        assert {"id", "printed", "mechanism", "steps", "coincidence", "searched"} <= set(e)
    by_id = {e["id"]: e for e in doc["explanations"]}
    assert by_id["lecornu.mean_pendulum_coefficient"]["steps"][0][-1] == "printed 6,47"


@pytest.mark.usefixtures("shared_claims", "searched_once")
def test_cli_one_claim_and_formats():
    code, out, _ = invoke("explain", "lecornu.x_bound", "-f", "json")
    assert code == 0 and [e["id"] for e in json.loads(out)["explanations"]] == ["lecornu.x_bound"]
    for fmt in ("csv", "markdown", "table"):
        code, out, _ = invoke("explain", "tisserand.example.psi_sin2", "-f", fmt)
        assert code == 0 and "psi_sin2" in out


@pytest.mark.parametrize(
    "args",
    [
        ("explain", "lecornu.nope"),
        ("explain", "nope"),
        ("explain", "lecornu.speed.1"),  # agrees, nothing declared
        ("explain", "lecornu.x_bound", "-p", "tisserand"),
        ("explain", "-p", "nowhere"),
    ],
)
@pytest.mark.usefixtures("shared_claims")
def test_cli_bad_claim_is_one_line(args):
    code, _, err = invoke(*args)
    assert_clean_error(code, err)


# --- the README says what the search finds -------------------------------------------------


def test_readme_paragraph_matches_the_search(rows):
    from pathlib import Path

    page = Path(__file__).resolve().parents[2] / "docs" / "findings.md"
    text = page.read_text(encoding="utf-8")
    paragraph = " ".join(text.split("**How he got his digits**", 1)[1].split("\n\n", 1)[0].split())
    lecornu = [r for r in rows.values() if r.paper == "lecornu" and r.verdict != "agrees"]
    explained = sum(r.explained for r in lecornu)
    assert f"Of Lecornu's {len(lecornu)}, {explained} are" in paragraph
    unexplained = [r.printed for r in lecornu if not r.explained]
    assert f"{len(unexplained)} stay unexplained" in paragraph.replace("Four", "4")
    six = rows["lecornu.mean_pendulum_coefficient"].explanation
    assert f"({six.coincidence:.1%}".replace(".", ",").replace("%", " %") in paragraph


# --- the plain procedures and the chops, against the claims' own procedures and mpmath ------

PLAIN = [
    "lecornu.example.time.3",
    "lecornu.example.time.5",
    "lecornu.example.interval.1",
    "lecornu.example.interval.2",
    "lecornu.example.interval.5",
    "lecornu.deviation.5",
    "lecornu.deviation.zero_length",
]


@pytest.mark.parametrize("claim_id", PLAIN)
def test_plain_procedure_rows_match_the_claims_procedures(rows, claim_id):
    """'his plain procedure' must be what pendcli.papers.lecornu.claims says he did, on his
    printed values (a second implementation, in floating point), rounded at his precision."""
    from pendcli.papers.lecornu.claims import author_procedures
    from pendcli.verify.causes import rounds_to

    table = load_paper_table("lecornu")
    printed = {c.id: c.number.value for c in table.claims}
    assert rows[claim_id].explanation.mechanism == "his plain procedure (no departure)"
    assert rounds_to(table.claim(claim_id).number, author_procedures()[claim_id](printed))


@pytest.mark.parametrize(
    ("claim_id", "order", "k"),
    [("lecornu.j2_zeros.2", 2, 2), ("lecornu.j1_zeros.1", 1, 6), ("lecornu.j1_zeros.5", 1, 2)],
)
def test_chopped_zeros_against_mpmath(rows, claim_id, order, k):
    with mpmath.workdps(50):
        zero = Fraction(mpmath.nstr(mpmath.besseljzero(order, k), 40))
    printed = _printed("lecornu", claim_id)
    assert _decimal(zero, 2, ROUND_DOWN) == printed != _decimal(zero, 2, ROUND_HALF_UP)
    assert rows[claim_id].explanation.mechanism == "chopped (decimals dropped)"


def test_the_space_searched_names_its_slips():
    with_slips = ex.Computation("x", (), lambda c: F(1), slips=True).describe()
    without = ex.Computation("x", (), lambda c: F(1), slips=False).describe()
    assert with_slips.endswith("dropped/doubled digit, sign)")
    assert without.endswith("no slip on the result")
