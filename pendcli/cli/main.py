"""`pendcli`: the entry point. Commands are thin; errors are one line and a non-zero exit."""

from __future__ import annotations

import atexit
import contextlib
import copy
import enum
import functools
import gc
import importlib
import os
import re
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from typer.core import TyperGroup

from pendcli.cli.common import (
    CacheOption,
    CheckFormat,
    FormatOption,
    PaperOption,
    complete_verdicts,
    emit,
)
from pendcli.cli.help_format import ARGUMENTS, epilog, name_values
from pendcli.cli.values import read_values
from pendcli.core.errors import PendcliError
from pendcli.render import OutputFormat

if TYPE_CHECKING:
    # click's Command, Context, Parameter and HelpFormatter live inside typer, under a private
    # name (typer._click); pendcli names none of them, so for mypy they are Any.
    Command = Any
    Context = Any
    Parameter = Any

    from pendcli.core.cache import ResultCache
    from pendcli.run.reproduce import ReproduceResult

# Subcommands whose modules load only when named: `pendcli --help` then costs neither their
# imports nor typer's conversion of their parameters (about half of start-up otherwise).
# name -> (module, attribute: a Typer sub-app or a command function, short help for --help);
# the papers' sub-apps come first, from the registry (:func:`lazy_commands`).
LAZY_COMMANDS: dict[str, tuple[str, str, str]] = {
    "formulas": (
        "pendcli.cli.formulas",
        "formulas",
        "Derived formulas against direct numerical solutions: observed order, verdict.",
    ),
    "equations": (
        "pendcli.cli.equations",
        "equations",
        "Every numbered equation and stated result, checked: holds, fails, misprint, ...",
    ),
    "explain": ("pendcli.cli.explain", "explain", "How he got each wrong digit, and the odds."),
    "cache": ("pendcli.cli.cache", "app", "The result cache: where it is, how big, emptying it."),
    "tradeoff": (
        "pendcli.cli.tradeoff",
        "tradeoff",
        "Speed against accuracy: each method's error and time (work-precision).",
    ),
}


def lazy_commands() -> dict[str, tuple[Callable[[], Any], str]]:
    """name -> (loader of its Typer app or command function, short help): each registered
    paper's sub-app, then :data:`LAZY_COMMANDS`."""
    from pendcli.papers.registry import all_papers

    out = {p.key: (p.cli.load, p.cli.help) for p in all_papers() if p.cli is not None}
    for name, (module_name, attribute, text) in LAZY_COMMANDS.items():
        out[name] = (functools.partial(_attribute, module_name, attribute), text)
    return out


def _attribute(module_name: str, attribute: str) -> Any:
    return getattr(importlib.import_module(module_name), attribute)


def _load_command(name: str) -> Command:
    target = lazy_commands()[name][0]()
    if not isinstance(target, typer.Typer):
        target_app = typer.Typer(add_completion=False, rich_markup_mode=None)
        target_app.command(name)(target)
        target = target_app
    command = typer.main.get_command(target)
    command.name = name
    return command


def summary(command: Command) -> str:
    """The first paragraph of a command's help, whole: click's short help stops at "eq." or
    "s.t.", and a docstring's first line is only part of its first sentence."""
    text = (command.short_help or command.help or "").strip()
    return " ".join(text.split("\n\n", 1)[0].split())


# Options that cannot be given together, refused in every command that has both.
EXCLUSIVE_OPTIONS = (("tol", "method"),)


def _excluding(callback: Callable[..., Any], first: str, second: str) -> Callable[..., Any]:
    @functools.wraps(callback)
    def checked(**kwargs: Any) -> Any:
        if kwargs.get(first) is not None and kwargs.get(second) is not None:
            from pendcli.core.errors import PendcliError

            raise PendcliError(
                f"--{first} and --{second} exclude each other: --{first} picks the cheapest "
                f"method meeting the tolerance, --{second} forces one; give one of them"
            )
        return callback(**kwargs)

    return checked


def _quiet_flag(value: bool) -> bool:
    from pendcli.core.console import set_quiet

    set_quiet(bool(value))
    return value


# typer reads these annotations by name from the module (`from __future__ import annotations`).
_QuietFlag = Annotated[
    bool,
    typer.Option(
        "--quiet",
        "-q",
        help="No status lines on stderr (method chosen, files written).",
        callback=_quiet_flag,
        expose_value=False,
    ),
]


def _quiet_carrier(quiet: _QuietFlag = False) -> None:
    """Only carries the option."""


