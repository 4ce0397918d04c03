"""make bench: one measurement behind every timing the README states."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tools import bench_startup, bench_summary

STARTUP = {
    "import typer": 0.05,
    "pendcli --help": 0.06,  # 1.2x: met (target 1.3)
    "import scipy.special, scipy.integrate": 0.40,
    "pendcli reproduce --format json": 0.80,  # 2.0x: missed (target 1.8)
}


def _floor() -> bench_startup.FloorTimes:
    times: bench_startup.FloorTimes = {(bench_startup.FLOOR, ""): (1.0, 2.0)}
    for label in bench_startup.FLOOR_TARGETS:
        times[label, "cold"] = (9.0, 30.0)
        times[label, "warm"] = (0.5, 0.25)
    return times


def test_each_headline_is_its_figure_over_its_reference_judged_against_its_target() -> None:
    heads = {
        h.what: h for h in bench_startup.headlines(STARTUP, _floor(), (30.0, 50.0), (12.0, 8.0))
    }
    assert heads["`pendcli --help`"].ratio == "wall 1.20x `import typer`"
    assert heads["`pendcli --help`"].target == "<= 1.3x (met)"
    assert heads["`pendcli reproduce --format json`"].target == "<= 1.8x (missed)"
    # CPU against B's 2.0 s of CPU; wall against B's 1.0 s of wall
    cold = heads["`pendcli equations --format json`, cold"]
    assert (cold.ratio, cold.target) == ("CPU 15.00x B", "<= 4x (missed)")
    warm = heads["`pendcli equations --format json`, warm"]
    assert (warm.ratio, warm.target) == ("CPU 0.12x B", "<= 4x (met)")
    out = heads["`pendcli reproduce --out DIR`, cold"]
    assert (out.ratio, out.target) == ("wall 9.00x B", "<= 4x (missed)")
    assert heads["`make test` (the fast suite)"].target == "<= 25 s wall (missed)"
    assert heads["install from nothing (`make reproduce`'s venv)"].target == "<= 15 s wall (met)"


def test_the_readme_block_is_replaced_between_its_markers_only() -> None:
    text = f"a\n{bench_summary.SUMMARY_START}\nold\n{bench_summary.SUMMARY_END}\nb\n"
    new = bench_summary.with_summary(text, ["x", "y"])
    assert new == f"a\n{bench_summary.SUMMARY_START}\nx\ny\n{bench_summary.SUMMARY_END}\nb\n"
    assert bench_summary.with_summary("no markers", ["x"]) is None


def test_the_tag_changes_with_any_figure() -> None:
    one = bench_startup.headlines(STARTUP, _floor(), (30.0, 50.0), None)
    other = bench_startup.headlines(STARTUP, _floor(), (30.5, 50.0), None)
    assert bench_summary.measurement_tag(list(map(str, one))) != bench_summary.measurement_tag(
        list(map(str, other))
    )


def test_the_readme_and_the_benchmarks_page_come_from_one_measurement() -> None:
    """The README's timings and docs/benchmarks.md carry the same tag: written by one run."""
    root = Path(__file__).resolve().parents[2]
    readme = (root / "docs" / "install.md").read_text("utf-8")
    page = (root / "docs" / "benchmarks.md").read_text("utf-8")
    block = readme.split(bench_summary.SUMMARY_START, 1)[1].split(bench_summary.SUMMARY_END)[0]
    tags = re.findall(r"measurement `([0-9a-f]{12})`", block)
    if not tags:
        pytest.fail("the README's timings block was never written by `make bench`")
    assert re.search(rf"Measurement `{tags[0]}`", page), "docs/benchmarks.md is another run's"


