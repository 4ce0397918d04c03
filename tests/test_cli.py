"""The CLI as a user meets it: outputs, one-line errors, exit codes, never a traceback."""

from __future__ import annotations

import json

import pytest
from cli_helpers import assert_clean_error, invoke
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st


def test_help_and_version():
    code, out, _ = invoke("--help")
    assert code == 0 and "reproduce" in out and "charbonnier" in out
    code, out, _ = invoke("--version")
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


BAD_VALUES = [
    "-1",
    "0",
    "-0",
    "nan",
    "inf",
    "-inf",
    "1e400",
    "abc",
    "",
    "3.5",
    "1e9",
    "-1e-300",
    "91°",
    "30'",
    "-5deg",
    "1e9rad",
    "2x",
]
COMMANDS = [
    ["lecornu", "example", "--speed"],
    ["lecornu", "example", "--length"],
    ["lecornu", "example", "--g"],
    ["lecornu", "zeros", "--order"],
    ["lecornu", "zeros", "--order", "1", "--count"],
    ["lecornu", "claims", "--g"],
    ["tisserand", "example", "--theta0"],
    ["tisserand", "example", "--theta1"],
    ["tisserand", "example", "--length"],
    ["charbonnier", "integral"],
    ["charbonnier", "table", "--n-max"],
    ["charbonnier", "integral", "3", "--x"],
    ["list", "--paper"],
    ["reproduce", "--paper"],
    ["charbonnier", "table", "--format"],
]


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    command=st.sampled_from(COMMANDS),
    value=st.one_of(st.sampled_from(BAD_VALUES), st.text(max_size=6)),
    extra=st.lists(st.sampled_from([*BAD_VALUES, "--format", "--x", "json"]), max_size=2),
)
def test_fuzz_cli_never_tracebacks(command, value, extra):
    code, _, err = invoke(*command, value, *extra)
    assert "Traceback" not in err
    assert code in (0, 2), err
    if code == 2:
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
