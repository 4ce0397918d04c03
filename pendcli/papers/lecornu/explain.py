"""Lecornu's hand computations, declared for the search of :mod:`pendcli.verify.explain`.

For each of the 22 printed numbers that do not agree, :func:`computations` gives the author's
computation as a function of his choices. The formulas are his (the procedures of
:mod:`.claims`: 0,00313·z², (1 m - l)/0,35, differences of his times, J_0 at his zeros and
ratios of his J_0, 3,83²/4, π(7π² - 3)/32); his printed intermediates are read from
``tables/published/lecornu.toml``, never retyped. The choices:

* his printed intermediate (0 steps) or more digits than he printed: the exact value, or his
  own formula unrounded (1 step);
* g as 9,8, 9,808 or Paris's 9,809 against the table's 9,81; π as 3,14, 3,1416 or 22/7;
* a Bessel value exact or read from a table of J_0, J_1 up to 20 (step 0,1 or 0,01, 3 or 4
  decimals, nearest or preceding entry or linear interpolation; the interpolation's
  correction with its sign reversed is a slip, 2 steps); a zero exact or interpolated in
  such a table;
* a square rounded or chopped at 2-5 figures; a borrow slip in 1 - l; 1/0,35 taken as his
  printed 2,86;
* the formula as printed against the formula as corrected (6,47).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from fractions import Fraction
from functools import cache, partial
from typing import Any

from pendcli.data.tables import load_paper_table
from pendcli.verify.bessel_tables import (
    TABLE_DECIMALS,
    TABLE_STEPS,
    TABLE_SUMMARY,
    bessel_axis,
    table_zero,
)
from pendcli.verify.explain import (
    G_READINGS,
    PI_READINGS,
    Axis,
    Computation,
    Declared,
    Option,
    Target,
    axis,
    constant_axis,
    fraction_text,
    printed_fraction,
    rounding_axis,
    target_of,
)

__all__ = ["computations", "declared", "targets"]

PAPER = "lecornu"
ELONGATIONS = 5
Choices = Mapping[str, Any]


def _printed(claim_id: str) -> Fraction:
    return printed_fraction(load_paper_table(PAPER).claim(claim_id).number)


def _text(claim_id: str) -> str:
    return load_paper_table(PAPER).claim(claim_id).published


def _constant(name: str) -> Fraction:
    return Fraction(repr(load_paper_table(PAPER).constant(name)))


@cache
def _zero(order: int, k: int) -> Fraction:
    """j_(order,k) to 30 digits (mpmath)."""
    import mpmath

    with mpmath.workdps(40):
        return Fraction(mpmath.nstr(mpmath.besseljzero(order, k), 30))


def _coefficient_exact() -> Fraction:
    """b²/(4g) at the table's g."""
    return _constant("speed") ** 2 / (4 * _constant("g"))


# --- the zeros (truncations) -------------------------------------------------------------


def _zero_computation(order: int, k: int) -> Computation:
    """A zero of J_order: exact, or interpolated in a table of J_0, J_1."""
    exact = _zero(order, k)
    options = [Option(f"j_({order},{k}) exact, {fraction_text(exact, 5)}", exact, 0)]
    for step in TABLE_STEPS:
        for d in TABLE_DECIMALS:
            z = table_zero(order, exact, step, d)
            label = f"zero interpolated in a table at step {fraction_text(step)}, {d} decimals"
            options.append(Option(f"{label}: {fraction_text(z, 5)}", z))
    equation = "J_1(z) = 0" if order == 1 else "2J_1(z) = zJ_0(z), eq. (14)"
    return Computation(
        f"the root of {equation}", (Axis("zero", tuple(options)),), lambda c: c["zero"]
    )


# --- the coefficient, lengths, times, intervals ------------------------------------------


def _coefficient_computation() -> Computation:
    g = _constant("g")
    readings = [(label, value) for label, value in G_READINGS if value != g]
    readings.append(("g = 9,809 (Paris)", Fraction(9809, 1000)))
    g_axis = constant_axis("g", g, readings, f"g = {fraction_text(g)} (the table's)")
    b = _constant("speed")
    return Computation("b²/(4g), b = 0,35", (g_axis,), lambda c: b**2 / (4 * c["g"]))


