"""The engine's bounded memo (pendcli.base.recent.Recent) forgets as
functools.lru_cache does: the same keys computed anew, for a random sequence of uses, and
never more kept than its size."""

from __future__ import annotations

import functools
import random

import pytest

from pendcli.base.recent import Recent


@pytest.mark.parametrize("size", [1, 3, 17])
def test_the_memo_misses_exactly_where_lru_cache_misses(size: int) -> None:
    generator = random.Random(size)
    uses = [generator.randint(0, 3 * size) for _ in range(2000)]
    lru_misses: list[int] = []

    @functools.lru_cache(maxsize=size)
    def computed(key: int) -> int:
        lru_misses.append(key)
        return key * key

    memo, misses = Recent(size), []
    for key in uses:
        computed(key)
        value = memo.get(key)
        if value is None:
            misses.append(key)
            memo.put(key, key * key)
        else:
            assert value == key * key
        assert len(memo) <= size
    assert misses == lru_misses


def test_a_memo_of_nothing_is_refused() -> None:
    with pytest.raises(ValueError, match="keeps nothing"):
        Recent(0)
