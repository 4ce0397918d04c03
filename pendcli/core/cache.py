"""A cache of computed results, keyed by the content of everything they depend on.

An entry's key is a SHA-256 over the bytes (and relative names) of every file of the
pendcli package and of the other source folders given (a registered paper's own package),
the bytes of every file under the tables folder in use (``$PENDCLI_TABLES`` included), the
version of Python, the machine, every distribution installed where the libraries are (the
names ``numpy-2.3.4.dist-info`` of site-packages: one listing, where
:mod:`importlib.metadata` costs a tenth of a second), and the parameters of the
computation (its kind, the paper). Any byte changed in any of them is another key: a miss,
never a stale result. What the key cannot see (an environment variable that picks another
BLAS kernel, a libm of the same version) is why ``pendcli check`` never reads the cache.

Where: ``$PENDCLI_CACHE`` (a folder; ``off`` disables it), else ``$XDG_CACHE_HOME/pendcli``,
else ``~/.cache/pendcli``. An entry is one JSON file written atomically
(:func:`pendcli.core.files.atomic_write`), so concurrent writers of the same key each
rename a complete file over it. An entry that is unreadable, truncated or not what its name
says is ignored (the result is computed again and the entry rewritten); a folder that cannot
be written leaves the computation uncached, with :attr:`ResultCache.problem` saying why.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import sys
from collections.abc import Callable, Iterable, Iterator, Mapping
from functools import cached_property
from pathlib import Path
from typing import Any

__all__ = [
    "ENV",
    "FORMAT",
    "KEEP",
    "KEEP_BYTES",
    "ResultCache",
    "cache_folder",
    "cached_json",
    "content_digest",
    "entries",
    "rows_from_json",
    "rows_to_json",
]

ENV = "PENDCLI_CACHE"
FORMAT = 1  # the entry layout; a new one makes every old entry a miss
# kept, the most recently used; older entries are removed when one is written (a report of
# every paper is about 8 MB)
KEEP = 200
KEEP_BYTES = 256_000_000
# not sources: byte-code, tool caches, and the package's copy of the tables (the tables folder
# in use is hashed on its own)
_SKIPPED = frozenset({"__pycache__", ".mypy_cache", ".pytest_cache", ".ruff_cache", "_tables"})
_PACKAGE = Path(__file__).resolve().parent.parent


def entries(folder: Path) -> list[tuple[Path, int]]:
    """The entries in ``folder`` with their sizes, the most recently used first."""
    found = []
    with contextlib.suppress(OSError):
        for entry in os.scandir(folder):
            if entry.name.endswith(".json"):
                with contextlib.suppress(OSError):
                    info = entry.stat()
                    found.append((info.st_mtime, Path(entry.path), info.st_size))
    return [(path, size) for _, path, size in sorted(found, key=lambda f: -f[0])]


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


def _files(root: Path) -> Iterator[Path]:
    """Every file under ``root``, in a fixed order."""
    for folder, subfolders, names in os.walk(root):
        subfolders[:] = sorted(d for d in subfolders if d not in _SKIPPED)
        for name in sorted(names):
            if not name.endswith((".pyc", ".tmp")):
                yield Path(folder) / name


def content_digest(roots: Iterable[tuple[str, Path]]) -> str:
    """SHA-256 over each file's name (relative to its labelled root) and bytes."""
    digest = hashlib.sha256()
    for label, root in roots:
        for path in _files(root):
            try:
                data = path.read_bytes()
            except OSError:
                data = b"\0unreadable"
            name = path.relative_to(root).as_posix()
            digest.update(f"{label}:{name}:{len(data)}\0".encode("utf-8", "surrogateescape"))
            digest.update(data)
    return digest.hexdigest()


