"""The ledger's rules for blame, findings, OCR readings and conditional verdicts
(tables/README.md): each checked against the raw TOML and the paper's text read here, or
against an independent computation, and each broken on purpose to see it refused."""

from __future__ import annotations

import csv
import dataclasses
import re
import tomllib
from fractions import Fraction
from pathlib import Path

import pytest
from helpers.ledgers import committed_ledger, committed_row
from helpers.mutations import altered_ledger, altered_row, edit_once

from pendcli.base.errors import PendcliError
from pendcli.data.ledger import load_ledger
from pendcli.papers.registry import paper
from pendcli.run.reproduce import ReproduceResult
from pendcli.verify.ledger_evaluation import Evaluated, coverage
from pendcli.verify.ledger_references import conditional, verify_printed

TABLES = Path(__file__).resolve().parents[2] / "tables"
PAPERS = ("tisserand", "lecornu", "charbonnier")
FLAWED = ("fails", "misprint")


def _raw(name: str) -> dict[str, object]:
    return tomllib.loads((TABLES / "equations" / f"{name}.toml").read_text("utf-8"))


def _text_lines(name: str) -> list[str]:
    return (TABLES / "papers" / f"{name}.txt").read_text("utf-8").splitlines()


def _as_list(value: object) -> list[str]:
    return [value] if isinstance(value, str) else list(value or [])  # type: ignore[call-overload]


# --- blame: the later use that decides a slip ---------------------------------------------


@pytest.mark.parametrize("name", PAPERS)
def test_every_slip_records_the_later_use_that_decides_it(name: str) -> None:
    """Read with tomllib and the text alone: a fails row that restates no other names the
    lines of its later use and the words there; a misprint those or why none; each word on
    one of the lines, none of them before the row."""
    lines = _text_lines(name)
    for entry in _raw(name)["equation"]:  # type: ignore[union-attr]
        if entry["status"] not in FLAWED or "restates" in entry:
            assert "unused" not in entry or entry["status"] == "misprint", entry["id"]
            continue
        if entry["status"] == "fails":
            assert entry.get("used_at") and "unused" not in entry, entry["id"]
        else:
            assert bool(entry.get("used_at")) != bool(entry.get("unused")), entry["id"]
        where = [lines[n - 1] for n in entry.get("used_at", [])]
        assert all(n > entry["lines"][1] for n in entry.get("used_at", [])), entry["id"]
        for word in _as_list(entry.get("used")):
            assert any(word in line for line in where), (entry["id"], word)


def _edited(name: str, within: str, *edits: tuple[str, str]) -> object:
    """The committed ledger ``name`` with ``edits`` made in row ``within``, validated."""
    from pendcli.data.ledger import ledger_path, parse_ledger

    text = (TABLES / "equations" / f"{name}.toml").read_text("utf-8")
    for old, new in edits:
        text = edit_once(text, old, new, within)
    return parse_ledger(tomllib.loads(text), name, ledger_path(name, TABLES), TABLES)


def test_a_fails_row_without_a_later_use_is_refused() -> None:
    """The axes' later use removed: a slip nothing later is shown to carry is no failure."""
    row = "lecornu.result.trajectory_after_52"
    used = "used = '\\operatorname{arc\\,tg} \\frac{\\rho_2 y}{\\rho_1 x}'\n"
    with pytest.raises(PendcliError, match=r"trajectory_after_52: a fails row records the later"):
        _edited("lecornu", row, ("used_at = [1132]\n", ""), (used, ""))


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        # a word the line does not print
        ('used = "k^{n-3}"', 'used = "k^{n+3}"', r"used 'k\^\{n\+3\}' is on none of the lines"),
        # a line before the row
        ("used_at = [530]", "used_at = [300]", r"used_at line 300 is not a later use"),
        # both records
        ("used_at = [530]", 'unused = "-"\nused_at = [530]', "either 'used_at' or 'unused'"),
    ],
)
def test_a_bad_later_use_is_refused(old: str, new: str, message: str) -> None:
    with pytest.raises(PendcliError, match=message):
        altered_ledger("charbonnier", old, new, "charbonnier.result.ec-monomial")


