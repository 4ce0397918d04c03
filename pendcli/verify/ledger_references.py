"""The ledger's references and the status a row's printed form earns against its own.

A row's ``reference`` names a builder of its paper's table (``Paper.references``); each is
built once per tables folder and shared by every row that cites it (:func:`row_printed_status`,
:func:`cited_references`), and built afresh under an assumed constant for a conditional row
(:func:`conditional`). :func:`printed_problem` says how a computed status contradicts the
recorded one.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from functools import cache
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError
from pendcli.data.ledger_conditions import Conditional, row_conditional
from pendcli.data.rows import NO_STATUS
from pendcli.verify.ledger_formulas import printed_status, row_dimensions, row_formula

if TYPE_CHECKING:
    from pendcli.data.ledger_rows import Ledger, LedgerRow
    from pendcli.data.printed import Formula
    from pendcli.verify.dimensions import DimensionCheck
    from pendcli.verify.ledger_paper import LedgerPaper as Paper
    from pendcli.verify.printed_check import Reference

__all__ = [
    "Computed",
    "References",
    "builders",
    "cited_reference",
    "cited_references",
    "conditional",
    "derivation_drift",
    "derivation_records",
    "paper_digest",
    "printed_dimensions",
    "printed_problem",
    "reference_table",
    "row_derivation",
    "row_printed_status",
    "say_derived_afresh",
    "stale_ledgers",
    "store_derivations",
    "use_store",
    "verify_printed",
]

# reference name -> the function that builds it (``Paper.references``)
References = Mapping[str, Callable[[], Any]]


# the names of the builders a ledger row may cite (``reference = "…"``)
BUILDER_PREFIXES = ("reference_", "numbers_")


def builders(*modules: ModuleType) -> dict[str, Callable[[], Any]]:
    """A paper's table of references: every public function a module defines whose name
    starts with ``reference_`` or ``numbers_``, by that name, in the modules' order; a name
    two modules define is refused (a later builder would silently replace the first)."""
    table: dict[str, Callable[[], Any]] = {}
    for module in modules:
        for name, value in vars(module).items():
            mine = getattr(value, "__module__", None) == module.__name__
            if not (name.startswith(BUILDER_PREFIXES) and callable(value) and mine):
                continue
            if name in table:
                raise ValueError(f"two references named {name!r}: {module.__name__} and another")
            table[name] = value
    return table


def reference_table(paper: Paper) -> References:
    """The paper's references by name (``Paper.references``), empty if it has none."""
    return paper.references() if paper.references is not None else {}


# (the status the printed form earns, None for none the ledger may record; why)
Computed = tuple[str | None, str]


def conditional(
    paper: Paper, ledger: Ledger, row: LedgerRow, references: References
) -> Conditional | None:
    """The row's verdict on each side of its condition, each computed from its reference
    built afresh under the assumed value (data/ledger_conditions); None without one."""
    if row.condition is None or row.reference is None:
        return None
    builder = references[row.reference]
    fresh = getattr(builder, "__wrapped__", builder)  # a cached builder: its function
    symbols = ledger.symbols_for(row)

    def compute() -> tuple[str | None, str]:
        built = _built(fresh, paper.key, row.reference or "")
        cases = _case_builders(row, references)
        return printed_status(row, symbols, _with_row_parameters(row, built, cases))

    return row_conditional(paper.key, row, ledger.assumptions, compute)


def _built(builder: Callable[[], Any], paper: str, name: str) -> Reference:
    try:
        result: Reference = builder()
    except ValueError as exc:  # a combination of parameters that makes no kind of check
        raise PendcliError(f"{paper} reference {name!r}: {exc}") from None
    return result


def printed_problem(row: LedgerRow, computed: Computed | None) -> str | None:
    """How the status ``computed`` from the row's printed form contradicts the recorded one,
    or None when they agree (or the row has no reference)."""
    if computed is None or computed[0] == row.status:
        return None
    status, why = computed
    return f"recorded {row.status}, but the printed form gives {status or NO_STATUS}: {why}"


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
    key = _read_by_references()
    cases = _case_builders(row, references)
    return _printed_status(row, tuple(sorted(symbols.items())), builder, key, cases)


