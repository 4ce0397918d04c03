"""Lecornu, § III « Étude des oscillations finies », lines 818-934: the references the
printed forms of (39)-(42') are judged against (verify/printed_check): (38) perturbed by the
slow lengthening, θ = ω + pε, ε split in powers of k and solved (β, δ), the
half-oscillation (42), (42') and T = T'.

Each ``reference_*`` maps ledger symbols (tables/equations/lecornu.toml [symbols]) to exact
expressions solved here by sympy; never a copy of the formula the row prints (line 886's
remark is judged on (41) as the ledger transcribes it: that is what it says of (41)).
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp

from pendcli.papers.lecornu.references_base import reference, symbols, zero_start_forced
from pendcli.papers.lecornu.references_conical_planes import first_order_solution
from pendcli.papers.taylor import taylor

# --- § III, (39)-(42'): the perturbation of (38) by the lengthening (lines 818-934) -------


def _u_symbols() -> list[Any]:
    return symbols("u", "k", "p")


@cache
def _slow_finite() -> dict[str, Any]:
    """ω of (38), F of (39) and its k, k³ coefficients A, B, β and δ solved with zero
    initial values ((40) split in powers of k), θ = ω + p(kβ + k³δ)."""
    u, k, p = _u_symbols()
    f = 9 * sp.cos(u) + 12 * u * sp.sin(u) - sp.cos(3 * u)
    omega = 2 * k * sp.cos(u) + k**3 / 24 * f
    forcing = sp.expand(-(u * omega.diff(u, 2) + 2 * omega.diff(u)))
    big_a, big_b = forcing.coeff(k, 1), forcing.coeff(k, 3)
    beta = zero_start_forced(big_a, u, 4, (1, 3))
    delta = zero_start_forced(big_b + 2 * beta * sp.cos(u) ** 2, u, 4, (1, 3))
    theta = omega + p * (k * beta + k**3 * delta)
    return {
        "f": f,
        "omega": omega,
        "F": forcing,
        "A": big_a,
        "B": big_b,
        "beta": beta,
        "delta": delta,
        "theta": theta,
    }


@cache
def reference_eq39() -> Any:
    """(39): (32) with θ = ω + pε, ω a solution of (33) (ω'' = −sin ω): ε'' solved from
    (32) exactly, compared at order p⁰; F its definition (line 824)."""
    u, _, p = _u_symbols()
    omega, domega, eps, deps = symbols("omega", "domega_du", "eps", "deps_du")
    q = sp.Symbol("q", real=True)
    d2omega = -sp.sin(omega)
    theta, first, second = omega + p * eps, domega + p * deps, d2omega + p * q
    motion = sp.expand(second + sp.sin(theta) + p * (u * second + 2 * first))
    solved = -motion.subs(q, 0) / motion.coeff(q)
    exact = {"d2eps_du2": solved, "d2omega_du2": d2omega, "F": -(u * d2omega + 2 * domega)}
    return reference(exact, "(32) with θ = ω + pε")


@cache
def reference_eq40() -> Any:
    """(40): (39) with ω of (38) (F computed from it), A and B its k and k³ coefficients,
    f and its derivatives from (38); a series in k through k³."""
    u, _k, _ = _u_symbols()
    (eps,) = symbols("eps")
    chain = _slow_finite()
    exact = {"d2eps_du2": chain["F"] - eps * sp.cos(chain["omega"]), **_coefficients(chain, u)}
    return reference(exact, "(39) with ω of (38)")


def _coefficients(chain: dict[str, Any], u: Any) -> dict[str, Any]:
    """A and B of (40) and f, f', f'' of (38), by the ledger's names."""
    f = chain["f"]
    return {"A40": chain["A"], "B40": chain["B"], "fu": f, "dfu": f.diff(u), "d2fu": f.diff(u, 2)}


@cache
def reference_eps_split() -> Any:
    """Lines 836-856: ε = α + kβ + k²γ + k³δ (line 838) in (40); the second derivatives
    solved from its k⁰ … k³ coefficients (A, B kept as names); α = γ = 0, the solutions
    with zero initial values of α'' + α = 0 and γ'' + γ = 2α cos²u."""
    u, k, _ = _u_symbols()
    names = ("alpha_e", "beta_e", "gamma_e", "delta_e")
    parts = symbols(*names)
    seconds = symbols(*(f"d2{n[:-2]}_du2" for n in names))
    big_a, big_b = symbols("A40", "B40")
    eps = sum(k**n * x for n, x in enumerate(parts))
    d2eps = sum(k**n * x for n, x in enumerate(seconds))
    left = sp.expand(d2eps + (1 - 2 * k**2 * sp.cos(u) ** 2) * eps - big_a * k - big_b * k**3)
    exact: dict[str, Any] = {"eps": eps}
    for n, second in enumerate(seconds):
        coefficient = left.coeff(k, n)
        exact[second.name] = -coefficient.subs(second, 0) / coefficient.coeff(second)
    return reference(exact, "(40), ε split in powers of k")


@cache
def reference_eps_reduced() -> Any:
    """Lines 850-856: as reference_eps_split, with α = γ = 0."""
    split = reference_eps_split()
    zero = {sp_name: 0 for sp_name in ("alpha_e", "gamma_e")}

    exact = {
        n: sp.sympify(v, strict=True).subs({sp.Symbol(m, real=True): 0 for m in zero})
        for n, v in split.exact.items()
    }
    return reference({**exact, **zero}, "(40) split, α = γ = 0")


@cache
def reference_beta_delta() -> Any:
    """Lines 858-880: β and δ solved with zero initial values, A and B computed from (38),
    f and its derivatives, β'' and δ'' those of the solutions."""
    u, _, _ = _u_symbols()
    chain = _slow_finite()
    exact = {
        "beta_e": chain["beta"],
        "delta_e": chain["delta"],
        **_coefficients(chain, u),
        "d2delta_du2": chain["delta"].diff(u, 2),
        "d2beta_du2": chain["beta"].diff(u, 2),
    }
    return reference(exact, "β, δ solved from (40) with zero initial values")


@cache
def reference_eq41() -> Any:
    """(41) and lines 888-900: θ = ω + p(kβ + k³δ) solved here; its value and slope at
    u = π/2; rg = √(g/a) (the text's r)."""
    u, _, _ = _u_symbols()
    theta = _slow_finite()["theta"]
    slope = theta.diff(u)
    exact = {
        "theta": theta,
        "theta_pi2": theta.subs(u, sp.pi / 2),
        "dtheta_du_pi2": slope.subs(u, sp.pi / 2),
    }
    (rg,) = symbols("rg")
    exact["dtheta_dt_pi2"] = rg * exact["dtheta_du_pi2"]
    return reference(exact, "θ = ω + p(kβ + k³δ) solved from (38)-(40)")


@cache
def reference_printed_41() -> Any:
    """Line 886's « Cette formule donne dθ/dt = 0 pour t = 0 »: (41) as the ledger
    transcribes it (row lecornu.eq.41), its u-derivative at u = 0 (dθ/dt = γ dθ/du)."""
    from pendcli.data.ledger import load_ledger
    from pendcli.data.printed import parse_formula

    ledger = load_ledger("lecornu")
    row = next(r for r in ledger.rows if r.id == "lecornu.eq.41")
    assert row.printed is not None
    ((_, theta),) = parse_formula(row.id, row.printed, ledger.symbols_for(row)).equations
    (u,) = symbols("u")
    return reference({"dtheta_du0": sp.diff(theta, u).subs(u, 0)}, "(41) as printed")


@cache
def reference_k3_neglected() -> Any:
    """Lines 888-892: the O(p) solution of (48) in u (as for (50)) at ψ = 3p/4 − π/2."""
    u, p, rho = symbols("u", "p", "rho")
    theta = first_order_solution(rho, 3 * p / 4 - sp.pi / 2, u)
    return reference({"theta": theta}, "(48) to O(p), ψ = 3p/4 − π/2")


@cache
def _half_oscillation() -> Any:
    """γT = π/2 − θ/θ_u at u = π/2 (line 904) for θ of reference_eq41: the series in p to
    first order, each part in k through k² (the orders (42) keeps), as a function of a, g,
    b, k (γ = √(g/a), p = b/√(ga))."""
    _, k, p = _u_symbols()
    a, g, b = symbols("a", "g", "b")
    exact = reference_eq41().exact
    ratio = exact["theta_pi2"] / exact["dtheta_du_pi2"]
    in_p = taylor(ratio, p, 2)
    kept = sum(taylor(sp.expand(in_p.coeff(p, n)), k, 3) * p**n for n in (0, 1))
    gamma = sp.sqrt(g / a)
    return sp.expand((sp.pi / 2 - kept).subs(p, b / sp.sqrt(g * a)) / gamma)


@cache
def reference_eq42() -> Any:
    """(42): the half-oscillation computed from θ of (41) as solved here (line 904)."""
    return reference({"T": _half_oscillation()}, "π/2γ − θ/θ' at u = π/2, θ solved here")


@cache
def reference_eq42_prime() -> Any:
    """(42'): (42) with k = sin(θ0/2), through θ0²."""
    k, theta0 = symbols("k", "theta0")
    half = _half_oscillation().subs(k, sp.sin(theta0 / 2))
    kept = taylor(half, theta0, 3)
    return reference({"T": kept}, "(42) with k = sin(θ0/2), through θ0²")


@cache
def reference_t_equals_t_prime() -> Any:
    """Lines 918-932: T (and each T' of the same half-oscillation, reversed) the duration
    of (42) at k = 0, l = a + bT; b scaled by ε (first order in b)."""
    k, a, b = symbols("k", "a", "b")
    scale = sp.Symbol("epsilon", positive=True)
    duration = _half_oscillation().subs(k, 0).subs(b, scale * b)
    exact = {"b": scale * b, "T": duration, "Tp": duration, "l": a + scale * b * duration}
    return reference(exact, "(42) at k = 0, to first order in b")
