"""The JSON schema of pendcli's output: one source for the README and the tests.

``pendcli reproduce --format json`` prints one object whose lists hold rows of the kinds
below; every paper subcommand prints ``claims`` and ``formulas`` rows the same way (and adds
its own keys beside them); ``pendcli tradeoff --format json`` prints ``rows``. The README's
"JSON schema" section is generated from here (``python -m tools.docs``) and
``tests/output/test_json_schema.py`` checks real output against it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from pendcli.data.vocabulary import PROCEDURE_VERDICTS, STATUSES
from pendcli.papers.registry import PAPERS  # the built-in papers the JSON describes
from pendcli.verify.check_kinds import KINDS
from pendcli.verify.claims import CAUSES, FORMULA_VERDICTS
from pendcli.verify.verdict import CLAIM_VERDICTS

__all__ = ["DOCUMENT", "Field", "RowKind", "check_row", "markdown"]

# JSON type name -> the Python types json.loads gives for it (bool is excluded from numbers).
_PYTHON_TYPES: dict[str, tuple[type, ...]] = {
    "string": (str,),
    "number": (int, float),
    "integer": (int,),
    "array": (list,),
    "boolean": (bool,),
    "null": (type(None),),
}


@dataclass(frozen=True)
class Field:
    name: str
    # JSON type names: "string", "number", "integer", "array", "boolean", "null"
    types: tuple[str, ...]
    meaning: str
    values: tuple[str, ...] = ()  # the only values a string may take (or null), when listed

    def problems(self, value: object) -> list[str]:
        """Why ``value`` (as json.loads gives it) does not fit this field; empty if it does."""
        allowed = tuple(t for name in self.types for t in _PYTHON_TYPES[name])
        wrong_bool = isinstance(value, bool) and "boolean" not in self.types
        if wrong_bool or not isinstance(value, allowed):
            return [f"{self.name}: {value!r} is not {' or '.join(self.types)}"]
        if self.values and value is not None and value not in self.values:
            return [f"{self.name}: {value!r} is not one of {', '.join(self.values)}"]
        return []


@dataclass(frozen=True)
class RowKind:
    key: str  # the document's key holding a list of such rows
    when: str  # when the document has that key
    fields: tuple[Field, ...]

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(f.name for f in self.fields)


_TEXT, _NUMBER, _OPTIONAL = ("string",), ("number",), ("number", "null")
_OPT_TEXT = ("string", "null")
_CAUSE_MEANING = (
    "why it does not agree or hold, null when nothing needs explaining; every cause but "
    "propagated is a root; computed by the rule of tables/README.md where the author's "
    "procedure is known"
)
_FROM_MEANING = (
    "ids of the rows it uses that are themselves a slip (or carry one) when `cause` is "
    "propagated, else []"
)

CLAIMS = RowKind(
    "claims",
    "always",
    (
        Field("id", _TEXT, "`<paper>.<name>`, unique"),
        Field("paper", _TEXT, "the paper", PAPERS),
        Field("source", _TEXT, "where the paper prints it (page, equation)"),
        Field("quantity", _TEXT, "what the number is"),
        Field("unit", _TEXT, "unit of `published` and `recomputed` (may be empty)"),
        Field("published", _TEXT, "the printed string, exactly as printed"),
        Field("published_value", _NUMBER, "the printed string's value"),
        Field("recomputed", _NUMBER, "the author's model, done exactly"),
        Field(
            "verdict",
            _TEXT,
            "against the truth (`recomputed`); see *How verdicts are decided*",
            CLAIM_VERDICTS,
        ),
        Field(
            "procedure_verdict",
            _OPT_TEXT,
            "against his own procedure on his printed inputs: faithful when its result, "
            "rounded or chopped at the printed precision, is the printed value, slip when not; "
            "null when no procedure of his is known (never guessed)",
            PROCEDURE_VERDICTS,
        ),
        Field(
            "procedure_value", _OPTIONAL, "his procedure on his printed inputs; null: none known"
        ),
        Field("procedure", _TEXT, "his procedure, as he does it; empty when none is known"),
        Field("procedure_inputs", ("array",), "ids of the printed values his procedure reads"),
        Field("abs_diff", _NUMBER, "recomputed − published"),
        Field("rel_diff", _OPTIONAL, "abs_diff / |published|; null when published is 0"),
        Field("digits", _NUMBER, "agreeing significant digits, at most 17"),
        Field("exact", _OPTIONAL, "a fuller model's value, where one answers a question"),
        Field("method", _TEXT, "how it was recomputed"),
        Field("note", _TEXT, "OCR corrections, explanations of any disagreement"),
        Field("cause", ("string", "null"), _CAUSE_MEANING, CAUSES),
        Field(
            "condition",
            _OPT_TEXT,
            "its verdict on each side of each change within the range of an assumption the "
            "paper does not state (Lecornu's g), computed; null when none turns it",
        ),
        Field("from", ("array",), _FROM_MEANING),
    ),
)
FORMULAS = RowKind(
    "formulas",
    "always; empty with `--no-formulas`",
    (
        Field("id", _TEXT, "`<paper>.<name>`, unique"),
        Field("paper", _TEXT, "the paper", PAPERS),
        Field("source", _TEXT, "the equation's number or place"),
        Field("published", _TEXT, "the formula as printed"),
        Field("recomputed", _TEXT, "the formula as found (the corrected term, if any)"),
        Field("verdict", _TEXT, "against a numerical solution", FORMULA_VERDICTS),
        Field("claimed_order", _OPTIONAL, "exponent of the residual the derivation implies"),
        Field("observed_order", _OPTIONAL, "least-squares slope of log|residual| on log p"),
        Field("note", _TEXT, "the verdict's reason and the residual's convention"),
        Field("residuals", ("array",), "`[p, |residual|]` pairs, p the small parameter"),
        Field("cause", ("string", "null"), _CAUSE_MEANING, CAUSES),
        Field("from", ("array",), _FROM_MEANING),
    ),
)
EQUATIONS = RowKind(
    "equations",
    "with `--equations` or `--out` (`pendcli equations` prints the same rows)",
    (
        Field("id", _TEXT, "`<paper>.eq.<label>` or `<paper>.result.<name>`, unique"),
        Field("paper", _TEXT, "the paper", PAPERS),
        Field(
            "equation",
            _TEXT,
            "the label as printed, e.g. `(41)`, `(II)`, `(42')`; empty "
            "for a result stated in the text",
        ),
        Field("section", _TEXT, "where the paper states it"),
        Field("statement", _TEXT, "what it states, in linear notation"),
        Field("status", _TEXT, "what the check found", STATUSES),
        Field(
            "kind",
            _OPT_TEXT,
            "the kind of check that decides the row (docs/ENGINE.md); null for a definition "
            "or a not-checkable row",
            tuple(KINDS),
        ),
        Field(
            "observed_order",
            _OPTIONAL,
            "the lowest order the formula checks in `measured` observed against a fuller model",
        ),
        Field("note", _TEXT, "the ledger's own note, empty without one"),
        Field("lines", ("array", "null"), "[first, last]: the lines of the paper's text"),
        Field("printed", ("string", "null"), "the formula as printed, in sympy notation"),
        Field("reading", ("string", "null"), "a misprint's reading, in the same notation"),
        Field("corrected", ("string", "null"), "a failure's correction, in the same notation"),
        Field(
            "dimensions",
            ("string", "null"),
            "the printed form's dimensional verdict; null without a printed form",
            ("consistent", "inconsistent", "dimensionless"),
        ),
        Field(
            "dimensions_detail",
            _OPT_TEXT,
            "the dimension check's reason (for inconsistent: the sides that disagree)",
        ),
        Field("reading_note", _OPT_TEXT, "the ledger's words on a misprint's evident reading"),
        Field("corrected_note", _OPT_TEXT, "the ledger's words on a failure's correction"),
        Field(
            "measured",
            _OPT_TEXT,
            "the formula checks that measure the row's approximation: `id verdict (order)`",
        ),
        Field("against", _OPT_TEXT, "the reference the printed form is judged against"),
        Field(
            "computed",
            _OPT_TEXT,
            "the status the engine computed from the printed form against `against`; null "
            "without a reference",
            ("holds", "fails", "misprint"),
        ),
        Field(
            "evidence",
            _OPT_TEXT,
            "the engine's why: the residual, digits or coefficient that decided",
        ),
        Field(
            "inconsistency",
            _OPT_TEXT,
            "how the row contradicts its check; always null (pendcli refuses such a ledger)",
        ),
        Field(
            "finding",
            ("boolean",),
            "true for a failing or misprinted row that restates no other: one entry per slip, "
            "what the counts count (tables/README.md, Blame)",
        ),
        Field(
            "restates",
            ("array",),
            "ids of the rows whose formula it repeats (a definition) or whose slip it only "
            "cites or carries (then no finding of its own)",
        ),
        Field(
            "used_at",
            ("array", "null"),
            "the lines where the author's later work uses the form: the wrong form carried "
            "(fails) or the right one taken (misprint); null without",
        ),
        Field(
            "later_use",
            _OPT_TEXT,
            "the later use that decides the blame, with the words there, or why none",
        ),
        Field(
            "carries",
            _OPT_TEXT,
            "the earlier row whose wrong form the row takes as input: a step that holds on "
            "wrong values, or a slip of its own beside the carried one",
        ),
        Field(
            "condition",
            _OPT_TEXT,
            "the verdict on each side of an assumption the paper does not state, with its "
            "range (e.g. holds for g <= 9.80, fails for g > 9.80)",
        ),
        Field(
            "condition_evidence",
            _OPT_TEXT,
            "the status computed at both ends of each side of the condition",
        ),
        Field(
            "step",
            _OPT_TEXT,
            "the row's own slip, judged against the printed input it carries",
        ),
        Field("readings", _OPT_TEXT, "the OCR readings of the paper's table applied to it"),
        Field("assumptions", ("array",), "ids of the ledger's unstated assumptions it rests on"),
        Field(
            "companions",
            ("array",),
            "a corrected or read row's companions (later rows and sentences citing its label, "
            "printing its wrong term or sharing a name it introduces), each with how it was "
            "judged against the changed form; empty for other rows",
        ),
    ),
)
STABILITY = RowKind(
    "stability",
    "with `--stability` or `--out`",
    (
        Field("family", _TEXT, "the quantity computed"),
        Field("method", _TEXT, "how"),
        Field("accurate_range", _TEXT, "where it is accurate, as measured"),
        Field("fails_beyond", _TEXT, "where and how it fails"),
        Field("measured", _TEXT, "the measurement behind both"),
    ),
)
TRADEOFF_ROWS = RowKind(
    "rows",
    "`pendcli tradeoff --format json`, beside `skipped`",
    (
        Field("family", _TEXT, "the quantity computed"),
        Field("method", _TEXT, "the method"),
        Field("setting", _TEXT, "its setting (tolerance, terms, nodes)"),
        Field("seconds", _NUMBER, "time per evaluation"),
        Field("error", _OPTIONAL, "worst relative error; null when the method failed"),
        Field("evaluations", ("integer", "null"), "function evaluations per problem"),
        Field("note", _TEXT, "why a method failed, if it did"),
    ),
)

# Every kind of row pendcli prints, by the document key that holds them.
DOCUMENT: dict[str, RowKind] = {
    k.key: k for k in (CLAIMS, FORMULAS, EQUATIONS, STABILITY, TRADEOFF_ROWS)
}


def check_row(kind: RowKind, row: Mapping[str, object]) -> list[str]:
    """Every way ``row`` departs from ``kind``: missing or extra keys, wrong types or values."""
    problems = [f"missing key {name!r}" for name in kind.names if name not in row]
    problems += [f"unexpected key {name!r}" for name in row if name not in kind.names]
    for f in kind.fields:
        if f.name in row:
            problems += f.problems(row[f.name])
    return problems


def markdown() -> str:
    """The README's description of the JSON output: one table of keys per kind of row."""
    parts = []
    for kind in DOCUMENT.values():
        parts += [f"`{kind.key}` ({kind.when}), a list of objects:", ""]
        parts += ["| key | type | meaning |", "|---|---|---|"]
        for f in kind.fields:
            meaning = f.meaning + (f" (one of {', '.join(f.values)})" if f.values else "")
            meaning = meaning.replace("|", "\\|")  # a pipe would end the Markdown cell
            parts.append(f"| `{f.name}` | {' or '.join(f.types)} | {meaning} |")
        parts.append("")
    return "\n".join(parts)
