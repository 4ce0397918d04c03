"""`pendcli cache`: where the result cache lives, and emptying it."""

from __future__ import annotations

from pendcli.cli.common import QuietFlag
from pendcli.cli.help_format import command, group

app = group("The result cache: where it is, how big, and emptying it.", "cache")


@command(app, "cache info")
def info(quiet: QuietFlag = False) -> None:
    """Where the result cache is ($PENDCLI_CACHE, off, or the default), its entries and size
    (and, when its folder is not used, why)."""
    from pendcli.base.cache import ENV, entries
    from pendcli.cli.common import say
    from pendcli.run.reproduce import result_cache

    cache = result_cache()
    if cache.folder is None:
        print(f"off ({ENV}=off): every run computes")
        return
    found = entries(cache.folder)
    size = sum(size for _, size in found)
    print(f"{cache.folder}: {len(found)} entries, {size / 1e6:.1f} MB")
    refusal = cache.refusal()
    if refusal is not None:
        say(refusal)


@command(app, "cache clear")
def clear(quiet: QuietFlag = False) -> None:
    """Remove every entry of the result cache (the next run computes everything); nothing
    else in its folder is touched."""
    from pendcli.cli.common import say
    from pendcli.run.reproduce import result_cache

    cache = result_cache()
    say(f"removed {cache.clear()} entries from {cache.folder}" if cache.folder else "cache off")
