"""Work Lecornu's computations no longer repeat, and the values they give unchanged.

* The zeros of the released-from-rest model: the bisection stops at the first halving that
  moves no end of any bracket, with the very bits the 64 halvings give, each a root to an
  ulp (mpmath at 30 digits, the independent check).
* The solution of (45) the general integral is judged against: sympy's evalf climbs in
  precision and calls each function again at each step; each 30-digit argument is computed
  once, and its value is mpmath's at that argument, computed afresh here.
"""

from __future__ import annotations

import random

import mpmath
import numpy as np
import sympy as sp

from pendcli.papers.lecornu import model, references_conical


def _full_bisection(f, grid: np.ndarray) -> np.ndarray:
    """The bisection as it ran before: always 64 halvings."""
    values = f(grid)
    idx = np.nonzero(np.signbit(values[:-1]) != np.signbit(values[1:]))[0]
    lo, hi, flo = grid[idx].copy(), grid[idx + 1].copy(), values[idx]
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        left = np.signbit(fm) == np.signbit(flo)
        lo, flo, hi = np.where(left, mid, lo), np.where(left, fm, flo), np.where(left, hi, mid)
    return np.asarray(0.5 * (lo + hi), dtype=float)


def test_the_zeros_stop_bisecting_when_no_end_moves_with_the_same_bits() -> None:
    rng = random.Random(5)
    for _ in range(4):
        z0 = rng.uniform(8.0, 40.0)
        for nu in (1, 2):
            calls = []

            def f(z, nu=nu, z0=z0, calls=calls):
                calls.append(1)
                return model.from_rest_cylinder(nu, z, z0)

            grid = np.arange(0.5, z0 - 1e-3, 0.05)
            zeros = model._bracketed_zeros(f, grid)
            assert len(calls) < 1 + 64  # it stopped early
            np.testing.assert_array_equal(zeros, _full_bisection(f, grid))
            with mpmath.workdps(30):
                y2, j2 = mpmath.bessely(2, z0), mpmath.besselj(2, z0)

                def exact_f(s, nu=nu, y2=y2, j2=j2):
                    return y2 * mpmath.besselj(nu, s) - j2 * mpmath.bessely(nu, s)

                for z in zeros[:: max(1, len(zeros) // 4)]:
                    exact = mpmath.findroot(exact_f, mpmath.mpf(float(z)))
                    assert abs(float(exact) - z) <= 2 * np.spacing(z)


def test_the_solution_of_45_is_computed_once_per_argument_with_mpmaths_value() -> None:
    numeric = references_conical._conical_solution()
    counted = {name: [] for name in ("v", "omega", "lam", "Iw")}

    def counting(name):
        def value(x):
            counted[name].append(mpmath.mpf(x))
            return numeric[name](x)

        return value

    with_counts = {**numeric, **{name: counting(name) for name in counted}}
    original = references_conical._conical_solution
    references_conical.reference_conical_solution.cache_clear()
    references_conical._conical_solution = lambda: with_counts  # type: ignore[assignment]
    try:
        exact = references_conical.reference_conical_solution().exact
    finally:
        references_conical._conical_solution = original  # type: ignore[assignment]
        references_conical.reference_conical_solution.cache_clear()
    (x,) = exact["v"].free_symbols
    residual = exact["v"] ** 2 - exact["omega"] * exact["lam"] * exact["v"] + exact["Iw"] / 7
    near = sp.Rational(2311, 1000)  # and a point 1e-16 away: a memo keyed coarsely mixes them
    for point in (near, near + sp.Rational(1, 10**16), sp.Rational(2718, 1000)):
        value = sp.N(residual.subs(x, point), 20)  # evalf climbs: each function asked again
        with mpmath.workdps(30):
            at = mpmath.mpf(str(sp.Float(point, 30)))
            v, w, lam = numeric["v"](at), numeric["omega"](at), numeric["lam"](at)
            expected = sp.Float(mpmath.nstr(v**2 - w * lam * v + numeric["Iw"](at) / 7, 30), 30)
        assert abs(value - expected) < sp.Float(10) ** -18 * abs(expected)
    for name, arguments in counted.items():
        assert len(arguments) == len(set(arguments)) == 3, name