@functools.cache
def _quiet_option() -> Parameter:
    """A `--quiet/-q` flag that silences `say` (core.console), for commands without their own."""
    probe = typer.Typer(add_completion=False, rich_markup_mode=None)
    probe.command()(_quiet_carrier)
    return typer.main.get_command(probe).params[0]


# A plain number as typed: both typer's coercion (pydantic) and Python read it the same way.
_PLAIN_FLOAT = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]{1,3})?")
_PLAIN_INT = re.compile(r"[+-]?[0-9]{1,18}")
_UNSET = object()


class PlainCoercion:
    """typer's coercion of one option's value, without importing pydantic for plain values.

    typer 0.29 converts every non-flag value through a pydantic TypeAdapter: importing pydantic
    and building the adapters costs ~0.04 s per run, a fifth of `reproduce`'s own work. Here
    None, a value already of the annotated type, a plain decimal number and a choice spelled
    exactly are converted directly; anything else (every error, every unusual spelling) goes
    to typer's own coercion, so values and error messages stay typer's. Tested against it in
    tests/test_startup.py.
    """

    def __init__(self, param: Parameter, annotation: Any) -> None:
        self.param = param
        self.annotation = annotation

    def direct(self, value: Any) -> Any:
        """The converted value, or _UNSET when typer's coercion must decide."""
        kind = self.annotation
        if value is None:
            return None
        if kind in (str, float, int) and type(value) is kind:
            return value
        if kind is float and isinstance(value, str) and _PLAIN_FLOAT.fullmatch(value):
            return float(value)
        if kind is int and isinstance(value, str) and _PLAIN_INT.fullmatch(value):
            return int(value)
        if isinstance(kind, type) and issubclass(kind, enum.Enum):
            if isinstance(value, kind):
                return value
            folded = [str(m.value).casefold() for m in kind]
            matches = [m for m in kind if m.value == value]
            if len(matches) == 1 and len(set(folded)) == len(folded):
                return matches[0]
        return _UNSET

    def coerce(self, value: Any, param: Parameter, ctx: Context | None) -> Any:
        converted = self.direct(value)
        if converted is not _UNSET:
            return converted
        # typer's own coercion: the public method of the class typer made the parameter with.
        typer_class: Any = type(param).__mro__[1]
        return typer_class.get_runtime_param(param).coerce(value, param=param, ctx=ctx)


@functools.cache
def _plain_class(typer_class: Any) -> type:
    """``typer_class`` (typer.core.TyperOption or TyperArgument) whose public
    ``get_runtime_param`` answers with a :class:`PlainCoercion`."""

    def get_runtime_param(self: Any) -> PlainCoercion:
        coercion = self.__dict__.get("pendcli_coercion")
        if coercion is None:
            coercion = self.pendcli_coercion = PlainCoercion(self, self.type_descriptor.annotation)
        return coercion

    name = f"Plain{typer_class.__name__}"
    return type(name, (typer_class,), {"get_runtime_param": get_runtime_param})


def _plain_coercion(params: list[Parameter]) -> None:
    """Give every single-valued option or argument typer made a :class:`PlainCoercion`."""
    from typer.core import TyperArgument, TyperOption

    for param in params:
        info = getattr(getattr(param, "type_descriptor", None), "parameter_info", None)
        if (
            type(param) not in (TyperOption, TyperArgument)  # (already plain: a subclass)
            or param.multiple
            or param.nargs != 1
            or getattr(info, "parser", None) is not None
            or getattr(info, "min", None) is not None
            or getattr(info, "max", None) is not None
        ):
            continue
        param.__class__ = _plain_class(type(param))  # type: ignore[arg-type]


def _adapt(command: Command, ctx: Context, path: str = "") -> None:
    """Every command: its whole first line as summary, examples, `--quiet`, exclusive options
    refused, plain values converted without pydantic (:class:`PlainCoercion`)."""
    if getattr(command, "pendcli_adapted", False):
        return
    command.pendcli_adapted = True
    command.context_class = type(ctx)  # help at the terminal's width, values kept whole
    path = f"{path} {command.name}".strip()
    command.short_help = summary(command) or None
    command.epilog = command.epilog or epilog(path)
    _plain_coercion(command.get_params(ctx))  # with its --help (the names are ctx's)
    name_values(command.params)
    read_values(command.params)
    subcommands: dict[str, Command] = getattr(command, "commands", {})
    for sub in subcommands.values():
        _adapt(sub, ctx, path)
    if subcommands and not getattr(command, "invoke_without_command", False):
        return
    params = command.params
    if not any(p.name == "quiet" or "-q" in p.opts for p in params):
        params.append(copy.copy(_quiet_option()))
    names = {p.name for p in params}
    for first, second in EXCLUSIVE_OPTIONS:
        if {first, second} <= names and command.callback is not None:
            command.callback = _excluding(command.callback, first, second)


