"""The typed rows every output renders: claims, formulas and equations, each built once.

A row carries every field any output shows (the terminal, JSON, CSV, Markdown, the report and
the HTML); ``as_dict`` is the flat mapping the renderers and the JSON document take, its keys
in the order the JSON schema (:mod:`pendcli.output.schema`) describes. Verdicts, statuses and
causes are the words of :mod:`pendcli.data.vocabulary`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

from pendcli.data.vocabulary import EquationStatus, FormulaVerdict, ProcedureVerdict, Verdict

__all__ = [
    "NO_STATUS",
    "ClaimRow",
    "EquationRow",
    "FormulaRow",
    "Recomputed",
    "equation_notes",
    "equation_status",
]


@dataclass(frozen=True)
class Recomputed:
    """A recomputed value in the claim's unit, with the author's model done exactly."""

    value: float
    exact: float | None = (
        None  # the same quantity from a fuller model, where one answers a question
    )
    method: str = ""  # how it was computed, briefly
    note: str = ""  # computed remark (appended to the table's note)


@dataclass(frozen=True)
class ClaimRow:
    """One line of the comparison: what the paper printed against what we recompute."""

    id: str
    paper: str
    source: str
    quantity: str
    unit: str
    published: str
    published_value: float
    recomputed: float
    verdict: Verdict
    abs_diff: float
    rel_diff: float | None
    digits: float
    exact: float | None
    method: str
    note: str
    cause: str | None = None  # why it disagrees (one of CAUSES), None when nothing to explain
    cause_from: tuple[str, ...] = ()  # the rows it inherits its error from ("propagated")
    as_printed: str = ""  # the OCR's text of the printed value, where `published` normalises it
    # against his own procedure (verify/causes): None where no procedure of his is known
    procedure_verdict: ProcedureVerdict | None = None
    procedure_value: float | None = None  # his procedure on his printed inputs
    procedure: str = ""  # the procedure, as he does it ("(1 m - l)/b"); "" when none is known
    procedure_inputs: tuple[str, ...] = ()  # the claims it reads, as printed
    # its verdict on each side of each change within an assumption the paper leaves open
    # (verify/claims.with_conditions): "agrees for g <= 9.8, last-digit for g > 9.8 (...)"
    condition: str | None = None

    def as_dict(self) -> dict[str, object]:
        """The row as JSON, CSV and the tables show it (``as_printed`` is the HTML's only):
        the verdict against his own procedure beside the one against the truth."""
        own = ("procedure_verdict", "procedure_value", "procedure", "procedure_inputs")
        skip = ("cause_from", "as_printed", *own)
        out: dict[str, object] = {}
        for k, v in self.__dict__.items():
            if k not in skip:
                out[k] = _json_number(v)
            if k == "verdict":
                out |= {o: _json_number(getattr(self, o)) for o in own}
        out["procedure_inputs"] = list(self.procedure_inputs)
        out["from"] = list(self.cause_from)
        return out


@dataclass(frozen=True)
class FormulaRow:
    """A derived formula checked against a numerical solution of the governing equation."""

    id: str
    paper: str
    source: str
    published: str  # the formula as printed
    recomputed: str  # the formula as found (corrected term, if any)
    verdict: FormulaVerdict
    claimed_order: float | None
    observed_order: float | None
    note: str
    residuals: tuple[tuple[float, float], ...] = field(default=())  # (parameter, |residual|)
    cause: str | None = None  # why it fails (one of CAUSES), None when it holds
    cause_from: tuple[str, ...] = ()  # the formula rows it inherits its error from

    def as_dict(self) -> dict[str, object]:
        skip = ("residuals", "cause", "cause_from")
        out = {k: _json_number(v) for k, v in self.__dict__.items() if k not in skip}
        out["residuals"] = [[_json_number(p), _json_number(r)] for p, r in self.residuals]
        out["cause"] = self.cause
        out["from"] = list(self.cause_from)
        return out


def _json_number(v: object) -> object:
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


@dataclass(frozen=True)
class EquationRow:
    """One row of the equation ledger, its check run: what ``pendcli equations``, ``reproduce
    --equations``, the report and the HTML show.

    Each piece is a field of its own: the ledger's words (``note``, ``reading_note``,
    ``corrected_note``), the kind of check that decides it and what the engine computed from
    the printed form against its reference (``kind``, ``against``, ``computed``,
    ``evidence``), the order the formula checks it names measured against a fuller model
    (``measured``, ``observed_order``) and the printed form's dimensions (``dimensions``,
    ``dimensions_detail``).
    """

    id: str
    paper: str
    equation: str  # the label as printed, "(4)"; "" for a stated result
    section: str
    statement: str
    status: EquationStatus
    kind: str | None  # the kind of check that decides the row (verify/check_kinds); None: none
    observed_order: float | None  # the lowest order the formula checks in measured observed
    note: str  # the ledger's own note, "" without one
    # where the row is printed, its formulas, the printed form's dimensions
    lines: tuple[int, int] | None = None  # first and last line of tables/papers/<paper>.txt
    printed: str | None = None  # the formula as printed, in the ledger's notation
    reading: str | None = None  # a misprint's evident reading, same notation
    corrected: str | None = None  # a failing formula's correction, same notation
    dimensions: str | None = None  # consistent, inconsistent or dimensionless
    dimensions_detail: str | None = None  # the dimension check's reason (a mismatch's sides)
    reading_note: str | None = None  # the ledger's words on a misprint's evident reading
    corrected_note: str | None = None  # the ledger's words on a failure's correction
    # the formula checks (formulas.py) that measure the row's approximation: "id verdict (order)"
    measured: str | None = None
    against: str | None = None  # the reference the printed form is judged against
    # the status the engine computed from the printed form (None: none the ledger may record,
    # or no reference), and the engine's why: the residual, digits or coefficient that decided
    computed: EquationStatus | None = None
    evidence: str | None = None
    inconsistency: str | None = None  # how the row contradicts its check (never in the output
    # of a consistent ledger: pendcli refuses an inconsistent one)
    # Blame (tables/README.md): whether the row is a finding of its own (failing or misprinted,
    # restating no other row), the rows whose slip it only cites or carries, the later use
    # that decides its blame (lines, and the words there or why none), what it carries
    finding: bool = False
    restates: tuple[str, ...] = ()
    used_at: tuple[int, ...] | None = None
    later_use: str | None = None
    carries: str | None = None
    # its verdict on each side of an assumption the paper leaves open, and each status computed
    condition: str | None = None
    condition_evidence: str | None = None
    step: str | None = None  # its own slip, judged against the printed input it carries
    readings: str | None = None  # the OCR readings of the paper's table applied to its formulas
    assumptions: tuple[str, ...] = ()  # the ledger's unstated assumptions its verdict rests on
    # a corrected or read row's companions (later rows and sentences depending on it), each
    # with how it was judged against the changed form (verify/ledger_companions)
    companions: tuple[str, ...] = ()

    def as_dict(self) -> dict[str, object]:
        out = dict(self.__dict__)
        out["lines"] = list(self.lines) if self.lines is not None else None
        out["restates"] = list(self.restates)
        out["used_at"] = list(self.used_at) if self.used_at is not None else None
        out["assumptions"] = list(self.assumptions)
        out["companions"] = list(self.companions)
        return out


# the blame and context fields of an equation row, in the order its note shows them
_CONTEXT = (
    ("restates", "restates (no finding of its own)"),
    ("later_use", "blame"),
    ("carries", "carries"),
    ("step", "its own slip"),
    ("readings", "read"),
    ("assumptions", "rests on the assumption(s)"),
)
NO_STATUS = "no status the ledger may record"  # what the printed form earns when computed is None


def equation_status(row: Mapping[str, object]) -> str:
    """An equation row's status as the tables show it: a conditional verdict names both sides
    (« fails (holds for g <= 9.80, fails for g > 9.80) »), never a bare status; a row that only
    restates another's slip says so."""
    status = str(row.get("status", ""))
    condition = str(row.get("condition") or "")
    if condition:
        return f"{status} ({condition.split(' (', 1)[0]})"
    if row.get("restates") and status in ("fails", "misprint"):
        return f"{status} (restates)"
    return status


