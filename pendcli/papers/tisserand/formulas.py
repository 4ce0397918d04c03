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
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from pendcli.verify.claims import FormulaRow
from pendcli.verify.formula_engine import (
    Study,
    extrapolate_to_zero,
    identify,
    make_row,
    study_verdict,
)
from pendcli.verify.formula_plots import PanelLabels, grid_caption, plot_studies

__all__ = [
    "BUILDERS",
    "CAPTIONS",
    "PANELS",
    "QuadratureReference",
    "Sample",
    "figures",
    "formula_checks",
    "integrands",
    "samples",
    "series_coefficients",
]

PAPER = "tisserand"
THETA0_SWEEP = (0.4, 0.28, 0.2, 0.14, 0.1)  # rad; θ1 = θ0/2
PARAM = "θ0 = 0.4 … 0.1 rad, θ1 = θ0/2"


class QuadratureReference:
    """Trapezoidal Fourier analysis of (4)-(5) on ``nodes`` points per period π of ψ."""

    def __init__(self, nodes: int = 64, harmonics: int = 6) -> None:
        self.nodes = nodes
        self.harmonics = harmonics

    @property
    def error_bound(self) -> float:
        return 1e-14  # rounding in the Fourier sums; the tests compare with N = 128 and an ODE

    @property
    def label(self) -> str:
        return f"Fourier analysis of (4)-(5), trapezoidal rule on {self.nodes} nodes"


DEFAULT = QuadratureReference()


