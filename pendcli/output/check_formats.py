"""What `pendcli check` tells a person or a CI system: the drift table, JSON, JUnit XML,
GitHub annotations, and the value-by-value list of what `check --update` rewrote.

Pure functions over :class:`~pendcli.run.regression.Drift` and the regenerated tables; the
comparison itself (and its tolerances, :data:`~pendcli.run.regression.TOLERANCES`) lives in
:mod:`pendcli.run.regression`.
"""

from __future__ import annotations

import csv
import io
import json
import os
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from xml.sax.saxutils import quoteattr

from pendcli.base.errors import PendcliError
from pendcli.run.drift import TOLERANCES, Drift, cell_drift, expected_columns, read_table

__all__ = [
    "changed_cells",
    "drift_rows",
    "github_annotations",
    "to_json",
    "to_junit",
    "tolerance_text",
]


def tolerance_text(column: str) -> str:
    """``"rel 1e-09"``, ``"abs 0.05"`` or ``"same text"``: how far ``column`` may move."""
    kind, tol = TOLERANCES.get(column, ("same", 0.0))
    if kind == "same":
        return "same text"
    return f"{kind} {tol:g}"


def drift_rows(drifts: Iterable[Drift]) -> list[dict[str, str]]:
    """One plain row per drift, with the tolerance the moved column is held to."""
    return [
        {
            "table": d.table,
            "id": d.id,
            "column": d.column,
            "published": d.published,
            "committed": d.committed,
            "now": d.now,
            "difference": d.difference,
            "tolerance": "" if d.column.startswith("(") else tolerance_text(d.column),
        }
        for d in drifts
    ]


def row_ids(tables: Mapping[str, str]) -> dict[str, list[str]]:
    """Table name -> the ids of its regenerated rows, in order (one JUnit testcase each)."""
    out: dict[str, list[str]] = {}
    for name, text in tables.items():
        _, rows = read_table(text, f"regenerated {name}", expected_columns(name))
        out[name] = list(rows)
    return out


def to_json(drifts: Sequence[Drift], tables: Mapping[str, str]) -> str:
    """The check as one JSON document: passed, counts, tolerances, every drift."""
    ids = row_ids(tables)
    doc = {
        "passed": not drifts,
        "tables": len(tables),
        "rows": sum(len(v) for v in ids.values()),
        "tolerances": {
            col: {"kind": kind, "tolerance": tol} for col, (kind, tol) in TOLERANCES.items()
        },
        "drifts": drift_rows(drifts),
    }
    return json.dumps(doc, indent=2, ensure_ascii=False) + "\n"


def _failure(drifts: Sequence[Drift]) -> str:
    lines = [_describe(d) for d in drifts]
    message = quoteattr(lines[0] if len(lines) == 1 else f"{len(lines)} drifts: {lines[0]} ...")
    body = "\n".join(lines).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return f'      <failure message={message} type="drift">{body}</failure>\n'


def _describe(d: Drift) -> str:
    """One drift in one line: ``recomputed 5.13 -> 5.14 (+1e-2; tolerance rel 1e-09)``."""
    if d.column.startswith("("):
        change = f"{d.committed} -> {d.now}"
    else:
        change = f"{d.column} {d.committed!r} -> {d.now!r}"
    extra = [x for x in (d.difference, _tol(d)) if x]
    return f"{d.table} {d.id}: {change}" + (f" ({'; '.join(extra)})" if extra else "")


def _tol(d: Drift) -> str:
    return "" if d.column.startswith("(") else f"tolerance {tolerance_text(d.column)}"


