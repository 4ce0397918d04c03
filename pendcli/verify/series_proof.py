"""Series proved by Cauchy's integral: the ``series`` and ``limit`` kinds' numerical proofs.

A residual's Laurent coefficients in the scale (or in a root of it, where the scale enters
as s**(p/q)) are computed by the trapezoidal rule on a small circle about 0 at random
rational values of the other symbols (:func:`taylor_verdict`): the coefficients below the
order are proved 0 to 2 × DIGITS digits, or one is decisively not 0, or nothing is decided
and sympy's series judges. :func:`finite_limit` proves a residual finite as the scale tends
to 0+ (its growing parts, negative powers and logarithms, cancel) the same way.
"""

from __future__ import annotations

import random
from collections.abc import Callable
from typing import Any

from pendcli.verify.point_values import DIGITS, POINTS, Sampled, compiled, random_value

__all__ = ["cauchy_applies", "finite_limit", "in_root", "taylor_verdict"]


# samples on the circle of _cauchy_verdict: the error goes as (radius / distance to the
# nearest singularity)**_CIRCLE_POINTS
_CIRCLE_POINTS = 64


def finite_limit(expr: Any, scale: Any) -> Any:
    """The limit of ``expr`` (a number but for ``scale``) as the scale tends to 0+, proved
    finite by Cauchy's integral, or None (decides nothing; sympy's limit then judges). Each
    log(scale**p R) is p log(scale) + log(R) (scale > 0), so that ``expr`` = P + Q log(scale)
    with P, Q Laurent series in a root t of the scale: t**j log(t) outgrows t**j and is
    outgrown by t**(j-1), so the sum is finite at 0+ exactly when P has no negative power
    and Q no power up to t**0; the limit is then P's constant term."""
    import mpmath
    import sympy as sp

    logarithm = sp.Dummy("log_scale")
    if expr.has(sp.Integral, sp.Derivative, sp.Subs):
        return None
    split = expr.replace(
        lambda e: isinstance(e, sp.log) and e.has(scale), lambda e: _log_split(e, scale, logarithm)
    )
    if split.has(sp.log(scale)) or sp.diff(split, logarithm, 2) != 0:
        return None
    rest, slope = split.subs(logarithm, 0), sp.diff(split, logarithm)
    value: Any = None
    for part, order in ((rest, 0), (slope, 1)):
        in_root = _meromorphic_in_root(part, scale, positive=True)
        if in_root is None or in_root[0].free_symbols - {in_root[1]}:
            return None
        sums = _laurent_sums(in_root[0], in_root[1])
        if sums is None:
            return None
        with mpmath.workdps(3 * DIGITS + 10):
            one, tolerance = mpmath.mpf(1), mpmath.mpf(10) ** (-2 * DIGITS)
            if _lowest_failing(sums, order, one, one, tolerance) is not None:
                return None
            if order == 0:  # P's constant term: the limit, once Q (the next part) is proved
                value = sums[0] / len(sums)
    if abs(mpmath.im(value)) > _CONVERGED * max(abs(value), 1):
        return None
    return sp.Float(mpmath.re(value), 3 * DIGITS)


def _log_split(log: Any, scale: Any, logarithm: Any) -> Any:
    """log(scale**p R) -> p logarithm + log(R) (unchanged when R holds the scale)."""
    import sympy as sp

    power, others = sp.Integer(0), []
    for factor in sp.Mul.make_args(log.args[0]):
        base, exponent = factor.as_base_exp()
        if base == scale and exponent.is_Rational:
            power += exponent
        elif factor.has(scale):
            return log
        else:
            others.append(factor)
    return power * logarithm + sp.log(sp.Mul(*others))