def test_the_two_slips_of_charbonnier_are_misprints_by_n17() -> None:
    """n° 17 (lines 530-534) computes with E_s(π/2) and k^(n−1): (9)'s E_c(π/2) and line
    435's k^(n+1) are not carried. Independently: with E_c = B_n/(n+1)·k^m αⁿ l0ⁿ sin^(n+1),
    ΔT½ = c/(k²αl0)·E_c(π/2) has k^(m−2); the printed k^(n−3) needs m = n − 1; and
    Δv_m = (k/2)l0Δα with Δα = −b_n k^(n−2) αⁿ l0^(n−1) I_n(π), I_n(π) = 2 I_n(π/2), is
    −c B_n k^(n−1) αⁿ l0ⁿ I_n(π/2) = −c E_s(π/2), not −c E_c(π/2) = −c B_n k^(n−1)αⁿl0ⁿ/(n+1)."""
    import sympy as sp

    k, alpha, l0, c, b_n, n = sp.symbols("k alpha l0 c B_n n", positive=True)
    m = sp.Symbol("m")
    assert sp.solve(sp.Eq(m - 2, n - 3), m) == [n - 1]
    half = sp.Symbol("I_half", positive=True)  # I_n(π/2)
    delta_alpha = -c * b_n * k ** (n - 2) * alpha**n * l0 ** (n - 1) * 2 * half
    e_s = b_n * k ** (n - 1) * alpha**n * l0**n * half
    assert sp.simplify(k / 2 * l0 * delta_alpha + c * e_s) == 0
    for row_id in ("charbonnier.eq.9", "charbonnier.result.ec-monomial"):
        row = committed_row(row_id)
        assert (row.status, row.used_at) == ("misprint", (534,) if "eq.9" in row_id else (530,))


# --- one entry per finding -----------------------------------------------------------------


def _independent_counts(name: str) -> dict[str, int]:
    """From the raw TOML: findings (fails or misprint, restating no row) and restating rows."""
    flawed = [e for e in _raw(name)["equation"] if e["status"] in FLAWED]  # type: ignore[union-attr]
    mine = [e for e in flawed if "restates" not in e]
    return {
        "fails findings": sum(e["status"] == "fails" for e in mine),
        "misprint findings": sum(e["status"] == "misprint" for e in mine),
        "restating": len(flawed) - len(mine),
    }


def _output_rows(name: str) -> list[object]:
    """The output rows of the committed ledger, as the engine builds them (no check run)."""
    from pendcli.verify.ledger_blame import row_context

    ledger = committed_ledger(name)
    references = paper(name).references()
    return [
        Evaluated(
            row,
            None,
            context=row_context(
                row, ledger, conditional(paper(name), ledger, row, references), None
            ),
        ).output_row()
        for row in ledger.rows
    ]


def test_a_restatement_is_not_counted_as_a_finding() -> None:
    """The counts of `pendcli equations`, the README's table, the report and the summary of
    `pendcli reproduce` against an independent count of the TOML; Tisserand's lines 126 and
    154 cite (13) and are no findings of their own."""
    rows = {name: _output_rows(name) for name in PAPERS}
    summary = ReproduceResult(PAPERS, equations=rows).summary_rows()  # type: ignore[arg-type]
    for name, line in zip(PAPERS, summary, strict=True):
        expected = _independent_counts(name)
        counts = coverage(rows[name])[name]  # type: ignore[arg-type]
        assert {k: counts[k] for k in expected} == expected, name
        assert counts["findings"] == expected["fails findings"] + expected["misprint findings"]
        assert (line["equations fails"], line["equations misprint"]) == (
            expected["fails findings"],
            expected["misprint findings"],
        )
        assert line["equations restating"] == expected["restating"]
    tisserand = {r.id: r for r in rows["tisserand"]}  # type: ignore[attr-defined]
    for row_id in ("what-gives-the-motion", "axis-and-ellipse-motion"):
        row = tisserand[f"tisserand.result.{row_id}"]
        assert row.restates == ("tisserand.eq.13",) and not row.finding


def test_a_restatement_takes_the_status_of_the_row_it_restates() -> None:
    with pytest.raises(PendcliError, match="has its status"):
        altered_ledger(
            "lecornu", 'restates = "lecornu.eq.42"', 'restates = "lecornu.eq.52"', "lecornu.eq.42'"
        )


def test_the_readmes_findings_come_from_the_ledger() -> None:
    """The section between the findings markers is what tools.docs writes from the rows:
    each paper's count of findings, and (52) among the misprints, not the failures."""
    from tools.docs import _findings_line

    readme = (TABLES.parent / "docs" / "findings.md").read_text("utf-8")
    section = readme.split("<!-- findings:start -->")[1].split("<!-- findings:end -->")[0]
    for name in PAPERS:
        rows = _output_rows(name)
        ids = [r.id for r in committed_ledger(name).readings]
        assert _findings_line(name, rows, ids) in section, name  # type: ignore[arg-type]
        expected = _independent_counts(name)
        total = expected["fails findings"] + expected["misprint findings"]
        assert f"**{name.capitalize()}**: {total} findings" in section
    lecornu = section.split("**Lecornu**")[1].split("**Charbonnier**")[0]
    fails, misprints = lecornu.split("misprints (no later step")
    assert "(52)" not in fails and "(52) line 1112" in misprints


