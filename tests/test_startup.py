"""Start-up: `pendcli --help` and `pendcli list` import neither scipy nor matplotlib; the bench
code runs on a tiny configuration (no timing is asserted: timings are benchmarks)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from pendcli import bench
from pendcli.render import OutputFormat  # named by the probe command's annotations

HEAVY = ("scipy", "matplotlib")

PROBE = """
import sys
sys.argv = ["pendcli", *{args!r}]
from pendcli.cli.main import run
try:
    run()
except SystemExit:
    pass
loaded = sorted({{m.split(".")[0] for m in sys.modules}} & {heavy!r})
sys.stderr.write("LOADED=" + ",".join(loaded) + "\\n")
"""


@pytest.mark.parametrize(
    "args",
    [
        ["--help"],
        ["-V"],
        ["list"],
        ["lecornu"],  # a bare group prints its help
        ["lecornu", "--help"],
        ["tradeoff", "--help"],
        ["charbonnier", "integral", "--help"],
        ["--show-completion", "bash"],
    ],
    ids=lambda a: " ".join(a),
)
def test_light_commands_do_not_import_scipy_or_matplotlib(args):
    proc = subprocess.run(
        [sys.executable, "-c", PROBE.format(args=args, heavy=set(HEAVY))],
        capture_output=True,
        text=True,
        check=True,
    )
    line = [x for x in proc.stderr.splitlines() if x.startswith("LOADED=")][-1]
    assert line == "LOADED=", f"pendcli {' '.join(args)} imported {line[7:]}"


def test_import_costs_parses_importtime():
    costs = dict(bench.import_costs(["--help"], top=50))
    assert "typer" in costs and costs["typer"] > 0
    assert not set(costs) & set(HEAVY)


def test_bench_runs_on_a_tiny_configuration(tmp_path, monkeypatch):
    quick = [sys.executable, "-c", "pass"]
    monkeypatch.setattr(
        bench,
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
    """typer would convert every option through pydantic (~0.04 s); rich is for tables only."""
    proc = subprocess.run(
        [sys.executable, "-c", PROBE.format(args=args, heavy={"pydantic", "rich"})],
        capture_output=True,
        text=True,
        check=True,
    )
    line = [x for x in proc.stderr.splitlines() if x.startswith("LOADED=")][-1]
    assert line == "LOADED=", f"pendcli {' '.join(args)} imported {line[7:]}"


def _typer_coercions():
    """Per annotation: (pendcli's PlainCoercion, typer's own pydantic-backed coercion)."""
    import typer

    from pendcli.cli.main import PlainCoercion

    def probe(
        real: float = 0.0, whole: int = 0, text: str = "", fmt: OutputFormat = OutputFormat.table
    ) -> None:
        """Only carries the options."""

    app = typer.Typer(add_completion=False)
    app.command()(probe)
    params = typer.main.get_command(app).params
    return {
        p.type_descriptor.annotation: (
            PlainCoercion(p, p.type_descriptor.annotation),
            p.get_runtime_param(),  # nothing installed yet: typer's own
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
    elsewhere it defers, so typer's value or error stands."""
    import typer

    from pendcli.cli.main import _UNSET

    for annotation, (plain, typer_own, param) in _typer_coercions().items():
        direct = plain.direct(value)
        if direct is _UNSET:
            continue
        try:
            expected = typer_own.coerce(value, param=param, ctx=None)
        except typer.BadParameter as exc:
            raise AssertionError(f"{annotation}: {value!r} accepted, typer refuses: {exc}") from exc
        assert type(direct) is type(expected) and direct == expected, (annotation, value)
