"""Lecornu's stability rows: the planar period out to 180° (his k⁴ remark) and the zeros of
J1 and J2 (his Bessel tables), each method against mpmath at 30-50 digits.
"""

from __future__ import annotations

import math
from typing import Any

from pendcli.base.errors import PendcliError
from pendcli.data.tables import load_paper_table
from pendcli.papers.lecornu.speed import reference_period_ratio
from pendcli.run.stability import rel, row, short

__all__ = ["bessel_rows", "planar_rows", "stability_rows"]

PLANAR_FAMILY = "planar period T/T0"
AMPLITUDES = (1e-6, 20.0, 90.0, 150.0, 179.0, 179.9999, 180 - 1e-7, 180 - 1e-10, 180 - 1e-13)
ZERO_INDICES = (1, 2, 6, 12)


def _planar_row(method: str, refs: dict[float, Any], agm_note: str) -> dict[str, str]:
    from pendcli.numerics import planar

    errs = {a: rel(planar.period_ratio(a, method), refs[a]) for a in AMPLITUDES}
    good = [a for a, e in errs.items() if e < 1e-14]
    bad = {a: e for a, e in errs.items() if e >= 1e-14}
    return row(
        PLANAR_FAMILY,
        method,
        f"rel. error < 1e-14 up to θ0 = {max(good, default=0):.16g}°" if good else "never",
        ", ".join(f"{a:.16g}°: {e:.0e}" for a, e in bad.items()) or "none measured",
        f"max rel. error {max(errs.values()):.1e} over {len(errs)} amplitudes up to "
        f"180° - 1e-13°; 180° exactly refused (infinite period)"
        + (agm_note if method == "agm" else ""),
    )


def _agm_note(k4_amplitude: float) -> str:
    from pendcli.numerics import planar

    def steps(amplitude: float) -> int:
        return planar.agm_ellipk(planar.complementary_modulus(amplitude))[1]

    return (
        f"; AGM iterations: {steps(k4_amplitude)} at {k4_amplitude:g}°, "
        f"{steps(AMPLITUDES[-1])} at 180° - 1e-13°"
    )


def _series_row(order: int, refs: dict[float, Any], k4: float, horizontal: float) -> dict[str, str]:
    from pendcli.numerics import planar
    from pendcli.papers.lecornu.model import lecornu_k4

    errs = {a: rel(planar.series_period_ratio(a, order), refs[a]) for a in (k4, horizontal, 150.0)}
    return row(
        PLANAR_FAMILY,
        f"series in k², order {order}" + (" (Lecornu keeps k², neglects k⁴)" if order == 1 else ""),
        ", ".join(f"{a:g}°: {e:.1e}" for a, e in errs.items()),
        f"k⁴ = {lecornu_k4(k4):.5f} at {k4:g}°, {lecornu_k4(horizontal):.2f} "
        f"at {horizontal:g}°; diverges as θ0 → 180°",
        "relative error of T against mpmath.ellipk at 50 digits",
    )


def planar_rows() -> list[dict[str, str]]:
    """Each method for T/T0 out to 1e-13 degree from 180°, and the k² series (orders 1, 8)."""
    table = load_paper_table("lecornu")
    k4, horizontal = table.constant("k4_amplitude"), table.constant("horizontal_amplitude")
    refs = {a: reference_period_ratio(a) for a in (*AMPLITUDES, k4, horizontal)}
    note = _agm_note(k4)
    rows = [_planar_row(m, refs, note) for m in ("agm", "ellipkm1", "ellipk", "quad")]
    rows += [_series_row(order, refs, k4, horizontal) for order in (1, 8)]
    return rows


def _bessel_row(method: str, refs: dict[tuple[int, int], Any]) -> dict[str, str]:
    from pendcli.numerics.besselzeros import bessel_zeros

    errs: dict[tuple[int, int], float] = {}
    failures = []
    for (order, s), r in refs.items():
        try:
            errs[(order, s)] = rel(float(bessel_zeros(order, s, method)[s - 1]), r)
        except PendcliError as exc:
            failures.append(f"J{order} s={s}: {short(exc)}")
    good = [k for k, e in errs.items() if e < 1e-13]
    fails = [f"J{k[0]} s={k[1]}: {e:.0e}" for k, e in errs.items() if e >= 1e-13] + failures
    return row(
        "zeros of J1, J2",
        method,
        f"rel. error < 1e-13 at {len(good)}/{len(refs)} (ν, s) checked"
        + (f", up to s = {max(k[1] for k in good)}" if good else ""),
        "; ".join(fails) or "none measured",
        f"against mpmath.besseljzero at 30 digits, s in {ZERO_INDICES}; max "
        f"{max(errs.values(), default=math.nan):.1e}",
    )


def bessel_rows() -> list[dict[str, str]]:
    """Each method of :func:`pendcli.numerics.besselzeros.bessel_zeros` against mpmath."""
    import mpmath

    from pendcli.numerics.besselzeros import METHODS

    with mpmath.workdps(30):
        refs = {(o, s): mpmath.besseljzero(o, s) for o in (1, 2) for s in ZERO_INDICES}
    return [_bessel_row(method, refs) for method in METHODS]


def stability_rows() -> list[dict[str, str]]:
    """Lecornu's rows: the planar period, then the Bessel zeros."""
    return planar_rows() + bessel_rows()
