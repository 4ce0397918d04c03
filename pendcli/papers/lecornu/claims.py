"""Every printed number of Lecornu's section II (and k⁴ of III), recomputed.

:func:`recompute` merges small builders, one per group of printed numbers (the zeros (15),
the speeds, the coefficient of (16), the example's lengths, times and intervals, J_0 at the
zeros of J_2, the deviations, the zeros of J_1 and their lengths, the constants -0,13 and
6,47, k⁴). Each value is the author's model done exactly (:mod:`.model`); the note gives the
author's own procedure from his printed, rounded intermediates (read from the published
table, never retyped), so that a carried rounding can be told from a slip; ``exact`` holds the
fuller model (released from rest, or the exact solution extrapolated to b → 0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from pendcli.base.errors import PendcliError
from pendcli.data.numbers import paper_decimals
from pendcli.numerics.besselzeros import bessel_zeros
from pendcli.papers.lecornu.model import (
    Array,
    ExampleModel,
    FromRestModel,
    constant,
    example_model,
    from_rest_model,
    half_oscillation_coefficient_exact,
    lecornu_k4,
    lecornu_series,
    mean_pendulum_coefficient_exact,
    period_b2_coefficient_exact,
    printed,
    printed_number,
)
from pendcli.verify.causes import Procedure
from pendcli.verify.claims import Recomputed

__all__ = ["ExampleInputs", "author_procedures", "check_claims_g", "example_inputs", "recompute"]

Claims = dict[str, Recomputed]
PRINTED_ELONGATIONS = 5  # the example lists five elongations, (15)


@dataclass(frozen=True)
class ExampleInputs:
    """What the builders share: the example at g, the zeros, and the author's printed values."""

    g: float
    speed: float  # 0,35 m/s
    length: float  # 1 m at t = 0
    z2: Array  # the first six zeros of J_2, ascending
    z1: Array  # the first seven zeros of J_1, ascending
    model: ExampleModel  # solution (10)
    rest: FromRestModel  # released from rest at 1 m
    printed_z2: Array  # (15), ascending
    printed_z1: Array  # descending, as printed
    printed_coefficient: float  # 0,00313 of (16)

    @property
    def b(self) -> str:
        """The speed as the paper prints it: "0,35 m/s"."""
        return f"{_comma(self.speed)} m/s"

    @property
    def l0(self) -> str:
        """The length at t = 0: "1 m"."""
        return f"{self.length:g} m"


def _printed_values(prefix: str, count: int) -> Array:
    """The printed values of claims ``prefix1..prefixN``, in table order."""
    return np.array([printed(f"{prefix}{k}") for k in range(1, count + 1)])


def check_claims_g(g: object, speed: float, z2: Array) -> float:
    """g, if the release (1 m at 0,35 m/s) stays nearest the fifth zero of J_2, i.e. the
    printed example keeps its five elongations: 2√g/b between the midpoints around j_(2,5)."""
    g_low = (speed * (z2[3] + z2[4]) / 4) ** 2
    g_high = (speed * (z2[4] + z2[5]) / 4) ** 2
    if not (isinstance(g, int | float) and math.isfinite(g) and g_low < g < g_high):
        raise PendcliError(
            f"g: {g!r} m/s² changes the structure of the printed example (no longer five "
            f"elongations from 1 m at 0,35 m/s); expected {g_low:.3f} < g < {g_high:.3f} for "
            "the claims"
        )
    return float(g)


def example_inputs(g: float | None = None) -> ExampleInputs:
    """The shared inputs at ``g`` (default: the table's g), the structure checked first."""
    speed, length = constant("speed"), constant("length")
    z2 = bessel_zeros(2, PRINTED_ELONGATIONS + 1)
    gg = check_claims_g(constant("g") if g is None else g, speed, z2)
    return ExampleInputs(
        g=gg,
        speed=speed,
        length=length,
        z2=z2,
        z1=bessel_zeros(1, 7),
        model=example_model(speed, length, gg),
        rest=from_rest_model(speed, length, gg, floor_fraction=1e-3),
        printed_z2=_printed_values("lecornu.j2_zeros.", PRINTED_ELONGATIONS),
        printed_z1=_printed_values("lecornu.j1_zeros.", 6),
        printed_coefficient=printed("lecornu.coefficient_b2_4g"),
    )


def _chop(v: float, decimals: int) -> float:
    f = 10.0**decimals
    return math.copysign(math.floor(abs(v) * f + 1e-9) / f, v)


def _comma(v: float, decimals: int | None = None) -> str:
    """A number the way the paper prints it: decimal comma (shortest form by default)."""
    text = f"{v:g}" if decimals is None else f"{v:.{decimals}f}"
    return text.replace(".", ",")


