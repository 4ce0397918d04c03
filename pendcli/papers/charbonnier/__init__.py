"""Charbonnier 1908: first-order perturbations of the pendulum and the integrals I_n(π).

Citation: P. Charbonnier, « Sur la théorie des perturbations du pendule », Nouvelles annales
de mathématiques, 4e série, t. 8 (1908), p. 145-162
(http://www.numdam.org/item?id=NAM_1908_4_8__145_0; OCR text: seed 002_a39831d5a7e646cb.txt).

What is reproduced
    * the printed table of I_n(π) = ∫_0^π sin^(n+1) x dx, n = 0..5, with I_0(π) = 2 and
      I_(-1)(π) = π from the text (no. 15): the claims (:mod:`.claims`);
    * the recurrence (n+1) I_n = -cos x sin^n x + n I_(n-2) and the printed closed forms
      2·(2·4…n)/(1·3·5…(n+1)) (n even), π·(1·3·5…n)/(2·4·6…(n+1)) (n odd), for n up to 501;
    * the general formulas (4)-(9) (θ, θ', ΔT, Δα, ΔT_1/2, Δθ'_m) on three perturbations,
      ΔT = 0 under any resistance (no. 13), the closed form of E_c (no. 15), Δα for the
      resistance b_n v^n, n = 0..5, and the friction count P (no. 16), ΔT_1/2 and Δv_m
      (no. 17): the formula checks (:mod:`.formulas`);
    * how far the first-order Δα of no. 16 holds, against the exact swing (:mod:`.resistance`).

Method
    I_n(π) exactly by Charbonnier's recurrence in rational arithmetic, and in floating point
    as B(½, (n+2)/2) (exact rational rounded for n < 60, else an asymptotic series of
    log Γ(m+½)/Γ(m)); I_n(x) for any real x by exact reduction to [0, π] and the incomplete
    beta function at 40 digits (:mod:`.model`). The perturbation formulas are compared with
    direct integration of θ'' + k²θ + εφ = 0 (scipy's solve_ivp at rtol 1e-12) at five sizes
    δ of the perturbation, the E integrals by Gauss-Legendre quadrature (:mod:`.perturbation`);
    a formula holds when the residual falls like δ² (first order: the error is O(ε²)).

Assumptions
    * I_n(π) is a pure number: no value of g or unit enters the claims.
    * The principal motion is linear (sin θ → θ), as in no. 3; t = 0 at θ = -α, at rest.
    * Charbonnier prints no g, l0 or α: the formula checks use g = 9,81 m/s², l0 = 1,5 m,
      α = 0,2 rad from ``[paper.constants]`` of ``tables/published/charbonnier.toml``. Their
      residuals are dimensionless and hold for any values; k² = g/l0 ≠ 1 only makes a wrong
      power of k visible.
    * The row labelled I_(-1) in the OCR's table holds the odd-n values I_1, I_3, I_5.

Findings
    Every printed I_n(π) and both closed forms are right. Two slips: E_c of no. 15 carries
    k^(n+1) where its own integral gives k^(n-1), and (9) (repeated in no. 13) has E_c(π/2)
    where (5) gives E_s(π/2) (no. 17's Δv_m uses the right one).

Modules: :mod:`.model` (I_n(x) by every method), :mod:`.claims` (``recompute()``),
:mod:`.perturbation` (the perturbed pendulum and its integration), :mod:`.formulas` (formula
checks), :mod:`.resistance` (monomial resistance, one swing), :mod:`.references` (the
references the equation ledger's printed forms are judged against), :mod:`.figures`,
:mod:`.explore` (the CLI's rows). This file names
its hooks by place and imports nothing heavy: each hook loads its module when called, so that
`pendcli --help` stays fast.
"""

from __future__ import annotations

from pendcli.papers.paper import CliApp, Paper, hook, merged, modules

__all__ = ["PAPER"]

PAPER = Paper(
    key="charbonnier",
    recompute=hook("pendcli.papers.charbonnier.claims:recompute"),
    formula_checks=hook("pendcli.papers.charbonnier.formulas:formula_checks"),
    references=hook("pendcli.papers.charbonnier.references:REFERENCES"),
    preload=modules("pendcli.papers.charbonnier.claims", "pendcli.papers.charbonnier.formulas"),
    author_procedures=None,
    tradeoff_families=hook("pendcli.papers.charbonnier.speed:FAMILIES"),
    stability_rows=hook("pendcli.papers.charbonnier.stability:stability_rows"),
    figures=hook("pendcli.papers.charbonnier.figures:figures"),
    formula_figures=hook("pendcli.papers.charbonnier.formulas:figures"),
    captions=merged(
        "pendcli.papers.charbonnier.formulas:CAPTIONS",
        "pendcli.papers.charbonnier.figures:CAPTIONS",
    ),
    explanations=hook("pendcli.papers.charbonnier.explain:declared"),
    cli=CliApp(
        help="Charbonnier 1908: perturbations, the table of I_n(π), the integrals I_n(x).",
        load=hook("pendcli.cli.charbonnier:app"),
    ),
)