def integrands(theta0: float, theta1: float, psi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """k dt/dψ from (4) and (dφ/dψ − u0u1/u²)/(u0u1) from (5), at the eccentric anomaly ψ."""
    u0, u1 = math.sin(theta0), math.sin(theta1)
    c0, c1 = math.cos(theta0), math.cos(theta1)
    u2 = u0**2 * np.cos(psi) ** 2 + u1**2 * np.sin(psi) ** 2
    c = np.sqrt(1.0 - u2)
    den = np.sqrt(1.0 + c * c0 + c * c1 + c0 * c1)
    kdt = np.sqrt((c + c0) * (c + c1) * (c0 + c1)) / (math.sqrt(2.0) * c * den)
    h = np.sqrt((c + c0) * (c + c1)) / (c * den)
    return kdt, (h - 1.0) / u2


def series_coefficients(
    theta0: float, theta1: float, ref: QuadratureReference = DEFAULT
) -> dict[str, np.ndarray]:
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


def _row(
    id_: str,
    source: str,
    published: str,
    residuals: Sequence[float],
    claimed: float,
    ref: QuadratureReference,
    **kw: Any,
) -> FormulaRow:
    return make_row(
        id=f"{PAPER}.{id_}",
        paper=PAPER,
        source=source,
        published=published,
        study=Study(PARAM, THETA0_SWEEP, tuple(residuals), claimed, ref.error_bound),
        reference=ref.label,
        **kw,
    )


@dataclass(frozen=True)
class Sample:
    """Tisserand's small quantities and the exact Fourier coefficients at one θ0 of the sweep."""

    u0: float
    u1: float
    a: np.ndarray  # k dt/dψ = Σ a_m cos 2mψ
    b: np.ndarray  # (dφ/dψ − u0u1/u²)/(u0u1) = Σ b_m cos 2mψ
    d: np.ndarray  # ψ − k't = Σ d_m sin 2mk't
    e: np.ndarray  # φ' − (3/8)u0u1k''t = Σ e_m sin 2mk't

    @property
    def s(self) -> float:
        return self.u0**2 + self.u1**2

    @property
    def dd(self) -> float:
        return self.u0**2 - self.u1**2

    @property
    def pp(self) -> float:
        return self.u0**2 * self.u1**2


def samples(ref: QuadratureReference = DEFAULT) -> list[Sample]:
    """One :class:`Sample` per θ0 of :data:`THETA0_SWEEP`, θ1 = θ0/2."""
    out = []
    for theta0 in THETA0_SWEEP:
        theta1 = theta0 / 2
        co = series_coefficients(theta0, theta1, ref)
        out.append(Sample(math.sin(theta0), math.sin(theta1), co["a"], co["b"], co["d"], co["e"]))
    return out


def _residuals(points: Sequence[Sample], residual: Callable[[Sample], float]) -> list[float]:
    return [float(residual(x)) for x in points]


def _eq_I(points: Sequence[Sample], ref: QuadratureReference) -> list[FormulaRow]:
    """(I): k' to the sixth order and k'' to the fourth."""

    def k_over_k1(x: Sample) -> float:
        q4, q6 = x.u0**4 + x.u1**4, x.u0**6 + x.u1**6
        return 1 + x.s / 16 + (25 * q4 - 26 * x.pp) / 1024 + (225 * q6 - 313 * x.pp * x.s) / 16384

    def k2_over_k1(x: Sample) -> float:
        return 1 + 9 * x.s / 32 + (151 * (x.u0**4 + x.u1**4) + 58 * x.pp) / 1024

    return [
        _row(
            "k_prime",
            "(I), (12)",
            "k/k' = 1 + (u0² + u1²)/16 + [25(u0⁴ + u1⁴) − 26u0²u1²]/1024 "
            "+ [225(u0⁶ + u1⁶) − 313u0²u1²(u0² + u1²)]/16384",
            _residuals(points, lambda x: x.a[0] - k_over_k1(x)),
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
            _residuals(points, lambda x: 8 / 3 * x.b[0] - k2_over_k1(x)),
            6,
            ref,
            note="k'' from the secular rate of φ' = φ − φ1: (3/8)u0u1k'' = mean dφ'/dt.",
        ),
    ]


def _eq_8(points: Sequence[Sample], ref: QuadratureReference) -> list[FormulaRow]:
    """(8), (11): kt and φ as Fourier series in ψ."""
    specs: tuple[tuple[str, str, str, Callable[[Sample], float]], ...] = (
        (
            "eq8_kt_sin2psi",
            "(8)",
            "kt: coefficient of sin 2ψ = (u0² − u1²)(3/32 + 25(u0² + u1²)/512)",
            lambda x: x.a[1] / 2 - x.dd * (3 / 32 + 25 * x.s / 512),
        ),
        (
            "eq8_kt_sin4psi",
            "(8)",
            "kt: coefficient of sin 4ψ = (u0² − u1²)²·35/4096",
            lambda x: x.a[2] / 4 - x.dd**2 * 35 / 4096,
        ),
        (
            "eq8_phi_psi",
            "(8), (11)",
            "φ: coefficient of ψ = u0u1(3/8 + 27(u0² + u1²)/256)",
            lambda x: x.u0 * x.u1 * (x.b[0] - 3 / 8 - 27 * x.s / 256),
        ),
        (
            "eq8_phi_sin2psi",
            "(8), (11)",
            "φ: coefficient of sin 2ψ = u0u1(u0² − u1²)·35/512",
            lambda x: x.u0 * x.u1 * (x.b[1] / 2 - x.dd * 35 / 512),
        ),
    )
    return [
        _row(id_, source, published, _residuals(points, residual), 6, ref)
        for id_, source, published, residual in specs
    ]


def _before_13(points: Sequence[Sample], ref: QuadratureReference) -> list[FormulaRow]:
    """The implicit form ψ = k't − … sin 2ψ − … sin 4ψ printed before (13)."""
    sin2 = _residuals(points, lambda x: -x.a[1] / (2 * x.a[0]) + x.dd * (3 / 32 + 11 * x.s / 256))
    sin4 = _residuals(points, lambda x: -x.a[2] / (4 * x.a[0]) + x.dd**2 * 35 / 4096)
    return [
        _row(
            "psi_in_psi_sin4psi",
            "before (13)",
            "ψ = k't − (u0² − u1²)(3/32 + 11(u0² + u1²)/256) sin 2ψ − (u0² − u1²)²(35/4096) sin 4ψ",
            [max(abs(x), abs(y)) for x, y in zip(sin2, sin4, strict=True)],
            6,
            ref,
            note="Both coefficients (of sin 2ψ and sin 4ψ, ψ on the right side) together: the "
            "larger residual is shown.",
        )
    ]


def _eq_II(points: Sequence[Sample], ref: QuadratureReference) -> list[FormulaRow]:
    """(13), (II): ψ as a Fourier series in k't."""
    return [
        _row(
            "II_sin2",
            "(13), (II)",
            "ψ: coefficient of sin 2k't = −(u0² − u1²)(3/32 + 11(u0² + u1²)/256)",
            _residuals(points, lambda x: x.d[1] + x.dd * (3 / 32 + 11 * x.s / 256)),
            6,
            ref,
        ),
        _sin4_row(points, ref),
    ]


def _sin4_row(points: Sequence[Sample], ref: QuadratureReference) -> FormulaRow:
    """(II)/(13): the coefficient of sin 4k't, 1/4096 as printed, against 35/4096."""
    norm = extrapolate_to_zero(THETA0_SWEEP, _residuals(points, lambda x: x.d[2] / x.dd**2), step=2)
    found = identify(norm, max_den=4096) or f"{norm:.3e}"
    alt_residuals = tuple(_residuals(points, lambda x: x.d[2] - x.dd**2 * 35 / 4096))
    alt_verdict, alt_order, _ = study_verdict(
        Study(PARAM, THETA0_SWEEP, alt_residuals, 6, ref.error_bound)
    )
    return _row(
        "II_sin4",
        "(13), (II)",
        "ψ: coefficient of sin 4k't = +(u0² − u1²)²/4096",
        _residuals(points, lambda x: x.d[2] - x.dd**2 / 4096),
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


def _eq_V(points: Sequence[Sample], ref: QuadratureReference) -> list[FormulaRow]:
    """(15), (V): the periodic term of φ'."""
    return [
        _row(
            "V_sin2",
            "(15), (V)",
            "φ' = (3/8)u0u1k''t + u0u1(u0² − u1²)(17/512) sin 2k't",
            _residuals(points, lambda x: x.e[1] - x.u0 * x.u1 * x.dd * 17 / 512),
            6,
            ref,
            note="Coefficient of sin 2k't in φ' = φ − φ1 as a function of k't (secular part "
            "removed with the exact rate).",
        )
    ]


INVERSE_SQUARE_SWEEP = (1.5, 1.2, 0.9, 0.6, 0.3)


def _eq_7(_points: Sequence[Sample], _ref: QuadratureReference) -> list[FormulaRow]:
    """(7): the coefficient of 1/u² in dφ/dψ is 1, at any amplitude (its own sweep)."""
    return [
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
        )
    ]


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


Builder = Callable[[Sequence[Sample], QuadratureReference], list[FormulaRow]]
#: one builder per printed equation, in report order
BUILDERS: tuple[Builder, ...] = (_eq_I, _eq_8, _before_13, _eq_II, _eq_V, _eq_7)


def formula_checks(ref: QuadratureReference = DEFAULT) -> list[FormulaRow]:
    """Every Tisserand formula check (see the module docstring), one builder per equation."""
    points = samples(ref)
    return [row for builder in BUILDERS for row in builder(points, ref)]


_THETA0 = "θ0 (rad), θ1 = θ0/2"
# What each residual panel shows: kt, ψ and φ are angles (rad), k/k' and k''/k' ratios.
PANELS: dict[str, PanelLabels] = {
    f"{PAPER}.{id_}": PanelLabels(name, _THETA0, unit)
    for id_, name, unit in (
        ("k_prime", "k/k′ to the sixth order", "k/k′, dimensionless"),
        ("k_second", "k″/k′ to the fourth order", "k″/k′, dimensionless"),
        ("eq8_kt_sin2psi", "kt: coefficient of sin 2ψ", "rad"),
        ("eq8_kt_sin4psi", "kt: coefficient of sin 4ψ", "rad"),
        ("eq8_phi_psi", "φ: coefficient of ψ", "dimensionless"),
        ("eq8_phi_sin2psi", "φ: coefficient of sin 2ψ", "rad"),
        ("psi_in_psi_sin4psi", "ψ(ψ): sin 2ψ, sin 4ψ terms", "rad, larger of two"),
        ("II_sin2", "ψ: coefficient of sin 2k′t", "rad"),
        ("II_sin4", "ψ: coefficient of sin 4k′t", "rad"),
        ("V_sin2", "φ′: coefficient of sin 2k′t", "rad"),
    )
}

# The report prints these under the figures (file stem -> caption).
CAPTIONS = {
    "formulas_tisserand": grid_caption(
        "Tisserand",
        "Reference: Fourier analysis of Tisserand's exact differentials (4)-(5) by the "
        "trapezoidal rule (exact to rounding); amplitudes θ0 = 0.4 … 0.1 rad with θ1 = θ0/2.",
    ),
}


def figures(outdir: str | Path, rows: list[FormulaRow] | None = None) -> list[Path]:
    """One PNG: residual against θ0 for every Tisserand formula (log-log)."""
    path = Path(outdir) / "formulas_tisserand.png"
    plot_studies(
        path,
        rows if rows is not None else formula_checks(),
        "Tisserand (1881): derived formulas against exact quadrature",
        PANELS,
    )
    return [path]
