"""`pendcli lecornu ...` subcommands."""

from __future__ import annotations

import typer

app = typer.Typer(help="Lecornu (see `pendcli lecornu --help`).", no_args_is_help=True)