def _coefficient_text() -> str:
    """His coefficient of (16) as printed: "0,00313"."""
    return printed_number("lecornu.coefficient_b2_4g").text


def _zeros_note(z: float) -> str:
    return f"Exact {z:.5f}: rounded {round(z, 2):.2f}, truncated {_chop(z, 2):.2f}."


def _exact_at(values: Array, k: int, limit: int | None = None) -> float | None:
    """values[k] if the fuller model reaches it (and k < limit), else None."""
    if k < len(values) and (limit is None or k < limit):
        return float(values[k])
    return None


# --- builders, one per group of printed numbers -------------------------------------------


def _j2_zeros(c: ExampleInputs) -> Claims:
    """(15): five zeros of J_2 below 20, the end of his tables."""
    out = {
        "lecornu.j2_zeros.count_below_20": Recomputed(
            float(np.sum(c.z2 < constant("table_limit"))),
            method="zeros of J_2 (pendcli.numerics.besselzeros, auto) below "
            f"{constant('table_limit'):g}",
            note=f"The sixth zero is {c.z2[5]:.4f}, just beyond the table's end.",
        )
    }
    for k in range(PRINTED_ELONGATIONS):
        out[f"lecornu.j2_zeros.{k + 1}"] = Recomputed(
            float(c.z2[k]),
            method="j_(2,k), correctly rounded (mpmath head of bessel_zeros)",
            note=_zeros_note(float(c.z2[k])),
        )
    return out


def _speeds(c: ExampleInputs) -> Claims:
    """The speeds √(g l/ξ) that make the 1 m pendulum follow (10)."""
    out = {}
    for k in range(PRINTED_ELONGATIONS):
        numerator = 2 * math.sqrt(c.g * c.length)
        out[f"lecornu.speed.{k + 1}"] = Recomputed(
            float(numerator / c.z2[k]),
            method=f"√(g l/ξ), ξ = z²/4, l = {c.l0}: 2√g/j_(2,k)",
            note=f"Author's procedure (printed z) gives {numerator / c.printed_z2[k]:.4f}.",
        )
    return out


def _coefficient(c: ExampleInputs) -> Claims:
    """b²/(4g) of (16), printed 0,00313: which g it needs."""
    number = printed_number("lecornu.coefficient_b2_4g")
    lowest = number.value - (number.resolution or 0.0) / 2  # the least value printed 0,00313
    g_max = c.speed**2 / (4 * lowest)
    coef = c.speed**2 / (4 * c.g)
    note = (
        f"Rounds to {number.text} only if g <= {g_max:.3f} "
        f"(g = {g_max:.2f} gives exactly {_comma(lowest, 6)}); with g = {c.g:g} it is "
        f"{coef:.6f}."
    )
    return {"lecornu.coefficient_b2_4g": Recomputed(coef, method=f"b²/(4g), b = {c.b}", note=note)}


def _lengths(c: ExampleInputs) -> Claims:
    """Lengths (16) at the elongations, (b²/4g) z², from 1 m down."""
    z_desc = c.printed_z2[::-1]
    author = c.printed_coefficient * z_desc**2
    first = printed_number(f"lecornu.j2_zeros.{PRINTED_ELONGATIONS}").text
    out = {}
    for k in range(PRINTED_ELONGATIONS):
        out[f"lecornu.example.length.{k + 1}"] = Recomputed(
            float(c.model.elongation_lengths[k]),
            exact=_exact_at(c.rest.elongation_lengths, k),
            method=f"(b²/4g) j_(2,k)², b = {c.b} (eq. (16))",
            note=(
                f"His printed {_coefficient_text()}·z² (printed z) gives "
                f"{author[k]:.4f}; with l = (z/{first})² ({c.l0} at the first elongation) "
                f"{(z_desc[k] / z_desc[0]) ** 2:.4f}."
            ),
        )
    return out


def _author_times(c: ExampleInputs) -> Array:
    """His times: (1 m - printed length)/0,35."""
    lengths = _printed_values("lecornu.example.length.", PRINTED_ELONGATIONS)
    return np.asarray((c.length - lengths) / c.speed, dtype=float)


