"""The CLI as a user meets it: outputs, one-line errors, exit codes, never a traceback."""

from __future__ import annotations

import contextlib
import errno
import io
import json
import os
import subprocess
import sys
from functools import cache

import pytest
from helpers.cli import (
    NO_BYTECODE,
    assert_clean_error,
    invoke,
    invoke_in_a_child,
    run_cli,
    run_cli_forked,
)

from pendcli.cli.main import run


def test_help_and_version():
    code, out, _ = invoke("--help")
    assert code == 0 and "reproduce" in out and "charbonnier" in out
    assert "--install-completion" in out and "-V, --version" in out
    for flag in ("--version", "-V"):
        code, out, _ = invoke(flag)
        assert code == 0 and out.startswith("pendcli ")


def test_charbonnier_table_json_schema():
    code, out, _ = invoke("charbonnier", "table", "--format", "json")
    assert code == 0
    doc = json.loads(out)
    assert set(doc) >= {"claims", "formulas"}
    for row in doc["claims"]:
        assert {"id", "paper", "source", "quantity", "published", "recomputed", "verdict"} <= set(
            row
        )
        assert isinstance(row["recomputed"], float)
        assert row["verdict"] in {"agrees", "truncated", "last-digit", "discrepant"}
    assert [r["n"] for r in doc["table"]] == list(range(-1, 6))


@pytest.mark.parametrize("fmt", ["table", "json", "csv", "markdown"])
def test_every_format_is_deterministic(fmt):
    first = invoke("charbonnier", "table", "--n-max", "8", "--format", fmt)
    assert first[0] == 0 and first[1]
    assert invoke("charbonnier", "table", "--n-max", "8", "--format", fmt) == first


def test_integral_accepts_negative_order_and_real_x():
    code, out, _ = invoke("charbonnier", "integral", "-1", "--x", "2.5", "--format", "json")
    assert code == 0
    assert json.loads(out)["integral"]["value"] == 2.5


def _pixels_of(image, rgb: tuple[int, int, int]) -> int:
    import numpy as np

    return int(np.all(np.abs(image[:, :, :3] - np.array(rgb) / 255) < 0.05, axis=-1).sum())


def test_plot_is_written(tmp_path):
    """The figure shows the recomputed curve (tab:blue) and the printed entries (tab:red)."""
    import matplotlib.image as mpimg

    path = tmp_path / "in.png"
    code, out, err = invoke("charbonnier", "table", "--plot", str(path), "--format", "json")
    assert code == 0, err
    assert json.loads(out)["claims"]  # the plot does not replace the output
    image = mpimg.imread(path)
    assert _pixels_of(image, (31, 119, 180)) > 200  # the curve
    assert _pixels_of(image, (214, 39, 40)) > 50  # the printed entries' circles


@pytest.mark.parametrize(
    "args",
    [
        ("charbonnier", "integral", "-3"),
        ("charbonnier", "integral", "abc"),
        ("charbonnier", "integral", "2", "--x", "nan"),
        ("charbonnier", "integral", "2", "--x", "inf"),
        ("charbonnier", "integral", "2", "--x", "1e400"),
        ("charbonnier", "integral", "99999999999999999999"),
        ("charbonnier", "table", "--n-max", "-5"),
        ("charbonnier", "table", "--n-max", "10000000"),
        ("charbonnier", "table", "--format", "xml"),
        ("charbonnier", "table", "--plot", "out.txt"),
        ("reproduce", "--paper", "newton"),
        ("list", "--paper", ""),
        ("nosuchcommand",),
        ("lecornu", "example", "--speed", "-0.35"),
        ("lecornu", "claims", "--g", "3.5"),  # found by the fuzz test: the example's structure
        ("lecornu", "example", "--length", "0"),
        ("lecornu", "example", "--g", "nan"),
        ("lecornu", "zeros", "--order", "3"),
        ("lecornu", "zeros", "--order", "1", "--count", "0"),
        ("tisserand", "example", "--theta0", "95°"),
        ("tisserand", "example", "--theta0", "30", "--theta1", "15°"),
        ("tisserand", "example", "--theta0", "15°", "--theta1", "30°"),
        ("tisserand", "example", "--length", "-0.5"),
        ("formulas", "--paper", "kepler"),
        ("formulas", "--plot", "README.md"),
        ("charbonnier", "nosuch"),
    ],
)
def test_bad_input_gives_one_line_and_exit_2(args):
    code, _, err = invoke(*args)
    assert_clean_error(code, err)


