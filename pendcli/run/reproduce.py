"""Run every claim (and formula check) of the chosen papers: the data behind `reproduce`
(the command) and :func:`pendcli.api.reproduce` (the function ``pendcli.run.reproduce``)."""

from __future__ import annotations

import contextlib
import functools
import sys
from collections.abc import Callable, Iterable
from contextlib import nullcontext
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from pendcli.data.rows import EquationRow
from pendcli.data.vocabulary import (
    CHECKED_STATUSES,
    CLAIM_VERDICTS,
    FORMULA_VERDICTS,
    PROCEDURE_VERDICTS,
    STATUSES,
    EquationStatus,
    FormulaVerdict,
)
from pendcli.output.columns import Column, Row, Section
from pendcli.output.summary import disagrees
from pendcli.papers.registry import claim_rows, formula_checks
from pendcli.verify.claims import ClaimRow, FormulaRow

if TYPE_CHECKING:
    from pathlib import Path

    from pendcli.base.cache import ResultCache
    from pendcli.papers.paper import Paper

__all__ = [
    "VERDICT_NAMES",
    "ReproduceResult",
    "ledger_rows",
    "parse_verdicts",
    "reproduce_all",
    "result_cache",
]


@dataclass
class ReproduceResult:
    papers: tuple[str, ...]
    claims: dict[str, list[ClaimRow]] = field(default_factory=dict)
    formulas: dict[str, list[FormulaRow]] = field(default_factory=dict)
    stability: list[dict[str, str]] = field(default_factory=list)
    equations: dict[str, list[EquationRow]] = field(default_factory=dict)

    def claim_dicts(self, only_failing: bool = False) -> list[dict[str, object]]:
        rows = [r.as_dict() for key in self.papers for r in self.claims.get(key, [])]
        return [r for r in rows if disagrees(r)] if only_failing else rows

    def formula_dicts(self, only_failing: bool = False) -> list[dict[str, object]]:
        rows = [r.as_dict() for key in self.papers for r in self.formulas.get(key, [])]
        return [r for r in rows if disagrees(r)] if only_failing else rows

    def equation_dicts(self, only_failing: bool = False) -> list[dict[str, object]]:
        rows = [r.as_dict() for key in self.papers for r in self.equations.get(key, [])]
        return [r for r in rows if disagrees(r)] if only_failing else rows

    def document(self, only_failing: bool = False) -> dict[str, object]:
        """What `--format json` prints (keys described in :mod:`pendcli.output.schema`)."""
        doc: dict[str, object] = {
            "claims": self.claim_dicts(only_failing),
            "formulas": self.formula_dicts(only_failing),
        }
        if self.equations:
            doc["equations"] = self.equation_dicts(only_failing)
        if self.stability:
            doc["stability"] = self.stability
        return doc

    def sections(self, compact: bool = False, only_failing: bool = False) -> list[Section]:
        """Titled sections for the table and Markdown outputs: claims, formulas, equations,
        stability, then the summary. ``compact``: the 80-column terminal view (no notes)."""
        out: list[Section] = []
        for key in self.papers:
            out += self._paper_sections(key, compact, only_failing)
        if self.stability and not compact:
            cols = [Column(k, k) for k in self.stability[0]]
            out.append(("Numerical stability: where each method is accurate", self.stability, cols))
        return out + self.summary_sections()

    def _paper_sections(self, key: str, compact: bool, only_failing: bool) -> list[Section]:
        from pendcli.output import summary
        from pendcli.output.views import EQUATION_COLUMNS, FORMULA_COLUMNS, claim_columns

        name = key.capitalize()
        rows = [r.as_dict() for r in self.claims.get(key, [])]
        frows = [r.as_dict() for r in self.formulas.get(key, [])]
        eqs = [r.as_dict() for r in self.equations.get(key, [])]
        if only_failing or compact:  # the terminal lists equations that fail or are misprinted
            eqs = [r for r in eqs if disagrees(r)]
        if only_failing:
            rows, frows = [r for r in rows if disagrees(r)], [r for r in frows if disagrees(r)]
        out: list[Section] = []
        if rows:
            cols = summary.compact_claim_columns() if compact else claim_columns(rows)
            out.append((f"{name}: printed numbers", rows, cols))
        if frows:
            fcols = summary.compact_formula_columns() if compact else FORMULA_COLUMNS
            out.append((f"{name}: derived formulas", frows, fcols))
        if eqs:
            ecols = summary.compact_equation_columns() if compact else EQUATION_COLUMNS
            what = "equations that fail or are misprinted" if compact else "equation ledger"
            out.append((f"{name}: {what}", eqs, ecols))
        return out

    def summary_sections(self) -> list[Section]:
        """Counts per paper (verdicts, causes, equations), then the propagation tree."""
        from pendcli.output.summary import propagation_tree

        summary = self.summary_rows()
        out: list[Section] = [
            ("Summary: printed numbers against the truth", summary, _NUMBER_SUMMARY),
            ("Summary: against his own procedure, and causes", summary, _OWN_SUMMARY),
        ]
        columns = _FORMULA_SUMMARY + (_EQUATION_SUMMARY if self.equations else ())
        out.append(("Summary: formulas and equations", summary, columns))
        rows = [r.as_dict() for key in self.papers for r in self.claims.get(key, [])]
        rows += [r.as_dict() for key in self.papers for r in self.formulas.get(key, [])]
        tree = propagation_tree(rows)
        if tree:
            title = "Where errors enter, and the rows that carry them"
            out.append((title, [{"tree": line} for line in tree], [Column("tree", "row (cause)")]))
        return out

    def verdict_counts(self) -> dict[str, dict[str, int]]:
        """Per paper: claim verdict -> count, and "formula holds"/"formula fails" -> count."""
        counts: dict[str, dict[str, int]] = {}
        for key in self.papers:
            c: dict[str, int] = {}
            for r in self.claims.get(key, []):
                c[r.verdict] = c.get(r.verdict, 0) + 1
            for f in self.formulas.get(key, []):
                c[f"formula {f.verdict}"] = c.get(f"formula {f.verdict}", 0) + 1
            counts[key] = c
        return counts

    def summary_rows(self) -> list[Row]:
        """One row per paper: claims by verdict, root causes apart from propagated rows,
        formulas holding/failing, and equations checked (when the ledger was run)."""
        from pendcli.verify.claims import cause_tally, procedure_tally

        counts = self.verdict_counts()
        out: list[Row] = []
        for key in self.papers:
            tally = cause_tally(self.claims.get(key, []))
            row: dict[str, object] = {
                "paper": key,
                **{v: counts[key].get(v, 0) for v in CLAIM_VERDICTS},
                **procedure_tally(self.claims.get(key, [])),
                "formulas holding": counts[key].get(f"formula {FormulaVerdict.HOLDS}", 0),
                "formulas failing": counts[key].get(f"formula {FormulaVerdict.FAILS}", 0),
                "root causes": tally.root_total,
                "propagated": tally.propagated,
            }
            if self.equations:  # failing and misprinted: the findings, one per slip
                eqs = self.equations.get(key, [])
                row["equations"] = len(eqs)
                for status in CHECKED_STATUSES:
                    mine = [r for r in eqs if r.status is status]
                    row[f"equations {status}"] = sum(
                        r.finding or r.status is EquationStatus.HOLDS for r in mine
                    )
                flawed = (EquationStatus.FAILS, EquationStatus.MISPRINT)
                row["equations restating"] = sum(r.status in flawed and not r.finding for r in eqs)
            out.append(row)
        return out

    def rows_with(self, names: frozenset[str]) -> list[dict[str, object]]:
        """Every claim, formula or equation row whose verdict or status is in ``names``."""
        rows = [*self.claim_dicts(), *self.formula_dicts(), *self.equation_dicts()]
        return [r for r in rows if str(r.get("verdict", r.get("status"))) in names]

    def tally(self, key: str) -> str:
        """``"12 agrees, 1 truncated, 5 formula holds"``: the verdicts a paper reached."""
        counts = self.verdict_counts()[key]
        order = (*CLAIM_VERDICTS, *(f"formula {v}" for v in FORMULA_VERDICTS))
        return ", ".join(f"{counts[v]} {v}" for v in order if v in counts)


