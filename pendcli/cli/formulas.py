"""`pendcli formulas`: placeholder until its issue lands."""

from __future__ import annotations

import typer

app = typer.Typer(help="Formulas (in progress).", no_args_is_help=True)