def test_tol_picks_a_measured_method_and_says_which():
    code, out, _ = invoke("lecornu", "zeros", "--tol", "1e-12", "--count", "3", "--format", "json")
    assert code == 0
    doc = json.loads(out)
    assert "<= tol 1e-12" in doc["method_reason"]
    code, out, _ = invoke("lecornu", "zeros", "--method", "scipy", "--format", "json")
    assert json.loads(out)["method_reason"] == "forced by --method"
    code, _, err = invoke("lecornu", "zeros", "--tol", "1e-30")
    assert_clean_error(code, err)
    assert "out of reach" in err


# --- the command line as a new user meets it -------------------------------------


@pytest.mark.parametrize("group", [(), ("lecornu",), ("tisserand",), ("charbonnier",)])
def test_bare_command_prints_its_help(group):
    """As typer's no_args_is_help does: the help on stderr, exit 2, nothing on stdout."""
    code, out, err = invoke(*group)
    assert code == 2 and out == ""
    assert err.startswith(f"Usage: pendcli {' '.join(group)}".rstrip()) and "Commands:" in err


def test_help_summaries_are_whole_sentences():
    """click's short help stops at the first period ("... on eq."): pendcli gives the line."""
    code, out, _ = invoke("lecornu", "--help")
    assert code == 0
    assert "integrated directly, linear and with sin θ." in " ".join(out.split())


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (("lecornu", "claims", "--g", "abc"), "--g must be a number, got 'abc'"),
        (("lecornu", "zeros", "--count", "2.5"), "--count must be an integer, got '2.5'"),
        (("charbonnier", "integral", "abc"), "N must be an integer, got 'abc'"),
        # integral reads a negative N, so click took an unknown option for N or an extra one
        (("charbonnier", "integral", "--n", "1e30"), "No such option: --n"),
        (("charbonnier", "integral", "4", "--bogus=3"), "No such option: --bogus"),
        (("charbonnier", "integral", "4", "-7"), "Got unexpected extra argument(s) (-7)"),
        (
            ("charbonnier", "table", "-f", "xml"),
            "-f must be one of table, json, csv or markdown, got 'xml'",
        ),
        (
            ("charbonnier", "table", "--format", "xml"),
            "--format must be one of table, json, csv or markdown, got 'xml'",
        ),
        (("lecornu", "example", "--speed", "-1"), "--speed must be in [0.001, 1000] m/s, got -1.0"),
        (("lecornu", "ode-check", "--floor", "0.9"), "--floor must be in [1e-09, 0.5], got 0.9"),
        (("lecornu", "example", "--speed=-1"), "--speed must be in [0.001, 1000] m/s, got -1.0"),
    ],
)
def test_errors_name_the_option_as_typed(args, expected):
    code, _, err = invoke(*args)
    assert_clean_error(code, err)
    assert err.startswith(f"pendcli: error: {expected}"), err
    assert "Input should be" not in err and "Value error" not in err


@pytest.mark.parametrize(
    "args",
    [
        ("lecornu", "zeros", "--tol", "1e-9", "--method", "scipy"),
        ("charbonnier", "integral", "3", "--method", "quad", "--tol", "1e-9"),
    ],
)
def test_tol_and_method_exclude_each_other(args):
    code, _, err = invoke(*args)
    assert_clean_error(code, err)
    assert "--tol and --method exclude each other" in err


