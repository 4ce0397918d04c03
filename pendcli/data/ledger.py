"""The equation ledger: every numbered equation and stated result of a paper, accounted for.

A ledger is ``tables/equations/<paper>.toml``: one ``[[equation]]`` row per equation label
printed in the paper's text (``tables/papers/<paper>.txt``) and per stated result, with a
status (``holds``, ``fails``, ``misprint``, ``definition``, ``not-checkable``) and, for the
first three, the ``kind`` of check that decides it (:mod:`pendcli.verify.check_kinds`) and the
``reference`` it is judged against (its builder in the paper's table, ``Paper.references``).
This module knows nothing about pendulums: it reads and validates ledgers and extracts the
labels a text prints; :mod:`pendcli.verify.ledger_evaluation` judges each row's printed form
by its kind and verifies that the status computed is the one the row records.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import fields
from pathlib import Path
from typing import Any

from pendcli.base.errors import PendcliError
from pendcli.base.recent import Recent
from pendcli.data.ledger_conditions import (
    check_listed,
    parse_assumptions,
    parse_condition,
)
from pendcli.data.ledger_labels import LABEL_FORMAT, label_offsets, labels_in_text
from pendcli.data.ledger_readings import Reading, parse_readings, readings_of
from pendcli.data.ledger_rows import Ledger, LedgerRow, as_strings
from pendcli.data.rows import EquationRow
from pendcli.data.text_blocks import validate_span
from pendcli.data.vocabulary import CHECKED_STATUSES, STATUSES
from pendcli.data.vocabulary import EquationStatus as Status
from pendcli.verify.check_kinds import PARAMETER_KEYS, parse_parameters
from pendcli.verify.ledger_blame import (
    BLAME_KEYS,
    parse_blame,
    validate_blame,
)
from pendcli.verify.ledger_companions import parse_companions
from pendcli.verify.ledger_formulas import (
    FORMULA_FIELDS,
    validate_formulas,
    validate_scopes,
    validate_symbols,
)
from pendcli.verify.ledger_step import STEP_KEYS, parse_step, validate_step

__all__ = [
    "CHECKED_STATUSES",
    "ROW_KEYS",
    "Ledger",
    "LedgerRow",
    "label_offsets",
    "labels_in_text",
    "load_ledger",
    "parse_ledger",
]

LEDGER_KEYS = ("paper", "text")
REQUIRED_KEYS = ("id", "equation", "section", "statement", "status")
# Where the row is printed (its lines, and the words of them it rests on), what it restates,
# and the printed form as a formula.
TEXT_KEYS = ("lines", "quote", "restates", "printed", "reading_formula", "corrected_formula",
             "reference")  # fmt: skip
# A checked row's kind of check (verify/check_kinds) and the formula checks (formulas.py) that
# measure the order of its approximation against a fuller model.
CHECK_KEYS = ("kind", "measured")
# The later use that decides a slip's blame and what a row carries (verify/ledger_blame), the
# assumption its verdict turns on (data/ledger_conditions), its own slip beside a carried one
# (verify/ledger_step).
BLAME_STEP_KEYS = (*BLAME_KEYS, "condition", *STEP_KEYS)
# (and the kind's parameters beside its reference: verify/check_kinds)
ROW_KEYS = (*REQUIRED_KEYS, *CHECK_KEYS, *PARAMETER_KEYS, "reading", "corrected", "wrong_term",
            "note", *TEXT_KEYS, *BLAME_STEP_KEYS)  # fmt: skip
# Keys whose value is not a plain string, each read by its own parser.
_SHAPED_KEYS = ("lines", "used_at", "restates", "step_symbols")
# Keys that take a string or a list of strings, each printed verbatim within the row's lines
# (``used``: within the lines of ``used_at``).
PRINTED_KEYS = ("wrong_term", "quote", "used")
LIST_KEYS = (*PRINTED_KEYS, "measured")
# The fields of an output row (`reproduce --format json` under "equations").
OUTPUT_KEYS = tuple(f.name for f in fields(EquationRow))

_ID = re.compile(r"^[a-z]+\.(?:eq|result)\.[A-Za-z0-9_'-]+(?:\.[a-z0-9-]+)?$")


def _tables_dir() -> Path:
    from pendcli.data.tables import tables_dir

    return tables_dir()


def ledger_path(paper: str, root: Path | None = None) -> Path:
    return (root or _tables_dir()) / "equations" / f"{paper}.toml"


# Each ledger parsed and validated once per content (its TOML and paper text), whichever step
# asks (20 loads of 3 ledgers in a cold `equations`); a load that fails is not kept.
_LOADED = Recent(16)


def load_ledger(paper: str, root: Path | None = None) -> Ledger:
    """Read and strictly validate ``tables/equations/<paper>.toml`` and the text it names
    (missing, empty, not a file or not UTF-8: an error, never an empty ledger)."""
    from pendcli.data.tables import parse_toml, read_table_text

    path = ledger_path(paper, root)
    folder = root or _tables_dir()
    source = read_table_text(path, "equation ledger")
    key = (paper, path, folder, source)
    kept: tuple[Ledger, str] | None = _LOADED.get(key)
    if kept is not None and _same_text(kept[0], folder, kept[1]):
        return kept[0]
    ledger = parse_ledger(parse_toml(source, path, "equation ledger"), paper, path, folder)
    _LOADED.put(key, (ledger, read_table_text(ledger.text, "paper text")))
    return ledger


def _same_text(ledger: Ledger, root: Path, text: str) -> bool:
    """The ledger's paper text is still inside the tables folder and reads ``text``."""
    from pendcli.data.tables import inside_tables, read_table_text

    try:
        inside_tables(ledger.text, root, f"{ledger.path}: [ledger] text")
        return ledger.text.is_file() and read_table_text(ledger.text, "paper text") == text
    except PendcliError:
        return False  # loaded again, to give the error the first load gives


