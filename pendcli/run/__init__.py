"""The orchestration: every paper at once.

``reproduce`` runs the claims, formula checks, ledgers and stability rows of the chosen
papers (forked workers, the result cache); ``regression`` is `pendcli check` over ``drift``
(the committed tables' columns and tolerances); ``tradeoff`` is the catalogue of every
paper's work-precision families, over ``tradeoff_engine`` (measuring, the tables, the choice
of a method); ``stability`` the helpers of the stability rows.

May import: ``pendcli.base``, ``pendcli.data``, ``pendcli.verify``, ``pendcli.numerics``,
``pendcli.output``, the registry (``pendcli.papers.registry``, through it every paper) and the
output modules. Never the CLI or the public API (``pendcli.api``). The papers may import the two
generic engines, ``tradeoff_engine`` and ``stability``, which import only ``pendcli.base``,
``pendcli.data``, ``pendcli.verify``: no module of a paper imports a module that imports the
registry.
"""
