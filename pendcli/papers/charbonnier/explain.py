"""Charbonnier's table of I_n(π) (no. 15), declared for :mod:`pendcli.verify.explain`.

Every printed I_n(π) agrees exactly; the search shows by which of his routes and how often
the same routes would give a random fraction. His routes, both printed in no. 15: the
recurrence (n + 1) I_n = -cos x sinⁿ x + n I_(n-2) at x = π (the boundary term vanishes),
from I_(-1) = π and I_0 = 2; and the closed form, a product of evens over odds. A slip the
search also tries: the recurrence's factor with its index shifted, (n + 1)/(n + 2) or
(n - 1)/n. A printed value is q·π^p; the search reproduces the rational q exactly (a
random target: another numerator over the same denominator).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from fractions import Fraction
from functools import partial
from typing import Any

from pendcli.data.numbers import exact_number
from pendcli.data.tables import load_paper_table
from pendcli.verify.explain import Axis, Computation, Declared, Option, Target

__all__ = ["computations", "declared", "targets"]

PAPER = "charbonnier"
PRINTED_N = range(-1, 6)
Choices = Mapping[str, Any]


def _recurrence(n: int, shift: int) -> Fraction:
    """q of I_n(π) = q π^(n mod 2) by (k + 1) I_k = k I_(k-2), the factor's index shifted."""
    q = Fraction(1) if n % 2 else Fraction(2)  # I_(-1) = π, I_0 = 2 (the text)
    for k in range(2 - n % 2, n + 1, 2):
        q *= Fraction(k + shift, k + 1 + shift)
    return q


def _closed_form(n: int) -> Fraction:
    """The printed general formula: 2·(2·4…n)/(1·3…(n+1)), or (1·3…n)/(2·4…(n+1)) times π."""
    if n == -1:
        return Fraction(1)
    if n % 2 == 0:
        return Fraction(2 * math.prod(range(2, n + 1, 2)), math.prod(range(1, n + 2, 2)))
    return Fraction(math.prod(range(1, n + 1, 2)), math.prod(range(2, n + 2, 2)))


def _computation(n: int) -> Computation:
    route = Axis(
        "route",
        (
            Option("recurrence (n + 1) I_n = n I_(n-2) at x = π, as printed", ("rec", 0), 0),
            Option("closed form, products of evens over odds, as printed", ("closed", 0), 0),
            Option("recurrence with the factor (n + 1)/(n + 2) (index slip)", ("rec", 1), 1),
            Option("recurrence with the factor (n - 1)/n (index slip)", ("rec", -1), 1),
        ),
    )

    def compute(c: Choices) -> Fraction:
        kind, shift = c["route"]
        return _closed_form(n) if kind == "closed" else _recurrence(n, shift)

    return Computation(f"I_{n}(π) / π^{n % 2}", (route,), compute, slips=False)


def targets() -> dict[str, Target]:
    """Each printed I_n(π) = q π^p as the numerator of q over its denominator."""
    table = load_paper_table(PAPER)
    out = {}
    for n in PRINTED_N:
        entry = table.claim(f"{PAPER}.I_pi.n{n}")
        q = exact_number(entry.number).exact  # « 2 » of the table is exact, like the rest
        if q is None:
            raise ValueError(f"{entry.id}: {entry.published!r} is not an exact value")
        out[entry.id] = Target(entry.published, q.numerator, Fraction(1, q.denominator), exact=True)
    return out


def computations() -> dict[str, Callable[[], Computation]]:
    """Claim id -> a builder of Charbonnier's computation of that printed value."""
    return {f"{PAPER}.I_pi.n{n}": partial(_computation, n) for n in PRINTED_N}


def declared() -> Declared:
    """What `pendcli explain` searches in this paper: its computations and their targets."""
    return Declared(computations(), targets())
