"""Tisserand's statuses computed from the printed forms can fail: one coefficient
changed in a row's printed form (or in its reading or correction) makes the engine refuse the
row; a misprint whose printed form is set to its reading is refused; a repeat in the summary
prints the formula it repeats."""

from __future__ import annotations

import dataclasses
import json
import shutil
import tomllib
from pathlib import Path

import pytest
from helpers.ledgers import committed_ledger

from pendcli.base.errors import PendcliError
from pendcli.data.ledger_rows import LedgerRow
from pendcli.papers.registry import paper as registered_paper
from pendcli.verify.ledger_evaluation import equation_rows
from pendcli.verify.ledger_formulas import row_formula
from pendcli.verify.ledger_references import verify_printed

ROOT = Path(__file__).resolve().parents[3]
TABLES = ROOT / "tables"
TISSERAND = registered_paper("tisserand").references()


def _ledger() -> tuple[dict[str, LedgerRow], dict[str, str]]:
    ledger = committed_ledger("tisserand")
    return {r.id: r for r in ledger.rows}, dict(ledger.symbols)


def _altered(row: LedgerRow, field: str, old: str, new: str) -> LedgerRow:
    text = getattr(row, field)
    assert text is not None and text.count(old) == 1, (row.id, field, old)
    return dataclasses.replace(row, **{field: text.replace(old, new)})


# (row, field, old, new): one coefficient (or one letter) of what the row prints or reads
CHANGES = [
    ("eq.1", "printed", "k*sqrt(2)*dt", "k*sqrt(3)*dt"),
    ("eq.2", "printed", "dtheta/(sin(theta)*", "dtheta/(sin(theta)**2*"),
    ("result.dtheta-dpsi", "printed", "(u*sqrt(1 - u**2))", "(u*sqrt(1 - 2*u**2))"),
    ("eq.4", "printed", "dpsi/sqrt(1 - u**2)", "dpsi/sqrt(1 - 2*u**2)"),
    ("eq.5", "printed", "dpsi/(u**2*", "dpsi/(u**3*"),
    ("eq.7", "printed", "35/128*u**2", "35/127*u**2"),
    ("result.inverse-square-coefficient", "printed", "1/u**2", "2/u**2"),
    ("eq.8", "printed", "25*(u0**2 + u1**2)/512", "26*(u0**2 + u1**2)/512"),
    ("eq.8", "printed", "35/4096", "36/4096"),
    ("eq.8", "printed", "35/512", "36/512"),
    ("eq.10", "printed", "u1/u0*tan(psi)", "u0/u1*tan(psi)"),
    ("eq.11", "printed", "27*(u0**2 + u1**2)/256", "28*(u0**2 + u1**2)/256"),
    ("eq.12", "printed", "26*u0**2*u1**2", "27*u0**2*u1**2"),
    ("result.psi-in-psi", "printed", "11*(u0**2 + u1**2)/256", "12*(u0**2 + u1**2)/256"),
    ("eq.13", "reading_formula", "1/4096", "2/4096"),
    ("eq.14", "printed", "9*(u0**2 + u1**2)/32", "10*(u0**2 + u1**2)/32"),
    ("eq.15", "printed", "17/512", "18/512"),
    ("result.eccentric-anomaly", "printed", "rho1*sin(psi)", "rho0*sin(psi)"),
    ("eq.I", "printed", "313*u0**2", "314*u0**2"),  # holds, its r read as g (the OCR's)
    ("eq.I", "printed", "151*(u0**4", "152*(u0**4"),
    ("eq.II", "printed", "1/4096", "2/4096"),
    ("eq.II", "printed", "11*(u0**2 + u1**2)/256", "12*(u0**2 + u1**2)/256"),
    ("result.first-approximation", "printed", "3/8*u0*u1*kpp*t", "3/7*u0*u1*kpp*t"),
    ("result.second-approximation", "printed", "3/32", "3/31"),
    ("result.resal-rate", "reading_formula", "3/8*u0*u1*kp", "3/7*u0*u1*kp"),
    ("result.square-from-formula-5", "reading_formula", "u1**4)/16", "u1**4)/15"),
    # the sentences' claims (the reading record): a word of each changed
    ("result.resal-small-oscillations", "printed", "1/rho0**2*cos", "1/rho1**2*cos"),
    ("result.resal-small-oscillations", "printed", "phip = dphip_dt*t", "phip = 2*dphip_dt*t"),
    ("result.start-of-psi", "printed", "u = u0", "u = u1"),
    ("result.formulas-1-2-become-4-5", "printed", "dpsi/(u**2*", "dpsi/(u**3*"),
    ("result.integrals-from-3", "printed", "(3*(u0**4", "(4*(u0**4"),
    ("result.motion-from-6-and-7", "printed", "27*(u0**2", "28*(u0**2"),
    ("result.psi-from-8", "printed", "11*(u0**2", "12*(u0**2"),
    ("result.phip-from-11-and-13", "printed", "17/512", "18/512"),
    ("result.tan-sq-psi-from-3", "printed", "(u0**2 - u**2)/", "(u1**2 - u**2)/"),
    ("result.ellipse-axes", "printed", "rho1 < rho0", "rho0 < rho1"),
    ("result.ellipse-axes", "printed", "rho <= rho0", "rho <= rho1"),
    ("result.summary-added-orders", "printed", "313*", "312*"),
    ("result.secular-term-second-order", "printed", "u0*u1 = ", "u0 = "),
    ("result.axis-turns-with-the-pendulum", "printed", "> 0", "< 0"),
    ("result.anomaly-proportional-to-time", "printed", "psi = kp*t", "psi = 2*kp*t"),
]  # fmt: skip


