"""The figures of ``out/report``: what to draw, drawn in forked workers, and their captions.

Each figure set is one call of a paper's ``figures`` / ``formula_figures`` hook or of the
work-precision plot; :class:`Drawing` shares the calls among ``jobs`` processes
(:mod:`pendcli.base.workers`), with the report's other work that needs no figure (its pages
rendered without their figures, its introduction), and gives the files per paper.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from pendcli.run.reproduce import ReproduceResult
    from pendcli.run.tradeoff_engine import Point


def figure_caption(path: Path) -> str:
    """The caption of a report figure: its paper's ``captions``, or the tradeoff's ``CAPTION``."""
    from pendcli.papers.registry import all_papers

    for paper in all_papers():
        captions = paper.captions() if paper.captions is not None else {}
        if path.stem in captions:
            return str(captions[path.stem])
    if path.stem == "work-precision":
        from pendcli.run.tradeoff import CAPTION

        return str(CAPTION)
    return path.stem.replace("_", " ")


# (paper or "tradeoff", "claims"/"formulas"/"tradeoff", the drawing function, its arguments):
# each figure is drawn by one call, in any process. The other work shared with the drawing has
# a kind of its own ("page", "introduction"), its function's value handed back as it is.
Task = tuple[str, str, Callable[..., Any], tuple[Any, ...]]
FIGURE_KINDS = ("claims", "formulas", "tradeoff")


def figure_tasks(result: ReproduceResult, folder: Path, tradeoff: list[Point] | None) -> list[Task]:
    """Every figure to draw, the costliest first (so two processes finish together);
    ``tradeoff``: the work-precision points, where the report has that section."""
    from pendcli.papers.registry import paper

    tasks: list[Task] = []
    # the residual grids, the one of most panels first (their cost goes with their panels)
    for key in sorted(result.formulas, key=lambda k: -len(result.formulas[k])):
        formula_figures = paper(key).formula_figures
        if key in result.papers and formula_figures is not None:
            args = (folder / "figures" / key / "formulas", result.formulas[key])
            tasks.append((key, "formulas", formula_figures, args))
    if tradeoff is not None:
        from pendcli.run.tradeoff import plot_tradeoff

        path = folder / "tradeoff" / "work-precision.png"
        tasks.append(("tradeoff", "tradeoff", plot_tradeoff, (tradeoff, path)))
    for key in result.papers:
        claim_figures = paper(key).figures
        if claim_figures is not None:
            drawn_from = (folder / "figures" / key, result.claims.get(key))
            tasks.append((key, "claims", claim_figures, drawn_from))
    return tasks


def _draw(function: Callable[..., Any], args: tuple[Any, ...]) -> list[Path]:
    """Draw one task (in a worker process or this one); the files it wrote."""
    out = function(*args)
    return [Path(p) for p in out] if isinstance(out, list | tuple) else [Path(out)]


def shared_order(figures: list[Task], pages: list[Task], last: list[Task]) -> list[Task]:
    """The order the processes take the tasks in, with no timings (measured: a residual grid
    0.5-1.6 s of CPU, the work-precision diagram 0.95, a paper's page 0.1-0.65, a paper's own
    figures 0.15-0.5): the grids and the diagram, then the pages (``pages``, the longest text
    first), then the claims' figures, then ``last`` (the smallest)."""
    claims = [t for t in figures if t[1] == "claims"]
    first = [t for t in figures if t[1] != "claims"]
    return [*first, *pages, *claims, *last]


def _draw_task(task: Task) -> Any:
    _, kind, function, args = task
    return _draw(function, args) if kind in FIGURE_KINDS else function(*args)


def _task_name(task: Task) -> str:
    """``tisserand claims figures``, ``tradeoff figures``, ``the page of lecornu``: what a dead
    worker was doing."""
    key, kind = task[:2]
    if kind == "page":
        return f"the page of {key or 'report'}"
    if kind not in FIGURE_KINDS:
        return f"the report's {kind}"
    return " ".join(dict.fromkeys(task[:2])) + " figures"


class Drawing:
    """Draws the tasks in ``jobs`` processes: this one and forked workers (base/workers.py)."""

    def __init__(self, tasks: list[Task], jobs: int | None) -> None:
        from pendcli.base.workers import ForkedWorkers, job_count

        self.tasks = tasks
        self.workers = ForkedWorkers(job_count(jobs, len(tasks)) - 1)

    def __enter__(self) -> Drawing:
        if self.workers.processes:
            _pyplot()  # once, here: the forked workers inherit it
        self.workers.__enter__()
        return self

    def results(
        self, first: Callable[[], object] | None = None
    ) -> tuple[dict[str, list[Path]], dict[tuple[str, str], Any]]:
        """Figures per paper (and "tradeoff"), claim figures before formula figures; and the
        value of each other task by its (key, kind). ``first`` is done here before this
        process takes a task: while the workers take theirs (with none, before the tasks)."""
        if first is not None and not self.workers.processes:
            first()
        drawn = self.workers.share(self.tasks, _draw_task, name=_task_name, first=first)
        by_key: dict[str, list[Path]] = {}
        others: dict[tuple[str, str], Any] = {}
        for (key, kind, _, _), value in zip(self.tasks, drawn, strict=True):
            if kind not in FIGURE_KINDS:
                others[key, kind] = value
                continue
            claims_first = kind == "claims"
            by_key.setdefault(key, [])
            by_key[key] = [*value, *by_key[key]] if claims_first else [*by_key[key], *value]
        return by_key, others

    def __exit__(self, *exc: Any) -> None:
        self.workers.__exit__(*exc)


def load_drawing_libraries() -> None:
    """matplotlib (Agg): loaded once before the workers that draw are forked, rather than
    once in each (`reproduce --out` loads it during the run, while a worker computes)."""
    _pyplot()


def _pyplot() -> None:
    """Load matplotlib (Agg) before forking the workers, rather than once in each."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot
