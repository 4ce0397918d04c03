"""How the author got his digits: a bounded search over hand-computation mechanisms.

A paper declares, for a printed number, the author's computation as a function of a few
*choices* (:class:`Axis`): which value of π or g he took, whether he used his own printed
intermediate or more digits, where he rounded or chopped, how he read a Bessel table. Each
choice has a cost in *steps*: 0 for the plain reading (the exact constant, his printed
intermediate), 1 for each departure. The search (:func:`scan`) runs every combination, in
exact rational arithmetic (:class:`fractions.Fraction`), then

* finishes the result at the printed precision: rounded half up (0 steps) or chopped toward
  zero (1 step, « je néglige les décimales »);
* optionally makes one slip on the finished digits (1 step, :func:`digit_slips`): a carry
  (one digit ±1), two adjacent digits transposed, 6 ↔ 9, a digit dropped or doubled, the sign.

A *chain* is the named steps of one combination; the simplest chains (fewest steps) that give
the printed digits exactly are the explanation.

**Coincidence.** A space that can produce many values explains nothing. The rate is measured,
not argued: draw ``N`` random targets of the same precision and size (same last place, same
sign, same number of significant digits; :func:`random_targets`, fixed seed) and count how
often the same search reproduces one with a chain no longer than the explanation's. The
search's enumeration does not depend on the target (only its finish does, at the same
precision), so running it on a random target is a lookup in the costs of the values it
reaches (:attr:`Scan.costs`); tests check the lookup against a fresh search. A second,
stricter rate draws the targets near the printed value only (within 10 %, at least 10 units
of the last place): it says how much of the neighbourhood the space covers.

:data:`COINCIDENCE_THRESHOLD` (5 %) separates an explanation from a coincidence: below it,
fewer than one random target in twenty is reproduced as simply.
"""

from __future__ import annotations

import itertools
import math
import random
import zlib
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from pendcli.data.numbers import PrintedNumber
from pendcli.data.tables import PublishedValue

__all__ = [
    "COINCIDENCE_THRESHOLD",
    "G_READINGS",
    "PI_READINGS",
    "RANDOM_TARGETS",
    "Axis",
    "Chain",
    "Computation",
    "Explanation",
    "Option",
    "Rounding",
    "Scan",
    "Step",
    "Target",
    "axis",
    "chop",
    "coincidence_rate",
    "constant_axis",
    "decimal_target",
    "digit_slips",
    "explain",
    "fraction_text",
    "printed_fraction",
    "random_targets",
    "round_half_up",
    "rounding_axis",
    "scan",
    "significant_round",
    "target_of",
]

COINCIDENCE_THRESHOLD = 0.05  # explained: fewer than 1 random target in 20 reproduced as simply
RANDOM_TARGETS = 2000  # N random targets per printed number (each a lookup): s.e. <= 0,011
_SEED = 24  # with the claim id: a fixed, distinct draw per claim
SIMPLEST_SHOWN = 3  # chains of the least cost kept, for the explanation

# Constants at the precision of the time, as exact decimals or fractions.
PI_READINGS: tuple[tuple[str, Fraction], ...] = (
    ("π = 3,14", Fraction(314, 100)),
    ("π = 3,1416", Fraction(31416, 10000)),
    ("π = 22/7", Fraction(22, 7)),
)
G_READINGS: tuple[tuple[str, Fraction], ...] = (
    ("g = 9,8", Fraction(98, 10)),
    ("g = 9,81", Fraction(981, 100)),
    ("g = 9,808", Fraction(9808, 1000)),
)


# --- exact rounding ---------------------------------------------------------------------


def round_half_up(x: Fraction, decimals: int) -> Fraction:
    """x rounded at ``decimals`` decimals, a half away from zero (as computers by hand did)."""
    scale = Fraction(10) ** decimals
    n = math.floor(abs(x) * scale + Fraction(1, 2))
    return Fraction(int(math.copysign(n, x)) if n else 0) / scale


def chop(x: Fraction, decimals: int) -> Fraction:
    """x with the decimals after ``decimals`` dropped (toward zero)."""
    scale = Fraction(10) ** decimals
    n = math.floor(abs(x) * scale)
    return Fraction(-n if x < 0 else n) / scale


def _exponent(x: Fraction) -> int:
    """e with 10^e <= |x| < 10^(e+1), exactly."""
    e = math.floor(math.log10(abs(x)))
    while Fraction(10) ** e > abs(x):
        e -= 1
    while Fraction(10) ** (e + 1) <= abs(x):
        e += 1
    return e