def test_quiet_is_accepted_everywhere_and_silences_status():
    code, _, err = invoke("lecornu", "zeros", "--count", "2")
    assert code == 0 and "method:" in err
    code, _, err = invoke("lecornu", "zeros", "--count", "2", "--quiet")
    assert code == 0 and err == ""
    assert invoke("list", "-q", "-p", "lecornu")[0] == 0
    for command in (
        ("list",),
        ("reproduce",),
        ("check",),
        ("formulas",),
        ("tradeoff",),
        ("charbonnier", "integral"),
        ("tisserand", "series"),
        ("lecornu", "ode-check"),
    ):
        code, out, _ = invoke(*command, "--help")
        assert code == 0 and "--quiet" in out, command


def test_plot_refuses_a_missing_folder_and_creates_none(tmp_path):
    target = tmp_path / "missing" / "dir" / "f.png"
    code, _, err = invoke("charbonnier", "table", "--plot", str(target))
    assert_clean_error(code, err)
    assert f"--plot: folder {target.parent} does not exist" in err
    assert not (tmp_path / "missing").exists()


def test_formulas_plot_refuses_a_file_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, _, err = invoke("formulas", "-p", "charbonnier", "--plot", "x.png")
    assert_clean_error(code, err)
    assert list(tmp_path.iterdir()) == []


def test_shell_completion_sees_lazy_commands():
    env = {
        **os.environ,
        "_PENDCLI_COMPLETE": "complete_bash",
        "COMP_WORDS": "pendcli lecornu ze",
        "COMP_CWORD": "2",
    }
    proc = run_cli(env=env)
    assert proc.returncode == 0, proc.stderr
    assert set(proc.stdout.split()) == {"zeros", "zero-length"}
    # the top level through the same entry point in this process (click reads the variables
    # when the command runs)
    top = {"_PENDCLI_COMPLETE": "complete_bash", "COMP_WORDS": "pendcli ", "COMP_CWORD": "1"}
    assert {"reproduce", "lecornu", "tradeoff"} <= set(invoke(env=top).out.split())
    # typer detects the calling shell (sh under make); with detection off (a variable typer
    # reads when it is imported: a fresh process) it takes a name
    env = {**os.environ, "_TYPER_COMPLETE_TEST_DISABLE_SHELL_DETECTION": "1"}
    proc = run_cli("--show-completion", "bash", env=env)
    assert proc.returncode == 0, proc.stderr
    assert "_PENDCLI_COMPLETE=complete_bash" in proc.stdout


# --- every OS error one line naming the path, exit 2; any locale -----------------


def _pendcli(*args, **kwargs):
    return run_cli(*args, **kwargs)


def _one_line(proc, expected: str) -> None:
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr == f"pendcli: error: {expected}\n", proc.stderr


FULL_DISK = [("list",), ("--help",), ("-V",), ("list", "-f", "json")]


@cache
def _on_a_full_disk(folder: str) -> dict[tuple[str, ...], tuple[int, str]]:
    """Each command of FULL_DISK run by the real entry point, its stdout /dev/full."""
    runs = run_cli_forked(FULL_DISK, "/dev/full", f"{folder}/stderr")
    return dict(zip(FULL_DISK, runs, strict=True))


@pytest.mark.parametrize("args", FULL_DISK)
def test_full_disk_on_stdout(args, tmp_path_factory):
    folder = tmp_path_factory.getbasetemp() / "full-disk"
    folder.mkdir(exist_ok=True)
    code, err = _on_a_full_disk(str(folder))[args]
    full_disk = "cannot write standard output: No space left on device"
    assert (code, err) == (2, f"pendcli: error: {full_disk}\n"), err


def test_closed_stdout():
    proc = run_cli("list", stderr=subprocess.PIPE, close_fds=False, preexec_fn=lambda: os.close(1))
    _one_line(proc, "cannot write standard output: it is closed")


