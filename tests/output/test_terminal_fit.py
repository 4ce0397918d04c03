"""Every command's table fits the terminal and never cuts a word or a number.

Each command is rendered at 80 and 120 columns (COLUMNS, which pendcli's console reads when
its output is not a terminal) and at 1000; every token of the narrow output must be a whole
token of the wide one: a number folded across two lines ("1.427" / "90973") is not.
"""

from __future__ import annotations

import pytest
from helpers.cli import invoke

COMMANDS = [
    ("reproduce",),
    ("reproduce", "--notes"),
    ("list",),
    ("check",),
    ("lecornu", "claims"),
    ("lecornu", "example"),
    ("lecornu", "ode-check"),
    ("lecornu", "g-sensitivity"),
    ("lecornu", "zeros"),
    ("lecornu", "series"),
    ("lecornu", "zero-length"),
    ("tisserand", "claims"),
    ("tisserand", "example"),
    ("tisserand", "series"),
    ("charbonnier", "table"),
    ("charbonnier", "integral", "4"),
    ("formulas",),
    ("equations",),
    ("explain",),
    ("explain", "lecornu.mean_pendulum_coefficient"),
]


def _render(args, width, monkeypatch, cache):
    # a command's rows computed at the first width, read back at the others (conftest.py)
    monkeypatch.setenv("COLUMNS", str(width))
    monkeypatch.setenv("PENDCLI_CACHE", str(cache))
    code, out, err = invoke(*args)
    assert code == 0, err
    return out


@pytest.mark.slow
@pytest.mark.parametrize("args", COMMANDS, ids=" ".join)
def test_no_token_is_cut_at_80_or_120_columns(
    args, monkeypatch, shared_result_cache, reproduce_computed_once
):
    whole = set(_render(args, 1000, monkeypatch, shared_result_cache).split())
    for width in (80, 120):
        out = _render(args, width, monkeypatch, shared_result_cache)
        cut = [t for t in out.split() if t not in whole and t.strip("─?")]
        assert not cut, f"{width} columns: {cut[:10]}"
        wide = [line for line in out.splitlines() if len(line) > width]
        assert not wide, f"{width} columns: a line of {len(wide[0])}: {wide[0][:60]}..."


def test_a_folded_number_is_caught(monkeypatch):
    """The check itself: rich's own folding (what pendcli did before) fails it."""
    from rich.console import Console
    from rich.table import Table

    def draw(width):
        table = Table()
        for name in ("a", "b", "c"):
            table.add_column(name, overflow="fold")
        table.add_row("1.4279097301604e-05", "-1.000e-04 and words", "x" * 30)
        console = Console(width=width, file=None, record=True)
        with console.capture() as captured:
            console.print(table)
        return captured.get()

    whole = set(draw(1000).split())
    assert [t for t in draw(30).split() if t not in whole and t.strip("─━┃│┏┓┗┛┡┩└┘")]
