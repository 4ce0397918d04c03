"""Lecornu's equation checks: the helpers every section uses (sympy, numeric, the Bessel solutions).

Part of :mod:`pendcli.papers.lecornu.equations` (one module per section of the memoir).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from functools import cache
from typing import Any

import numpy as np

from pendcli.core.formula_engine import DEFAULT_REFERENCE, Study, judge
from pendcli.core.ledger_check import EquationCheck, Method
from pendcli.papers.identities import vanishes_identically

Array = np.ndarray
PI = math.pi
P_SWEEP = (0.032, 0.016, 0.008, 0.004, 0.002)  # p = b/√(ga), as the formula checks
P_PARAM = "p = b/√(ga) = 0.032 … 0.002"


def equation_check(holds: bool, method: Method, detail: str, **kw: Any) -> EquationCheck:
    return EquationCheck(holds=bool(holds), method=method, detail=detail, **kw)


def _study(residuals: Sequence[float], order: float, params: Sequence[float] = P_SWEEP) -> Study:
    return Study(P_PARAM, tuple(params), tuple(residuals), order, DEFAULT_REFERENCE.error_bound)


def judged_series(residuals: Sequence[float], order: float, what: str, **kw: Any) -> EquationCheck:
    """A truncated series judged by the formula engine's rule on the observed order."""
    verdict, observed, reason = judge(_study(residuals, order))
    worst = max(abs(r) for r in residuals)
    return equation_check(
        verdict == "holds",
        "numeric",
        f"{what}: max residual {worst:.2e}, observed order "
        f"{'n/a' if observed is None else f'{observed:.2f}'} (claimed {order:g}); {reason}",
        observed_order=observed,
        claimed_order=order,
        **kw,
    )


# --- sympy helpers -----------------------------------------------------------------------


def sympy_module() -> Any:
    import sympy

    return sympy


def is_zero(expr: Any) -> bool:
    """expr is identically zero (expand, cancel, then sympy simplify after expansion)."""
    return vanishes_identically(expr, expand_first=True)


def is_rational_zero(expr: Any) -> bool:
    """expr is identically zero, tried first as a rational function of its atoms (sympy
    cancel: exact, milliseconds where simplify takes seconds on the large residuals of
    (45)-(46)), then as :func:`is_zero`."""
    sp = sympy_module()
    return bool(sp.cancel(sp.together(expr)) == 0) or is_zero(expr)


def all_zero(*exprs: Any) -> bool:
    return all(is_zero(e) for e in exprs)


def trig_form(expr: Any, u: Any) -> dict[tuple[int, str, int], Any]:
    """expr = Σ c·u^j·{sin, cos}(m u) with exact coefficients: {(j, 'sin'|'cos'|'1', m): c}.

    Found exactly by writing sin and cos as (z ∓ 1/z)/(2i), (z + 1/z)/2, z = e^{iu}.
    """
    sp = sympy_module()
    z = sp.Symbol("zz")
    e = sp.expand(sp.expand_trig(sp.expand(expr)))
    e = sp.expand(e.subs({sp.sin(u): (z - 1 / z) / (2 * sp.I), sp.cos(u): (z + 1 / z) / 2}))
    poly = sp.Poly(sp.expand(e * z**12), z, u)
    raw: dict[tuple[int, int], Any] = {}
    for (zp, up), c in poly.terms():
        raw[(up, zp - 12)] = c
    out: dict[tuple[int, str, int], Any] = {}
    for j, m in {(j, abs(m)) for j, m in raw}:
        plus, minus = raw.get((j, m), 0), raw.get((j, -m), 0)
        if m == 0:
            out[(j, "1", 0)] = sp.nsimplify(plus)
            continue
        out[(j, "cos", m)] = sp.simplify(plus + minus)
        out[(j, "sin", m)] = sp.simplify(sp.I * (plus - minus))
    return {key: c for key, c in out.items() if c != 0}


def trig_text(form: dict[tuple[int, str, int], Any]) -> str:
    """Σ c·u^j·sin(mu) as text, highest power of u first: '(3/4)u² sin u − …'."""
    sup = {0: "", 1: "", 2: "²", 3: "³", 4: "⁴", 5: "⁵"}
    parts = []
    for (j, fn, m), c in sorted(form.items(), key=lambda kv: (-kv[0][0], kv[0][1], kv[0][2])):
        mag = abs(c)
        coef = "" if mag == 1 and (j or fn != "1") else f"({mag})" if "/" in str(mag) else f"{mag}"
        arg = "" if fn == "1" else f" {fn} {'' if m == 1 else m}u"
        parts.append(("− " if c < 0 else "+ ") + f"{coef}{'u' if j else ''}{sup[j]}{arg}".strip())
    text = " ".join(parts)
    return text[2:] if text.startswith("+ ") else "−" + text[2:]


# --- numeric helpers ---------------------------------------------------------------------


@cache
def _formula_rows() -> dict[str, Any]:
    from pendcli.core.claims import shared_formula_rows
    from pendcli.papers.lecornu.formulas import formula_checks

    return {r.id: r for r in shared_formula_rows("lecornu", formula_checks)}


def from_formulas(*ids: str) -> EquationCheck:
    from pendcli.core.ledger_check import check_from_formula_rows

    return check_from_formula_rows(_formula_rows().values(), [f"lecornu.{i}" for i in ids])


@cache
def linear_reduced_ode(
    ps: tuple[float, ...], theta0: tuple[float, ...], omega0: tuple[float, ...], t_end: float
) -> Callable[..., Array]:
    """(3) linearised in Lecornu's reduced variables, (1 + pτ)θ'' + 2pθ' + θ = 0, per p."""
    arr = np.array(ps)
    m = len(ps)

    def rhs(t: float, y: Array) -> Array:
        th, om = y[:m], y[m:]
        return np.concatenate((om, -(2.0 * arr * om + th) / (1.0 + arr * t)))

    return DEFAULT_REFERENCE.solve(rhs, t_end, [*theta0, *omega0])
