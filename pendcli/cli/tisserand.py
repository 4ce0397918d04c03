"""`pendcli tisserand ...` subcommands."""

from __future__ import annotations

import typer

app = typer.Typer(help="Tisserand (see `pendcli tisserand --help`).", no_args_is_help=True)