def test_broken_pipe_leaves_quietly_like_other_tools():
    # `pendcli reproduce | head`: the reader stopping is no fault. Exit 141 (128 + SIGPIPE,
    # what a shell shows for a process SIGPIPE killed), nothing on stderr, no
    # "Exception ignored" at shutdown.
    import signal

    read, write = os.pipe()
    os.close(read)  # nobody will read: the first write fails with EPIPE
    proc = run_cli("list", "-f", "json", stdout=write, stderr=subprocess.PIPE)
    os.close(write)
    assert proc.returncode == 128 + signal.SIGPIPE
    assert proc.stderr == ""


def test_file_size_limit_names_the_plot_and_leaves_no_file(tmp_path):
    import resource

    target = tmp_path / "f.png"

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (2048, 2048))

    proc = _pendcli(
        "charbonnier",
        "table",
        "--plot",
        str(target),
        "-f",
        "json",
        preexec_fn=limit,
        env=NO_BYTECODE,
    )
    _one_line(proc, f"cannot write {target}: File too large")
    assert list(tmp_path.iterdir()) == []


def test_os_error_in_a_command_names_the_file(tmp_path, monkeypatch):
    """An OSError escaping a command (here a plot into /dev/full/...) is one line, exit 2."""
    code, _, err = invoke("charbonnier", "table", "--plot", "/dev/full/x.png")
    assert_clean_error(code, err)
    assert "/dev/full" in err


ASCII = {**os.environ, "LC_ALL": "C", "PYTHONIOENCODING": "ascii"}


@pytest.mark.parametrize(
    "args",
    [
        ("list",),
        ("list", "-f", "markdown"),
        ("list", "-f", "csv"),
        ("tisserand", "claims"),
        ("reproduce", "-p", "tisserand", "--no-formulas"),
        ("lecornu", "claims", "--g", "abc"),
    ],
)
def test_ascii_only_locale(args):
    proc = _pendcli(*args, env=ASCII)
    assert proc.returncode in (0, 2), proc.stderr
    assert "Traceback" not in proc.stderr and "internal error" not in proc.stderr
    proc.stdout.encode("ascii")  # nothing but ASCII reached the stream


def test_ascii_only_json_is_the_same_document():
    """The escapes are JSON's own (\\uXXXX): the document parses to the UTF-8 one."""
    plain = invoke("list", "-f", "json")  # the UTF-8 document: in this process
    ascii_only = _pendcli("list", "-f", "json", env=ASCII)
    assert ascii_only.returncode == 0
    assert json.loads(ascii_only.stdout) == json.loads(plain.out)
    assert "\\u03b8" in ascii_only.stdout  # θ


def test_stdout_write_failure_in_process(monkeypatch):
    """The same path in-process: a stdout that fails like a full disk."""

    class Full(io.StringIO):
        def write(self, text):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(sys, "argv", ["pendcli", "list"])
    err = io.StringIO()
    with (
        contextlib.redirect_stdout(Full()),
        contextlib.redirect_stderr(err),
        pytest.raises(SystemExit) as exit_info,
    ):
        run()
    assert exit_info.value.code == 2
    full_disk = "cannot write standard output: No space left on device"
    assert err.getvalue() == f"pendcli: error: {full_disk}\n"


def test_file_size_limit_during_out_names_the_final_path(tmp_path):
    """`--out` is built in a temporary folder: the error names the file under DIR, leaves none."""
    import resource

    out = tmp_path / "out"

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))

    code, _, err = invoke_in_a_child(
        "reproduce",
        "-p",
        "charbonnier",
        "--no-formulas",
        "--no-equations",  # the ledger and the stability table only add computing time:
        "--no-stability",  # the report, tables and figures are still written under --out
        "--out",
        str(out),
        "-q",
        limit=limit,
    )
    assert code == 2, err
    assert err.startswith(f"pendcli: error: cannot write {out}"), err
    assert err.endswith(": File too large\n") and ".new-" not in err
    assert list(tmp_path.iterdir()) == []
