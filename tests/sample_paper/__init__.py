"""A minimal paper, for the tests only: proof that a paper is one folder and one registry line.

The « paper » is a made-up two-line note (``tables/papers/sample.txt``): the period of a
simple pendulum of small amplitude, T = 2π√(l/g) (its equation (1)), and its value for
l = 1 m, g = 9,81 m/s², printed 2,006 s. One claim, one ledger row, one figure, one CLI
command. ``tests/test_sample_paper.py`` registers :data:`PAPER` (alone) with
:func:`pendcli.papers.registry.registered` and runs every output on it; nothing outside this
folder knows it exists.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

from pendcli.core.claims import Recomputed
from pendcli.core.paper import CliApp, Paper

__all__ = ["PAPER"]


def _recompute() -> Mapping[str, Recomputed]:
    from sample_paper.model import period

    return {"sample.period": Recomputed(period(), method="2π√(l/g), l and g from the table")}


def _references() -> Mapping[str, Callable[[], Any]]:
    from sample_paper.references import REFERENCES

    return REFERENCES


def _figures(folder: Path) -> Sequence[Path]:
    from sample_paper.model import plot_period

    return [plot_period(folder / "sample-period.png")]


def _captions() -> Mapping[str, str]:
    return {"sample-period": "The small-amplitude period 2π√(l/g) against the length l."}


def _cli() -> Any:
    from sample_paper.cli import app

    return app


PAPER = Paper(
    key="sample",
    recompute=_recompute,
    references=_references,
    figures=_figures,
    captions=_captions,
    cli=CliApp(help="A sample paper (tests only): the period of a simple pendulum.", load=_cli),
)
