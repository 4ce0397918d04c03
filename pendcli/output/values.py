"""Plain values: what a row's cell holds once numpy scalars, tuples and non-finite floats
are made JSON's (shared by the columns and the JSON renderer; imports no other renderer)."""

from __future__ import annotations

import math
import numbers

__all__ = ["plain"]


def plain(value: object) -> object:
    """``value`` with tuples as lists, non-finite floats as None (JSON has no NaN) and numpy
    scalars and arrays as the Python numbers and lists they hold (a numpy float's repr is
    ``np.float64(...)``; numpy itself is not imported)."""
    if type(value).__module__ == "numpy" and hasattr(value, "tolist"):
        value = value.tolist()
    if isinstance(value, bool | str) or value is None:
        return value
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        value = float(value)
        return value if math.isfinite(value) else None
    if isinstance(value, tuple | list):
        return [plain(v) for v in value]
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    return value
