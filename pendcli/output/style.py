"""The number style of each output, written once: digits, decimal mark, angles, lists.

Every renderer writes its numbers through one :class:`NumberStyle`:

* the terminal (:data:`TERMINAL`): at most 7 significant digits, a decimal point;
* Markdown (:data:`MARKDOWN`): at most 10 significant digits, a decimal point;
* JSON and CSV (:data:`MACHINE`): every digit (``repr``, an exact round trip), a point;
* the edition and the report's prose (:data:`EDITION`): the papers' decimal comma, the typeset
  minus and powers of ten (``1,2·10⁻⁵``), angles with ′ and ″, lists separated by « ; ».

Within a column the notation is one: fixed, trailing zeros kept and the decimal points aligned
(:meth:`NumberStyle.column`), never a switch to ``9.092e-04`` among fixed numbers unless the
column needs a power of ten throughout. An angle beside a sexagesimal printed value is written
sexagesimal (:meth:`NumberStyle.angle`). The renderers set the style while they format
(:func:`using`), so a column's own format (:func:`~pendcli.output.columns.fmt_float`) follows
the output it is drawn in. Nothing here knows what the numbers measure.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass

from pendcli.data.numbers import fixed, fixed_decimals, sexagesimal_text, significant

__all__ = [
    "EDITION",
    "MACHINE",
    "MARKDOWN",
    "TERMINAL",
    "NumberStyle",
    "current",
    "trimmed",
    "using",
]

# The smallest and largest magnitudes a column shows in fixed notation: below, a fixed number
# would be mostly leading zeros; above, more digits before the point than the style shows.
_FIXED_SMALLEST = 1e-4


@dataclass(frozen=True)
class NumberStyle:
    """How one output writes numbers; ``digits`` None: every digit (``repr``)."""

    name: str
    digits: int | None
    decimal: str = "."
    minus: str = "-"
    typeset_power: bool = False
    angle_marks: tuple[str, str, str] = ("°", "'", "''")
    list_separator: str = ", "

    def cap(self, digits: int | None) -> int | None:
        """``digits`` asked by a column, within what this output shows."""
        if self.digits is None:
            return digits
        return self.digits if digits is None else min(digits, self.digits)

    def number(self, value: float | None, digits: int | None = None) -> str:
        """One number, significant digits (trailing zeros dropped); "" for None or NaN."""
        if value is None or (isinstance(value, float) and math.isnan(value)):
            return ""
        if isinstance(value, int):  # (and a bool)
            return str(value).replace("-", self.minus)
        if math.isinf(value):
            return "inf" if value > 0 else self.minus + "inf"
        if value == 0:
            return "0"
        sig = self.cap(digits)
        if sig is None:
            return repr(float(value)).replace(".", self.decimal).replace("-", self.minus)
        return significant(value, sig, self.decimal, self.minus, self.typeset_power)

    def fixed(self, value: float, digits: int | None = None, most: int | None = None) -> str:
        """``value`` in fixed notation with the style's significant digits (trailing zeros
        kept); with ``most``, fewer digits until the text fits ``most`` characters (at least
        two significant digits: a smaller room gets the power of ten)."""
        sig = self.cap(digits) or 17
        while True:
            text = fixed(value, fixed_decimals(value, sig), self.decimal, self.minus)
            if most is None or len(text) <= most:
                return text
            if sig <= 2:
                return self.number(value, 2)
            sig -= 1

    def column(
        self, values: Sequence[float | None], digits: int | None = None, trim: bool = False
    ) -> list[str]:
        """A column of numbers in one notation: fixed with ``digits`` significant digits
        (trailing zeros kept) and the decimal points aligned (blank padding after the shorter
        fractions), or, when a value is too small or too large for fixed notation, every value
        with its power of ten. None and NaN give "". ``trim``: trailing zeros dropped instead
        (a column whose digits were not chosen: 0.375, not 0.3750000)."""
        sig = self.cap(digits) or 17
        finite = [v for v in values if v is not None and math.isfinite(v) and v != 0]
        if any(abs(v) < _FIXED_SMALLEST or abs(v) >= 10**sig for v in finite):
            texts = [self._scientific(v, sig) for v in values]
            return [trimmed(t, self.decimal) for t in texts] if trim else texts
        texts = [
            ""
            if v is None or math.isnan(v)
            else self.number(v)
            if math.isinf(v)
            else fixed(v, fixed_decimals(v, sig), self.decimal, self.minus)
            for v in values
        ]
        if trim:
            return [trimmed(t, self.decimal) for t in texts]
        after = [len(t) - t.index(self.decimal) if self.decimal in t else 0 for t in texts]
        widest = max(after, default=0)
        return [t + " " * (widest - a) if t else t for t, a in zip(texts, after, strict=True)]

    def _scientific(self, value: float | None, sig: int) -> str:
        if value is None or not math.isfinite(value):
            return self.number(value)
        mantissa, _, exponent = f"{value:.{sig - 1}e}".partition("e")
        text = mantissa.replace(".", self.decimal).replace("-", self.minus)
        if self.typeset_power:
            return significant(value, sig, self.decimal, self.minus, True)
        return f"{text}e{exponent}"

    def angle(self, degrees: float, decimals: int = 2) -> str:
        """An angle in degrees, sexagesimal as the papers print it: ``-1°7'33.14''``,
        ``2'42.20''``, ``1.69''`` (leading zero parts left out)."""
        return sexagesimal_text(degrees, decimals, self.angle_marks, self.decimal, self.minus)

    def listing(self, items: Sequence[object]) -> str:
        """Numbers in a row, separated so that a decimal comma cannot be read as one:
        ``0, 0.91, 1.66`` with a point, ``0 ; 0,91 ; 1,66`` with a comma."""
        return self.list_separator.join(
            self.number(i) if isinstance(i, float) else str(i) for i in items
        )


def trimmed(text: str, decimal: str = ".") -> str:
    """A number without the trailing zeros of its digits (``0.3750000`` -> ``0.375``,
    ``1.000000e-05`` -> ``1e-05``)."""
    mantissa, mark, power = text.partition("e")
    if decimal not in mantissa or not mantissa[-1:].isdigit():
        return text
    return mantissa.rstrip("0").rstrip(decimal) + mark + power


TERMINAL = NumberStyle("terminal", 7)
MARKDOWN = NumberStyle("markdown", 10)
MACHINE = NumberStyle("machine", None)
EDITION = NumberStyle(
    "edition",
    10,
    decimal=",",
    minus="\u2212",
    typeset_power=True,
    angle_marks=("°", "′", "″"),
    list_separator=" ; ",
)

# Outside a renderer (a library caller formatting a value itself): the digits it asks for.
_UNCAPPED = NumberStyle("uncapped", None)
_current: ContextVar[NumberStyle] = ContextVar("number_style", default=_UNCAPPED)


def current() -> NumberStyle:
    """The style of the output being drawn (uncapped outside a renderer)."""
    return _current.get()


@contextmanager
def using(style: NumberStyle) -> Iterator[NumberStyle]:
    """Draw with ``style``: every number formatted inside follows it."""
    token = _current.set(style)
    try:
        yield style
    finally:
        _current.reset(token)
