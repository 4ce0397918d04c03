"""`pendcli tradeoff`: placeholder until its issue lands."""

from __future__ import annotations

import typer

app = typer.Typer(help="Tradeoff (in progress).", no_args_is_help=True)
