"""The order two processes take a run's steps in: the largest ledger's parts first (the part
with its formula checks before the other), then the smaller ledgers', the stability table,
the claims last. A large part taken last leaves the other process idle while it runs."""

from __future__ import annotations

import tomllib
from collections.abc import Callable, Sequence
from typing import Any, ClassVar

import pytest

from pendcli.base import workers
from pendcli.data.tables import tables_dir

PAPERS = ("tisserand", "lecornu", "charbonnier")


def _ledger_sizes() -> dict[str, int]:
    """Rows of each ledger, counted in its TOML here (not by the code under test)."""
    folder = tables_dir() / "equations"
    return {
        key: len(tomllib.loads((folder / f"{key}.toml").read_text("utf-8"))["equation"])
        for key in PAPERS
    }


class _Recording:
    """ForkedWorkers that runs every step here and records the order it was handed."""

    taken: ClassVar[list[Any]] = []

    def __init__(self, processes: int) -> None:
        self.processes = processes

    def __enter__(self) -> _Recording:
        return self

    def __exit__(self, *exc: object) -> None:
        return None

    def share(
        self,
        items: Sequence[Any],
        run: Callable[[Any], Any],
        done: Any = None,
        name: Any = None,
        first: Any = None,
    ) -> list[Any]:
        _Recording.taken[:] = list(items)
        return [run(item) for item in items]


def _taken(
    monkeypatch: pytest.MonkeyPatch, jobs: int, formulas: bool = True
) -> list[tuple[str, str]]:
    from pendcli.papers import registry
    from pendcli.run import reproduce

    monkeypatch.setattr(workers, "ForkedWorkers", _Recording)
    monkeypatch.setattr(reproduce, "claim_rows", lambda key: [])
    monkeypatch.setattr(reproduce, "formula_checks", lambda key: [])
    monkeypatch.setattr(registry, "equation_rows", lambda keys, part, measure=True: [])
    monkeypatch.setattr(registry, "stability_rows", lambda papers: [])
    reproduce.reproduce_all(PAPERS, formulas=formulas, equations=True, stability=True, jobs=jobs)
    return list(_Recording.taken)


def test_two_processes_take_the_largest_ledger_first(monkeypatch: pytest.MonkeyPatch) -> None:
    sizes = _ledger_sizes()
    by_size = sorted(PAPERS, key=lambda key: -sizes[key])
    assert len(set(sizes.values())) == len(PAPERS)  # an order to check
    taken = _taken(monkeypatch, jobs=2)
    ledger = [(key, what) for key, what in taken if "equations" in what]
    assert [key for key, _ in ledger] == [key for key in by_size for _ in range(2)]
    assert all(what.startswith("formulas+") for what in [w for _, w in ledger][::2])
    assert [what for _, what in taken[len(ledger) :]] == ["stability", *["claims"] * 3]
    assert [key for key, _ in taken[-3:]] == by_size


def test_one_process_keeps_the_order_listed(monkeypatch: pytest.MonkeyPatch) -> None:
    """With one process the claims come first (a table that does not match the code is the
    run's error at once): the order is the listed one, the papers as asked."""
    taken = _taken(monkeypatch, jobs=1)
    assert taken[:3] == [(key, "claims") for key in PAPERS]


def test_formula_checks_of_their_own_follow_their_ledger_s_parts(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The ledger without the formula rows (`pendcli equations`): each paper's formula checks,
    which its measured rows read, right after its ledger's parts, the largest ledger's paper
    first (lecornu's, taken last, left the other process idle)."""
    from pendcli.run.reproduce import LEDGER_PARTS

    sizes = _ledger_sizes()
    by_size = sorted(PAPERS, key=lambda key: -sizes[key])
    parts = [f"equations {i}/{LEDGER_PARTS}" for i in range(LEDGER_PARTS)]
    taken = _taken(monkeypatch, jobs=2, formulas=False)
    ledgers = [(k, w) for k in by_size for w in (*parts, "formulas")]
    assert taken == [*ledgers, ("all", "stability"), *((k, "claims") for k in by_size)]
