"""The numeric mode of the printed-form engine (pendcli/verify/printed_numeric.py):
printed numbers judged by their printed digits against computed values, on hand-checked cases
(rounding against truncation, one unit off in the last place, a list with one wrong entry, a
correction that is or is not the computed one), the ledger rows whose printed form is numbers
(their status computed, their numbers tied to the published claims, each number's claim
printed on the row's lines), and mutations of those rows in a copy of tables/."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from itertools import pairwise
from pathlib import Path

import mpmath
import pytest
from helpers.ledgers import committed_ledger
from helpers.mutations import altered_tables

from pendcli.data.ledger import load_ledger
from pendcli.data.ledger_rows import LedgerRow
from pendcli.data.printed import parse_formula
from pendcli.data.tables import clear_table_cache, load_paper_table
from pendcli.papers.registry import paper as paper_named
from pendcli.verify.ledger_references import verify_printed
from pendcli.verify.printed_check import Reference
from pendcli.verify.printed_numeric import Numbers, numeric_status, printed_numbers

ROOT = Path(__file__).resolve().parents[2]
TABLES = ROOT / "tables"
LECORNU = paper_named("lecornu").references()
SYMBOLS = {"l": "L", "b": "L T^-1", "g": "L T^-2", "xi": "1", "z": "1", "metre": "L", "x": "1"}

# the rows whose printed form is numbers, and the reference each gives
NUMERIC_ROWS = {
    "lecornu.eq.15": "numbers_j2_roots",
    "lecornu.result.table_speeds": "numbers_table_speeds",
    "lecornu.eq.16": "numbers_eq16",
    "lecornu.result.table_lengths": "numbers_table_lengths",
    "lecornu.result.table_times": "numbers_table_times",
    "lecornu.result.table_intervals": "numbers_table_intervals",
    "lecornu.result.table_j0": "numbers_table_j0",
    "lecornu.result.table_amplitudes": "numbers_table_amplitudes",
    "lecornu.result.table_j1_roots": "numbers_j1_roots",
    "lecornu.result.table_vertical_lengths": "numbers_vertical_lengths",
}


def _status(
    printed: str,
    values: list[object],
    reading: str | None = None,
    corrected: str | None = None,
    **kw: object,
) -> tuple[str | None, str]:
    def formula(text: str | None) -> object:
        return None if text is None else parse_formula("test", text, SYMBOLS)

    numbers = Numbers(tuple(values), what="hand values", **kw)  # type: ignore[arg-type]
    return numeric_status(formula(printed), formula(reading), formula(corrected), numbers)  # type: ignore[arg-type]


# --- hand-checked cases --------------------------------------------------------------------


def test_a_rounded_number_holds_and_says_so() -> None:
    status, why = _status("5.14", [mpmath.mpf("5.135622")])
    assert status == "holds" and "5.14 agrees" in why


def test_a_chopped_number_holds_as_a_truncation() -> None:
    # 8.41724 rounds to 8.42 and chops to 8.41: the rule of verdict.judge, said in the reason
    status, why = _status("8.41", [mpmath.mpf("8.417244")])
    assert status == "holds" and "8.41 truncated" in why
    assert _status("8.42", [mpmath.mpf("8.417244")])[0] == "holds"


def test_one_unit_off_in_the_last_place_is_refused() -> None:
    # 5.1356: 5.15 is one unit above its rounding (last-digit), 5.12 two below
    for printed in ("5.15", "5.12"):
        status, why = _status(printed, [mpmath.mpf("5.135622")])
        assert status is None, printed
        assert f"#1 {printed}" in why
    # 5.13 is one unit below 5.14, but it is 5.1356 chopped: a truncation, not a slip
    assert _status("5.13", [mpmath.mpf("5.135622")])[0] == "holds"


def test_a_value_on_the_half_unit_rounds_either_way() -> None:
    # b²/(4g) at b = 0,35, g = 9,80 is 0,003125 exactly: printed 0,00313 or 0,00312 both round
    exact = Fraction(35, 100) ** 2 / (4 * Fraction(980, 100))
    assert exact == Fraction(3125, 10**6)
    assert _status("0.00313", [exact])[0] == "holds"
    assert _status("0.00312", [exact])[0] == "holds"
    # at g = 9,81 it is 0,0031218: 0,00313 is one unit off
    assert _status("0.00313", [Fraction(35, 100) ** 2 / (4 * Fraction(981, 100))])[0] is None


def test_a_list_is_judged_entry_by_entry_and_names_the_wrong_one() -> None:
    values = [mpmath.mpf(v) for v in ("1.218715", "0.744849", "0.539086")]
    assert _status("1.22; 0.74; 0.54", values)[0] == "holds"
    status, why = _status("1.22; 0.75; 0.54", values)
    assert status is None
    assert "1 of 3 off" in why and "#2 0.75" in why and "#1" not in why.split("off")[1]


def test_signs_places_and_name_value_pairs_are_read_as_printed() -> None:
    entries = printed_numbers("-0.130; +0.072; z = 17.96; 1; l = 0.00313*metre*z**2")
    shown = [(e.name, e.number.text, e.number.decimals) for e in entries]
    assert shown == [
        ("", "-0.130", 3),
        ("", "+0.072", 3),
        ("z", "17.96", 2),
        ("", "1", 0),
        ("", "0.00313", 5),  # a decimal inside a formula; its 2 and the z's are notation
    ]
    assert _status("-0.130", [mpmath.mpf("0.1308")])[0] is None  # the sign counts


def test_a_count_mismatch_is_refused() -> None:
    status, why = _status("1.22; 0.74", [1.2187, 0.7448, 0.5391])
    assert status is None and "2 printed numbers, 3 computed" in why


def test_a_correction_must_be_the_computed_value_rounded_to_the_printed_places() -> None:
    value = [mpmath.mpf(32) / 35]  # (1 − 0,68)/0,35 = 0,9143
    assert _status("0.94", value, corrected="0.91")[0] == "fails"
    for wrong in ("0.92", "0.914", "0.94"):
        assert _status("0.94", value, corrected=wrong)[0] is None, wrong
    # a correction that only chops the computed value is not the computed one
    assert _status("0.94", [mpmath.mpf("0.9178")], corrected="0.91")[0] is None
    # entries that pass as printed may stay as printed (a chopped one included)
    values = [mpmath.mpf("1.20365"), mpmath.mpf("0.555332")]
    assert _status("1.21; 0.55", values, corrected="1.20; 0.55")[0] == "fails"
    assert _status("1.21; 0.55", values, corrected="1.20; 0.56")[0] == "fails"


def test_a_misprint_needs_its_reading_to_pass_and_its_printed_form_to_fail() -> None:
    value = [mpmath.mpf("0.0664476")]
    assert _status("0.072", value, reading="0.066")[0] == "misprint"
    assert _status("0.072", value, reading="0.072")[0] is None
    # a printed form that holds is holds, whatever the reading says
    assert _status("0.066", value, reading="0.072")[0] == "holds"


def test_a_formula_with_a_printed_decimal_checks_its_identities_too() -> None:
    import sympy as sp

    b, g, z = sp.symbols("b g z", real=True)
    identity = Reference({"xi": z**2 / 4, "l": b**2 / g * z**2 / 4})
    printed = "l = b**2/g*xi = b**2/(4*g)*z**2 = 0.00313*metre*z**2"
    value = [Fraction(3125, 10**6)]
    assert _status(printed, value, identity=identity)[0] == "holds"
    wrong = "l = b**2/g*xi = b**2/(2*g)*z**2 = 0.00313*metre*z**2"  # 4g -> 2g
    status, why = _status(wrong, value, identity=identity)
    assert status is None and "identities" in why
    assert _status(printed, value)[0] is None  # an identity without its reference


def test_a_printed_number_that_is_not_the_published_claims_is_refused() -> None:
    claim = load_paper_table("lecornu", TABLES).claim("lecornu.j2_zeros.1").number
    tie = (("lecornu.j2_zeros.1", claim),)
    assert _status("5.14", [mpmath.mpf("5.1356")], published=tie)[0] == "holds"
    status, why = _status("5.140", [mpmath.mpf("5.1356")], published=tie)
    assert status is None and "lecornu.j2_zeros.1" in why


# --- the ledger's numeric rows ---------------------------------------------------------------


def _rows() -> dict[str, LedgerRow]:
    """The committed ledger's rows (loaded once per process: tests/helpers/ledgers.py)."""
    return {r.id: r for r in committed_ledger("lecornu").rows}


