"""Start-up: `pendcli --help` and `pendcli list` import neither scipy nor matplotlib; the bench
code runs on a tiny configuration (no timing is asserted: timings are benchmarks)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from pendcli import bench

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
    from pendcli import tradeoff

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
