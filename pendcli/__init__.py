"""pendcli: regenerate the numerical claims of three historical papers on the pendulum.

The library is a set of pure functions (one module per paper: :mod:`pendcli.charbonnier`,
:mod:`pendcli.lecornu`, :mod:`pendcli.tisserand`) plus small shared modules: number
parsing (:mod:`pendcli.numbers`), verdicts (:mod:`pendcli.verdict`), the published tables
(:mod:`pendcli.tables`), the claim engine (:mod:`pendcli.claims`) and output formats
(:mod:`pendcli.render`). :mod:`pendcli.cli` is a thin adapter over them.
"""

__version__ = "0.1.0"
