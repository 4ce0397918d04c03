"""The equation ledger: every numbered equation and stated result of a paper, accounted for.

A ledger is ``tables/equations/<paper>.toml``: one ``[[equation]]`` row per equation label
printed in the paper's text (``tables/papers/<paper>.txt``) and per stated result, with a
status (``holds``, ``fails``, ``misprint``, ``definition``, ``not-checkable``) and, for the
first three, the ``kind`` of check that decides it (:mod:`pendcli.core.check_kinds`) and the
``reference`` it is judged against (its builder in the paper's table, ``Paper.references``).
This module knows nothing about pendulums: it reads and validates ledgers, extracts the
labels a text prints, judges each row's printed form by its kind and verifies that the
status computed is the one the row records. A disagreement is an error in the
ledger, reported, never re-labelled.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, fields
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.core.errors import PendcliError
from pendcli.core.ledger_formulas import (
    printed_status,
    row_dimensions,
    row_formula,
    validate_formulas,
    validate_scopes,
    validate_symbols,
)
from pendcli.core.rows import NO_STATUS, EquationRow
from pendcli.core.text_blocks import Span, validate_span
from pendcli.core.vocabulary import CHECKED_STATUSES, STATUSES
from pendcli.core.vocabulary import EquationStatus as Status

if TYPE_CHECKING:
    from pendcli.core.claims import FormulaRow
    from pendcli.core.dimensions import DimensionCheck
    from pendcli.core.paper import Paper
    from pendcli.core.printed_check import Reference

__all__ = [
    "CHECKED_STATUSES",
    "ROW_KEYS",
    "Evaluated",
    "Ledger",
    "LedgerRow",
    "Measured",
    "References",
    "cited_references",
    "coverage",
    "equation_rows",
    "evaluate",
    "label_offsets",
    "labels_in_text",
    "load_ledger",
    "measured",
    "parse_ledger",
    "printed_problem",
    "reference_table",
    "row_printed_status",
]

LEDGER_KEYS = ("paper", "text")
REQUIRED_KEYS = ("id", "equation", "section", "statement", "status")
# Where the row is printed (its lines, and the words of them it rests on), what it restates,
# and the printed form as a formula.
TEXT_KEYS = ("lines", "quote", "restates", "printed", "reading_formula", "corrected_formula",
             "reference")  # fmt: skip
# A checked row's kind of check (core/check_kinds) and the formula checks (formulas.py) that
# measure the order of its approximation against a fuller model.
CHECK_KEYS = ("kind", "measured")
ROW_KEYS = (*REQUIRED_KEYS, *CHECK_KEYS, "reading", "corrected", "wrong_term", "note", *TEXT_KEYS)
# Keys that take a string or a list of strings, each printed verbatim within the row's lines.
PRINTED_KEYS = ("wrong_term", "quote")
LIST_KEYS = (*PRINTED_KEYS, "measured")
# The fields of an output row (`reproduce --format json` under "equations").
OUTPUT_KEYS = tuple(f.name for f in fields(EquationRow))

# An equation label: an arabic number (with an optional letter and primes: (42'), (17a)),
# a roman numeral (I)-(XXXIX), or a single lower-case letter ((p), (q)); an OCR prime may be
# a typewriter quote or a TeX ^{\prime}.
_LABEL = r"(?:\d{1,3}[a-z]?|[IVX]{1,6}|[a-z])(?:'|’|\^\{?\\prime\}?)*"
_LABEL_TOKEN = re.compile(rf"\(({_LABEL})\)")
_LABEL_FORMAT = re.compile(rf"^\({_LABEL}\)$")
# Where a label sits in display mathematics: at its start (after $$, a line break \\ or a
# \begin{...}), in a \tag{...}, or at its end after a \quad (a label "in the margin").
_OPENERS = r"(?:\$\$|\\\\|\\begin\{[a-zA-Z*]+\}(?:\{[^}]*\})?)"
_AT_START = re.compile(rf"{_OPENERS}\s*\(({_LABEL})\)(?=\s|\\|\{{|$)")
_TAGGED = re.compile(rf"\\tag\*?\{{\(?({_LABEL})\)?\}}")
_AT_END = re.compile(rf"\\q?quad\s*\(({_LABEL})\)\s*(?:[.,;]\s*)?(?=\$\$|\\\\|\\end\{{)")
_DISPLAY = re.compile(r"\$\$(.*?)\$\$", re.DOTALL)
_ID = re.compile(r"^[a-z]+\.(?:eq|result)\.[A-Za-z0-9_'-]+(?:\.[a-z0-9-]+)?$")


def _normalise(label: str) -> str:
    return re.sub(r"’|\^\{?\\prime\}?", "'", label)


def labels_in_text(text: str) -> list[str]:
    """Every equation label the text prints, as ``"(41)"``, in order, repeats kept.

    Only labels placed in display mathematics count (at the start of a formula line, in a
    ``\\tag``, or in the margin at its end): a reference in the prose ("la formule (5)"), a
    year, a page number or a citation is never a label.
    """
    return [label for _, label in label_offsets(text)]


def label_offsets(text: str) -> list[tuple[int, str]]:
    """(character offset, label) of every label :func:`labels_in_text` finds, in order."""
    found: list[tuple[int, str]] = []
    for display in _DISPLAY.finditer(text):
        body = "$$" + display.group(1) + "$$"
        offset = display.start()
        for pattern in (_AT_START, _TAGGED, _AT_END):
            for match in pattern.finditer(body):
                found.append((offset + match.start(1), f"({_normalise(match.group(1))})"))
    return sorted(set(found))


@dataclass(frozen=True)
class LedgerRow:
    """One equation or stated result, as the ledger records it."""

    id: str
    paper: str
    equation: str
    section: str
    statement: str
    status: Status
    kind: str | None = None
    # ids of the paper's formula checks whose observed order the row shows
    measured: tuple[str, ...] | None = None
    reading: str | None = None
    corrected: str | None = None
    # the wrong term(s) as the OCR text prints them (marked in the HTML)
    wrong_term: str | tuple[str, ...] | None = None
    note: str | None = None
    lines: Span | None = None
    # the words of the text the row rests on (a sentence, a phrase), verbatim from its lines
    quote: str | tuple[str, ...] | None = None
    restates: str | None = None
    printed: str | None = None
    reading_formula: str | None = None
    corrected_formula: str | None = None
    reference: str | None = None

    @property
    def wrong_terms(self) -> tuple[str, ...]:
        return _as_strings(self.wrong_term)

    @property
    def quotes(self) -> tuple[str, ...]:
        return _as_strings(self.quote)


def _as_strings(value: str | tuple[str, ...] | None) -> tuple[str, ...]:
    return (value,) if isinstance(value, str) else value or ()


@dataclass(frozen=True)
class Ledger:
    paper: str
    text: Path
    path: Path
    rows: tuple[LedgerRow, ...]
    # [symbols]: (name, dimension) pairs the formulas of the rows are written in.
    symbols: tuple[tuple[str, str], ...] = ()
    # [[scope]]: a stretch of the text where some letters mean something else (Lecornu's u is
    # a length in § I and a pure number from (32) on): (first, last line), its (name, dim).
    scopes: tuple[tuple[tuple[int, int], tuple[tuple[str, str], ...]], ...] = ()

    def symbols_for(self, row: LedgerRow) -> dict[str, str]:
        """The symbols ``row``'s formulas are written in: [symbols], then the names of the
        scope whose lines hold the row's first line, which take precedence."""
        table = dict(self.symbols)
        first = row.lines[0] if row.lines is not None else 0
        for (low, high), names in self.scopes:
            if low <= first <= high:
                table.update(names)
        return table

    def labels(self) -> Counter[str]:
        """How many rows each printed label has (stated results, with no label, excluded)."""
        return Counter(r.equation for r in self.rows if r.equation)


