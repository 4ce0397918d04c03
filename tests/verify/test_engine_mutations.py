"""Mutation testing of the printed-form engine itself (pendcli/verify/printed_verdict.py,
printed_check.py, point_values.py, series_proof.py and printed_numeric.py): each plausible
bug of the engine, put in by monkeypatching one of its seams (a constant or a function of
those modules, named here: a rewritten engine keeps them or maps each mutation onto its own),
must change the verdict of MANY ledger rows, not one; the
tests of the data (tests/**/test_printed*.py) change a row and keep the engine.

The sample, seeded and generic over the rows: every 6th ``holds`` row, every 4th ``misprint``
and every 2nd ``fails`` row (ledger order, the three papers in turn) among the rows with a symbolic
reference and an integer to edit (outside an exponent), every misprint whose reading is judged
against another reference than its printed form, and every row with a numeric reference
(not an inequality: its bound moved one unit may still hold, a looser bound being still true):
54 rows (23 holds, 11 misprint, 7 fails, 13 numeric). Each is judged as committed (it must keep
its recorded status) and with seeded data mutations, made to the committed ledger's text and
validated by ``parse_ledger`` (tests/helpers/mutations.py), each of which must be refused (the
status computed is not the recorded one): 177 cases.

* a holds row: one integer of its printed form (a seeded choice among those whose edits the
  loader accepts) changed ``n -> n + 1``, and the same one nudged by one part in a million;
* a misprint row: its printed form set to its reading, and an integer of its reading changed;
* a fails row: its printed form set to its correction, and an integer of its correction changed;
* a numeric row: up to two of its printed decimals (of the reading, of the correction) one unit
  up and one unit down in the last place, judged with the ties to the published claims set
  aside (so that the digits, not the tie, decide); of each number's two changes the engine
  must refuse at least one (the other may still round or chop to the value), and the
  mutations are judged on those it refuses.

The unmutated engine judges every case rightly (KNOWN_RAISES would list one it raises on: none). An
engine mutation is caught by a row when one of the row's cases gets the wrong verdict (the
committed row another status, a mutated one its recorded status) or the engine raises. Rows
catching each mutation, of the sampled rows it applies to (asserted: at least):

=================================================  ======  =========  ========
engine mutation                                    caught  of (rows)  asserted
=================================================  ======  =========  ========
reading dropped (misprint rows)                        11         11         9
reading unjudged: a misprint whenever one is given     10         11         8
reading judged before the printed form                  9         11         7
Reference.reading ignored (cross-reference rows)        2          2         2
correction unjudged (fails rows)                        7          7         6
tolerance 1e-15 -> 1e-3 (holds rows)                   12         23        10
tolerance 1e-15 -> 1e-1 (holds rows)                   12         23        10
Cauchy coefficients' bound 1e-40 -> 1e-3 (series)       6          7         5
float64's "holds" margin 1e-14 -> 1e-3 (checked)       20         41        16
float64 refuses its own rounding (checked rows)         20         41        16
series order + 1 (rows with a scale)                    9         13         7
series order - 1 (rows with a scale)                    6         13         5
« … » no longer set to 0 (rows printing it)             5          5         4
one unit off in the last place passes (numeric)         9         13         5
numbers judged at one place fewer (numeric)            11         13         8
=================================================  ======  =========  ========

A tolerance reaches only the rows whose residual sympy leaves uncancelled: where the
substitution cancels it to the edit alone (b*dtheta_dt/500000), its size is itself and no
tolerance below 1 lets it pass; a series is judged by its Cauchy coefficients, not at points.
With each mutation's patch removed, each of these tests fails (0 rows catch it). A mutation's
test judges the rows in order until as many as asserted have caught it. CPU of the whole file,
one process: 23 s (the sample and its baseline 15 s, its references 7 s of it; the mutations
6 s); the
fast suite keeps one representative, the tolerance loosened to 1e-3 caught by each of five
holds rows (1.2 s alone); the rest is slow (tests/conftest.py).
"""

from __future__ import annotations

import dataclasses
import random
import re
from collections import Counter
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from decimal import Decimal
from typing import Any

import pytest
from helpers.ledgers import committed_ledger
from helpers.mutations import altered_field, judged_after_edit
from helpers.run_once import judged_once, once_per_run

