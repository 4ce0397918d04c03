"""`pendcli -V --verbose` and report.md name the library versions."""

from __future__ import annotations

from importlib.metadata import version

import pytest
from helpers.cli import invoke

from pendcli.base.versions import LIBRARIES


def test_version_alone_is_one_line() -> None:
    code, out, err = invoke("-V")
    assert (code, err) == (0, "")
    assert out == f"pendcli {version('pendcli')}\n"


@pytest.mark.parametrize("args", [("-V", "--verbose"), ("--verbose", "-V")])
def test_verbose_version_names_every_library(args: tuple[str, ...]) -> None:
    code, out, err = invoke(*args)
    assert (code, err) == (0, "")
    shown = dict(line.split(" ", 1) for line in out.splitlines())
    for name in ("numpy", "scipy", "mpmath", "sympy", "matplotlib", "typer"):
        assert shown[name] == version(name)
    assert set(LIBRARIES) <= set(shown)
    assert shown["python"].count(".") == 2


def test_verbose_without_version_changes_nothing() -> None:
    assert invoke("--verbose", "list", "-p", "tisserand", "-f", "json") == invoke(
        "list", "-p", "tisserand", "-f", "json"
    )
