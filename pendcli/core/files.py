"""Files written so that a crash never leaves half of one.

Every file pendcli commits or hands to a user goes through here:

- :func:`atomic_write` writes a temporary file beside the target, flushes it to disk and
  renames it over the target, so a reader (or a crash) sees the old file or the new one.
- :func:`replace_directory` builds a whole folder beside the target and swaps it in with one
  atomic exchange (Linux ``renameat2(RENAME_EXCHANGE)``), so a set of files (the regenerated
  tables, ``out/``) is old or new as a whole, and files the new set lacks are gone.  Where the
  exchange is not available it falls back to two renames, leaving at worst the new folder
  under a temporary name beside a missing target, never a mix.
- :func:`locked` serialises writers and readers of a folder with ``flock``.

An OS failure (full disk, read-only folder, missing parent) becomes a :class:`PendcliError`
naming the path and the cause, never a traceback.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import errno
import os
import shutil
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

from pendcli.core.errors import PendcliError

__all__ = ["atomic_write", "describe_os_error", "locked", "remove_stale", "replace_directory"]

_RENAME_EXCHANGE = 2  # linux/fs.h
_AT_FDCWD = -100


# Errors that can only come from writing; others (EACCES, ENOENT...) may be a read as well.
_WRITE_ERRNOS = frozenset({errno.ENOSPC, errno.EFBIG, errno.EROFS, errno.EDQUOT, errno.EPIPE})


def describe_os_error(exc: OSError, path: Path | str | None = None, action: str = "") -> str:
    """One line: the path and the cause (``cannot write out/x.csv: No space left on device``).

    ``action`` defaults to "write" when ``path`` is given (the caller was writing it) or the
    error can only come from a write, else to "access".
    """
    where = path if path is not None else (exc.filename or "")
    cause = exc.strerror or str(exc) or type(exc).__name__
    if not action:
        action = "write" if path is not None or exc.errno in _WRITE_ERRNOS else "access"
    return f"cannot {action} {where}: {cause}" if where != "" else f"I/O error: {cause}"


def _fsync_dir(folder: Path) -> None:
    # Make the rename itself durable; some file systems refuse O_RDONLY on a folder: ignore.
    with contextlib.suppress(OSError):
        fd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def atomic_write(path: Path | str, data: str | bytes, encoding: str = "utf-8") -> Path:
    """Write ``data`` to ``path`` atomically (temporary file, fsync, rename)."""
    target = Path(path)
    payload = data.encode(encoding) if isinstance(data, str) else data
    tmp: str | None = None
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
        with os.fdopen(fd, "wb") as fh:
            fh.write(payload)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, 0o644)
        os.replace(tmp, target)
        tmp = None
    except OSError as exc:
        raise PendcliError(describe_os_error(exc, target)) from None
    finally:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
    _fsync_dir(target.parent)
    return target


def _exchange(a: Path, b: Path) -> bool:
    """Atomically swap two paths (both must exist); False where the OS cannot."""
    libc_name = ctypes.util.find_library("c")
    if libc_name is None:
        return False
    libc = ctypes.CDLL(libc_name, use_errno=True)
    renameat2 = getattr(libc, "renameat2", None)
    if renameat2 is None:
        return False
    rc = renameat2(_AT_FDCWD, os.fsencode(a), _AT_FDCWD, os.fsencode(b), _RENAME_EXCHANGE)
    if rc == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.EOPNOTSUPP):
        return False
    raise OSError(err, os.strerror(err), str(b))


def _sync_tree(folder: Path) -> None:
    for root, _dirs, files in os.walk(folder):
        for name in files:
            fd = os.open(Path(root) / name, os.O_RDONLY)
            try:
                os.fsync(fd)
            finally:
                os.close(fd)
        _fsync_dir(Path(root))


def replace_directory(target: Path | str, fill: Callable[[Path], object]) -> Path:
    """Build a fresh folder with ``fill(tmp)`` beside ``target`` and swap it in as a whole.

    Files of the old folder that ``fill`` does not write are gone afterwards; if ``fill``
    raises, ``target`` is untouched.
    """
    target = Path(target)
    parent = target.parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
        new = Path(tempfile.mkdtemp(prefix=f".{target.name}.new-", dir=parent))
    except OSError as exc:
        raise PendcliError(describe_os_error(exc, target)) from None
    try:
        fill(new)
        _sync_tree(new)
        os.chmod(new, 0o755)
        if target.exists() and _exchange(new, target):
            old = new  # after the exchange the temporary name holds the old folder
        elif target.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=parent))
            os.rmdir(old)
            os.rename(target, old)
            os.rename(new, target)
        else:
            os.rename(new, target)
            old = None
        _fsync_dir(parent)
    except OSError as exc:
        shutil.rmtree(new, ignore_errors=True)
        where = _as_target(str(exc.filename), new, target) if exc.filename else target
        raise PendcliError(describe_os_error(exc, where)) from None
    except PendcliError as exc:
        shutil.rmtree(new, ignore_errors=True)
        raise PendcliError(_as_target(str(exc), new, target)) from None
    except BaseException:
        shutil.rmtree(new, ignore_errors=True)
        raise
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)
    return target


def _as_target(text: str, new: Path, target: Path) -> str:
    """A message about a file of the temporary folder, naming it where the user will look."""
    return text.replace(str(new), str(target))


def remove_stale(parent: Path | str, name: str) -> None:
    """Remove leftovers of an interrupted :func:`replace_directory` of ``parent/name``."""
    for leftover in Path(parent).glob(f".{name}.*-*"):
        if leftover.is_dir():
            shutil.rmtree(leftover, ignore_errors=True)


@contextlib.contextmanager
def locked(lock_file: Path | str, shared: bool = False) -> Iterator[None]:
    """Hold an advisory lock on ``lock_file`` (shared for readers, exclusive for writers)."""
    import fcntl

    path = Path(lock_file)
    try:
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    except OSError as exc:
        # A read-only tree can still be read: without a lock file there is no writer either.
        if shared:
            yield
            return
        raise PendcliError(describe_os_error(exc, path)) from None
    try:
        fcntl.flock(fd, fcntl.LOCK_SH if shared else fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)
