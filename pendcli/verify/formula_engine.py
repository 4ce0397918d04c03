"""Shared machinery for the derived-formula checks: residual studies, order fit, verdict.

A derived formula of a paper is a truncated series in a small parameter ``p`` (several
parameters are reduced to one by a fixed ray, e.g. θ1 = θ0/2). It is checked by computing
the quantity from a numerical solution of the paper's own governing equation (the
*reference*) at a few values of ``p`` and forming the residual = reference − formula.

Conventions (stated in every row's note):

* ``claimed_order`` is the exponent of the residual the paper's derivation implies: a formula
  correct through p² has a residual O(p³), so claimed_order = 3. For a coefficient (e.g. the
  coefficient of sin 2k't in a series) the residual is that of the coefficient itself.
* ``observed_order`` is the least-squares slope of log|residual| against log p.
* verdict ``holds`` when the observed order is at least the claimed order minus
  :data:`ORDER_TOLERANCE` AND every residual used is at least :data:`FLOOR_FACTOR` times the
  reference's error bound (otherwise the slope would measure the reference, not the formula);
  a formula whose residual sits at the reference's error level at every point is exact in the
  model and also ``holds``. Anything else ``fails``.
* Where a formula fails, the leading residual coefficient is fitted (Richardson on the two
  smallest parameters) and recognised as a small rational times a power of π
  (:func:`identify`), which gives the corrected term.

The reference is scipy's ``solve_ivp`` (DOP853 at rtol 1e-12 by default, see
:class:`Integrator`); the tests re-run every study with a second method (Radau, or DOP853 at a
tighter tolerance) and check the residuals do not move beyond the stated error bound.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from typing import TYPE_CHECKING, Any, TypeVar, overload

import numpy as np

from pendcli.data.vocabulary import FormulaVerdict
from pendcli.verify.claims import FormulaRow

if TYPE_CHECKING:
    pass

__all__ = [
    "DEFAULT_INTEGRATOR",
    "DENOMINATORS",
    "FLOOR_FACTOR",
    "ORDER_TOLERANCE",
    "Integrator",
    "Study",
    "crossings",
    "extrapolate_to_zero",
    "fit_basis",
    "fit_order",
    "identify",
    "identify_combination",
    "leading_coefficient",
    "make_row",
    "richardson",
    "study_verdict",
]

# A dense ODE solution (scipy's OdeSolution): t or an array of t -> the state (components first).
DenseSolution = Callable[..., np.ndarray]
N = TypeVar("N", float, Fraction)  # a number richardson works on exactly as given

ORDER_TOLERANCE = 0.3  # |observed − claimed| allowed below the claim; above it is "better"
# Denominators the papers' series use: powers of two, and three times powers of two.
DENOMINATORS = tuple(sorted({2**j * m for j in range(15) for m in (1, 3)}))
FLOOR_FACTOR = 10.0  # a residual must exceed the reference's error bound this many times


@dataclass(frozen=True)
class Integrator:
    """How the governing equation is integrated (scipy.integrate.solve_ivp)."""

    method: str = "DOP853"
    rtol: float = 1e-12
    atol: float = 1e-14

    @property
    def error_bound(self) -> float:
        """A bound on the reference's error relative to the solution's scale.

        Global error of a tolerance-controlled solver over a few oscillations stays within
        a few tens of times rtol; the tests measure it (second method) against this bound.
        """
        return 100.0 * max(self.rtol, self.atol)

    def solve(
        self, rhs: Callable[..., Any], t_end: float, y0: Sequence[float], t0: float = 0.0
    ) -> DenseSolution:
        """Integrate y' = rhs(t, y) from t0 to t_end with dense output (the OdeSolution)."""
        from scipy.integrate import solve_ivp

        sol = solve_ivp(
            rhs,
            (t0, t_end),
            np.asarray(y0, dtype=float),
            method=self.method,
            rtol=self.rtol,
            atol=self.atol,
            dense_output=True,
        )
        if not sol.success:  # pragma: no cover - the systems here are smooth and short
            raise RuntimeError(f"reference integration failed: {sol.message}")
        return sol.sol

    @property
    def label(self) -> str:
        return f"solve_ivp {self.method}, rtol {self.rtol:.0e}, atol {self.atol:.0e}"