def _counts(*pairs: tuple[str, str]) -> tuple[Column, ...]:
    return tuple(Column(k, h, justify="left" if k == "paper" else "right") for k, h in pairs)


# The terminal summary, in two tables that each fit 80 columns.
_NUMBER_SUMMARY = _counts(("paper", "paper"), *((v, v) for v in CLAIM_VERDICTS))
_OWN_SUMMARY = _counts(
    ("paper", "paper"),
    *((v, v) for v in (*PROCEDURE_VERDICTS, "no procedure")),
    ("root causes", "roots"),
    ("propagated", "carried"),
)
_FORMULA_SUMMARY = _counts(
    ("paper", "paper"), ("formulas holding", "formulas hold"), ("formulas failing", "fail")
)
_EQUATION_SUMMARY = _counts(
    ("equations", "equations"),
    ("equations holds", "hold"),
    ("equations fails", "fail"),
    ("equations misprint", "misprint"),
    ("equations restating", "restating"),
)


def reproduce_all(
    keys: tuple[str, ...],
    formulas: bool = True,
    quiet: bool = True,
    stability: bool = False,
    jobs: int | None = None,
    equations: bool = False,
    cache: ResultCache | None = None,
    meanwhile: Callable[[], object] | None = None,
) -> ReproduceResult:
    """Evaluate the claims (and, if asked, the formula checks, the equation ledger and the
    stability measurements).

    With two cores this process and a forked worker share the steps, each taking the next one
    when free (``jobs=1`` or ``PENDCLI_JOBS=1``: all here). A progress bar on stderr counts the
    steps done, only on a terminal and when not ``quiet``. With a ``cache``
    (:func:`result_cache`), each paper's claims, formula checks and ledger (and the stability
    table) are read from it when stored, else computed and stored; without one (the library's
    default, and `pendcli check`'s) everything is computed. ``meanwhile``: done here while a
    forked worker takes its first step (the report's libraries loaded; no worker: not done).
    """
    wanted = _wanted(keys, formulas, equations, stability)
    stored = _cached(cache, wanted, keys)
    steps = _steps(keys, formulas, equations, stability, stored)
    computed = _computed(steps, keys, stored, quiet, jobs, meanwhile=meanwhile)
    _store_all(cache, computed, keys)
    return _result(keys, wanted, {**stored, **computed})


