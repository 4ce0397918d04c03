"""Tisserand (1881): the series (I), (II), (V), (8), (13) checked against exact quadrature.

F. Tisserand, « Sur le mouvement du pendule conique », Bull. sci. math. astron., 2e série,
t. 5 (1881), p. 448-454 (seed 000_2b684d438490999f.txt).

Reference: Tisserand's own exact differentials (4) and (5), k dt/dψ and dφ/dψ as functions
of the eccentric anomaly ψ through u² = sin²θ = u0² cos²ψ + u1² sin²ψ (3). Both are even,
π-periodic and analytic in ψ, so their Fourier coefficients from the trapezoidal rule on N
equispaced nodes are exact to rounding (spectral convergence); integrating term by term gives
kt(ψ) and φ(ψ) as exact Fourier series, the very form of (8). The series in k't, (II) and
(V), come from inverting kt(ψ) by Newton's method on the nodes and a second Fourier analysis.
The 1/u² part of dφ/dψ integrates to arctan((u1/u0) tan ψ) exactly (the φ1 of (9)) and is
removed before the Fourier analysis. The tests check (4)-(5) against a direct integration of
the spherical pendulum and N = 64 against N = 128.

Small parameter: θ0 with θ1 = θ0/2 fixed (s = u0² + u1², Δ = u0² − u1² are both O(θ0²)).
"""

from __future__ import annotations

import math

import numpy as np

from pendcli.core.claims import FormulaRow
from pendcli.core.formula_engine import (
    Study,
    extrapolate_to_zero,
    identify,
    judge,
    make_row,
    plot_studies,
)

__all__ = ["QuadratureReference", "figures", "formula_checks", "series_coefficients"]

PAPER = "tisserand"
THETA0_SWEEP = (0.4, 0.28, 0.2, 0.14, 0.1)  # rad; θ1 = θ0/2
PARAM = "θ0 = 0.4 … 0.1 rad, θ1 = θ0/2"


class QuadratureReference:
    """Trapezoidal Fourier analysis of (4)-(5) on ``nodes`` points per period π of ψ."""

    def __init__(self, nodes: int = 64, harmonics: int = 6):
        self.nodes = nodes
        self.harmonics = harmonics

    @property
    def error_bound(self) -> float:
        return 1e-14  # rounding in the Fourier sums; the tests compare with N = 128 and an ODE

    @property
    def label(self) -> str:
        return f"Fourier analysis of (4)-(5), trapezoidal rule on {self.nodes} nodes"


DEFAULT = QuadratureReference()


def integrands(theta0: float, theta1: float, psi: np.ndarray):
    """k dt/dψ from (4) and (dφ/dψ − u0u1/u²)/(u0u1) from (5), at the eccentric anomaly ψ."""
    u0, u1 = math.sin(theta0), math.sin(theta1)
    c0, c1 = math.cos(theta0), math.cos(theta1)
    u2 = u0**2 * np.cos(psi) ** 2 + u1**2 * np.sin(psi) ** 2
    c = np.sqrt(1.0 - u2)
    den = np.sqrt(1.0 + c * c0 + c * c1 + c0 * c1)
    kdt = np.sqrt((c + c0) * (c + c1) * (c0 + c1)) / (math.sqrt(2.0) * c * den)
    h = np.sqrt((c + c0) * (c + c1)) / (c * den)
    return kdt, (h - 1.0) / u2


def series_coefficients(theta0: float, theta1: float, ref: QuadratureReference = DEFAULT):
    """Exact Fourier coefficients: kt(ψ), φ(ψ) − φ1(ψ), ψ(k't) and φ'(k't).

    Returns a dict: ``a`` (k dt/dψ = Σ a_m cos 2mψ), ``b`` ((dφ/dψ − u0u1/u²)/(u0u1)
    = Σ b_m cos 2mψ), ``d`` (ψ − k't = Σ d_m sin 2mk't), ``e`` (φ' − (3/8)u0u1k''t
    = Σ e_m sin 2mk't), all indexed by m = 0..harmonics.
    """
    n, mmax = ref.nodes, ref.harmonics
    psi = (np.arange(n) + 0.5) * math.pi / n
    kdt, reg = integrands(theta0, theta1, psi)
    ms = np.arange(mmax + 1)
    cos_basis = np.cos(2 * np.outer(ms, psi))
    a = 2 * cos_basis @ kdt / n
    b = 2 * cos_basis @ reg / n
    a[0] /= 2
    b[0] /= 2
    # Invert k't = τ = ψ + Σ a_m/(2m a0) sin 2mψ on the τ nodes (Newton; the sines are O(θ0²)).
    tau = psi.copy()
    x = tau.copy()
    sm = ms[1:]
    for _ in range(30):
        f = x + (a[1:] / (2 * sm * a[0])) @ np.sin(2 * np.outer(sm, x)) - tau
        df = 1 + (a[1:] / a[0]) @ np.cos(2 * np.outer(sm, x))
        step = f / df
        x -= step
        if np.max(np.abs(step)) < 1e-17:
            break
    sin_basis = np.sin(2 * np.outer(ms, tau))
    d = 2 * sin_basis @ (x - tau) / n
    u0u1 = math.sin(theta0) * math.sin(theta1)
    phi_prime = u0u1 * (b[0] * x + (b[1:] / (2 * sm)) @ np.sin(2 * np.outer(sm, x)))
    e = 2 * sin_basis @ (phi_prime - u0u1 * b[0] * tau) / n
    return {"a": a, "b": b, "d": d, "e": e}