# Each row's status, computed by its printed numbers, is the recorded one: judged once, with
# every ledger row, in tests/data/test_ledger.py (test_the_engine_computes_the_recorded_status).
@pytest.mark.parametrize(("row_id", "reference"), NUMERIC_ROWS.items())
def test_each_numeric_row_has_its_reference(row_id: str, reference: str) -> None:
    assert _rows()[row_id].reference == reference


@pytest.mark.parametrize("row_id", NUMERIC_ROWS)
def test_each_printed_number_is_the_published_claims_on_the_rows_lines(row_id: str) -> None:
    row = _rows()[row_id]
    numbers = LECORNU[NUMERIC_ROWS[row_id]]()
    entries = printed_numbers(row.printed or "")
    claims = load_paper_table("lecornu", TABLES)
    assert len(numbers.published) == len(entries) == len(numbers.values)
    for entry, tie in zip(entries, numbers.published, strict=True):
        if tie is None:  # the +θ0 of line 246: the normalisation, no claim (see the table)
            assert row_id == "lecornu.result.table_amplitudes" and entry.place == 1
            continue
        claim = claims.claim(tie[0])
        assert claim.lines is not None and row.lines is not None
        assert row.lines[0] <= claim.lines[0] <= claim.lines[1] <= row.lines[1], tie[0]
        # the ledger's number is the claim's, digit for digit (decimal comma read as point)
        assert entry.number.value == claim.number.value, tie[0]
        assert entry.number.decimals == claim.number.decimals, tie[0]