def _length_axis(k: int) -> Axis:
    """The length at the k-th elongation: his printed l_k, or more digits."""
    claim = f"lecornu.example.length.{k}"
    z = _printed(f"lecornu.j2_zeros.{ELONGATIONS + 1 - k}")
    own = _printed("lecornu.coefficient_b2_4g") * z**2
    exact = _coefficient_exact() * _zero(2, ELONGATIONS + 1 - k) ** 2
    return axis(
        f"l_{k}",
        (f"his printed l_{k} = {_text(claim)}", _printed(claim)),
        (f"his 0,00313·{fraction_text(z)}² unrounded, {fraction_text(own, 5)}", own),
        (f"the exact length {fraction_text(exact, 5)}", exact),
    )


def _time_computation(k: int) -> Computation:
    """t_k = (1 m - l_k)/0,35 (his times from his lengths)."""
    length, speed = _constant("length"), _constant("speed")
    slip = Axis(
        "1 - l",
        (
            Option("1 - l subtracted right", Fraction(0), 0),
            Option("borrow slip in 1 - l: last place +1", Fraction(1, 100)),
            Option("borrow slip in 1 - l: last place -1", Fraction(-1, 100)),
        ),
    )
    end = _printed("lecornu.example.time_zero_length")
    divide = axis(
        "1/b",
        ("divided by 0,35", 1 / speed),
        (f"multiplied by his 1/0,35 = {_text('lecornu.example.time_zero_length')}", end),
    )

    def compute(c: Choices) -> Fraction:
        return (length - c[f"l_{k}"] + c["1 - l"]) * c["1/b"]

    return Computation("(1 m - l)/0,35", (_length_axis(k), slip, divide), compute)


def _time_axis(name: str, claim: str, k: int | None) -> Axis:
    """A time: his printed value, or the time from the exact length (None: zero length)."""
    length, speed = _constant("length"), _constant("speed")
    exact_length = Fraction(0) if k is None else _coefficient_exact() * _zero(2, 6 - k) ** 2
    exact = (length - exact_length) / speed
    return axis(
        name,
        (f"his printed {name} = {_text(claim)}", _printed(claim)),
        (f"{name} from the exact length, {fraction_text(exact, 4)}", exact),
    )


def _interval_computation(k: int) -> Computation:
    """The k-th interval: the difference of his (printed) times."""
    earlier = f"lecornu.example.time.{k}"
    later = (
        "lecornu.example.time_zero_length" if k == ELONGATIONS else f"lecornu.example.time.{k + 1}"
    )
    axes = (
        _time_axis("earlier time", earlier, k),
        _time_axis("later time", later, None if k == ELONGATIONS else k + 1),
    )
    return Computation(
        "later time - earlier time", axes, lambda c: c["later time"] - c["earlier time"]
    )


# --- J_0 and the deviations --------------------------------------------------------------


def _argument_axis(k: int) -> Axis:
    claim = f"lecornu.j2_zeros.{k}"
    exact = _zero(2, k)
    return axis(
        "z",
        (f"at his printed zero z = {_text(claim)}", _printed(claim)),
        (f"at the exact zero {fraction_text(exact, 5)}", exact),
    )


def _j0_computation(k: int) -> Computation:
    """J_0 at the k-th zero of J_2 (his printed zero, read from his tables)."""
    axes = (_argument_axis(k), bessel_axis("J_0", 0, "J_0"))
    return Computation("J_0(z)", axes, lambda c: c["J_0"](c["z"]))


def _j0_value_axis(name: str, k: int) -> Axis:
    """J_0 at the k-th zero: his printed value (0 steps), or read again at his printed zero."""
    claim = f"lecornu.j0_at_j2_zeros.{k}"
    z = _printed(f"lecornu.j2_zeros.{k}")
    options = [Option(f"his printed {name} = {_text(claim)}", _printed(claim), 0)]
    for option in bessel_axis(name, 0, f"{name} at z = {_text(f'lecornu.j2_zeros.{k}')}").options:
        options.append(Option(option.label, option.value(z), max(1, option.steps)))
    return Axis(name, tuple(options), f"his printed value, or {TABLE_SUMMARY}")


def _deviation_computation(k: int | None) -> Computation:
    """θ/θ0 = J_0(z_k)/J_0(17,96), or 1/J_0(17,96) at zero length (k None)."""
    first = _j0_value_axis("J_0(17,96)", ELONGATIONS)
    if k is None:
        return Computation("1/J_0(17,96)", (first,), lambda c: 1 / c["J_0(17,96)"])
    name = f"J_0({_text(f'lecornu.j2_zeros.{k}')})"
    axes = (_j0_value_axis(name, k), first)
    return Computation(f"{name}/J_0(17,96)", axes, lambda c: c[name] / c["J_0(17,96)"])


# --- the J_1 lengths, 3,83²/4, 6,47 ------------------------------------------------------


