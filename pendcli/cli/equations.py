"""`pendcli equations`: every numbered equation and stated result, with its status and check."""

from __future__ import annotations

from typing import Annotated

import typer

from pendcli.cli.common import FormatOption, PaperOption, emit
from pendcli.render import OutputFormat

StatusOption = Annotated[
    str | None,
    typer.Option(
        "--status",
        "-s",
        help="Only this status: holds, fails, misprint, definition or not-checkable.",
    ),
]


def equations(
    paper: PaperOption = None, status: StatusOption = None, fmt: FormatOption = OutputFormat.table
) -> None:
    """The equation ledger: each equation's status, checked (exit 0 whatever the statuses)."""
    from pendcli.core.claims import resolve_papers
    from pendcli.core.errors import PendcliError
    from pendcli.core.ledger import coverage, equation_rows
    from pendcli.core.ledger_check import STATUSES
    from pendcli.render import Column

    if status is not None and status not in STATUSES:
        raise PendcliError(f"unknown status {status!r}; choose one of {', '.join(STATUSES)}")
    rows = equation_rows(resolve_papers(paper))
    counts = coverage(rows)
    shown = [r for r in rows if status is None or r["status"] == status]
    cut = {"check": 60, "note": 60, "section": 24}
    keys = ("id", "equation", "section", "status", "check", "observed_order", "note")
    columns = [Column(k, k, table_max=cut.get(k)) for k in keys]
    tally = [{"paper": p, **c} for p, c in counts.items()]
    count_columns = [Column(k, k) for k in ("paper", *STATUSES, "total", "checked")]
    emit(
        fmt,
        [("equations", shown, columns), ("coverage", tally, count_columns)],
        {"equations": shown, "coverage": counts},
    )
