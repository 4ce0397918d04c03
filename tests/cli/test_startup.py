"""Start-up: `pendcli --help` and `pendcli list` import neither scipy nor matplotlib; the bench
code runs on a tiny configuration (no timing is asserted: timings are benchmarks)."""

from __future__ import annotations

import re
import subprocess
import sys
from functools import cache
from typing import Annotated

import pytest
import typer

from pendcli.cli.values import number, word  # named by the probe command's annotations
from pendcli.output import OutputFormat
from tools import bench, bench_startup

HEAVY = ("scipy", "matplotlib")

# One fresh interpreter imports what every command imports (pendcli.cli.main, as `python -m
# pendcli` does before it reads its arguments), then runs each command in a child forked from
# that state: each child starts where a fresh `pendcli` process would be when it reads its
# arguments, and says which of the heavy packages it has loaded once its command is done.
# Eight commands cost one interpreter's start-up and imports, not eight.
PROBE = """
import os
import sys

from pendcli.cli.main import run

for index, args in enumerate({arg_lists!r}):
    sys.stdout.flush()
    sys.stderr.flush()
    if os.fork() == 0:
        try:
            sys.argv = ["pendcli", *args]
            try:
                run()
            except SystemExit:
                pass
            loaded = sorted({{m.split(".")[0] for m in sys.modules}} & {heavy!r})
            sys.stdout.flush()
            sys.stderr.write(f"LOADED[{{index}}]=" + ",".join(loaded) + "\\n")
            sys.stderr.flush()
        finally:
            os._exit(0)
    os.wait()
"""


@cache
def _loaded(
    arg_lists: tuple[tuple[str, ...], ...], heavy: frozenset[str]
) -> dict[tuple[str, ...], str]:
    """Per command line of ``arg_lists``: the packages of ``heavy`` it loaded (comma-separated)."""
    proc = subprocess.run(
        [sys.executable, "-c", PROBE.format(arg_lists=arg_lists, heavy=set(heavy))],
        capture_output=True,
        text=True,
        check=True,
    )
    said = dict(re.findall(r"^LOADED\[(\d+)\]=(.*)$", proc.stderr, re.MULTILINE))
    assert len(said) == len(arg_lists), proc.stderr
    return {args: said[str(index)] for index, args in enumerate(arg_lists)}


LIGHT = [
    ["--help"],
    ["-V"],
    ["list"],
    ["lecornu"],  # a bare group prints its help
    ["lecornu", "--help"],
    ["tradeoff", "--help"],
    ["charbonnier", "integral", "--help"],
    ["--show-completion", "bash"],
]


@pytest.mark.parametrize("args", LIGHT, ids=lambda a: " ".join(a))
def test_light_commands_do_not_import_scipy_or_matplotlib(args):
    loaded = _loaded(tuple(map(tuple, LIGHT)), frozenset(HEAVY))[tuple(args)]
    assert loaded == "", f"pendcli {' '.join(args)} imported {loaded}"


def test_import_costs_parses_importtime():
    costs = dict(bench_startup.import_costs(["--help"], top=50))
    assert "typer" in costs and costs["typer"] > 0
    assert not set(costs) & set(HEAVY)


def test_bench_runs_on_a_tiny_configuration(tmp_path, monkeypatch):
    quick = ["true"]  # a command that costs nothing: what is run is not under test here
    monkeypatch.setattr(
        bench_startup,
        "_commands",
        lambda: {
            k: quick
            for k in (
                "import typer",
                "pendcli --help",
                "import scipy.special, scipy.integrate",
                "pendcli reproduce --format json",
            )
        },
    )
    monkeypatch.setattr(bench, "import_costs", lambda args, top=8: [("typer", 0.01)])
    from pendcli.run import tradeoff

    monkeypatch.setattr(tradeoff, "family_names", lambda: ["planar_period"])
    text = bench.run(runs=1, quick=True, tables=True, root=tmp_path)
    assert (tmp_path / "tradeoff" / "planar_period.csv").exists()
    assert "pendcli --help" in text and "planar_period" in text and "nproc" in text

    readme = tmp_path / "README.md"
    readme.write_text(f"# x\n\n{bench.START}\nold\n{bench.END}\ntail\n", encoding="utf-8")
    assert bench.write_section(readme, text)
    content = readme.read_text(encoding="utf-8")
    assert "old" not in content and text in content and content.endswith("tail\n")
    bare = tmp_path / "BARE.md"
    bare.write_text("no markers\n", encoding="utf-8")
    assert not bench.write_section(bare, text)
    assert bare.read_text(encoding="utf-8") == "no markers\n"