@pytest.mark.parametrize(
    ("args", "says"),
    [
        (["--runs", "0"], "--runs: 0 is out of range; expected >= 1"),
        (["--floor-runs", "x"], "--floor-runs: 'x' is not a whole number; expected >= 1"),
        (["--summary", "/nonexistent/README.md"], "--summary /nonexistent/README.md: no such"),
    ],
)
def test_a_bad_bench_argument_is_one_line_and_exit_2(
    args: list[str], says: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """Read by bench's own main, in this process (the entry point's exit status, in a
    process, is the next test's)."""
    from tools import bench

    with pytest.raises(SystemExit) as exit_info:
        bench.main(args)
    err = capsys.readouterr().err
    assert exit_info.value.code == 2
    assert says in err.strip().splitlines()[-1]
    assert "Traceback" not in err


def test_the_bench_entry_point_exits_2_with_one_line_for_a_bad_argument() -> None:
    import subprocess
    import sys

    run = subprocess.run(
        [sys.executable, "-m", "tools.bench", "--runs", "0"], capture_output=True, text=True
    )
    assert run.returncode == 2
    assert "--runs: 0 is out of range; expected >= 1" in run.stderr.strip().splitlines()[-1]
    assert "Traceback" not in run.stderr


def test_a_timed_run_accounts_its_children_and_raises_with_their_stderr() -> None:
    """The CPU of a child's child is counted (a busy loop of ~0.1 s in a grandchild: above
    the child's own start, ~0.03 s), an exit status outside ``allowed`` raises with the run's
    stderr, one inside does not."""
    import os
    import subprocess
    import sys

    busy = "import time\nt = time.process_time()\nwhile time.process_time() - t < 0.1: pass"
    child = f"import subprocess, sys; subprocess.run([sys.executable, '-c', {busy!r}])"
    wall, cpu = bench_summary.timed_process([sys.executable, "-c", child], dict(os.environ))
    assert cpu >= 0.1 and wall >= 0.1
    fail = ["sh", "-c", "printf broken >&2; exit 3"]
    with pytest.raises(subprocess.CalledProcessError) as raised:
        bench_summary.timed_process(fail, dict(os.environ))
    assert raised.value.returncode == 3 and raised.value.stderr == "broken"
    assert bench_summary.timed_process(fail, dict(os.environ), allowed=(3,))[0] > 0


def test_the_ledgers_floor_is_shown_as_its_share_of_b_in_cpu() -> None:
    """What a cold `equations` pays before any check, as CPU over B's CPU (3.0 / 2.0)."""
    times = {**_floor(), (bench_startup.LEDGERS, ""): (2.5, 3.0)}
    text = "\n".join(bench_startup.floor_lines(times, 1))
    assert f"| {bench_startup.LEDGERS} | | 2.50 | 3.00 | CPU 1.50x B | |" in text
    assert bench_startup.LEDGERS not in "\n".join(bench_startup.floor_lines(_floor(), 1))


def test_the_derivations_floor_is_a_row_of_the_table_and_a_headline_as_its_share_of_b() -> None:
    """Stored derivations read back, without a verdict: 7.0 s of CPU over B's 2.0 s is 3.50x
    B, in the table beside the ledgers' row and among the README's headlines; absent, neither
    shows."""
    times = {
        **_floor(),
        (bench_startup.LEDGERS, ""): (2.5, 3.0),
        (bench_startup.DERIVATIONS, ""): (6.0, 7.0),
    }
    text = "\n".join(bench_startup.floor_lines(times, 1))
    assert f"| {bench_startup.DERIVATIONS} | | 6.00 | 7.00 | CPU 3.50x B | |" in text
    assert text.index(bench_startup.LEDGERS) < text.index(bench_startup.DERIVATIONS)
    heads = {h.what: h for h in bench_startup.headlines(STARTUP, times, None, None)}
    assert (heads[bench_startup.DERIVATIONS].cpu, heads[bench_startup.DERIVATIONS].ratio) == (
        7.0,
        "CPU 3.50x B",
    )
    assert bench_startup.DERIVATIONS not in {
        h.what for h in bench_startup.headlines(STARTUP, _floor(), None, None)
    }


def test_the_derivations_floor_command_reads_every_stored_row_of_every_ledger(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from pendcli.data.ledger import load_ledger
    from pendcli.papers.registry import ledger_papers
    from pendcli.verify import derivation_store

    read: list[str] = []
    real = derivation_store.row_record
    monkeypatch.setattr(
        derivation_store,
        "row_record",
        lambda name, record, nodes: read.append(name) or real(name, record, nodes),
    )
    exec(bench_startup.READ_DERIVATIONS, {})
    rows = {row.id for key in ledger_papers() for row in load_ledger(key).rows}
    assert len(read) == len(set(read)) > 300  # every row but the few judged live
    assert set(read) <= rows


def test_the_ledgers_floor_command_reads_every_ledger(monkeypatch: pytest.MonkeyPatch) -> None:
    from pendcli.data import ledger
    from pendcli.papers.registry import ledger_papers

    read: list[str] = []
    monkeypatch.setattr(ledger, "load_ledger", lambda key: read.append(key))
    exec(bench_startup.READ_LEDGERS, {})
    assert read == list(ledger_papers()) and len(read) == 3
