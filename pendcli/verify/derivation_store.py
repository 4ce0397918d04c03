"""The engine's derivations as data: ``tables/derivations/<paper>.json``.

What a row's reference gives (the exact symbolic work of
:func:`pendcli.verify.printed_check.derive`: each residual with the model put in, its cases spelled
out) is written once by ``make regen`` and read back here, so that a cold ``pendcli equations``
judges every row without building one reference. ``pendcli check`` derives them again and fails on
any difference.

The format (JSON, one file per paper)::

    {"format": 1, "paper": "...", "tables": "<digest of the paper's published table and ledger>",
     "rows": {"<row id>": {"inputs": "<digest of the row>", "kind": "<kind called for>",
                           "forms": {"printed": {"holds": "...", "items": [ITEM, ...]},
                                     "reading": ..., "corrected": ...}}}}

with ITEM = {"call", "where", "expr", "scale", "order", "domain", "strict", "why"} and, where
float64 cannot follow the residual itself, "taylor" (a series' terms below its order) or
"limit" (a bounded residual's limit), derived once (core/derived.derived_once); each
expression is sympy's ``srepr``, read back by a closed grammar (data/stored_expr): calls of
the sympy constructors of its ``HEADS`` with number, string and boolean arguments, nothing
evaluated, the size of a file and the depth of an expression bounded. The store is
used only when its ``tables`` digest is that of the tables in use and the row's ``inputs``
digest is the row's; otherwise the row is derived afresh (said once on stderr). Only the
store shipped with the package is read, never one from a tables folder given by
``PENDCLI_TABLES``: a folder with the same content shares it, an edited one derives.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError
from pendcli.data.stored_expr import read_expr
from pendcli.verify.derived import CALLS, Derived, Item, derived_once, stored_text

if TYPE_CHECKING:
    from pendcli.verify.derived import StoredRowFields as LedgerRow

__all__ = [
    "FORMAT",
    "StoredRow",
    "row_inputs",
    "row_record",
    "store_path",
    "stored_rows",
    "stores_here",
    "write_store",
]

FORMAT = 1
_MAX_BYTES = 8_000_000  # a store's file


# A row's stored derivation: the kind its reference calls for, and each form's items
StoredRow = tuple[str, dict[str, Derived]]


_PACKAGE_TABLES = Path(__file__).resolve().parent.parent / "_tables"


def store_path(paper: str) -> Path:
    """The store shipped with the package (never a ``PENDCLI_TABLES`` folder's)."""
    return _PACKAGE_TABLES / "derivations" / f"{paper}.json"


def stores_here(tables: Path) -> bool:
    """Whether ``tables`` is the package's own folder, the only one whose derivations are
    stored (``make regen``, ``check --update``) and compared (``check``)."""
    return tables.resolve() == _PACKAGE_TABLES.resolve()


def row_inputs(row: LedgerRow, symbols: Mapping[str, str]) -> str:
    """The digest of what the row's derivation reads of the row itself."""
    parts = [
        row.read("printed"),
        row.read("reading_formula"),
        row.read("corrected_formula"),
        row.reference,
        row.kind,
        sorted(symbols.items()),
    ]
    return hashlib.sha256(json.dumps(parts, ensure_ascii=True).encode()).hexdigest()


def stored_rows(paper: str, tables: str) -> dict[str, tuple[str, dict[str, Any]]]:
    """{row id: (inputs digest, record)} of the paper's store when it was derived from tables
    whose digest is ``tables``; empty when there is none or it is stale. The records are read
    as JSON here, their expressions only when a row is judged (:func:`row_record`)."""
    raw = _raw_store(paper)
    if raw is None or raw.get("tables") != tables or raw.get("format") != FORMAT:
        return {}
    rows = raw.get("rows")
    if not isinstance(rows, dict):
        raise PendcliError(f"{store_path(paper)}: 'rows' is not a table")
    return {k: (str(v.get("inputs")), v) for k, v in rows.items() if isinstance(v, dict)}


@cache
def _raw_store(paper: str) -> dict[str, Any] | None:
    path = store_path(paper)
    try:
        with path.open("rb") as handle:
            data = handle.read(_MAX_BYTES + 1)
    except FileNotFoundError:
        return None
    except OSError as exc:
        raise PendcliError(f"{path}: cannot read the derivations ({exc.strerror})") from None
    if len(data) > _MAX_BYTES:
        raise PendcliError(f"{path}: more than {_MAX_BYTES} bytes of derivations")
    try:
        raw = json.loads(data)
    except (ValueError, RecursionError):
        raise PendcliError(f"{path}: not JSON: run `make regen`") from None
    return raw if isinstance(raw, dict) else None


def row_record(where: str, record: Mapping[str, Any]) -> StoredRow:
    """A stored row read back: (kind, {form: Derived}); a malformed record is an error naming
    the row."""
    kind, forms = record.get("kind"), record.get("forms")
    if not isinstance(kind, str) or not isinstance(forms, dict) or "printed" not in forms:
        raise PendcliError(f"{where}: a stored derivation needs 'kind' and 'forms.printed'")
    out = {}
    for form, derived in forms.items():
        if form not in ("printed", "reading", "corrected") or not isinstance(derived, dict):
            raise PendcliError(f"{where}: unknown stored form {str(form)[:40]!r}")
        items = tuple(_item(f"{where} {form}", i) for i in derived.get("items", ()))
        out[form] = Derived(items, str(derived.get("holds", "")))
    return kind, out


def _item(where: str, raw: Any) -> Item:
    if not isinstance(raw, dict) or raw.get("call") not in CALLS or raw["call"] == "rounded":
        raise PendcliError(f"{where}: a stored item needs a call among {', '.join(CALLS[:3])}")
    text = raw.get("expr")
    if text is not None and not isinstance(text, str):
        raise PendcliError(f"{where}: a stored expression must be a string")
    scale = read_expr(where, raw["scale"]) if raw.get("scale") is not None else None
    domain = {
        str(name): (read_expr(where, low), read_expr(where, high))
        for name, (low, high) in dict(raw.get("domain") or {}).items()
    }
    order = raw.get("order")
    if order is not None and not isinstance(order, int):
        raise PendcliError(f"{where}: a stored order must be an integer")
    where_shown, strict, why = str(raw.get("where", "")), bool(raw.get("strict")), raw.get("why")
    rooted = _rooted(where, raw.get("rooted"))
    taylor, limit = (_optional_text(where, raw, name) for name in ("taylor", "limit"))
    return Item(
        raw["call"], where_shown, None, scale, order, domain, strict, str(why or ""),
        text=text, rooted=rooted, taylor=taylor, limit=limit,
    )  # fmt: skip


def _optional_text(where: str, raw: Mapping[str, Any], name: str) -> str | None:
    value = raw.get(name)
    if value is not None and not isinstance(value, str):
        raise PendcliError(f"{where}: a stored {name} must be a string")
    return value


def _rooted(where: str, raw: Any) -> tuple[str, int] | None:
    if raw is None:
        return None
    ok = isinstance(raw, list) and len(raw) == 2 and isinstance(raw[0], str)
    if not ok or not isinstance(raw[1], int) or not 1 < raw[1] <= 12:
        raise PendcliError(f"{where}: 'rooted' must be [an expression, a degree in 2..12]")
    return raw[0], raw[1]


def item_record(item: Item) -> dict[str, Any]:
    """An item as the store writes it (a rounded item, judged from its live reference, has
    no record: its row is never stored)."""

    if item.call == "rounded":
        raise ValueError("a rounded item is judged from its live reference")

    def text(value: Any) -> str | None:
        if value is None:
            return None
        return stored_text(value)

    return {
        "call": item.call,
        "where": item.where,
        "expr": item.source,
        "scale": text(item.scale),
        "order": item.order,
        "domain": {k: [text(low), text(high)] for k, (low, high) in sorted(item.domain.items())},
        "strict": item.strict,
        "why": item.why,
        **({"rooted": list(item.rooted)} if item.rooted else {}),
        **derived_once(item),
    }


def write_store(paper: str, tables: str, rows: Mapping[str, dict[str, Any]]) -> Path:
    """Write the paper's store atomically (a crash never leaves half a file)."""
    from pendcli.base.files import atomic_write

    body = {"format": FORMAT, "paper": paper, "tables": tables, "rows": dict(rows)}
    text = json.dumps(body, indent=1, ensure_ascii=False, sort_keys=True) + "\n"
    _raw_store.cache_clear()
    return atomic_write(store_path(paper), text)
