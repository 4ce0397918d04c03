"""Charbonnier's stability rows: every method for I_n, and the first-order amplitude loss.

I_n(π) is checked for n from -1 to 10^12 against mpmath's beta function at 50 digits, I_n(x)
on a grid of (n, x) against the positive hypergeometric series (and near π/2 for huge n
against mpmath's incomplete beta at 80 digits); the amplitude-loss formula (no. 16) against
direct ODE integration.  Rows are built from the measurements only (see
:mod:`pendcli.run.stability`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from pendcli.papers.charbonnier.speed import (
    gammaln_ratio,
    naive_betainc,
    printed_products,
    products_max_n,
    reference_integral_pi,
    reference_integral_x,
    scipy_beta,
)
from pendcli.run.stability import rel, row, ulps, worst

__all__ = ["integral_rows", "resistance_rows", "stability_rows"]

FAMILY = "I_n = ∫ sin^(n+1)"
LOSS_FAMILY = "Charbonnier Δα, b_n v^n"
N_PI = (-1, 0, 1, 2, 5, 17, 59, 60, 61, 100, 1001, 1837, 10**4, 10**6, 10**9, 10**12, 10**15)
GRID_X = (0.01, 0.3, 1.0, 1.4, 2.0, 3.0)
GRID_N = (1, 10, 100, 1000, 10**4)
RECURRENCE_X = (0.1, 0.2, 0.5, 1.0, 2.0, 2.5, 3.0)
HUGE_N = ((10**6, 1.5707), (10**9, 1.5708), (10**12, 1.5708))
ULP_GOOD = 4  # "accurate" for the general-x methods: within 4 ulp


def _ref_x(n: int, x: float) -> Any:
    return reference_integral_x((n, x))


def _ref_beta_80(n: int, x: float) -> Any:
    """I_n(x) by mpmath's incomplete beta at 80 digits (for n up to 10^12 near π/2)."""
    import mpmath

    with mpmath.workdps(80):
        a = mpmath.mpf(n + 2) / 2
        part = mpmath.betainc(a, 0.5, 0, mpmath.sin(mpmath.mpf(x)) ** 2) / 2
        return part if 2 * x <= math.pi else mpmath.beta(a, 0.5) - part


def _integral_pi_points() -> list[tuple[int]]:
    """Every n below the series threshold and 60 past it, N_PI, and 200 n log-spaced to 1e15."""
    from pendcli.papers.charbonnier.wallis import MAX_N, SERIES_FROM

    ns = set(range(-1, SERIES_FROM + 60)) | set(N_PI)
    ns |= {
        round(10 ** (math.log10(SERIES_FROM) + k * math.log10(MAX_N / SERIES_FROM) / 199))
        for k in range(200)
    }
    return [(n,) for n in sorted(ns)]


def _integral_pi_row() -> dict[str, str]:
    from pendcli.papers.charbonnier.model import integral_pi
    from pendcli.papers.charbonnier.wallis import MAX_N, SERIES_FROM

    points = _integral_pi_points()
    bad, where = worst(points, integral_pi, reference_integral_pi)
    assert where is not None
    return row(
        FAMILY,
        f"integral_pi (Wallis rationals n < {SERIES_FROM}, double-double Γ-ratio series beyond)",
        f"x = π, -1 <= n <= {MAX_N:.0e}: correctly rounded",
        f"n > {MAX_N:.0e}: refused (PendcliError)",
        f"max {bad:.3f} ulp over {len(points)} n up to {MAX_N:.0e} (worst at n = {where[0]})",
    )


def _integral_pi_exact_row() -> dict[str, str]:
    from pendcli.papers.charbonnier.model import integral_pi_exact

    # No timings here: the report must be byte-identical run to run (timings are in tradeoff).
    q, p = integral_pi_exact(10**4)
    exact_ulps = ulps(float(q) * math.pi if p else float(q), reference_integral_pi(10**4))
    return row(
        FAMILY,
        "integral_pi_exact (recurrence in rationals)",
        "exact for -1 <= n <= 1e5 (then one rounding)",
        "n > 1e5: refused (numerator and denominator grow to ~n digits)",
        f"{exact_ulps:.2f} ulp after rounding at n = 1e4 (cost grows as n²: see tradeoff)",
    )


def _general_x_row(
    fn: Callable[[int, float], float], label: str, refs: dict[tuple[int, float], Any], huge: bool
) -> dict[str, str]:
    """One method on the (n, x) grid; ``huge``: also n = 1e6..1e12 near π/2."""
    errors = {p: ulps(fn(*p), r) for p, r in refs.items() if abs(float(r)) >= 1e-290}
    where = max(errors, key=lambda p: errors[p])
    bad = errors[where]
    good = max(
        (n for n in GRID_N if all(u <= ULP_GOOD for p, u in errors.items() if p[0] <= n)),
        default=None,
    )
    extra, huge_ulps = "", math.inf
    if huge:
        huge_ulps = max(ulps(fn(n, x), _ref_beta_80(n, x)) for n, x in HUGE_N)
        extra = f"; input reduced exactly; max {huge_ulps:.2f} ulp at n = 1e6..1e12 near π/2"
    return row(
        FAMILY,
        label,
        (f"within {ULP_GOOD} ulp for n <= {good}" if good else f"never within {ULP_GOOD} ulp")
        + (" on the grid; to n = 1e12 near π/2" if extra and huge_ulps <= ULP_GOOD else ""),
        "none measured" if bad <= ULP_GOOD else f"worst {bad:.0f} ulp at (n, x) = {where}",
        f"max {bad:.1f} ulp over n in {GRID_N}, x in {GRID_X}" + extra,
    )


