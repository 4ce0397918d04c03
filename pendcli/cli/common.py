"""Shared CLI pieces: options, the console, and printing rows in the chosen format."""

from __future__ import annotations

import sys
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from enum import StrEnum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from pendcli.base.console import console
from pendcli.cli.values import word
from pendcli.output import OutputFormat, Section

if TYPE_CHECKING:
    from pendcli.base.cache import ResultCache


class CheckFormat(StrEnum):
    """`pendcli check --format`: the same names as :class:`pendcli.output.check_formats.CheckFormat`
    (kept here so `pendcli --help` does not import the check's modules)."""

    table = "table"
    json = "json"
    junit = "junit"


def bad_value(option: str, value: object, expected: str) -> Exception:
    """The one wording of a refused value: ``--option: 'value' ...; expected ...``."""
    from pendcli.base.errors import invalid_value

    return invalid_value(option, value, expected)


def _paper_value(value: str | None) -> str | None:
    """``--paper`` checked while parsing, before any work (and with the common wording)."""
    from pendcli.papers.registry import PAPERS

    if value is not None and value.strip().casefold() not in PAPERS:
        from pendcli.base.errors import either

        raise bad_value("--paper", value, f"one of {either(PAPERS)}")
    return value


def complete_papers(incomplete: str) -> list[str]:
    """Shell completion of ``--paper``."""
    from pendcli.papers.registry import PAPERS

    return [p for p in PAPERS if p.startswith(incomplete.casefold())]


def complete_verdicts(incomplete: str) -> list[str]:
    """Shell completion of a comma-separated list of verdicts or statuses (``--fail-on``)."""
    from pendcli.run.reproduce import VERDICT_NAMES

    done, _, last = incomplete.rpartition(",")
    prefix = f"{done}," if done else ""
    return [prefix + v for v in VERDICT_NAMES if v.startswith(last.casefold())]


def complete_statuses(incomplete: str) -> list[str]:
    """Shell completion of ``--status`` (the equation ledger's statuses)."""
    from pendcli.data.vocabulary import STATUSES

    return [s for s in STATUSES if s.startswith(incomplete.casefold())]


FormatOption = Annotated[
    OutputFormat,
    typer.Option("--format", "-f", help="Output format.", case_sensitive=False),
]
PaperOption = Annotated[
    str | None,
    typer.Option(
        "--paper",
        "-p",
        help="Only this paper: tisserand, lecornu or charbonnier.",
        metavar="PAPER",
        parser=word,
        callback=_paper_value,
        autocompletion=complete_papers,
    ),
]
PlotOption = Annotated[
    Path | None,
    typer.Option(
        "--plot", metavar="FILE", help="Also draw the comparison to this file (.png, .svg or .pdf)."
    ),
]
CacheOption = Annotated[
    bool,
    typer.Option(
        "--cache/--no-cache",
        help="Read and store results in the result cache ($PENDCLI_CACHE; off: compute "
        "everything afresh). Its key covers the code, the tables and the library versions.",
    ),
]


def _quiet_flag(value: bool) -> bool:
    from pendcli.base.console import set_quiet

    set_quiet(bool(value))
    return value


# `--quiet/-q` for a command without a quiet of its own: silences :func:`say` (its value is not
# passed on: a command declares ``quiet: QuietFlag = False`` and reads nothing from it).
QuietFlag = Annotated[
    bool,
    typer.Option(
        "--quiet",
        "-q",
        help="No status lines on stderr (method chosen, files written).",
        callback=_quiet_flag,
        expose_value=False,
    ),
]


def refuse_both(first: str, first_value: object, second: str, second_value: object) -> None:
    """Options that exclude each other (``--tol`` and ``--method``): both given is an error."""
    if first_value is not None and second_value is not None:
        from pendcli.base.errors import PendcliError

        raise PendcliError(
            f"--{first} and --{second} exclude each other: --{first} picks the cheapest "
            f"method meeting the tolerance, --{second} forces one; give one of them"
        )


@contextmanager
def result_cache(use: bool, quiet: bool = False) -> Iterator[ResultCache]:
    """The run's result cache; after the run, one status line if it could not be written
    (none under ``quiet``, none after an error: that error is the one line)."""
    from pendcli.run.reproduce import result_cache as open_cache

    cache = open_cache(use)
    yield cache
    if cache.problem is not None and not quiet:
        say(cache.problem)


def emit(fmt: OutputFormat, sections: Sequence[Section], document: Mapping[str, object]) -> None:
    """Print titled sections of rows (tables) or the whole document (JSON, CSV, Markdown)."""
    from pendcli.base.console import for_display
    from pendcli.output import render

    # rich (~0.02 s to import) only for the table: the data formats never use the console.
    text = render(fmt, sections, document, console=console() if fmt is OutputFormat.table else None)
    # a table is for the eye: "?" keeps its columns; the data formats keep \uXXXX escapes
    sys.stdout.write(for_display(text) if fmt is OutputFormat.table else text)


def say(message: str) -> None:
    """A status line on stderr (so stdout stays machine-readable); nothing under --quiet."""
    from pendcli.base.console import is_quiet

    if not is_quiet():
        console(stderr=True).print(message)


@contextmanager
def busy(description: str) -> Iterator[None]:
    """A spinner with ``description`` on stderr while a slow step runs (a second or more:
    the equation ledger, drawing figures); only on a terminal, never under --quiet, and
    gone when the step ends, so nothing of it reaches a pipe or a log."""
    from pendcli.base.console import is_quiet

    if is_quiet() or not sys.stderr.isatty():
        yield
        return
    with console(stderr=True).status(description):
        yield
