"""Tisserand (1881), p. 450-452, lines 92-154: the motion as exact series in the angles.

The references of the series (8) to (15) and of the sentences that cite them, and the base of
the summary's (:mod:`.references`). The scale s multiplies u, u0, u1 (the angles' order); W
stands for u² / s². k dt/dψ and u²·dφ/dψ/(u0u1) come from (4) and (5) by truncated binomial
series (cos θ = √(1 − s²W)), then u² = u0² cos²ψ + u1² sin²ψ (3) and an exact term-by-term
integration in ψ give kt(ψ) and φ(ψ); k' and k'' are the rates their secular terms define
((12), and the k'' that makes the secular term of φ' equal (3/8)u0u1k''t). ψ(τ), τ = k't,
inverts kt(ψ) by a fixed point. Nothing here is a printed coefficient.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.papers.taylor import degree_in, taylor
from pendcli.papers.tisserand.references_differentials import ledger_symbols, scale
from pendcli.verify.printed_check import Reference


@cache
def series_symbols() -> Any:
    """s (the scale), W (u²/s²), C (cos 2ψ), ψ, u0, u1, g, l: the ledger's real symbols."""
    return (
        scale(),
        sp.Symbol("W", real=True),
        sp.Symbol("C", real=True),
        *ledger_symbols("psi", "u0", "u1", "g", "l"),
    )


@cache
def _ring() -> Any:
    """Sparse polynomials over ℚ in s, W, u0, u1 (sympy's ``ring``: fast products)."""
    return sp.ring("s W u0 u1", sp.QQ)


def _truncated(poly: Any, n: int) -> Any:
    """``poly`` (of the ring) with the powers s**n and above dropped."""
    ring = _ring()[0]
    return ring({m: c for m, c in poly.terms() if m[0] < n})


def _binomial(p: Any, alpha: Any, n: int) -> Any:
    """(1 + p)**alpha through s**(n − 1), p of the ring without constant term."""
    ring = _ring()[0]
    total, term, j = ring.one, ring.one, 1
    while True:
        term = _truncated(term * p, n)
        if not term:
            return total
        total += term * sp.QQ.from_sympy(sp.binomial(alpha, j))
        j += 1


@cache
def _differentials(n: int) -> tuple[Any, Any]:
    """k dt/dψ from (4) and u²·(1/(u0u1)) dφ/dψ from (5), through s**(n − 1), in s, W, u0, u1."""
    _, s, big_w, u0, u1 = _ring()
    half = sp.Rational(1, 2)
    c, c0, c1 = (_binomial(-(s**2) * v, half, n) for v in (big_w, u0**2, u1**2))
    quarter = _truncated((1 + c * c0 + c * c1 + c0 * c1) * sp.QQ(1, 4) - 1, n)
    eighth = _truncated((c + c0) * (c + c1) * (c0 + c1) * sp.QQ(1, 8) - 1, n)
    pair = _truncated((c + c0) * (c + c1) * sp.QQ(1, 4) - 1, n)
    inverse_c = _binomial(c - 1, -1, n)
    square = _truncated((1 + eighth) * _binomial(quarter, -1, n), n)  # (4) squared over 2
    k_dt_dpsi = _truncated(_binomial(square - 1, half, n) * inverse_c, n)
    u2_dphi = _truncated(_binomial(pair, half, n) * _binomial(quarter, -half, n) * inverse_c, n)
    return k_dt_dpsi, u2_dphi


def _integral_in_psi(expr: Any) -> Any:
    """∫₀^ψ expr dψ for expr a polynomial in C = cos 2ψ: each Cᵐ by its Fourier sum."""
    _, _, big_c, psi, *_ = series_symbols()
    total = sp.Integer(0)
    for (m,), coefficient in sp.Poly(sp.expand(expr), big_c).terms():
        for j in range(m + 1):  # Cᵐ = 2⁻ᵐ Σ_j binom(m, j) cos(2(m − 2j)ψ)
            freq = 2 * abs(m - 2 * j)
            part = psi if freq == 0 else sp.sin(freq * psi) / freq
            total += coefficient * sp.binomial(m, j) * part / 2**m
    return sp.expand(total)


@cache
def motion_series(n: int) -> dict[str, Any]:
    """kt(ψ), φ'(ψ) = φ − φ1 and their secular coefficients A (kt = Aψ + …) and P, from (4),
    (5) and (3), through s**(n − 1)."""
    s, big_w, big_c, psi, u0, u1, *_ = series_symbols()
    names = (s, big_w, u0, u1)
    k_dt_dpsi = _differentials(n)[0].as_expr(*names)
    # u²·dφ/dψ/(u0u1) − 1 is divisible by u² = s²W: the 1/u² coefficient is exactly 1 (line 78)
    quotient, remainder = divmod(_differentials(n + 2)[1] - 1, _ring()[1] ** 2 * _ring()[2])
    if remainder:
        raise ValueError("u²·dφ/dψ/(u0u1) − 1 is not divisible by u²")
    u2 = (u0**2 + u1**2) / 2 + (u0**2 - u1**2) / 2 * big_c  # (3) over s²
    kt = _integral_in_psi(k_dt_dpsi.subs(big_w, u2))
    rest = quotient.as_expr(*names).subs(big_w, u2)
    phip = sp.expand(s**2 * u0 * u1 * _integral_in_psi(rest))
    return {"kt": kt, "phip": phip, "A": kt.coeff(psi, 1), "P": phip.coeff(psi, 1)}


