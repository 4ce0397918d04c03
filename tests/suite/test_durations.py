"""The 2 s rule's guard (tests/helpers/durations.py): a fast test over the limit fails it,
a slow one does not, and ``--recheck`` keeps a test only if a rerun alone is over the limit
too (a real pytest process here, on a folder of two tiny tests: one that burns CPU, one that
costs nothing but was recorded as heavy, as a crowded machine would record it)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from helpers import durations

TESTS = Path(__file__).resolve().parents[1]


@pytest.fixture
def bare_pytest(monkeypatch: pytest.MonkeyPatch) -> None:
    """The reruns' pytest processes load no installed plugin (hypothesis, xdist...): what
    they time is the conftest's timing hooks alone, and each starts in 0.15 s, not 0.25 s."""
    monkeypatch.setenv("PYTEST_DISABLE_PLUGIN_AUTOLOAD", "1")


def _timings(path: Path, seconds: dict[str, tuple[float, bool]]) -> Path:
    lines = [
        {"test": test, "phase": "call", "slow": slow, "wall": cpu, "cpu": cpu, "load": 0.1}
        for test, (cpu, slow) in seconds.items()
    ]
    path.write_text("".join(json.dumps(line) + "\n" for line in lines), encoding="utf-8")
    return path


def test_a_fast_test_over_the_limit_fails_the_guard_and_a_slow_one_does_not(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = _timings(tmp_path / "t.jsonl", {"a.py::fast": (2.5, False), "a.py::slow": (9.0, True)})
    assert durations.main([str(path), "--limit", "2"]) == 1
    assert "over 2 s and not marked slow: a.py::fast (2.50 s cpu)" in capsys.readouterr().out
    path = _timings(tmp_path / "t.jsonl", {"a.py::fast": (1.5, False), "a.py::slow": (9.0, True)})
    assert durations.main([str(path), "--limit", "2"]) == 0


def test_a_recheck_keeps_a_heavy_test_and_clears_one_recorded_heavy_by_a_crowded_run(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
    bare_pytest: None,
) -> None:
    (tmp_path / "conftest.py").write_text(
        f"import sys\nsys.path.insert(0, {str(TESTS)!r})\n"
        "from helpers.timing import pytest_addoption, pytest_runtest_call  # noqa: F401\n",
        encoding="utf-8",
    )
    (tmp_path / "test_burn.py").write_text(
        "import time\n\n\ndef test_heavy():\n    end = time.process_time() + 0.03\n"
        "    while time.process_time() < end:\n        pass\n\n\n"
        "def test_light():\n    pass\n",
        encoding="utf-8",
    )
    monkeypatch.chdir(tmp_path)
    recorded = {"test_burn.py::test_heavy": (0.5, False), "test_burn.py::test_light": (3.0, False)}
    path = _timings(tmp_path / "t.jsonl", recorded)
    assert durations.main([str(path), "--limit", "0.015", "--recheck", "1"]) == 1
    out = capsys.readouterr().out
    assert "over 0.015 s and not marked slow: test_burn.py::test_heavy" in out
    assert "not marked slow: test_burn.py::test_light" not in out
    assert "rechecked test_burn.py::test_light: 3.00 s in the run, least 0.0" in out


def test_a_recheck_that_cannot_run_the_test_clears_nothing(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
    bare_pytest: None,
) -> None:
    """A rerun whose test errors (a fixture the rerun lacks, as xdist's ``worker_id`` without
    xdist) measures only its setup: it is no rerun, and the test stays over the limit."""
    (tmp_path / "conftest.py").write_text(
        f"import sys\nsys.path.insert(0, {str(TESTS)!r})\n"
        "from helpers.timing import (  # noqa: F401\n"
        "    pytest_addoption, pytest_runtest_call, pytest_runtest_setup, pytest_runtest_teardown\n"
        ")\n",
        encoding="utf-8",
    )
    (tmp_path / "test_broken.py").write_text(
        "def test_needs(a_fixture_only_xdist_gives):\n    pass\n", encoding="utf-8"
    )
    monkeypatch.chdir(tmp_path)
    path = _timings(tmp_path / "t.jsonl", {"test_broken.py::test_needs": (3.0, False)})
    assert durations.main([str(path), "--limit", "2", "--recheck", "1"]) == 1
    out = capsys.readouterr().out
    assert "rechecked test_broken.py::test_needs: 3.00 s in the run, least 3.00 s" in out


def test_each_workers_timeline_says_how_long_it_sat_idle_before_the_last(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """gw0 starts at 100.0 and its last phase ends at 110.0; gw1 ends at 104.0: gw1 sat idle
    6 s. Seconds are counted from the first start (the earliest end minus its wall); the
    lines may come in any order (the files of two runs appended, say)."""
    lines = [
        {"test": "a.py::one", "phase": "call", "slow": False, "wall": 8.0, "cpu": 7.0,
         "load": 0.1, "worker": "gw0", "end": 110.0},
        {"test": "a.py::two", "phase": "call", "slow": False, "wall": 1.0, "cpu": 0.5,
         "load": 0.1, "worker": "gw1", "end": 104.0},
        {"test": "<collection gw0>", "phase": "collect", "slow": False, "wall": 2.0, "cpu": 1.5,
         "load": 0.1, "worker": "gw0", "end": 102.0},
        {"test": "<collection gw1>", "phase": "collect", "slow": False, "wall": 2.5, "cpu": 1.5,
         "load": 0.1, "worker": "gw1", "end": 102.6},
    ]  # fmt: skip
    path = tmp_path / "t.jsonl"
    path.write_text("".join(json.dumps(line) + "\n" for line in lines), encoding="utf-8")
    assert durations.main([str(path), "--limit", "10"]) == 0
    out = capsys.readouterr().out
    assert "gw0: tests 7.0 s CPU, 8.0 s wall; done at 10.0 s, idle 0.0 s" in out
    assert "gw1: tests 0.5 s CPU, 1.0 s wall; done at 4.0 s, idle 6.0 s" in out
