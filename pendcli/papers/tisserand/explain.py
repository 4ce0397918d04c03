"""Tisserand's hand computation of the example, declared for :mod:`pendcli.verify.explain`.

His example (θ0 = 30°, θ1 = 15°) prints three coefficients in seconds of arc and a bound of
1/5 mm. All four agree with his own series (II), (V); the search asks how robust the agreement
is: which readings of the constants of the time also give his seconds, and how often the same
search would give a random number of seconds. His computation, from the summary formulas:

* u0 = sin 30° = 1/2; u1 = sin 15°, exact or from a table (4 or 5 figures), or u1² =
  (2 - √3)/4 with √3 to 3-5 figures; u1² kept or rounded at 3-5 figures;
* (II): ψ's sin 2k't coefficient -(u0² - u1²)(3/32 + 11(u0² + u1²)/256), its sin 4k't
  coefficient (u0² - u1²)²/4096; (V): φ's u0 u1 (u0² - u1²)·17/512;
* radians to seconds by 648000/π exact, 206265, or π as 3,1416 or 3,14;
* the shift l sin θ0 |c| with l = 0,5 m from his printed 2'42'' (or his unrounded c),
  « au plus » a fifth of a millimetre: the shift rounded up at one decimal of a millimetre.

The printed values (the seconds, 1/5, l, θ0, θ1) are read from the published table.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from fractions import Fraction
from functools import cache, partial
from typing import Any

from pendcli.data.tables import load_paper_table
from pendcli.verify.explain import (
    PI_READINGS,
    Axis,
    Computation,
    Declared,
    Target,
    axis,
    fraction_text,
    printed_fraction,
    rounding_axis,
    significant_round,
)

__all__ = ["computations", "declared", "targets"]

PAPER = "tisserand"
Choices = Mapping[str, Any]


def _constant(name: str) -> Fraction:
    return Fraction(repr(load_paper_table(PAPER).constant(name)))


@cache
def _sin_degrees(degrees: Fraction) -> Fraction:
    import mpmath

    with mpmath.workdps(40):
        x = mpmath.mpf(degrees.numerator) / degrees.denominator
        return Fraction(mpmath.nstr(mpmath.sin(mpmath.radians(x)), 30))


@cache
def _pi() -> Fraction:
    import mpmath

    with mpmath.workdps(40):
        return Fraction(mpmath.nstr(mpmath.pi, 35))


@cache
def _sqrt3() -> Fraction:
    import mpmath

    with mpmath.workdps(40):
        return Fraction(mpmath.nstr(mpmath.sqrt(3), 30))


def _u1_squared_axis() -> Axis:
    """u1² = sin² θ1: exact, from a table of sines, or (2 - √3)/4 with a short √3."""
    theta1 = _constant("theta1")
    u1 = _sin_degrees(theta1)
    read = {k: significant_round(u1, k) for k in (4, 5)}  # a table of sines to k figures
    others = [
        (f"sin {theta1}° from a {k}-figure table, {fraction_text(v, k + 1)}", v**2)
        for k, v in read.items()
    ]
    if theta1 == 15:  # sin² 15° = (2 - √3)/4, the form a computer would use
        for k in (3, 4, 5):
            root = significant_round(_sqrt3(), k)
            others.append((f"u1² = (2 - √3)/4, √3 = {fraction_text(root, k)}", (2 - root) / 4))
    return axis("u1²", (f"sin {theta1}° exact", u1 * u1), *others)


def _seconds_axis() -> Axis:
    """One radian in seconds of arc: 648000/π exactly, 206265, or with a short π."""
    others = [("1 rad = 206265''", Fraction(206265))]
    others += [(f"1 rad = 648000''/π, {label}", 648000 / pi) for label, pi in PI_READINGS[:2]]
    return axis("1 rad", ("1 rad = 648000''/π exact", 648000 / _pi()), *others)


def _u0_squared() -> Fraction:
    return _sin_degrees(_constant("theta0")) ** 2


def _coefficient(kind: str) -> Callable[[Choices], Fraction]:
    """One of the three printed coefficients in seconds, from (II) or (V)."""

    def compute(c: Choices) -> Fraction:
        p0, p1 = _u0_squared(), c["rounding"](c["u1²"])
        e = p0 - p1
        if kind == "psi_sin2":
            rad = -e * (Fraction(3, 32) + 11 * (p0 + p1) / 256)
        elif kind == "psi_sin4":
            rad = e * e / 4096
        else:  # (V): u0 u1 = sin θ0 · √(u1²); u0 = 1/2 exactly at 30°
            rad = _sin_degrees(_constant("theta0")) * _sqrt_fraction(p1) * e * Fraction(17, 512)
        return rad * c["1 rad"]

    return compute


def _sqrt_fraction(x: Fraction) -> Fraction:
    import mpmath

    with mpmath.workdps(40):
        return Fraction(mpmath.nstr(mpmath.sqrt(mpmath.mpf(x.numerator) / x.denominator), 30))


FORMULAS = {
    "psi_sin2": "-(u0² - u1²)(3/32 + 11(u0² + u1²)/256), (II)",
    "psi_sin4": "(u0² - u1²)²/4096, (II)",
    "phi_sin2": "u0 u1 (u0² - u1²)·17/512, (V)",
}


def _coefficient_computation(kind: str) -> Computation:
    axes = (_u1_squared_axis(), rounding_axis("rounding", (3, 4, 5)), _seconds_axis())
    # rounding_axis names its options after the axis: "rounding kept in full" reads badly
    axes = (axes[0], _renamed(axes[1], "rounding", "u1²"), axes[2])
    return Computation(FORMULAS[kind], axes, _coefficient(kind), slips=False)


def _renamed(a: Axis, old: str, new: str) -> Axis:
    return Axis(
        a.name, tuple(type(o)(o.label.replace(old, new, 1), o.value, o.steps) for o in a.options)
    )


def _displacement_computation() -> Computation:
    """l sin θ0 |c| in mm, c his printed 2'42'' (or unrounded from (V))."""
    table = load_paper_table(PAPER)
    printed_c = printed_fraction(table.claim("tisserand.example.phi_sin2").number)  # degrees
    unrounded = (
        _coefficient("phi_sin2")(
            {
                "u1²": _sin_degrees(_constant("theta1")) ** 2,
                "rounding": lambda x: x,
                "1 rad": 648000 / _pi(),
            }
        )
        / 3600
    )
    c_axis = axis(
        "c",
        (f"his printed c = {table.claim('tisserand.example.phi_sin2').published}", printed_c),
        (f"his unrounded c from (V), {fraction_text(unrounded * 3600, 3)}''", unrounded),
    )
    to_rad = axis(
        "1°",
        ("1° = π/180 exact", _pi() / 180),
        *((f"1° = π/180, {label}", pi / 180) for label, pi in PI_READINGS[:2]),
    )
    sin0 = _sin_degrees(_constant("theta0"))
    length_mm = 1000 * _constant("length")

    def compute(c: Choices) -> Fraction:
        return length_mm * sin0 * abs(c["c"]) * c["1°"]

    return Computation("l sin θ0 |c|, l = 0,5 m, in mm", (c_axis, to_rad), compute, slips=False)


def targets() -> dict[str, Target]:
    """The printed numbers searched for (the bound 1/5 mm at one decimal of a millimetre)."""
    table = load_paper_table(PAPER)
    out = {}
    for kind in FORMULAS:
        entry = table.claim(f"{PAPER}.example.{kind}")
        seconds = printed_fraction(entry.number) * 3600
        out[entry.id] = Target(entry.published, int(seconds), Fraction(1), False)
    bound = table.claim(f"{PAPER}.example.displacement")
    tenth = Fraction(1, 10)
    value = printed_fraction(bound.number)
    out[bound.id] = Target(bound.published, int(value / tenth), tenth, bound=True)
    return out


def computations() -> dict[str, Callable[[], Computation]]:
    """Claim id -> a builder of Tisserand's computation of that printed number."""
    out: dict[str, Callable[[], Computation]] = {
        f"{PAPER}.example.{kind}": partial(_coefficient_computation, kind) for kind in FORMULAS
    }
    out[f"{PAPER}.example.displacement"] = _displacement_computation
    return out


def declared() -> Declared:
    """What `pendcli explain` searches in this paper: its computations and their targets."""
    return Declared(computations(), targets())
