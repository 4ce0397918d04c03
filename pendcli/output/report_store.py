"""A report stored in the result cache: its key, and its files packed and checked back.

A report of the same result (:func:`result_digest`: every field of every row, and the
code, tables and versions the cache keys on) is read back instead of drawn again; what is
read back is refused unless it is exactly what pendcli writes (:func:`unpack`).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from pendcli.run.reproduce import ReproduceResult


def result_digest(result: ReproduceResult) -> str:
    """SHA-256 over every field of every row of ``result`` (and its papers, in order)."""
    import hashlib
    import json

    from pendcli.base.cache import rows_to_json

    rows = {
        name: {key: rows_to_json(table[key]) for key in sorted(table)}
        for name, table in (
            ("claims", result.claims),
            ("formulas", result.formulas),
            ("equations", result.equations),
        )
    }
    every = {"papers": list(result.papers), **rows, "stability": result.stability}
    return hashlib.sha256(json.dumps(every, sort_keys=True).encode()).hexdigest()


def pack(folder: Path, names: list[Path]) -> dict[str, Any]:
    """The report's files (relative name -> base64 of the bytes), to be stored."""
    import base64

    files = {n.as_posix(): base64.b64encode((folder / n).read_bytes()).decode() for n in names}
    return {"files": files}


def unpack(entry: Any, folder: Path, written: list[Path]) -> bool:
    """Write a stored report into ``folder`` (and its names into ``written``); False, with
    nothing written, when the entry is not a stored report (:func:`_stored_files`)."""
    decoded = _stored_files(entry)
    if decoded is None:
        return False
    for name, data in decoded.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_bytes(data)
    written.extend(decoded)
    return True


# A stored report's file names are names pendcli writes: relative paths of at most
# _STORED_DEPTH parts (each a letter, digit or "_", then those or ".", "+", "-"), at most
# _STORED_NAME characters, at most _STORED_FILES of them.
_STORED_PART = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.+-]{0,99}")
_STORED_DEPTH, _STORED_NAME, _STORED_FILES = 8, 200, 1000


def _stored_files(entry: Any) -> dict[Path, bytes] | None:
    """The files of a stored report, name -> bytes; None unless ``entry`` is ``{"files":
    {name: base64}}`` with 1 to _STORED_FILES names of the form above, none of them the
    manifest nor a folder of another, each with strict base64."""
    import base64
    import binascii

    from pendcli.base.owned_folders import MANIFEST

    files = entry.get("files") if isinstance(entry, dict) and set(entry) == {"files"} else None
    if not isinstance(files, dict) or not 0 < len(files) <= _STORED_FILES:
        return None
    names = set(files)
    if MANIFEST in names or not all(_stored_name(n) for n in names):
        return None
    if any(
        name.rsplit("/", i)[0] in names for name in names for i in range(1, name.count("/") + 1)
    ):
        return None  # "zz" and "zz/b": a file where a folder must be
    try:
        return {Path(n): base64.b64decode(d, validate=True) for n, d in files.items()}
    except (TypeError, ValueError, binascii.Error):
        return None


def _stored_name(name: object) -> bool:
    if not isinstance(name, str) or len(name) > _STORED_NAME:
        return False
    parts = name.split("/")
    return len(parts) <= _STORED_DEPTH and all(_STORED_PART.fullmatch(p) for p in parts)
