"""The engine's derivations as data: ``tables/derivations/<paper>.json``.

What a row's reference gives (the exact symbolic work of
:func:`pendcli.verify.printed_check.derive`: each residual with the model put in, its cases spelled
out) is written once by ``make regen`` and read back here, so that a cold ``pendcli equations``
judges every row without building one reference. ``pendcli check`` derives them again and fails on
any difference.

The format (JSON, one file per paper)::

    {"format": 2, "paper": "...", "tables": "<digest of the paper's published table and ledger>",
     "nodes": [NODE, ...],
     "rows": {"<row id>": {"inputs": "<digest of the row>", "kind": "<kind called for>",
                           "forms": {"printed": {"holds": "...", "items": [ITEM, ...]},
                                     "reading": ..., "corrected": ...}}}}

with ITEM = {"call", "where", "expr", "scale", "order", "domain", "strict", "why"} and, where
float64 cannot follow the residual itself, "taylor" (a series' terms below its order) or
"limit" (a bounded residual's limit), derived once (verify/derived.derived_once); "rooted" =
[the residual in a root t of the scale, its degree]. Each expression (``expr``, ``scale``, a
``domain``'s ends, ``taylor``, ``limit``, the rooted residual) is the index of a node of the
paper's table ``nodes`` (data/stored_expr: ``[head, argument, ...]``, a compound's arguments
earlier nodes, each distinct subexpression once, one node a line), read back by a closed
grammar: sympy's constructors of its ``HEADS`` and literals, nothing evaluated, the size of a
file, of a table and of the tree a node stands for bounded. The store is used only when its
``tables`` digest is that of the tables in use and the row's ``inputs`` digest is the row's;
otherwise the row is derived afresh (said once on stderr). Only the store shipped with the
package is read, never one from a tables folder given by ``PENDCLI_TABLES``: a folder with the
same content shares it, an edited one derives.
"""

from __future__ import annotations

import functools
import hashlib
import json
from collections.abc import Callable, Mapping
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError
from pendcli.data.stored_expr import Nodes, NodeWriter, StoredExpr, read_nodes
from pendcli.verify.derived import CALLS, Derived, Item, derived_once, stored_text

if TYPE_CHECKING:
    from pendcli.verify.derived import StoredRowFields as LedgerRow

__all__ = [
    "FORMAT",
    "StoredRow",
    "canonical_record",
    "row_inputs",
    "row_record",
    "store_path",
    "stored_nodes",
    "stored_rows",
    "stores_here",
    "text_records",
    "write_store",
]

FORMAT = 2
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
    as JSON here, their expressions (nodes of :func:`stored_nodes`) only when a row is judged
    (:func:`row_record`)."""
    raw = _raw_store(paper)
    if raw is None or raw.get("tables") != tables or raw.get("format") != FORMAT:
        return {}
    rows = raw.get("rows")
    if not isinstance(rows, dict):
        raise PendcliError(f"{store_path(paper)}: 'rows' is not a table")
    return {k: (str(v.get("inputs")), v) for k, v in rows.items() if isinstance(v, dict)}


def stored_nodes(paper: str) -> Nodes:
    """The paper's table of nodes, checked whole the first time it is asked for."""
    raw = _raw_store(paper)
    found = None if raw is None else raw.get("nodes")
    if not isinstance(found, Nodes):
        found = read_nodes(f"{store_path(paper)}", [] if found is None else found)
        if raw is not None:
            raw["nodes"] = found
    return found


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


def row_record(where: str, record: Mapping[str, Any], nodes: Nodes | None = None) -> StoredRow:
    """A stored row read back: (kind, {form: Derived}), its expressions nodes of ``nodes``
    (its paper's table); a malformed record is an error naming the row."""
    kind, forms = record.get("kind"), record.get("forms")
    if not isinstance(kind, str) or not isinstance(forms, dict) or "printed" not in forms:
        raise PendcliError(f"{where}: a stored derivation needs 'kind' and 'forms.printed'")
    table = nodes if nodes is not None else Nodes(where, [])
    out = {}
    for form, derived in forms.items():
        if form not in ("printed", "reading", "corrected") or not isinstance(derived, dict):
            raise PendcliError(f"{where}: unknown stored form {str(form)[:40]!r}")
        items = tuple(_item(f"{where} {form}", i, table) for i in derived.get("items", ()))
        out[form] = Derived(items, str(derived.get("holds", "")))
    return kind, out


