"""The fast suite's split (tests/conftest.py): every long family keeps a fast case
and leaves the rest to `make test-slow`, every slow pattern still names a collected test, and
CI runs the slow suite. What a test sees is its own session's collection (under xdist each
worker collects the whole suite); a family whose file was not collected is not judged."""

from __future__ import annotations

import re
from fnmatch import fnmatch
from pathlib import Path

import pytest
from conftest import REPRESENTATIVES, SLOW_CASES, SLOW_FAMILIES
from helpers.suite_split import COLLECTED, FAMILY_SPLIT

ROOT = Path(__file__).resolve().parents[2]


def _collected_files(config: pytest.Config) -> set[str]:
    return {nodeid.split("::")[0] for nodeid in config.stash[COLLECTED]}


def test_every_long_family_keeps_a_fast_case_and_leaves_the_rest_to_the_slow_run(
    request: pytest.FixtureRequest,
) -> None:
    files = _collected_files(request.config)
    split = request.config.stash[FAMILY_SPLIT]
    for pattern, stride in REPRESENTATIVES.items():
        if pattern.split("::")[0] not in files:
            continue
        fast, total = split[pattern]
        assert total > 0, f"{pattern}: names no collected test"
        assert fast >= 1, f"{pattern}: no case left in the fast suite"
        assert fast < total, f"{pattern}: every case is fast (every {stride}th was to be)"


def test_every_slow_pattern_names_a_collected_test(request: pytest.FixtureRequest) -> None:
    collected = request.config.stash[COLLECTED]
    files = _collected_files(request.config)
    # a pattern of any file (*::…) is judged when the whole suite was collected
    whole = {p.relative_to(ROOT).as_posix() for p in (ROOT / "tests").rglob("test_*.py")} <= files
    stale = [
        pattern
        for pattern in SLOW_FAMILIES
        if pattern.split("::")[0] in files or (whole and "*" in pattern.split("::")[0])
        if not any(fnmatch(n.partition("[")[0], pattern) for n in collected)
    ]
    stale += [
        f"{test} [{part}]"
        for test, part in SLOW_CASES
        if test.split("::")[0] in files
        if not any(n.partition("[")[0] == test and part in n.partition("[")[2] for n in collected)
    ]
    assert stale == []


def _target(make: str, name: str) -> str:
    return make.split(f"\n{name}:")[1].split("\n\n")[0]


def test_ci_runs_the_slow_suite_and_make_test_leaves_it_out() -> None:
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    make = (ROOT / "Makefile").read_text(encoding="utf-8")
    assert '-m "not slow and not browser"' in _target(make, "test")
    assert '-m "slow and not browser"' in _target(make, "test-slow")
    # CI runs every test but the browser's (then that one): in one run, or fast and slow apart
    assert '-m "not browser"' in _target(make, "test-all")
    assert "make test-all" in ci or {"make test", "make test-slow"} <= set(ci)
    assert "make test-durations" in ci
    # and the README's own test command, as a user runs it
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    command = readme.split("```sh\n", 1)[1].split("```", 1)[0].splitlines()[1].split("#")[0]
    assert command.strip() == "make test" and "make test" in ci


def test_make_test_browser_collects_every_file_with_a_browser_test() -> None:
    """`make test-browser` collects only the files it names: a browser test elsewhere would
    never run."""
    make = (ROOT / "Makefile").read_text(encoding="utf-8")
    named = set(make.split("\nBROWSER_TESTS :=", 1)[1].split("\n", 1)[0].split())
    marked = {
        p.relative_to(ROOT).as_posix()
        for p in (ROOT / "tests").rglob("test_*.py")
        if re.search(r"pytest\.mark\.browser\b", p.read_text(encoding="utf-8"))
    }
    assert marked and marked <= named, marked - named
