"""How every help of pendcli is laid out: at the terminal's width, with no word or value cut
across two lines, and each value named for a reader (``--count K``, not ``--count <int>``).

click wraps help at 80 columns at most (``max_content_width``) and breaks lines after a
hyphen, so a value a user copies came out as ``mcmahon-`` / ``newton`` and a default as
``[default:`` / ``5]``. Here the help is wrapped at the terminal's width ($COLUMNS, else the
terminal's own, else 80), and the tokens that must stay whole are bound before wrapping (a
hyphen between two characters of a word, the spaces of a bracketed note, of a comparison
such as ``1 <= K <= 10^7``) and unbound in the finished text.

Every command and group of pendcli is made with the classes here, given to typer by its public
``cls`` (:func:`command`, :func:`group`): :class:`HelpContext` (the width and the formatter),
:class:`Command` (an argument named by its value alone: ``N``, ``[CLAIM]``) and :class:`Group`
(each subcommand listed with the whole first paragraph of its help). Each option names its
value itself (``typer.Option(metavar="K")``).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import typer
from typer.core import TyperCommand, TyperGroup

from pendcli.cli.coercion import plain_coercion

__all__ = [
    "ARGUMENTS",
    "EXAMPLES",
    "Command",
    "Group",
    "HelpContext",
    "command",
    "epilog",
    "group",
    "keep_whole",
    "restore",
    "summary",
]

# a width far above any terminal's: click then takes the terminal's own (minus its margin)
MAX_CONTENT_WIDTH = 10_000
_SPACE, _HYPHEN = "\u00a0", "\u2011"  # no-break space and hyphen, while wrapping only
_WORD_HYPHEN = re.compile(r"(?<=[\w.'])-(?=[\w.])")
_BRACKETED = re.compile(r"\[[^\[\]\n]{1,60}\]")
_COMPARISON = re.compile(r"[^\s(]+ (?:<=|>=|<|>|=|≤|≥) [^\s,;)]+(?: (?:<=|<|≤) [^\s,;)]+)?")

# the positional arguments by parameter name, named in an error as their help names them
ARGUMENTS = {"claim": "CLAIM", "family": "FAMILY", "n": "N"}


def keep_whole(text: str) -> str:
    """``text`` with its values bound: a wrap never cuts them (see :func:`restore`)."""
    text = _WORD_HYPHEN.sub(_HYPHEN, text)
    for pattern in (_BRACKETED, _COMPARISON):
        text = pattern.sub(lambda m: m.group(0).replace(" ", _SPACE), text)
    return text


def restore(text: str) -> str:
    """The text :func:`keep_whole` bound, as written (plain spaces and hyphens)."""
    return text.replace(_SPACE, " ").replace(_HYPHEN, "-")


_Formatter: Any = typer.Context.formatter_class  # click's HelpFormatter


class WholeWordsFormatter(_Formatter):
    """click's help formatter writing text and definition lists with values bound."""

    def write_text(self, text: str) -> None:
        super().write_text(keep_whole(text))

    def write_dl(self, rows: Any, *args: Any, **kwargs: Any) -> None:
        super().write_dl([(first, keep_whole(second)) for first, second in rows], *args, **kwargs)

    def getvalue(self) -> str:
        return restore(super().getvalue())


class HelpContext(typer.Context):
    """The context of every pendcli command: help at the terminal's full width, values whole."""

    formatter_class = WholeWordsFormatter

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("max_content_width", MAX_CONTENT_WIDTH)
        super().__init__(*args, **kwargs)


def summary(command: Any) -> str:
    """The first paragraph of a command's help, whole: click's short help stops at "eq." or
    "s.t.", and a docstring's first line is only part of its first sentence."""
    text = (command.short_help or command.help or "").strip()
    return " ".join(text.split("\n\n", 1)[0].split())


def _argument_name(param: Any) -> str:
    return str(param.metavar or (param.name or "").upper())


class Command(TyperCommand):
    """A pendcli command: its arguments shown by the name of their value (``N``, ``[CLAIM]``),
    not with their Python type (``N <int>``) or in braces (``{N}``)."""

    context_class = HelpContext

    def get_params(self, ctx: Any) -> list[Any]:
        return plain_coercion(super().get_params(ctx))  # without pydantic (start-up)

    def collect_usage_pieces(self, ctx: Any) -> list[str]:
        pieces = [self.options_metavar] if self.options_metavar else []
        for param in self.get_params(ctx):
            if param.param_type_name == "argument":
                name = _argument_name(param)
                pieces.append(name if param.required else f"[{name}]")
        return pieces

    def format_options(self, ctx: Any, formatter: Any) -> None:
        rows: dict[str, list[tuple[str, str]]] = {"argument": [], "option": []}
        for param in self.get_params(ctx):
            record = param.get_help_record(ctx)
            if record is not None and param.param_type_name in rows:
                first = _argument_name(param) if param.param_type_name == "argument" else None
                rows[param.param_type_name].append((first or record[0], record[1]))
        for title, kind in (("Arguments", "argument"), ("Options", "option")):
            if rows[kind]:
                with formatter.section(title):
                    formatter.write_dl(rows[kind])


class Group(TyperGroup):
    """A pendcli group: its commands listed with the whole first paragraph of their help."""

    context_class = HelpContext

    def get_params(self, ctx: Any) -> list[Any]:
        return plain_coercion(super().get_params(ctx))  # without pydantic (start-up)

    def format_commands(self, ctx: Any, formatter: Any) -> None:
        rows = [(name, self.summary_of(ctx, name)) for name in self.list_commands(ctx)]
        if rows:
            with formatter.section("Commands"):
                formatter.write_dl(rows)

    def summary_of(self, ctx: Any, name: str) -> str:
        """The line that lists the subcommand ``name``."""
        found = self.get_command(ctx, name)
        return summary(found) if found is not None else ""