def _tables_dir() -> Path:
    from pendcli.core.tables import tables_dir

    return tables_dir()


def ledger_path(paper: str, root: Path | None = None) -> Path:
    return (root or _tables_dir()) / "equations" / f"{paper}.toml"


def load_ledger(paper: str, root: Path | None = None) -> Ledger:
    """Read and strictly validate ``tables/equations/<paper>.toml`` and the text it names
    (missing, empty, not a file or not UTF-8: an error, never an empty ledger)."""
    from pendcli.core.tables import read_table_text, read_toml

    path = ledger_path(paper, root)
    ledger = parse_ledger(read_toml(path, "equation ledger"), paper, path, root or _tables_dir())
    read_table_text(ledger.text, "paper text")
    return ledger


def parse_ledger(raw: dict[str, Any], paper: str, path: Path, root: Path) -> Ledger:
    """Validate a parsed ledger: unknown keys, missing fields and bad values are errors."""
    _refuse_unknown(f"{path}", "top-level key(s)", raw, ("ledger", "equation", "symbols", "scope"))
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
    rows: list[LedgerRow] = []
    seen: set[str] = set()
    for index, entry in enumerate(entries):
        row = _row(path, index, entry, paper)
        if row.id in seen:
            raise PendcliError(f"{path}: {row.id}: duplicate id")
        seen.add(row.id)
        rows.append(row)
    text_path = _text_inside(path, text, root)
    _check_text_fields(path, rows, text_path)
    symbols = validate_symbols(path, raw.get("symbols"))
    scopes = validate_scopes(path, raw.get("scope"), dict(symbols))
    ledger = Ledger(paper, text_path, path, tuple(rows), symbols, scopes)
    validate_formulas(path, rows, ledger.symbols_for)
    return ledger


