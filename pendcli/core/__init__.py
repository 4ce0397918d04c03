"""The core: what every paper shares, and nothing of any one paper or of the pendulum.

Printed numbers and their precision (``numbers``), the verdict rule (``verdict``) and its
words (``vocabulary``), the typed rows every output renders (``rows``), the tables and their
schema (``tables``, ``schema``), the formula engine (``formula_engine``), the ledger and its
engine (``ledger*``, ``check_kinds``, ``printed*``, ``point_values``, ``series_proof``), the
contract of a paper (``paper``), and the plumbing (``files``, ``cache``, ``workers``,
``console``, ``interrupts``). A core module imports only the standard library, numpy, scipy,
sympy, mpmath, matplotlib and other core modules (``schema`` also takes the registry's keys):
never a paper, the CLI or the orchestration above it (docs/ARCHITECTURE.md).
"""
