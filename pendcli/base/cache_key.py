"""What a result cache key is made of: the bytes of the code and the tables, and the libraries
installed here.

:func:`folders_digest` hashes every file under the folders given (names relative to their
labelled root, sizes, bytes), reading regular files only, in chunks, each at most
:data:`MAX_HASHED_BYTES`, and no link out of its folder: anything else (a FIFO, a device, a
huge file) is one line, exit 2. :func:`installed_signature` is Python's version, the machine
and every distribution pendcli computes with, followed through their ``Requires-Dist`` whose
environment marker holds (:func:`required_distributions`): a test tool installed beside them
is not in it.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import re
import stat
import sys
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

__all__ = [
    "MAX_HASHED_BYTES",
    "READ_FLAGS",
    "folders_digest",
    "installed_signature",
    "required_distributions",
    "runtime_signature",
]

# a file under a hashed folder larger is refused (the largest table is under 1 MB)
MAX_HASHED_BYTES = 64 * 2**20
_CHUNK = 2**20
# not sources: byte-code, tool caches, and the package's copy of the tables (the tables folder
# in use is hashed on its own)
_SKIPPED = frozenset({"__pycache__", ".mypy_cache", ".pytest_cache", ".ruff_cache", "_tables"})
# a file opened for reading: never through a link, never waiting on a FIFO
READ_FLAGS = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC


def _files(root: Path) -> Iterator[tuple[Path, str]]:
    """Every file under the (resolved) folder ``root`` with its name relative to it, in a
    fixed order; a link is given as the file it names, refused when that is outside ``root``
    (a link to a folder inside is skipped: its files are hashed where they are)."""
    for folder, subfolders, names in os.walk(root):
        here = Path(folder)
        subfolders[:] = sorted(d for d in subfolders if d not in _SKIPPED)
        for name in [d for d in subfolders if (here / d).is_symlink()]:
            _inside(root, here / name)
            subfolders.remove(name)
        for name in sorted(names):
            if not name.endswith((".pyc", ".tmp")):
                path = here / name
                shown = path.relative_to(root).as_posix()
                yield (_inside(root, path) if path.is_symlink() else path), shown


def _inside(root: Path, link: Path) -> Path:
    """The path ``link`` names, when it lies inside ``root`` (a dangling link: itself)."""
    from pendcli.base.errors import PendcliError

    target = link.resolve()
    if not target.exists():
        return link
    if target != root and root not in target.parents:
        raise PendcliError(
            f"{link} is a link out of {root} (to {target}); the result cache hashes only "
            f"files inside it: copy the file in, or run with --no-cache"
        )
    return target


def _hash_file(digest: Any, path: Path) -> None:
    """Add ``path``'s size and bytes to ``digest``, read in chunks; a FIFO, a device, a socket
    or a file above :data:`MAX_HASHED_BYTES` is one line (never opened, never waited on)."""
    try:
        mode = os.lstat(path).st_mode
        fd = os.open(path, READ_FLAGS) if stat.S_ISREG(mode) else -1
    except OSError:  # vanished, no permission
        mode, fd = 0, -1
    if fd < 0 and (mode == 0 or stat.S_ISLNK(mode)):  # or a dangling link: a key of its own
        digest.update(b"\0unreadable")
        return
    try:
        info = os.fstat(fd) if fd >= 0 else None
        if info is None or not stat.S_ISREG(info.st_mode):
            raise _not_hashed(path, "is a FIFO, device or socket")
        if info.st_size > MAX_HASHED_BYTES:
            raise _not_hashed(path, f"is {info.st_size} bytes")
        digest.update(f"{info.st_size}\0".encode())
        left = info.st_size
        while left > 0 and (chunk := os.read(fd, min(left, _CHUNK))):
            digest.update(chunk)
            left -= len(chunk)
    finally:
        if fd >= 0:
            os.close(fd)


def _not_hashed(path: Path, problem: str) -> Exception:
    from pendcli.base.errors import PendcliError

    return PendcliError(
        f"{path} {problem}: the result cache hashes only regular files of at most "
        f"{MAX_HASHED_BYTES} bytes; remove it, or run with --no-cache"
    )


def folders_digest(roots: Iterable[tuple[str, Path]]) -> str:
    """SHA-256 over each file's name (relative to its labelled root), size and bytes."""
    digest = hashlib.sha256()
    for label, root in roots:
        base = Path(root).resolve()
        for path, shown in _files(base):
            digest.update(f"{label}:{shown}:".encode("utf-8", "surrogateescape"))
            _hash_file(digest, path)
    return digest.hexdigest()


