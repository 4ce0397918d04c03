"""The CI regression of tables: regenerate everything, compare with the committed CSVs.

The committed tables live in ``tables/regenerated/``, one CSV per table: ``<paper>-claims.csv``,
``<paper>-formulas.csv`` and, for a paper with an equation ledger, ``<paper>-equations.csv``
(each ledger row's status, the dimensions of its printed form, the order it observes).
:func:`run_check` recomputes them and fails (exit 1) on

* a claim, formula or ledger row added or removed,
* a changed published string (the printed value in ``tables/published`` was edited),
* a changed verdict (against the truth or against the author's procedure), cause or ledger
  status (or the dimensions of a printed form, or its label or lines),
* a numeric column that moved beyond its tolerance (:data:`TOLERANCES`, explicit per column).

``--update`` rewrites the committed tables instead. Tolerances are relative for values and
absolute for fitted orders; they exist so that a different libm or scipy release, which
moves a result in its last bits, does not fail CI, while any real change does.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from pendcli.base.errors import PendcliError
from pendcli.base.files import lock_file, locked
from pendcli.base.owned_folders import replace_owned_folder, write_through
from pendcli.data.tables import tables_dir
from pendcli.output.columns import Column
from pendcli.output.csv import to_csv
from pendcli.papers.registry import keys
from pendcli.run.drift import (
    CLAIM_COLUMNS,
    EQUATION_COLUMNS,
    FORMULA_COLUMNS,
    TOLERANCES,
    Drift,
    cell_drift,
    compare_tables,
    expected_columns,
    find_drifts,
    read_committed,
    read_table,
)
from pendcli.verify.derivation_store import stores_here

if TYPE_CHECKING:
    from rich.console import Console

    from pendcli.run.reproduce import ReproduceResult

__all__ = [
    "TOLERANCES",
    "Drift",
    "compare_tables",
    "find_drifts",
    "kept_within_tolerance",
    "regenerated_tables",
    "rewrite_with",
    "run_check",
]


def _cells(row: dict[str, object], columns: tuple[str, ...]) -> dict[str, object]:
    """A row's cells for the CSV: ``from`` (a list of ids) as one space-separated cell."""
    cells = {k: row[k] for k in columns}
    cells["from"] = " ".join(str(i) for i in row["from"])  # type: ignore[attr-defined]
    cells["cause"] = row["cause"] or ""
    if "condition" in cells:
        cells["condition"] = cells["condition"] or ""
    return cells


def _claim_rows(result: ReproduceResult, key: str) -> list[dict[str, object]]:
    return [_cells(r.as_dict(), CLAIM_COLUMNS) for r in result.claims.get(key, [])]


def _formula_rows(result: ReproduceResult, key: str) -> list[dict[str, object]]:
    return [_cells(r.as_dict(), FORMULA_COLUMNS) for r in result.formulas.get(key, [])]


def _equation_rows(result: ReproduceResult, key: str) -> list[dict[str, object]]:
    out = []
    for row in result.equations.get(key, []):
        first, last = row.lines if row.lines is not None else ("", "")
        cells = {k: row.as_dict()[k] for k in EQUATION_COLUMNS if k != "lines"}
        cells["lines"] = f"{first}-{last}" if row.lines is not None else ""
        cells["dimensions"] = row.dimensions or ""
        cells["finding"] = "yes" if row.finding else ""
        cells["condition"] = row.condition or ""
        out.append(cells)
    return out


def regenerated_tables(result: ReproduceResult) -> dict[str, str]:
    """File name -> CSV text for every regenerated table of a reproduce result (the ledger's
    table only where the result holds the ledger: ``reproduce_all(..., equations=True)``)."""
    out: dict[str, str] = {}
    for key in result.papers:
        out[f"{key}-claims.csv"] = to_csv(_claim_rows(result, key), CLAIM_COLUMNS)
        if result.formulas.get(key):
            out[f"{key}-formulas.csv"] = to_csv(_formula_rows(result, key), FORMULA_COLUMNS)
        if result.equations.get(key):
            out[f"{key}-equations.csv"] = to_csv(_equation_rows(result, key), EQUATION_COLUMNS)
    return out