def test_the_intervals_are_the_differences_of_the_printed_instants_exactly() -> None:
    # the second method for the changed status: exact rationals, not mpmath
    claims = load_paper_table("lecornu", TABLES)
    ids = [f"lecornu.example.time.{k}" for k in range(1, 6)] + ["lecornu.example.time_zero_length"]
    numbers = [claims.claim(i).number for i in ids]
    instants = [Fraction(f"{n.value:.{n.decimals}f}") for n in numbers]
    gaps = [b - a for a, b in pairwise(instants)]
    printed = [Fraction(e.number.text) for e in printed_numbers("0.94; 0.72; 0.57; 0.40; 0.23")]
    assert gaps == printed


def _altered(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, *edits: tuple[str, str, str]
) -> tuple[LedgerRow, ...]:
    """A copy of tables/ with ``(file, old, new)`` edits, which the run then reads (the
    references read the published table of $PENDCLI_TABLES); the ledger's rows."""
    root = altered_tables(tmp_path, *edits)
    monkeypatch.setenv("PENDCLI_TABLES", str(root))
    clear_table_cache()
    return load_ledger("lecornu", root).rows


def _verified(row_id: str, rows: tuple[LedgerRow, ...], root: Path) -> tuple[str, str]:
    row = next(r for r in rows if r.id == row_id)
    computed, problem = verify_printed(row, load_ledger("lecornu", root).symbols_for(row), LECORNU)
    assert computed is not None and problem is not None, f"{row_id}: not refused"
    return computed, problem