def significant_round(x: Fraction, figures: int, mode: str = "round") -> Fraction:
    """x kept to ``figures`` significant figures, rounded half up or chopped."""
    if x == 0:
        return x
    decimals = figures - 1 - _exponent(x)
    return round_half_up(x, decimals) if mode == "round" else chop(x, decimals)


def fraction_text(x: Fraction, decimals: int = 6) -> str:
    """A rational as the paper writes decimals: comma, ``decimals`` places, trailing 0 cut."""
    text = f"{float(x):.{decimals}f}".rstrip("0").rstrip(".")
    return text.replace(".", ",")


# --- the declared space -----------------------------------------------------------------


@dataclass(frozen=True)
class Option:
    """One choice on an axis: the step as spelled out, its value, its cost in steps."""

    label: str
    value: Any
    steps: int = 1


@dataclass(frozen=True)
class Axis:
    """One choice the author made (a constant, an intermediate, a rounding)."""

    name: str
    options: tuple[Option, ...]
    summary: str = ""  # the options in a few words, where listing them all would be long

    def describe(self) -> str:
        if self.summary:
            return f"{self.name}: {self.summary} ({len(self.options)} options)"
        return f"{self.name}: {' | '.join(o.label for o in self.options)}"


def axis(name: str, plain: tuple[str, Any], *others: tuple[str, Any], cost: int = 1) -> Axis:
    """An axis whose first option is the plain reading (0 steps), the others ``cost`` each."""
    rest = tuple(Option(label, value, cost) for label, value in others)
    return Axis(name, (Option(plain[0], plain[1], 0), *rest))


def constant_axis(
    name: str, exact: Fraction, readings: Sequence[tuple[str, Fraction]], exact_label: str = ""
) -> Axis:
    """A constant: its exact value (0 steps) or a reading of the time (1 step each)."""
    return axis(name, (exact_label or f"{name} exact", exact), *readings)


@dataclass(frozen=True)
class Rounding:
    """Keep an intermediate as it is, or to ``figures`` significant figures."""

    mode: str = "none"  # "none", "round" or "chop"
    figures: int = 0

    def __call__(self, x: Fraction) -> Fraction:
        return x if self.mode == "none" else significant_round(x, self.figures, self.mode)


def rounding_axis(name: str, figures: Sequence[int] = (2, 3, 4, 5)) -> Axis:
    """Where he may have rounded or chopped an intermediate ``name``, at 2-5 figures."""
    options = [Option(f"{name} kept in full", Rounding(), 0)]
    for mode, word in (("round", "rounded"), ("chop", "chopped")):
        options += [Option(f"{name} {word} to {k} figures", Rounding(mode, k)) for k in figures]
    return Axis(
        name, tuple(options), f"kept in full, rounded or chopped to {_figures(figures)} figures"
    )


def _figures(figures: Sequence[int]) -> str:
    return (
        ", ".join(map(str, figures[:-1])) + f" or {figures[-1]}"
        if len(figures) > 1
        else str(figures[0])
    )


@dataclass(frozen=True)
class Computation:
    """The author's computation of one printed number, as a function of his choices."""

    text: str  # the formula as he computes it, e.g. "π(7π² - 3)/32"
    axes: tuple[Axis, ...]
    compute: Callable[[Mapping[str, Any]], Fraction]  # axis name -> option value -> result
    slips: bool = True  # one slip on the finished digits allowed (decimal prints only)
    chop_allowed: bool = True  # the finish may chop (a printed bound is rounded up instead)

    @property
    def size(self) -> int:
        """Number of combinations of the choices (before finish and slips)."""
        return math.prod(len(a.options) for a in self.axes)

    def describe(self, target: Target | None = None) -> str:
        """What the search tries, in words: the formula, each axis and its options."""
        parts = [a.describe() for a in self.axes]
        finish = "round half up" + (" | chop" if self.chop_allowed else "")
        if target is not None and (target.bound or target.exact):
            finish = "rounded up (a bound)" if target.bound else "exactly equal"
        slips = (
            "; one slip on the result (carry, transposition, 6↔9, dropped/doubled digit, sign)"
            if self.slips
            else "; no slip on the result"
        )
        return f"{self.text}; " + "; ".join(parts) + f"; finish: {finish}{slips}"


