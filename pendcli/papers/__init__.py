"""The papers pendcli reproduces: one package per paper, each declaring one ``PAPER``.

A paper package (``pendcli.papers.<key>``) holds the paper's computations and declares its
:class:`~pendcli.papers.paper.Paper` in its ``__init__``; :mod:`pendcli.papers.registry` lists
them, and is where the layers above look a paper up by its key.
"""