LEDGER = "equations/lecornu.toml"
PUBLISHED = "published/lecornu.toml"
HOLDS_EDITS = [
    # (15)'s numbers with the key after them: lecornu.result.decimals_neglected prints them too
    ("lecornu.eq.15", "14.80; 17.96'\nstatus", "14.81; 17.96'\nstatus"),
    ("lecornu.result.table_speeds", "'1.22; 0.74; 0.54; 0.42;", "'1.22; 0.74; 0.55; 0.42;"),
    ("lecornu.result.table_j1_roots", "10.17; 7.01; 3.83'", "10.17; 7.01; 3.84'"),
    ("lecornu.result.table_intervals", "'0.94; 0.72; 0.57; 0.40;", "'0.94; 0.72; 0.57; 0.41;"),
    ("lecornu.result.table_lengths", "'1; 0.68; 0.42; 0.22;", "'1; 0.68; 0.43; 0.22;"),
]


@pytest.fixture(autouse=True)
def _fresh_tables() -> Iterator[None]:
    clear_table_cache()
    yield
    clear_table_cache()


@pytest.mark.parametrize(("row_id", "old", "new"), HOLDS_EDITS)
def test_one_printed_digit_changed_in_a_holds_row_is_refused_naming_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, row_id: str, old: str, new: str
) -> None:
    rows = _altered(tmp_path, monkeypatch, (LEDGER, old, new))
    computed, problem = _verified(row_id, rows, tmp_path / "tables")
    assert problem.startswith("recorded holds") and not computed.startswith("holds")


