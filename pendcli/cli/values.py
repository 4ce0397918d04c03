"""How pendcli reads a value typed on its command line: one rule for every option and argument.

* **Decimal comma**: a number is accepted with a decimal point or a decimal comma, as a
  historian copies it from the papers (« 9,81 », « 0,35 »): ``--g 9,81`` is ``--g 9.81``, as
  ``--theta0 30,5°`` is 30.5°. A comma is read as a decimal one only between digits, once,
  with no point beside it.
* **Finite**: every number pendcli takes is finite; ``1e400`` (infinite as a double), ``inf``
  and ``nan`` are refused in the one wording (``--length must be finite, got 1e400``).
* **Case**: a word chosen from a list (``--paper``, ``--status``, ``--method``, a family, the
  verdicts of ``--fail-on``, ``--format``) is read whatever its case and surrounding spaces:
  ``-p LECORNU`` and ``-s Holds`` are ``lecornu`` and ``holds``.
* **Blank**: an empty or blank value is refused before anything runs
  (:func:`pendcli.cli.main.refuse_blank`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import Any

from pendcli.core.errors import PendcliError

__all__ = ["CASE_FOLDED", "decimal_point", "read_values"]

# options and arguments whose value is a word of a list, read in any case
CASE_FOLDED = frozenset({"paper", "status", "method", "family", "fail_on"})
_DECIMAL_COMMA = re.compile(r"[+-]?[0-9]+,[0-9]+(?:[eE][+-]?[0-9]+)?")


def decimal_point(text: str) -> str:
    """``9,81`` as ``9.81``; any other text as it is."""
    stripped = text.strip()
    return stripped.replace(",", ".") if _DECIMAL_COMMA.fullmatch(stripped) else text


def _is_number(param: Any) -> bool:
    annotation = getattr(getattr(param, "type_descriptor", None), "annotation", None)
    return annotation is float or str(annotation) == "list[float]"


def _each(value: Any, change: Callable[[Any], Any]) -> Any:
    if isinstance(value, (tuple, list)):
        return type(value)(_each(v, change) for v in value)
    return change(value)


def _fold(value: Any) -> Any:
    return value.strip().casefold() if isinstance(value, str) else value


def _as_number(value: Any) -> Any:
    return decimal_point(value) if isinstance(value, str) else value


def _refuse_infinite(param: Any, typed: Any, value: Any) -> None:
    values = value if isinstance(value, (tuple, list)) else (value,)
    texts = typed if isinstance(typed, (tuple, list)) else (typed,)
    for number, text in zip(values, texts, strict=False):
        if isinstance(number, float) and not math.isfinite(number):
            raise PendcliError(f"{param.name} must be finite, got {text}", param.name)


def read_values(params: list[Any]) -> None:
    """Make each parameter read its value by the rules above (once per parameter)."""
    for param in params:
        number, fold = _is_number(param), param.name in CASE_FOLDED
        if not (number or fold) or getattr(param, "pendcli_reads", False):
            continue
        param.pendcli_reads = True
        param.process_value = _reader(param, param.process_value, number, fold)


def _reader(param: Any, original: Callable[..., Any], number: bool, fold: bool) -> Any:
    def process_value(ctx: Any, value: Any) -> Any:
        typed = value
        if number:
            value = _each(value, _as_number)
        if fold:
            value = _each(value, _fold)
        result = original(ctx, value)
        if number:
            _refuse_infinite(param, typed, result)
        return result

    return process_value