def motion_reference(n: int, what: str) -> Reference:
    """The exact motion (4), (5), (3) through s**(n − 1): t, φ, φ1, φ', k' (12), k'' (the rate
    of φ' over (3/8)u0u1), k = √(g/l), θ0, θ1 and u0, u1 scaled by s."""
    s, _, _, psi, u0, u1, g, length = series_symbols()
    series = motion_series(n)
    k = sp.sqrt(g / length)
    phi1 = sp.atan(u1 / u0 * sp.tan(psi))
    kp = k / series["A"]
    exact = {
        "k": k,
        "t": series["kt"] / k,
        "phi1": phi1,
        "phip": series["phip"],
        "phi": phi1 + series["phip"],
        "kp": kp,
        "kpp": kp * series["P"] / (sp.Rational(3, 8) * s**2 * u0 * u1),
        "theta0": sp.asin(s * u0),
        "theta1": sp.asin(s * u1),
        "u0": s * u0,
        "u1": s * u1,
    }
    return Reference(exact, what=what)


def _below(expr: Any, n: int) -> Any:
    """``expr`` expanded, the terms of degree n and above in the scale s dropped."""
    s = series_symbols()[0]
    keep = [t for t in sp.Add.make_args(sp.expand(expr)) if degree_in(t, s) < n]
    return sp.Add(*keep)


def _shifted(periodic: Any, delta: Any, n: int) -> Any:
    """``periodic``(ψ) = Σ c_m sin(2mψ) at ψ = τ + δ (δ = O(s²)): its Taylor series in δ,
    through s**(n − 1)."""
    psi, tau = series_symbols()[3], sp.Symbol("tau", real=True)
    total, power = sp.Integer(0), sp.Integer(1)
    for j in range((n + 1) // 2):
        derivative = sp.diff(periodic, psi, j).subs(psi, tau) if j else periodic.subs(psi, tau)
        total += _below(derivative * power / sp.factorial(j), n)
        power = _below(power * delta, n)
    return _below(total, n)


@cache
def motion_in_kpt(n: int) -> dict[str, Any]:
    """ψ and φ' as series in τ = k't, through s**(n − 1): kt(ψ)/A = ψ + Q(ψ) (12) inverted by
    the fixed point ψ = τ − Q(ψ), each pass exact one order (s²) further."""
    s, _, _, psi, *_ = series_symbols()
    tau = sp.Symbol("tau", real=True)
    series = motion_series(n)
    inverse_a = _below(taylor(1 / series["A"], s, n), n)
    periodic = _below((series["kt"] - series["A"] * psi) * inverse_a, n)
    delta = sp.Integer(0)
    for _ in range((n + 1) // 2):
        delta = -_shifted(periodic, delta, n)
    phip_periodic = series["phip"] - series["P"] * psi
    phip = _below(series["P"] * (tau + delta) + _shifted(phip_periodic, delta, n), n)
    return {"psi": tau + delta, "phip": phip, "tau": tau}


def in_kpt_reference(n: int, what: str) -> Reference:
    """The exact motion as functions of τ = k't (t = τ/k'), through s**(n − 1)."""
    base = motion_reference(n, what)
    in_tau = motion_in_kpt(n)
    exact = dict(base.exact)
    exact.update(psi=in_tau["psi"], phip=in_tau["phip"], t=in_tau["tau"] / base.exact["kp"])
    del exact["phi"], exact["phi1"]  # functions of ψ: not needed in τ
    return Reference(exact, what=what)


# --- the builders the ledger cites ------------------------------------------------------------


# (8) line 92, (11) line 102, (12) line 108, ψ in ψ before (13) line 112: series in ψ.
def reference_motion_order_4() -> Reference:
    """The exact motion through the fourth order in the angles: (8), (11), the line before
    (13), (13), (II), (15) are compared with it."""
    return motion_reference(5, "(4), (5), (3) to order 4")


# (14), line 120: k'' printed to the second order.
def reference_motion_order_2() -> Reference:
    """The exact motion through the second order: (14), printed to the second order."""
    return motion_reference(3, "(4), (5), (3) to order 2")


# (13) lines 114-116, (15) line 124, and the summary's (II) line 162: series in k't.
def reference_in_kpt_order_4() -> Reference:
    """The exact motion in τ = k't through the fourth order: (13), (II), (15)."""
    return in_kpt_reference(5, "(4), (5), (3) in k't, to order 4")


# Lines 126 and 154: the sentences citing (13), (15) and (10) together.
def reference_cited_in_kpt() -> Reference:
    """Lines 126 and 154: the exact motion in τ = k't through the fourth order, with φ1 and
    φ = φ1 + φ' as functions of τ (φ1 = arctan((u1/u0) tan ψ) of (9), at the exact ψ(τ)), so
    that the formulas a sentence cites, ψ (13), φ' (15), tan φ1 (10), are judged at one time."""
    base = reference_in_kpt_order_4()
    _, _, _, _, u0, u1, *_ = series_symbols()
    phi1 = sp.atan(u1 / u0 * sp.tan(base.exact["psi"]))
    exact = {**base.exact, "phi1": phi1, "phi": phi1 + base.exact["phip"]}
    return Reference(exact, what="(4), (5), (3) in k't")
