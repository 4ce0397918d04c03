"""The `pendcli` app: its options (-V, --verbose), the commands that read or run every paper
(`list`, `reproduce`, `check`) and, through :class:`~pendcli.cli.lazy.LazyGroup`, the others,
each loaded when named."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from pendcli.cli.common import (
    CacheOption,
    CheckFormat,
    FormatOption,
    PaperOption,
    QuietFlag,
    complete_verdicts,
    emit,
)
from pendcli.cli.help_format import command, epilog
from pendcli.cli.lazy import LazyGroup
from pendcli.cli.values import word
from pendcli.output import OutputFormat

if TYPE_CHECKING:
    from pendcli.base.cache import ResultCache
    from pendcli.run.reproduce import ReproduceResult

__all__ = ["app"]

app = typer.Typer(
    cls=LazyGroup,
    name="pendcli",
    epilog=epilog(""),
    help=(
        "Regenerate, number by number, the claims of three historical papers on the pendulum "
        "(Tisserand 1881, Lecornu after 1894, Charbonnier 1908): published against recomputed "
        "values. "
        "A number may be typed with a decimal point or a decimal comma (9.81 or 9,81), a word "
        "of a list in any case (-p LECORNU)."
    ),
    no_args_is_help=True,
    # -h as well as --help, in every command (click passes it down to each subcommand).
    context_settings={"help_option_names": ["-h", "--help"]},
    pretty_exceptions_enable=False,
    # --install-completion / --show-completion; completion asks LazyGroup, which loads a
    # subcommand's module only when the word being completed needs it.
    add_completion=True,
    # Plain click help: typer's rich help imports rich.markdown and markdown_it (~130 ms),
    # more than the rest of start-up together.
    rich_markup_mode=None,
)


def _version(ctx: typer.Context, value: bool) -> None:
    ctx.meta["pendcli.version"] = value
    _show_version(ctx)


def _verbose(ctx: typer.Context, value: bool) -> None:
    ctx.meta["pendcli.verbose"] = value
    _show_version(ctx)


def _show_version(ctx: typer.Context) -> None:
    """Once both eager options are read (in either order): the version, with --verbose every
    library's too."""
    if "pendcli.version" not in ctx.meta or "pendcli.verbose" not in ctx.meta:
        return
    if ctx.meta["pendcli.version"]:
        from pendcli.base.versions import library_versions

        versions = library_versions()
        shown = versions if ctx.meta["pendcli.verbose"] else versions[2:3]
        print("\n".join(f"{name} {found}" for name, found in shown))
        raise typer.Exit()


@app.callback()
def main(
    version: Annotated[
        bool,
        typer.Option(
            "--version", "-V", callback=_version, is_eager=True, help="Show the version and exit."
        ),
    ] = False,
    verbose: Annotated[
        bool,
        typer.Option(
            "--verbose", callback=_verbose, is_eager=True, help="With -V: every library's too."
        ),
    ] = False,
) -> None:
    """Published against recomputed values for Tisserand, Lecornu and Charbonnier."""


@command(app, "list")
def list_claims(
    paper: PaperOption = None, fmt: FormatOption = OutputFormat.table, quiet: QuietFlag = False
) -> None:
    """Every claim with its id, paper and source (reads the tables only; computes nothing)."""
    from pendcli.data.reader_text import for_reader
    from pendcli.output import Column
    from pendcli.papers.registry import resolve_papers
    from pendcli.verify.claims import list_rows

    rows = list_rows(resolve_papers(paper))

    def raised(key: str) -> Column:  # the OCR's 0^m,5 as the page prints it, 0ᵐ,5
        return Column(key, key, fmt=lambda r: for_reader(str(r.get(key) or ""), plain=True))

    columns = [raised(k) if k in ("source", "quantity", "published") else Column(k, k)
               for k in ("id", "paper", "source", "quantity", "published", "unit")]  # fmt: skip
    emit(fmt, [("", rows, columns)], {"claims": rows})


OutOption = Annotated[
    Path | None,
    typer.Option(
        "--out",
        "-o",
        metavar="DIR",
        help="Also write the report, tables and figures to this folder (replaced whole; a new "
        "one is created inside an existing folder, never a chain of missing ones).",
    ),
]
FormulasOption = Annotated[
    bool, typer.Option("--formulas/--no-formulas", help="Include the checks of derived formulas.")
]
StabilityOption = Annotated[
    bool | None,
    typer.Option(
        "--stability/--no-stability",
        help="Include the measured stability table (default: only with --out).",
    ),
]
QuietOption = Annotated[bool, typer.Option("--quiet", "-q", help="No progress or status lines.")]


EquationsOption = Annotated[
    bool | None,
    typer.Option(
        "--equations/--no-equations",
        help="Check every numbered equation too (the ledger: sympy and ODE work, its cost "
        "measured in docs/benchmarks.md). Default: only with --out.",
    ),
]


NotesOption = Annotated[
    bool, typer.Option("--notes", help="Table format: every column, notes included.")
]
OnlyFailingOption = Annotated[
    bool, typer.Option("--only-failing", help="Only the rows that do not agree, hold or check.")
]
MeasureOption = Annotated[
    bool, typer.Option("--measure", help="With --out: time the speed families now.")
]
PdfOption = Annotated[
    bool,
    typer.Option("--pdf", help="With --out: print each HTML page to PDF (headless Chromium)."),
]
FailOnOption = Annotated[
    str | None,
    typer.Option(
        "--fail-on",
        metavar="VERDICT[,...]",
        parser=word,
        help="Exit 1 when any row has one of these verdicts or statuses (for CI), e.g. "
        "discrepant,fails. An equation status (misprint...) runs the ledger.",
        autocompletion=complete_verdicts,
    ),
]


