"""Developer tools run from a checkout, never installed: ``make bench`` (``python -m
tools.bench``, with :mod:`tools.bench_summary` for the suite and install timings) and ``make
regen`` / ``make check`` (``python -m tools.docs``, the generated sections of the README and
docs/). Run from the repository's root, which puts this folder on the import path.

May import anything of ``pendcli``; nothing in ``pendcli`` imports this folder.
"""
