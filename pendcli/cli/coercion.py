"""Plain values converted without pydantic: the one start-up trick of pendcli's CLI.

typer 0.29 converts every option and argument that is not a bare flag through a pydantic
``TypeAdapter``, defaults and unset options included: importing pydantic and building the
adapters made `pendcli list -f json` cost 0.36 s of CPU against 0.17 s with this module
(median of 10 paired whole-process runs, 2.09x; ``python -X importtime`` charges 0.18 s to
``typer._adapters`` alone). Here None, a value already of the annotated type, a plain decimal
number, a value read by the option's own ``parser=`` (:mod:`pendcli.cli.values`) and a
choice spelled exactly are converted directly; anything else (every other spelling, every
error but the parser's own) goes to typer's coercion, so values and messages stay typer's.
tests/cli/test_startup.py holds the direct conversion against typer's for many spellings.

How: :class:`pendcli.cli.help_format.Command` and ``Group`` pass the parameters of a context
(``get_params``, before click parses them) through :func:`plain_coercion`, which gives each
single-valued one the class of this module whose public ``get_runtime_param`` answers with a
:class:`PlainCoercion`.
"""

from __future__ import annotations

import enum
import functools
import re
from typing import Any

import typer
from typer.core import TyperArgument, TyperOption

__all__ = ["UNSET", "PlainCoercion", "plain_coercion"]

# A plain number as typed: both typer's coercion (pydantic) and Python read it the same way.
_PLAIN_FLOAT = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]{1,3})?")
_PLAIN_INT = re.compile(r"[+-]?[0-9]{1,18}")
UNSET = object()


class PlainCoercion:
    """typer's coercion of one parameter's value, without importing pydantic for plain values."""

    def __init__(self, param: Any, annotation: Any, parser: Any = None) -> None:
        self.param = param
        self.annotation = annotation
        self.parser = parser

    def direct(self, value: Any) -> Any:
        """The converted value, or :data:`UNSET` when typer's coercion must decide."""
        kind = self.annotation
        if value is None:
            return None
        if self.parser is not None and isinstance(value, str):
            return self.parser(value)
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
        return UNSET

    def coerce(self, value: Any, param: Any, ctx: Any) -> Any:
        try:
            converted = self.direct(value)
        except ValueError as exc:  # the option's own reader refused it: its words
            raise typer.BadParameter(str(exc), ctx=ctx, param=param) from None
        if converted is not UNSET:
            return converted
        # typer's own coercion: the public method of the class typer made the parameter with.
        typer_class: Any = type(param).__mro__[1]
        return typer_class.get_runtime_param(param).coerce(value, param=param, ctx=ctx)


@functools.cache
def _plain_class(typer_class: Any) -> type:
    """``typer_class`` (TyperOption or TyperArgument) whose ``get_runtime_param`` answers
    with a :class:`PlainCoercion`."""

    def get_runtime_param(self: Any) -> PlainCoercion:
        coercion = self.__dict__.get("plain_coercion")
        if coercion is None:
            descriptor = self.type_descriptor
            parser = descriptor.parameter_info.parser
            coercion = PlainCoercion(self, descriptor.annotation, parser)
            self.plain_coercion = coercion
        return coercion

    return type(
        f"Plain{typer_class.__name__}", (typer_class,), {"get_runtime_param": get_runtime_param}
    )


def plain_coercion(params: list[Any]) -> list[Any]:
    """Give every single-valued option or argument typer made a :class:`PlainCoercion`;
    ``params``, returned."""
    for param in params:
        info = getattr(getattr(param, "type_descriptor", None), "parameter_info", None)
        if (
            type(param) not in (TyperOption, TyperArgument)  # (already plain: a subclass)
            or param.multiple
            or param.nargs != 1
            or getattr(info, "min", None) is not None
            or getattr(info, "max", None) is not None
        ):
            continue
        param.__class__ = _plain_class(type(param))  # type: ignore[arg-type]
    return params