def _laurent_sums(expr: Any, variable: Any) -> list[Any] | None:
    """The Cauchy sums of ``expr`` (a function of ``variable`` alone) on the circle of
    :func:`_cauchy_verdict`, the whole circle sampled (None: no number there)."""
    import mpmath

    try:
        function = compiled((variable,), expr)
    except (SyntaxError, TypeError, ValueError, NameError):
        return None
    with mpmath.workdps(3 * DIGITS + 10):
        count = _CIRCLE_POINTS
        roots = _unit_roots(count)
        try:
            sums = _fourier(_circle_samples(function, mpmath.mpf(1) / 100, roots, [], False), roots)
        except (ArithmeticError, TypeError, ValueError, NameError, AttributeError):
            return None
        if not all(mpmath.isfinite(v) for v in sums):
            return None
        # the terms about count/2 small (no singularity near the circle but the one at 0),
        # or all of them rounding (the expression is 0 to the working precision)
        tail = _aliased_tail(sums)
        peak = max(abs(v) for v in sums)
        return sums if tail < _CONVERGED * peak or peak < 10 ** -(3 * DIGITS) else None


def taylor_verdict(expr: Any, reference: Sampled, order: int) -> tuple[bool | None, str]:
    """A quick proof that the series of ``expr`` in the scale vanishes below ``order`` (its
    Laurent coefficients: sympy's series keeps a pole's terms too) at random rational values
    of the other symbols: each coefficient by Cauchy's integral on a small circle about 0
    (the trapezoidal rule, exact far beyond 20 digits for a function analytic on the circle;
    a removable singularity at 0 costs nothing), every term bounded over the scale's domain
    by 10**-(2 * digits). A scale that enters through powers s**(p/q) (a branch point at 0)
    is s = t**q, t > 0: a Puiseux series in s is a Laurent series in t, its terms below
    s**order those below t**(q * order). (True, why): proved; (False, why): a coefficient
    below the order is decisively not 0 (:func:`_cauchy_verdict`); (None, ""): decides
    nothing, ``expr`` is then truncated by sympy and judged at the points as before."""

    in_root = _in_root(expr, reference)
    if in_root is None:
        return None, ""
    variable, branch = in_root[1:]
    return _cauchy_verdict(in_root[0], reference, branch * order, variable, branch)


def cauchy_applies(expr: Any, reference: Sampled) -> bool:
    """Whether :func:`taylor_verdict` can judge ``expr`` by Cauchy's integral at all (no
    integral, derivative or substitution in it; a rational domain; analytic in a root of the
    scale but for a pole); when not, sympy's series is the only way, and is taken once."""
    return _in_root(expr, reference) is not None


def in_root(expr: Any, reference: Sampled) -> tuple[Any, Any, int] | None:
    """(``expr`` in t, t, q) with the scale s = t**q, t > 0, when ``expr`` enters through
    powers s**(p/q) (q > 1); None when it is analytic in the scale itself or Cauchy's integral
    cannot judge it: what float64 expands in t (verify/float_verdict)."""
    found = _in_root(expr, reference)
    return found if found is not None and found[2] > 1 else None


