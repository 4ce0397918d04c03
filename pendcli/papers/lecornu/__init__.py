"""Lecornu: the pendulum whose length varies in proportion to time, l = a + bt.

Citation
    L. Lecornu, « Mémoire sur le pendule de longueur variable ». Published after his note of
    15 January 1894 in the Comptes rendus de l'Académie des sciences; the OCR text carries no
    journal header (seed ``001_8a46a810516a7d16.txt`` in the shared seeds). The printed
    numbers are transcribed in ``tables/published/lecornu.toml``.

Reproduced
    Section II (small oscillations): eq. (9) x u'' + u = 0 with θl = u, l = (b²/g) x, whose
    solution bounded at zero length is φ = √x J_1(2√x) (series (10)); elongations where
    J_2(z) = 0 (eqs. (12)-(14), z = 2√x), vertical passages where J_1(z) = 0. The printed
    numbers: the zeros (15) of J_2 below 20, the speeds √(g l/ξ) (ξ = z²/4) that make a 1 m
    pendulum follow (10), the coefficient b²/(4g) of (16) for b = 0,35 m/s, the lengths,
    times and intervals of the elongations, J_0 at the zeros of J_2, the successive
    deviations, the zeros of J_1 and their lengths, the bound (3,83)²/4, the constants
    -0,13 and 6,47 (after (24) and (28)), and k⁴ of section III (:mod:`.claims`). The
    derived formulas (26)-(52) are checked against direct integration (:mod:`.formulas`).

Method
    The author's model (the linear equation, solution (10)) is done exactly with
    scipy.special and :mod:`pendcli.numerics.besselzeros` (:mod:`.model`). Each derived table
    is also recomputed by the author's own procedure from his printed, rounded intermediates
    (read from the published table), so a carried rounding can be told from a slip. Where a
    fuller model answers a question about a claim it fills the exact column: the example
    released from rest at 1 m with b = 0,35 m/s exactly (« abandonné sans impulsion »), the
    general solution of (9) u ∝ √x [Y_2(z₀)J_1(z) - J_2(z₀)Y_1(z)], checked against solve_ivp
    on eq. (3); the coefficients -0,13 and 6,47 from the exact Bessel solution extrapolated
    to b → 0. Explorations for the CLI (other speeds, lengths and g; the ODE with sin θ; zero
    length; the series in double precision) are in :mod:`.explore`, figures in
    :mod:`.figures`.

Assumptions
    g = 9.81 m/s² (not printed; Paris g is 9.809, :data:`.explore.G_PARIS`); every
    g-dependent claim is also shown at other g by `pendcli lecornu g-sensitivity`. Lengths in
    metres, speeds in m/s, times in seconds. The example's pendulum is 1 m long at t = 0 and
    shortens at 0,35 m/s, so t = (1 - l)/b (the author's 2,86 s = 1/0,35 fixes this origin).
    These numbers are read from ``[paper.constants]`` of the published table, never retyped.

Nothing heavy is imported here (each hook of :data:`PAPER` loads its module when called):
``pendcli --help`` stays fast.
"""

from __future__ import annotations

from pendcli.papers.paper import CliApp, Paper, hook, merged, modules

__all__ = ["PAPER"]

PAPER = Paper(
    key="lecornu",
    recompute=hook("pendcli.papers.lecornu.claims:recompute"),
    formula_checks=hook("pendcli.papers.lecornu.formulas:formula_checks"),
    references=hook("pendcli.papers.lecornu.references:REFERENCES"),
    preload=modules("pendcli.papers.lecornu.claims", "pendcli.papers.lecornu.formulas"),
    author_procedures=hook("pendcli.papers.lecornu.claims:author_procedures"),
    tradeoff_families=hook("pendcli.papers.lecornu.speed:FAMILIES"),
    stability_rows=hook("pendcli.papers.lecornu.stability:stability_rows"),
    figures=hook("pendcli.papers.lecornu.figures:figures"),
    formula_figures=hook("pendcli.papers.lecornu.formula_figures:figures"),
    captions=merged(
        "pendcli.papers.lecornu.formula_figures:CAPTIONS", "pendcli.papers.lecornu.figures:CAPTIONS"
    ),
    explanations=hook("pendcli.papers.lecornu.explain:declared"),
    cli=CliApp(
        help="Lecornu: the pendulum of variable length (zeros of J1/J2, the 0,35 m/s example).",
        load=hook("pendcli.cli.lecornu:app"),
    ),
)