def _computed(
    steps: list[Step],
    keys: tuple[str, ...],
    stored: dict[Wanted, Any],
    quiet: bool,
    jobs: int | None,
    title: str = "reproducing",
    meanwhile: Callable[[], object] | None = None,
) -> dict[Wanted, Any]:
    """The steps run, shared by this process and the forked workers (reproduce_all), and
    gathered into one value per cached unit: a ledger's parts back in its order."""
    from pendcli.base.console import progress_bar, status_line
    from pendcli.base.workers import ForkedWorkers, counting_rows, job_count
    from pendcli.data.ledger import load_ledger
    from pendcli.papers.registry import paper
    from pendcli.verify.ledger_evaluation import with_measured
    from pendcli.verify.ledger_references import say_derived_afresh, stale_ledgers

    # found before the workers fork (they inherit that it is said), said once at the end
    judged = {k for k, w in steps if "equations" in w}
    stale = stale_ledgers([paper(k) for k in sorted(judged)])
    # formula checks computed in a step of this run: the ledger's parts leave out what they found
    unmeasured = frozenset(judged & {k for k, w in steps if "formulas" in w})

    workers = job_count(jobs, len(steps)) - 1
    if workers:
        status_line("" if quiet else f"{title}: loading the libraries")
        _preload(steps, keys)
    # one process: the steps as listed, the claims first (a published table that does not
    # match the code fails at once, not after every ledger); two: the costliest first
    order = _costliest_first(steps) if workers else steps
    rows = None if quiet or not sys.stderr.isatty() else sum(map(_part_rows, steps))
    status_line("")
    with contextlib.ExitStack() as lent:
        _lend_formula_rows(lent, stored, steps)
        done = lent.enter_context(counting_rows())  # before the fork: workers count too
        bar = progress_bar(quiet, len(steps), title, (rows, done) if rows else None)
        with ForkedWorkers(workers) as pool, bar as advance:
            run = functools.partial(_run_step, papers=keys, unmeasured=unmeasured)
            values = pool.share(
                order, run, lambda step, _: advance(_named(step), 1), _named, first=meanwhile
            )
    by_step = dict(zip(order, values, strict=True))
    computed: dict[Wanted, Any] = {}
    ledger_parts: dict[str, list[tuple[int, list[EquationRow]]]] = {}
    for step in steps:  # gathered in one order whoever computed what, so the output is too
        _gather(computed, ledger_parts, *step, by_step[step])
    for key, parts in ledger_parts.items():  # the ledger's parts, back in its order
        computed[key, "equations"] = [
            row for _, rows in sorted(parts, key=lambda p: p[0]) for row in rows
        ]
    for key in sorted(unmeasured):  # what the formula checks found, added once, not rerun
        ledger, formulas = load_ledger(key), computed[key, "formulas"]
        computed[key, "equations"] = with_measured(computed[key, "equations"], ledger, formulas)
    say_derived_afresh(stale)
    return computed