def _installed() -> str:
    """Python's version, the machine, and every distribution installed beside the libraries
    pendcli computes with (the folders holding numpy, scipy, ...), each with its version."""
    from importlib.util import find_spec

    from pendcli.core.versions import DEPENDENCIES

    found = [sys.version, sys.platform, os.uname().machine if hasattr(os, "uname") else ""]
    folders: dict[str, None] = {}
    for name in DEPENDENCIES:  # not pendcli: its files are hashed
        spec = find_spec(name)
        if spec is not None and spec.origin:
            folders[str(Path(spec.origin).parent.parent)] = None
    for folder in folders:
        with contextlib.suppress(OSError):
            names = os.listdir(folder)
            found += sorted(
                f"{folder}/{n}" for n in names if n.endswith((".dist-info", ".egg-info"))
            )
    return "\n".join(found)


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
        self.problem: str | None = None  # why nothing could be written, once

    @property
    def enabled(self) -> bool:
        return self.folder is not None

    @cached_property
    def base(self) -> str:
        """The part of every key that does not depend on the call: code, data, versions."""
        roots = [("pendcli", _PACKAGE)]
        roots += [(f"source{i}", s) for i, s in enumerate(self.sources) if s != _PACKAGE]
        roots.append(("tables", self.tables))
        versions = _installed()
        return hashlib.sha256(f"{FORMAT}\0{versions}\0{content_digest(roots)}".encode()).hexdigest()

    def key(self, kind: str, params: Mapping[str, Any]) -> str:
        call = json.dumps({"kind": kind, "params": params}, sort_keys=True)
        return hashlib.sha256(f"{self.base}\0{call}".encode()).hexdigest()

    def entry_path(self, kind: str, params: Mapping[str, Any]) -> Path:
        assert self.folder is not None
        return self.folder / f"{self.key(kind, params)}.json"

    def get(self, kind: str, params: Mapping[str, Any]) -> Any | None:
        """The stored value, or None (off, absent, unreadable, truncated or not this key's)."""
        if self.folder is None:
            return None
        path = self.entry_path(kind, params)
        try:
            entry = json.loads(path.read_bytes())
        except (OSError, ValueError, RecursionError):
            return None
        expected = {"format": FORMAT, "kind": kind, "params": json.loads(json.dumps(params))}
        if not isinstance(entry, dict) or "value" not in entry:
            return None
        if {k: entry.get(k) for k in expected} != expected:
            return None
        with contextlib.suppress(OSError):
            os.utime(path)  # used: kept longest by the pruning
        return entry["value"]

    def put(self, kind: str, params: Mapping[str, Any], value: Any) -> None:
        """Store ``value`` (JSON-serialisable); a failure to write leaves it unstored."""
        if self.folder is None or self.problem is not None:
            return
        from pendcli.core.errors import PendcliError
        from pendcli.core.files import atomic_write, describe_os_error

        entry = {"format": FORMAT, "kind": kind, "params": params, "value": value}
        try:
            text = json.dumps(entry, allow_nan=True)
        except (TypeError, ValueError) as exc:  # not serialisable: a programming error
            self.problem = f"result cache: {kind} not stored ({exc})"
            return
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            atomic_write(self.entry_path(kind, params), text)
        except OSError as exc:
            self.problem = f"result cache not written ({describe_os_error(exc)})"
            return
        except PendcliError as exc:
            self.problem = f"result cache not written ({exc})"
            return
        self._prune()

    def _prune(self) -> None:
        """Remove all but the most recently used entries: at most :data:`KEEP` of them and
        :data:`KEEP_BYTES` in all."""
        assert self.folder is not None
        kept = total = 0
        for path, size in entries(self.folder):
            kept, total = kept + 1, total + size
            if kept > KEEP or total > KEEP_BYTES:
                with contextlib.suppress(OSError):
                    path.unlink()

    def clear(self) -> int:
        """Remove every entry; how many were removed."""
        if self.folder is None or not self.folder.is_dir():
            return 0
        removed = 0
        for path in self.folder.glob("*.json"):
            with contextlib.suppress(OSError):
                path.unlink()
                removed += 1
        return removed


def cached_json(
    cache: ResultCache | None, kind: str, params: Mapping[str, Any], compute: Callable[[], Any]
) -> Any:
    """The stored JSON value of (``kind``, ``params``), else ``compute()`` (stored)."""
    if cache is None:
        return compute()
    found = cache.get(kind, params)
    if found is None:
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
    the field annotations); raises TypeError, ValueError or KeyError on anything else."""
    import typing

    hints = typing.get_type_hints(cls)
    if not isinstance(data, list):
        raise TypeError("not a list of rows")
    return [cls(**{name: _typed(hints[name], v) for name, v in item.items()}) for item in data]


def _typed(hint: Any, value: Any) -> Any:
    import types
    import typing
    from enum import Enum

    origin = typing.get_origin(hint)
    if value is None:
        return None
    if origin in (typing.Union, types.UnionType):
        options = [a for a in typing.get_args(hint) if a is not type(None)]
        return _typed(options[0], value) if len(options) == 1 else value
    if origin is tuple:
        args = typing.get_args(hint)
        if len(args) == 2 and args[1] is Ellipsis:
            return tuple(_typed(args[0], v) for v in value)
        return tuple(_typed(a, v) for a, v in zip(args, value, strict=True))
    if isinstance(hint, type) and issubclass(hint, Enum):
        return hint(value)
    return value
