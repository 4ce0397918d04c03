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
- :mod:`pendcli.base.owned_folders` does the swap under that lock and only for a folder
  pendcli made (its manifest, or a fixed set of names), writing through a symlinked target.

Temporary names carry the writer's pid (``.name.new-<pid>-<random>``,
``.name.<pid>-<random>.tmp``): leftovers of a killed run are removed by the next one only
when that pid is no longer alive, and nothing else beside a target is ever touched. Modes
follow the umask (a replaced file or folder keeps its own).

An OS failure (full disk, read-only folder, missing parent, the limit of open files reached)
becomes a :class:`PendcliError` naming the path and the cause, never a traceback.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import errno
import glob
import hashlib
import os
import re
import shutil
import stat
import tempfile
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path

from pendcli.base.errors import PendcliError

__all__ = [
    "atomic_write",
    "content_digest",
    "describe_os_error",
    "file_digest",
    "lock_file",
    "locked",
    "pid_alive",
    "remove_stale",
    "replace_directory",
    "write_set",
]

# The signals a user or a supervisor sends to stop a run: held back while a lock is taken or
# released and during a set's renames.
_STOP_SIGNALS = ("SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT")
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
    if exc.errno in (errno.EMFILE, errno.ENFILE):  # what was opened is not at fault
        return _too_many_open(exc.errno, where)
    cause = exc.strerror or str(exc) or type(exc).__name__
    if not action:
        action = "write" if path is not None or exc.errno in _WRITE_ERRNOS else "access"
    return f"cannot {action} {where}: {cause}" if where != "" else f"I/O error: {cause}"


def _too_many_open(code: int, where: Path | str) -> str:
    """EMFILE (this process's limit, ``ulimit -n``) or ENFILE (the system's table) reached."""
    opening = f" opening {where}" if where != "" else ""
    if code == errno.ENFILE:
        return f"too many open files on this system (ENFILE){opening}"
    import resource

    soft = resource.getrlimit(resource.RLIMIT_NOFILE)[0]
    limit = "" if soft == resource.RLIM_INFINITY else f", is {soft}"
    return f"too many open files (EMFILE: the limit, ulimit -n{limit}){opening}; raise the limit"


def _fsync_dir(folder: Path) -> None:
    # Make the rename itself durable; some file systems refuse O_RDONLY on a folder: ignore.
    with contextlib.suppress(OSError):
        fd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def atomic_write(path: Path | str, data: str | bytes, encoding: str = "utf-8") -> Path:
    """Write ``data`` to ``path`` atomically (temporary file, fsync, rename).

    The new file keeps the mode of the file it replaces, else gets the umask's (0666 masked);
    leftovers of a killed earlier write of the same file (dead writer) are removed first.
    """
    target = Path(path)
    tmp = _write_temporary(target, data.encode(encoding) if isinstance(data, str) else data)
    try:
        os.replace(tmp, target)
    except OSError as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise PendcliError(describe_os_error(exc, target)) from None
    _fsync_dir(target.parent)
    return target


def _umask() -> int:
    # os.umask can only be read by setting it: set it back at once (pendcli has no threads
    # that create files at this moment).
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _mode_for(target: Path, full: int) -> int:
    """The mode a replacement of ``target`` gets: the old file's, else ``full`` under the umask."""
    try:
        return stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        return full & ~_umask()


# A temporary name is the target's name plus at most this many bytes (".", ".new-", the pid,
# "-", 8 random characters, ".tmp"); a name too long for that is shortened and hashed, so a
# legal 255-byte target name still has a legal temporary name.
_TEMP_ROOM = 40
_NAME_MAX = 255


def _tag(name: str) -> str:
    """``name``, or a shortened, hashed stand-in when ``.name`` plus a suffix would not fit."""
    raw = os.fsencode(name)
    if len(raw) + _TEMP_ROOM <= _NAME_MAX:
        return name
    digest = hashlib.sha1(raw).hexdigest()[:12]
    keep = raw[: _NAME_MAX - _TEMP_ROOM - len(digest) - 1]
    return f"{os.fsdecode(keep)}~{digest}"  # a cut character stays its bytes (surrogateescape)


def _temp_prefix(name: str) -> str:
    return f".{_tag(name)}.{os.getpid()}-"