def _times(c: ExampleInputs) -> Claims:
    """Times of the elongations, t = (1 m - l)/b, and of zero length."""
    author = _author_times(c)
    out = {}
    for k in range(PRINTED_ELONGATIONS):
        out[f"lecornu.example.time.{k + 1}"] = Recomputed(
            float(c.model.elongation_times[k]),
            exact=_exact_at(c.rest.elongation_times, k),
            method=f"({c.l0} - l_k)/b, b = {c.b}",
            note=f"Author's procedure ({c.length:g} - printed l)/{_comma(c.speed)} gives "
            f"{author[k]:.4f}.",
        )
    exact_speed = 2 * math.sqrt(c.g * c.length) / c.z2[4]
    out["lecornu.example.time_zero_length"] = Recomputed(
        c.model.zero_length_time,
        method=f"{c.l0} / b",
        note=(
            f"With the exact speed that makes {c.l0} an elongation, "
            f"b = 2√g/j_(2,5) = {exact_speed:.5f} m/s, it would be "
            f"{c.length / exact_speed:.4f} s."
        ),
    )
    return out


def _intervals(c: ExampleInputs) -> Claims:
    """Intervals between successive elongations, the last one up to zero length."""
    author = np.diff(np.append(_author_times(c), c.length / c.speed))
    rest = np.diff(c.rest.elongation_times)
    out = {}
    for k in range(PRINTED_ELONGATIONS):
        out[f"lecornu.example.interval.{k + 1}"] = Recomputed(
            float(c.model.intervals[k]),
            exact=_exact_at(rest, k, limit=PRINTED_ELONGATIONS - 1),
            method="differences of the elongation times, the last up to l = 0",
            note=f"Differences of his own (printed-length) times give {author[k]:.4f}.",
        )
    return out


def _j0_values(c: ExampleInputs) -> Claims:
    """J_0 at the zeros of J_2 (the amplitudes, up to a constant)."""
    from scipy.special import j0

    out = {}
    for k in range(PRINTED_ELONGATIONS):
        out[f"lecornu.j0_at_j2_zeros.{k + 1}"] = Recomputed(
            float(j0(c.z2[k])),
            method="J_0(j_(2,k)) (scipy.special.j0)",
            note=f"J_0 at the printed z = {c.printed_z2[k]:.2f} is "
            f"{float(j0(c.printed_z2[k])):.5f}.",
        )
    return out


def _deviations(c: ExampleInputs) -> Claims:
    """The deviations -1,27 θ0 ... +6,19 θ0: J_0(z)/J_0(17,96) for z = 14,80 ... 5,14."""
    from scipy.special import j0

    j0_ids = [f"lecornu.j0_at_j2_zeros.{k}" for k in range(1, PRINTED_ELONGATIONS + 1)]
    numbers = [printed_number(i) for i in j0_ids]
    first = numbers[-1]  # θ0 at z = 17,96
    first_half = (first.resolution or 0.0) / 2
    out = {}
    for k, zi in enumerate((3, 2, 1, 0)):
        half = (numbers[zi].resolution or 0.0) / 2
        lo, hi = abs(numbers[zi].value) - half, abs(numbers[zi].value) + half
        out[f"lecornu.deviation.{k + 2}"] = Recomputed(
            float(j0(c.z2[zi]) / j0(c.z2[4])),
            exact=_exact_at(c.rest.amplitude_ratios, k + 1),
            method="J_0(j_(2,k))/J_0(j_(2,5))",
            note=(
                "Author's procedure, ratio of his printed J_0: "
                f"{numbers[zi].value / first.value:.3f}; his 3-decimal J_0 allow |ratio| in "
                f"[{lo / (abs(first.value) + first_half):.2f}, "
                f"{hi / (abs(first.value) - first_half):.2f}]."
            ),
        )
    return out


def _zero_length(c: ExampleInputs) -> Claims:
    """The deviation at zero length, 1/J_0(17,96), and the limit 2J_1(z)/z → 1 behind it."""
    from scipy.special import j0

    # At x = 1e-20 the next term of φ(x)/x, -x/2, is far below double precision: the limit.
    limit = float(lecornu_series(1, 1e-20) / 1e-20)
    j0_first = printed("lecornu.j0_at_j2_zeros.5")
    exact_speed = 2 * math.sqrt(c.g * c.length) / c.z2[4]
    note = (
        f"Author's procedure 1/({j0_first:+.3f}) = {1 / j0_first:.2f}. Released from rest at "
        f"{c.l0} with b = {c.b} exactly (not the speed 2√g/j_(2,5) = "
        f"{exact_speed:.5f} that satisfies his condition) the solution has a Y_1 part "
        f"(weight J_2(z0)/Y_2(z0) = {c.rest.singular_weight:.2e}) and θ grows like 1/l: no "
        "finite limit."
    )
    return {
        "lecornu.deviation.zero_length": Recomputed(
            float(limit / j0(c.z2[4])),
            method="lim 2J_1(z)/z = 1 over J_0(j_(2,5))",
            note=note,
        ),
        "lecornu.limit_2j1_over_z": Recomputed(
            limit, method="φ(x)/x from series (10) at x = 1e-20 (= 2J_1(z)/z, z → 0)"
        ),
    }