@pytest.mark.parametrize(("row_id", "field", "old", "new"), CHANGES)
def test_one_changed_coefficient_is_refused(row_id: str, field: str, old: str, new: str) -> None:
    rows, symbols = _ledger()
    original = rows[f"tisserand.{row_id}"]
    _, problem = verify_printed(original, symbols, TISSERAND)
    assert problem is None, problem  # the row as committed is consistent
    changed = _altered(original, field, old, new)
    _, problem = verify_printed(changed, symbols, TISSERAND)
    assert problem is not None and problem.startswith(f"recorded {original.status}, but"), problem


# (row, the form its printed is set to): the misprints made right (the numerical application
# holds, read through the OCR reading degree-as-prime)
MADE_RIGHT = [
    ("eq.13", "reading_formula", "misprint"),
    ("result.resal-rate", "reading_formula", "misprint"),
]


@pytest.mark.parametrize(("row_id", "field", "status"), MADE_RIGHT)
def test_a_slip_whose_printed_form_is_its_reading_is_refused(
    row_id: str, field: str, status: str
) -> None:
    rows, symbols = _ledger()
    row = rows[f"tisserand.{row_id}"]
    assert row.status == status
    made_right = dataclasses.replace(row, printed=getattr(row, field))
    _, problem = verify_printed(made_right, symbols, TISSERAND)
    assert problem is not None
    assert problem.startswith(f"recorded {status}, but the printed form gives holds"), problem


def test_the_misprinted_cross_reference_is_judged_on_both_sides() -> None:
    """« La formule (5) donnera »: the printed form and its reading are the same formula; the
    printed one is judged against (5) (no dt: it fails), the reading against (4)."""
    rows, symbols = _ledger()
    row = rows["tisserand.result.square-from-formula-5"]
    assert row.printed == row.reading_formula
    computed, problem = verify_printed(row, symbols, TISSERAND)
    assert problem is None and computed is not None and computed.startswith("misprint")
    as_if_4 = dataclasses.replace(row, reference="reference_differential_4")
    _, problem = verify_printed(as_if_4, symbols, TISSERAND)
    assert problem is not None and "gives holds" in problem


def _one_row_tables(root: Path, row_id: str, old: str, new: str) -> None:
    """A tables/ with the Tisserand ledger cut to one row, ``old`` -> ``new`` in its printed."""
    raw = tomllib.loads((TABLES / "equations" / "tisserand.toml").read_text(encoding="utf-8"))
    (row,) = [r for r in raw["equation"] if r["id"] == row_id]
    assert row["printed"].count(old) == 1
    row["printed"] = row["printed"].replace(old, new)
    parts = [f'[ledger]\npaper = "tisserand"\ntext = {json.dumps(raw["ledger"]["text"])}']
    symbols = "\n".join(f"{json.dumps(k)} = {json.dumps(v)}" for k, v in raw["symbols"].items())
    body = "\n".join(f"{k} = {json.dumps(v, ensure_ascii=False)}" for k, v in row.items())
    parts += [f"[symbols]\n{symbols}", f"[[equation]]\n{body}"]
    (root / "equations").mkdir(parents=True)
    (root / "equations" / "tisserand.toml").write_text("\n\n".join(parts) + "\n", "utf-8")
    (root / "papers").mkdir()
    shutil.copy(TABLES / "papers" / "tisserand.txt", root / "papers" / "tisserand.txt")


def test_a_changed_coefficient_is_refused_naming_the_row(tmp_path: Path) -> None:
    """End to end, as PENDCLI_TABLES names a copy of tables/: (15)'s 17/512 -> 18/512."""
    _one_row_tables(tmp_path / "changed", "tisserand.eq.15", "17/512", "18/512")
    with pytest.raises(PendcliError, match=r"tisserand\.eq\.15: recorded holds, but"):
        equation_rows([registered_paper("tisserand")], tmp_path / "changed")
    _one_row_tables(tmp_path / "same", "tisserand.eq.15", "17/512", "17/512")
    rows = equation_rows([registered_paper("tisserand")], tmp_path / "same")
    assert [r.status for r in rows] == ["holds"]


