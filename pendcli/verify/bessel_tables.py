"""Values read from the Bessel tables a nineteenth-century author used: the tabulated entry,
read at the nearest or preceding argument or interpolated (or the interpolation's correction
applied with its sign reversed, a slip), and a zero found from the table by interpolation.

The choices of an explanation (:mod:`pendcli.verify.explain`) a paper builds from them.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from pendcli.verify.explain import Axis, Option, fraction_text, round_half_up

__all__ = [
    "TABLE_DECIMALS",
    "TABLE_END",
    "TABLE_STEPS",
    "TABLE_SUMMARY",
    "TableReading",
    "bessel_axis",
    "bessel_exact",
    "table_entry",
    "table_readings",
    "table_zero",
]


TABLE_STEPS = (Fraction(1, 10), Fraction(1, 100))  # argument step of a Bessel table


TABLE_DECIMALS = (3, 4)  # tabulated to 3 or 4 decimals


TABLE_END = 20  # « les tables ne vont pas plus loin »


TABLE_SUMMARY = (
    "exact, or read from a table to 20 at step 0,1 or 0,01, 3 or 4 decimals: nearest or "
    "preceding entry, linear interpolation, or the interpolation's sign reversed (a slip)"
)


def bessel_exact(order: int, z: Fraction) -> Fraction:
    """J_order(z) to 30 significant digits (mpmath), as a rational."""
    import mpmath

    with mpmath.workdps(40):
        return Fraction(
            mpmath.nstr(mpmath.besselj(order, mpmath.mpf(z.numerator) / z.denominator), 30)
        )


_ENTRIES: dict[tuple[int, Fraction, int], Fraction] = {}


def table_entry(order: int, x: Fraction, decimals: int) -> Fraction:
    """The tabulated J_order(x): the true value rounded half up at ``decimals`` decimals."""
    if not 0 <= x <= TABLE_END:
        raise ValueError(f"the tables end at {TABLE_END}: no entry at {float(x)}")
    key = (order, x, decimals)
    if key not in _ENTRIES:
        _ENTRIES[key] = round_half_up(bessel_exact(order, x), decimals)
    return _ENTRIES[key]


@dataclass(frozen=True)
class TableReading:
    """How a value is read from a table: its step, its decimals, with or without interpolation.

    ``nearest`` / ``preceding``: the entry at the nearest / the preceding tabulated argument;
    ``linear``: linear interpolation between the two entries around z; ``reversed``: the
    interpolation's correction applied with the wrong sign (a slip: one step more).
    """

    step: Fraction
    decimals: int
    mode: str

    def label(self, what: str) -> str:
        words = {
            "nearest": "nearest entry",
            "preceding": "preceding entry",
            "linear": "linear interpolation",
            "reversed": "interpolation with the correction's sign reversed",
        }[self.mode]
        step = fraction_text(self.step)
        return f"{what} from a table at step {step}, {self.decimals} decimals, {words}"

    def read(self, order: int, z: Fraction) -> Fraction:
        below = math.floor(z / self.step) * self.step
        lower = table_entry(order, below, self.decimals)
        if self.mode == "preceding" or z == below:
            return lower
        upper = table_entry(order, below + self.step, self.decimals)
        if self.mode == "nearest":
            return lower if z - below < below + self.step - z else upper
        sign = -1 if self.mode == "reversed" else 1
        return lower + sign * (upper - lower) * (z - below) / self.step


def table_readings(modes: Sequence[str] = ("nearest", "preceding", "linear")) -> list[TableReading]:
    return [TableReading(step, d, m) for step in TABLE_STEPS for d in TABLE_DECIMALS for m in modes]


def bessel_axis(name: str, order: int, what: str) -> Axis:
    """J_order at a given z: exact (0 steps), read from a table (1), or misread (2).

    The option values are functions z -> J_order(z) so that the argument can itself be a
    choice (his printed zero or the exact one).
    """
    options = [Option(f"{what} exact", lambda z: bessel_exact(order, z), 0)]
    for r in table_readings():
        options.append(Option(r.label(what), lambda z, r=r: r.read(order, z), 1))
    for r in table_readings(("reversed",)):
        options.append(Option(r.label(what), lambda z, r=r: r.read(order, z), 2))
    return Axis(name, tuple(options), TABLE_SUMMARY)


def _table_f(kind: int, x: Fraction, decimals: int) -> Fraction:
    """The tabulated function whose zeros are wanted: J_1 (kind 1) or 2J_1 - xJ_0 (kind 2)."""
    if kind == 1:
        return table_entry(1, x, decimals)
    return 2 * table_entry(1, x, decimals) - x * table_entry(0, x, decimals)


def table_zero(kind: int, near: Fraction, step: Fraction, decimals: int) -> Fraction:
    """A zero of J_1 (kind 1) or of J_2 (kind 2: 2J_1(z) = zJ_0(z), eq. (14)) found from a
    table of J_0, J_1 by linear interpolation across the sign change nearest ``near``."""
    start = math.floor(near / step)
    for offset in (0, -1, 1, -2, 2):
        a = (start + offset) * step
        b = a + step
        if b > TABLE_END or a < 0:
            continue
        fa, fb = _table_f(kind, a, decimals), _table_f(kind, b, decimals)
        if fa == 0:
            return a
        if (fa < 0) != (fb < 0):
            return a + step * fa / (fa - fb)
    raise ValueError(f"no sign change of the tabulated function near {float(near)}")