def _item(where: str, raw: Any, nodes: Nodes) -> Item:
    if not isinstance(raw, dict) or raw.get("call") not in CALLS or raw["call"] == "rounded":
        raise PendcliError(f"{where}: a stored item needs a call among {', '.join(CALLS[:3])}")

    def stored(value: Any) -> StoredExpr | None:
        return None if value is None else node(value)

    def node(value: Any) -> StoredExpr:
        return StoredExpr(nodes, nodes.node(where, value))

    def built(value: Any) -> Any:
        return nodes.expr(nodes.node(where, value))

    scale = built(raw["scale"]) if raw.get("scale") is not None else None
    domain = raw.get("domain") or {}
    ends = [e for e in domain.values() if isinstance(e, list) and len(e) == 2]
    if not isinstance(domain, dict) or len(ends) != len(domain):
        raise PendcliError(f"{where}: a stored domain maps a name to [low, high]")
    bounds = {str(name): (built(low), built(high)) for name, (low, high) in domain.items()}
    order = raw.get("order")
    if order is not None and not isinstance(order, int):
        raise PendcliError(f"{where}: a stored order must be an integer")
    where_shown, strict, why = str(raw.get("where", "")), bool(raw.get("strict")), raw.get("why")
    rooted = _rooted(where, raw.get("rooted"))
    return Item(
        raw["call"], where_shown, None, scale, order, bounds, strict, str(why or ""),
        text=stored(raw.get("expr")),
        rooted=None if rooted is None else (node(rooted[0]), rooted[1]),
        taylor=stored(raw.get("taylor")), limit=stored(raw.get("limit")),
    )  # fmt: skip


def _rooted(where: str, raw: Any) -> tuple[Any, int] | None:
    if raw is None:
        return None
    ok = isinstance(raw, list) and len(raw) == 2
    if not ok or type(raw[1]) is not int or not 1 < raw[1] <= 12:
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
    """Write the paper's store atomically (a crash never leaves half a file): ``rows`` as
    :func:`item_record` writes their items (sympy's srepr), each expression made a node of
    the paper's table, each distinct subexpression once, in the order of the rows."""
    from pendcli.base.files import atomic_write

    writer = NodeWriter(f"{paper} derivations")
    encoded = {
        row_id: _with_exprs(record, functools.partial(writer.encode, row_id))
        for row_id, record in sorted(rows.items())
    }
    head = {"format": FORMAT, "paper": paper, "tables": tables}
    body = json.dumps(encoded, indent=1, ensure_ascii=False, sort_keys=True)
    nodes = ",\n".join(json.dumps(n, ensure_ascii=False) for n in writer.raw())
    text = json.dumps(head, ensure_ascii=False)[:-1]
    text += f', "nodes": [\n{nodes}\n],\n"rows": {body}}}\n'
    _raw_store.cache_clear()
    return atomic_write(store_path(paper), text)


def text_records(paper: str) -> tuple[str, dict[str, dict[str, Any]]]:
    """The paper's store as :func:`write_store` takes it: (its tables digest, {row id: the
    record with each expression written as sympy's srepr})."""
    raw = _raw_store(paper) or {}
    nodes = stored_nodes(paper)
    rows = raw.get("rows")
    return str(raw.get("tables")), {
        row_id: canonical_record(record, nodes)
        for row_id, record in (rows.items() if isinstance(rows, dict) else ())
        if isinstance(record, dict)
    }


def canonical_record(record: dict[str, Any], nodes: Nodes | None = None) -> dict[str, Any]:
    """A record with each expression written as the store writes a node: a stored one's
    (node indices of ``nodes``) and a derived one's (srepr texts, ``nodes`` None) compare
    equal when their expressions are the same."""
    if nodes is not None:
        return _with_exprs(record, lambda index: nodes.text(nodes.node("a stored row", index)))
    writer = NodeWriter("a derived row")
    return _with_exprs(record, lambda text: writer.nodes_read.text(writer.encode("", text)))


def _with_exprs(record: dict[str, Any], change: Callable[[Any], Any]) -> dict[str, Any]:
    """``record`` with ``change`` applied to each expression of its items (expr, scale, a
    domain's ends, taylor, limit, the rooted residual); a live row has none."""
    if "forms" not in record:
        return dict(record)

    def item(raw: dict[str, Any]) -> dict[str, Any]:
        out = dict(raw)
        for key in ("expr", "scale", "taylor", "limit"):
            if out.get(key) is not None:
                out[key] = change(out[key])
        if out.get("domain"):
            out["domain"] = {k: [change(e) for e in ends] for k, ends in out["domain"].items()}
        if out.get("rooted"):
            out["rooted"] = [change(out["rooted"][0]), out["rooted"][1]]
        return out

    forms = {  # in the order of their names, as the store writes them, whoever made them
        form: {**derived, "items": [item(i) for i in derived.get("items", ())]}
        for form, derived in sorted(record["forms"].items())
    }
    return {**record, "forms": forms}
