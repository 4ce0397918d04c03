"""The CI regression of tables: regenerate everything, compare with the committed CSVs.

The committed tables live in ``tables/regenerated/``, one CSV per table: ``<paper>-claims.csv``
and ``<paper>-formulas.csv``. :func:`run_check` recomputes them and fails (exit 1) on

* a claim or formula added or removed,
* a changed published string (the printed value in ``tables/published`` was edited),
* a changed verdict,
* a numeric column that moved beyond its tolerance (:data:`TOLERANCES`, explicit per column).

``--update`` rewrites the committed tables instead. Tolerances are relative for values and
absolute for fitted orders; they exist so that a different libm or scipy release, which
moves a result in its last bits, does not fail CI, while any real change does.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.core.claims import PAPERS
from pendcli.core.errors import PendcliError
from pendcli.core.files import locked, remove_stale, replace_directory
from pendcli.core.tables import tables_dir
from pendcli.render.columns import Column
from pendcli.render.csv import to_csv

if TYPE_CHECKING:
    from rich.console import Console

    from pendcli.reproduce import ReproduceResult

__all__ = [
    "TOLERANCES",
    "Drift",
    "compare_tables",
    "find_drifts",
    "regenerated_tables",
    "run_check",
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
)
FORMULA_COLUMNS = ("id", "source", "claimed_order", "observed_order", "verdict")

# column -> (kind, tolerance). "rel": |now - then| <= tol * max(|then|, tiny);
# "abs": |now - then| <= tol; "same": must be identical text.
TOLERANCES: dict[str, tuple[str, float]] = {
    "published": ("same", 0.0),
    "unit": ("same", 0.0),
    "source": ("same", 0.0),
    "verdict": ("same", 0.0),
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


def _claim_rows(result: ReproduceResult, key: str) -> list[dict[str, object]]:
    return [{k: r.as_dict()[k] for k in CLAIM_COLUMNS} for r in result.claims.get(key, [])]


def _formula_rows(result: ReproduceResult, key: str) -> list[dict[str, object]]:
    return [{k: r.as_dict()[k] for k in FORMULA_COLUMNS} for r in result.formulas.get(key, [])]


def regenerated_tables(result: ReproduceResult) -> dict[str, str]:
    """File name -> CSV text for every regenerated table of a reproduce result."""
    out: dict[str, str] = {}
    for key in result.papers:
        out[f"{key}-claims.csv"] = to_csv(_claim_rows(result, key), CLAIM_COLUMNS)
        if result.formulas.get(key):
            out[f"{key}-formulas.csv"] = to_csv(_formula_rows(result, key), FORMULA_COLUMNS)
    return out


def _read_csv(text: str, where: str) -> tuple[list[str], dict[str, dict[str, str]]]:
    reader = csv.DictReader(io.StringIO(text))
    if not reader.fieldnames or "id" not in reader.fieldnames:
        raise PendcliError(f"{where}: malformed table (no 'id' column)")
    rows: dict[str, dict[str, str]] = {}
    for line, row in enumerate(reader, start=2):
        if None in row or any(v is None for v in row.values()):
            raise PendcliError(f"{where}: line {line} has the wrong number of fields")
        if row["id"] in rows:
            raise PendcliError(f"{where}: line {line} repeats id {row['id']!r}")
        rows[row["id"]] = row
    return list(reader.fieldnames), rows


def _number(text: str, where: str) -> float | None:
    if text == "":
        return None
    try:
        return float(text)
    except ValueError:
        raise PendcliError(f"{where}: {text!r} is not a number") from None


def compare_tables(name: str, committed_text: str, now_text: str) -> list[Drift]:
    """Every drift between a committed table and its regeneration."""
    where = f"tables/regenerated/{name}"
    _, then = _read_csv(committed_text, where)
    columns, now = _read_csv(now_text, f"regenerated {name}")
    drifts: list[Drift] = []
    for cid in sorted(set(then) - set(now)):
        drifts.append(
            Drift(name, cid, "(row)", then[cid].get("published", ""), "present", "gone", "")
        )
    for cid in sorted(set(now) - set(then)):
        drifts.append(Drift(name, cid, "(row)", now[cid].get("published", ""), "absent", "new", ""))
    for cid in [c for c in now if c in then]:
        for col in columns:
            if col != "id":
                drift = _cell_drift(name, cid, col, then[cid], now[cid])
                if drift is not None:
                    drifts.append(drift)
    return drifts


def _cell_drift(
    name: str, cid: str, col: str, then: dict[str, str], now: dict[str, str]
) -> Drift | None:
    """How one cell moved beyond its column's tolerance (:data:`TOLERANCES`), or None."""
    published = now.get("published", "")
    if col not in then:
        return Drift(name, cid, col, published, "(no column)", now[col], "")
    a, b = then[col], now[col]
    kind, tol = TOLERANCES.get(col, ("same", 0.0))
    if kind == "same":
        return Drift(name, cid, col, published, a, b, "changed") if a != b else None
    x = _number(a, f"tables/regenerated/{name}: {cid!r} column {col!r}")
    y = _number(b, f"regenerated {name}: {cid!r} column {col!r}")
    if x is None or y is None:
        if (x is None) != (y is None):
            return Drift(name, cid, col, published, a, b, "appeared/vanished")
        return None
    diff = y - x
    limit = tol * max(abs(x), 1e-300) if kind == "rel" else tol
    if abs(diff) <= limit and not math.isnan(diff):
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
        drifts.extend(compare_tables(name, path.read_text(encoding="utf-8"), text))
    return drifts