def _j1_zeros(c: ExampleInputs) -> Claims:
    """The zeros of J_1 (vertical passages), printed from 19,61 down to 3,83."""
    out = {}
    for k in range(6):
        z = float(c.z1[5 - k])
        out[f"lecornu.j1_zeros.{k + 1}"] = Recomputed(
            z, method="j_(1,k), correctly rounded", note=_zeros_note(z)
        )
    return out


def _j1_lengths(c: ExampleInputs) -> Claims:
    """Lengths (16) at the vertical passages, and the bound (3,83)²/4 of x."""
    author = c.printed_coefficient * c.printed_z1**2
    out = {}
    for k in range(6):
        out[f"lecornu.j1_lengths.{k + 1}"] = Recomputed(
            float(c.model.passage_lengths[k]),
            method=f"(b²/4g) j_(1,k)², b = {c.b} (eq. (16))",
            note=f"His printed {_coefficient_text()}·z² (printed z) gives {author[k]:.4f}.",
        )
    smallest = printed_number("lecornu.j1_zeros.6")  # 3,83
    out["lecornu.x_bound"] = Recomputed(
        float(c.z1[0] ** 2 / 4),
        method="j_(1,1)²/4",
        note=f"From the printed {smallest.text}: {smallest.text}²/4 = {smallest.value**2 / 4:.5f}.",
    )
    return out


def _section_ii_constants(c: ExampleInputs) -> Claims:
    """-0,13 and 6,47: the printed expressions, and the exact solution as b → 0."""
    d_printed = math.pi * (7 * math.pi**2 - 3) / 32
    d_exact = mean_pendulum_coefficient_exact()
    note = (
        f"The printed expression is {d_printed:.4f}. The exact solution extrapolated to "
        f"b → 0 gives {d_exact:.4f} = π(π² - 3)/32 = {math.pi * (math.pi**2 - 3) / 32:.4f}: "
        "the expansion of π√(l/g) has π³/32, not 7π³/32, in its b² term. His period's "
        f"3π/32 = {3 * math.pi / 32:.5f} is right (exact solution: "
        f"{period_b2_coefficient_exact():.5f})."
    )
    return {
        "lecornu.half_oscillation_coefficient": Recomputed(
            (math.pi**2 - 12) / 16,
            exact=half_oscillation_coefficient_exact(),
            method="(π² - 12)/16, the printed expression",
            note="The exact column: the exact Bessel solution, time from a vertical passage "
            "to the next elongation, extrapolated to b → 0.",
        ),
        "lecornu.mean_pendulum_coefficient": Recomputed(
            d_printed, exact=d_exact, method="π(7π² - 3)/32, the printed expression", note=note
        ),
    }


def _k4(c: ExampleInputs) -> Claims:
    """k⁴ = sin⁴(θ0/2) at θ0 = 20° (and its bound 1/1000) and for a swing of 180°."""
    remark, horizontal = constant("k4_amplitude"), constant("horizontal_amplitude")
    k4 = lecornu_k4(remark)
    return {
        "lecornu.k4.theta20": Recomputed(k4, method=f"sin⁴(θ0/2), θ0 = {remark:g}°"),
        "lecornu.k4.theta20_below_one_thousandth": Recomputed(
            k4, method=f"sin⁴(θ0/2), θ0 = {remark:g}°, against the bound"
        ),
        "lecornu.k4.swing180": Recomputed(
            lecornu_k4(horizontal),
            method=f"sin⁴(θ0/2), θ0 = {horizontal:g}° (a swing of 180°, to the horizontal)",
        ),
    }


BUILDERS = (
    _j2_zeros,
    _speeds,
    _coefficient,
    _lengths,
    _times,
    _intervals,
    _j0_values,
    _deviations,
    _zero_length,
    _j1_zeros,
    _j1_lengths,
    _section_ii_constants,
    _k4,
)


def recompute(g: float | None = None) -> dict[str, Recomputed]:
    """Every printed number of section II (and k⁴ of III) at ``g`` (default: the table's)."""
    inputs = example_inputs(g)
    out: Claims = {}
    for build in BUILDERS:
        out.update(build(inputs))
    # the computed notes in the memoir's decimal comma, as the table's notes beside them
    return {k: replace(r, note=paper_decimals(r.note)) for k, r in out.items()}


# --- the author's own procedures, from his printed values --------------------------------


