"""A cache of computed results, keyed by the content of everything they depend on.

An entry's key is a SHA-256 over the bytes (and relative names) of every file of the
pendcli package and of the other source folders given (a registered paper's own package),
the bytes of every file under the tables folder in use (``$PENDCLI_TABLES`` included), the
version of Python, the machine, the libraries pendcli computes with and every distribution
they require here, transitively (the names ``numpy-2.3.4.dist-info`` of site-packages,
followed through their ``Requires-Dist`` whose environment marker holds: a test tool
installed beside them, or a library only another system needs, is not in it), and the
parameters of the computation (its kind, the paper). Any byte changed in any of them is
another key: a miss, never a stale result. What the key cannot see (an environment variable
that picks another BLAS kernel, a libm of the same version) is why ``pendcli check`` never
reads the cache. The key's parts are computed in :mod:`pendcli.base.cache_key` (regular files
only, each of a bounded size, no link out of its folder).

Where: ``$PENDCLI_CACHE`` (a folder; ``off`` disables it), else ``$XDG_CACHE_HOME/pendcli``,
else ``~/.cache/pendcli``. The folder is used only when it is owned by this user and
writable by no one else (a link to such a folder included), and is pendcli's: it holds
pendcli's :data:`MARKER` (written when pendcli creates the folder or finds it empty), or
nothing but pendcli's own names. Otherwise the run goes uncached and :attr:`ResultCache.problem`
says why. An entry is ``pendcli-<key>.json``: a header line with the format, the key and the
SHA-256 of the rest, then the JSON of the call and its value, written to a temporary name and
renamed (concurrent writers of one key each rename a whole file over it). Pruning and ``clear``
remove only such names, and pendcli's temporaries whose writer is dead; nothing else.

An entry is read only as a regular file of this user, opened without following a link or
waiting (a FIFO), at most :data:`MAX_ENTRY_BYTES`; one whose header, digest, call or value
does not check out (the callers validate the value's every field) is a miss: computed again
and rewritten.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
import secrets
import stat
from collections.abc import Callable, Iterable, Iterator, Mapping
from functools import cached_property
from pathlib import Path
from typing import Any

from pendcli.base.cache_key import READ_FLAGS, folders_digest, installed_signature
from pendcli.base.files import pid_alive

__all__ = [
    "ENV",
    "FORMAT",
    "KEEP",
    "KEEP_BYTES",
    "MARKER",
    "MAX_ENTRY_BYTES",
    "ResultCache",
    "cache_folder",
    "cached_json",
    "entries",
    "rows_from_json",
    "rows_to_json",
]

ENV = "PENDCLI_CACHE"
FORMAT = 3  # the entry layout and its rows' fields; a new one makes every old entry a miss
# kept, the most recently used; older entries are removed when one is written (a report of
# every paper is about 8 MB)
KEEP = 200
KEEP_BYTES = 256_000_000
# an entry larger is neither written nor read (the largest, a report of every paper, is
# about 8 MB)
MAX_ENTRY_BYTES = 64 * 2**20
_CHUNK = 2**20
# the cache directory tag (https://bford.info/cachedir/): backup tools skip the folder
MARKER = "CACHEDIR.TAG"
_MARKER_TEXT = (
    b"Signature: 8a477f597d28d172789f06886806bc55\n"
    b"# This file is a cache directory tag created by pendcli (its result cache).\n"
    b"# For information about cache directory tags see: https://bford.info/cachedir/\n"
)
# the only names pendcli writes in the folder: entries, their temporaries (the writer's pid,
# 8 random characters), and, read only to be removed, the entries of the first layout
_ENTRY = re.compile(r"pendcli-[0-9a-f]{64}\.json")
_TEMPORARY = re.compile(r"\.(?:pendcli-)?[0-9a-f]{64}\.json\.(?P<pid>[0-9]+)-[a-z0-9_]{8}\.tmp")
_FORMER = re.compile(r"[0-9a-f]{64}\.json")
_HEADER = "pendcli result cache {format} key {key} sha256 "
_PACKAGE = Path(__file__).resolve().parent.parent


def cache_folder(environ: Mapping[str, str] | None = None) -> Path | None:
    """Where entries live (None: the cache is off, ``PENDCLI_CACHE=off``)."""
    env = os.environ if environ is None else environ
    chosen = env.get(ENV, "").strip()
    if chosen.lower() == "off":
        return None
    if chosen:
        return Path(chosen).expanduser()
    xdg = env.get("XDG_CACHE_HOME", "").strip()
    base = Path(xdg) if xdg and Path(xdg).is_absolute() else Path.home() / ".cache"
    return base / "pendcli"


def _ours(name: str) -> bool:
    return any(p.fullmatch(name) for p in (_ENTRY, _TEMPORARY, _FORMER))


def _listing(fd: int) -> list[tuple[str, float, int]]:
    """(name, time used, size) of each entry of the open folder ``fd`` (regular files only)."""
    found = []
    with contextlib.suppress(OSError), os.scandir(fd) as scan:
        for entry in scan:
            if _ENTRY.fullmatch(entry.name):
                with contextlib.suppress(OSError):
                    info = entry.stat(follow_symlinks=False)
                    if stat.S_ISREG(info.st_mode):
                        found.append((entry.name, info.st_mtime, info.st_size))
    return sorted(found, key=lambda f: -f[1])


def entries(folder: Path) -> list[tuple[Path, int]]:
    """The entries in ``folder`` with their sizes, the most recently used first."""
    try:
        fd = os.open(folder, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
    except OSError:
        return []
    try:
        return [(folder / name, size) for name, _, size in _listing(fd)]
    finally:
        os.close(fd)


def _refusal(fd: int, folder: Path) -> str | None:
    """Why the open folder ``fd`` is not used (its owner, its mode), or None."""
    info = os.fstat(fd)
    where = str(folder)
    if info.st_uid != os.geteuid():
        return (
            f"result cache off: {where} is owned by uid {info.st_uid}, not by you "
            f"(uid {os.geteuid()}); set {ENV} to a folder of your own"
        )
    if info.st_mode & (stat.S_IWGRP | stat.S_IWOTH):
        return (
            f"result cache off: {where} is writable by others (mode "
            f"{stat.S_IMODE(info.st_mode):04o}); chmod go-w it or set {ENV} to a folder of your own"
        )
    return None


def _read_regular(fd: int, name: str, limit: int, touch: bool = False) -> bytes | None:
    """The bytes of ``name`` in the open folder ``fd``, or None: not a regular file of this
    user (a link, a FIFO, a device: never followed nor waited on), larger than ``limit``, or
    unreadable. ``touch``: marked used (its time: the pruning keeps it longest)."""
    try:
        file = os.open(name, READ_FLAGS, dir_fd=fd)
    except OSError:
        return None
    try:
        info = os.fstat(file)
        if not stat.S_ISREG(info.st_mode) or info.st_uid != os.geteuid():
            return None
        if info.st_size > limit:
            return None
        data = _read_at_most(file, info.st_size)
        if touch:
            with contextlib.suppress(OSError):
                os.utime(file)
        return data
    except OSError:
        return None
    finally:
        os.close(file)


def _read_at_most(fd: int, size: int) -> bytes:
    """``size`` bytes of ``fd`` (fewer if it ends sooner), read in chunks."""
    parts, left = [], size
    while left > 0:
        chunk = os.read(fd, min(left, _CHUNK))
        if not chunk:
            break
        parts.append(chunk)
        left -= len(chunk)
    return b"".join(parts)


def _remove(fd: int, names: Iterable[str]) -> int:
    """Unlink each of ``names`` in the open folder ``fd``; how many were removed."""
    removed = 0
    for name in names:
        with contextlib.suppress(OSError):
            os.unlink(name, dir_fd=fd)
            removed += 1
    return removed


def _leftovers(fd: int) -> list[str]:
    """pendcli's temporaries in the open folder whose writer is dead, and entries of the
    first layout (never read)."""
    found = []
    for name in os.listdir(fd):
        temporary = _TEMPORARY.fullmatch(name)
        if _FORMER.fullmatch(name) or (temporary and not pid_alive(int(temporary["pid"]))):
            found.append(name)
    return found


def _make(folder: Path) -> None:
    """Create ``folder`` (its parents as the umask says, itself private to this user)."""
    folder.parent.mkdir(parents=True, exist_ok=True)
    with contextlib.suppress(FileExistsError):
        os.mkdir(folder, 0o700)


def _create(fd: int, name: str, data: bytes, mode: int) -> None:
    """Write a new file ``name`` (never an existing one, never through a link) in ``fd``."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC
    with open(os.open(name, flags, mode, dir_fd=fd), "wb") as file:
        file.write(data)