class LazyGroup(TyperGroup):
    """The top-level group: eager commands first, then the lazily imported ones."""

    def make_context(self, *args: Any, **kwargs: Any) -> Context:
        from pendcli.cli.help_format import whole_words_context

        base: Any = TyperGroup.context_class  # click's Context
        self.context_class = whole_words_context(base)
        return super().make_context(*args, **kwargs)

    def parse_args(self, ctx: Context, args: list[str]) -> list[str]:
        _plain_coercion(self.get_params(ctx))  # --help, --install-completion...
        name_values(self.params)
        read_values(self.params)
        self.epilog = self.epilog or epilog("")
        return super().parse_args(ctx, args)

    def list_commands(self, ctx: Context) -> list[str]:
        lazy = lazy_commands()
        return [*super().list_commands(ctx), *(n for n in lazy if n not in self.commands)]

    def get_command(self, ctx: Context, cmd_name: str) -> Command | None:
        if cmd_name in lazy_commands() and cmd_name not in self.commands:
            self.commands[cmd_name] = _load_command(cmd_name)
        command = super().get_command(ctx, cmd_name)
        if command is not None:
            _adapt(command, ctx)
        return command

    def format_commands(self, ctx: Context, formatter: Any) -> None:
        rows = []
        lazy = lazy_commands()
        for name in self.list_commands(ctx):
            if name in lazy and name not in self.commands:
                rows.append((name, lazy[name][1]))
            else:
                rows.append((name, summary(self.commands[name])))
        with formatter.section("Commands"):
            formatter.write_dl(rows)


app = typer.Typer(
    cls=LazyGroup,
    name="pendcli",
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
        from pendcli.core.versions import library_versions

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


@app.command("list")
def list_claims(paper: PaperOption = None, fmt: FormatOption = OutputFormat.table) -> None:
    """Every claim with its id, paper and source (reads the tables only; computes nothing)."""
    from pendcli.core.claims import list_rows
    from pendcli.core.reader_text import for_reader
    from pendcli.papers.registry import resolve_papers
    from pendcli.render import Column

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


@app.command("reproduce")
def reproduce(
    paper: PaperOption = None,
    fmt: FormatOption = OutputFormat.table,
    out: OutOption = None,
    formulas: FormulasOption = True,
    equations: EquationsOption = None,
    stability: StabilityOption = None,
    notes: Annotated[
        bool, typer.Option("--notes", help="Table format: every column, notes included.")
    ] = False,
    only_failing: Annotated[
        bool,
        typer.Option("--only-failing", help="Only the rows that do not agree, hold or check."),
    ] = False,
    quiet: QuietOption = False,
    measure: Annotated[
        bool, typer.Option("--measure", help="With --out: time the speed families now.")
    ] = False,
    pdf: Annotated[
        bool,
        typer.Option("--pdf", help="With --out: print each HTML page to PDF (headless Chromium)."),
    ] = False,
    fail_on: Annotated[
        str | None,
        typer.Option(
            "--fail-on",
            metavar="VERDICT[,...]",
            help="Exit 1 when any row has one of these verdicts or statuses (for CI), e.g. "
            "discrepant,fails. An equation status (misprint...) runs the ledger.",
            autocompletion=complete_verdicts,
        ),
    ] = None,
    cache: CacheOption = True,
) -> None:
    """Every claim, published against recomputed, with a verdict (exit 0 unless --fail-on)."""
    from pendcli.cli.common import result_cache
    from pendcli.core.errors import PendcliError
    from pendcli.papers.registry import resolve_papers
    from pendcli.run.reproduce import EQUATION_ONLY, reproduce_all

    fail_names = _fail_names(fail_on)
    if fail_names & EQUATION_ONLY and equations is None:
        equations = True
    if measure and out is None:
        raise PendcliError("--measure needs --out (it re-times the report's speed families)")
    if pdf and out is None:
        raise PendcliError("--pdf needs --out (it prints the HTML pages written there)")
    if out is not None:  # refuse a bad folder before the run, not after
        from pendcli.cli.targets import check_replaced_folder
        from pendcli.report import check_out_folder

        check_replaced_folder(out, "--out")
        check_out_folder(out)
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
        )
        compact = fmt is OutputFormat.table and not notes
        emit(fmt, result.sections(compact, only_failing), result.document(only_failing))
        if compact:
            from pendcli.summary import CAUSE_LEGEND

            print(CAUSE_LEGEND)
        if out is not None:
            _write_report(result, out, quiet, measure, pdf, stored)
    if fail_names:
        _fail_on(result, fail_names, quiet)


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
    from pendcli.report import write_report

    written = write_report(result, out, quiet=quiet, measure=measure, pdf=pdf, cache=cache)
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
    from pendcli.core.console import status_line
    from pendcli.run.regression import run_check

    if not quiet and fmt is CheckFormat.table:  # seconds before the progress bar can start
        status_line("check: reading the committed tables and the equation ledgers")
    if update and fmt is not CheckFormat.table:
        from pendcli.core.errors import PendcliError

        raise PendcliError(f"--format: {fmt.value!r} with --update; expected table")
    code = run_check(update=update, quiet=quiet, fmt=fmt.value)
    raise typer.Exit(code)