# --- conditional verdicts -------------------------------------------------------------------


def _coefficient_rounds_to(g: Fraction) -> Fraction:
    """b²/(4g) for b = 0,35 rounded half up to five decimals, exactly (fractions)."""
    value = Fraction(35, 100) ** 2 / (4 * g) * 10**5
    return Fraction(int(value + Fraction(1, 2)), 10**5)


def test_the_conditional_row_names_both_sides_and_its_range() -> None:
    """(16)'s 0,00313 holds for g <= 9.80 and is a misprint above, the engine computing each end of
    each side; exact fractions agree: b²/(4g) rounds to 0,00313 at 9,78 and 9,80 (0,003125,
    half up), to 0,00312 just above 9,80, at 9,81 and 9,83."""
    for g, printed in (("9.78", True), ("9.80", True), ("9.8000001", False), ("9.83", False)):
        assert (_coefficient_rounds_to(Fraction(g)) == Fraction(313, 10**5)) is printed, g
    ledger = committed_ledger("lecornu")
    row = committed_row("lecornu.eq.16")
    found = conditional(paper("lecornu"), ledger, row, paper("lecornu").references())
    assert found is not None and found.problem is None, found
    assert found.text.startswith("holds for g <= 9.80, misprint for g > 9.80 (assumption g: ")
    assert "9.78 to 9.83" in found.text and "the tables take 9.81" in found.text
    for point in ("g = 9.78: holds", "g = 9.8: holds", "g = 9.83: misprint"):
        assert point in found.evidence
    with (TABLES / "regenerated" / "lecornu-equations.csv").open(encoding="utf-8") as file:
        csv_row = next(r for r in csv.DictReader(file) if r["id"] == "lecornu.eq.16")
    assert csv_row["condition"] == found.text and csv_row["status"] == "misprint"


def test_a_conditional_row_that_loses_its_range_is_refused() -> None:
    """The assumption without its range, the row without its condition: both refused."""
    with pytest.raises(PendcliError, match="has a constant and a range"):
        altered_ledger("lecornu", "range = [9.78, 9.83]\n", "")
    with pytest.raises(PendcliError, match=r"lecornu\.eq\.16: listed by the assumption g"):
        altered_ledger("lecornu", 'condition = "g <= 9.80"\n', "", "lecornu.eq.16")


@pytest.mark.parametrize("bound", ["9.79", "9.81"])
def test_a_condition_at_the_wrong_bound_is_refused(bound: str) -> None:
    """At 9,79 the side above still holds at its open end; at 9,81 the side below fails at
    its end: the verdict does not split there."""
    old = 'condition = "g <= 9.80"'
    ledger = altered_ledger("lecornu", old, old.replace("9.80", bound), "lecornu.eq.16")
    row = next(r for r in ledger.rows if r.id == "lecornu.eq.16")
    found = conditional(paper("lecornu"), ledger, row, paper("lecornu").references())
    assert found is not None and found.problem is not None
    assert "does not split the verdict" in found.problem


# --- the reading table ----------------------------------------------------------------------


@pytest.mark.parametrize("name", PAPERS)
def test_each_reading_applies_to_every_row_it_touches(name: str) -> None:
    """Uniform, never silent: a row whose lines meet a reading's and whose printed form holds
    the OCR's token (a regex here, on the raw TOML) names the reading; each reading's TeX is
    in the text within its lines."""
    raw = _raw(name)
    lines = _text_lines(name)
    named = {r.id: {i for i, _ in r.readings} for r in committed_ledger(name).rows}
    for reading in raw.get("reading", []):  # type: ignore[union-attr]
        spans = reading["lines"]
        for tex in reading["tex"]:
            assert any(tex in "\n".join(lines[a - 1 : b]) for a, b in spans), tex
        for entry in raw["equation"]:  # type: ignore[union-attr]
            first, last = entry.get("lines", [0, -1])
            meets = any(a <= last and first <= b for a, b in spans)
            token = any(
                re.search(rf"(?<![\w.]){re.escape(old)}(?![\w])", entry.get("printed", ""))
                for old, _ in reading["replace"]
            )
            if meets and token:
                assert reading["id"] in named[entry["id"]], (entry["id"], reading["id"])


