"""Developer tools run from a checkout, never installed: ``make bench`` (``python -m
tools.bench``, over :mod:`tools.bench_startup`, :mod:`tools.bench_scaling` and
:mod:`tools.bench_summary`) and ``make regen`` / ``make check`` (``python -m tools.docs``, the
generated sections of the README and docs/). Run from the repository's root, which puts this
folder on the import path.

May import anything of ``pendcli``; nothing in ``pendcli`` imports this folder.
"""