from pendcli.base.errors import PendcliError
from pendcli.data.ledger_rows import LedgerRow
from pendcli.data.vocabulary import Verdict
from pendcli.papers.registry import paper as paper_named
from pendcli.verify import (
    derived,
    float_verdict,
    point_values,
    printed_check,
    printed_numeric,
    printed_verdict,
    series_proof,
)
from pendcli.verify.ledger_formulas import printed_status
from pendcli.verify.ledger_references import cited_reference, reference_table
from pendcli.verify.printed_check import Reference
from pendcli.verify.printed_numeric import Numbers

PAPERS = ("charbonnier", "lecornu", "tisserand")
SEED = 19
EVERY = {"holds": 6, "misprint": 4, "fails": 2}  # one row in so many, per recorded status
CASES = 177  # the cases judged, committed rows and data mutations
FIELD = {"holds": "printed", "misprint": "reading_formula", "fails": "corrected_formula"}
_INTEGER = re.compile(r"(?<![\w.])[1-9]\d*(?![\w.])")
_DECIMAL = re.compile(r"(?<![\w.])([+-]?)(\d+\.\d+)(?![\w.])")


# --- the rows and their data mutations -------------------------------------------------


@dataclass(frozen=True)
class Sampled:
    """A sampled committed row, its reference and what the engine's seams can reach in it."""

    row: LedgerRow
    reference: Any  # Reference or Numbers

    @property
    def numeric(self) -> bool:
        return isinstance(self.reference, Numbers)

    @property
    def series(self) -> bool:
        """Judged by a series in a scale (compared through an order), in a case or not."""
        references = (self.reference, *getattr(self.reference, "cases", ()))
        return not self.numeric and any(r.scale is not None for r in references)

    @property
    def cross_reference(self) -> bool:
        """A misprint whose reading is judged against another reference than its printed form."""
        return not self.numeric and self.reference.reading is not None

    @property
    def ellipsis(self) -> bool:
        fields = (self.row.printed, self.row.reading_formula, self.row.corrected_formula)
        return any("..." in (f or "") for f in fields)


@dataclass(frozen=True, eq=False)
class Case:
    """One formula of a sampled row to judge: as committed (``committed``: it must earn the
    recorded status) or with a data mutation (it must not)."""

    sampled: Sampled
    what: str
    row: LedgerRow
    symbols: dict[str, str]
    committed: bool

    def status(self) -> str | None:
        reference = self.sampled.reference
        if self.sampled.numeric:  # the digits judge, not the tie to the published claims
            reference = dataclasses.replace(reference, published=())
        return printed_status(self.row, self.symbols, reference)[0]

    def right(self, status: str | None) -> bool:
        return (status == self.row.status) == self.committed


_REFERENCES: dict[tuple[str, str, Any], Any] = {}


def reference_of(row: LedgerRow) -> Any:
    """The row's reference with its keys, built once per name and keys (as the ledger's own
    check shares it)."""
    assert row.reference is not None
    key = (row.paper, row.reference, row.parameters)
    if key not in _REFERENCES:
        _REFERENCES[key] = cited_reference(paper_named(row.paper), row.reference, row.id)
    return _REFERENCES[key]


def in_exponent(text: str, start: int) -> bool:
    """Whether the character at ``start`` lies in an exponent: right after ``**`` or within a
    bracket opened right after it."""
    opened: list[bool] = []
    for i, char in enumerate(text[:start]):
        if char == "(":
            opened.append(text[:i].rstrip().endswith("**"))
        elif char == ")" and opened:
            opened.pop()
    return any(opened) or text[:start].rstrip().endswith("**")


def coefficients(formula: str) -> list[re.Match[str]]:
    """The integers (1 and more) of a formula outside its exponents: what a changed
    coefficient may edit."""
    return [m for m in _INTEGER.finditer(formula) if not in_exponent(formula, m.start())]


def seeded_choice(row: LedgerRow, items: list[Any], count: int = 1) -> list[Any]:
    """``count`` items chosen by a generator seeded with the row's id (stable across runs)."""
    generator = random.Random(f"{SEED}:{row.id}")
    return generator.sample(items, min(count, len(items)))


def spliced(text: str, match: re.Match[str], new: str) -> str:
    return text[: match.start()] + new + text[match.end() :]


