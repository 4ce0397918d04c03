"""CLI conventions: -h, examples in every help, completion of values, colour variables,
output targets refused before any work."""

from __future__ import annotations

import functools
import shlex
from pathlib import Path

import pytest
import typer
from helpers.cli import assert_clean_error, invoke

from pendcli.cli.app import app
from pendcli.cli.help_format import EXAMPLES


@functools.cache  # one group for the module: each example only makes a context of it
def _leaf_commands():
    group = typer.main.get_command(app)
    ctx = typer.Context(group, info_name="pendcli")
    out = []
    for name in group.list_commands(ctx):
        command = group.get_command(ctx, name)
        subs = getattr(command, "commands", {})
        out += [f"{name} {sub}" for sub in subs] if subs else [name]
    return group, ctx, out


COMMANDS = _leaf_commands()[2]


@pytest.mark.parametrize("path", COMMANDS)
def test_every_command_takes_dash_h_and_shows_examples(path):
    code, out, err = invoke(*path.split(), "-h")
    assert code == 0, err
    assert "Examples:" in out
    assert f"pendcli {path}" in out.split("Examples:")[1]


def test_every_example_fits_80_columns():
    """click indents the Examples block by four: each line stays within 80 columns."""
    assert [e for lines in EXAMPLES.values() for e in lines if len(e) + 4 > 80] == []


def test_the_top_level_help_has_examples():
    code, out, _ = invoke("-h")
    assert code == 0
    assert "Examples:" in out


def _command(group, ctx, words):
    command, rest = group, list(words)
    while rest and hasattr(command, "commands"):
        sub = command.get_command(ctx, rest[0])
        if sub is None:
            break
        command, rest = sub, rest[1:]
    return command, rest


@pytest.mark.parametrize(
    "example", [e for lines in EXAMPLES.values() for e in lines], ids=lambda e: e[:50]
)
def test_every_example_parses(example):
    """Each example names a real command and options that take the values given."""
    group, ctx, _ = _leaf_commands()
    typed = example.split("  ")[0].split(">")[0]  # the command, before any comment or redirect
    words = shlex.split(typed)[1:]
    command, rest = _command(group, ctx, words)
    assert command is not group or not words, example
    command.make_context(words[0] if words else "pendcli", rest, parent=ctx)


def test_every_command_has_an_entry_in_examples():
    assert set(COMMANDS) <= set(EXAMPLES)


def test_paper_values_complete():
    from pendcli.cli.common import complete_papers, complete_statuses, complete_verdicts

    assert complete_papers("l") == ["lecornu"]
    assert complete_statuses("mis") == ["misprint"]
    assert complete_verdicts("agrees,dis") == ["agrees,discrepant"]


def test_bad_paper_has_the_common_wording():
    code, _, err = invoke("list", "--paper", "newton")
    assert_clean_error(code, err)
    assert "--paper must be one of tisserand, lecornu or charbonnier, got 'newton'" in err


def _colour(env):
    """Whether `pendcli list` colours its output to a pipe (a captured stdout is not a
    terminal), run in this process with ``env``."""
    code, out, err = invoke("list", "-p", "charbonnier", env=env)
    assert code == 0, err
    return "\x1b[" in out


def test_force_color_colours_a_pipe_and_no_color_wins():
    clean = {"FORCE_COLOR": "", "NO_COLOR": ""}
    assert not _colour(clean)
    assert _colour({**clean, "FORCE_COLOR": "1"})
    assert not _colour({"FORCE_COLOR": "1", "NO_COLOR": "1"})


@pytest.mark.parametrize(
    "args",
    [
        ("tisserand", "example", "--plot", "/proc/pendcli-x.png"),
        ("reproduce", "--out", "/proc/pendcli-x"),
    ],
)
def test_an_unwritable_target_is_refused_before_any_work(args, monkeypatch):
    import pendcli.run.reproduce

    def fail(*_a, **_k):
        raise AssertionError("computed before checking the output target")

    monkeypatch.setattr(pendcli.run.reproduce, "reproduce_all", fail)
    monkeypatch.setattr("pendcli.papers.tisserand.model.check_amplitudes", fail, raising=False)
    code, _, err = invoke(*args)
    assert_clean_error(code, err)
    assert "/proc" in err


@pytest.mark.parametrize(
    ("args", "named"),
    [
        (["explain", ""], "argument 2, after 'explain',"),
        (["explain", "   "], "argument 2, after 'explain',"),
        (["formulas", "--plot", ""], "--plot"),
        (["formulas", "--plot="], "--plot"),
        (["reproduce", "-p", " "], "-p"),
        (["lecornu", "example", "--g", "\t"], "--g"),
        ([""], "argument 1"),
    ],
)
def test_an_empty_or_blank_value_is_one_line_before_any_work(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, args: list[str], named: str
) -> None:
    """`explain ''` printed nothing and exited 0 after 3 s; `formulas --plot ''` drew three
    figures into the current folder: a blank value is refused, naming where it stands."""
    monkeypatch.chdir(tmp_path)
    code, out, err = invoke(*args)
    assert_clean_error(code, err)
    assert f"error: {named} must not be empty or blank, got " in err, err
    assert out == "" and not list(tmp_path.iterdir())