def _write_entry(fd: int, name: str, data: bytes) -> None:
    """``data`` into the open folder ``fd`` as ``name``: written to a temporary name (the
    writer's pid and 8 random characters), then renamed over it (readers see old or new)."""
    temporary = f".{name}.{os.getpid()}-{secrets.token_hex(4)}.tmp"
    _create(fd, temporary, data, 0o600)
    try:
        os.replace(temporary, name, src_dir_fd=fd, dst_dir_fd=fd)
    except OSError:
        _remove(fd, [temporary])
        raise


class ResultCache:
    """The entries of one run: ``get`` a stored value or None, ``put`` a computed one.

    ``folder`` None: the cache is off (every ``get`` misses, nothing is written).
    ``tables``: the tables folder the computation reads; ``sources``: source folders beyond
    the pendcli package (a paper registered from elsewhere).
    """

    def __init__(self, folder: Path | None, tables: Path, sources: Iterable[Path] = ()) -> None:
        self.folder = folder
        self.tables = tables
        self.sources = tuple(dict.fromkeys(Path(s).resolve() for s in sources))
        self.problem: str | None = None  # why the cache is off or not written, once
        self._claimed: tuple[int, int] | None = None  # (device, inode) found pendcli's

    @property
    def enabled(self) -> bool:
        return self.folder is not None

    @cached_property
    def base(self) -> str:
        """The part of every key that does not depend on the call: code, data, versions."""
        roots = [("pendcli", _PACKAGE)]
        roots += [(f"source{i}", s) for i, s in enumerate(self.sources) if s != _PACKAGE]
        roots.append(("tables", self.tables))
        versions = installed_signature()
        return hashlib.sha256(f"{FORMAT}\0{versions}\0{folders_digest(roots)}".encode()).hexdigest()

    def key(self, kind: str, params: Mapping[str, Any]) -> str:
        call = json.dumps({"kind": kind, "params": params}, sort_keys=True)
        return hashlib.sha256(f"{self.base}\0{call}".encode()).hexdigest()

    def entry_path(self, kind: str, params: Mapping[str, Any]) -> Path:
        assert self.folder is not None
        return self.folder / f"pendcli-{self.key(kind, params)}.json"

    def keep_out_of(self, out: Path | str, what: str = "--out") -> None:
        """Turn the cache off (one status line) when its folder is ``out`` or inside it: the
        report replaces that folder whole."""
        if self.folder is None:
            return
        mine, theirs = self.folder.resolve(), Path(out).resolve()
        if mine == theirs or theirs in mine.parents:
            self.problem = (
                f"result cache off: {ENV} {str(self.folder)!r} is inside {what} {str(out)!r}, "
                f"which the report replaces whole; set {ENV} to another folder"
            )
            self.folder = None

    def get(self, kind: str, params: Mapping[str, Any]) -> Any | None:
        """The stored value, or None (off, refused, absent, not a regular file, too large,
        damaged, or not this key's)."""
        if self.folder is None:
            return None
        name = self.entry_path(kind, params).name  # the key first: a bad tables folder stops here
        with self._opened(create=False) as fd:
            data = None if fd is None else _read_regular(fd, name, MAX_ENTRY_BYTES, touch=True)
        return None if data is None else self._value(data, kind, params)

    def _value(self, data: bytes, kind: str, params: Mapping[str, Any]) -> Any | None:
        """The value an entry's bytes hold, when its header names this format and key and its
        digest is its body's, and the body is this call's; else None."""
        header, newline, body = data.partition(b"\n")
        expected = _HEADER.format(format=FORMAT, key=self.key(kind, params)).encode()
        if not newline or header != expected + hashlib.sha256(body).hexdigest().encode():
            return None
        try:
            entry = json.loads(body)
        except (ValueError, RecursionError):
            return None
        call = {"kind": kind, "params": json.loads(json.dumps(params))}
        if not isinstance(entry, dict) or set(entry) != {*call, "value"}:
            return None
        return entry["value"] if {k: entry[k] for k in call} == call else None

    def put(self, kind: str, params: Mapping[str, Any], value: Any) -> None:
        """Store ``value`` (JSON-serialisable); a failure to write leaves it unstored."""
        if self.folder is None or self.problem is not None:
            return
        from pendcli.base.files import describe_os_error

        try:
            call = {"kind": kind, "params": params, "value": value}
            body = json.dumps(call, allow_nan=True).encode()
        except (TypeError, ValueError) as exc:  # not serialisable: a programming error
            self.problem = f"result cache: {kind} not stored ({exc})"
            return
        if len(body) > MAX_ENTRY_BYTES:
            return  # never read back
        path = self.entry_path(kind, params)
        header = _HEADER.format(format=FORMAT, key=self.key(kind, params))
        data = f"{header}{hashlib.sha256(body).hexdigest()}\n".encode() + body
        with self._opened(create=True) as fd:
            if fd is None:
                return
            try:
                _write_entry(fd, path.name, data)
            except OSError as exc:
                self.problem = f"result cache not written ({describe_os_error(exc, path)})"
                return
            self._prune(fd)

    @contextlib.contextmanager
    def _opened(self, create: bool) -> Iterator[int | None]:
        """The folder, open and checked (:meth:`_check`), closed after; None: off, absent
        (and not ``create``), or refused (:attr:`problem` says why)."""
        fd = None if self.folder is None or self.problem is not None else self._open(create)
        try:
            yield fd
        finally:
            if fd is not None:
                os.close(fd)

    def _open(self, create: bool) -> int | None:
        from pendcli.base.files import describe_os_error

        assert self.folder is not None
        try:
            if create:
                _make(self.folder)
            fd = os.open(self.folder, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
        except OSError as exc:
            if not create and isinstance(exc, FileNotFoundError):
                return None  # nothing stored yet
            self.problem = f"result cache off ({describe_os_error(exc, action='use')})"
            return None
        try:
            self.problem = _refusal(fd, self.folder) or self._claim(fd)
        except OSError as exc:
            self.problem = f"result cache off ({describe_os_error(exc, self.folder, 'use')})"
        if self.problem is not None:
            os.close(fd)
            return None
        return fd

    def _claim(self, fd: int) -> str | None:
        """None when the open folder is pendcli's: it holds pendcli's :data:`MARKER`, or only
        names pendcli writes (then the marker is written and former entries removed); else
        why it is not used."""
        info = os.fstat(fd)
        if self._claimed == (info.st_dev, info.st_ino):
            return None
        if _read_regular(fd, MARKER, len(_MARKER_TEXT)) != _MARKER_TEXT:
            names = os.listdir(fd)
            foreign = sorted(n for n in names if not _ours(n))
            if foreign:
                return (
                    f"result cache off: {self.folder} holds {foreign[0]!r}, not pendcli's "
                    f"(no {MARKER}); set {ENV} to an empty or new folder"
                )
            with contextlib.suppress(FileExistsError):
                _create(fd, MARKER, _MARKER_TEXT, 0o644)
            _remove(fd, _leftovers(fd))
        self._claimed = (info.st_dev, info.st_ino)
        return None

    def _prune(self, fd: int) -> None:
        """Remove all but the most recently used entries (at most :data:`KEEP` of them and
        :data:`KEEP_BYTES` in all), and pendcli's temporaries whose writer is dead."""
        kept = total = 0
        stale = []
        for name, _, size in _listing(fd):
            kept, total = kept + 1, total + size
            if kept > KEEP or total > KEEP_BYTES:
                stale.append(name)
        _remove(fd, [*stale, *_leftovers(fd)])

    def clear(self) -> int:
        """Remove every entry and pendcli's temporaries whose writer is dead (nothing else);
        how many entries were removed. A refused folder is one line (PendcliError)."""
        from pendcli.base.errors import PendcliError

        with self._opened(create=False) as fd:
            if fd is None:
                if self.problem is not None:
                    raise PendcliError(self.problem)
                return 0
            removed = _remove(fd, [n for n in os.listdir(fd) if _ENTRY.fullmatch(n)])
            _remove(fd, _leftovers(fd))
        return removed

    def refusal(self) -> str | None:
        """Why the folder is not used (None: it is, or it does not exist yet)."""
        with self._opened(create=False):
            return self.problem


def cached_json(
    cache: ResultCache | None,
    kind: str,
    params: Mapping[str, Any],
    compute: Callable[[], Any],
    valid: Callable[[Any], bool],
) -> Any:
    """The stored JSON value of (``kind``, ``params``) when ``valid`` accepts it, else
    ``compute()`` (stored)."""
    if cache is None:
        return compute()
    found = cache.get(kind, params)
    if found is None or not valid(found):
        found = compute()
        cache.put(kind, params, found)
    return found


def rows_to_json(rows: Iterable[Any]) -> list[dict[str, Any]]:
    """Dataclass rows as JSON values: each field by name, an enum as its value, a tuple as a
    list. A field of any other type (a numpy scalar) raises TypeError: such rows are not
    cached, since their outputs could differ from the plain value's."""
    from dataclasses import fields

    return [{f.name: _plain(getattr(row, f.name)) for f in fields(row)} for row in rows]


def _plain(value: Any) -> Any:
    from enum import Enum

    if value is None or type(value) in (str, int, float, bool):
        return value
    if isinstance(value, Enum):
        return _plain(value.value)
    if type(value) in (tuple, list):
        return [_plain(v) for v in value]
    raise TypeError(f"{type(value).__name__} is not a plain JSON value")


def rows_from_json(cls: type, data: Any) -> list[Any]:
    """The rows :func:`rows_to_json` wrote, as ``cls`` again (enums and tuples restored from
    the field annotations); raises TypeError or ValueError on anything else: not a list of
    objects, a field missing or unknown, a value not of its field's type."""
    import typing
    from dataclasses import fields

    hints = typing.get_type_hints(cls)
    names = {f.name for f in fields(cls)}
    if not isinstance(data, list):
        raise TypeError("not a list of rows")
    rows = []
    for item in data:
        if not isinstance(item, dict) or set(item) != names:
            raise TypeError(f"not the fields of a {cls.__name__}")
        rows.append(cls(**{name: _typed(hints[name], v) for name, v in item.items()}))
    return rows


def _typed(hint: Any, value: Any) -> Any:
    """``value`` as the annotation ``hint`` says (an enum from its value, a tuple from a
    list); TypeError or ValueError when it is not of that type (an int is a float)."""
    import types
    import typing
    from enum import Enum

    origin = typing.get_origin(hint)
    if origin in (typing.Union, types.UnionType):
        return _one_of(typing.get_args(hint), value)
    if origin is tuple:
        return _tuple(typing.get_args(hint), value)
    if isinstance(hint, type) and issubclass(hint, Enum):
        if type(value) is not str:
            raise TypeError(f"{value!r} is not a {hint.__name__}")
        return hint(value)
    plain = {str: (str,), int: (int,), float: (float, int), bool: (bool,)}.get(hint)
    if plain is None or type(value) not in plain:
        raise TypeError(f"{value!r} is not a {getattr(hint, '__name__', hint)}")
    return value


def _one_of(options: tuple[Any, ...], value: Any) -> Any:
    if value is None:
        if type(None) in options:
            return None
        raise TypeError("None where a value is needed")
    for option in (o for o in options if o is not type(None)):
        with contextlib.suppress(TypeError, ValueError):
            return _typed(option, value)
    raise TypeError(f"{value!r} is none of {options}")


def _tuple(args: tuple[Any, ...], value: Any) -> tuple[Any, ...]:
    if type(value) is not list:
        raise TypeError(f"{value!r} is not a list")
    if len(args) == 2 and args[1] is Ellipsis:
        return tuple(_typed(args[0], v) for v in value)
    return tuple(_typed(a, v) for a, v in zip(args, value, strict=True))