def _in_root(expr: Any, reference: Sampled) -> tuple[Any, Any, int] | None:
    import sympy as sp

    scale = reference.scale
    low, high = reference.domain.get(scale.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
    if expr.has(sp.Integral, sp.Derivative, sp.Subs) or not all(
        isinstance(sp.sympify(b, strict=True), sp.Rational) for b in (low, high)
    ):
        return None
    return _meromorphic_in_root(expr, scale, positive=sp.sympify(low, strict=True) > 0)


def _meromorphic_in_root(expr: Any, scale: Any, positive: bool) -> tuple[Any, Any, int] | None:
    """(``expr`` in t, t, q) with scale = t**q (t > 0 when q > 1: a ``positive`` scale) and
    ``expr`` in t analytic about 0 but for a pole (:func:`_analytic_at_zero`); None if not."""
    import sympy as sp

    if _analytic_at_zero(expr, scale):
        return expr, scale, 1
    branch = _branch_denominator(expr, scale)
    if branch is None or not positive:
        return None
    root = sp.Dummy("root", positive=True)  # s = root**branch over the scale's domain s > 0
    in_root = expr.subs(scale, root**branch)
    # a root's base expanded: (t**2 b (c + d/(t**2 b)))**2 is 0 * zoo at t = 0, its expansion
    # a polynomial in t whose value at 0 says whether the root branches there
    in_root = in_root.replace(
        lambda e: e.is_Pow and not e.exp.is_Integer and e.base.has(root),
        lambda e: sp.expand(e.base) ** e.exp,
    )
    return (in_root, root, branch) if _analytic_at_zero(in_root, root) else None


def _branch_denominator(expr: Any, scale: Any) -> int | None:
    """The least q such that every power of ``expr`` with a base 0 at scale = 0 has an
    exponent in (1/q)Z (None: an exponent not rational, or none fractional)."""
    import math

    import sympy as sp

    denominators = []
    for node in sp.preorder_traversal(expr):
        if isinstance(node, sp.Pow) and node.has(scale) and not node.exp.is_Integer:
            if not node.exp.is_Rational:
                return None
            if node.base.subs(scale, 0) == 0:
                denominators.append(int(node.exp.q))
    return math.lcm(*denominators) if denominators else None


def _cauchy_verdict(
    expr: Any, reference: Sampled, order: int, variable: Any, branch: int
) -> tuple[bool | None, str]:
    """:func:`taylor_verdict` in ``variable`` (the scale, or its ``branch``-th root), whose
    domain is the scale's domain's ``branch``-th root."""
    import mpmath
    import sympy as sp

    count = _CIRCLE_POINTS
    if order >= count // 2:
        return None, ""
    free = sorted(expr.free_symbols - {variable}, key=lambda s: s.name)
    try:
        function = compiled((variable, *free), expr)
    except (SyntaxError, TypeError, ValueError, NameError):
        return None, ""
    generator = random.Random(23)
    scale = reference.scale
    bounds = reference.domain.get(scale.name, (sp.Rational(1, 10), sp.Rational(1, 2)))
    with mpmath.workdps(3 * DIGITS + 10):
        radius, tolerance = mpmath.mpf(1) / 100, mpmath.mpf(10) ** (-2 * DIGITS)
        # a_j = c_j radius**j; the term c_j t**j is at most |a_j| (t / radius)**j on the domain
        ends = [mpmath.root(abs(mpmath.mpf(b.p) / b.q), branch) for b in map(sp.Rational, bounds)]
        far, near = max(ends) / radius, min(ends) / radius
        roots = _unit_roots(count)
        real = not expr.has(sp.I)
        for _ in range(POINTS):
            values = [random_value(generator, reference, s) for s in free]
            if not all(isinstance(q, sp.Rational) for q in values):
                return None, ""
            args = [mpmath.mpf(q.p) / q.q for q in values]
            try:
                # sums[j % count] = sum_k samples[k] roots[k]**-j, all j at once
                samples = _circle_samples(function, radius, roots, args, real)
                sums = _fourier(samples, roots)
                failing = _lowest_failing(sums, order, far, near, tolerance)
                if failing is not None and real:  # judged again on the whole circle
                    samples = _circle_samples(function, radius, roots, args, False)
                    sums = _fourier(samples, roots)
                    failing = _lowest_failing(sums, order, far, near, tolerance)
            except (ArithmeticError, TypeError, ValueError, NameError, AttributeError):
                return None, ""
            if failing is None:
                continue
            if expr.has(sp.Float) or not _decisive(samples, sums, failing):
                return None, ""
            shown = ", ".join(f"{s}={q}" for s, q in zip(free, values, strict=True))
            value = sums[failing % count] / count / radius**failing
            if abs(mpmath.im(value)) < _CONVERGED * abs(value):  # rounding's imaginary part
                value = mpmath.re(value)
            power = sp.Rational(failing, branch)
            where = f" at {shown}" if shown else ""
            return False, f"the coefficient of {scale}**{power} is {mpmath.nstr(value, 6)}{where}"
    return True, f"vanishes at {POINTS} random rational points"


def _lowest_failing(sums: list[Any], order: int, far: Any, near: Any, tolerance: Any) -> Any:
    """The lowest power j < ``order`` whose Cauchy coefficient is not below the tolerance
    (-count/2 for one that is no number), or None."""
    import mpmath

    count = len(sums)
    for j in range(-(count // 2), order):
        a = abs(sums[j % count])
        bound = far ** (-j) if j >= 0 else min(near, 1) ** (-j)
        if not mpmath.isfinite(a):
            return -(count // 2)
        if a / count > tolerance * bound:
            return j
    return None


# A coefficient of an exact residual (no decimal: a 20-digit Float leaves noise at 1e-20
# that the points' tolerance forgives) is decisively not 0 when it exceeds _DECISIVE times
# the largest sample on the circle while the coefficients about count/2 (what the
# trapezoidal rule aliases onto the low ones) are below _CONVERGED times it: far above
# the aliasing, the working precision's rounding and the points' relative tolerance.
_DECISIVE, _CONVERGED = 1e-10, 1e-24


def _aliased_tail(sums: list[Any]) -> Any:
    """The largest Cauchy sum about count/2: what the trapezoidal rule aliases onto the low
    coefficients, small once the circle has converged."""
    count = len(sums)
    return max(abs(sums[j % count]) for j in range(count // 2 - 4, count // 2 + 5))


def _decisive(samples: list[Any], sums: list[Any], power: int) -> bool:
    import mpmath

    count = len(samples)
    peak = max(abs(v) for v in samples)
    if not mpmath.isfinite(peak) or peak == 0:
        return False
    tail = _aliased_tail(sums) / count
    return tail < _CONVERGED * peak and abs(sums[power % count]) / count > _DECISIVE * peak


def _circle_samples(
    function: Callable[..., Any], radius: Any, roots: list[Any], args: list[Any], real: bool
) -> list[Any]:
    """``function(radius * w, *args)`` at each root of unity ``w``. A ``real`` expression
    (no I in it) whose values at ±radius are real is taken to have real coefficients: its
    lower half circle is the conjugate of its upper (f(z̄) = f(z)‾), half the evaluations.
    Were the coefficients not real, the mirrored samples would jump across the real axis
    and their low coefficients would not vanish: the proof then fails, never passes."""
    import mpmath

    half = len(roots) // 2
    upper = [function(radius * w, *args) for w in roots[: half + 1]]
    if real and mpmath.im(upper[0]) == 0 and mpmath.im(upper[half]) == 0:
        return upper + [mpmath.conj(v) for v in reversed(upper[1:half])]
    return upper + [function(radius * w, *args) for w in roots[half + 1 :]]


def _unit_roots(count: int) -> list[Any]:
    """The ``count``-th roots of unity at the working precision: the circle's directions."""
    import mpmath

    return [mpmath.expjpi(mpmath.mpf(2 * k) / count) for k in range(count)]


def _fourier(samples: list[Any], roots: list[Any]) -> list[Any]:
    """The discrete Fourier transform ``X[j] = sum_k samples[k] * roots[k]**-j`` (``roots``:
    the len(samples)-th roots of unity, a power of two of them) by the radix-2 FFT: the
    Cauchy coefficients of :func:`_cauchy_verdict` in n log n products, not n² of them."""
    count = len(samples)
    if count == 1:
        return list(samples)
    even = _fourier(samples[0::2], roots[0::2])
    odd = _fourier(samples[1::2], roots[0::2])
    half = count // 2
    turned = [odd[j] * roots[-j % count] for j in range(half)]
    return [even[j] + turned[j] for j in range(half)] + [even[j] - turned[j] for j in range(half)]


def _analytic_at_zero(expr: Any, scale: Any) -> bool:
    """Whether every part of ``expr`` that depends on ``scale`` is a sum, a product, a power
    with a constant rational exponent (a fractional one of a base that is not 0 at 0) or a
    function analytic where it is finite, none of its branch points at 0 (Abs, Piecewise,
    an unknown function: False)."""
    import sympy as sp

    plain = (sp.Add, sp.Mul, sp.sin, sp.cos, sp.tan, sp.exp, sp.atan, sp.sinh, sp.cosh)
    for node in sp.preorder_traversal(expr):
        if node.is_Atom or not node.has(scale):
            continue
        at_zero = node.args[0].subs(scale, 0) if node.args else None
        if isinstance(node, sp.Pow):
            power = node.args[1]
            if not power.is_Rational or (not power.is_Integer and at_zero == 0):
                return False
        elif isinstance(node, sp.log):
            if at_zero == 0:
                return False
        elif isinstance(node, (sp.asin, sp.acos)):
            if at_zero in (1, -1):
                return False
        elif isinstance(node, sp.besselj):
            if not node.args[0].is_Integer:
                return False
        elif not isinstance(node, plain):
            return False
    return True