def _case_builders(row: LedgerRow, references: References) -> tuple[Callable[[], Any], ...]:
    """The builders of the references the row's ``cases`` key names, in order."""
    names = dict(row.parameters).get("cases", ())
    missing = [n for n in names if n not in references]
    if missing:
        raise PendcliError(f"{row.id}: the {row.paper} references have no {missing[0]!r}")
    return tuple(references[n] for n in names)


def _with_row_parameters(
    row: LedgerRow, reference: Any, case_builders: tuple[Callable[[], Any], ...]
) -> Any:
    """The reference with the row's kind parameters (verify/check_kinds) in place of its own,
    its ``cases`` built (each once per tables folder)."""
    from pendcli.verify.check_kinds import with_parameters

    if not row.parameters:
        return reference
    names = dict(row.parameters).get("cases", ())
    key = _read_by_references()
    cases = tuple(
        _reference(b, row.paper, n, key) for b, n in zip(case_builders, names, strict=True)
    )
    try:
        return with_parameters(reference, row.parameters, cases)
    except ValueError as exc:  # a combination of parameters that makes no kind of check
        why = f"{row.id}: reference {row.reference!r} with the row's keys: {exc}"
        raise PendcliError(why) from None


@cache
def _printed_status(
    row: LedgerRow,
    symbols: tuple[tuple[str, str], ...],
    builder: Callable[[], Any],
    tables: str,
    case_builders: tuple[Callable[[], Any], ...],
) -> tuple[str | None, str]:
    from pendcli.verify.check_kinds import kind_mismatch, kind_problem
    from pendcli.verify.printed_verdict import stored_status

    assert row.reference is not None and row.kind is not None
    stored = _stored(row, dict(symbols))
    if stored is not None:  # derived by `make regen` from these very tables
        kind, forms = stored
        return (None, kind_mismatch(row.kind, kind)) if kind != row.kind else stored_status(forms)
    built = _reference(builder, row.paper, row.reference, tables)
    reference = _with_row_parameters(row, built, case_builders)
    formula = row_formula(f"{row.id}: printed", row.printed or "", dict(symbols))
    wrong_kind = kind_problem(row.kind, formula, reference)
    if wrong_kind:
        return None, wrong_kind
    return printed_status(row, dict(symbols), reference)


def row_derivation(
    row: LedgerRow, symbols: Mapping[str, str], references: References
) -> dict[str, Any] | None:
    """What the store keeps of ``row`` (verify/derivation_store): its inputs' digest, the kind
    its reference calls for and each form's items; None for a row the store cannot keep (no
    reference, printed numbers, a rounded decimal: judged from the live reference)."""
    from pendcli.verify.check_kinds import kind_called_for
    from pendcli.verify.derivation_store import item_record, row_inputs
    from pendcli.verify.printed_numeric import Numbers
    from pendcli.verify.printed_verdict import derived_forms

    if row.reference is None or row.reference not in references:
        return None
    name = row.reference
    built = _reference(references[name], row.paper, name, _read_by_references())
    reference = _with_row_parameters(row, built, _case_builders(row, references))
    inputs = row_inputs(row, symbols)
    dims = row_dimensions(row, symbols)["printed"]
    shared = {"inputs": inputs, "reference": name, "dimensions": [dims.verdict, dims.detail]}
    if isinstance(reference, Numbers):
        return {**shared, "live": "printed numbers"}

    def parsed(field: str) -> Formula | None:
        text = row.read(field)
        return None if text is None else row_formula(f"{row.id}: {field}", text, symbols)

    printed = parsed("printed")
    assert printed is not None
    reading, corrected = parsed("reading_formula"), parsed("corrected_formula")
    forms = derived_forms(printed, reading, corrected, reference)
    live = _live_only(forms)
    if live:
        return {**shared, "live": live}
    return {
        **shared,
        "kind": kind_called_for(printed, reference),
        "forms": {
            f: {"holds": d.holds, "items": [item_record(i) for i in d.items]}
            for f, d in forms.items()
        },
    }


def _live_only(forms: Mapping[str, Any]) -> str | None:
    """Why the row's items can only be judged from the live reference (a rounded decimal, a
    function known by its numbers only), or None."""
    from sympy.core.function import AppliedUndef

    for derived in forms.values():
        for item in derived.items:
            if item.call == "rounded":
                return "a rounded decimal"
            if item.expr is not None and any(
                hasattr(f, "_imp_") for f in item.expr.atoms(AppliedUndef)
            ):
                return "a function known by its numbers"
    return None


