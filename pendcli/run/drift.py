"""The committed tables of ``tables/regenerated/``: their columns, their tolerances, and how
a cell drifts from its committed value.

Each regenerated CSV has a fixed header (:data:`CLAIM_COLUMNS`, :data:`FORMULA_COLUMNS`,
:data:`EQUATION_COLUMNS`); :func:`read_table` validates one (header, field counts, unique ids,
numbers where a column is numeric), and :func:`compare_tables` lists every :class:`Drift`
between a committed table and its regeneration: a row added or removed, a cell changed, or
a numeric cell moved beyond its column's tolerance (:data:`TOLERANCES`: relative for values,
absolute for fitted orders). :mod:`pendcli.run.regression` runs the check;
:mod:`pendcli.output.check_formats` formats its drifts.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path

from pendcli.base.errors import PendcliError

__all__ = [
    "CLAIM_COLUMNS",
    "EQUATION_COLUMNS",
    "FORMULA_COLUMNS",
    "TOLERANCES",
    "Drift",
    "cell_drift",
    "compare_tables",
    "expected_columns",
    "find_drifts",
    "read_committed",
    "read_table",
]

CLAIM_COLUMNS = (
    "id",
    "published",
    "unit",
    "recomputed",
    "exact",
    "abs_diff",
    "rel_diff",
    "verdict",
    "procedure_verdict",
    "procedure_value",
    "cause",
    "from",
    "condition",
)
FORMULA_COLUMNS = ("id", "source", "claimed_order", "observed_order", "verdict", "cause", "from")
# finding: a failing or misprinted row that restates no other (tables/README.md, Blame);
# condition: its verdict on each side of an assumption the paper leaves open
EQUATION_COLUMNS = ("id", "equation", "lines", "status", "kind", "dimensions", "observed_order",
                    "finding", "condition")  # fmt: skip

# column -> (kind, tolerance). "rel": |now - then| <= tol * max(|then|, tiny);
# "abs": |now - then| <= tol; "same": must be identical text.
TOLERANCES: dict[str, tuple[str, float]] = {
    "published": ("same", 0.0),
    "unit": ("same", 0.0),
    "source": ("same", 0.0),
    "verdict": ("same", 0.0),
    # the verdict against the author's own procedure, and that procedure on his printed inputs
    "procedure_verdict": ("same", 0.0),
    "procedure_value": ("rel", 1e-9),
    "cause": ("same", 0.0),  # why a row disagrees, and the rows it inherits from
    "from": ("same", 0.0),
    "equation": ("same", 0.0),  # a ledger row's label as printed, and where it is printed
    "lines": ("same", 0.0),
    "status": ("same", 0.0),  # the ledger's computed status, and its printed form's dimensions
    "kind": ("same", 0.0),  # the kind of check that decides the row
    # a finding of its own, and a conditional verdict's sides (a ledger row's or a claim's)
    "finding": ("same", 0.0),
    "condition": ("same", 0.0),
    "dimensions": ("same", 0.0),
    "recomputed": ("rel", 1e-9),  # closed forms, special functions: last-bit noise only
    "exact": ("rel", 1e-7),  # fuller models (quadrature, ODE at tight tolerance)
    "abs_diff": ("abs", 1e-9),
    "rel_diff": ("abs", 1e-9),
    "claimed_order": ("abs", 0.0),
    "observed_order": ("abs", 0.05),  # a least-squares slope over 4-6 points
}


@dataclass(frozen=True)
class Drift:
    table: str
    id: str
    column: str
    published: str
    committed: str
    now: str
    difference: str


def expected_columns(name: str) -> tuple[str, ...] | None:
    """The header a regenerated table ``name`` must have (None for a name pendcli never writes)."""
    if name.endswith("-claims.csv"):
        return CLAIM_COLUMNS
    if name.endswith("-formulas.csv"):
        return FORMULA_COLUMNS
    if name.endswith("-equations.csv"):
        return EQUATION_COLUMNS
    return None


Table = tuple[tuple[str, ...], dict[str, dict[str, str]]]


def read_table(text: str, where: str, columns: tuple[str, ...] | None = None) -> Table:
    """Parse and validate one regenerated CSV: header ``columns`` (or any starting with ``id``),
    every row as many fields, a unique non-empty id, numeric columns numbers. Errors name
    ``where`` and the line."""
    reader = csv.reader(io.StringIO(text, newline=""), strict=True)
    try:
        header = tuple(next(reader, ()))
        _check_header(header, where, columns)
        if not text.endswith("\n"):  # pendcli ends every table with one: the last row is cut
            last = text.count("\n") + 1
            raise PendcliError(
                f"{where}: line {last} ends without a newline; the table was cut short"
            )
        rows: dict[str, dict[str, str]] = {}
        for fields in reader:
            if fields:  # a blank line carries nothing
                row = _check_row(fields, header, f"{where}: line {reader.line_num}", rows)
                rows[row["id"]] = row
    except csv.Error as exc:
        raise PendcliError(f"{where}: line {reader.line_num}: malformed CSV ({exc})") from None
    return header, rows


def _check_header(header: tuple[str, ...], where: str, columns: tuple[str, ...] | None) -> None:
    wanted = ",".join(columns) if columns else "id,..."
    if not header:
        raise PendcliError(f"{where}: empty table; expected the header line {wanted}")
    if (columns and header != columns) or header[0] != "id" or len(set(header)) != len(header):
        raise PendcliError(f"{where}: line 1: header {','.join(header)!r}; expected {wanted}")


def _check_row(
    fields: list[str], header: tuple[str, ...], where: str, seen: dict[str, dict[str, str]]
) -> dict[str, str]:
    if len(fields) != len(header):
        raise PendcliError(f"{where} has {len(fields)} fields; expected {len(header)}")
    row = dict(zip(header, fields, strict=True))
    if not row["id"]:
        raise PendcliError(f"{where} has an empty id")
    if row["id"] in seen:
        raise PendcliError(f"{where} repeats id {row['id']!r}")
    for col in header:
        if TOLERANCES.get(col, ("same", 0.0))[0] != "same":
            _number(row[col], f"{where}, column {col!r}")
    return row


def _number(text: str, where: str) -> float | None:
    """A numeric cell: empty (no value) or a float; ``inf``/``nan``/``1e400`` parse, and
    :func:`cell_drift` treats them as changes."""
    if text == "":
        return None
    try:
        return float(text)
    except ValueError:
        raise PendcliError(f"{where}: {text!r} is not a number") from None


def compare_tables(
    name: str, committed_text: str, now_text: str, where: str | None = None
) -> list[Drift]:
    """Every drift between a committed table (read from ``where``) and its regeneration."""
    columns, now = read_table(now_text, f"regenerated {name}", expected_columns(name))
    _, then = read_table(committed_text, where or f"tables/regenerated/{name}", columns)
    drifts: list[Drift] = []
    for cid in sorted(set(then) - set(now)):
        drifts.append(
            Drift(name, cid, "(row)", then[cid].get("published", ""), "present", "gone", "")
        )
    for cid in sorted(set(now) - set(then)):
        drifts.append(Drift(name, cid, "(row)", now[cid].get("published", ""), "absent", "new", ""))
    for cid in [c for c in now if c in then]:
        for col in columns[1:]:
            drift = cell_drift(name, cid, col, then[cid], now[cid])
            if drift is not None:
                drifts.append(drift)
    return drifts


def cell_drift(
    name: str, cid: str, col: str, then: dict[str, str], now: dict[str, str]
) -> Drift | None:
    """How one cell moved beyond its column's tolerance (:data:`TOLERANCES`), or None."""
    published = now.get("published", "")
    a, b = then[col], now[col]
    kind, tol = TOLERANCES.get(col, ("same", 0.0))
    if kind == "same":
        return Drift(name, cid, col, published, a, b, "changed") if a != b else None
    x, y = _number(a, col), _number(b, col)
    if x is None or y is None:
        if (x is None) != (y is None):
            return Drift(name, cid, col, published, a, b, "appeared/vanished")
        return None
    if not (math.isfinite(x) and math.isfinite(y)):
        # tol·|inf| would swallow any change: a non-finite value holds only as the same token.
        return None if a == b else Drift(name, cid, col, published, a, b, "non-finite")
    diff = y - x
    limit = tol * max(abs(x), 1e-300) if kind == "rel" else tol
    if abs(diff) <= limit:
        return None
    rel = f" ({diff / x:+.2e} rel)" if x else ""
    return Drift(name, cid, col, published, a, b, f"{diff:+.3e}{rel}")


def find_drifts(folder: Path, tables: dict[str, str]) -> list[Drift]:
    """Every drift between the committed tables in ``folder`` and ``tables`` (name -> CSV)."""
    drifts: list[Drift] = []
    committed_names = {p.name for p in folder.glob("*.csv")} if folder.is_dir() else set()
    for name in sorted(committed_names - set(tables)):
        drifts.append(Drift(name, "(table)", "(file)", "", "committed", "no longer produced", ""))
    for name, text in tables.items():
        path = folder / name
        if not path.is_file():
            drifts.append(Drift(name, "(table)", "(file)", "", "missing", "produced", ""))
            continue
        drifts.extend(compare_tables(name, read_committed(path), text, str(path)))
    return drifts


def read_committed(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise PendcliError(f"{path}: not UTF-8 text (byte {exc.start})") from None
    except OSError as exc:
        raise PendcliError(f"cannot read {path}: {exc.strerror or type(exc).__name__}") from None
