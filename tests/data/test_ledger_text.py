"""The ledger bound to the printed text: each row's ``lines`` span of
tables/papers/<paper>.txt holds its label and its numbers; the display blocks are counted."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers.ledgers import committed_ledger

from pendcli.base.errors import PendcliError
from pendcli.data.ledger import labels_in_text, parse_ledger
from pendcli.data.ledger_rows import LedgerRow
from pendcli.data.text_blocks import blocks_covered, display_blocks

ROOT = Path(__file__).resolve().parents[2]
TABLES = ROOT / "tables"
PAPERS = ("tisserand", "lecornu", "charbonnier")
# The display formulas counted in each text.
BLOCKS = {"tisserand": 47, "lecornu": 243, "charbonnier": 86}
# Rows whose statement names a number printed outside their span, and why.
NUMBERS_ELSEWHERE = {
    # « ... en ne conservant que les termes du premier ordre »: the equation it solves (d²θ/dt²,
    # k²θ, θ0 = 0) is printed in n° 4-5, before the span.
    "charbonnier.result.general-solution",
    # "(e.g. two elongations), θ = 0 at ...": the 0 is the statement's own example.
    "lecornu.result.area_theorem",
    # "as x → 0": the text says « lorsque x tend vers zéro » in words.
    "lecornu.result.small_x_asymptotics",
}
_SCRIPT = {ord(c): f" {d} " for c, d in zip("⁰¹²³⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉", "0123456789" * 2, strict=True)}
_CITED_LABEL = re.compile(r"\((?:\d{1,3}'?|[IVX]+)\)")


def _text_lines(paper: str) -> list[str]:
    return (TABLES / "papers" / f"{paper}.txt").read_text(encoding="utf-8").split("\n")


def _span_text(row: LedgerRow, lines: list[str]) -> str:
    assert row.lines is not None
    return "\n".join(lines[row.lines[0] - 1 : row.lines[1]])


def _numbers(text: str) -> set[str]:
    return set(re.findall(r"\d+", _CITED_LABEL.sub(" ", text.translate(_SCRIPT))))


def _tie_fault(row: LedgerRow, lines: list[str]) -> str | None:
    """Why the row is not tied to its printed lines: its label and the numbers of its
    statement printed there (None: it is)."""
    if row.lines is None:
        return f"{row.id}: no lines"
    span = _span_text(row, lines)
    if row.equation and row.equation not in labels_in_text(span):
        return f"{row.id}: {row.equation} not in its span"
    # Numbers of cited labels, "(5)", are left out on both sides: they name, not state.
    missing = _numbers(row.statement) - set(re.findall(r"\d+", span))
    if row.id in NUMBERS_ELSEWHERE:
        return None if missing else f"{row.id}: exemption no longer needed"
    return f"{row.id}: numbers {sorted(missing)} not printed in {row.lines}" if missing else None


# One case per paper, naming every row that fails: one case per row (378) cost about 1 ms of
# pytest (2 ms under xdist) apiece, more than the check itself.
@pytest.mark.parametrize("paper", PAPERS)
def test_every_row_is_tied_to_its_printed_lines(paper: str) -> None:
    lines = _text_lines(paper)
    faults = [_tie_fault(row, lines) for row in committed_ledger(paper).rows]
    assert [f for f in faults if f] == []


@pytest.mark.parametrize("paper", PAPERS)
def test_the_display_blocks_are_counted(paper: str) -> None:
    text = (TABLES / "papers" / f"{paper}.txt").read_text(encoding="utf-8")
    blocks = display_blocks(text)
    assert len(blocks) == BLOCKS[paper] == text.count("$$") // 2
    lines = text.split("\n")
    for block in blocks:
        assert lines[block.first - 1].lstrip().startswith("$$") or "$$" in lines[block.first - 1]
        assert "$$" in lines[block.last - 1]


def test_a_block_is_covered_only_when_wholly_inside_a_span() -> None:
    blocks = display_blocks("a\n$$x\ny$$\nb\n$$z$$\n")
    assert [(b.first, b.last) for b in blocks] == [(2, 3), (5, 5)]
    assert blocks_covered(blocks, [(3, 5)]) == [False, True]
    assert blocks_covered(blocks, [(1, 3)]) == [True, False]
    assert blocks_covered(blocks, []) == [False, False]


_GOOD = {
    "id": "tisserand.eq.1",
    "equation": "(1)",
    "section": "p. 448",
    "statement": "a = b",
    "status": "definition",
    "note": "defines a",
    "lines": [36, 36],
}


def _parse(*rows: dict[str, object]) -> None:
    raw = {"ledger": {"paper": "tisserand", "text": "tables/papers/tisserand.txt"}}
    parse_ledger({**raw, "equation": list(rows)}, "tisserand", Path("t.toml"), TABLES)


@pytest.mark.parametrize(
    ("lines", "message"),
    [
        ([0, 3], "1 <= first <= last"),
        ([40, 30], "1 <= first <= last"),
        ([200, 207], "<= 206 (the text's last line)"),
        ([3], "two line numbers"),
        ("36", "two line numbers"),
        ([True, 3], "two line numbers"),
    ],
)
def test_bad_lines_are_refused_naming_the_row(lines: object, message: str) -> None:
    with pytest.raises(PendcliError, match=re.escape(message)) as info:
        _parse({**_GOOD, "lines": lines})
    assert "tisserand.eq.1" in str(info.value)


def test_restates_must_name_another_row() -> None:
    other = {**_GOOD, "id": "tisserand.eq.2", "equation": "(2)", "restates": "tisserand.eq.1"}
    _parse(_GOOD, other)
    with pytest.raises(PendcliError, match=re.escape("tisserand.eq.2: restates 'tisserand.eq.9'")):
        _parse(_GOOD, {**other, "restates": "tisserand.eq.9"})
    with pytest.raises(PendcliError, match=re.escape("restates 'tisserand.eq.2', not another row")):
        _parse(_GOOD, {**other, "restates": "tisserand.eq.2"})