# mkstemp/mkdtemp's 8 random characters
_RANDOM = "[a-z0-9_]{8}"


def pid_alive(pid: int) -> bool:
    """Whether process ``pid`` is alive (another user's counts): a writer's leftovers are
    removed only once it is dead."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True  # someone else's live process
    except (OverflowError, OSError):
        return False
    return True


def _dead_leftovers(folder: Path, pattern: str, shape: str) -> Iterator[Path]:
    """Entries of ``folder`` matching the glob ``pattern`` and the regular expression
    ``shape`` (whose group ``pid`` names the writer) whose writer is no longer alive."""
    regex = re.compile(shape)
    for candidate in folder.glob(pattern):
        match = regex.fullmatch(candidate.name)
        if match is not None and not pid_alive(int(match.group("pid"))):
            yield candidate


def _remove_dead_temporaries(folder: Path, name: str) -> None:
    """Remove ``.name.<pid>-<random>.tmp`` files of :func:`atomic_write` whose writer died."""
    tag = _tag(name)
    shape = rf"\.{re.escape(tag)}\.(?P<pid>\d+)-{_RANDOM}\.tmp"
    for leftover in _dead_leftovers(folder, f".{glob.escape(tag)}.*.tmp", shape):
        if leftover.is_file() and not leftover.is_symlink():
            with contextlib.suppress(OSError):
                leftover.unlink()


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
        mode = _mode_for(target, 0o777)
    except OSError as exc:
        raise PendcliError(describe_os_error(exc, target)) from None
    new: Path | None = None
    spare = _Spare()  # so the clean-up can still open a folder once the limit is reached
    try:
        with _signals_held():  # named before a stop can land, so the clean-up below finds it
            new = Path(
                tempfile.mkdtemp(prefix=f".{_tag(target.name)}.new-{os.getpid()}-", dir=parent)
            )
        old = _fill_and_swap(target, new, fill, mode)
    except OSError as exc:
        _discard(new, spare)
        raise PendcliError(_fill_error(exc, new, target)) from None
    except PendcliError as exc:
        _discard(new, spare)
        raise PendcliError(_as_target(str(exc), new, target) if new else str(exc)) from None
    except BaseException:
        _discard(new, spare)
        raise
    _discard(old, spare)  # the swap is done: only the old folder is left to remove
    return target


class _Spare:
    """One file descriptor held in reserve and given back before a clean-up: a run that
    reached its limit of open files (EMFILE) can then still remove its temporary folder."""

    def __init__(self) -> None:
        try:
            self.fd = os.open(os.devnull, os.O_RDONLY)
        except OSError:
            self.fd = -1

    def release(self) -> None:
        self.fd = _closed(self.fd)


def _fill_error(exc: OSError, new: Path | None, target: Path) -> str:
    """The line for an OS error while filling ``new``: a file of the new folder is named where
    the user will look (``target``); any other file (a font read, a module imported) as it is,
    never as one pendcli was writing."""
    name = os.fsdecode(exc.filename) if exc.filename else ""
    if new is not None and name and Path(name).is_relative_to(new):
        return describe_os_error(exc, _as_target(name, new, target))
    return describe_os_error(exc) if name else describe_os_error(exc, target)


def _fill_and_swap(
    target: Path, new: Path, fill: Callable[[Path], object], mode: int
) -> Path | None:
    """Fill ``new`` and swap it in for ``target``; the old folder's temporary path (None
    when there was none)."""
    parent = target.parent
    fill(new)
    _sync_tree(new)
    os.chmod(new, mode)
    if target.exists() and _exchange(new, target):
        old: Path | None = new  # after the exchange the temporary name holds the old folder
    elif target.exists():
        prefix = f".{_tag(target.name)}.old-{os.getpid()}-"
        old = Path(tempfile.mkdtemp(prefix=prefix, dir=parent))
        os.rmdir(old)
        os.rename(target, old)
        os.rename(new, target)
    else:
        os.rename(new, target)
        old = None
    _fsync_dir(parent)
    return old


def _discard(folder: Path | None, spare: _Spare | None = None) -> None:
    """Remove a temporary folder, with the stop signals held (a second one must not cut the
    clean-up short; it is raised after). ``spare`` is released first; where shutil.rmtree
    cannot finish (it holds two descriptors a level), :func:`_remove_tree` needs one."""
    if spare is not None:
        spare.release()
    if folder is not None:
        with _signals_held():
            shutil.rmtree(folder, ignore_errors=True)
            if os.path.lexists(folder):
                with contextlib.suppress(OSError):
                    _remove_tree(folder)


def _remove_tree(folder: Path) -> None:
    """Remove ``folder`` and all under it holding one descriptor at a time (os.listdir closes
    its own before returning); links are removed, never followed."""
    for name in os.listdir(folder):
        path = folder / name
        if stat.S_ISDIR(os.lstat(path).st_mode):
            _remove_tree(path)
        else:
            os.unlink(path)
    os.rmdir(folder)


def _as_target(text: str, new: Path, target: Path) -> str:
    """A message about a file of the temporary folder, naming it where the user will look."""
    return text.replace(str(new), str(target))


def remove_stale(parent: Path | str, name: str) -> None:
    """Remove leftovers of an interrupted :func:`replace_directory` of ``parent/name``.

    Only pendcli's own temporary folders of that target (``.name.new-<pid>-<random>``,
    ``.name.old-<pid>-<random>``, the name glob-escaped) whose writer is no longer alive are
    removed; nothing else beside the target is touched.
    """
    tag = _tag(name)
    shape = rf"\.{re.escape(tag)}\.(?:new|old)-(?P<pid>\d+)-{_RANDOM}"
    for leftover in _dead_leftovers(Path(parent), f".{glob.escape(tag)}.*-*", shape):
        if leftover.is_dir() and not leftover.is_symlink():
            shutil.rmtree(leftover, ignore_errors=True)


def lock_file(target: Path | str) -> Path:
    """The lock file of a target folder: beside it, ``.name.lock`` (kept between runs)."""
    target = Path(target)
    return target.parent / f".{_tag(target.name)}.lock"


@contextlib.contextmanager
def locked(lock_file: Path | str, shared: bool = False, busy: str | None = None) -> Iterator[None]:
    """Hold an advisory lock on ``lock_file`` (shared for readers, exclusive for writers).

    With ``busy`` (a message), a lock another process holds is refused with that message
    instead of waited for. An exclusive holder removes the lock file when done; a waiter that
    then holds a removed file's lock tries again on the current one. The file is created and
    locked with the stopping signals held back, so an interrupt never leaves a lock file that
    no one holds.
    """
    path = Path(lock_file)
    fd, held = -1, False
    try:
        while not held:
            with _signals_held():  # an interrupt lands after, inside this try
                fd = _open_lock_file(path, shared)
                got = fd < 0 or _lock(fd, shared, path, wait=False)
                held = got is True
            if fd < 0:  # a read-only tree can still be read: no lock file, no writer either
                break
            if got is None:
                if busy:
                    raise PendcliError(busy)
                held = _lock(fd, shared, path, wait=True) is True  # the holder removes it
            if not held:
                fd = _closed(fd)
        yield
    finally:
        _release(path, fd, held and not shared)


def _release(path: Path, fd: int, remove: bool) -> None:
    """Remove (a writer's) lock file and close it, with the stop signals held. One that lands
    in the few steps before they are held (a second one) is raised after the release."""
    landed: BaseException | None = None
    for _ in range(3):
        released = False
        try:
            with _signals_held():
                if remove:
                    with contextlib.suppress(OSError):
                        os.unlink(path)
                _closed(fd)
                released = True
        except BaseException as exc:
            landed = exc
        if released:
            break
    if landed is not None:
        raise landed


def _open_lock_file(path: Path, shared: bool) -> int:
    """The lock file's descriptor; -1 for a reader where it cannot be created (read-only)."""
    try:
        return os.open(path, os.O_RDWR | os.O_CREAT, 0o666)
    except OSError as exc:
        if shared:
            return -1
        raise PendcliError(describe_os_error(exc, path)) from None


def _closed(fd: int) -> int:
    if fd >= 0:
        with contextlib.suppress(OSError):
            os.close(fd)
    return -1


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """Hold back SIGINT, SIGTERM, SIGHUP, SIGQUIT (delivered on leaving): blocked in this
    thread, and pendcli's own handler defers them whichever thread receives them."""
    import signal

    from pendcli.base.interrupts import stops_deferred

    stops = {getattr(signal, name) for name in _STOP_SIGNALS if hasattr(signal, name)}
    held = signal.pthread_sigmask(signal.SIG_BLOCK, stops)
    try:
        with stops_deferred():
            yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)


