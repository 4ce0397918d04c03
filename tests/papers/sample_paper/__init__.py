"""A minimal paper, for the tests only: proof that a paper is one folder and one registry line.

The « paper » is a made-up two-line note (``tables/papers/sample.txt``): the period of a
simple pendulum of small amplitude, T = 2π√(l/g) (its equation (1)), and its value for
l = 1 m, g = 9,81 m/s², printed 2,006 s. One claim, one ledger row, one figure, one CLI
command. ``tests/papers/test_sample_paper.py`` registers :data:`PAPER` (alone) with
:func:`pendcli.papers.registry.registered` and runs every output on it; nothing outside this
folder knows it exists.
"""

from __future__ import annotations

from pendcli.papers.paper import CliApp, Paper, hook

__all__ = ["PAPER"]

PAPER = Paper(
    key="sample",
    recompute=hook("sample_paper.model:recompute"),
    references=hook("sample_paper.references:REFERENCES"),
    figures=hook("sample_paper.model:figures"),
    captions=hook("sample_paper.model:CAPTIONS"),
    cli=CliApp(
        help="A sample paper (tests only): the period of a simple pendulum.",
        load=hook("sample_paper.cli:app"),
    ),
)
