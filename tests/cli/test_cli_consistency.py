"""One way for every command: blank values refused for every option and argument, output
targets refused before any work, one rule for decimal commas, case and infinite numbers, and a
result cache whose key the test tools do not change."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest
import typer
from helpers.cli import assert_clean_error, invoke


def _commands() -> list[tuple[tuple[str, ...], Any]]:
    """(path, command) of every command that runs (groups' subcommands included)."""
    from pendcli.cli.app import app

    root = typer.main.get_command(app)
    found = []
    with root.make_context("pendcli", [], resilient_parsing=True) as ctx:
        for name in root.list_commands(ctx):
            command = root.get_command(ctx, name)
            subs = getattr(command, "commands", {})
            if not subs or getattr(command, "invoke_without_command", False):
                found.append(((name,), command))
            found += [((name, sub), c) for sub, c in sorted(subs.items())]
    return found


def _valued_parameters() -> list[tuple[tuple[str, ...], str]]:
    """(command path, option name or "" for an argument) of every parameter taking a value."""
    out = []
    for path, command in _commands():
        for param in command.params:
            if getattr(param, "is_flag", False) or param.name in ("help", "quiet"):
                continue
            out.append((path, param.opts[0] if param.param_type_name == "option" else ""))
    return out


VALUED = _valued_parameters()


# The three blanks of a parameter in one case (62 cases, not 186: each case costs pytest and
# xdist about 3 ms of their own); a failure names the blank it failed on.
@pytest.mark.parametrize(("path", "option"), VALUED, ids=[" ".join(p) + " " + o for p, o in VALUED])
def test_every_blank_value_is_one_line_before_any_work(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, path: tuple[str, ...], option: str
) -> None:
    monkeypatch.chdir(tmp_path)
    for blank in ("", " ", "\t "):
        args = [*path, option, blank] if option else [*path, blank]
        code, out, err = invoke(*args)
        assert_clean_error(code, err)
        assert "must not be empty or blank" in err and out == "", (blank, err)
        assert not list(tmp_path.iterdir()), blank
        if option.startswith("--"):
            code, out, err = invoke(*path, f"{option}={blank}")
            assert_clean_error(code, err)
            said = f"pendcli: error: {option} must not be empty or blank"
            assert err.startswith(said), (blank, err)


def test_the_parameters_scanned_include_every_kind() -> None:
    """The scan above reaches strings, paths, numbers and arguments (it would pass vacuously)."""
    options = {o for _, o in VALUED}
    assert {"--plot", "--out", "--write-tables", "--theta0", "--g", "--paper", ""} <= options


def _no_work(monkeypatch: pytest.MonkeyPatch) -> None:
    """Any measurement or reproduction started fails the test."""

    def fail(*args: object, **kwargs: object) -> None:
        raise AssertionError("work started before the target was checked")

    monkeypatch.setattr("pendcli.run.tradeoff.measure_family", fail)
    monkeypatch.setattr("pendcli.run.reproduce.reproduce_all", fail)


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (["tradeoff", "--quick", "integral_pi", "--write-tables", "{file}"], "must be a folder"),
        (["tradeoff", "--quick", "--write-tables", "{missing}/a/b"], "mkdir -p"),
        (["tradeoff", "--quick", "--write-tables", "{file}/sub"], "inside the file"),
        (["reproduce", "--out", "{missing}/deep/dir"], "creates only the last folder"),
        (["reproduce", "--out", "{file}"], "file"),
    ],
)
def test_output_targets_are_refused_before_any_work(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, args: list[str], said: str
) -> None:
    _no_work(monkeypatch)
    file = tmp_path / "taken.txt"
    file.write_text("not a folder\n")
    filled = [a.format(file=file, missing=tmp_path / "missing") for a in args]
    code, out, err = invoke(*filled)
    assert_clean_error(code, err)
    assert said in err and out == "", err
    assert "File exists" not in err
    assert not (tmp_path / "missing").exists()


def test_a_mount_point_is_refused_as_out_before_any_work(monkeypatch: pytest.MonkeyPatch) -> None:
    _no_work(monkeypatch)
    mount = next(p for p in ("/proc", "/sys", "/dev") if os.path.ismount(p))
    code, out, err = invoke("reproduce", "--out", mount)
    assert_clean_error(code, err)
    assert "mount point" in err and out == ""


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["lecornu", "zeros", "--order", "3"], "--order must be 1 or 2, got 3"),
        (["lecornu", "ode-check", "--floor", "1"], "--floor must be in [1e-09, 0.5], got 1.0"),
        (["lecornu", "example", "--length", "1e400"], "--length must be finite, got 1e400"),
        (["lecornu", "example", "--speed", "nan"], "--speed must be finite, got nan"),
        (["lecornu", "claims", "--g", "abc"], "--g must be a number, got 'abc'"),
        (["equations", "-s", "wrong"], "--status must be one of holds, fails, "),
    ],
)
def test_one_wording_of_a_refused_value(args: list[str], message: str) -> None:
    code, _, err = invoke(*args)
    assert_clean_error(code, err)
    assert err.startswith(f"pendcli: error: {message}"), err
    assert err.count("(") <= 1, err  # no nested parentheses


def test_a_decimal_comma_reads_as_a_point_everywhere() -> None:
    """`--theta0 '30,5°'` was accepted while `--g 9,81` was refused."""
    comma = invoke("lecornu", "claims", "--g", "9,81", "-f", "json")
    point = invoke("lecornu", "claims", "--g", "9.81", "-f", "json")
    assert comma.code == point.code == 0 and comma.out == point.out
    listed = invoke("lecornu", "ode-check", "--amplitude", "1,5", "-f", "csv")
    assert listed.code == 0, listed.err
    assert listed.out == invoke("lecornu", "ode-check", "--amplitude", "1.5", "-f", "csv").out