# (paper key or "all", what): one cached unit, "claims", "formulas", "equations" (a whole
# ledger) or "stability" (the table of every paper asked for)
Wanted = tuple[str, str]


def _wanted(
    keys: tuple[str, ...], formulas: bool, equations: bool, stability: bool
) -> list[Wanted]:
    out = [(k, "claims") for k in keys]
    out += [(k, "formulas") for k in keys if formulas]
    out += [(k, "equations") for k in keys if equations]
    return out + ([("all", "stability")] if stability else [])


def result_cache(use: bool = True) -> ResultCache:
    """This run's result cache (:mod:`pendcli.base.cache`): its folder from
    ``$PENDCLI_CACHE`` (off: ``use`` False or ``PENDCLI_CACHE=off``), its key over pendcli's
    code, every registered paper's own package, the tables folder in use and the versions."""
    from pendcli.base.cache import ResultCache, cache_folder
    from pendcli.data.tables import tables_dir
    from pendcli.papers.registry import all_papers

    return ResultCache(cache_folder() if use else None, tables_dir(), _paper_sources(all_papers()))


def _paper_sources(papers: Iterable[Paper]) -> list[Path]:
    """The package folder each paper's code lives in (its ``recompute``'s top-level package)."""
    from pathlib import Path

    folders = []
    for found in papers:
        top = str(getattr(found.recompute, "__module__", "") or "").split(".")[0]
        module = sys.modules.get(top)
        where = getattr(module, "__file__", None)
        if where:
            folders.append(Path(where).resolve().parent)
    return folders


# How each cached unit is written and read back (the stability table is plain JSON already).
_ROW_CLASSES: dict[str, type] = {
    "claims": ClaimRow,
    "formulas": FormulaRow,
    "equations": EquationRow,
}


def _params(item: Wanted, keys: tuple[str, ...]) -> dict[str, Any]:
    key, what = item
    return {"papers": list(keys)} if what == "stability" else {"paper": key}


def _cached(
    cache: ResultCache | None, wanted: list[Wanted], keys: tuple[str, ...]
) -> dict[Wanted, Any]:
    """What ``cache`` holds of ``wanted``; an entry that does not read back as rows is a miss."""
    if cache is None or not cache.enabled:
        return {}
    found: dict[Wanted, Any] = {}
    for item in wanted:
        value = cache.get(item[1], _params(item, keys))
        if value is None:
            continue
        try:
            found[item] = _decoded(item[1], value)
        except (TypeError, ValueError, KeyError, AttributeError):
            continue  # written by other code under a colliding key, or damaged: recompute
    return found


def _decoded(what: str, value: Any) -> Any:
    from pendcli.base.cache import rows_from_json

    if what in _ROW_CLASSES:
        return rows_from_json(_ROW_CLASSES[what], value)
    if not isinstance(value, list) or not all(
        isinstance(row, dict) and all(isinstance(v, str) for v in row.values()) for row in value
    ):
        raise TypeError("not a list of rows of text")
    return value


def _store_all(
    cache: ResultCache | None, computed: dict[Wanted, Any], keys: tuple[str, ...]
) -> None:
    """Each computed unit into ``cache`` (none: nothing stored)."""
    if cache is not None:
        for item, value in computed.items():
            _store_in_cache(cache, item, value, keys)


def _store_in_cache(cache: ResultCache, item: Wanted, value: Any, keys: tuple[str, ...]) -> None:
    from pendcli.base.cache import rows_to_json

    try:
        encoded = rows_to_json(value) if item[1] in _ROW_CLASSES else value
    except TypeError:
        return  # a value JSON cannot carry exactly: computed each time
    cache.put(item[1], _params(item, keys), encoded)


