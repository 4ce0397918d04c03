"""JSON: the whole document, deterministic, floats exact, NaN and infinities as null."""

from __future__ import annotations

import json
import math
import numbers
from collections.abc import Mapping, Sequence

from pendcli.render.columns import Section

__all__ = ["JsonRenderer", "plain", "to_json"]


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


def to_json(document: Mapping[str, object]) -> str:
    """Deterministic JSON: keys in insertion order, two-space indent, UTF-8 text kept."""
    return json.dumps(plain(dict(document)), indent=2, ensure_ascii=False, allow_nan=False) + "\n"


class JsonRenderer:
    """Prints the document whole; the sections are the terminal's view of it."""

    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        return to_json(document)