def run() -> None:
    """Console-script entry: every user error and OS error one line and exit 2, no traceback."""
    if sys.stdout is None:  # started with `>&-`: Python leaves no stdout at all
        _write_error("cannot write standard output: it is closed")
        sys.exit(2)
    from pendcli.core.console import protect_streams, set_quiet

    # At exit, skip the collector's last pass over every object scipy made (~0.06 s of CPU
    # measured): the OS frees them anyway. Other atexit handlers and the flushes still run.
    atexit.unregister(gc.freeze)
    atexit.register(gc.freeze)
    set_quiet(False)
    from pendcli.core.interrupts import stop_on_signals

    stop_on_signals()  # Ctrl-C, TERM, HUP: one line, status 128 + the signal (_invoke)
    original = protect_streams()
    try:
        code = _invoke(sys.argv[1:])
        code = _flush_standard_output(code)
    finally:
        sys.stdout = original
    sys.exit(code)


def refuse_blank(args: list[str]) -> None:
    """No option or argument of pendcli takes an empty or blank value: one is a slip of the
    shell (an unset variable, stray quotes), refused in one line where typer would read ''
    as the current folder (`formulas --plot ''`) or as no claim at all (`explain ''`)."""
    for index, arg in enumerate(args):
        name, equals, value = arg.partition("=") if arg.startswith("--") else ("", "", arg)
        if (equals and not value.strip()) or (not equals and not arg.strip()):
            before = args[index - 1] if index and args[index - 1].startswith("-") else ""
            after = f", after {args[index - 1]!r}," if index else ""
            where = name or before or f"argument {index + 1}{after}"
            raise PendcliError(f"{where} must not be empty or blank, got {value or arg!r}")


def _invoke(args: list[str]) -> int:
    """Run the app; turn every way it can end into an exit code and at most one stderr line."""
    from pendcli.core.interrupts import Interrupted

    try:
        refuse_blank(args)
        # prog_name fixed: the usage line and the completion variable (_PENDCLI_COMPLETE)
        # must not depend on how Python was started (`python -m pendcli`, a test runner).
        code = app(args=args, prog_name="pendcli", standalone_mode=False)
    except PendcliError as exc:
        return _fail(_named_as_typed(exc, args), 2)
    except typer.TyperException as exc:  # click's usage errors: rephrased, one line
        if _is_bare_group_help(exc):  # a bare group: its help, as typer does
            _write_error(exc.format_message(), prefix="")
            return 2
        return _fail(usage_message(exc, args), 2)
    except Interrupted as exc:
        return _fail(str(exc), exc.status)
    except (typer.Abort, KeyboardInterrupt):
        return _fail("aborted", 130)
    except typer.Exit as exc:
        return exc.exit_code
    except OSError as exc:
        from pendcli.core.files import describe_os_error  # not on the start-up path

        return _fail(describe_os_error(exc), 2)
    except Exception as exc:  # a bug: still one line, unless PENDCLI_DEBUG asks for the trace
        from pendcli.core.errors import out_of_memory

        if (memory := out_of_memory(exc)) is not None:  # a limit reached, no bug: exit 2
            return _fail(memory, 2)
        if os.environ.get("PENDCLI_DEBUG"):
            raise
        return _fail(f"internal error: {type(exc).__name__}: {exc} (set PENDCLI_DEBUG=1)", 3)
    return code if isinstance(code, int) else 0


def _is_bare_group_help(exc: typer.TyperException) -> bool:
    """A group named without a subcommand (``no_args_is_help``): the error's text is its help."""
    ctx = getattr(exc, "ctx", None)
    return (
        ctx is not None
        and not isinstance(exc, typer.BadParameter)
        and exc.format_message() == ctx.get_help()
    )