def parse_ledger(
    raw: dict[str, Any], paper: str, path: Path, root: Path, partial: bool = False
) -> Ledger:
    """Validate a parsed ledger: unknown keys, missing fields and bad values are errors.
    ``partial``: the rows are a selection of the ledger (one row's formulas read alone), so
    a row they name but do not hold (restated, carried, an assumption's) is not missing."""
    top = ("ledger", "equation", "symbols", "scope", "reading", "assumption", "companion")
    _refuse_unknown(f"{path}", "top-level key(s)", raw, top)
    header = raw.get("ledger")
    if not isinstance(header, dict) or header.get("paper") != paper:
        raise PendcliError(f"{path}: [ledger] must be a table with paper = {paper!r}")
    _refuse_unknown(f"{path}: [ledger]", "key(s)", header, LEDGER_KEYS)
    text = header.get("text")
    if not isinstance(text, str) or not text.startswith("tables/"):
        raise PendcliError(f"{path}: [ledger] text must name a file under tables/, got {text!r}")
    entries = raw.get("equation")
    if not isinstance(entries, list) or not entries:
        raise PendcliError(f"{path}: no [[equation]] rows")
    keys = [repr(entry) for entry in entries]
    rows: list[LedgerRow] = []
    seen: set[str] = set()
    for index, (entry, key) in enumerate(zip(entries, keys, strict=True)):
        row = _row_once(path, index, entry, paper, key)
        if row.id in seen:
            raise PendcliError(f"{path}: {row.id}: duplicate id")
        seen.add(row.id)
        rows.append(row)
    text_path = _text_inside(path, text, root)
    lines = _text_lines(text_path)
    context = _context(paper, raw, lines)
    done = {i: r for i, k in enumerate(keys) if (r := _CHECKED_ROWS.get((context, k)))}
    _check_text_fields(path, rows, lines, text_path.name, partial, done)
    symbols = validate_symbols(path, raw.get("symbols"))
    scopes = validate_scopes(path, raw.get("scope"), dict(symbols))
    readings = parse_readings(path, raw.get("reading"), lines)
    rows = [done.get(i) or _with_readings(row, readings, lines) for i, row in enumerate(rows)]
    assumptions = parse_assumptions(path, raw.get("assumption"), None if partial else seen)
    named = {a.id: a for a in assumptions}
    for row in rows:
        parse_condition(f"{path}: {row.id}", row, named)
    check_listed(path, rows, assumptions)
    parse_companions(f"{path}", raw.get("companion"))  # its shape; its match: when judged
    ledger = Ledger(paper, text_path, path, tuple(rows), symbols, scopes, readings, assumptions)
    validate_formulas(path, [r for i, r in enumerate(rows) if i not in done], ledger.symbols_for)
    if not partial:
        validate_step(path, ledger)
    for index, row in enumerate(rows):  # the ledger is valid: each new row is kept
        if index not in done:
            _CHECKED_ROWS.put((context, keys[index]), row)
    return ledger