def symbolic_cases(sampled: Sampled) -> list[Case]:
    """The committed row and its data mutations (module docstring), for a symbolic reference:
    the integer edited is the first, in a seeded order, whose edits the ledger's loader
    accepts (its grammar bounds what an argument of exp or a derivative's order may reach)."""
    row = sampled.row
    field = FIELD[row.status]
    text = getattr(row, field)
    cases = [Case(sampled, "as committed", row, committed_symbols(row), True)]
    if field != "printed" and text != row.printed:  # a cross-reference's slip may be no text
        edited, symbols = altered_field(row, "printed", text)
        cases.append(Case(sampled, f"printed set to its {field}", edited, symbols, False))
    tokens = coefficients(text)
    for token in seeded_choice(row, tokens, len(tokens)):
        n = int(token.group())
        edits = {str(n + 1): f"{field} {n} -> {n + 1}"}
        if field == "printed":
            edits[f"({n}*1000001/1000000)"] = f"printed {n} -> {n} + {n}/10**6"
        try:
            edited = [
                (altered_field(row, field, spliced(text, token, new)), what)
                for new, what in edits.items()
            ]
        except PendcliError:  # refused by the loader: the next integer
            continue
        return cases + [Case(sampled, what, *pair, False) for pair, what in edited]
    assert sampled.cross_reference, f"{row.id}: no integer of its {field} can be edited"
    return cases


def numeric_cases(sampled: Sampled) -> list[Case]:
    """The committed row and, for up to two of its decimals (seeded), each one unit up and
    one unit down in the last place."""
    row = sampled.row
    field = FIELD[row.status]
    text = getattr(row, field)
    cases = [Case(sampled, "as committed", row, committed_symbols(row), True)]
    for match in seeded_choice(row, list(_DECIMAL.finditer(text)), 2):
        sign, digits = match.groups()
        unit = Decimal(1).scaleb(Decimal(digits).as_tuple().exponent)
        for step in (unit, -unit):
            if Decimal(digits) + step < 0:
                continue
            new = f"{sign}{Decimal(digits) + step}"
            edited, symbols = altered_field(row, field, spliced(text, match, new))
            what = f"{field} #{match.start()} {match.group()} -> {new}"
            cases.append(Case(sampled, what, edited, symbols, False))
    return cases


def committed_symbols(row: LedgerRow) -> dict[str, str]:
    return committed_ledger(row.paper).symbols_for(row)


def sampled_rows() -> Iterator[Sampled]:
    """The sample of the module docstring, in ledger order."""
    seen = dict.fromkeys(EVERY, 0)
    for paper in PAPERS:
        for row in committed_ledger(paper).rows:
            if row.reference is None:
                continue
            sampled = Sampled(row, reference_of(row))
            if sampled.numeric:
                yield sampled
                continue
            if sampled.cross_reference:
                yield sampled
            elif row.kind == "inequality":
                continue  # a bound moved one unit may still hold: a looser bound is still true
            elif coefficients(getattr(row, FIELD[row.status])):
                seen[row.status] += 1
                if (seen[row.status] - 1) % EVERY[row.status] == 0:
                    yield sampled


def cases_of(sampled: Sampled) -> list[Case]:
    return numeric_cases(sampled) if sampled.numeric else symbolic_cases(sampled)


# --- the engine mutations ---------------------------------------------------------------


def wrapped(
    monkeypatch: pytest.MonkeyPatch, module: Any, name: str, wrapper: Callable[..., Any]
) -> None:
    """``module.name`` replaced by ``wrapper(original)``."""
    monkeypatch.setattr(module, name, wrapper(getattr(module, name)))


def reading_dropped(monkeypatch: pytest.MonkeyPatch) -> None:
    """computed_status judges no reading (as though the row gave none)."""
    wrapped(
        monkeypatch,
        printed_verdict,
        "computed_status",
        lambda f: lambda p, r, c, ref: f(p, None, c, ref),
    )


def reading_unjudged(monkeypatch: pytest.MonkeyPatch) -> None:
    """A row with a reading is a misprint whenever its printed form fails."""

    def wrapper(original: Callable[..., Any]) -> Callable[..., Any]:
        def mutant(printed: Any, reading: Any, corrected: Any, reference: Any) -> Any:
            status, why = original(printed, None, corrected, reference)
            return ("misprint", why) if status is None and reading is not None else (status, why)

        return mutant

    wrapped(monkeypatch, printed_verdict, "computed_status", wrapper)