@pytest.mark.parametrize(
    "row_id",
    [
        "tisserand.eq.I",
        "charbonnier.eq.5",
        "lecornu.result.arctg_series",
        "lecornu.result.eps_split",
        "lecornu.result.u_at_roots",
    ],
)
def test_a_row_read_through_the_table_fails_without_it(row_id: str) -> None:
    """Tisserand's r for g, Charbonnier's x for α and Lecornu's lost primes under one rule:
    each holds read, and its printed form alone (the OCR's letters as printed) does not."""
    row = committed_row(row_id)
    symbols = committed_ledger(row.paper).symbols_for(row)
    references = paper(row.paper).references()
    assert row.status == "holds" and row.readings
    assert verify_printed(row, symbols, references)[1] is None
    unread = dataclasses.replace(row, readings=())
    _, problem = verify_printed(unread, symbols, references)
    assert problem is not None and problem.startswith("recorded holds, but the printed form")


def test_a_reading_whose_tex_is_not_in_its_lines_is_refused() -> None:
    with pytest.raises(PendcliError, match=r"\(r-for-g\): tex .* is not within its lines"):
        altered_ledger("tisserand", "lines = [[160, 160]]", "lines = [[161, 161]]")


# --- every slip in a row; a step and its values ---------------------------------------------


def test_the_quarter_values_carry_41_and_add_a_slip_of_their_own() -> None:
    """Lines 894-900, with sympy on the ledger's printed (41): at u = π/2 its pk³ term of θ is
    (3π² + 4)/32 (carried as printed) and of dθ/du (π³/2 + 8π)/32, where the text prints
    (π²/4 + 8π)/32: a second slip, which the row names and the engine verifies."""
    import sympy as sp

    source = committed_row("lecornu.eq.41").printed or ""
    u, k, p = sp.symbols("u k p")
    theta = sp.sympify(source.split("=", 1)[1], locals={"u": u, "k": k, "p": p})
    at = {u: sp.pi / 2}
    term = sp.expand(theta.subs(at)).coeff(p).coeff(k, 3)
    slope = sp.expand(sp.diff(theta, u).subs(at)).coeff(p).coeff(k, 3)
    assert sp.simplify(term - (3 * sp.pi**2 + 4) / 32) == 0
    assert sp.simplify(slope - (sp.pi**3 / 2 + 8 * sp.pi) / 32) == 0
    row = committed_row("lecornu.result.quarter_values")
    assert len(row.wrong_terms) == 2 and "pi**3/2 + 8*pi" in (row.step_formula or "")
    from pendcli.verify.ledger_step import step_evidence

    said, problem = step_evidence(row, committed_ledger("lecornu"))
    assert problem is None and said is not None and "the printed form fails" in said
    bad = altered_ledger("lecornu", "(pi**3/2 + 8*pi))'", "(pi**2/4 + 8*pi))'", row.id)
    _, problem = step_evidence(next(r for r in bad.rows if r.id == row.id), bad)
    assert problem is not None and "does not show a slip of the row's own" in problem


def test_a_step_that_holds_shows_the_slip_its_values_carry() -> None:
    """Line 232: the intervals hold as differences of the printed instants, and the row says
    its values carry the instant 0,94's slip; the instants' row records that later use."""
    rows = {r.id: r for r in _output_rows("lecornu")}  # type: ignore[attr-defined]
    row = rows["lecornu.result.table_intervals"]
    assert row.status == "holds" and row.carries is not None
    assert row.carries.startswith("the step holds; the values carry lecornu.result.table_times")
    assert committed_row("lecornu.result.table_times").used_at == (232,)
    with pytest.raises(PendcliError, match="a slip a later row carries makes its row fail"):
        altered_ledger(
            "lecornu",
            'carries = "lecornu.result.table_times"',
            'carries = "lecornu.result.table_lengths"',
            "lecornu.result.table_intervals",
        )


def test_a_carried_slip_is_recorded_on_both_rows() -> None:
    """The row a slip is carried from names a line of the row carrying it: the J₀ of line
    240 are carried into line 246, not into the intervals of line 232."""
    old = 'carries = "lecornu.result.table_times"'
    new = 'carries = "lecornu.result.table_j0"'
    with pytest.raises(PendcliError, match="whose used_at names no line of this row"):
        _edited("lecornu", "lecornu.result.table_intervals", (old, new))


def test_the_ledgers_load_with_every_rule() -> None:
    for name in PAPERS:
        assert load_ledger(name, TABLES).rows
    row, _ = altered_row("tisserand", "tisserand.eq.I", "lines = [160, 160]", "lines = [160, 160]")
    assert row.readings == (("r-for-g", (("r", "g"),)),)