def _zero_axis(claim: str, order: int, k: int) -> Axis:
    exact = _zero(order, k)
    return axis(
        "z",
        (f"his printed z = {_text(claim)}", _printed(claim)),
        (f"the exact zero {fraction_text(exact, 5)}", exact),
    )


def _j1_length_computation(index: int) -> Computation:
    """l = 0,00313 z² at a zero of J_1 (printed from 19,61 down: index 1 is j_(1,6))."""
    claim = f"lecornu.j1_zeros.{index}"
    coefficient = axis(
        "b²/4g",
        ("his printed 0,00313", _printed("lecornu.coefficient_b2_4g")),
        (
            f"b²/4g at g = 9,81 unrounded, {fraction_text(_coefficient_exact(), 7)}",
            _coefficient_exact(),
        ),
        ("b²/4g at g = 9,8 unrounded, 0,003125", _constant("speed") ** 2 / (4 * Fraction(98, 10))),
    )
    first = _printed(f"lecornu.j2_zeros.{ELONGATIONS}")
    formula = axis(
        "formula",
        ("(16): l = (b²/4g) z²", "coefficient"),
        (
            f"l = (z/{_text(f'lecornu.j2_zeros.{ELONGATIONS}')})² (1 m at the first elongation)",
            "ratio",
        ),
    )
    axes = (_zero_axis(claim, 1, 7 - index), rounding_axis("z²", (3, 4, 5)), coefficient, formula)

    def compute(c: Choices) -> Fraction:
        square = c["z²"](c["z"] ** 2)
        if c["formula"] == "ratio":
            return square / first**2
        return c["b²/4g"] * square

    return Computation("0,00313 z²", axes, compute)


def _x_bound_computation() -> Computation:
    axes = (_zero_axis("lecornu.j1_zeros.6", 1, 1), rounding_axis("z²", (3, 4, 5)))
    return Computation("z²/4, z = 3,83", axes, lambda c: c["z²"](c["z"] ** 2) / 4)


@cache
def _pi() -> Fraction:
    import mpmath

    with mpmath.workdps(40):
        return Fraction(mpmath.nstr(mpmath.pi, 35))


def _mean_pendulum_computation() -> Computation:
    """π(7π² - 3)/32 as printed, or the corrected π(π² - 3)/32; π as he may have taken it."""
    formula = axis("formula", ("as printed, π(7π² - 3)/32", 7), ("as corrected, π(π² - 3)/32", 1))
    axes = (formula, constant_axis("π", _pi(), PI_READINGS, "π exact"), rounding_axis("π²"))

    def compute(c: Choices) -> Fraction:
        pi = c["π"]
        return pi * (c["formula"] * c["π²"](pi * pi) - 3) / 32

    return Computation("π(7π² - 3)/32", axes, compute)


# --- the declarations ----------------------------------------------------------------------


def _builders() -> dict[str, Callable[[], Computation]]:
    ex = "lecornu.example."
    return {
        "lecornu.j2_zeros.2": lambda: _zero_computation(2, 2),
        "lecornu.coefficient_b2_4g": _coefficient_computation,
        **{f"{ex}time.{k}": partial(_time_computation, k) for k in (2, 3, 5)},
        **{f"{ex}interval.{k}": partial(_interval_computation, k) for k in (1, 2, 5)},
        **{f"lecornu.j0_at_j2_zeros.{k}": partial(_j0_computation, k) for k in (1, 2, 4)},
        **{f"lecornu.deviation.{k}": partial(_deviation_computation, 6 - k) for k in (2, 3, 4, 5)},
        "lecornu.deviation.zero_length": lambda: _deviation_computation(None),
        "lecornu.j1_zeros.1": lambda: _zero_computation(1, 6),
        "lecornu.j1_zeros.5": lambda: _zero_computation(1, 2),
        "lecornu.j1_lengths.1": lambda: _j1_length_computation(1),
        "lecornu.j1_lengths.6": lambda: _j1_length_computation(6),
        "lecornu.x_bound": _x_bound_computation,
        "lecornu.mean_pendulum_coefficient": _mean_pendulum_computation,
    }


def computations() -> dict[str, Callable[[], Computation]]:
    """Claim id -> a builder of the author's computation of that printed number (built only
    when asked: a Bessel table is read lazily)."""
    return _builders()


def targets() -> dict[str, Target]:
    """The printed number of every declared claim, at its printed precision."""
    table = load_paper_table(PAPER)
    return {cid: target_of(table.claim(cid)) for cid in _builders()}


def declared() -> Declared:
    """What `pendcli explain` searches in this paper: its computations and their targets."""
    return Declared(computations(), targets())