def _lock(fd: int, shared: bool, path: Path, wait: bool) -> bool | None:
    """Lock ``fd``: True when held; None when another process holds it (``wait`` False);
    False when ``path`` no longer names the file locked (its holder removed it)."""
    import fcntl

    kind = fcntl.LOCK_SH if shared else fcntl.LOCK_EX
    try:
        fcntl.flock(fd, kind | (0 if wait else fcntl.LOCK_NB))
        current = os.stat(path)
    except BlockingIOError:
        return None
    except FileNotFoundError:
        return False
    mine = os.fstat(fd)
    return (mine.st_dev, mine.st_ino) == (current.st_dev, current.st_ino)


def write_set(
    changes: dict[Path, str | bytes | None], unchanged: Mapping[Path, str | None] | None = None
) -> None:
    """Write a set of files in different places (``None``: remove that file) as nearly at
    once as POSIX allows.

    There is no atomic rename of several files. So every new file is first written in full to
    a temporary beside its target and synced; only then does one short loop rename them over
    their targets (and remove the dropped ones), all with the stopping signals blocked, so
    Ctrl-C or a TERM arriving mid-way takes effect after the whole set. Only a SIGKILL or a power
    cut within that loop (a few renames) can leave it part new. A failure before the loop
    leaves every target untouched.

    ``unchanged``: path -> :func:`content_digest` of what the caller read from it (None: it
    was absent). Just before the renames each must still hold that, else nothing is written
    and the error names the file: an edit made while the set was computed is never lost.
    """

    temporaries: dict[Path, str] = {}
    # The stops are held over the temporaries' writing too: a signal between mkstemp and the
    # bookkeeping of its name left a temporary behind (1 run in 3 of the attack test).
    with _signals_held():
        try:
            for path, data in changes.items():
                if data is not None:
                    temporaries[path] = _write_temporary(path, data)
            _refuse_changed(unchanged or {})
            for path, data in changes.items():
                if data is None:
                    with contextlib.suppress(FileNotFoundError):
                        os.unlink(path)
                else:
                    os.replace(temporaries[path], path)
                    del temporaries[path]
            for folder in {path.parent for path in changes}:
                _fsync_dir(folder)
        except OSError as exc:
            raise PendcliError(describe_os_error(exc)) from None
        finally:
            for tmp in temporaries.values():
                with contextlib.suppress(OSError):
                    os.unlink(tmp)