def ledger_rows(
    keys: tuple[str, ...],
    cache: ResultCache | None = None,
    quiet: bool = True,
    jobs: int | None = None,
) -> list[EquationRow]:
    """The equation ledgers of the papers ``keys`` (`pendcli equations`), each read from
    ``cache`` when stored, else computed (and stored): each ledger's parts (:data:`LEDGER_PARTS`)
    shared by this process and a forked worker, as in :func:`reproduce_all` (``jobs=1``: here)."""
    wanted = [(k, "equations") for k in keys]
    stored = _cached(cache, wanted, keys)
    steps = _steps(keys, formulas=False, equations=True, stability=False, stored=stored,
                   claims=False)  # fmt: skip
    computed = _computed(steps, keys, stored, quiet, jobs, "checking every equation (sympy)")
    _store_all(cache, computed, keys)
    found = {**stored, **computed}
    return [row for item in wanted for row in found[item]]


def _result(
    keys: tuple[str, ...], wanted: list[Wanted], values: dict[Wanted, Any]
) -> ReproduceResult:
    result = ReproduceResult(papers=keys)
    for key, what in wanted:
        if what == "stability":
            result.stability = values[key, what]
        else:
            getattr(result, what)[key] = values[key, what]
    return result


# Each ledger is cut in this many contiguous parts, taken by whichever process is free. Four
# against two, paired runs: equations cold 1.06x the wall, reproduce --out 0.94x: no gain.
LEDGER_PARTS = 2


def _steps(
    keys: tuple[str, ...],
    formulas: bool,
    equations: bool,
    stability: bool,
    stored: dict[Wanted, Any] | None = None,
    claims: bool = True,
) -> list[Step]:
    """The steps of a run, for what is not ``stored``. Each ledger is cut in LEDGER_PARTS parts
    that two processes can share; the first goes with the formula checks, lent to it, the others
    get what they found once all is back: computed once (stored formula rows are lent to all)."""
    from pendcli.verify.ledger_evaluation import names_formula_checks

    have = stored or {}
    steps = [(k, "claims") for k in keys if claims and (k, "claims") not in have]
    for k in keys:
        need_formulas = formulas and (k, "formulas") not in have
        need_ledger = equations and (k, "equations") not in have
        if need_formulas:
            steps.append((k, f"formulas+equations 0/{LEDGER_PARTS}" if need_ledger else "formulas"))
        elif need_ledger and (k, "formulas") not in have and names_formula_checks(k):
            steps.append((k, "formulas"))  # what its `measured` rows read: a step of its own
    for k in keys:
        if equations and (k, "equations") not in have:
            together = formulas and (k, "formulas") not in have
            steps += [
                (k, f"equations {i}/{LEDGER_PARTS}")
                for i in range(1 if together else 0, LEDGER_PARTS)
            ]
    if stability and ("all", "stability") not in have:
        steps.append(("all", "stability"))
    return steps


def _part_rows(step: Step) -> int:
    """How many ledger rows a step judges (0: none, or its ledger does not load: it says why)."""
    from pendcli.base.errors import PendcliError
    from pendcli.data.ledger import load_ledger

    key, what = step
    if not what.startswith(("equations", "formulas+equations")):
        return 0
    index, count = (int(x) for x in what.rsplit(" ", 1)[1].split("/"))
    try:
        size = len(load_ledger(key).rows)
    except (PendcliError, OSError):
        return 0
    return size * (index + 1) // count - size * index // count


Step = tuple[str, str]


def _named(step: Step) -> str:
    """``tisserand: equations 1/2``: a step as the progress bar and a worker's death name it."""
    return f"{step[0]}: {step[1]}"


def _costliest_first(steps: list[Step]) -> list[Step]:
    """The order the processes take the steps in, with no timings: the ledgers' parts, the
    largest ledger's first (its part of 1.8 s CPU, taken last, left the other process idle),
    the part with the formula checks first, checks of their own after their ledger's parts;
    then the stability table, the claims last (the smallest, they fill the gaps)."""
    rank = {"equations": 0, "formulas+equations": 0, "formulas": 0, "stability": 1}
    rows = {k: sum(_part_rows(s) for s in steps if s[0] == k) for k, _ in steps}

    def key(s: Step) -> tuple[int, int, bool, bool]:
        return rank.get(s[1].split()[0], 3), -rows[s[0]], "+" not in s[1], s[1] == "formulas"

    return sorted(steps, key=key)