# Each [[equation]] entry validated once per content, whichever ledger holds it: a ledger
# edited in one entry (a mutation test's edit) validates that entry alone again. _ROWS: the
# row its entry alone gives ((paper, repr of the entry) -> LedgerRow; the path and index only
# name an error). _CHECKED_ROWS: the row with its readings applied, whose lines, quotes and
# formulas passed in a context (paper, [symbols], [[scope]], [[reading]] and the paper's text:
# all the checks of one row read) -> LedgerRow; kept only once the whole ledger is valid.
# What concerns several rows (duplicates, restatements, blame, assumptions, steps) is checked
# on every load. A failure is never kept, so each names its own ledger.
_ROWS = Recent(4096)
_CHECKED_ROWS = Recent(4096)


def _row_once(path: Path, index: int, entry: object, paper: str, key: str) -> LedgerRow:
    row: LedgerRow | None = _ROWS.get((paper, type(entry).__name__, key))
    if row is None:
        row = _row(path, index, entry, paper)
        _ROWS.put((paper, type(entry).__name__, key), row)
    return row


def _context(paper: str, raw: dict[str, Any], lines: list[str] | None) -> str:
    """What a row's own checks read besides the row: one digest."""
    import hashlib

    parts = [paper, *(repr(raw.get(k)) for k in ("symbols", "scope", "reading"))]
    parts.append(repr(None) if lines is None else "\n".join(lines))
    return hashlib.sha256("\0".join(parts).encode()).hexdigest()


def _with_readings(
    row: LedgerRow, readings: tuple[Reading, ...], lines: list[str] | None
) -> LedgerRow:
    from dataclasses import replace

    formulas = (getattr(row, f) for f in (*FORMULA_FIELDS, "step_formula"))
    applied = readings_of(readings, row.lines, formulas, lines)
    return replace(row, readings=applied) if applied else row


def _text_inside(path: Path, text: str, root: Path) -> Path:
    """``[ledger] text`` under the tables folder ``root``; one that leads out is refused."""
    from pendcli.data.tables import inside_tables

    return inside_tables(
        root / text.removeprefix("tables/"), root, f"{path}: [ledger] text = {text!r}"
    )


def _refuse_unknown(where: str, what: str, entry: dict[str, Any], valid: Iterable[str]) -> None:
    unknown = sorted(set(entry) - set(valid))
    if unknown:
        raise PendcliError(
            f"{where}: unknown {what} {', '.join(map(repr, unknown))}; valid: {', '.join(valid)}"
        )


def _row(path: Path, index: int, entry: object, paper: str) -> LedgerRow:
    if not isinstance(entry, dict):
        raise PendcliError(f"{path}: [[equation]] #{index + 1} is not a table")
    where = f"{path}: {entry.get('id', f'[[equation]] #{index + 1}')}"
    _refuse_unknown(where, "key(s)", entry, ROW_KEYS)
    printed: dict[str, object] = {k: _strings(where, k, entry[k]) for k in LIST_KEYS if k in entry}
    if "measured" in printed:
        printed["measured"] = as_strings(printed["measured"])  # type: ignore[arg-type]
    printed.update(parse_blame(where, entry))
    printed.update(parse_step(where, entry))
    printed["parameters"] = parse_parameters(where, entry.get("kind"), entry)
    entry = {k: v for k, v in entry.items() if k not in PARAMETER_KEYS}
    for key in (k for k in ROW_KEYS if k not in _SHAPED_KEYS + LIST_KEYS + PARAMETER_KEYS):
        value = entry.get(key)
        if key in REQUIRED_KEYS and value is None:
            raise PendcliError(f"{where}: missing {key!r}")
        blank = not isinstance(value, str) or not value.strip()
        if value is not None and blank and not (key == "equation" and value == ""):
            raise PendcliError(f"{where}: {key!r} must be a non-empty string")
    if entry["status"] not in STATUSES:
        raise PendcliError(
            f"{where}: unknown status {entry['status']!r}; valid: {', '.join(STATUSES)}"
        )
    lines = entry.get("lines")
    span = None if lines is None else validate_span(where, lines)
    status = Status(entry["status"])
    row = LedgerRow(paper=paper, **{**entry, **printed, "lines": span, "status": status})
    _check_identity(where, row)
    _check_status_fields(where, row)
    return row


