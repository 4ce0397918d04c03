"""How pendcli reads a value typed on its command line: one rule for every option and argument.

* **Decimal comma**: a number is accepted with a decimal point or a decimal comma, as a
  historian copies it from the papers (« 9,81 », « 0,35 »): ``--g 9,81`` is ``--g 9.81``, as
  ``--theta0 30,5°`` is 30.5°. A comma is read as a decimal one only between digits, once,
  with no point beside it.
* **Finite**: every number pendcli takes is finite; ``1e400`` (infinite as a double), ``inf``
  and ``nan`` are refused in the one wording (``--length must be finite, got 1e400``).
* **Case**: a word chosen from a list (``--paper``, ``--status``, ``--method``, a family, the
  verdicts of ``--fail-on``) is read whatever its case and surrounding spaces: ``-p LECORNU``
  and ``-s Holds`` are ``lecornu`` and ``holds`` (``--format``: typer's ``case_sensitive=False``).
* **Blank**: an empty or blank value is refused before anything runs
  (:func:`pendcli.cli.main.refuse_blank`).

Each option declares its reader with typer's ``parser=``: ``typer.Option(parser=number)``,
``typer.Option(parser=word)``. A refused value raises ``ValueError("must ...")``, which
:func:`pendcli.cli.messages.usage_message` names by the option as typed.
"""

from __future__ import annotations

import math
import re

__all__ = ["decimal_point", "number", "word"]

_DECIMAL_COMMA = re.compile(r"[+-]?[0-9]+,[0-9]+(?:[eE][+-]?[0-9]+)?")


def decimal_point(text: str) -> str:
    """``9,81`` as ``9.81``; any other text as it is."""
    stripped = text.strip()
    return stripped.replace(",", ".") if _DECIMAL_COMMA.fullmatch(stripped) else text


def number(text: str | float) -> float:
    """A finite number, typed with a decimal point or a decimal comma."""
    if isinstance(text, float | int) and not isinstance(text, bool):
        value = float(text)
    else:
        try:
            value = float(decimal_point(str(text)))
        except ValueError:
            raise ValueError(f"must be a number, got {text!r}") from None
    if not math.isfinite(value):
        raise ValueError(f"must be finite, got {text}")
    return value


def word(text: str) -> str:
    """A word of a list, in any case and with surrounding spaces: ``" Holds"`` is ``holds``."""
    return text.strip().casefold()
