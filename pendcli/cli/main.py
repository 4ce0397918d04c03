"""`pendcli`: the entry point. Commands are thin; errors are one line and a non-zero exit."""

from __future__ import annotations

import importlib
import os
import sys
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Annotated, NoReturn

import typer
from typer.core import TyperGroup

from pendcli.cli.common import FormatOption, PaperOption, emit
from pendcli.render import OutputFormat

if TYPE_CHECKING:  # click as typer vendors it; only its types are named here
    from typer._click import Command, Context, HelpFormatter

    from pendcli.reproduce import ReproduceResult

# Subcommands whose modules load only when named: `pendcli --help` then costs neither their
# imports nor typer's conversion of their parameters (about half of start-up otherwise).
# name -> (module, attribute: a Typer sub-app or a command function, short help for --help)
LAZY_COMMANDS: dict[str, tuple[str, str, str]] = {
    "tisserand": (
        "pendcli.cli.tisserand",
        "app",
        "Tisserand 1881: the conical pendulum, the example, series against the exact motion.",
    ),
    "lecornu": (
        "pendcli.cli.lecornu",
        "app",
        "Lecornu: the pendulum of variable length (zeros of J1/J2, the 0,35 m/s example).",
    ),
    "charbonnier": (
        "pendcli.cli.charbonnier",
        "app",
        "Charbonnier 1908: perturbations, the table of I_n(π), the integrals I_n(x).",
    ),
    "formulas": (
        "pendcli.cli.formulas",
        "formulas",
        "Derived formulas against direct numerical solutions: observed order, verdict.",
    ),
    "tradeoff": (
        "pendcli.cli.tradeoff",
        "tradeoff",
        "Speed against accuracy: each method's error and time (work-precision).",
    ),
}


def _load_command(name: str) -> Command:
    module_name, attribute, _ = LAZY_COMMANDS[name]
    target = getattr(importlib.import_module(module_name), attribute)
    if not isinstance(target, typer.Typer):
        target_app = typer.Typer(add_completion=False, rich_markup_mode=None)
        target_app.command(name)(target)
        target = target_app
    command = typer.main.get_command(target)
    command.name = name
    return command


class LazyGroup(TyperGroup):
    """The top-level group: eager commands first, then the lazily imported ones."""

    def list_commands(self, ctx: Context) -> list[str]:
        return [*super().list_commands(ctx), *(n for n in LAZY_COMMANDS if n not in self.commands)]

    def get_command(self, ctx: Context, cmd_name: str) -> Command | None:
        if cmd_name in LAZY_COMMANDS and cmd_name not in self.commands:
            self.commands[cmd_name] = _load_command(cmd_name)
        return super().get_command(ctx, cmd_name)

    def format_commands(self, ctx: Context, formatter: HelpFormatter) -> None:
        rows = []
        for name in self.list_commands(ctx):
            if name in LAZY_COMMANDS and name not in self.commands:
                rows.append((name, LAZY_COMMANDS[name][2]))
            else:
                rows.append((name, self.commands[name].get_short_help_str(limit=200)))
        with formatter.section("Commands"):
            formatter.write_dl(rows)


app = typer.Typer(
    cls=LazyGroup,
    name="pendcli",
    help=(
        "Regenerate, number by number, the claims of three historical papers on the pendulum "
        "(Tisserand 1881, Lecornu 1894, Charbonnier 1908): published against recomputed values."
    ),
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    add_completion=False,
    # Plain click help: typer's rich help imports rich.markdown and markdown_it (~130 ms),
    # more than the rest of start-up together.
    rich_markup_mode=None,
)


def _version(value: bool) -> None:
    if value:
        from importlib.metadata import version as installed_version

        print(f"pendcli {installed_version('pendcli')}")
        raise typer.Exit()


@app.callback()
def main(
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="Show the version.")
    ] = False,
) -> None:
    """Published against recomputed values for Tisserand, Lecornu and Charbonnier."""