def test_a_digit_changed_in_both_the_ledger_and_the_claims_is_refused_by_the_digits(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # 14,80 -> 14,81 in (15) and in its claim: the tie holds, the rounding rule refuses
    rows = _altered(
        tmp_path,
        monkeypatch,
        (LEDGER, "14.80; 17.96'\nstatus", "14.81; 17.96'\nstatus"),
        (PUBLISHED, 'published = "14,80"', 'published = "14,81"'),
    )
    _, problem = _verified("lecornu.eq.15", rows, tmp_path / "tables")
    assert "#4 14.81: computed 14.796, last-digit" in problem
    assert "not the published" not in problem


def test_a_fails_row_set_to_its_correction_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the ledger alone: refused as no longer the published number; with the claim too, it
    # is refused because the correction now holds (recorded fails, computed holds)
    old, new = "printed = '0; 0.94; 1.66; 2.23; 2.63'", "printed = '0; 0.91; 1.66; 2.23; 2.63'"
    rows = _altered(tmp_path, monkeypatch, (LEDGER, old, new))
    _, problem = _verified("lecornu.result.table_times", rows, tmp_path / "tables")
    assert "is not claim lecornu.example.time.2's" in problem
    rows = _altered(
        tmp_path / "both",
        monkeypatch,
        (LEDGER, old, new),
        (
            PUBLISHED,
            '0^{sec},94"\nas_printed = "0^{sec}, 94"\nnote = "Arith',
            '0^{sec},91"\nnote = "Arith',
        ),
    )
    _, problem = _verified("lecornu.result.table_times", rows, tmp_path / "both" / "tables")
    assert "recorded fails, but the printed form gives holds" in problem


# --- Tisserand's numerical application, and the identity rows of Lecornu's § II --------------

TISSERAND_LEDGER = "equations/tisserand.toml"


def _verified_in(
    paper: str, row_id: str, root: Path | None = None
) -> tuple[str | None, str | None]:
    """The row's computed status and problem, in ``root``'s ledger (default the committed one,
    loaded once per process)."""
    ledger = committed_ledger(paper) if root is None else load_ledger(paper, root)
    row = next(r for r in ledger.rows if r.id == row_id)
    return verify_printed(row, ledger.symbols_for(row), paper_named(paper).references())


@pytest.mark.parametrize(
    ("paper", "row_id", "status"),
    [
        ("tisserand", "tisserand.result.numerical-application", "holds"),
        ("tisserand", "tisserand.result.displacement", "holds"),
        ("lecornu", "lecornu.result.table_26", "holds"),
        ("lecornu", "lecornu.result.largest_length_comparison", "misprint"),
        ("lecornu", "lecornu.result.c_equals_4_over_pi", "holds"),
        ("lecornu", "lecornu.result.amplitude_factor", "holds"),
        ("charbonnier", "charbonnier.result.in-pi", "holds"),
    ],
)
def test_the_rows_record_the_status_worked_out_by_hand(
    paper: str, row_id: str, status: str
) -> None:
    """The engine computes each recorded status (tests/data/test_ledger.py, every row once):
    these rows' statuses, worked out by hand, are the recorded ones."""
    assert next(r for r in committed_ledger(paper).rows if r.id == row_id).status == status


def test_tisserands_amplitudes_in_minutes_give_none_of_his_coefficients() -> None:
    # the OCR reading's two sides: 30°, 15° (read) give all three coefficients; 30', 15'
    # (the OCR's primes, the reading removed) give about 1'' for 1°7'33''
    import dataclasses

    computed, _ = _verified_in("tisserand", "tisserand.result.numerical-application")
    assert computed is not None and computed.startswith("holds:")
    assert "1°7'33'' agrees" in computed and "2'42'' agrees" in computed
    ledger = committed_ledger("tisserand")
    row = next(r for r in ledger.rows if r.id == "tisserand.result.numerical-application")
    assert [i for i, _ in row.readings] == ["degree-as-prime"]
    unread = dataclasses.replace(row, readings=())
    references = paper_named("tisserand").references()
    computed, problem = verify_printed(unread, ledger.symbols_for(row), references)
    assert "3 of 3 off, theta0 = 0.5, theta1 = 0.25" in f"{computed} {problem}"


@pytest.mark.parametrize(
    ("paper", "row_id", "old", "new"),
    [
        # an amplitude the reading does not read: refused (recorded holds, computed not)
        ("tisserand", "tisserand.result.numerical-application",
         "printed = 'theta0 = 30*arcmin; theta1 = 15*arcmin;",
         "printed = 'theta0 = 30*arcmin; theta1 = 14*arcmin;"),
        ("lecornu", "lecornu.result.largest_length_comparison",
         "printed = 'dasc = (3*pi**2 + 12*b)/(16*g); ddesc = (pi**2 - 12*b)/(16*g)'",
         "printed = 'dasc = (3*pi**2 + 12)*b/(16*g); ddesc = (pi**2 - 12)*b/(16*g)'"),
        # one coefficient of a holds row: refused
        ("lecornu", "lecornu.result.table_26", "tv2 = pi*sqrt(a/g) + pi**2*b/(4*g)",
         "tv2 = pi*sqrt(a/g) + pi**2*b/(8*g)"),
        ("tisserand", "tisserand.result.displacement", "shift = mm/5'", "shift = mm/6'"),
        ("lecornu", "lecornu.result.c_equals_4_over_pi", "; C = 4/pi'", "; C = 3/pi'"),
        ("lecornu", "lecornu.result.amplitude_factor", "theta = R*cos(3*b/", "theta = R*cos(2*b/"),
        ("lecornu", "lecornu.result.amplitude_factor", "= R/l**(3/4)'", "= R/l**(1/2)'"),
        ("charbonnier", "charbonnier.result.in-pi", "Ipi_even = 2*factorial2(n)/factorial2(n + 1)",
         "Ipi_even = 2*factorial2(n)/factorial2(n + 2)"),
        ("charbonnier", "charbonnier.result.in-pi", "Ipi_odd = pi*factorial2(n)",
         "Ipi_odd = 2*factorial2(n)"),
        ("lecornu", "lecornu.result.c_equals_4_over_pi", "*sin(omega)**2, (omega, 0, pi/2)); C",
         "*sin(omega)**3, (omega, 0, pi/2)); C"),
    ],
)  # fmt: skip
def test_an_edit_of_the_printed_form_is_refused_naming_the_row(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, paper: str, row_id: str, old: str, new: str
) -> None:
    _altered(tmp_path, monkeypatch, (f"equations/{paper}.toml", old, new))
    _, problem = _verified_in(paper, row_id, tmp_path / "tables")
    assert problem is not None and problem.startswith("recorded "), row_id