def run_check(update: bool = False, quiet: bool = False, root: Path | None = None) -> int:
    """Regenerate every table; compare (or, with ``update``, rewrite). Returns the exit code."""
    from pendcli.core.console import console
    from pendcli.reproduce import reproduce_all

    folder = (root or tables_dir()).resolve() / "regenerated"
    result = reproduce_all(PAPERS, formulas=True, quiet=quiet)
    tables = regenerated_tables(result)
    out = console()
    if update:
        removed = _rewrite(folder, tables)
        if not quiet:
            out.print(f"rewrote {len(tables)} tables in {folder}")
            if removed:
                out.print(
                    f"removed {len(removed)} table(s) no longer produced: {', '.join(removed)}"
                )
        return 0
    with locked(_lock_file(folder), shared=True):
        drifts = find_drifts(folder, tables)
    if drifts:
        _print_drifts(out, drifts)
        return 1
    if not quiet:
        n = sum(len(v) for v in result.claims.values())
        f = sum(len(v) for v in result.formulas.values())
        out.print(
            f"check passed: {len(tables)} tables, {n} claims, {f} formulas match "
            f"tables/regenerated within tolerance"
        )
    return 0


def _lock_file(folder: Path) -> Path:
    return folder.parent / f".{folder.name}.lock"


def _rewrite(folder: Path, tables: dict[str, str]) -> list[str]:
    """``pendcli check --update``: the committed tables become the regenerated ones.

    The whole set is written beside the folder and swapped in at once under an exclusive
    lock, so a crash leaves the old set or the new one, never a mix or a cut table.
    Returns the names of the tables that are no longer produced (removed by the swap).
    """

    def fill(tmp: Path) -> None:
        for name, text in tables.items():
            (tmp / name).write_text(text, encoding="utf-8")

    removed = sorted(p.name for p in folder.glob("*.csv") if p.name not in tables)
    with locked(_lock_file(folder)):
        remove_stale(folder.parent, folder.name)
        replace_directory(folder, fill)
    return removed


def _print_drifts(out: Console, drifts: list[Drift]) -> None:
    from pendcli.render.table import to_rich_table

    rows = [dataclasses.asdict(d) for d in drifts]
    cols = [Column(k, k) for k in (f.name for f in dataclasses.fields(Drift))]
    out.print(to_rich_table(rows, cols, title=f"check FAILED: {len(drifts)} drift(s)"))
    out.print("If the change is intended, run `pendcli check --update` (make regen) and commit.")
