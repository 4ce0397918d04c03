"""Folders pendcli owns, and only those, replaced whole under a lock.

A folder pendcli writes as a whole (``out/``, the regenerated tables) is replaced only when it
is pendcli's: its :data:`MANIFEST` lists every file in it, or a fixed set of names does
(:func:`check_owned`). :func:`replace_owned_folder` holds the folder's lock
(:func:`pendcli.base.files.locked`) from that check to the swap
(:func:`pendcli.base.files.replace_directory`), and writes through a symlinked target
(:func:`write_through`).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from pendcli.base.errors import PendcliError
from pendcli.base.files import (
    describe_os_error,
    lock_file,
    locked,
    remove_stale,
    replace_directory,
)

__all__ = [
    "MANIFEST",
    "check_owned",
    "folder_entries",
    "manifest_text",
    "probe_lock",
    "read_manifest",
    "replace_owned_folder",
    "write_through",
]


# Written into every folder pendcli makes as a whole (``reproduce --out``): the files it
# wrote. A non-empty folder without it, or holding a file it does not list, is not pendcli's
# and is never replaced.
MANIFEST = "pendcli-manifest.txt"


_MANIFEST_HEAD = (
    "# Files pendcli wrote in this folder, one a line. pendcli replaces this folder as a whole\n"
    "# only while every file in it is listed here; anything else makes it refuse.\n"
)


def folder_entries(folder: Path) -> list[str]:
    """Every file, link and subfolder under ``folder``, as POSIX paths relative to it."""
    entries = []
    for root, dirs, files in os.walk(folder):
        base = Path(root).relative_to(folder)
        entries += [(base / n).as_posix() for n in (*dirs, *files)]
    return sorted(entries)


def read_manifest(folder: Path) -> set[str] | None:
    """The files ``folder``'s manifest lists (None without a readable manifest)."""
    path = folder / MANIFEST
    if path.is_symlink() or not path.is_file():
        return None
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None
    if not text.startswith(_MANIFEST_HEAD):
        return None
    return {line for line in text.splitlines() if line and not line.startswith("#")}


def manifest_text(names: list[str]) -> str:
    """The manifest listing ``names`` (paths relative to its folder)."""
    return _MANIFEST_HEAD + "".join(f"{name}\n" for name in names if name != MANIFEST)


def _manifest_of(folder: Path) -> str:
    return manifest_text([e for e in folder_entries(folder) if not (folder / e).is_dir()])


def check_owned(target: Path, what: str, known: Callable[[str], bool] | None = None) -> None:
    """Refuse (one line) to replace a non-empty folder with a file pendcli did not write.

    pendcli's files are those the folder's :data:`MANIFEST` lists, or, with ``known``, those
    whose relative path ``known`` accepts (a committed set of fixed names).
    """
    if not target.is_dir():
        return
    present = folder_entries(target)
    if not present:
        return
    suggestion = "move them away or give a new folder"
    if known is None:
        listed = read_manifest(target)
        if listed is None:
            raise PendcliError(
                f"{what} {str(target)!r} is a folder pendcli did not make (no {MANIFEST}) "
                "and would be replaced as a whole; give a new or empty folder"
            )
        ours = {MANIFEST, *listed}
        ours |= {p.as_posix() for name in listed for p in Path(name).parents if p != Path(".")}
    else:
        ours = {name for name in present if known(name)}
    foreign = [name for name in present if name not in ours]
    if foreign:
        raise PendcliError(
            f"{what} {str(target)!r} holds {len(foreign)} file(s) pendcli did not write "
            f"({foreign[0]!r}) that replacing it would delete; {suggestion}"
        )


def write_through(target: Path, what: str) -> Path:
    """The folder a symlinked ``target`` names (written in place of the link, which stays),
    or ``target`` itself; a link to nothing or to a file is refused."""
    if not target.is_symlink():
        return target
    real = target.resolve()
    if not real.is_dir():
        problem = "a file" if real.exists() else "nothing"
        raise PendcliError(f"{what} {str(target)!r} is a link to {problem} ({real}); give a folder")
    return real


def replace_owned_folder(
    target: Path | str,
    fill: Callable[[Path], object],
    what: str,
    known: Callable[[str], bool] | None = None,
    wait: bool = False,
) -> Path:
    """:func:`replace_directory` of a folder pendcli owns, under an exclusive lock.

    The lock (:func:`lock_file`) is held from the ownership check to the swap: a second
    writer waits (``wait``) or is refused in one line. Only a folder pendcli made is replaced
    (:func:`check_owned`); without ``known`` the new folder gets a :data:`MANIFEST` of the
    files ``fill`` wrote. A symlinked target is written through (:func:`write_through`).
    Returns the folder written (the link's target for a link).
    """
    real = write_through(Path(target), what)
    busy = None
    if not wait:
        busy = (
            f"{what} {str(target)!r} is being written by another pendcli run; wait for it "
            "to finish or give another folder"
        )
    try:
        real.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise PendcliError(describe_os_error(exc, real)) from None

    def fill_all(tmp: Path) -> None:
        fill(tmp)
        if known is None:
            (tmp / MANIFEST).write_text(_manifest_of(tmp), encoding="utf-8")

    with locked(lock_file(real), busy=busy):
        check_owned(real, what, known)
        remove_stale(real.parent, real.name)
        replace_directory(real, fill_all)
    return real


def probe_lock(target: Path, what: str) -> None:
    """Refuse now (one line) if another pendcli run holds ``target``'s lock."""
    path = lock_file(write_through(target, what))
    if path.is_file():
        busy = (
            f"{what} {str(target)!r} is being written by another pendcli run; wait for it "
            "to finish or give another folder"
        )
        with locked(path, busy=busy):
            pass
