"""`pendcli sample ...`: the sample paper's one command."""

from __future__ import annotations

from typing import Annotated

import typer

app = typer.Typer(
    help="A sample paper (tests only).",
    no_args_is_help=True,
    add_completion=False,
    rich_markup_mode=None,
)


@app.callback()
def sample() -> None:
    """A sample paper (tests only): the period of a simple pendulum."""


@app.command("period")
def period_command(
    length: Annotated[float, typer.Option("--length", help="Length l in metres.")] = 1.0,
) -> None:
    """The small-amplitude period 2π√(l/g) of a pendulum of length l."""
    from sample_paper.model import period

    typer.echo(f"{period(length):.6f}")
