"""Every help of pendcli (the top level, each group, each command) rendered at 80 and 120
columns: no line wider than the terminal, the width used, no word or value cut across two
lines (``mcmahon-`` / ``newton``, ``[default:`` / ``5]``), no internal name (``<int>``,
``<list[float]>``, ``solve_ivp``, a module path), and the same plain layout everywhere."""

from __future__ import annotations

import re
from typing import Any

import pytest
import typer
from helpers.cli import invoke

WIDTHS = (80, 120)
INTERNAL = re.compile(
    r"<(?:int|float|str|path|bool|list\[[a-z]+\])>|list\[|solve_ivp|gammaln|pendcli\.[a-z_]+\.|"
    r"floor_fraction|[╭╰│]"
)


def _tree() -> list[tuple[tuple[str, ...], Any]]:
    """(command path, click command) of the top level, every group and every command."""
    from pendcli.cli.app import app

    root = typer.main.get_command(app)
    found: list[tuple[tuple[str, ...], Any]] = [((), root)]
    with root.make_context("pendcli", [], resilient_parsing=True) as ctx:
        for name in root.list_commands(ctx):
            command = root.get_command(ctx, name)
            found.append(((name,), command))
            for sub_name, sub in sorted(getattr(command, "commands", {}).items()):
                found.append(((name, sub_name), sub))
    return found


TREE = _tree()


def _help(path: tuple[str, ...], width: int) -> str:
    code, out, err = invoke(*path, "--help", env={"COLUMNS": str(width)}, utf8=True)
    assert code == 0 and err == "", (path, err)
    return out


def _source_texts(command: Any) -> list[str]:
    """The words pendcli wrote for this help: the command's and each parameter's help."""
    texts = [command.help or ""]
    texts += [getattr(p, "help", None) or "" for p in command.params]
    return texts


@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize(("path", "command"), TREE, ids=[" ".join(p) or "pendcli" for p, _ in TREE])
def test_help_fits_keeps_every_token_whole_and_names_no_internals(
    path: tuple[str, ...], command: Any, width: int
) -> None:
    out = _help(path, width)
    lines = out.splitlines()
    assert all(len(line) <= width for line in lines), max(lines, key=len)
    assert not re.search(r"\[default:[^\]]*$", out, re.MULTILINE), out
    assert not re.search(r"\w-\n\s+\w", out), out
    assert not INTERNAL.search(out), INTERNAL.search(out)
    # every word of the help as written stands whole on one line (the Examples block too)
    for text in _source_texts(command):
        for token in text.split():
            if len(token) > 2 and token != "\b":
                assert any(token in line for line in lines), (token, out)


def test_help_uses_the_terminals_width() -> None:
    """At 120 columns the top-level help's description runs past 80 (click stopped at 80)."""
    wide = _help((), 120).splitlines()
    assert any(len(line) > 82 for line in wide), wide
    assert all(len(line) <= 80 for line in _help((), 80).splitlines())


@pytest.mark.parametrize("group", ["cache", "lecornu", "tisserand", "charbonnier"])
def test_a_bare_group_prints_its_plain_help_on_stderr_with_exit_2(group: str) -> None:
    """`pendcli cache` drew a boxed help on stdout; the other groups plain help on stderr."""
    code, out, err = invoke(group, env={"COLUMNS": "100"}, utf8=True)
    assert code == 2 and out == ""
    assert err.startswith(f"Usage: pendcli {group} [OPTIONS] COMMAND") and "Commands:" in err
    assert not INTERNAL.search(err)


def test_a_value_users_copy_stays_on_one_line_at_80_columns() -> None:
    out = _help(("lecornu", "zeros"), 80)
    assert "mcmahon-newton" in out
    assert "[default: 5]" in out and "[default: 2]" in out
    assert "--count K " in out and "1 <= K <= 10^7." in out


def test_the_integral_names_its_argument_one_way() -> None:
    out = _help(("charbonnier", "integral"), 100)
    assert "[OPTIONS] N\n" in out and "{n}" not in out and "Order n" not in out
    code, _, err = invoke("charbonnier", "integral", "--", "-5")
    assert code == 2 and err.startswith("pendcli: error: N must be in [-1, "), err


@pytest.mark.parametrize("group", ["tisserand", "lecornu", "charbonnier", "cache", "tradeoff"])
def test_each_group_help_ends_with_examples(group: str) -> None:
    out = _help((group,), 100)
    examples = out.split("Examples:\n", 1)[1].splitlines() if "Examples:" in out else []
    assert any(line.strip().startswith(f"pendcli {group}") for line in examples), out