def _text(claim_id: str) -> str:
    """A printed value as the paper prints it, for a procedure's text: "0,00313"."""
    return printed_number(claim_id).text


def _lengths_from_zeros(prefix: str, zeros: list[str]) -> dict[str, Procedure]:
    """l = (b²/4g) z² (16) at his printed zero, for each row: b²/(4g) itself, not his printed
    0,00313, which the lengths of lines 224 and 256 do not carry (rounded, 0,00313·z² gives
    0,69 and 0,56 for the printed 0,68 and 0,55; b²/(4g) gives them at every g from 9,80 to
    9,81: ledger row lecornu.eq.16). g is the tables' (the paper prints none)."""
    speed, g = constant("speed"), constant("g")
    text = f"b²/(4g)·z² (16), b = {_comma(speed)}, g = {g:g}"
    coefficient = speed**2 / (4 * g)
    return {
        f"{prefix}{k}": Procedure((z,), lambda zero: coefficient * zero**2, text)
        for k, z in enumerate(zeros, start=1)
    }


def _times_procedures(length: float, speed: float) -> dict[str, Procedure]:
    """Times (1 m - l)/b from his lengths, and intervals as differences of his times."""
    out: dict[str, Procedure] = {}
    times = [f"lecornu.example.time.{k}" for k in range(1, PRINTED_ELONGATIONS + 1)]
    b = _comma(speed)
    for k, t in enumerate(times, start=1):
        lk = f"lecornu.example.length.{k}"
        out[t] = Procedure(
            (lk,), lambda printed_length: (length - printed_length) / speed, f"({length:g} - l)/{b}"
        )
    end = "lecornu.example.time_zero_length"
    out[end] = Procedure((), lambda: length / speed, f"{length:g}/{b}")
    for k, (a, later) in enumerate(zip(times, [*times[1:], end], strict=True), start=1):
        out[f"lecornu.example.interval.{k}"] = Procedure(
            (a, later), lambda earlier, then: then - earlier, "difference of his times"
        )
    return out


def _amplitude_procedures() -> dict[str, Procedure]:
    """J_0 at his printed zeros, and the deviations as ratios of his J_0."""
    from scipy.special import j0

    out: dict[str, Procedure] = {}
    for k in range(1, PRINTED_ELONGATIONS + 1):
        z = f"lecornu.j2_zeros.{k}"
        out[f"lecornu.j0_at_j2_zeros.{k}"] = Procedure(
            (z,), lambda zero: float(j0(zero)), f"J_0 at his zero {_text(z)}"
        )
    first = f"lecornu.j0_at_j2_zeros.{PRINTED_ELONGATIONS}"  # θ0, at z = 17,96
    last_zero = _text(f"lecornu.j2_zeros.{PRINTED_ELONGATIONS}")
    for k, zi in enumerate((4, 3, 2, 1), start=2):
        numerator = f"lecornu.j0_at_j2_zeros.{zi}"
        text = f"his J_0({_text(f'lecornu.j2_zeros.{zi}')})/J_0({last_zero})"
        out[f"lecornu.deviation.{k}"] = Procedure(
            (numerator, first), lambda j, j_first: j / j_first, text
        )
    out["lecornu.deviation.zero_length"] = Procedure(
        (first,), lambda j_first: 1 / j_first, f"1/his J_0({last_zero})"
    )
    return out


def author_procedures() -> dict[str, Procedure]:
    """How Lecornu obtained each derived printed number from his earlier printed ones.

    The inputs are claim ids: evaluated on the printed values these give his own figures
    (the "Author's procedure" of the notes); on the recomputed values, the recomputation.
    :mod:`pendcli.verify.causes` judges each number against them and derives its cause.
    """
    descending = [f"lecornu.j2_zeros.{k}" for k in range(PRINTED_ELONGATIONS, 0, -1)]
    j1 = [f"lecornu.j1_zeros.{k}" for k in range(1, 7)]
    out = {
        **_lengths_from_zeros("lecornu.example.length.", descending),
        **_lengths_from_zeros("lecornu.j1_lengths.", j1),
        **_times_procedures(constant("length"), constant("speed")),
        **_amplitude_procedures(),
    }
    smallest = "lecornu.j1_zeros.6"
    out["lecornu.x_bound"] = Procedure(
        (smallest,), lambda zero: zero**2 / 4, f"{_text(smallest)}²/4"
    )
    out["lecornu.mean_pendulum_coefficient"] = Procedure(
        (), lambda: math.pi * (7 * math.pi**2 - 3) / 32, "his π(7π² - 3)/32"
    )
    return out
