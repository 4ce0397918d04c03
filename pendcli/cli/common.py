"""Shared CLI pieces: options, the console, and printing rows in the chosen format."""

from __future__ import annotations

import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Annotated

import typer

from pendcli.core.console import console
from pendcli.render import OutputFormat, Section

FormatOption = Annotated[
    OutputFormat,
    typer.Option("--format", "-f", help="Output format.", case_sensitive=False),
]
PaperOption = Annotated[
    str | None,
    typer.Option("--paper", "-p", help="Only this paper: tisserand, lecornu or charbonnier."),
]
PlotOption = Annotated[
    Path | None,
    typer.Option("--plot", help="Also draw the comparison to this file (.png, .svg or .pdf)."),
]


def emit(fmt: OutputFormat, sections: Sequence[Section], document: Mapping[str, object]) -> None:
    """Print titled sections of rows (tables) or the whole document (JSON, CSV, Markdown)."""
    from pendcli.core.console import for_display
    from pendcli.render import render

    # rich (~0.02 s to import) only for the table: the data formats never use the console.
    text = render(fmt, sections, document, console=console() if fmt is OutputFormat.table else None)
    # a table is for the eye: "?" keeps its columns; the data formats keep \uXXXX escapes
    sys.stdout.write(for_display(text) if fmt is OutputFormat.table else text)


def say(message: str) -> None:
    """A status line on stderr (so stdout stays machine-readable); nothing under --quiet."""
    from pendcli.core.console import is_quiet

    if not is_quiet():
        console(stderr=True).print(message)