def _row(id_, source, published, residuals, claimed, ref, **kw) -> FormulaRow:
    return make_row(
        id=f"{PAPER}.{id_}",
        paper=PAPER,
        source=source,
        published=published,
        study=Study(PARAM, THETA0_SWEEP, tuple(residuals), claimed, ref.error_bound),
        reference=ref.label,
        **kw,
    )


def formula_checks(ref: QuadratureReference = DEFAULT) -> list[FormulaRow]:
    """Every Tisserand formula check (see the module docstring)."""
    cols: dict[str, list[float]] = {}

    def put(key, value):
        cols.setdefault(key, []).append(float(value))

    for theta0 in THETA0_SWEEP:
        theta1 = theta0 / 2
        u0, u1 = math.sin(theta0), math.sin(theta1)
        s, dd, pp = u0**2 + u1**2, u0**2 - u1**2, u0**2 * u1**2
        co = series_coefficients(theta0, theta1, ref)
        a, b, d, e = co["a"], co["b"], co["d"], co["e"]
        k_over_k1 = (
            1
            + s / 16
            + (25 * (u0**4 + u1**4) - 26 * pp) / 1024
            + (225 * (u0**6 + u1**6) - 313 * pp * s) / 16384
        )
        put("k1", a[0] - k_over_k1)
        put("k2", 8 / 3 * b[0] - (1 + 9 * s / 32 + (151 * (u0**4 + u1**4) + 58 * pp) / 1024))
        put("kt_sin2", a[1] / 2 - dd * (3 / 32 + 25 * s / 512))
        put("kt_sin4", a[2] / 4 - dd**2 * 35 / 4096)
        put("phi_psi", u0 * u1 * (b[0] - 3 / 8 - 27 * s / 256))
        put("phi_sin2", u0 * u1 * (b[1] / 2 - dd * 35 / 512))
        put("psi_sin2psi", -a[1] / (2 * a[0]) + dd * (3 / 32 + 11 * s / 256))
        put("psi_sin4psi", -a[2] / (4 * a[0]) + dd**2 * 35 / 4096)
        put("II_sin2", d[1] + dd * (3 / 32 + 11 * s / 256))
        put("II_sin4", d[2] - dd**2 / 4096)
        put("II_sin4_alt", d[2] - dd**2 * 35 / 4096)
        put("II_sin4_norm", d[2] / dd**2)
        put("V_sin2", e[1] - u0 * u1 * dd * 17 / 512)
        # (7): lim u→0 of u²·(1/(u0u1)) dφ/dψ, from (5) at θ → 0 by extrapolation in u².
        put("inv_u2", _inverse_square_coefficient(theta0, theta1) - 1.0)
    rows = [
        _row(
            "k_prime",
            "(I), (12)",
            "k/k' = 1 + (u0² + u1²)/16 + [25(u0⁴ + u1⁴) − 26u0²u1²]/1024 "
            "+ [225(u0⁶ + u1⁶) − 313u0²u1²(u0² + u1²)]/16384",
            cols["k1"],
            8,
            ref,
            note="k' = π / (half radial period) from the mean of k dt/dψ; the sixth-order "
            "term (given without derivation) is tested: residual O(θ0⁸). (I) prints "
            "k = √(r/l): OCR for √(g/l).",
        ),
        _row(
            "k_second",
            "(I), (14)",
            "k'' = k'[1 + 9(u0² + u1²)/32 + (151(u0⁴ + u1⁴) + 58u0²u1²)/1024]",
            cols["k2"],
            6,
            ref,
            note="k'' from the secular rate of φ' = φ − φ1: (3/8)u0u1k'' = mean dφ'/dt.",
        ),
        _row(
            "eq8_kt_sin2psi",
            "(8)",
            "kt: coefficient of sin 2ψ = (u0² − u1²)(3/32 + 25(u0² + u1²)/512)",
            cols["kt_sin2"],
            6,
            ref,
        ),
        _row(
            "eq8_kt_sin4psi",
            "(8)",
            "kt: coefficient of sin 4ψ = (u0² − u1²)²·35/4096",
            cols["kt_sin4"],
            6,
            ref,
        ),
        _row(
            "eq8_phi_psi",
            "(8), (11)",
            "φ: coefficient of ψ = u0u1(3/8 + 27(u0² + u1²)/256)",
            cols["phi_psi"],
            6,
            ref,
        ),
        _row(
            "eq8_phi_sin2psi",
            "(8), (11)",
            "φ: coefficient of sin 2ψ = u0u1(u0² − u1²)·35/512",
            cols["phi_sin2"],
            6,
            ref,
        ),
        _row(
            "psi_in_psi_sin4psi",
            "before (13)",
            "ψ = k't − (u0² − u1²)(3/32 + 11(u0² + u1²)/256) sin 2ψ − (u0² − u1²)²(35/4096) sin 4ψ",
            [
                max(abs(x), abs(y))
                for x, y in zip(cols["psi_sin2psi"], cols["psi_sin4psi"], strict=True)
            ],
            6,
            ref,
            note="Both coefficients (of sin 2ψ and sin 4ψ, ψ on the right side) together: the "
            "larger residual is shown.",
        ),
        _row(
            "II_sin2",
            "(13), (II)",
            "ψ: coefficient of sin 2k't = −(u0² − u1²)(3/32 + 11(u0² + u1²)/256)",
            cols["II_sin2"],
            6,
            ref,
        ),
        _sin4_row(cols, ref),
        _row(
            "V_sin2",
            "(15), (V)",
            "φ' = (3/8)u0u1k''t + u0u1(u0² − u1²)(17/512) sin 2k't",
            cols["V_sin2"],
            6,
            ref,
            note="Coefficient of sin 2k't in φ' = φ − φ1 as a function of k't (secular part "
            "removed with the exact rate).",
        ),
        make_row(
            id=f"{PAPER}.eq7_inverse_square",
            paper=PAPER,
            source="(7)",
            published="the coefficient of 1/u² in (1/(u0u1)) dφ/dψ is always 1",
            study=Study(
                "θ0 = 0.3 … 1.5 rad, θ1 = θ0/2",
                INVERSE_SQUARE_SWEEP,
                tuple(_inverse_square_coefficient(t, t / 2) - 1 for t in INVERSE_SQUARE_SWEEP),
                None,
                1e-13,
            ),
            reference="(5) at u → 0, Richardson extrapolation in u²",
            note="lim u→0 of u²(1/(u0u1))dφ/dψ from (5) for amplitudes up to 86°: 1 to "
            "rounding. Indeed at θ = 0 the two square roots of (5) are both "
            "√((1 + cos θ0)(1 + cos θ1)), at any amplitude.",
        ),
    ]
    return rows