LIGHT_JSON = [
    ["list", "--format", "json"],
    ["list", "-f", "csv", "--paper", "lecornu"],
    ["lecornu", "zeros", "--count", "3", "-f", "json"],
    ["charbonnier", "integral", "2", "--x", "1.5", "-f", "markdown"],
]


@pytest.mark.parametrize("args", LIGHT_JSON, ids=lambda a: " ".join(a))
def test_plain_options_and_data_formats_import_neither_pydantic_nor_rich(args):
    """typer would convert every option through pydantic (pendcli.cli.coercion: ~0.19 s of
    CPU); rich is for tables only."""
    loaded = _loaded(tuple(map(tuple, LIGHT_JSON)), frozenset({"pydantic", "rich"}))[tuple(args)]
    assert loaded == "", f"pendcli {' '.join(args)} imported {loaded}"


@cache  # built once for the 44 spellings: both coercions only read their parameter
def _typer_coercions():
    """Per parameter: (pendcli's PlainCoercion, typer's own pydantic-backed coercion)."""
    from pendcli.cli.coercion import PlainCoercion

    def probe(
        real: float = 0.0,
        whole: int = 0,
        text: str = "",
        fmt: OutputFormat = OutputFormat.table,
        read: Annotated[float, typer.Option(parser=number)] = 0.0,
        folded: Annotated[str, typer.Option(parser=word)] = "",
    ) -> None:
        """Only carries the options."""

    app = typer.Typer(add_completion=False)
    app.command()(probe)  # a plain typer command: its parameters keep typer's coercion
    params = typer.main.get_command(app).params
    return {
        p.name: (
            PlainCoercion(p, p.type_descriptor.annotation, p.type_descriptor.parameter_info.parser),
            p.get_runtime_param(),
            p,
        )
        for p in params
    }


SPELLINGS = [
    "0", "-0", "+0", "1", "-17", "+5", "007", "1.", ".5", "-.5", "+.5", "1.25", "1e3", "1E-3",
    "2.5e+10", "1e308", "1e309", "1e-330", "123456789012345678", "9" * 30, "1_000", " 1", "1 ",
    "inf", "-inf", "nan", "NaN", "abc", "", "0x10", "1e", "e5", ".", "-", "1.5.2", "١٢",
    "json", "JSON", "table", "csv ", "markdown", 1.5, 2, True,
]  # fmt: skip


@pytest.mark.parametrize("value", SPELLINGS, ids=repr)
def test_plain_coercion_gives_what_typer_gives(value):
    """Where PlainCoercion converts directly, typer's coercion gives the same value and type;
    where the option's reader refuses, typer refuses in its words; elsewhere it defers, so
    typer's value or error stands."""
    import math

    import typer

    from pendcli.cli.coercion import UNSET

    for name, (plain, typer_own, param) in _typer_coercions().items():
        try:
            direct = plain.direct(value)
        except ValueError as refused:
            with pytest.raises(typer.BadParameter, match=re.escape(str(refused))):
                typer_own.coerce(value, param=param, ctx=None)
            continue
        if direct is UNSET:
            continue
        try:
            expected = typer_own.coerce(value, param=param, ctx=None)
        except typer.BadParameter as exc:
            raise AssertionError(f"{name}: {value!r} accepted, typer refuses: {exc}") from exc
        same = direct == expected or (math.isnan(direct) and math.isnan(expected))
        assert type(direct) is type(expected) and same, (name, value)


# Assignments that change what typer or click made, by the attribute they set: a class swapped,
# a method replaced on an instance (a parameter's reader, its usage, a command's callback).
_REWRITES = re.compile(
    r"\.(__class__|process_value|get_usage_pieces|display_type_rich|callback|context_class"
    r"|short_help|epilog|metavar|get_runtime_param)\s*=[^=]"
)


def test_the_cli_changes_nothing_typer_made_but_in_its_one_trick():
    """typer is used as it comes (its public ``cls``, ``metavar``, ``parser``, ``epilog``):
    the one start-up trick, plain values without pydantic, lives in pendcli/cli/coercion.py."""
    from pathlib import Path

    folder = Path(__file__).resolve().parents[2] / "pendcli" / "cli"
    found = {
        path.name: [m.group(1) for m in _REWRITES.finditer(path.read_text(encoding="utf-8"))]
        for path in sorted(folder.glob("*.py"))
    }
    assert {name: hits for name, hits in found.items() if hits} == {"coercion.py": ["__class__"]}
