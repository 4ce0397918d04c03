"""The two § II builders that references_late imports under this module's name (its
reference_vertical_to_elongation and reference_mean_pendulum build on them); their home is
:mod:`pendcli.papers.lecornu.references_slow`. Nothing else is here: the references of lines
1-698 are in the section modules (see ``PAPER.references`` in the package)."""

from __future__ import annotations

from pendcli.papers.lecornu.references_slow import reference_quarter_time, reference_root_epsilon

__all__ = ["reference_quarter_time", "reference_root_epsilon"]
