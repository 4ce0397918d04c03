"""Tisserand 1881: the conical (spherical) pendulum, its series and its numerical example.

Citation: F. Tisserand, « Sur le mouvement du pendule conique », Bulletin des sciences
mathématiques et astronomiques, 2e série, t. 5 (1881), p. 448-454
(OCR text: seed 000_2b684d438490999f.txt).

What is reproduced
    * the summary formulas (I)-(VI): k' and k'' (I), ψ(t) (II), the rotation φ' of the major
      axis (V), and Resal's first approximation (the axis turns at (3/8) u0 u1 per unit k't);
    * the derivation's intermediate series (7), (8), the implicit form before (13), (13);
    * the numerical example « θ0 = 30', θ1 = 15' »: ψ = k't - 1°7'33'' sin 2k't +
      2'' sin 4k't and φ' = (3/8) u0 u1 k'' t + 2'42'' sin 2k't;
    * the remark for l = 0,5 m: the periodic term of φ' moves the bob on the circle through
      the ends of the major axis (radius l sin θ0) by at most a fifth of a millimetre.

Method
    ``Recomputed.value`` is what Tisserand's formulas give, evaluated exactly as printed
    (:func:`model.series_conical`); ``Recomputed.exact`` is the same quantity for the exact
    motion (:mod:`pendcli.numerics.spherical`: spectral quadrature of his exact (4)-(5),
    checked against direct integration of Newton's equations and, for k', k'' and Ω, against
    complete elliptic integrals). The formula checks (:mod:`.formulas`) measure the order of
    each series' residual against a Fourier analysis of (4)-(5).

Assumptions
    * Units: the example is printed with primes (30', 15'), but with minutes of arc every
      printed coefficient is off by three to five orders of magnitude (the sin 2k't term
      would be 1.1'', not 1°7'33''); with degrees (30°, 15°) Tisserand's own series give
      1°7'33.1'', 1.69'' and 2'42.2''. The degree signs were printed or OCR'd as primes; the
      claims read θ0 = 30°, θ1 = 15° (:func:`.claims.reading_evidence` recomputes both).
    * No value of g enters: time is in units of 1/k, k = √(g/l), lengths in l; l = 0,5 m
      only for the displacement. The amplitudes and l are read from ``[paper.constants]`` of
      ``tables/published/tisserand.toml``.
    * t = 0 at the largest angle θ0 with φ = 0 (Tisserand's convention).

Findings
    All of Tisserand's series coefficients are right (each leaves a residual of the next even
    order against the exact motion), including 1/4096 for sin 4k't in (II) and (13) (the sin²
    of (13) is a slip) and 35/4096 for sin 4ψ in the implicit form before (13). His example's
    arithmetic is right to the printed second; but at 30° the truncated series are poor for
    the periodic terms (the sin 2k't term of φ' is 2'42'' by (V), 3'28'' exactly), so the
    « au plus un cinquième de millimètre » holds for his formula and fails (0.25 mm) for the
    true motion.

Modules: :mod:`.units` (angles typed and printed), :mod:`.model` (the series, the example's
data, the exact motion), :mod:`.claims` (``recompute()``), :mod:`.formulas` (formula checks),
:mod:`.references` (what the ledger's printed forms are judged against),
:mod:`.figures`, :mod:`.explore` (the CLI's example and series views). This file names
its hooks by place and imports nothing heavy: each hook loads its module when called, so that
`pendcli --help` stays fast.
"""

from __future__ import annotations

from pendcli.papers.paper import CliApp, Paper, hook, merged, modules

__all__ = ["PAPER"]

PAPER = Paper(
    key="tisserand",
    recompute=hook("pendcli.papers.tisserand.claims:recompute"),
    formula_checks=hook("pendcli.papers.tisserand.formulas:formula_checks"),
    references=hook("pendcli.papers.tisserand.references:REFERENCES"),
    preload=modules("pendcli.papers.tisserand.claims", "pendcli.papers.tisserand.formulas"),
    author_procedures=None,
    tradeoff_families=hook("pendcli.papers.tisserand.speed:FAMILIES"),
    stability_rows=hook("pendcli.papers.tisserand.stability:stability_rows"),
    figures=hook("pendcli.papers.tisserand.figures:figures"),
    formula_figures=hook("pendcli.papers.tisserand.formulas:figures"),
    captions=merged(
        "pendcli.papers.tisserand.formulas:CAPTIONS", "pendcli.papers.tisserand.figures:CAPTIONS"
    ),
    explanations=hook("pendcli.papers.tisserand.explain:declared"),
    cli=CliApp(
        help="Tisserand 1881: the conical pendulum, the example, series against the exact motion.",
        load=hook("pendcli.cli.tisserand:app"),
    ),
)