INVERSE_SQUARE_SWEEP = (1.5, 1.2, 0.9, 0.6, 0.3)


def _inverse_square_coefficient(theta0: float, theta1: float) -> float:
    """lim u→0 of u²·(1/(u0u1))dφ/dψ from (5), continued analytically to u below u1."""
    c0, c1 = math.cos(theta0), math.cos(theta1)
    values = []
    hs = (2e-4, 1e-4)
    for h in hs:
        c = math.sqrt(1 - h * h)
        values.append(
            math.sqrt((c + c0) * (c + c1)) / (c * math.sqrt(1 + c * c0 + c * c1 + c0 * c1))
        )
    # The expression is a function of u² = h²: one Richardson step removes the h² term.
    return (values[1] * hs[0] ** 2 - values[0] * hs[1] ** 2) / (hs[0] ** 2 - hs[1] ** 2)


def _sin4_row(cols, ref) -> FormulaRow:
    """(II)/(13): the coefficient of sin 4k't, 1/4096 as printed, against 35/4096."""
    norm = extrapolate_to_zero(THETA0_SWEEP, cols["II_sin4_norm"], step=2)
    found = identify(norm, max_den=4096) or f"{norm:.3e}"
    alt = Study(PARAM, THETA0_SWEEP, tuple(cols["II_sin4_alt"]), 6, ref.error_bound)
    alt_verdict, alt_order, _ = judge(alt)
    return _row(
        "II_sin4",
        "(13), (II)",
        "ψ: coefficient of sin 4k't = +(u0² − u1²)²/4096",
        cols["II_sin4"],
        6,
        ref,
        recomputed=f"+(u0² − u1²)²·{found}",
        note=f"Leading coefficient found {norm:.6e} = {found}. The 35/4096 of (8) is the "
        "coefficient of sin 4ψ in kt (and, with a minus sign, in ψ as a function of ψ before "
        "(13)); inverting the series adds the square (3/32)² = 36/4096 of the sin 2 "
        "coefficient, so in terms of k't it becomes (36 − 35)/4096 = 1/4096, as (13) and "
        "(II) print. With 35/4096 the "
        f"residual is O(θ0^{alt_order:.2f}) ({alt_verdict}). (13) prints 'sin² 4k't' and "
        "'+ … sin 4k't'; (II) '+ … sin 4k't − …': the sign + is right.",
    )


def figures(outdir, rows: list[FormulaRow] | None = None) -> list:
    """One PNG: residual against θ0 for every Tisserand formula (log-log)."""
    from pathlib import Path

    path = Path(outdir) / "formulas_tisserand.png"
    plot_studies(
        path, rows if rows is not None else formula_checks(), "Tisserand: derived formulas"
    )
    return [path]