def _flush_standard_output(code: int) -> int:
    """Flush stdout now, so a full disk or a closed pipe is reported here, not at shutdown."""
    from pendcli.core.errors import PendcliError

    try:
        sys.stdout.flush()
    except PendcliError as exc:  # core.console names the stream (standard output)
        # Python flushes stdout again at exit and would print "Exception ignored ...".
        with contextlib.suppress(OSError, ValueError):
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            os.close(devnull)
        return code if code >= 2 else _fail(str(exc), 2)  # an earlier error already spoke
    return code


def _write_error(message: str, prefix: str = "pendcli: error: ") -> None:
    if sys.stderr is None:
        return
    with contextlib.suppress(OSError, ValueError):
        sys.stderr.write(f"{prefix}{message.rstrip()}\n")
        sys.stderr.flush()


def _fail(message: str, code: int) -> int:
    """One line on stderr, whole: a newline in it (a path's) is shown escaped."""
    from pendcli.core.errors import one_line

    _write_error(one_line(message.strip()) or "error")
    return code


def _typed_option(param: Parameter, args: list[str]) -> str:
    """The option's name as the user typed it (`-f` or `--format`), else its first name."""
    names = [*param.opts, *param.secondary_opts]
    for arg in args:
        for name in names:
            if arg == name or (name.startswith("--") and arg.startswith(f"{name}=")):
                return name
    if param.param_type_name == "argument":
        return (param.name or "argument").upper()
    return names[0] if names else (param.name or "value")


_EXPECTED = {
    "float_parsing": "a number",
    "float_type": "a number",
    "finite_number": "finite",
    "int_parsing": "an integer",
    "int_type": "an integer",
    "int_from_float": "an integer",
}


def usage_message(exc: Exception, args: list[str]) -> str:
    """click's or pydantic's wording of a parse error in pendcli's: the option, the value, why."""
    param = getattr(exc, "param", None)
    if param is None or not isinstance(exc, typer.BadParameter):
        return _format_message(exc)
    if not str(getattr(exc, "message", "")):  # a missing option or argument: click's wording
        return _format_message(exc)
    name = _typed_option(param, args)
    errors = getattr(exc.__cause__, "errors", None)
    first = errors()[0] if callable(errors) and errors() else {}
    value = first.get("input")
    kind = _EXPECTED.get(str(first.get("type")))
    if kind is not None:
        return f"{name} must be {kind}, got {value!r}"
    message = str(getattr(exc, "message", exc)).removeprefix("Value error, ").rstrip(".")
    descriptor = getattr(param, "type_descriptor", None)
    choice = re.match(r"(?P<value>'.*') is not one of ", message)
    if choice and descriptor is not None and descriptor.is_choice:
        from pendcli.core.errors import either

        names = either(str(getattr(c, "value", c)) for c in descriptor.choices or ())
        return f"{name} must be one of {names}, got {choice['value']}"
    return f"{name}: {message}"


def _format_message(exc: Exception) -> str:
    format_message = getattr(exc, "format_message", None)
    text = format_message() if callable(format_message) else str(exc)
    return " ".join(str(text).split())


def _named_as_typed(exc: PendcliError, args: list[str]) -> str:
    """The error with its parameter named as the option typed: ``method: 'x' ...`` becomes
    ``--method: 'x' ...``. Messages without a ``parameter`` go through :func:`options_as_typed`."""
    message = str(exc)
    name = exc.parameter
    if name is None or name.startswith("-") or not message.startswith(name):
        return options_as_typed(message, args)
    for arg in args:
        typed = arg.split("=", 1)[0]
        key = typed[2:].replace("-", "_")
        if typed.startswith("--") and key and (key == name or name.startswith(f"{key}_")):
            return typed + message[len(name) :]
    if name in ARGUMENTS:  # a positional argument: named as its help names it (N, CLAIM)
        return ARGUMENTS[name] + message[len(name) :]
    return message


_LEADING_NAME = re.compile(r"^([A-Za-z_]\w*)(?::| (?:=|must|is|changes)) ")


def options_as_typed(message: str, args: list[str]) -> str:
    """Name the option as typed: ``speed = -1 is out of range`` becomes ``--speed = -1 ...``.

    The models name their inputs (``speed``, ``floor_fraction``); the user typed options
    (``--speed``, ``--floor``). Only a name the command line holds is rewritten.
    """
    match = _LEADING_NAME.match(message)
    if match is None:
        return message
    name = match.group(1)
    for arg in args:
        if not arg.startswith("--"):
            continue
        typed = arg.split("=", 1)[0]
        key = typed[2:].replace("-", "_")
        if key and (key == name or name.startswith(f"{key}_")):
            pattern = rf"(?<![\w-]){re.escape(name)}(?=:| (?:=|<|<=|>|>=|must|is|changes) )"
            return re.sub(pattern, typed, message)
    return message