def correction_unjudged(monkeypatch: pytest.MonkeyPatch) -> None:
    """A row with a correction fails (as recorded) whenever its printed form fails."""

    def wrapper(original: Callable[..., Any]) -> Callable[..., Any]:
        def mutant(printed: Any, reading: Any, corrected: Any, reference: Any) -> Any:
            status, why = original(printed, reading, None, reference)
            return ("fails", why) if status is None and corrected is not None else (status, why)

        return mutant

    wrapped(monkeypatch, printed_verdict, "computed_status", wrapper)


def reading_first(monkeypatch: pytest.MonkeyPatch) -> None:
    """The reading judged before the printed form: a row is a misprint when its reading holds."""

    def wrapper(original: Callable[..., Any]) -> Callable[..., Any]:
        def mutant(printed: Any, reading: Any, corrected: Any, reference: Any) -> Any:
            symbolic = reading is not None and isinstance(reference, Reference)
            if symbolic and printed_check.judged(reading, reference.reading or reference)[0]:
                return "misprint", "the reading holds"
            return original(printed, reading, corrected, reference)

        return mutant

    wrapped(monkeypatch, printed_verdict, "computed_status", wrapper)


def reading_reference_ignored(monkeypatch: pytest.MonkeyPatch) -> None:
    """``Reference.reading`` ignored: the reading judged against the printed form's reference."""

    def wrapper(original: Callable[..., Any]) -> Callable[..., Any]:
        def mutant(printed: Any, reading: Any, corrected: Any, reference: Any) -> Any:
            if isinstance(reference, Reference):
                reference = dataclasses.replace(reference, reading=None)
            return original(printed, reading, corrected, reference)

        return mutant

    wrapped(monkeypatch, printed_verdict, "computed_status", wrapper)