def run_check(
    update: bool = False, quiet: bool = False, root: Path | None = None, fmt: str = "table"
) -> int:
    """Regenerate every table; compare (or, with ``update``, rewrite). Returns the exit code.

    ``fmt``: ``table`` (the drift table), ``json`` or ``junit`` (a testcase per claim,
    formula and table), on standard output; see :mod:`pendcli.output.check_formats`.
    """
    from pendcli.base.console import console
    from pendcli.run.reproduce import reproduce_all

    folder = (root or tables_dir()).resolve() / "regenerated"
    _load_ledgers(root)
    if not update:  # a damaged committed table is named at once, not after the computation
        _read_committed_tables(folder)
    stale = _derivations(update, root)
    if stale:  # the statuses below are judged from these: stale ones would mislead
        for line in stale:
            console(stderr=True).print(line, markup=False, highlight=False)
        return 1
    result = reproduce_all(keys(), formulas=True, equations=True, quiet=quiet or fmt != "table")
    tables = regenerated_tables(result)
    out = console()
    if update:
        from pendcli.output.check_formats import changed_cells

        # no reader's lock: the folder is swapped whole, so this reads the old set or the new
        # one; a lock file only a reader made would be left behind by an interrupt
        tables = kept_within_tolerance(folder, tables)  # noise below the check stays out
        changes = changed_cells(folder, tables)
        # a set that holds these bytes already is left as it is (no swap: its files keep their
        # times, so make and a watcher see no change where there is none)
        same = _holds_already(folder, tables)
        removed = [] if same else _rewrite(folder, tables)
        if not quiet:
            _print_changes(out, changes, folder, 0 if same else len(tables))
            if removed:
                out.print(
                    f"removed {len(removed)} table(s) no longer produced: {', '.join(removed)}"
                )
        return 0
    with locked(_lock_file(folder), shared=True):
        drifts = find_drifts(folder, tables)
    _report(out, fmt, drifts, tables, folder, quiet)
    if drifts or quiet or fmt != "table":
        return 1 if drifts else 0
    n = sum(len(v) for v in result.claims.values())
    f = sum(len(v) for v in result.formulas.values())
    e = sum(len(v) for v in result.equations.values())
    again = "; the stored derivations derived again and equal"
    derived = again if stores_here(root or tables_dir()) else ""
    out.print(
        f"check passed: {len(tables)} tables, {n} claims, {f} formulas, {e} ledger rows match "
        f"tables/regenerated within tolerance{derived}"
    )
    return 0


def _derivations(update: bool, root: Path | None) -> list[str]:
    """Each ledger paper's stored derivations derived again (``tables/derivations/``): with
    ``update``, written; else how they differ from what the code derives, a line per row
    naming its reference (empty when every one agrees). Only the package's own tables have a
    store; a tables folder of one's own is derived afresh when judged."""
    from pendcli.papers.registry import PAPERS, ledger_papers, paper
    from pendcli.verify.ledger_references import store_derivations

    if not stores_here(root or tables_dir()):
        return []
    built_in = [k for k in ledger_papers() if k in PAPERS]  # an added paper has no store
    if update:
        for key in built_in:
            store_derivations(paper(key))
        return []
    return _drift_lines(built_in)


def _drift_lines(keys: list[str]) -> list[str]:
    """:func:`derivation_drift` of each paper, shared by this process and a forked worker
    (the ledger of most rows first, Lecornu's: 15 of the 22 s of CPU), in the order of
    ``keys`` whoever derived what."""
    from pendcli.base.workers import ForkedWorkers, job_count
    from pendcli.data.ledger import load_ledger

    order = sorted(keys, key=lambda key: -len(load_ledger(key).rows))
    with ForkedWorkers(job_count(None, len(order)) - 1) as pool:
        lines = pool.share(order, _drift, name=lambda key: f"the {key} derivations")
    by_key = dict(zip(order, lines, strict=True))
    return [line for key in keys for line in by_key[key]]


