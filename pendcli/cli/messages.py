"""The wording of a refused command line: click's or pydantic's message said in pendcli's one
line, the option named as the user typed it (``-f`` or ``--format``), the value, why."""

from __future__ import annotations

import re
from typing import Any

import typer

from pendcli.base.errors import PendcliError
from pendcli.cli.help_format import ARGUMENTS

__all__ = ["named_as_typed", "options_as_typed", "usage_message"]


def _typed_option(param: Any, args: list[str]) -> str:
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
    unknown = _unknown_option(exc, param)
    if unknown is not None:
        return f"No such option: {unknown}"
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
        from pendcli.base.errors import either

        names = either(str(getattr(c, "value", c)) for c in descriptor.choices or ())
        return f"{name} must be one of {names}, got {choice['value']}"
    if message.startswith("must "):  # pendcli's own readers (pendcli.cli.values)
        return f"{name} {message}"
    return f"{name}: {message}"


_EXTRA = re.compile(r"Got unexpected extra argument(?:s|\(s\))? \((?P<first>[^)\s]+)")


def _unknown_option(exc: Exception, param: Any) -> str | None:
    """An option the command does not have, where a command that reads negative numbers as
    arguments (``charbonnier integral -1``) took it for its argument or an extra one: click
    then says "N must be an integer, got '--n'" or "unexpected extra argument (--n)"."""
    if param is not None and getattr(param, "param_type_name", None) == "argument":
        errors = getattr(exc.__cause__, "errors", None)
        value = (errors()[0] if callable(errors) and errors() else {}).get("input")
    else:
        match = _EXTRA.match(_format_message(exc))
        value = match["first"] if match else None
    if not isinstance(value, str) or not value.startswith("-"):
        return None
    try:
        float(value)
    except ValueError:
        return value.split("=", 1)[0]
    return None  # a negative number: not an option


def _format_message(exc: Exception) -> str:
    format_message = getattr(exc, "format_message", None)
    text = format_message() if callable(format_message) else str(exc)
    return " ".join(str(text).split())


def named_as_typed(exc: PendcliError, args: list[str]) -> str:
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