@command(app, "reproduce")
def reproduce(
    paper: PaperOption = None,
    fmt: FormatOption = OutputFormat.table,
    out: OutOption = None,
    formulas: FormulasOption = True,
    equations: EquationsOption = None,
    stability: StabilityOption = None,
    notes: NotesOption = False,
    only_failing: OnlyFailingOption = False,
    quiet: QuietOption = False,
    measure: MeasureOption = False,
    pdf: PdfOption = False,
    fail_on: FailOnOption = None,
    cache: CacheOption = True,
) -> None:
    """Every claim, published against recomputed, with a verdict (exit 0 unless --fail-on)."""
    from pendcli.cli.common import result_cache
    from pendcli.output.report_figures import load_drawing_libraries
    from pendcli.papers.registry import resolve_papers
    from pendcli.run.reproduce import EQUATION_ONLY, reproduce_all

    fail_names = _fail_names(fail_on)
    if fail_names & EQUATION_ONLY and equations is None:
        equations = True
    _check_report_options(out, measure, pdf)
    with result_cache(cache, quiet) as stored:
        if out is not None:  # a cache inside the report's folder would be replaced with it
            stored.keep_out_of(out)
        result = reproduce_all(
            resolve_papers(paper),
            formulas=formulas,
            stability=(out is not None) if stability is None else stability,
            equations=(out is not None) if equations is None else equations,
            quiet=quiet or fmt is not OutputFormat.table,
            cache=stored,
            meanwhile=None if out is None else load_drawing_libraries,
        )
        compact = fmt is OutputFormat.table and not notes
        emit(fmt, result.sections(compact, only_failing), result.document(only_failing))
        if compact:
            from pendcli.output.summary import CAUSE_LEGEND

            print(CAUSE_LEGEND)
        if out is not None:
            _write_report(result, out, quiet, measure, pdf, stored)
    if fail_names:
        _fail_on(result, fail_names, quiet)


def _check_report_options(out: Path | None, measure: bool, pdf: bool) -> None:
    """--measure and --pdf need --out; a bad --out folder is refused before the run, not after."""
    from pendcli.base.errors import PendcliError

    if measure and out is None:
        raise PendcliError("--measure needs --out (it re-times the report's speed families)")
    if pdf and out is None:
        raise PendcliError("--pdf needs --out (it prints the HTML pages written there)")
    if out is not None:
        from pendcli.cli.targets import check_replaced_folder
        from pendcli.output.report import check_out_folder

        check_replaced_folder(out, "--out")
        check_out_folder(out)


def _fail_names(text: str | None) -> frozenset[str]:
    if text is None:
        return frozenset()
    from pendcli.run.reproduce import parse_verdicts

    return parse_verdicts(text)


def _fail_on(result: ReproduceResult, names: frozenset[str], quiet: bool) -> None:
    """Exit 1 when a row has one of ``names`` (after the output, so CI logs show the table)."""
    from pendcli.cli.common import say

    hits = result.rows_with(names)
    if hits:
        if not quiet:
            ids = ", ".join(str(r["id"]) for r in hits[:5]) + (" ..." if len(hits) > 5 else "")
            say(f"--fail-on: {len(hits)} row(s) are {', '.join(sorted(names))}: {ids}")
        raise typer.Exit(1)


def _write_report(
    result: ReproduceResult,
    out: Path,
    quiet: bool,
    measure: bool,
    pdf: bool,
    cache: ResultCache | None = None,
) -> None:
    from pendcli.cli.common import say
    from pendcli.output.report import write_report

    written = write_report(result, out, quiet=quiet, measure=measure, pdf=pdf, cache=cache)
    if not quiet:
        for key in result.papers:
            say(f"{key}: {result.tally(key)}")
        say(f"wrote {len(written)} files to {out} (report: {out / 'report.md'})")


@command(app, "check")
def check(
    update: Annotated[
        bool, typer.Option("--update", help="Rewrite the committed regenerated tables instead.")
    ] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print only failures.")] = False,
    fmt: Annotated[
        CheckFormat,
        typer.Option(
            "--format",
            "-f",
            help="table (the drift table), json, or junit (JUnit XML: a testcase per claim, "
            "formula, ledger row and table). Under GitHub Actions each drift is also an ::error "
            "annotation.",
            case_sensitive=False,
        ),
    ] = CheckFormat.table,
) -> None:
    """Regenerate every table and compare with the committed ones (exit 1 on any drift).

    The tables are the claims, the formula checks and the equation ledgers' rows. A number
    may move within its column's tolerance (the last bits another libm or scipy changes);
    text (published, verdict, cause, a ledger row's status) must be identical. The drift table and
    --format json show each tolerance.
    """
    from pendcli.base.console import status_line
    from pendcli.run.regression import run_check

    if not quiet and fmt is CheckFormat.table:  # seconds before the progress bar can start
        status_line("check: reading the committed tables and the equation ledgers")
    if update and fmt is not CheckFormat.table:
        from pendcli.base.errors import PendcliError

        raise PendcliError(f"--format: {fmt.value!r} with --update; expected table")
    code = run_check(update=update, quiet=quiet, fmt=fmt.value)
    raise typer.Exit(code)
