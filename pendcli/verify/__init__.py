"""The verdicts: every rule that judges a printed number, formula or equation.

The verdict rule of a printed number (``verdict``), why a value disagrees (``causes``), a
published table joined with its recomputation (``claims``), the author's hand computations
(``explain``, the Bessel tables he read ``bessel_tables``), derived formulas against numerical
solutions (``formula_engine``, ``formula_plots``), dimensional analysis (``dimensions``), and
the ledger engine: each row judged and its status checked (``ledger_evaluation``; a paper seen
through the protocol ``ledger_paper``), the kinds of check (``check_kinds``), a printed form
against its reference (``printed_check``, ``printed_numeric``, ``printed_verdict``,
``derived``, ``float_verdict``, ``point_values``, ``series_proof``, ``derivation_store``) and
the ledger's rules over rows (``ledger_references``, ``ledger_formulas``, ``ledger_step``,
``ledger_blame``, ``ledger_companions``).

May import: ``pendcli.base``, ``pendcli.data`` and other ``verify`` modules; never a paper,
the registry, the run, the outputs or the CLI (``tests/test_package_rules.py``).
"""
