"""Lecornu's inputs and commands: a bad input is one line naming it and its range, and each
command's output in every format (the example's constants read from the published table)."""

from __future__ import annotations

import json

import pytest
from helpers.cli import assert_clean_error, invoke

from pendcli.base.errors import PendcliError
from pendcli.data.tables import load_paper_table
from pendcli.papers.lecornu import claims, model

TABLE = load_paper_table("lecornu")
G = TABLE.constant("g")
B = TABLE.constant("speed")
L = TABLE.constant("length")


# --- input errors -----------------------------------------------------------------------


@pytest.mark.parametrize(
    "kwargs",
    [
        {"speed": 0.0},
        {"speed": -0.35},
        {"speed": float("nan")},
        {"length": -1.0},
        {"length": float("inf")},
        {"g": 0.0},
        {"speed": 1e-3, "length": 1000.0},  # too many oscillations
        {"speed": 10.0},  # too fast: no elongation of (10) below the release
    ],
    ids=lambda kw: ",".join(f"{k}={v}" for k, v in kw.items()),
)
def test_example_bad_input(kwargs):
    with pytest.raises(PendcliError, match=r" must be |; expected "):
        model.example_model(**{"speed": B, "length": L, "g": G, **kwargs})


@pytest.mark.parametrize("g", [3.5, 12.0, float("nan"), "9.81"])
def test_claims_refuse_a_g_that_changes_the_example(g):
    with pytest.raises(PendcliError, match="structure of the printed example"):
        claims.recompute(g)


def test_elongation_times_bad_method():
    with pytest.raises(PendcliError, match="bessel, ode"):
        model.elongation_times(B, L, G, "rk4")


# --- CLI ------------------------------------------------------------------------------------


def _lecornu(*args):
    return invoke("lecornu", *args)


@pytest.mark.parametrize("fmt", ["table", "markdown", "json", "csv"])
def test_cli_zeros_formats(fmt):
    result = _lecornu("zeros", "--order", "2", "--count", "5", "--format", fmt)
    assert result.code == 0, result.out
    # the terminal shows 7 significant digits, Markdown 10, JSON and CSV every digit
    assert ("17.95982" if fmt == "table" else "17.95981949") in result.out


@pytest.mark.parametrize(
    ("args", "key"),
    [
        (("series",), "limits"),
        (("zero-length", "--speed", "10"), "rows"),
        (("ode-check", "--amplitude", "2", "--floor", "0.1"), "rows"),
    ],
)
def test_cli_other_commands_json(args, key):
    result = _lecornu(*args, "--format", "json")
    assert result.code == 0, result.out
    assert json.loads(result.out)[key]


@pytest.mark.parametrize(
    "args",
    [
        ("example", "--length", "-1"),
        ("example", "--speed", "0"),
        ("zeros", "--count", "0"),
        ("zeros", "--order", "3"),
        ("zeros", "--count", "9", "--method", "series"),
        ("ode-check", "--floor", "0"),
        ("ode-check", "--amplitude", "180"),
        ("claims", "--g", "3.5"),
    ],
    ids=" ".join,
)
def test_cli_bad_input_is_one_error(args):
    result = _lecornu(*args)
    assert_clean_error(result.code, result.err)
    assert " must be " in result.err or "; expected " in result.err, result.err