def equation_notes(row: Mapping[str, object]) -> str:
    """An equation row's pieces as one line of prose (the table's, Markdown's and the report's
    note column): the reading, the correction, the ledger's note, the status computed from
    the printed form and why, what the formula checks measured, a dimension mismatch, an
    inconsistency."""
    notes = []
    if row.get("condition"):
        notes.append(f"conditional: {row['condition']}; {row.get('condition_evidence')}")
    if row.get("reading_note"):
        notes.append(f"reading: {row['reading_note']}")
    if row.get("corrected_note"):
        notes.append(f"corrected: {row['corrected_note']}")
    if row.get("note"):
        notes.append(str(row["note"]))
    if row.get("against") is not None:
        computed = row.get("computed") or NO_STATUS
        notes.append(f"computed from the printed form: {computed}: {row.get('evidence')}")
    for key, label in _CONTEXT:
        value = row.get(key)
        if value:
            shown = ", ".join(map(str, value)) if isinstance(value, list | tuple) else value
            notes.append(f"{label}: {shown}")
    if row.get("measured"):
        notes.append(f"measured: {row['measured']}")
    if row.get("dimensions") == "inconsistent":
        notes.append(f"dimensions: {row.get('dimensions_detail')}")
    if row.get("inconsistency"):
        notes.append(f"LEDGER INCONSISTENT: {row['inconsistency']}")
    return "; ".join(notes)