def _text_inside(path: Path, text: str, root: Path) -> Path:
    """``[ledger] text`` under the tables folder ``root``; one that leads out is refused."""
    from pendcli.core.tables import inside_tables

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
    printed = {k: _strings(where, k, entry[k]) for k in LIST_KEYS if k in entry}
    if "measured" in printed:
        printed["measured"] = tuple(_as_strings(printed["measured"]))
    for key in (k for k in ROW_KEYS if k != "lines" and k not in LIST_KEYS):
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


def _check_text_fields(path: Path, rows: list[LedgerRow], text: Path) -> None:
    """``lines`` within the paper's text (when the text is there to count), each wrong term
    and quote printed verbatim within them, and ``restates`` naming another row."""
    from pendcli.core.tables import read_table_text

    ids = {r.id for r in rows}
    # not UTF-8 or empty: the text's own one-line error; missing: load_ledger says so
    lines = read_table_text(text, "paper text").splitlines() if text.exists() else None
    for row in rows:
        if row.lines is not None and lines is not None:
            validate_span(f"{path}: {row.id}", list(row.lines), len(lines))
        if lines is not None:
            _check_printed_within_lines(f"{path}: {row.id}", row, lines, text.name)
        if row.restates is not None and (row.restates not in ids or row.restates == row.id):
            raise PendcliError(f"{path}: {row.id}: restates {row.restates!r}, not another row")


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
        if not _LABEL_FORMAT.match(row.equation):
            raise PendcliError(f'{where}: equation must be a label as printed, e.g. "(4)"')
        stem = row.id.split(".")[2]
        if stem != row.equation[1:-1]:
            raise PendcliError(f"{where}: id does not match the label {row.equation}")


def _check_status_fields(where: str, row: LedgerRow) -> None:
    from pendcli.core.check_kinds import KINDS

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


def reference_table(paper: Paper) -> References:
    """The paper's references by name (``Paper.references``), empty if it has none."""
    return paper.references() if paper.references is not None else {}


# (the status the printed form earns, None for none the ledger may record; why)
Computed = tuple[str | None, str]


@dataclass(frozen=True)
class Measured:
    """What the formula checks a row names (``measured``) found: each ``id verdict (order)``,
    and the lowest observed order among them (None: none is measured)."""

    detail: str
    observed_order: float | None