def _strings(where: str, key: str, value: object) -> str | tuple[str, ...]:
    """A ``wrong_term`` or ``quote``: a non-empty string, or a non-empty list of them."""
    items = value if isinstance(value, list) else [value]
    if not items or not all(isinstance(v, str) and v.strip() for v in items):
        raise PendcliError(f"{where}: {key!r} must be a non-empty string or list of strings")
    return value if isinstance(value, str) else tuple(str(v) for v in items)


def _text_lines(text: Path) -> list[str] | None:
    """The paper text's lines, None when it is not there (load_ledger says so)."""
    from pendcli.data.tables import read_table_text

    # not UTF-8 or empty: the text's own one-line error
    return read_table_text(text, "paper text").splitlines() if text.exists() else None


def _check_text_fields(
    path: Path,
    rows: list[LedgerRow],
    lines: list[str] | None,
    text: str,
    partial: bool = False,
    done: Mapping[int, LedgerRow] | None = None,
) -> None:
    """``lines`` within the paper's text ``lines`` (when the text is there to count), each
    wrong term and quote printed verbatim within them (but for the rows ``done``: found so in
    this very text), ``restates`` naming another row and the later use of a slip
    (verify/ledger_blame)."""
    for index, row in enumerate(rows):
        if lines is None or (done is not None and index in done):
            continue
        if row.lines is not None:
            validate_span(f"{path}: {row.id}", list(row.lines), len(lines))
        _check_printed_within_lines(f"{path}: {row.id}", row, lines, text)
    validate_blame(path, rows, lines, partial)


def _check_printed_within_lines(where: str, row: LedgerRow, lines: list[str], text: str) -> None:
    """Each wrong term and quote occurs, exactly as transcribed, within the row's lines."""
    for key, items in (("wrong_term", row.wrong_terms), ("quote", row.quotes)):
        if items and row.lines is None:
            raise PendcliError(f"{where}: {key!r} needs 'lines' (where it is printed)")
        if row.lines is None:
            continue
        first, last = row.lines
        span = "\n".join(lines[first - 1 : last])
        for item in items:
            if item not in span:
                raise PendcliError(
                    f"{where}: {key} {item!r} is not in its lines [{first}, {last}] of {text}"
                )


def _check_identity(where: str, row: LedgerRow) -> None:
    if not _ID.match(row.id) or not row.id.startswith(f"{row.paper}."):
        raise PendcliError(
            f"{where}: id must read '{row.paper}.eq.<label>[.<section>]' or "
            f"'{row.paper}.result.<slug>'"
        )
    is_result = row.id.startswith(f"{row.paper}.result.")
    if is_result and row.equation:
        raise PendcliError(f'{where}: a stated result has equation = ""')
    if not is_result:
        if not LABEL_FORMAT.match(row.equation):
            raise PendcliError(f'{where}: equation must be a label as printed, e.g. "(4)"')
        stem = row.id.split(".")[2]
        if stem != row.equation[1:-1]:
            raise PendcliError(f"{where}: id does not match the label {row.equation}")


def _check_status_fields(where: str, row: LedgerRow) -> None:
    from pendcli.verify.check_kinds import KINDS

    checked = row.status in CHECKED_STATUSES
    for key in ("kind", "reference"):
        if checked and getattr(row, key) is None:
            raise PendcliError(f"{where}: status {row.status.value!r} needs a {key}")
    for key in (*CHECK_KEYS, "reference"):
        if not checked and getattr(row, key) is not None:
            raise PendcliError(f"{where}: status {row.status.value!r} takes no {key}")
    if row.kind is not None and row.kind not in KINDS:
        raise PendcliError(f"{where}: unknown kind {row.kind!r}; valid: {', '.join(KINDS)}")
    if not checked and row.note is None:
        raise PendcliError(f"{where}: status {row.status.value!r} needs a note (what or why)")
    if (row.reading is not None) != (row.status is Status.MISPRINT):
        raise PendcliError(f"{where}: 'reading' is required for, and only for, misprint")
    if (row.corrected is not None) != (row.status is Status.FAILS):
        raise PendcliError(f"{where}: 'corrected' is required for, and only for, fails")