def _general_x_rows() -> list[dict[str, str]]:
    from pendcli.papers.charbonnier.model import integral, integral_fast

    refs = {(n, x): _ref_x(n, x) for n in GRID_N for x in GRID_X}
    return [
        _general_x_row(integral, "integral (40-digit incomplete beta)", refs, huge=True),
        _general_x_row(
            integral_fast, "integral_fast (scipy betainc + δ·pdf correction)", refs, huge=False
        ),
        _general_x_row(naive_betainc, "scipy betainc with sin²x rounded (naive)", refs, huge=False),
    ]


def _recurrence_row() -> dict[str, str]:
    """Charbonnier's recurrence: exact at π, cancels at small x."""
    from pendcli.papers.charbonnier.model import integral_recurrence

    worst_pi, _ = worst(
        [(n,) for n in (1, 10, 101, 1000, 10**4, 10**5)],
        lambda n: integral_recurrence(n, math.pi),
        reference_integral_pi,
    )
    breaks = {}
    for n in (10, 100):
        ok = [x for x in RECURRENCE_X if rel(integral_recurrence(n, x), _ref_x(n, x)) < 1e-10]
        bad = [x for x in RECURRENCE_X if x not in ok]
        breaks[n] = (min(ok) if ok else None, max(bad) if bad else None)
    rec_err = rel(integral_recurrence(100, 0.5), _ref_x(100, 0.5))
    return row(
        FAMILY,
        "Charbonnier's recurrence (double, upward)",
        f"x = π: max {worst_pi:.1f} ulp up to n = 1e5; "
        + "; ".join(f"n = {n}: rel. error < 1e-10 from x = {b[0]}" for n, b in breaks.items()),
        "; ".join(
            f"n = {n}: fails at x <= {b[1]} (subtracts nearly equal numbers)"
            for n, b in breaks.items()
            if b[1] is not None
        ),
        f"relative error at (n, x) = (100, 0.5): {rec_err:.1e}",
    )


def _products_row() -> dict[str, str]:
    """The printed products evaluated in floats: exact enough until they overflow."""
    first = products_max_n() + 1  # measured by forming them (speed.products_max_n)
    bad, _ = worst(
        [(n,) for n in (1, 2, 10, 50, 100, 150, first - 1)], printed_products, reference_integral_pi
    )
    return row(
        FAMILY,
        "printed products 2·4…n / 1·3…(n+1) as floats",
        f"n < {first}",
        f"n >= {first}: OverflowError (the products exceed 1.8e308); --method refuses them",
        f"max {bad:.1f} ulp for n < {first}",
    )


def _scipy_row(label: str, fn: Callable[[int], float]) -> dict[str, str]:
    errs = {n: rel(fn(n), reference_integral_pi(n)) for n in (10, 100, 10**3, 10**4, 10**6, 10**9)}
    good = [n for n, e in errs.items() if e < 1e-14]
    bad = {n: e for n, e in errs.items() if e >= 1e-14}
    return row(
        FAMILY,
        label,
        f"rel. error < 1e-14 for n in {good}",
        "; ".join(f"n = {n:.0e}: {e:.0e}" for n, e in bad.items()) or "none measured",
        "rel. error "
        + ", ".join(f"{e:.0e}" for e in errs.values())
        + " at n = "
        + ", ".join(f"{n:.0e}" for n in errs),
    )


def integral_rows() -> list[dict[str, str]]:
    """Every method for I_n: at π, on the (n, x) grid, the recurrence, products, scipy."""
    return [
        _integral_pi_row(),
        _integral_pi_exact_row(),
        *_general_x_rows(),
        _recurrence_row(),
        _products_row(),
        _scipy_row("scipy.special.beta(1/2, m)", scipy_beta),
        _scipy_row("exp(gammaln(1/2) + gammaln(m) - gammaln(m + 1/2))", gammaln_ratio),
    ]


def resistance_rows() -> list[dict[str, str]]:
    """Charbonnier's first-order amplitude loss (no. 16) against the ODE, n = 0..5."""
    from pendcli.papers.charbonnier.resistance import first_order_limit

    rows = []
    for n in range(6):
        lim = first_order_limit(n)
        if n == 0:
            rows.append(
                row(
                    LOSS_FAMILY,
                    "first-order formula, n = 0 (friction)",
                    "exact for the linear pendulum until it sticks (β < 1)",
                    "β >= 1: the pendulum stays at rest",
                    f"|formula - ODE|/|ODE| = {lim['error_at_half']:.0e} at β = 0.5",
                )
            )
            continue
        rows.append(
            row(
                LOSS_FAMILY,
                f"first-order formula, n = {n}",
                f"within 1% while β = b_n v_m^n/(gα) <= {lim['beta']:.2e} "
                f"(predicted loss <= {100 * lim['predicted_loss']:.2f}% of α per swing)",
                "error grows ∝ β beyond (second-order terms)",
                f"against DOP853 at rtol 1e-11; {lim['error']:.4f} at that β",
            )
        )
    return rows


def stability_rows() -> list[dict[str, str]]:
    """Charbonnier's rows: the integrals I_n, then the amplitude loss per swing."""
    return integral_rows() + resistance_rows()
