"""The papers pendcli reproduces: one package per paper, each declaring one ``PAPER``.

A paper package (``pendcli.papers.<key>``) holds the paper's computations and declares its
:class:`~pendcli.core.paper.Paper` in its ``__init__``; :mod:`pendcli.papers.registry` lists
them. :func:`formula_checks` and :func:`sharing_formula_rows` are the registry's, here for
the callers that name them from this package.
"""

from __future__ import annotations

from pendcli.papers.registry import formula_checks, sharing_formula_rows

__all__ = ["formula_checks", "sharing_formula_rows"]
