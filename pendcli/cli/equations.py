"""`pendcli equations`: every numbered equation and stated result, with its status and check."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from pendcli.cli.common import (
    CacheOption,
    FormatOption,
    PaperOption,
    QuietFlag,
    bad_value,
    busy,
    complete_statuses,
    emit,
    result_cache,
)
from pendcli.cli.values import word
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from pendcli.base.cache import ResultCache

StatusOption = Annotated[
    str | None,
    typer.Option(
        "--status",
        "-s",
        metavar="STATUS",
        parser=word,
        help="Only this status: holds, fails, misprint, definition or not-checkable.",
        autocompletion=complete_statuses,
    ),
]


NotesOption = Annotated[
    bool, typer.Option("--notes", help="Table format: every column (statement, check, note).")
]


def equations(
    paper: PaperOption = None,
    status: StatusOption = None,
    notes: NotesOption = False,
    fmt: FormatOption = OutputFormat.table,
    cache: CacheOption = True,
    quiet: QuietFlag = False,
) -> None:
    """The equation ledger: each equation's status, checked (exit 0 whatever the statuses)."""
    from pendcli.base.console import is_quiet
    from pendcli.data.vocabulary import STATUSES
    from pendcli.output import Column
    from pendcli.output.summary import compact_equation_columns
    from pendcli.output.views import EQUATION_COLUMNS
    from pendcli.papers.registry import resolve_papers
    from pendcli.run.reproduce import ledger_rows
    from pendcli.verify.ledger_evaluation import coverage

    if status is not None and status not in STATUSES:
        from pendcli.base.errors import either

        raise bad_value("--status", status, f"one of {either(STATUSES)}")
    with result_cache(cache) as stored:
        # a progress bar of the ledgers' parts on a terminal (the workers fork before it)
        rows = ledger_rows(resolve_papers(paper), stored, quiet=is_quiet())
        with busy("reading the texts' display formulas"):
            counts = coverage(rows)
            texts = {p: _text_coverage(stored, p) for p in counts}
    shown = [r.as_dict() for r in rows if status is None or r.status == status]
    compact = fmt is OutputFormat.table and not notes
    columns = compact_equation_columns() if compact else EQUATION_COLUMNS
    tally = [{"paper": p, **c, **texts[p]} for p, c in counts.items()]
    # The text's display formulas ($$ blocks) inside some row's lines, of all of them; its
    # paragraphs of prose the reading record accounts for, of all of them.
    count_columns = [
        *(Column(k, k) for k in ("paper", *STATUSES, "total", "checked")),
        Column("blocks_covered", "$$ covered"),
        Column("blocks", "$$ blocks"),
        Column("paragraphs_read", "¶ read"),
        Column("paragraphs", "¶ prose"),
        Column("findings", "findings"),  # failing or misprinted, restating no other row
        Column("restating", "restating"),
    ]
    hint = " (--notes: what each states, how it is checked)" if compact else ""
    sections = [
        (f"{key.capitalize()}: equations{hint}", [r for r in shown if r["paper"] == key], columns)
        for key in counts
    ]
    emit(
        fmt,
        [*(s for s in sections if s[1]), ("coverage", tally, count_columns)],
        {"equations": shown, "coverage": {p: {**c, **texts[p]} for p, c in counts.items()}},
    )


def _text_coverage(cache: ResultCache, paper: str) -> dict[str, object]:
    """The ``$$`` blocks of the paper's text its ledger covers and the paragraphs of prose its
    reading record accounts for (cached with the ledger: the ledger's validation imports
    sympy)."""
    from pendcli.base.cache import cached_json
    from pendcli.data.ledger_coverage import ledger_text_coverage
    from pendcli.data.reading import reading_coverage

    def compute() -> dict[str, object]:
        return {**ledger_text_coverage(paper).as_dict(), **reading_coverage(paper).as_dict()}

    found: dict[str, object] = cached_json(
        cache, "text-coverage", {"paper": paper}, compute, _is_coverage
    )
    return found


def _is_coverage(value: object) -> bool:
    """A stored coverage has the keys and types ``TextCoverage.as_dict`` gives."""
    keys = {"blocks", "blocks_covered", "blocks_share", "uncovered_lines"}
    keys |= {"paragraphs", "paragraphs_read", "unread_paragraphs", "labels_printed_twice"}
    if not isinstance(value, dict) or set(value) != keys:
        return False
    counts = [value[k] for k in ("blocks", "blocks_covered", "paragraphs", "paragraphs_read")]
    lines = value["uncovered_lines"]
    spans, twice = value["unread_paragraphs"], value["labels_printed_twice"]
    if type(lines) is not list or type(value["blocks_share"]) not in (int, float):
        return False
    if type(spans) is not list or not all(type(s) is list and len(s) == 2 for s in spans):
        return False
    if type(twice) is not dict or not all(type(v) is list for v in twice.values()):
        return False
    numbers = [
        *counts,
        *lines,
        *(n for s in spans for n in s),
        *(n for v in twice.values() for n in v),
    ]
    return all(type(n) is int for n in numbers)