DEFAULT_INTEGRATOR = Integrator()


def crossings(
    sol: DenseSolution, component: int, t0: float, t1: float, count: int, grid: int = 400
) -> list[float]:
    """The first ``count`` zeros of one component of a dense solution in (t0, t1].

    Sign changes are bracketed on a grid and each bracket narrowed to one step of the solver,
    where the dense output is a polynomial (degree <= 7 for DOP853, 3 for Radau): sampled at
    :data:`_NODES` Chebyshev points it is interpolated exactly, its root found by safeguarded
    Newton on the interpolant, then polished by one Newton step on the solution itself.  Each
    stage evaluates every bracket in one vectorised call (brentq made ~40 one-point calls per
    zero).
    """
    ts, values = _grid_values(sol, t0, t1, grid)
    ys = values[component]
    brackets = np.nonzero((ys[:-1] != 0.0) & (ys[:-1] * ys[1:] <= 0.0))[0][:count]
    if len(brackets) < count:  # pragma: no cover - windows are chosen to contain the events
        raise RuntimeError(f"found {len(brackets)} of {count} zeros of component {component}")
    steps = getattr(sol, "ts", None)
    if steps is None:  # not a scipy OdeSolution: no known polynomial pieces
        return _brentq_roots(sol, component, ts, brackets)
    lo, hi = _within_one_step(sol, component, ts[brackets], ts[brackets + 1], steps)
    return _polished_roots(sol, component, lo, hi)


_NODES = 14  # Chebyshev points per bracket: exact for the interpolant of degree <= 13
_grid_cache: list[tuple[object, tuple[float, float, int], np.ndarray, np.ndarray]] = []


def _grid_values(
    sol: DenseSolution, t0: float, t1: float, grid: int
) -> tuple[np.ndarray, np.ndarray]:
    """sol on the bracketing grid; the last one is kept, as callers scan its components in turn."""
    key = (float(t0), float(t1), int(grid))
    if _grid_cache and _grid_cache[0][0] is sol and _grid_cache[0][1] == key:
        return _grid_cache[0][2], _grid_cache[0][3]
    ts = np.linspace(t0, t1, grid)
    values = np.asarray(sol(ts))
    _grid_cache[:] = [(sol, key, ts, values)]
    return ts, values