def command(app: typer.Typer, path: str, **settings: Any) -> Callable[..., Any]:
    """``app.command`` for the command ``pendcli <path>``: made a :class:`Command`, with its
    examples (:func:`epilog`)."""
    name = path.rsplit(" ", 1)[-1]
    return app.command(name, cls=Command, epilog=epilog(path), **settings)


def group(help: str, path: str) -> typer.Typer:
    """The Typer app of the group ``pendcli <path>``: a :class:`Group`, plain help (typer's
    rich help imports rich.markdown and markdown_it, ~130 ms), its examples."""
    return typer.Typer(
        cls=Group,
        help=help,
        epilog=epilog(path),
        no_args_is_help=True,
        add_completion=False,
        rich_markup_mode=None,
    )


# Examples shown at the end of each command's --help (the command path after `pendcli`).
EXAMPLES: dict[str, tuple[str, ...]] = {
    "": (
        "pendcli reproduce                     all papers: printed against recomputed",
        "pendcli reproduce -p lecornu --notes  one paper, every column",
        "pendcli check -f junit > check.xml    CI: a testcase per claim and table",
    ),
    "list": ("pendcli list -p tisserand", "pendcli list -f csv > claims.csv"),
    "reproduce": (
        "pendcli reproduce --only-failing",
        "pendcli reproduce -p charbonnier -f json",
        "pendcli reproduce --out out          report.md, report.html, tables, figures",
        "pendcli reproduce --out out --pdf    the pages printed to PDF too (Chromium)",
        "pendcli reproduce --fail-on discrepant,fails   CI: exit 1 on a bad verdict",
    ),
    "check": (
        "pendcli check",
        "pendcli check -f junit > check.xml",
        "pendcli check --update               then review and commit the tables",
    ),
    "tisserand claims": ("pendcli tisserand claims", "pendcli tisserand claims -f json"),
    "tisserand example": (
        "pendcli tisserand example",
        "pendcli tisserand example --theta0 45° --theta1 20° --plot ex.png",
    ),
    "tisserand series": ("pendcli tisserand series --order 4", "pendcli tisserand series -f csv"),
    "lecornu claims": ("pendcli lecornu claims", "pendcli lecornu claims --g 9.81"),
    "lecornu zeros": (
        "pendcli lecornu zeros --order 1 --count 10",
        "pendcli lecornu zeros --count 1000000 --tol 1e-12 -f csv > zeros.csv",
    ),
    "lecornu example": (
        "pendcli lecornu example",
        "pendcli lecornu example --speed 0.5 --length 2 --plot theta.png",
    ),
    "lecornu ode-check": (
        "pendcli lecornu ode-check",
        "pendcli lecornu ode-check --amplitude 1 --amplitude 10",
    ),
    "lecornu g-sensitivity": ("pendcli lecornu g-sensitivity",),
    "lecornu series": ("pendcli lecornu series -f json",),
    "lecornu zero-length": ("pendcli lecornu zero-length --speed 0.35 --length 1",),
    "charbonnier table": (
        "pendcli charbonnier table",
        "pendcli charbonnier table --n-max 40 --plot table.png",
    ),
    "charbonnier integral": (
        "pendcli charbonnier integral 4              I_4(π) = 16/15",
        "pendcli charbonnier integral 1000 -x 1.5",
        "pendcli charbonnier integral 5 --tol 1e-10  the cheapest method for it",
    ),
    "formulas": (
        "pendcli formulas -p lecornu",
        "pendcli formulas --plot figures/   one residual plot per formula",
    ),
    "equations": (
        "pendcli equations -p tisserand",
        "pendcli equations --status misprint --notes",
    ),
    "tisserand": (
        "pendcli tisserand claims                 the printed numbers, judged",
        "pendcli tisserand example --theta0 45°   θ1 keeps the example's ratio",
        "pendcli tisserand series --order 4",
    ),
    "lecornu": (
        "pendcli lecornu claims --g 9.81",
        "pendcli lecornu zeros --order 1 --count 10",
        "pendcli lecornu example --speed 0,5 --plot theta.png",
        "pendcli lecornu g-sensitivity            which g fits his figures",
    ),
    "charbonnier": (
        "pendcli charbonnier table",
        "pendcli charbonnier integral 4              I_4(π) = 16/15",
        "pendcli charbonnier integral 5 --tol 1e-10",
    ),
    "cache": ("pendcli cache info", "pendcli cache clear"),
    "cache info": ("pendcli cache info",),
    "cache clear": ("pendcli cache clear", "pendcli reproduce --no-cache   all computed afresh"),
    "tradeoff": ("pendcli tradeoff --quick", "pendcli tradeoff integral_pi --plot wp.png"),
    "explain": (
        "pendcli explain -p lecornu     each wrong digit: its mechanism and odds",
        "pendcli explain lecornu.mean_pendulum_coefficient   every step of one",
        "pendcli explain -f json > explanations.json",
    ),
}


def epilog(path: str) -> str | None:
    """The Examples block of a command's help; "\b" keeps click from rewrapping it."""
    lines = EXAMPLES.get(path)
    return "\b\nExamples:\n" + "\n".join(f"  {line}" for line in lines) if lines else None