@dataclass(frozen=True)
class Evaluated:
    row: LedgerRow
    problem: str | None
    dimensions: DimensionCheck | None = None  # the printed form's, when it has one
    computed: Computed | None = None  # computed from the printed form; None without a reference
    measured: Measured | None = None

    def output_row(self) -> EquationRow:
        """The row every output shows: each piece in a field of its own."""
        row, dims, measured = self.row, self.dimensions, self.measured
        status, why = self.computed if self.computed is not None else (None, None)
        return EquationRow(
            id=row.id,
            paper=row.paper,
            equation=row.equation,
            section=row.section,
            statement=row.statement,
            status=row.status,
            kind=row.kind,
            observed_order=measured.observed_order if measured is not None else None,
            note=row.note or "",
            lines=row.lines,
            printed=row.printed,
            reading=row.reading_formula,
            corrected=row.corrected_formula,
            dimensions=dims.verdict if dims is not None else None,
            dimensions_detail=dims.detail if dims is not None else None,
            reading_note=row.reading,
            corrected_note=row.corrected,
            measured=measured.detail if measured is not None else None,
            against=row.reference,
            computed=Status(status) if status is not None else None,
            evidence=why,
            inconsistency=self.problem,
        )


def measured(row: LedgerRow, formulas: Iterable[FormulaRow]) -> Measured | None:
    """What the formula checks ``row`` names found (None: it names none); a name that is no
    formula check of the paper is an error naming the row."""
    if not row.measured:
        return None
    by_id = {r.id: r for r in formulas}
    wanted = [f"{row.paper}.{name}" for name in row.measured]
    missing = [i for i in wanted if i not in by_id]
    if missing:
        raise PendcliError(f"{row.id}: measured names no formula check {', '.join(missing)}")
    chosen = [by_id[i] for i in wanted]
    orders = [r.observed_order for r in chosen if r.observed_order is not None]
    detail = "; ".join(f"{r.id} {r.verdict} (order {_order(r.observed_order)})" for r in chosen)
    return Measured(detail, min(orders) if orders else None)


def _formula_rows(paper: Paper, ledger: Ledger) -> list[FormulaRow]:
    """The paper's formula checks when a row of its ledger names one (else none: not run)."""
    from pendcli.core.claims import shared_formula_rows

    if paper.formula_checks is None or not any(r.measured for r in ledger.rows):
        return []
    return shared_formula_rows(paper.key, paper.formula_checks)


# (i, n): the i-th of n contiguous slices of a ledger's rows, so that two processes can
# share a long ledger; (0, 1) is the whole ledger.
Part = tuple[int, int]


def evaluate(paper: Paper, root: Path | None = None, part: Part = (0, 1)) -> list[Evaluated]:
    """Every row of the paper's ledger (or of ``part`` of it) judged from its printed form,
    with its consistency verified."""
    ledger = load_ledger(paper.key, root)
    rows = ledger.rows
    index, count = part
    start, stop = len(rows) * index // count, len(rows) * (index + 1) // count
    references = reference_table(paper)
    formulas = _formula_rows(paper, ledger)
    out = []
    for row in rows[start:stop]:
        symbols = ledger.symbols_for(row)
        dims = row_dimensions(row, symbols).get("printed")
        computed = row_printed_status(row, symbols, references) if row.reference else None
        problem = printed_problem(row, computed)
        out.append(Evaluated(row, problem, dims, computed, measured(row, formulas)))
    return out


def printed_problem(row: LedgerRow, computed: Computed | None) -> str | None:
    """How the status ``computed`` from the row's printed form contradicts the recorded one,
    or None when they agree (or the row has no reference)."""
    if computed is None or computed[0] == row.status:
        return None
    status, why = computed
    return f"recorded {row.status}, but the printed form gives {status or NO_STATUS}: {why}"


# reference name -> the function that builds it (``Paper.references``)
References = Mapping[str, Callable[[], Any]]


def verify_printed(
    row: LedgerRow, symbols: Mapping[str, str], references: References
) -> tuple[str | None, str | None]:
    """(the status computed from the row's printed form and why, as one line; why it
    contradicts the recorded status or None); (None, None) for a row without a reference."""
    if row.reference is None:
        return None, None
    computed = row_printed_status(row, symbols, references)
    return f"{computed[0] or NO_STATUS}: {computed[1]}", printed_problem(row, computed)


def row_printed_status(
    row: LedgerRow, symbols: Mapping[str, str], references: References
) -> tuple[str | None, str]:
    """The status ``row``'s printed form earns, by its kind, against its reference (built by
    ``references[row.reference]``) and why, computed once per row and symbol table."""

    assert row.reference is not None
    builder = references.get(row.reference)
    if builder is None:
        raise PendcliError(f"{row.id}: the {row.paper} references have no {row.reference!r}")
    # keyed on what a reference may read: the published numbers and the ledgers
    return _printed_status(row, tuple(sorted(symbols.items())), builder, _read_by_references())