def _preload(steps: list[Step], papers: tuple[str, ...]) -> None:
    """Import, once and before the fork, what both processes would otherwise each import:
    the papers' modules, scipy (~0.35 s), and sympy, mpmath and the references for a ledger."""
    import scipy.integrate
    import scipy.special  # noqa: F401

    from pendcli.papers.registry import paper

    for key in dict.fromkeys(key for key, _ in steps if key != "all"):
        preload = paper(key).preload
        if preload is not None:
            preload()
    if any("equations" in what for _, what in steps):
        import mpmath  # noqa: F401
        import sympy  # noqa: F401

        for key in papers:
            references = paper(key).references
            if references is not None:
                references()


def _run_step(step: Step, papers: tuple[str, ...], unmeasured: frozenset[str]) -> Any:
    key, what = step
    if what == "claims":
        return claim_rows(key)
    if what == "formulas":
        return formula_checks(key)
    if what.startswith(("equations", "formulas+equations")):
        return _ledger_step(key, what, what.startswith("formulas") or key not in unmeasured)
    from pendcli.papers.registry import stability_rows

    return stability_rows(papers)


def _ledger_step(key: str, what: str, measure: bool = True) -> Any:
    """``equations i/n``: (i, that part of the ledger; ``measure`` False: without what the
    formula checks found); ``formulas+equations i/n``: the formula checks too, lent to it."""
    from pendcli.papers.registry import equation_rows
    from pendcli.verify.claims import sharing_formula_rows

    index, count = (int(x) for x in what.rsplit(" ", 1)[1].split("/"))
    rows = formula_checks(key) if what.startswith("formulas") else None
    with sharing_formula_rows(key, rows) if rows is not None else nullcontext():
        part = equation_rows([key], part=(index, count), measure=measure)
    return (rows, (index, part)) if rows is not None else (index, part)


def _gather(
    computed: dict[Wanted, Any],
    ledger_parts: dict[str, list[tuple[int, list[EquationRow]]]],
    key: str,
    what: str,
    value: Any,
) -> None:
    if what in ("claims", "formulas"):
        computed[key, what] = value
    elif what.startswith("equations"):
        ledger_parts.setdefault(key, []).append(value)
    elif what.startswith("formulas+equations"):
        computed[key, "formulas"], part = value
        ledger_parts.setdefault(key, []).append(part)
    else:
        computed[key, "stability"] = value


def _lend_formula_rows(
    stack: contextlib.ExitStack, stored: dict[Wanted, Any], steps: list[Step]
) -> None:
    """Lend the stored formula rows to the ledger's checks that re-read them (before the fork:
    a worker inherits them); rows computed in this run are added once all is back."""
    from pendcli.verify.claims import sharing_formula_rows

    for key in dict.fromkeys(k for k, what in steps if what.startswith("equations")):
        if (key, "formulas") in stored:
            stack.enter_context(sharing_formula_rows(key, stored[key, "formulas"]))


# Every verdict (claims, formulas) and status (equations) a row can have, best first.
VERDICT_NAMES = tuple(dict.fromkeys(map(str, (*CLAIM_VERDICTS, *FORMULA_VERDICTS, *STATUSES))))
# Statuses only the equation ledger gives: asking to fail on one runs the ledger.
EQUATION_ONLY = frozenset(VERDICT_NAMES) - {*CLAIM_VERDICTS, *FORMULA_VERDICTS}


def parse_verdicts(text: str, option: str = "--fail-on") -> frozenset[str]:
    """``"discrepant,fails"`` -> the set of names; an unknown one is a one-line error."""
    from pendcli.base.errors import invalid_value

    names = [n.strip().casefold() for n in text.split(",") if n.strip()]
    for name in names or [text]:
        if name not in VERDICT_NAMES:
            expected = f"one or more of {', '.join(VERDICT_NAMES)} (comma-separated)"
            raise invalid_value(option, name, expected)
    return frozenset(names)
