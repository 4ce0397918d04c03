"""When the report's own writing is done beside the drawing (output/report_figures.Drawing)."""

from __future__ import annotations

import os

import pytest

from pendcli.output import report_figures


def test_the_workers_draw_while_this_process_writes_the_tables() -> None:
    """``first`` (the report writes claims.json and its tables there) is done once, here,
    once every worker holds its tasks: they draw while it writes, no worker left waiting."""
    tasks = [("", "page", str, (i,)) for i in range(4)]
    seen = []
    with report_figures.Drawing(tasks, jobs=2) as drawing:

        def first() -> None:
            seen.append((os.getpid(), [worker.busy for worker in drawing.workers.workers]))

        _, done = drawing.results(first=first)
    assert seen == [(os.getpid(), [True])]
    assert done == {("", "page"): "3"}  # each task's value by (key, kind): the last one kept


@pytest.mark.parametrize("with_first", [True, False])
def test_with_no_worker_first_is_done_before_the_tasks(with_first: bool) -> None:
    order: list[str] = []
    tasks = [("", "page", order.append, (f"task {i}",)) for i in range(2)]
    with report_figures.Drawing(tasks, jobs=1) as drawing:
        drawing.results(first=(lambda: order.append("first")) if with_first else None)
    assert order == ["first", "task 0", "task 1"] if with_first else ["task 0", "task 1"]