@dataclass(frozen=True)
class Target:
    """A printed number as an integer count of its last place: ``units`` × ``unit``."""

    text: str
    units: int  # the printed value / unit, exactly
    unit: Fraction  # the value of one unit of the last printed place (0,01; 1'')
    bound: bool = False  # an upper bound: the finish rounds up
    exact: bool = False  # an exact printed value (a fraction): reproduced only if equal

    @property
    def value(self) -> Fraction:
        return self.units * self.unit


def decimal_target(text: str, value: float, decimals: int, bound: bool = False) -> Target:
    """A printed decimal (value read from the table) at its printed number of decimals."""
    unit = Fraction(1, 10**decimals)
    return Target(text, round(Fraction(str(value)) / unit), unit, bound)


# --- slips on the finished digits -------------------------------------------------------


def digit_slips(units: int) -> Iterator[tuple[str, int]]:
    """Every single slip on the digits of ``units`` (its printed digits, last place = 1)."""
    sign = -1 if units < 0 else 1
    digits = str(abs(units))
    seen = {abs(units)}

    def emit(label: str, text: str) -> Iterator[tuple[str, int]]:
        if text and int(text) not in seen:
            seen.add(int(text))
            yield label, sign * int(text)

    for i, d in enumerate(digits):
        place = len(digits) - 1 - i
        for delta in (1, -1):  # a carry neglected, or made where none belonged
            changed = abs(units) + delta * 10**place
            if changed >= 0:
                yield from emit(f"carry slip: digit {d} {'+' if delta > 0 else '-'}1", str(changed))
        if d in "69":
            turned = digits[:i] + ("9" if d == "6" else "6") + digits[i + 1 :]
            yield from emit(f"inverted type: {d} for {'9' if d == '6' else '6'}", turned)
        yield from emit(f"digit {d} dropped", digits[:i] + digits[i + 1 :])
        yield from emit(f"digit {d} doubled", digits[: i + 1] + digits[i:])
        if i + 1 < len(digits) and digits[i] != digits[i + 1]:
            swapped = digits[:i] + digits[i + 1] + digits[i] + digits[i + 2 :]
            yield from emit(f"digits {digits[i]}{digits[i + 1]} transposed", swapped)
    if units:
        yield "sign reversed", -units


# --- the search -------------------------------------------------------------------------


@dataclass(frozen=True)
class Step:
    name: str  # the axis or "finish" or "slip"
    label: str  # the step spelled out
    steps: int


@dataclass(frozen=True)
class Chain:
    """One combination of choices, its unrounded result and the printed digits it gives."""

    steps: tuple[Step, ...]
    value: Fraction  # the computation's result before the finish
    units: int  # the finished (and slipped) result in units of the last place

    @property
    def cost(self) -> int:
        return sum(s.steps for s in self.steps)

    @property
    def slips(self) -> int:
        """Steps that are mistakes (a slip on the digits, a misread table): ranked last."""
        return sum(1 for s in self.steps if s.name == "slip" or "reversed" in s.label)

    def spelled(self, target: Target) -> list[str]:
        """Each step in words, the unrounded result, and what it prints."""
        shown = [s.label for s in self.steps if s.name not in ("finish", "slip")]
        out = [*shown, f"result {fraction_text(self.value, 8)}"]
        out += [s.label for s in self.steps if s.name in ("finish", "slip")]
        return [*out, f"printed {target.text}"]


def _finishes(target: Target, value: Fraction, chop_allowed: bool) -> Iterator[tuple[Step, int]]:
    q = value / target.unit
    if target.exact:  # a printed fraction: equal or nothing, no rounding
        if q.denominator == 1:
            yield Step("finish", "exactly", 0), int(q)
        return
    if target.bound:  # « au plus »: the bound is the value rounded up at the printed place
        yield Step("finish", "rounded up (a bound)", 0), math.ceil(q)
        return
    yield Step("finish", "rounded half up", 0), int(round_half_up(q, 0))
    if chop_allowed:
        yield Step("finish", "chopped (decimals dropped)", 1), int(chop(q, 0))


@dataclass(frozen=True)
class Scan:
    """Everything one search reaches: the cheapest cost of each value, the matching chains."""

    target: Target
    costs: dict[int, int]  # units reached -> fewest steps
    matches: tuple[Chain, ...]  # chains giving target.units, cheapest first
    combinations: int  # chains tried (choices × finishes × slips)

    @property
    def best_cost(self) -> int | None:
        return self.matches[0].cost if self.matches else None


