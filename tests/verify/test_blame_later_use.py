"""The blame rule's later use, its two tests (a formula written again, a number used) and the
reading rule, each against the raw TOML, the paper's text and an independent computation
(mpmath, sympy), and each broken on purpose to see it refused (tables/README.md, « Blame »)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import mpmath
import pytest
from helpers.ledgers import committed_row
from helpers.mutations import altered_ledger

from pendcli.base.errors import PendcliError

TABLES = Path(__file__).resolve().parents[2] / "tables"
PAPERS = ("tisserand", "lecornu", "charbonnier")


def _entries(name: str) -> list[dict[str, object]]:
    raw = tomllib.loads((TABLES / "equations" / f"{name}.toml").read_text("utf-8"))
    return raw["equation"]  # type: ignore[no-any-return]


def _text(name: str) -> list[str]:
    return (TABLES / "papers" / f"{name}.txt").read_text("utf-8").splitlines()


@pytest.mark.parametrize("name", PAPERS)
def test_every_later_use_lies_after_its_row(name: str) -> None:
    """Read with tomllib alone: no used_at line within (or before) the row's own lines."""
    for entry in _entries(name):
        last = entry["lines"][1]  # type: ignore[index]
        assert all(n > last for n in entry.get("used_at", [])), entry["id"]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("name", "row", "old", "new"),
    [
        # the conclusion of the row's own sentence (the old record of resal-rate)
        (
            "tisserand",
            "tisserand.result.square-from-formula-5",
            "used_at = [72]",
            "used_at = [70, 72]",
        ),
        # the last line of the row (the old record of mean_pendulum's kind)
        (
            "charbonnier",
            "charbonnier.result.integration-by-parts",
            "used_at = [461]",
            "used_at = [456]",
        ),
    ],
)
def test_a_later_use_within_the_row_is_refused(name: str, row: str, old: str, new: str) -> None:
    with pytest.raises(PendcliError, match=rf"{row}: used_at line \d+ is not a later use"):
        altered_ledger(name, old, new, row)


def _lengths(coefficient: mpmath.mpf, zeros: list[str]) -> list[mpmath.mpf]:
    return [coefficient * mpmath.mpf(z) ** 2 for z in zeros]


def _hundredths(value: mpmath.mpf) -> int:
    """``value`` rounded half up to two decimals, in hundredths."""
    return int(mpmath.floor(value * 100 + mpmath.mpf(1) / 2))


def test_the_lengths_of_16_are_b2_4g_rounded_not_0_00313() -> None:
    """Lines 224 and 256 computed independently (mpmath, the zeros as printed): rounded, the
    printed 0,68 and 0,55 come from b²/(4g) at every g from 9,80 to 9,81 and not from
    0,00313 (0,6856 → 0,69, 0,5553 → 0,56); so (16)'s last digit is not carried, and the
    row is a misprint above g = 9,80, whose reading the engine checked."""
    zeros = {"0^m, 68": "14.80", "0^m, 55": "13.32"}
    with mpmath.workdps(30):
        b = mpmath.mpf("0.35")
        for g in ("9.80", "9.805", "9.81"):
            for printed, z in zeros.items():
                (value,) = _lengths(b**2 / (4 * mpmath.mpf(g)), [z])
                assert _hundredths(value) == int(printed[-2:]), (g, z, value)
        for printed, z in zeros.items():
            (value,) = _lengths(mpmath.mpf("0.00313"), [z])
            assert _hundredths(value) == int(printed[-2:]) + 1, (z, value)
    row = committed_row("lecornu.eq.16")
    lines = _text("lecornu")
    assert row.status == "misprint" and row.used_at == (224, 256)
    assert all(any(w in lines[n - 1] for n in row.used_at) for w in zeros)
    assert row.condition == "g <= 9.80"


def test_a_formula_written_again_later_carries_the_slip() -> None:
    """One rule for lines 561 and 1126: a later line that writes the wrong form again in a
    result of its own carries it. sympy: T' = (π/2)√(l/g) − (π² − 12β)/16·b/g at
    l = a + (πb/2)√(a/g), to first order in b, is (π/2)√(a/g) + (π² + 12β)/16·b/g: the
    printed 12b of line 926 (β = b) gives the printed (π² + 12b) of line 932."""
    import sympy as sp

    a, g, b, beta, eps = sp.symbols("a g b beta epsilon", positive=True)
    length = a + sp.pi * b / 2 * sp.sqrt(a / g)
    t_prime = sp.pi / 2 * sp.sqrt(length / g) - (sp.pi**2 - 12 * beta) / 16 * b / g
    series = sp.series(t_prime.subs(b, eps * b), eps, 0, 2).removeO().subs(eps, 1)
    expected = sp.pi / 2 * sp.sqrt(a / g) + (sp.pi**2 + 12 * beta) / 16 * b / g
    assert sp.simplify(series - expected) == 0
    lines = _text("lecornu")
    for row_id, wrong in (
        ("lecornu.result.vertical_to_elongation", "12b"),
        ("lecornu.result.trajectory_after_52", "\\frac{\\rho_2 y}{\\rho_1 x}"),
    ):
        row = committed_row(row_id)
        assert row.status == "fails" and row.used_at, row_id
        assert row.lines is not None and min(row.used_at) > row.lines[1]
        assert all(wrong in lines[n - 1] for n in row.used_at), row_id


def test_tisserand_degrees_are_a_reading_not_a_finding() -> None:
    """30', 15' at line 194: a degree sign and a prime, a glyph pair; the author's
    coefficients follow from degrees (the engine judges them, the row holds read), and the
    row names the reading and is no finding. Without the reading it fails to hold."""
    row = committed_row("tisserand.result.numerical-application")
    assert row.status == "holds" and [i for i, _ in row.readings] == ["degree-as-prime"]
    assert "θ_0 = 30', \\quad θ_1" not in (row.note or "")
    assert "relativement considérables" in _text("tisserand")[201]