def to_junit(drifts: Sequence[Drift], tables: Mapping[str, str]) -> str:
    """JUnit XML: a suite per table, a testcase per claim or formula and one for the table
    itself (header, presence), so a CI system lists each drift on its own row."""
    ids = row_ids(tables)
    by_case: dict[tuple[str, str], list[Drift]] = {}
    for d in drifts:
        by_case.setdefault((d.table, d.id), []).append(d)
    names = sorted({*ids, *(d.table for d in drifts)})
    suites = []
    for name in names:
        cases = ["(table)", *ids.get(name, [])]
        cases += [cid for (t, cid) in by_case if t == name and cid not in cases]
        failed = sum((name, cid) in by_case for cid in cases)
        suite = [
            f'  <testsuite name={quoteattr(name)} tests="{len(cases)}" '
            f'failures="{failed}" errors="0" skipped="0">\n'
        ]
        for cid in cases:
            head = f"    <testcase classname={quoteattr(name)} name={quoteattr(cid)}"
            found = by_case.get((name, cid))
            suite.append(f"{head}>\n{_failure(found)}    </testcase>\n" if found else f"{head}/>\n")
        suite.append("  </testsuite>\n")
        suites.append("".join(suite))
    total = sum(1 + len(ids.get(n, [])) for n in names)
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<testsuites name="pendcli check" tests="{total}" failures="{len(by_case)}">\n'
        + "".join(suites)
        + "</testsuites>\n"
    )


def _escape_data(text: str) -> str:
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _escape_property(text: str) -> str:
    return _escape_data(text).replace(":", "%3A").replace(",", "%2C")


def _line_numbers(path: Path) -> dict[str, int]:
    """id -> line of its row in a committed CSV ({} when it cannot be read)."""
    try:
        reader = csv.reader(io.StringIO(path.read_text(encoding="utf-8"), newline=""))
        return {fields[0]: reader.line_num for fields in reader if fields}
    except (OSError, UnicodeDecodeError, csv.Error):
        return {}


def github_annotations(drifts: Sequence[Drift], folder: Path) -> list[str]:
    """``::error file=...,line=...::`` workflow commands, one per drift, pointing at the row
    of the committed table (GitHub Actions shows them on the pull request)."""
    lines: dict[str, dict[str, int]] = {}
    out = []
    for d in drifts:
        path = folder / d.table
        if d.table not in lines:
            lines[d.table] = _line_numbers(path)
        try:
            shown = str(path.relative_to(Path.cwd()))
        except ValueError:
            shown = str(path)
        where = f"file={_escape_property(shown)}"
        line = lines[d.table].get(d.id)
        if line is not None:
            where += f",line={line}"
        title = _escape_property(f"pendcli check: {d.id} {d.column}")
        out.append(f"::error {where},title={title}::{_escape_data(_describe(d))}")
    return out


def in_github_actions() -> bool:
    return os.environ.get("GITHUB_ACTIONS") == "true"


def changed_cells(folder: Path, tables: Mapping[str, str]) -> list[Drift]:
    """What `check --update` changes, value by value: every cell whose text moves (beyond
    its tolerance or within it, marked so), every row and table added or removed."""
    committed = {p.name for p in folder.glob("*.csv")} if folder.is_dir() else set()
    changes: list[Drift] = []
    for name in sorted(committed | set(tables)):
        if name not in tables:
            changes.append(Drift(name, "(table)", "(file)", "", "committed", "removed", ""))
            continue
        if name not in committed:
            changes.append(Drift(name, "(table)", "(file)", "", "missing", "written", ""))
            continue
        try:
            changes += _table_changes(name, (folder / name).read_text("utf-8"), tables[name])
        except (PendcliError, OSError, UnicodeDecodeError) as exc:
            reason = str(exc)
            changes.append(Drift(name, "(table)", "(file)", "", "unreadable", "rewritten", reason))
    return changes


def _table_changes(name: str, committed_text: str, now_text: str) -> list[Drift]:
    columns, now = read_table(now_text, f"regenerated {name}", expected_columns(name))
    _, then = read_table(committed_text, name, columns)
    changes = [
        Drift(name, cid, "(row)", then[cid].get("published", ""), "present", "gone", "")
        for cid in then
        if cid not in now
    ]
    changes += [
        Drift(name, cid, "(row)", now[cid].get("published", ""), "absent", "new", "")
        for cid in now
        if cid not in then
    ]
    for cid in (c for c in now if c in then):
        for col in columns[1:]:
            if then[cid][col] == now[cid][col]:
                continue
            drift = cell_drift(name, cid, col, then[cid], now[cid])
            a, b = then[cid][col], now[cid][col]
            changes.append(
                drift or Drift(name, cid, col, now[cid].get("published", ""), a, b, "noise")
            )
    return changes
