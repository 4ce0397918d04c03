"""The plumbing that knows nothing of pendulums, papers or tables.

The one exception type and its one-line messages (``errors``), the input checks of the models
(``checks``), atomic writes, locked folders and manifests (``files``), the streams a command
writes to (``console``), Ctrl-C and the signals (``interrupts``), the forked workers of a run
(``workers``), the result cache keyed by the code, the tables and the versions (``cache``), the
versions a run was made with (``versions``), a bounded memo (``recent``) and the figures'
files (``plotting``).

May import: the standard library, numpy, scipy, sympy, mpmath, matplotlib and other ``base``
modules; never another pendcli package (``tests/test_package_rules.py``).
"""