@cache
def _printed_status(
    row: LedgerRow, symbols: tuple[tuple[str, str], ...], builder: Callable[[], Any], tables: str
) -> tuple[str | None, str]:
    from pendcli.core.check_kinds import kind_problem

    assert row.reference is not None and row.kind is not None
    reference = _reference(builder, row.paper, row.reference, tables)
    formula = row_formula(f"{row.id}: printed", row.printed or "", dict(symbols))
    wrong_kind = kind_problem(row.kind, formula, reference)
    if wrong_kind:
        return None, wrong_kind
    return printed_status(row, dict(symbols), reference)


@cache
def _reference(builder: Callable[[], Any], paper: str, name: str, tables: str) -> Reference:
    # one Reference per builder and tables folder, shared by every row that cites it
    # (building one can take a second of sympy: solving, integrating, expanding)
    try:
        result: Reference = builder()
    except ValueError as exc:  # a combination of parameters that makes no kind of check
        raise PendcliError(f"{paper} reference {name!r}: {exc}") from None
    return result


def cited_references(paper: Paper, root: Path | None = None) -> dict[str, Reference]:
    """Every reference the paper's ledger cites (``reference = "…"``), by name, each built once
    and shared as :func:`row_printed_status` shares it: what a cold run pays besides its
    verdicts, the author's model done exactly."""

    table = reference_table(paper)
    names = dict.fromkeys(r.reference for r in load_ledger(paper.key, root).rows if r.reference)
    missing = [n for n in names if n not in table]
    if missing:
        raise PendcliError(f"the {paper.key} references have no {', '.join(map(repr, missing))}")
    key = _read_by_references()
    return {n: _reference(table[n], paper.key, n, key) for n in names}


# tables folder -> the digest of what a reference may read in it
_DIGESTS: dict[str, str] = {}


def _read_by_references() -> str:
    """The content of the tables a reference may read (the published numbers, the ledgers),
    as one digest: a copy of the tables folder shares the references built for the original,
    an edited one builds its own."""
    from pendcli.core.cache import content_digest
    from pendcli.core.tables import tables_dir

    root = tables_dir()
    if str(root) not in _DIGESTS:
        parts = (("published", root / "published"), ("equations", root / "equations"))
        _DIGESTS[str(root)] = content_digest(p for p in parts if p[1].is_dir())
    return _DIGESTS[str(root)]


def _clear_reference_caches() -> None:
    _printed_status.cache_clear()
    _reference.cache_clear()
    _DIGESTS.clear()


def _register_reference_caches() -> None:
    from pendcli.core.tables import on_table_change

    on_table_change(_clear_reference_caches)


_register_reference_caches()


def equation_rows(
    papers: Iterable[Paper], root: Path | None = None, part: Part = (0, 1)
) -> list[EquationRow]:
    """The rows of ``reproduce --format json`` under "equations" for ``papers`` (``part`` of
    each ledger); raises PendcliError if a paper's ledger is missing, empty or not a file, or
    a check contradicts its row's status."""
    rows = []
    problems = []
    for paper in papers:
        if paper.references is None:  # a paper without a ledger (its file is then not read)
            continue
        for item in evaluate(paper, root, part):
            rows.append(item.output_row())
            if item.problem:
                problems.append(f"{item.row.id}: {item.problem}")
    if problems:
        raise PendcliError(f"equation ledger inconsistent: {problems[0]} ({len(problems)} rows)")
    return rows


def coverage(rows: Iterable[EquationRow]) -> dict[str, dict[str, int]]:
    """Per paper: the count of rows by status, the total and how many are checked."""
    table: dict[str, dict[str, int]] = {}
    for row in rows:
        counts = table.setdefault(row.paper, {s.value: 0 for s in STATUSES})
        counts[row.status.value] += 1
    for counts in table.values():
        counts["total"] = sum(counts[s] for s in STATUSES)
        counts["checked"] = sum(counts[s] for s in CHECKED_STATUSES)
    return table


def _order(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.2f}"
