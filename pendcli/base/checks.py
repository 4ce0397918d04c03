"""Input checks shared by the models: one message shape, naming the value and its valid range."""

from __future__ import annotations

import math
from numbers import Real

from pendcli.base.errors import PendcliError, out_of_range

__all__ = ["real_in_range"]


def real_in_range(name: str, value: object, lo: float, hi: float, unit: str = "") -> float:
    """``value`` as a float if it is a finite real in [lo, hi]; else a PendcliError naming both."""
    unit_text = f" {unit}" if unit else ""
    if isinstance(value, bool) or not isinstance(value, Real):
        raise PendcliError(
            f"{name} must be a real number in [{lo:g}, {hi:g}]{unit_text}, got {value!r}"
        )
    v = float(value)
    if not math.isfinite(v) or not lo <= v <= hi:
        raise out_of_range(name, repr(v), f"{lo:g} <= {name} <= {hi:g}{unit_text}")
    return v
