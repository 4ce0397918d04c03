"""JSON: the whole document, deterministic, floats exact, NaN and infinities as null."""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence

from pendcli.output.columns import Section
from pendcli.output.values import plain

__all__ = ["JsonRenderer", "plain", "to_json"]


def to_json(document: Mapping[str, object]) -> str:
    """Deterministic JSON: keys in insertion order, two-space indent, UTF-8 text kept."""
    return json.dumps(plain(dict(document)), indent=2, ensure_ascii=False, allow_nan=False) + "\n"


class JsonRenderer:
    """Prints the document whole; the sections are the terminal's view of it."""

    def __call__(self, sections: Sequence[Section], document: Mapping[str, object]) -> str:
        return to_json(document)
