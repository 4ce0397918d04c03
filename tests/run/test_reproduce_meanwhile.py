"""What a run does in its own process while a forked worker computes (``meanwhile``)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from pendcli.run.reproduce import reproduce_all


def _noting(log: Path):  # type: ignore[no-untyped-def]
    def note() -> None:
        with log.open("a", encoding="utf-8") as fh:  # a worker's call reaches the file too
            fh.write(f"{os.getpid()}\n")

    return note


def test_meanwhile_is_done_once_and_in_this_process_with_a_worker(tmp_path: Path) -> None:
    log = tmp_path / "calls"
    keys = ("tisserand", "charbonnier")
    result = reproduce_all(keys, formulas=False, jobs=2, meanwhile=_noting(log))
    assert log.read_text(encoding="utf-8").split() == [str(os.getpid())]
    assert set(result.claims) == set(keys) and all(result.claims.values())


@pytest.mark.parametrize("jobs", [1, 2])
def test_meanwhile_is_not_left_for_a_later_run(tmp_path: Path, jobs: int) -> None:
    """Done in a run with a worker only (with none, nothing runs beside it), and never by a
    later run of the same process."""
    log = tmp_path / "calls"
    reproduce_all(("tisserand", "charbonnier"), formulas=False, jobs=jobs, meanwhile=_noting(log))
    reproduce_all(("tisserand", "charbonnier"), formulas=False, jobs=2)
    calls = log.read_text(encoding="utf-8").split() if log.exists() else []
    assert calls == ([str(os.getpid())] if jobs == 2 else [])