def test_case_is_read_the_same_for_every_word_option() -> None:
    """`-p LECORNU` was accepted while `-s Holds` was refused."""
    assert (
        invoke("list", "-p", "LECORNU", "-f", "csv").out
        == invoke("list", "-p", "lecornu", "-f", "csv").out
    )
    upper = invoke("lecornu", "zeros", "--method", "SciPy", "--count", "3", "-f", "csv")
    assert (
        upper.code == 0
        and upper.out
        == invoke("lecornu", "zeros", "--method", "scipy", "--count", "3", "-f", "csv").out
    )


def test_theta0_alone_keeps_the_examples_ratio() -> None:
    """`tisserand example --theta0 10°` failed on a default θ1 = 15° the user never set."""
    from pendcli.papers.tisserand import model

    ratio = model.example_ratio()
    code, _, err = invoke("tisserand", "example", "--theta0", "10°", "-f", "json")
    assert code == 0, err
    assert f"the example's ratio θ1/θ0 = {ratio:g}" in err
    given = invoke("tisserand", "example", "--theta0", "10°", "--theta1", f"{10 * ratio:g}°")
    assert given.code == 0


# ------------------------------------------------------------ the result cache's key


def _site(tmp_path: Path) -> Path:
    site = tmp_path / "site"
    for name, requires in (
        ("numpy-2.0", ['colorama; platform_system == "Windows"', "tzdata; python_version < '3'"]),
        ("scipy-1.0", ["numpy>=1.25", 'pytest; extra == "test"']),
    ):
        info = site / f"{name}.dist-info"
        info.mkdir(parents=True)
        lines = [f"Name: {name.split('-')[0]}", *(f"Requires-Dist: {r}" for r in requires)]
        (info / "METADATA").write_text("\n".join(lines) + "\n")
    return site


@pytest.mark.skipif(os.name == "nt", reason="colorama is required on Windows")
def test_the_key_ignores_test_tools_and_other_systems_needs(tmp_path: Path) -> None:
    """make test installs pytest, ruff, mypy, hypothesis and, with them, libraries that the
    runtime requires only elsewhere (colorama on Windows): none of them changes a result."""
    from pendcli.base.cache_key import runtime_signature

    site = _site(tmp_path)

    def key() -> str:
        return runtime_signature([site], ["scipy"])

    before = key()
    assert "numpy-2.0.dist-info" in before and "scipy-1.0.dist-info" in before
    for tool in ("pytest-9.0", "ruff-0.17.6", "mypy-2.4.1", "hypothesis-6.170", "colorama-0.4.6"):
        (site / f"{tool}.dist-info").mkdir()
    (site / "tzdata-2026.1.dist-info").mkdir()
    assert key() == before
    (site / "numpy-2.0.dist-info").rename(site / "numpy-2.1.dist-info")
    assert key() != before


# ------------------------------------------------------------ progress


def _judge(count: int) -> int:
    """``count`` rows judged (a worker receives this function by pickle: module level)."""
    from pendcli.base.workers import row_done

    for _ in range(count):
        row_done()
    return count


def test_rows_done_are_counted_across_forked_workers() -> None:
    """A progress bar reads rows judged in this process and in its forked workers (a cold
    `equations` bar sat at "tisserand: equations 0/2" for 45 s)."""
    from pendcli.base.workers import ForkedWorkers, counting_rows, row_done

    with counting_rows() as done, ForkedWorkers(1) as pool:
        results = pool.share([5, 7, 11, 13], _judge)
        assert done() == sum(results) == 36
    row_done()  # outside a counting run: nothing to count, no error


def test_status_lines_stay_off_a_pipe(capsys: pytest.CaptureFixture[str]) -> None:
    from pendcli.base.console import status_line

    status_line("loading the libraries")
    assert capsys.readouterr().err == ""


def test_help_of_the_package_lists_reproduce_with_the_functions() -> None:
    """`help(pendcli)` lists every function of the API, `reproduce` among them."""
    import pydoc

    import pendcli

    text = pydoc.render_doc(pendcli, renderer=pydoc.plaintext)
    for name in pendcli.__all__:
        if callable(getattr(pendcli, name)) and not isinstance(getattr(pendcli, name), type):
            assert f"    {name}(" in text or f", {name}(" in text, name


def _on_a_terminal(*args: str) -> str:
    """What `pendcli ARGS` writes to a pseudo-terminal (stdout and stderr both), run in this
    process: what it checks is whether its streams are a terminal, and these are one."""
    import pty
    import threading

    leader, follower = pty.openpty()
    chunks: list[bytes] = []

    def read_all() -> None:  # the terminal's buffer is small: read while the command writes
        while True:
            try:
                data = os.read(leader, 65536)
            except OSError:  # every handle on the follower closed
                break
            if not data:
                break
            chunks.append(data)

    reader = threading.Thread(target=read_all)
    reader.start()
    try:
        with open(follower, "w", encoding="utf-8") as terminal:
            invoke(*args, env={"COLUMNS": "120"}, terminal=terminal)
    finally:
        reader.join()
        os.close(leader)
    return b"".join(chunks).decode("utf-8", "replace")


def test_a_slow_step_shows_a_sign_of_life_on_a_terminal_only() -> None:
    """`lecornu example --speed 0.001` ran 10 s with nothing on stderr."""
    shown = _on_a_terminal("lecornu", "example")
    assert "solving the example" in shown, shown[:500]
    piped = invoke("lecornu", "example", "-f", "csv")
    assert piped.code == 0 and piped.err == ""