# off: every row derived afresh from its live reference (`pendcli check`, the engine's tests)
_STORE = {"on": True}


def use_store(on: bool) -> None:
    """Whether rows are judged from the stored derivations when they are current."""
    _STORE["on"] = on
    _printed_status.cache_clear()


def _stored(row: LedgerRow, symbols: Mapping[str, str]) -> Any:
    """The row's stored derivation (kind, forms) when the store is on and current for the
    row and the tables in use; else None (and, once per paper, a line on stderr)."""
    from pendcli.verify.derivation_store import row_inputs, row_record, stored_nodes, stored_rows

    if not _STORE["on"]:
        return None
    entry = stored_rows(row.paper, paper_digest(row.paper)).get(row.id)
    if entry is None or entry[0] != row_inputs(row, symbols):
        _say_derived_afresh(row.paper)
        return None
    if "live" in entry[1]:  # judged from the live reference by design
        return None
    return row_record(row.id, entry[1], stored_nodes(row.paper))


def printed_dimensions(row: LedgerRow, symbols: Mapping[str, str]) -> DimensionCheck | None:
    """The dimensional verdict of the row's printed form (None without one): the store's,
    derived from these very tables (``make regen``, compared by ``check``), else computed."""
    from pendcli.verify.derivation_store import row_inputs, stored_rows
    from pendcli.verify.dimensions import DIMENSION_VERDICTS, DimensionCheck

    if row.printed is None:
        return None
    entry = None
    if _STORE["on"] and row.reference is not None:
        entry = stored_rows(row.paper, paper_digest(row.paper)).get(row.id)
    stored = entry[1].get("dimensions") if entry and entry[0] == row_inputs(row, symbols) else None
    if isinstance(stored, list) and len(stored) == 2 and stored[0] in DIMENSION_VERDICTS:
        return DimensionCheck(stored[0], str(stored[1]))
    return row_dimensions(row, symbols).get("printed")


_SAID: set[str] = set()


def stale_ledgers(papers: list[Paper]) -> list[str]:
    """Those of ``papers`` whose stored derivations are not for the tables in use, marked as
    said (a run's forked workers inherit it and stay quiet): the run says it once, at its end,
    with :func:`say_derived_afresh`, and not at all when it fails."""
    from pendcli.data.ledger import load_ledger
    from pendcli.verify.derivation_store import stored_rows

    stale = []
    for paper in papers:
        if not _STORE["on"] or paper.references is None or paper.key in _SAID:
            continue
        try:  # a ledger that does not load is the run's one-line error, said by the run
            load_ledger(paper.key)  # (parsed here once: the forked workers inherit it)
            if not stored_rows(paper.key, paper_digest(paper.key)):
                stale.append(paper.key)
        except (PendcliError, OSError):
            continue
    _SAID.update(stale)
    return stale


def say_derived_afresh(keys: list[str]) -> None:
    """The line, once per ledger, that it was derived afresh (slower; ``make regen``)."""
    for key in keys:
        _SAID.discard(key)
        _say_derived_afresh(key)


def _say_derived_afresh(paper: str) -> None:
    import sys

    if paper not in _SAID:
        _SAID.add(paper)
        print(
            f"pendcli: the {paper} ledger is derived afresh (its stored derivations are for "
            "other tables; `make regen` stores them): slower",
            file=sys.stderr,
        )


@cache
def _reference(builder: Callable[[], Any], paper: str, name: str, tables: str) -> Reference:
    # one Reference per builder and tables folder, shared by every row that cites it
    # (building one can take a second of sympy: solving, integrating, expanding)
    return _built(builder, paper, name)


def cited_references(paper: Paper, root: Path | None = None) -> dict[str, Reference]:
    """Every reference the paper's ledger cites (``reference = "…"``), by name, each built once
    and shared as :func:`row_printed_status` shares it: what a cold run pays besides its
    verdicts, the author's model done exactly."""
    from pendcli.data.ledger import load_ledger

    table = reference_table(paper)
    names = dict.fromkeys(r.reference for r in load_ledger(paper.key, root).rows if r.reference)
    missing = [n for n in names if n not in table]
    if missing:
        raise PendcliError(f"the {paper.key} references have no {', '.join(map(repr, missing))}")
    key = _read_by_references()
    return {n: _reference(table[n], paper.key, n, key) for n in names}


