"""The tables as typed data: what the papers print, read and validated, judged by nothing.

Printed numbers and their precision (``numbers``), the words of verdicts, statuses and causes
(``vocabulary``), the typed rows every output renders (``rows``), the published tables
(``tables``), the texts' ``$$`` blocks and line spans (``text_blocks``), a text as a reader
reads it (``reader_text``), the ledger's notation as a closed grammar (``formula_grammar``,
``printed``) and a stored expression read back (``stored_expr``), the equation ledgers loaded
and validated (``ledger``, their types ``ledger_rows``, ``ledger_labels``,
``ledger_readings``, ``ledger_conditions``, ``ledger_coverage``) and the reading records
(``reading``, ``reading_citations``).

May import: ``pendcli.base`` and other ``data`` modules; never a paper, the run, the outputs
or the CLI. One exception, named in ``tests/test_package_rules.py``: the ledger's loader
refuses a row by the engine's rules (``verify``: the kinds, blame, companions, formulas, step).
"""