@app.command("list")
def list_claims(paper: PaperOption = None, fmt: FormatOption = OutputFormat.table) -> None:
    """Every claim with its id, paper and source (reads the tables only; computes nothing)."""
    from pendcli.core.claims import list_rows, resolve_papers
    from pendcli.render import Column

    rows = list_rows(resolve_papers(paper))
    columns = [Column(k, k) for k in ("id", "paper", "source", "quantity", "published", "unit")]
    emit(fmt, [("", rows, columns)], {"claims": rows})


OutOption = Annotated[
    Path | None,
    typer.Option("--out", "-o", help="Also write the report, tables and figures to this folder."),
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


@app.command("reproduce")
def reproduce(
    paper: PaperOption = None,
    fmt: FormatOption = OutputFormat.table,
    out: OutOption = None,
    formulas: FormulasOption = True,
    stability: StabilityOption = None,
    quiet: QuietOption = False,
) -> None:
    """Every claim, published against recomputed, with a verdict (exit 0 whatever the verdicts)."""
    from pendcli.core.claims import resolve_papers
    from pendcli.reproduce import reproduce_all

    result = reproduce_all(
        resolve_papers(paper),
        formulas=formulas,
        stability=(out is not None) if stability is None else stability,
        quiet=quiet or fmt is not OutputFormat.table,
    )
    emit(fmt, result.sections(), result.document())
    if out is not None:
        _write_report(result, out, quiet)


def _write_report(result: ReproduceResult, out: Path, quiet: bool) -> None:
    from pendcli.cli.common import say
    from pendcli.report import write_report

    written = write_report(result, out, quiet=quiet)
    if not quiet:
        for key in result.papers:
            say(f"{key}: {result.tally(key)}")
        say(f"wrote {len(written)} files to {out} (report: {out / 'report.md'})")


@app.command("check")
def check(
    update: Annotated[
        bool, typer.Option("--update", help="Rewrite the committed regenerated tables instead.")
    ] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print only failures.")] = False,
) -> None:
    """Regenerate every table and compare with the committed ones (exit 1 on any drift)."""
    from pendcli.regression import run_check

    code = run_check(update=update, quiet=quiet)
    raise typer.Exit(code)


def run() -> None:
    """Console-script entry: turn every user error into one line and exit code 2."""
    from pendcli.core.errors import PendcliError

    click_exceptions = _click_exceptions()

    try:
        code = app(standalone_mode=False)
    except PendcliError as exc:
        _fail(str(exc), 2)
    except click_exceptions.UsageError as exc:
        if type(exc).__name__ == "NoArgsIsHelpError":  # help was shown: not an error
            sys.exit(0)
        _fail(exc.format_message().replace("\n", " "), 2)
    except click_exceptions.ClickException as exc:
        _fail(exc.format_message().replace("\n", " "), 2)
    except (typer.Abort, KeyboardInterrupt):
        _fail("aborted", 130)
    except typer.Exit as exc:
        sys.exit(exc.exit_code)
    except BrokenPipeError:
        sys.exit(0)
    except Exception as exc:  # a bug: still one line, unless PENDCLI_DEBUG asks for the trace
        if os.environ.get("PENDCLI_DEBUG"):
            raise
        _fail(f"internal error: {type(exc).__name__}: {exc} (set PENDCLI_DEBUG=1 for details)", 3)
    sys.exit(code if isinstance(code, int) else 0)


def _click_exceptions() -> ModuleType:
    """click's exceptions: recent typer vendors click as ``typer._click``, older typer uses it."""
    try:
        return importlib.import_module("typer._click.exceptions")
    except ImportError:  # pragma: no cover
        return importlib.import_module("click.exceptions")


def _fail(message: str, code: int) -> NoReturn:
    first = message.strip().splitlines()[0] if message.strip() else "error"
    sys.stderr.write(f"pendcli: error: {first}\n")
    sys.exit(code)