def cited_reference(paper: Paper, name: str, row_id: str | None = None) -> Any:
    """The reference ``name`` as the ledger judges a row against it: built, with the kind
    parameters of the row ``row_id`` (by default the first row citing it) in place."""
    from pendcli.data.ledger import load_ledger

    table = reference_table(paper)
    rows = [r for r in load_ledger(paper.key).rows if r.reference == name]
    row = next((r for r in rows if row_id in (None, r.id)), None)
    if name not in table or row is None:
        raise PendcliError(f"the {paper.key} ledger cites no reference {name!r} in {row_id}")
    built = _reference(table[name], paper.key, name, _read_by_references())
    return _with_row_parameters(row, built, _case_builders(row, table))


# tables folder -> the digest of what a reference may read in it
_DIGESTS: dict[str, str] = {}


def _read_by_references() -> str:
    """The content of the tables a reference may read (the published numbers, the ledgers),
    as one digest: a copy of the tables folder shares the references built for the original,
    an edited one builds its own."""
    from pendcli.base.cache_key import folders_digest
    from pendcli.data.tables import tables_dir

    root = tables_dir()
    if str(root) not in _DIGESTS:
        parts = (("published", root / "published"), ("equations", root / "equations"))
        _DIGESTS[str(root)] = folders_digest(p for p in parts if p[1].is_dir())
    return _DIGESTS[str(root)]


# (tables folder, paper) -> the digest of the paper's published table and ledger
_PAPER_DIGESTS: dict[tuple[str, str], str] = {}


def paper_digest(paper: str) -> str:
    """The digest of what a paper's derivations read: its published table and its ledger
    (the store is current for a paper while these are unchanged; another paper's edit leaves
    it current)."""
    import hashlib

    from pendcli.base.files import file_digest
    from pendcli.data.tables import tables_dir

    root = tables_dir()
    key = (str(root), paper)
    if key not in _PAPER_DIGESTS:
        parts = [file_digest(root / f / f"{paper}.toml") or "" for f in ("published", "equations")]
        _PAPER_DIGESTS[key] = hashlib.sha256("\n".join(parts).encode()).hexdigest()
    return _PAPER_DIGESTS[key]


def _clear_reference_caches() -> None:
    _PAPER_DIGESTS.clear()
    _printed_status.cache_clear()
    _reference.cache_clear()
    _DIGESTS.clear()


def _register_reference_caches() -> None:
    from pendcli.data.tables import on_table_change

    on_table_change(_clear_reference_caches)


_register_reference_caches()


def derivation_records(paper: Paper, root: Path | None = None) -> dict[str, dict[str, Any]]:
    """Every row of the paper's ledger the store can keep, derived from its live reference:
    what ``make regen`` writes and ``pendcli check`` compares with the store."""
    from pendcli.data.ledger import load_ledger

    ledger = load_ledger(paper.key, root)
    table = reference_table(paper)
    out = {}
    for row in ledger.rows:
        record = row_derivation(row, ledger.symbols_for(row), table)
        if record is not None:
            out[row.id] = record
    return out


def store_derivations(paper: Paper) -> Path:
    """Derive and write the paper's store (verify/derivation_store), for the tables in use."""
    from pendcli.verify.derivation_store import write_store

    return write_store(paper.key, paper_digest(paper.key), derivation_records(paper))


def derivation_drift(paper: Paper) -> list[str]:
    """How the stored derivations differ from what the code derives now: one line per row
    (its reference named), empty when they agree."""
    from pendcli.verify.derivation_store import canonical_record, stored_nodes, stored_rows

    stored = stored_rows(paper.key, paper_digest(paper.key))
    if not stored and paper.references is not None:
        return [f"{paper.key}: no stored derivations for these tables (run `make regen`)"]
    fresh = derivation_records(paper)
    nodes = stored_nodes(paper.key)
    lines = []
    for row_id in sorted(set(stored) | set(fresh)):
        old = stored.get(row_id, (None, None))[1]
        new = fresh.get(row_id)
        old = None if old is None else canonical_record(old, nodes)
        if old != (None if new is None else canonical_record(new)):
            reference = (new or old or {}).get("reference", "")
            lines.append(
                f"{row_id}: the stored derivation differs from the code's {reference}".rstrip()
            )
    return lines