def _drift(key: str) -> list[str]:
    from pendcli.papers.registry import paper
    from pendcli.verify.ledger_references import derivation_drift

    return derivation_drift(paper(key))


def _read_committed_tables(folder: Path) -> None:
    """Every committed table pendcli writes, read and validated as the comparison will read
    it (:func:`read_table`): a cut, damaged or unreadable one is its one-line error now."""
    for path in sorted(folder.glob("*.csv")) if folder.is_dir() else []:
        columns = expected_columns(path.name)
        if columns is not None:
            read_table(read_committed(path), str(path), columns)


def _load_ledgers(root: Path | None) -> None:
    """Every paper's equation ledger and text, read and validated (not checked: that is
    ``pendcli equations``): a missing or empty one fails ``check`` instead of passing unseen."""
    from pendcli.data.ledger import load_ledger
    from pendcli.papers.registry import ledger_papers

    for key in ledger_papers():
        load_ledger(key, root)


def _holds_already(folder: Path, tables: dict[str, str]) -> bool:
    """Whether ``folder`` holds exactly ``tables``: the same tables, byte for byte, no other."""
    try:
        if {p.name for p in folder.glob("*.csv")} != set(tables):
            return False
        return all((folder / n).read_bytes() == t.encode("utf-8") for n, t in tables.items())
    except OSError:
        return False


def _lock_file(folder: Path) -> Path:
    return lock_file(write_through(folder, "tables/regenerated"))


def _rewrite(folder: Path, tables: dict[str, str]) -> list[str]:
    """``pendcli check --update``: the committed tables become the regenerated ones.

    The whole set is written beside the folder and swapped in at once under an exclusive
    lock (a second writer waits), so a crash leaves the old set or the new one, never a mix
    or a cut table. A file that is not a table pendcli writes (``<paper>-claims.csv``,
    ``<paper>-formulas.csv``) makes it refuse rather than delete it; a symlinked folder is
    written through. Returns the names of the tables that are no longer produced (removed by
    the swap).
    """

    def fill(tmp: Path) -> None:
        for name, text in tables.items():
            (tmp / name).write_text(text, encoding="utf-8")

    removed = sorted(p.name for p in folder.glob("*.csv") if p.name not in tables)
    replace_owned_folder(
        folder,
        fill,
        "tables/regenerated",
        known=lambda n: expected_columns(n) is not None,
        wait=True,
    )
    return removed


def kept_within_tolerance(folder: Path, tables: dict[str, str]) -> dict[str, str]:
    """The regenerated ``tables`` with each committed row kept as it is where none of its
    cells moved beyond its column's tolerance (:func:`cell_drift`). The check cannot tell such
    a row from the committed one; rewriting it would only record the last bits of this CPU's
    BLAS and SIMD kernels (another CPU moves an observed order by ~1e-9). A row that moved, a
    new row and a table that cannot be read are written as regenerated, a dropped row goes."""
    out: dict[str, str] = {}
    for name, text in tables.items():
        try:
            columns, now = read_table(text, f"regenerated {name}", expected_columns(name))
            _, then = read_table((folder / name).read_text(encoding="utf-8"), name, columns)
        except (OSError, UnicodeDecodeError, PendcliError):
            out[name] = text
            continue
        rows = [
            then[cid] if cid in then and _unmoved(name, cid, columns, then, now) else now[cid]
            for cid in now
        ]
        out[name] = to_csv(list(rows), columns)
    return out


def _unmoved(
    name: str,
    cid: str,
    columns: tuple[str, ...],
    then: dict[str, dict[str, str]],
    now: dict[str, dict[str, str]],
) -> bool:
    return all(cell_drift(name, cid, c, then[cid], now[cid]) is None for c in columns[1:])


