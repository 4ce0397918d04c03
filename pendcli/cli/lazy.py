"""The top-level group of `pendcli`: the subcommands whose modules load only when named.

`pendcli --help` then costs neither their imports nor typer's conversion of their parameters
(about half of start-up otherwise): each is listed by a short help written here (or by its
paper's ``cli`` hook), and its module is imported when the command line, the help or the
shell completion names it. This is click's documented pattern for lazy subcommands: a group
class whose ``list_commands`` and ``get_command`` answer from the table.
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable
from typing import Any

import typer

from pendcli.cli.help_format import Command, Group, epilog, summary

__all__ = ["LAZY_COMMANDS", "LazyGroup", "lazy_commands"]

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


def _load_command(name: str) -> Any:
    """The click command of ``name``: its Typer sub-app, or its function made a command."""
    target = lazy_commands()[name][0]()
    if not isinstance(target, typer.Typer):
        target_app = typer.Typer(add_completion=False, rich_markup_mode=None)
        target_app.command(name, cls=Command, epilog=epilog(name))(target)
        target = target_app
    loaded = typer.main.get_command(target)
    loaded.name = name
    return loaded


class LazyGroup(Group):
    """The top-level group: eager commands first, then the lazily imported ones."""

    def list_commands(self, ctx: Any) -> list[str]:
        lazy = lazy_commands()
        return [*super().list_commands(ctx), *(n for n in lazy if n not in self.commands)]

    def get_command(self, ctx: Any, cmd_name: str) -> Any:
        if cmd_name in lazy_commands() and cmd_name not in self.commands:
            self.commands[cmd_name] = _load_command(cmd_name)
        return super().get_command(ctx, cmd_name)

    def summary_of(self, ctx: Any, name: str) -> str:
        """A lazy command not loaded yet is listed by its short help, without loading it."""
        lazy = lazy_commands()
        if name in lazy and name not in self.commands:
            return lazy[name][1]
        return summary(self.commands[name])