def _within_one_step(
    sol: DenseSolution, component: int, a: np.ndarray, b: np.ndarray, steps: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Each bracket [a, b] cut at the solver's steps, keeping the first piece with the sign
    change (f(a) != 0 and f(a)·f(b) <= 0 on entry): the solution is one polynomial there."""
    steps = np.sort(np.asarray(steps, dtype=float))
    knots = [
        np.concatenate(([x], steps[(steps > x) & (steps < y)], [y]))
        for x, y in zip(a, b, strict=True)
    ]
    fs = np.asarray(sol(np.concatenate(knots)))[component]
    lo, hi, offset = a.copy(), b.copy(), 0
    for i, k in enumerate(knots):
        f = fs[offset : offset + len(k)]
        offset += len(k)
        j = int(np.nonzero((f[:-1] != 0.0) & (f[:-1] * f[1:] <= 0.0))[0][0])
        lo[i], hi[i] = k[j], k[j + 1]
    return lo, hi


@cache
def _chebyshev_matrices() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nodes in (-1, 1), values -> coefficients, and coefficients -> derivative's."""
    from numpy.polynomial import chebyshev as C

    unit = np.cos(np.pi * (np.arange(_NODES) + 0.5) / _NODES)
    to_coef = np.linalg.inv(C.chebvander(unit, _NODES - 1))
    deriv = np.stack([np.pad(C.chebder(e), (0, 1)) for e in np.eye(_NODES)], axis=1)
    return unit, to_coef, deriv


def _polished_roots(
    sol: DenseSolution, component: int, lo: np.ndarray, hi: np.ndarray
) -> list[float]:
    """The root in each one-step bracket: Newton on the exact interpolant, then on ``sol``."""
    from numpy.polynomial.chebyshev import chebval

    unit, to_coef, deriv = _chebyshev_matrices()
    mid, half = (lo + hi) / 2, (hi - lo) / 2
    samples = np.asarray(sol((mid[:, None] + half[:, None] * unit).ravel()))[component]
    coef = to_coef @ samples.reshape(len(lo), _NODES).T  # one column per bracket
    dcoef = deriv @ coef
    ends = chebval(np.array([[-1.0], [1.0]]), coef, tensor=False)  # f at -1 and +1
    x = _newton_in_brackets(coef, dcoef, ends[0], ends[1])
    t = mid + half * x
    slope = chebval(x, dcoef, tensor=False) / np.where(half > 0, half, 1.0)
    f = np.asarray(sol(t))[component]
    step = np.where(slope != 0.0, f / np.where(slope != 0.0, slope, 1.0), 0.0)
    return [float(v) for v in np.clip(t - step, lo, hi)]


def _newton_in_brackets(
    coef: np.ndarray, dcoef: np.ndarray, f_lo: np.ndarray, f_hi: np.ndarray
) -> np.ndarray:
    """A root in [-1, 1] of each Chebyshev series (one per column) that changes sign there:
    Newton, falling back to bisection whenever a step leaves the shrinking bracket."""
    from numpy.polynomial.chebyshev import chebval

    a, b = -np.ones(len(f_lo)), np.ones(len(f_lo))
    rising = f_hi > f_lo
    x = np.clip(np.where(f_hi != f_lo, (f_lo + f_hi) / (f_lo - f_hi), 0.0), -1.0, 1.0)
    for _ in range(60):
        f = chebval(x, coef, tensor=False)
        d = chebval(x, dcoef, tensor=False)
        below = (f < 0) == rising  # the root lies to the right of x
        a, b = np.where(below, x, a), np.where(below, b, x)
        newton = x - f / np.where(d != 0.0, d, np.nan)
        inside = (newton > a) & (newton < b)
        x_new = np.where(f == 0.0, x, np.where(inside, newton, (a + b) / 2))
        if np.all(np.abs(x_new - x) <= 4e-16):
            return x_new
        x = x_new
    return x  # pragma: no cover - Newton on a polynomial converges in a few steps


def _brentq_roots(
    sol: DenseSolution, component: int, ts: np.ndarray, brackets: np.ndarray
) -> list[float]:
    from scipy.optimize import brentq

    def f(t: float) -> float:
        return float(sol(t)[component])

    return [brentq(f, ts[i], ts[i + 1], xtol=1e-15, rtol=1e-15) for i in brackets]


@dataclass(frozen=True)
class Study:
    """Residuals of one formula at several values of its small parameter."""

    parameter: str  # what p is, e.g. "p = b/√(ga)"
    params: tuple[float, ...]
    residuals: tuple[float, ...]  # signed: reference − formula
    claimed_order: float | None
    floor: float  # the reference's error bound in the residual's units

    def pairs(self) -> tuple[tuple[float, float], ...]:
        return tuple(
            (float(p), float(abs(r))) for p, r in zip(self.params, self.residuals, strict=True)
        )


def _log_points(params: Sequence[float], residuals: Sequence[float]) -> list[tuple[float, float]]:
    return [
        (math.log(p), math.log(abs(r))) for p, r in zip(params, residuals, strict=True) if r != 0
    ]


def _slope(points: Sequence[tuple[float, float]]) -> float:
    x = np.array([a for a, _ in points])
    y = np.array([b for _, b in points])
    return float(np.polyfit(x, y, 1)[0])


def fit_order(params: Sequence[float], residuals: Sequence[float]) -> float | None:
    """Least-squares slope of log|r| against log p (None with fewer than 2 usable points)."""
    points = _log_points(params, residuals)
    return _slope(points) if len(points) >= 2 else None


def study_verdict(study: Study) -> tuple[FormulaVerdict, float | None, str]:
    """(verdict, observed order, reason) by the rule in the module docstring."""
    above = [
        (p, r)
        for p, r in zip(study.params, study.residuals, strict=True)
        if abs(r) > FLOOR_FACTOR * study.floor
    ]
    if not above:
        return (
            FormulaVerdict.HOLDS,
            None,
            f"residual within {FLOOR_FACTOR:g}× the reference's error bound "
            f"({study.floor:.1e}) at every point: exact in this model",
        )
    if study.claimed_order is None:  # an identity: it must hold to the reference's precision
        return (
            FormulaVerdict.FAILS,
            None,
            "residual far above the reference's error: the identity is false",
        )
    if len(above) < 3:
        return (
            FormulaVerdict.FAILS,
            fit_order(study.params, study.residuals),
            "too few residuals above the reference's error to fit an order",
        )
    used = "" if len(above) == len(study.params) else f" (fit on {len(above)} points)"
    return _judge_order(study.claimed_order, above, used)


def _judge_order(
    claimed: float, above: Sequence[tuple[float, float]], used: str
) -> tuple[FormulaVerdict, float, str]:
    """Holds iff the slope over the residuals above the floor reaches the claimed order."""
    # every residual in `above` exceeds a positive floor: none is dropped as zero
    observed = _slope(_log_points([p for p, _ in above], [r for _, r in above]))
    if observed >= claimed - ORDER_TOLERANCE:
        faster = (
            "; vanishes faster than claimed" if observed > claimed + ORDER_TOLERANCE + 0.4 else ""
        )
        return (
            FormulaVerdict.HOLDS,
            observed,
            f"observed order ≥ claimed − {ORDER_TOLERANCE}{faster}{used}",
        )
    return (
        FormulaVerdict.FAILS,
        observed,
        f"observed order {observed:.2f} < claimed {claimed:g} − {ORDER_TOLERANCE}{used}",
    )


@overload
def leading_coefficient(
    params: Sequence[float], residuals: Sequence[float], order: int, step: int = 1
) -> float: ...
@overload
def leading_coefficient(
    params: Sequence[float], residuals: Sequence[np.ndarray], order: int, step: int = 1
) -> np.ndarray: ...
def leading_coefficient(
    params: Sequence[float],
    residuals: Sequence[float] | Sequence[np.ndarray],
    order: int,
    step: int = 1,
) -> float | np.ndarray:
    """c in residual ≈ c·p^order (1 + d·p^step), by Richardson on the two smallest parameters.

    ``residuals`` may hold arrays (a coefficient function sampled on a grid).
    """
    pairs = sorted(zip(params, residuals, strict=True), key=lambda pr: pr[0])[:2]
    (p1, r1), (p2, r2) = pairs
    c1, c2 = np.asarray(r1) / p1**order, np.asarray(r2) / p2**order
    w1, w2 = p1**step, p2**step
    out = (c1 * w2 - c2 * w1) / (w2 - w1)
    return float(out) if np.ndim(out) == 0 else out


def richardson(values: Sequence[N], params: Sequence[N]) -> N:
    """f(0) from samples f(p_i) of f(p) = f0 + f1 p + f2 p² + ...: Richardson (Neville) at 0.

    The value at p = 0 of the polynomial of degree n − 1 through the n points (params[i],
    values[i]); its error is O(p_1 p_2 ... p_n). Each step is (t·P_{i+1..j} − P_{i..j−1}) /
    (t − 1) with t = p_i/p_j: for halving steps, t = 2, 4, ..., the classical table
    (2 f(p/2) − f(p), then (4 r_2 − r_1)/3, ...). Works on floats and on Fractions (exactly).
    """
    if len(values) != len(params) or not values:
        raise ValueError("richardson needs as many parameters as values, at least one")
    if len(set(params)) != len(params):
        raise ValueError(f"richardson needs distinct parameters, got {list(params)}")
    table = list(values)
    for m in range(1, len(table)):
        table = [
            (params[i] / params[i + m] * table[i + 1] - table[i]) / (params[i] / params[i + m] - 1)
            for i in range(len(table) - 1)
        ]
    return table[0]


def extrapolate_to_zero(
    params: Sequence[float], values: Sequence[float], step: int = 1, degree: int = 3
) -> float:
    """The value at p = 0 of a polynomial in p^step fitted to (p, value) (all points)."""
    x = np.asarray(params, dtype=float) ** step
    deg = min(degree, len(x) - 1)
    return float(np.polyval(np.polyfit(x, np.asarray(values, dtype=float), deg), 0.0))


def fit_basis(
    grid: np.ndarray, values: np.ndarray, basis: Mapping[str, Callable[..., np.ndarray]]
) -> dict[str, float]:
    """Least-squares coefficients of values on named functions of the grid."""
    names = list(basis)
    mat = np.stack([basis[n](grid) for n in names], axis=1)
    coef, *_ = np.linalg.lstsq(mat, values, rcond=None)
    return dict(zip(names, (float(c) for c in coef), strict=True))


def identify_combination(
    value: float,
    terms: Sequence[tuple[float, str]],
    denominators: Sequence[int] = DENOMINATORS[:14],
) -> str | None:
    """Recognise value as (n1·term1 + n2·term2)/d with integers |n_i| <= 200, or None."""
    best = None
    (a, na), (b, nb) = terms
    for d in denominators:
        for n1 in range(-200, 201):
            n2 = round((value * d - n1 * a) / b)
            err = abs((n1 * a + n2 * b) / d - value)
            ok = abs(n2) <= 200 and err < 2e-5 * max(abs(value), 1e-300)
            if ok and (best is None or err < best[3]):
                best = (d, n1, n2, err)
        if best is not None:
            break
    if best is None:
        return None
    d, n1, n2, _ = best
    terms_out = [(n, name) for n, name in ((n1, na), (n2, nb)) if n]
    terms_out.sort(key=lambda t: t[0] < 0)  # a positive term first
    text = ""
    for n, name in terms_out:
        mag = str(abs(n)) if (abs(n) != 1 or not name) else ""
        sign = "−" if n < 0 else "+"
        text += (f" {sign} " if text else ("−" if n < 0 else "")) + mag + name
    text = text or "0"
    return f"({text})/{d}" if d != 1 else text


_PI_POWERS = ((0, 1.0, ""), (1, math.pi, "π"), (2, math.pi**2, "π²"), (3, math.pi**3, "π³"))


def identify(value: float, rel: float = 2e-5, max_den: int = 16384) -> str | None:
    """Recognise value as (n/d)·π^k, d a power of two (or 3×), |n| <= 4000, or None.

    The smallest such d within ``rel`` wins; a value fitted to ~1e-6 is thus recognised
    only if it sits on one of a few thousand candidates, not on any nearby fraction.
    """
    best = None
    for d in DENOMINATORS:
        if d > max_den:
            break
        for _k, power, name in _PI_POWERS:
            n = round(value * d / power)
            if n == 0 or abs(n) > 4000:
                continue
            err = abs(n / d * power - value) / abs(value)
            if err < rel and (best is None or err < best[3]):
                best = (n, d, name, err)
        if best is not None:
            break
    if best is None:
        return None
    n, d, name, _ = best
    q = Fraction(n, d)
    text = f"{q.numerator}" if q.denominator == 1 else f"{q.numerator}/{q.denominator}"
    return f"{text}{'·' + name if name else ''}"


def make_row(
    *,
    id: str,
    paper: str,
    source: str,
    published: str,
    study: Study,
    reference: str,
    recomputed: str | None = None,
    note: str = "",
    verdict_override: tuple[FormulaVerdict, str] | None = None,
) -> FormulaRow:
    """A FormulaRow from a study: verdict, observed order and the convention in the note."""
    verdict, observed, reason = study_verdict(study)
    if verdict_override is not None:
        verdict, reason = verdict_override
    convention = (
        f"Residual = reference − formula over {study.parameter} (claimed order: its exponent; "
        f"holds iff observed ≥ claimed − {ORDER_TOLERANCE} and residuals ≥ {FLOOR_FACTOR:g}× "
        f"the reference error {study.floor:.0e}). Reference: {reference}."
    )
    text = " ".join(t for t in (note, f"Verdict: {reason}.", convention) if t)
    return FormulaRow(
        id=id,
        paper=paper,
        source=source,
        published=published,
        recomputed=recomputed if recomputed is not None else published,
        verdict=verdict,
        claimed_order=study.claimed_order,
        observed_order=observed,
        note=text,
        residuals=study.pairs(),
    )
