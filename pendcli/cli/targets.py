"""Every output target checked before any work: a command that would fail writing its result
fails at once, in one line, having computed and printed nothing.

A folder given to be written (``--out``, ``--write-tables``) is an existing folder pendcli may
write, or a new one whose parent folder exists: pendcli creates that one folder, never a chain
of missing parents (``--out /nonexistent/deep/dir`` is refused, as ``mkdir`` without ``-p``
would refuse it). ``--out`` is replaced whole when the report is written, so it cannot be a
mount point (the swap that replaces it fails there, "Device or resource busy").
"""

from __future__ import annotations

import os
from pathlib import Path

from pendcli.base.errors import PendcliError

__all__ = ["check_folder_target", "check_replaced_folder"]


def _writable(folder: Path) -> bool:
    return os.access(folder, os.W_OK | os.X_OK)


def check_folder_target(path: Path | str | None, option: str) -> Path | None:
    """``path`` when it can receive files: an existing writable folder, or a new folder whose
    parent is an existing writable folder; else a PendcliError naming the option."""
    if path is None:
        return None
    path = Path(path)
    shown = str(path)
    if path.exists():
        if not path.is_dir():
            raise PendcliError(f"{option} must be a folder, got the file {shown!r}")
        if not _writable(path):
            raise PendcliError(f"{option} must be a folder you can write, got {shown!r}")
        return path
    parent = path.parent
    if not parent.exists():
        raise PendcliError(
            f"{option} must be a new folder in an existing one, got {shown!r}: {str(parent)!r} "
            f"does not exist; pendcli creates only the last folder (mkdir -p {str(parent)!r} first)"
        )
    if not parent.is_dir():
        raise PendcliError(
            f"{option} must be a folder, got {shown!r} inside the file {str(parent)!r}"
        )
    if not _writable(parent):
        raise PendcliError(
            f"{option} must be a folder you can create, got {shown!r}: "
            f"{str(parent)!r} is not writable"
        )
    return path


def check_replaced_folder(path: Path | str | None, option: str) -> Path | None:
    """:func:`check_folder_target` for a folder replaced whole: not a mount point either."""
    checked = check_folder_target(path, option)
    if checked is not None and checked.exists() and os.path.ismount(checked):
        raise PendcliError(
            f"{option} must be a folder pendcli can replace whole, got the mount point "
            f"{str(checked)!r}; give a folder inside it"
        )
    return checked