def tolerance(value: float) -> Callable[[pytest.MonkeyPatch], None]:
    """The residual's relative tolerance at the random points (1e-15) set to ``value``."""

    def mutation(monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.setattr(point_values, "_TOLERANCE", value)

    return mutation


def cauchy_tolerance(monkeypatch: pytest.MonkeyPatch) -> None:
    """The bound on a series' Cauchy coefficients below the order (1e-40) set to 1e-3."""
    import mpmath

    def wrapper(original: Callable[..., Any]) -> Callable[..., Any]:
        def mutant(sums: Any, order: int, far: Any, near: Any, bound: Any) -> Any:
            return original(sums, order, far, near, bound * mpmath.mpf(10) ** 37)

        return mutant

    wrapped(monkeypatch, series_proof, "_lowest_failing", wrapper)


def order_shifted(step: int) -> Callable[[pytest.MonkeyPatch], None]:
    """Every equation's series compared through its order + ``step``."""

    def mutation(monkeypatch: pytest.MonkeyPatch) -> None:
        def wrapper(original: Callable[..., Any]) -> Callable[..., Any]:
            def mutant(item: Any) -> Any:
                if item.order is None:
                    return original(item)
                return original(dataclasses.replace(item, order=item.order + step))

            return mutant

        wrapped(monkeypatch, derived, "item_passes", wrapper)

    return mutation


def float_tolerance(value: float) -> Callable[[pytest.MonkeyPatch], None]:
    """Float64's margin for "holds" (1e-14 of the residual's terms) set to ``value``."""

    def mutation(monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.setattr(float_verdict, "HOLDS", value)

    return mutation


def float_fails_at_rounding(monkeypatch: pytest.MonkeyPatch) -> None:
    """Float64 refuses a residual at its rounding (FAILS 1e-6 -> 1e-18): a true form fails."""
    monkeypatch.setattr(float_verdict, "FAILS", 1e-18)
    monkeypatch.setattr(float_verdict, "HOLDS", 1e-19)


def ellipsis_kept(monkeypatch: pytest.MonkeyPatch) -> None:
    """« … » no longer set to 0 (the engine looks for another symbol's name)."""
    monkeypatch.setattr(printed_check, "ELLIPSIS", "ellipsis_renamed")


def last_digit_passes(monkeypatch: pytest.MonkeyPatch) -> None:
    """A printed number one unit off in its last place passes (as agrees and truncated do)."""
    passing = (Verdict.AGREES, Verdict.TRUNCATED, Verdict.LAST_DIGIT)
    monkeypatch.setattr(printed_numeric, "_PASSING", passing)


def one_place_fewer(monkeypatch: pytest.MonkeyPatch) -> None:
    """A printed number judged at one place fewer than printed (its unit ten times larger)."""

    def wrapper(original: Callable[..., Any]) -> Callable[..., Any]:
        def mutant(printed: Any, value: float, comparison: str = "equal") -> Any:
            if printed.resolution is not None:
                printed = dataclasses.replace(printed, resolution=10 * printed.resolution)
            return original(printed, value, comparison)

        return mutant

    wrapped(monkeypatch, printed_numeric, "judge", wrapper)


@dataclass(frozen=True)
class EngineMutation:
    patch: Callable[[pytest.MonkeyPatch], None]
    applies: Callable[[Sampled], bool]  # the rows whose cases it is judged on
    least: int  # sampled rows that must catch it

    def caught_by(
        self, sample: list[Sampled], cases: dict[str, list[Case]], enough: int | None = None
    ) -> list[str]:
        """The ids of the applicable rows one of whose cases this mutation judges wrongly, in
        the sample's order; with ``enough``, the first ``enough`` of them (the rows after are
        not judged: the test asks for so many)."""
        caught: list[str] = []
        with pytest.MonkeyPatch.context() as monkeypatch:
            self.patch(monkeypatch)
            for sampled in filter(self.applies, sample):
                if enough is not None and len(caught) >= enough:
                    break
                if any(wrong(case) for case in cases[sampled.row.id]):
                    caught.append(sampled.row.id)
        return caught


def wrong(case: Case) -> bool:
    try:
        return not case.right(case.status())
    except Exception:  # a mutated engine that raises gives no verdict: caught
        return True


def status_is(*statuses: str) -> Callable[[Sampled], bool]:
    return lambda s: not s.numeric and s.row.status in statuses


MUTATIONS = {
    "reading dropped": EngineMutation(reading_dropped, status_is("misprint"), 9),
    "reading unjudged": EngineMutation(reading_unjudged, status_is("misprint"), 8),
    "reading judged first": EngineMutation(reading_first, status_is("misprint"), 7),
    "reading's reference ignored": EngineMutation(
        reading_reference_ignored, lambda s: s.cross_reference, 2
    ),
    "correction unjudged": EngineMutation(correction_unjudged, status_is("fails"), 6),
    "tolerance 1e-15 -> 1e-3": EngineMutation(tolerance(1e-3), status_is("holds"), 10),
    "tolerance 1e-15 -> 1e-1": EngineMutation(tolerance(1e-1), status_is("holds"), 10),
    "Cauchy tolerance 1e-40 -> 1e-3": EngineMutation(
        cauchy_tolerance, lambda s: s.series and s.row.status == "holds", 5
    ),
    "float tolerance 1e-14 -> 1e-3": EngineMutation(
        float_tolerance(1e-3), status_is("holds", "misprint", "fails"), 16
    ),
    "float refuses its rounding": EngineMutation(
        float_fails_at_rounding, status_is("holds", "misprint", "fails"), 16
    ),
    "order + 1": EngineMutation(order_shifted(1), lambda s: s.series, 7),
    "order - 1": EngineMutation(order_shifted(-1), lambda s: s.series, 5),
    "ellipsis not 0": EngineMutation(ellipsis_kept, lambda s: s.ellipsis, 4),
    "one unit off passes": EngineMutation(last_digit_passes, lambda s: s.numeric, 5),
    "one place fewer": EngineMutation(one_place_fewer, lambda s: s.numeric, 8),
}


# --- the tests ----------------------------------------------------------------------------

Judged = dict[str, list[tuple[Case, str | None]]]  # row id -> (case, its status), unmutated
RAISES = "raises "
# Data mutations on which the unmutated engine raises where it should refuse: (row, case) ->
# the exception. None: an edit that leaves the residual without a power series (2/p -> 3/p in
# a phase, a pole 1/p sympy's series cannot expand) is refused like any other failing form.
KNOWN_RAISES: dict[tuple[str, str], str] = {}


def status_or_raised(case: Case) -> str | None:
    try:
        return case.status()
    except Exception as error:
        return RAISES + type(error).__name__


@pytest.fixture(scope="module")
def sample(tmp_path_factory: pytest.TempPathFactory) -> list[Sampled]:
    # chosen and judged once for the run: the other worker builds the chosen rows' references
    chosen = once_per_run(tmp_path_factory, "engine", lambda: [s.row.id for s in sampled_rows()])
    rows = {row.id: row for paper in PAPERS for row in committed_ledger(paper).rows}
    return [Sampled(rows[row_id], reference_of(rows[row_id])) for row_id in chosen]


@pytest.fixture(scope="module")
def baseline(sample: list[Sampled], tmp_path_factory: pytest.TempPathFactory) -> Judged:
    cases = {s.row.id: cases_of(s) for s in sample}
    return judged_once(tmp_path_factory, "engine-cases", cases, status_or_raised, lambda c: c.what)


def rightly_judged(baseline: Judged) -> dict[str, list[Case]]:
    """Each sampled row's cases the unmutated engine judges rightly: every symbolic one but
    those it raises on, and the refused one-unit changes of a numeric row (the test below)."""
    return {
        row: [c for c, status in pairs if not str(status).startswith(RAISES) and c.right(status)]
        for row, pairs in baseline.items()
    }


def test_the_correct_engine_gives_every_sampled_case_its_right_verdict(
    sample: list[Sampled], baseline: Judged
) -> None:
    counts = Counter("numeric" if s.numeric else s.row.status for s in sample)
    assert counts == {"holds": 23, "misprint": 11, "fails": 7, "numeric": 13}
    assert sum(len(pairs) for pairs in baseline.values()) == CASES
    raised = {(row, c.what): str(status)[len(RAISES) :]
              for row, pairs in baseline.items()
              for c, status in pairs if str(status).startswith(RAISES)}  # fmt: skip
    assert raised == KNOWN_RAISES
    wrongly = []
    for row, pairs in baseline.items():
        if pairs[0][0].sampled.numeric:  # the committed row right, and for each decimal
            numbers = {c.what.split(" -> ")[0]: False for c, _ in pairs[1:]}  # one change refused
            numbers.update({c.what.split(" -> ")[0]: True for c, s in pairs[1:] if c.right(s)})
            wrongly += [f"{row}: {n}" for n, refused in numbers.items() if not refused]
            pairs = pairs[:1]
        wrongly += [f"{row}: {c.what} gives {s}" for c, s in pairs
                    if (row, c.what) not in raised and not c.right(s)]  # fmt: skip
    assert wrongly == []


@pytest.mark.parametrize("name", list(MUTATIONS))
def test_an_engine_mutation_is_caught_by_many_rows(
    name: str, sample: list[Sampled], baseline: Judged
) -> None:
    mutation = MUTATIONS[name]
    applicable = [s.row.id for s in sample if mutation.applies(s)]
    caught = mutation.caught_by(sample, rightly_judged(baseline), enough=mutation.least)
    assert len(caught) >= mutation.least, (name, len(caught), len(applicable), caught)


FAST = (
    "charbonnier.eq.1",
    "charbonnier.result.recurrence",
    "lecornu.eq.35",
    "lecornu.result.cos_cube",
    "tisserand.eq.17",
)


def test_a_loosened_tolerance_is_caught_by_each_of_five_rows() -> None:
    """The fast representative: five holds rows judged at points (no series), each refused
    with its nudged integer by the engine, and accepted once its tolerance is 1e-3."""
    chosen = [
        Sampled(row, reference_of(row))
        for paper in PAPERS
        for row in committed_ledger(paper).rows
        if row.id in FAST
    ]
    cases = {s.row.id: symbolic_cases(s) for s in chosen}
    assert all(c.right(c.status()) for judged in cases.values() for c in judged)
    loosened = EngineMutation(tolerance(1e-3), lambda s: True, len(FAST))
    assert loosened.caught_by(chosen, cases) == list(FAST)


def test_a_residual_without_a_power_series_is_refused_not_raised() -> None:
    """An edit of the phase (2/p -> 3/p) leaves sin(1/p) in the residual, which sympy's series
    cannot expand (PoleError): the engine refuses the printed form, naming why, where it raised
    and `pendcli equations` ended in an internal error."""
    old = "sin(2/p + r*t"
    row_id = "lecornu.result.theta_first_order"
    computed, problem = judged_after_edit(
        reference_table(paper_named("lecornu")), row_id, old, "sin(3/p + r*t", within=row_id
    )
    assert computed is not None and computed.startswith("no status the ledger may record")
    assert "no power series in p about 0" in computed and "PoleError" in computed, computed
    assert problem is not None and problem.startswith("recorded holds, but"), problem