def content_digest(data: str | bytes) -> str:
    """SHA-256 of ``data`` (text as UTF-8): what :func:`write_set` compares with the disk."""
    return hashlib.sha256(data.encode("utf-8") if isinstance(data, str) else data).hexdigest()


def file_digest(path: Path | str) -> str | None:
    """:func:`content_digest` of the file's bytes now; None where there is no such file."""
    try:
        with open(path, "rb") as fh:
            return hashlib.file_digest(fh, "sha256").hexdigest()
    except FileNotFoundError:
        return None
    except OSError as exc:
        raise PendcliError(describe_os_error(exc, path, "read")) from None


def _refuse_changed(unchanged: Mapping[Path, str | None]) -> None:
    for path, digest in unchanged.items():
        now = file_digest(path)
        if now != digest:
            what = "changed" if now and digest else "was removed" if digest else "was created"
            raise PendcliError(
                f"{str(path)!r} {what} since this run read it (an edit made meanwhile?); "
                "nothing was written, so that edit is kept; run again to include it"
            )


def _write_temporary(target: Path, data: str | bytes) -> str:
    """``data`` in a synced temporary file beside ``target``, with the mode ``target`` will
    have; its path."""
    payload = data.encode("utf-8") if isinstance(data, str) else data
    try:
        _remove_dead_temporaries(target.parent, target.name)
        mode = _mode_for(target, 0o666)
        fd, tmp = tempfile.mkstemp(
            prefix=_temp_prefix(target.name), suffix=".tmp", dir=target.parent
        )
    except OSError as exc:
        raise PendcliError(describe_os_error(exc, target)) from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(payload)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, mode)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise PendcliError(describe_os_error(exc, target)) from None
        raise
    return tmp
