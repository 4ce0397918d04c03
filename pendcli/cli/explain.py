"""`pendcli explain`: how the author got each printed number that does not agree."""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Annotated, Any

import typer

from pendcli.cli.common import FormatOption, PaperOption, QuietFlag, emit
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from pendcli.output import Section
    from pendcli.verify.explain import ExplainedRow

ClaimArgument = Annotated[
    str | None,
    typer.Argument(
        metavar="CLAIM", help="One claim id (pendcli list shows them); default: every row."
    ),
]


def explain(
    claim: ClaimArgument = None,
    paper: PaperOption = None,
    fmt: FormatOption = OutputFormat.table,
    quiet: QuietFlag = False,
) -> None:
    """The author's hand computation behind each wrong digit, with the odds of a coincidence."""
    from pendcli.papers.registry import resolve_papers

    claim = _as_listed(claim)
    keys = _papers_for(claim, paper) if claim else resolve_papers(paper)
    _show_start(keys)
    rows = [r for key in keys for r in _explained(key, claim)]
    _clear_progress()
    if claim and not rows:
        raise _nothing_to_explain(claim)
    sections = _sections(rows, keys) + (_steps_sections(rows[0]) if claim else [])
    emit(fmt, sections, {"explanations": [r.as_dict() for r in rows]})


def _as_listed(claim: str | None) -> str | None:
    """The claim id as `pendcli list` spells it, whatever the case typed (ids hold capitals:
    ``charbonnier.I_pi.n3``); an unknown id as typed (refused with the list's pointer)."""
    if claim is None:
        return None
    from pendcli.data.tables import load_paper_table
    from pendcli.papers.registry import PAPERS

    key = claim.split(".", 1)[0].strip().casefold()
    if key not in PAPERS:
        return claim
    wanted = claim.strip().casefold()
    found = [c.id for c in load_paper_table(key).claims if c.id.casefold() == wanted]
    return found[0] if len(found) == 1 else claim


def _papers_for(claim: str, paper: str | None) -> tuple[str, ...]:
    """The paper holding ``claim`` (its id's first part), checked against --paper."""
    from pendcli.base.errors import PendcliError
    from pendcli.data.tables import load_paper_table
    from pendcli.papers.registry import PAPERS, resolve_papers

    key = claim.split(".", 1)[0].strip().casefold()
    known = key in PAPERS and any(c.id == claim for c in load_paper_table(key).claims)
    if not known:
        raise PendcliError(
            f"unknown claim {claim!r}; `pendcli list` shows every claim id "
            f"(ids start with {', '.join(p + '.' for p in PAPERS)})"
        )
    if paper is not None and resolve_papers(paper) != (key,):
        raise PendcliError(f"claim {claim!r} belongs to {key}, not to --paper {paper}")
    return (key,)


def _nothing_to_explain(claim: str) -> Exception:
    from pendcli.base.errors import PendcliError

    return PendcliError(
        f"claim {claim!r} agrees with its recomputation and declares no hand computation: "
        "nothing to explain (`pendcli explain` lists the rows it explains)"
    )


def _explained(key: str, claim: str | None) -> list[ExplainedRow]:
    from pendcli.papers.registry import claim_rows, explanations
    from pendcli.verify.explain import explain_rows

    verdicts = {r.id: (r.verdict, r.cause, r.published) for r in claim_rows(key)}
    return explain_rows(key, explanations(key), verdicts, claim, progress=_progress(key))


def _progress(key: str) -> Callable[[str], None] | None:
    """A one-line status on a terminal's stderr (nothing in a pipe or under --quiet)."""
    from pendcli.base.console import is_quiet

    if is_quiet() or not sys.stderr.isatty():
        return None

    def show(claim_id: str) -> None:
        sys.stderr.write(f"\r\033[Kexplain {key}: searching {claim_id}")
        sys.stderr.flush()

    return show


def _show_start(keys: tuple[str, ...]) -> None:
    """A first status line at once (the recomputation before the first search takes seconds)."""
    from pendcli.base.console import is_quiet

    if not is_quiet() and sys.stderr.isatty():
        sys.stderr.write(f"\r\033[Kexplain {keys[0]}: recomputing the claims")
        sys.stderr.flush()


def _clear_progress() -> None:
    from pendcli.base.console import is_quiet

    if not is_quiet() and sys.stderr.isatty():
        sys.stderr.write("\r\033[K")
        sys.stderr.flush()


def _sections(rows: list[ExplainedRow], keys: tuple[str, ...]) -> list[Section]:
    from pendcli.output import Column
    from pendcli.output.views import printed_for_display

    columns = [
        Column("id", "claim"),
        Column("printed", "printed", fmt=lambda r: printed_for_display(r["printed"])),
        Column("verdict", "verdict"),
        Column("cause", "cause and mechanism"),
        Column("cost", "steps", justify="right"),
        Column("coincidence", "coincidence", fmt=_rate("coincidence"), justify="right"),
        Column("coincidence_near", "near", fmt=_rate("coincidence_near"), justify="right"),
    ]
    return [
        (
            f"{key.capitalize()}: how the printed digits were got (coincidence: share of "
            "random targets of the same size the search reproduces as simply)",
            [r.as_dict() for r in rows if r.paper == key],
            columns,
        )
        for key in keys
        if any(r.paper == key for r in rows)
    ]


def _steps_sections(row: ExplainedRow) -> list[Section]:
    """One claim: every step of its simplest chains, and the space searched."""
    from pendcli.output import Column

    d = row.as_dict()
    chains = d["steps"] if isinstance(d["steps"], list) else []
    steps = [
        {"chain": n, "step": k, "what": label}
        for n, chain in enumerate(chains, start=1)
        for k, label in enumerate(chain, start=1)
    ]
    step_columns = [Column("chain", "chain"), Column("step", "step"), Column("what", "what")]
    searched = [{"searched": d["searched"]}]
    return [
        (f"{row.id}: the simplest chains, step by step", steps, step_columns),
        ("what was searched", searched, [Column("searched", "searched")]),
    ]


def _rate(key: str) -> Callable[[Mapping[str, Any]], str]:
    def text(row: Mapping[str, Any]) -> str:
        value = row.get(key)
        return "-" if not isinstance(value, float) else f"{value:.1%}"

    return text
