"""A bounded memo: the most recently used keys of a computation shared within a command."""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Hashable
from typing import Any

__all__ = ["Recent"]


class Recent:
    """Key -> value for the ``size`` most recently used keys (a ``get`` or a ``put`` is a
    use); the least recently used is forgotten first, as functools.lru_cache does: the
    engine's compiled residuals and quadratures are shared by the rows of one command, and a
    process that judges many ledgers (the test suite) must not keep them all for its life."""

    def __init__(self, size: int) -> None:
        if size < 1:
            raise ValueError(f"a memo of {size} entries keeps nothing")
        self.size = size
        self._entries: OrderedDict[Hashable, Any] = OrderedDict()

    def __len__(self) -> int:
        return len(self._entries)

    def __contains__(self, key: Hashable) -> bool:
        return key in self._entries

    def get(self, key: Hashable, default: Any = None) -> Any:
        if key not in self._entries:
            return default
        self._entries.move_to_end(key)
        return self._entries[key]

    def put(self, key: Hashable, value: Any) -> None:
        self._entries[key] = value
        self._entries.move_to_end(key)
        while len(self._entries) > self.size:
            self._entries.popitem(last=False)