def installed_signature() -> str:
    """Python's version, the machine, and each distribution pendcli computes with (its
    libraries and everything they require here, transitively), each with its version: a test
    or lint tool installed beside them (pytest, ruff, mypy, hypothesis) is not part of a
    result, so adding one keeps every entry valid."""
    from importlib.util import find_spec

    from pendcli.base.versions import DEPENDENCIES

    folders: dict[Path, None] = {}
    for name in DEPENDENCIES:  # not pendcli: its files are hashed
        spec = find_spec(name)
        if spec is not None and spec.origin:
            folders[Path(spec.origin).parent.parent] = None
    return runtime_signature(folders, DEPENDENCIES)


def runtime_signature(folders: Iterable[Path], roots: Iterable[str]) -> str:
    """The part of the key the installed libraries make: Python's version, the machine, and
    in each of ``folders`` the distributions of ``roots`` and what they require here
    (:func:`required_distributions`), with their versions."""
    found = [sys.version, sys.platform, os.uname().machine if hasattr(os, "uname") else ""]
    roots = tuple(roots)
    for folder in folders:
        with contextlib.suppress(OSError):
            found += [f"{folder}/{n}" for n in required_distributions(Path(folder), roots)]
    return "\n".join(found)


def _project(name: str) -> str:
    """A distribution's name as PEP 503 compares it (``Markdown_It-py`` -> ``markdown-it-py``)."""
    return re.sub(r"[-_.]+", "-", name).lower()


def required_distributions(folder: Path, roots: Iterable[str]) -> list[str]:
    """The ``*.dist-info`` / ``*.egg-info`` names in ``folder`` of ``roots`` and of every
    distribution they require (their ``Requires-Dist``, extras left out), sorted."""
    metadata = {}
    for entry in os.listdir(folder):
        if entry.endswith((".dist-info", ".egg-info")):
            metadata[_project(entry.rsplit(".", 1)[0].split("-", 1)[0])] = entry
    wanted, queue = set(), [_project(r) for r in roots]
    while queue:
        name = queue.pop()
        if name in wanted or name not in metadata:
            continue
        wanted.add(name)
        queue += _requires(folder / metadata[name])
    return sorted(metadata[n] for n in wanted)


def _requires(info: Path) -> list[str]:
    text = ""
    for file in ("METADATA", "PKG-INFO"):
        with contextlib.suppress(OSError, UnicodeDecodeError):
            text = (info / file).read_text(encoding="utf-8")
            break
    out = []
    for line in text.splitlines():
        if not line.startswith("Requires-Dist:"):
            continue
        requirement, _, marker = line.removeprefix("Requires-Dist:").partition(";")
        name = re.match(r"\s*([A-Za-z0-9][A-Za-z0-9._-]*)", requirement)
        if name and _applies(marker):
            out.append(_project(name.group(1)))
    return out


def _applies(marker: str) -> bool:
    """Whether a requirement's environment marker holds here: never for an extra (a test
    tool), never on another system or Python (``colorama; platform_system == "Windows"``:
    a test tool installing colorama on Linux changed the key). Without the ``packaging``
    library to read it, a marker is taken to hold (a key too wide misses, never serves a
    stale result)."""
    marker = marker.strip()
    if not marker:
        return True
    if "extra" in marker:
        return False
    try:
        from packaging.markers import Marker
    except ImportError:
        return True
    try:
        return bool(Marker(marker).evaluate())
    except Exception:  # an invalid marker: followed, as without packaging
        return True