def rewrite_with(
    tables: dict[str, str],
    others: dict[Path, str],
    root: Path | None = None,
    unchanged: dict[Path, str | None] | None = None,
) -> list[str]:
    """``make regen``: the committed tables and ``others`` (the README) rewritten as one set
    (:func:`pendcli.base.files.write_set`: all written first, then renamed in one short loop
    that Ctrl-C or TERM cannot split), under the tables' lock. Returns the tables removed.
    Nothing is written if a table changed after it was read here, or a file of ``unchanged``
    (path -> digest of what the caller read) since the caller read it."""
    from pendcli.base.files import file_digest, write_set
    from pendcli.base.owned_folders import check_owned

    folder = write_through((root or tables_dir()).resolve() / "regenerated", "tables/regenerated")
    folder.mkdir(parents=True, exist_ok=True)
    with locked(_lock_file(folder)):
        check_owned(folder, "tables/regenerated", lambda n: expected_columns(n) is not None)
        names = {*tables, *(p.name for p in folder.glob("*.csv"))}  # as kept_within_tolerance reads
        read = {folder / n: file_digest(folder / n) for n in names} | (unchanged or {})
        tables = kept_within_tolerance(folder, tables)
        removed = sorted(p.name for p in folder.glob("*.csv") if p.name not in tables)
        changes: dict[Path, str | bytes | None] = {folder / n: t for n, t in tables.items()}
        changes.update({folder / name: None for name in removed})
        changes.update(others)
        write_set(changes, read)
    return removed


def _report(
    out: Console, fmt: str, drifts: list[Drift], tables: dict[str, str], folder: Path, quiet: bool
) -> None:
    """The drifts in ``fmt`` on standard output; under GitHub Actions also one annotation per
    drift (on stderr when stdout carries a JSON or JUnit document)."""
    import sys

    from pendcli.output import check_formats as check_report

    if fmt == "json":
        sys.stdout.write(check_report.to_json(drifts, tables))
    elif fmt == "junit":
        sys.stdout.write(check_report.to_junit(drifts, tables))
    elif drifts:
        _print_drifts(out, drifts)
    if drifts and check_report.in_github_actions():
        stream = sys.stdout if fmt == "table" else sys.stderr
        for line in check_report.github_annotations(drifts, folder):
            print(line, file=stream)


def _by_table(out: Console, rows: list[dict[str, str]], keys: tuple[str, ...], title: str) -> None:
    """One table per regenerated table (its name as title): the columns then fit a terminal."""
    from pendcli.output.table import to_rich_table

    out.print(title)
    for name in dict.fromkeys(r["table"] for r in rows):
        mine = [r for r in rows if r["table"] == name]
        cols = [Column(k, "was" if k == "committed" else k) for k in keys]
        out.print(to_rich_table(mine, cols, title=name))


def _print_drifts(out: Console, drifts: list[Drift]) -> None:
    from pendcli.output.check_formats import drift_rows

    keys = ("id", "column", "published", "committed", "now", "difference", "tolerance")
    _by_table(out, drift_rows(drifts), keys, f"check FAILED: {len(drifts)} drift(s)")
    out.print("If the change is intended, run `pendcli check --update` (make regen) and commit.")


def _print_changes(out: Console, changes: list[Drift], folder: Path, count: int) -> None:
    """`check --update`: every value it rewrote ("noise": within tolerance), then the count."""
    from pendcli.output.check_formats import drift_rows

    if changes:
        keys = ("id", "column", "committed", "now", "difference")
        _by_table(out, drift_rows(changes), keys, f"check --update: {len(changes)} change(s)")
    else:
        out.print("no value changed")
    if count:
        out.print(f"rewrote {count} tables in {folder}")
    else:
        out.print(f"no table rewritten: {folder} holds these bytes already")