# --- a repeat prints the formula it repeats --------------------------------------------------


def _equations(row: LedgerRow, symbols: dict[str, str]) -> list[tuple[object, object]]:
    assert row.printed is not None
    return list(row_formula(row.id, row.printed, symbols).equations)


def repeats_its_row(repeat: LedgerRow, original: LedgerRow, symbols: dict[str, str]) -> bool:
    """Each equation of ``repeat`` is one of ``original``'s, once the names ``original``
    defines (an equation whose one side is a bare symbol) are replaced by what they name."""
    import sympy as sp

    names: dict[object, object] = {}
    for lhs, rhs in _equations(original, symbols):
        if isinstance(rhs, sp.Symbol) and not isinstance(lhs, sp.Symbol):
            names[rhs] = lhs  # sin(theta) = u: u names sin θ
        elif isinstance(lhs, sp.Symbol) and lhs not in (rhs.free_symbols if rhs else set()):
            names.setdefault(lhs, rhs)  # phi1 = atan(...)

    def residual(lhs: object, rhs: object) -> object:
        return sp.expand((lhs - rhs).subs(names))  # type: ignore[operator]

    known = [residual(lhs, rhs) for lhs, rhs in _equations(original, symbols)]
    return all(
        any(sp.expand(residual(lhs, rhs) - k) == 0 for k in known)
        for lhs, rhs in _equations(repeat, symbols)
    )


def _repeats() -> list[object]:
    rows, _ = _ledger()
    return [
        pytest.param(r.id, r.restates, id=r.id)
        for r in rows.values()
        if r.restates and r.status == "definition"
    ]


@pytest.mark.parametrize(("row_id", "restated"), _repeats())
def test_a_repeat_prints_the_formula_it_repeats(row_id: str, restated: str) -> None:
    rows, symbols = _ledger()
    repeat = rows[row_id]
    assert repeat.status == "definition" and (repeat.note or "").startswith("repeats")
    assert repeats_its_row(repeat, rows[restated], symbols), row_id


def test_a_repeat_with_a_changed_coefficient_is_not_a_repeat() -> None:
    rows, symbols = _ledger()
    changed = _altered(rows["tisserand.eq.V"], "printed", "17/512", "18/512")
    assert not repeats_its_row(changed, rows["tisserand.eq.15"], symbols)
    changed = _altered(rows["tisserand.eq.IV"], "printed", "u1**2*sin(psi)**2", "u1**2*sin(psi)")
    assert not repeats_its_row(changed, rows["tisserand.eq.3"], symbols)


def test_every_checked_row_has_a_reference() -> None:
    # the numerical asides too: their printed numbers are judged by verify/printed_numeric
    rows, _ = _ledger()
    checked = [r for r in rows.values() if r.status in ("holds", "fails", "misprint")]
    assert [r.id for r in checked if not r.reference] == []


# --- the sentences that cite formulas (lines 126, 154, 190, 206) -------------------------

CITED_CHANGES = [
    ("result.what-gives-the-motion", "reading_formula", "17/512", "18/512"),
    ("result.what-gives-the-motion", "reading_formula", "atan(u1/u0*", "atan(u0/u1*"),
    ("result.axis-and-ellipse-motion", "reading_formula", "17/512", "18/512"),
    ("result.axis-and-ellipse-motion", "reading_formula", "= u1/u0*tan", "= u0/u1*tan"),
    ("result.third-approximation", "printed", "/sin(2*kp*t) > 0", "/sin(2*kp*t) < 0"),
    ("result.third-approximation", "printed", "11*(u0**2 + u1**2)/256", "12*(u0**2 + u1**2)/256"),
    ("result.periodic-term-cited", "printed", "3/32", "3/31"),
]  # fmt: skip


@pytest.mark.parametrize(("row_id", "field", "old", "new"), CITED_CHANGES)
def test_a_changed_coefficient_of_a_citing_sentence_is_refused(
    row_id: str, field: str, old: str, new: str
) -> None:
    test_one_changed_coefficient_is_refused(row_id, field, old, new)


@pytest.mark.parametrize(
    "row_id", ["result.what-gives-the-motion", "result.axis-and-ellipse-motion"]
)
def test_a_sentence_citing_13_carries_its_slip(row_id: str) -> None:
    """Lines 126 and 154 take ψ from (13): as printed (sin² 4k't) it fails, so the rows are
    misprints on both sides; with (13) read, the printed form holds and the row is refused."""
    test_a_slip_whose_printed_form_is_its_reading_is_refused(row_id, "reading_formula", "misprint")
