"""Lecornu, lines 1-698 (issue 19): each status computed from the printed form against its
reference (pendcli/papers/lecornu/references_early.py) is the recorded one, and an edit of a
printed form (one coefficient, or a misprint set to its reading) is refused, naming the row."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from ledgers import committed_ledger

from pendcli.core.ledger import LedgerRow, load_ledger, verify_printed
from pendcli.papers.lecornu import equations as CHECKS
from pendcli.papers.lecornu import references_early

ROOT = Path(__file__).resolve().parent.parent
TABLES = ROOT / "tables"
LAST_LINE = 698


def _early_rows() -> list[LedgerRow]:
    return [r for r in committed_ledger("lecornu").rows if r.lines and r.lines[0] <= LAST_LINE]


def _referenced() -> list[object]:
    return [pytest.param(r, id=r.id) for r in _early_rows() if r.reference]


@pytest.mark.parametrize("row", _referenced())
def test_the_computed_status_is_the_recorded_one(row: LedgerRow) -> None:
    symbols = committed_ledger("lecornu").symbols_for(row)
    computed, problem = verify_printed(row, symbols, CHECKS)
    assert problem is None, problem
    assert computed is not None and computed.startswith(f"{row.status}:")


def test_every_reference_is_exported_by_the_equations_module() -> None:
    for name in references_early.__all__:
        assert getattr(CHECKS, name) is getattr(references_early, name)
    used = {r.reference for r in _early_rows() if r.reference}
    assert used <= set(references_early.__all__) | set(dir(CHECKS))


def _altered(tmp_path: Path, old: str, new: str) -> tuple[dict[str, LedgerRow], dict[str, str]]:
    root = tmp_path / "tables"
    shutil.copytree(TABLES, root)
    path = root / "equations" / "lecornu.toml"
    text = path.read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new), encoding="utf-8")
    ledger = load_ledger("lecornu", root)
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
def test_a_changed_coefficient_is_refused(tmp_path: Path, row_id: str, old: str, new: str) -> None:
    rows, symbols = _altered(tmp_path, old, new)
    computed, problem = verify_printed(rows[row_id], symbols, CHECKS)
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
def test_a_misprint_printed_as_its_reading_is_refused(
    tmp_path: Path, row_id: str, old: str, new: str
) -> None:
    rows, symbols = _altered(tmp_path, old, new)
    _, problem = verify_printed(rows[row_id], symbols, CHECKS)
    assert problem is not None
    assert problem.startswith("recorded misprint, but the printed form gives holds")


def test_an_incomplete_correction_of_the_general_rule_is_refused(tmp_path: Path) -> None:
    """The general rule's correction without the switch point's + 1/(φ1φ'1) term fails."""
    old = "Integral(varphi**(-2), (x, x0, x1)) + 1/(varphi1*varphip1) - 1/(varphik*varphipk)"
    new = "Integral(varphi**(-2), (x, x0, x1)) - 1/(varphik*varphipk)"
    rows, symbols = _altered(tmp_path, old, new)
    _, problem = verify_printed(rows["lecornu.result.general_constants"], symbols, CHECKS)
    assert problem is not None and "and so does its fails" in problem


def test_the_new_numeric_checks_can_fail() -> None:
    """check_curvature judges the printed claim false (and computes the correction);
    check_half_period_root finds the observed order 3 that line 664 implies."""
    curvature = references_early.check_curvature()
    assert not curvature.holds and curvature.corrected
    root = references_early.check_half_period_root()
    assert root.holds and root.observed_order is not None and root.observed_order > 2.7