def _chains(computation: Computation, target: Target) -> Iterator[Chain]:
    for combo in itertools.product(*(a.options for a in computation.axes)):
        choices = {a.name: o.value for a, o in zip(computation.axes, combo, strict=True)}
        value = Fraction(computation.compute(choices))
        base = tuple(
            Step(a.name, o.label, o.steps) for a, o in zip(computation.axes, combo, strict=True)
        )
        for finish, units in _finishes(target, value, computation.chop_allowed):
            yield Chain((*base, finish), value, units)
            if computation.slips:
                for label, slipped in digit_slips(units):
                    yield Chain((*base, finish, Step("slip", label, 1)), value, slipped)


def scan(computation: Computation, target: Target) -> Scan:
    """Run every chain of ``computation``; keep the costs reached and the matches."""
    costs: dict[int, int] = {}
    matches: list[Chain] = []
    tried = 0
    for chain in _chains(computation, target):
        tried += 1
        if chain.cost < costs.get(chain.units, 1 << 30):
            costs[chain.units] = chain.cost
        if chain.units == target.units:
            matches.append(chain)
    matches.sort(key=lambda c: (c.cost, c.slips))
    return Scan(target, costs, tuple(matches), tried)


# --- the coincidence rate ---------------------------------------------------------------


def random_targets(target: Target, n: int, seed: int, near: bool = False) -> list[int]:
    """``n`` targets (units) of the printed one's precision and size, drawn with ``seed``.

    Same last place, same sign, same number of significant digits (a printed 6,47 draws
    from 1,00 ... 9,99); ``near``: within 10 % of it (at least 10 units of the last place).
    """
    magnitude = abs(target.units)
    digits = len(str(magnitude))
    low, high = (10 ** (digits - 1) if digits > 1 else 0), 10**digits - 1
    if near:
        spread = max(10, magnitude // 10)
        low, high = max(low if target.units else 0, magnitude - spread), magnitude + spread
    sign = -1 if target.units < 0 else 1
    draw = random.Random(seed)
    return [sign * draw.randint(low, high) for _ in range(n)]


def coincidence_rate(costs: Mapping[int, int], drawn: Sequence[int], within: int) -> float:
    """The share of ``drawn`` targets the search reaches in at most ``within`` steps."""
    return sum(1 for t in drawn if costs.get(t, within + 1) <= within) / len(drawn)


def claim_seed(claim_id: str) -> int:
    """A fixed seed per claim: the draw is the same on every run and machine."""
    return _SEED * 1_000_003 + zlib.crc32(claim_id.encode())


# --- the explanation ---------------------------------------------------------------------


@dataclass(frozen=True)
class Explanation:
    """What the search found for one printed number."""

    id: str
    printed: str
    computation: Computation
    scan: Scan
    coincidence: float | None  # share of random targets reproduced as simply (None: no match)
    coincidence_near: float | None  # the same, targets within 10 % of the printed value
    chains: tuple[Chain, ...] = field(default=())

    @property
    def explained(self) -> bool:
        return self.coincidence is not None and self.coincidence <= COINCIDENCE_THRESHOLD

    @property
    def mechanism(self) -> str | None:
        """The simplest chain's departures from the plain computation, or None."""
        if not self.chains:
            return None
        departures = [s.label for s in self.chains[0].steps if s.steps]
        return "; ".join(departures) or "his plain procedure (no departure)"

    @property
    def searched(self) -> str:
        return (
            f"{self.computation.describe(self.scan.target)} ({self.scan.combinations} chains; "
            "coincidence: "
            f"{RANDOM_TARGETS} random targets of the same precision and size)"
        )

    def as_dict(self) -> dict[str, object]:
        target = self.scan.target
        return {
            "id": self.id,
            "printed": self.printed,
            "mechanism": self.mechanism,
            "steps": [c.spelled(target) for c in self.chains],
            "cost": self.scan.best_cost,
            "coincidence": self.coincidence,
            "coincidence_near": self.coincidence_near,
            "explained": self.explained,
            "searched": self.searched,
        }


def explain(claim_id: str, computation: Computation, target: Target) -> Explanation:
    """Search ``computation`` for ``target`` and measure the coincidence rate of what it finds."""
    found = scan(computation, target)
    cost = found.best_cost
    rate = near = None
    if cost is not None:
        seed = claim_seed(claim_id)
        rate = coincidence_rate(found.costs, random_targets(target, RANDOM_TARGETS, seed), cost)
        drawn = random_targets(target, RANDOM_TARGETS, seed, near=True)
        near = coincidence_rate(found.costs, drawn, cost)
    simplest = tuple(c for c in found.matches if c.cost == cost)[:SIMPLEST_SHOWN]
    return Explanation(claim_id, target.text, computation, found, rate, near, simplest)


# --- printed values as exact numbers ------------------------------------------------------


def printed_fraction(number: PrintedNumber) -> Fraction:
    """A printed decimal exactly (0,68 -> 17/25), read from its table, never retyped."""
    if number.kind == "decimal" and number.decimals is not None:
        return round_half_up(Fraction(repr(number.value)), number.decimals)
    if number.kind == "sexagesimal":  # degrees; the papers print whole seconds
        return Fraction(round(number.value * 3600), 3600)
    if number.exact is not None and number.pi_power == 0:
        return number.exact
    raise ValueError(f"{number.text!r} is not a plain decimal, angle or rational")


def target_of(entry: PublishedValue) -> Target:
    """The printed number of a published entry as a search target (its last place)."""
    number = entry.number
    bound = entry.comparison == "upper-bound"
    if number.kind == "decimal" and number.decimals is not None:
        unit = Fraction(1, 10**number.decimals)
        return Target(entry.published, int(printed_fraction(number) / unit), unit, bound)
    if number.kind == "sexagesimal":
        unit = Fraction(1, 3600)
        return Target(entry.published, int(printed_fraction(number) / unit), unit, bound)
    raise ValueError(f"{entry.id}: {number.text!r} has no last printed place")


# --- a paper's explanations ----------------------------------------------------------------

Builders = Mapping[str, Callable[[], Computation]]


@dataclass(frozen=True)
class Declared:
    """What a paper's explain module declares: computations by claim id, and their targets."""

    computations: Builders
    targets: Mapping[str, Target]


@dataclass(frozen=True)
class ExplainedRow:
    """One printed number: its verdict and cause, and what the search found (or did not)."""

    id: str
    paper: str
    printed: str
    verdict: str
    cause: str | None  # the table's cause (one of CAUSES), None for a row that agrees
    explanation: Explanation | None  # None: no computation declared for it

    @property
    def explained(self) -> bool:
        return self.explanation is not None and self.explanation.explained

    @property
    def cause_with_mechanism(self) -> str:
        """The cause and its mechanism where one is found below the threshold, else
        "unexplained" (a row that agrees: its verdict, with the mechanism if any)."""
        base, e = self.cause or self.verdict, self.explanation
        if e is None or e.coincidence is None:
            return f"{base}; mechanism unexplained"
        if not e.explained:  # reproduced, but no better than chance
            return f"{base}; mechanism unexplained ({e.coincidence:.0%} of random targets fit)"
        return f"{base}: {e.mechanism}"

    def as_dict(self) -> dict[str, object]:
        if self.explanation is not None:
            out = self.explanation.as_dict()
        else:
            out = {"id": self.id, "printed": self.printed, "mechanism": None, "steps": []}
            out |= {"cost": None, "coincidence": None, "coincidence_near": None}
            out |= {"explained": False, "searched": "nothing: no computation declared"}
        return {
            **out,
            "paper": self.paper,
            "verdict": self.verdict,
            "cause": self.cause_with_mechanism,
        }


def explain_rows(
    key: str,
    found: Declared,
    verdicts: Mapping[str, tuple[str, str | None, str]],
    claim_id: str | None = None,
    progress: Callable[[str], None] | None = None,
) -> list[ExplainedRow]:
    """Explain every printed number of ``key`` that does not agree, and every one its paper
    declares (``found``; ``verdicts``: id -> (verdict, cause, printed), in table order); only
    ``claim_id`` if given. A row that does not agree and has no declared computation is kept,
    unexplained."""
    wanted = [
        cid
        for cid, (verdict, _, _) in verdicts.items()
        if (verdict != "agrees" or cid in found.computations) and claim_id in (None, cid)
    ]
    rows = []
    for cid in wanted:
        if progress is not None:
            progress(cid)
        verdict, cause, printed = verdicts[cid]
        build = found.computations.get(cid)
        explanation = None if build is None else explain(cid, build(), found.targets[cid])
        rows.append(ExplainedRow(cid, key, printed, verdict, cause, explanation))
    return rows
