"""Tisserand 1881: the conical (spherical) pendulum, its series and its numerical example.

F. Tisserand, « Sur le mouvement du pendule conique », Bulletin des sciences mathématiques et
astronomiques, 2e série, t. 5 (1881), p. 448-454 (seed 000_2b684d438490999f.txt).

Reproduced here:

* the summary formulas (I)-(VI): k' and k'' (I), ψ(t) (II), the rotation φ' of the major axis
  (V), and Resal's first approximation (the axis turns at (3/8) u0 u1 per unit k't);
* the numerical example « θ0 = 30', θ1 = 15' »: ψ = k't - 1°7'33'' sin 2k't + 2'' sin 4k't,
  φ' = (3/8) u0 u1 k'' t + 2'42'' sin 2k't;
* the remark for l = 0,5 m: the periodic term of φ' moves the bob on the circle through the
  ends of the major axis (radius l sin θ0) by at most a fifth of a millimetre.

Reading of the units: the example is printed with primes (30', 15'), but with minutes of arc
every printed coefficient is off by three to five orders of magnitude (the sin 2k't term would
be 1.1'', not 1°7'33''); with degrees (30°, 15°) Tisserand's own series give 1°7'33.1'',
1.69'' and 2'42.2''. The degree signs were printed or OCR'd as primes; the claims use
θ0 = 30°, θ1 = 15° (see :func:`reading_evidence`, which recomputes both readings).

Methods: ``Recomputed.value`` is what Tisserand's formulas give (:func:`series_conical`, the
series as printed in the summary (I), (II), (V)); ``Recomputed.exact`` is the same quantity
from the exact motion (:mod:`pendcli.numerics.spherical`: quadrature of his (4)-(5), checked against
direct integration of Newton's equations and, for k', k'' and Ω, against complete elliptic
integrals). No value of g is needed: everything is in units of k = √(g/l) and of l
(l = 0,5 m only for the displacement).

Findings: all of Tisserand's series coefficients are right (each leaves a residual of the next
even order against the exact motion), including 1/4096 for sin 4k't in (II) and (13) (the
sin² of (13) is a slip) and 35/4096 for sin 4ψ in the implicit form before (13). His example's
arithmetic is right to the printed second; but at 30° the truncated series are poor for the
periodic terms (the sin 2k't term of φ' is 2'42'' by (V), 3'28'' exactly), so the « au plus
un cinquième de millimètre » holds for his formula and fails (0.25 mm) for the true motion.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from pendcli.core.claims import Recomputed
from pendcli.core.errors import PendcliError
from pendcli.numerics.spherical import (
    ConicalMotion,
    check_amplitudes,
    exact_conical,
    projected_path,
)

__all__ = [
    "EXAMPLE_AS_PRINTED",
    "EXAMPLE_LENGTH_M",
    "EXAMPLE_READING",
    "ConicalMotion",
    "angle_text",
    "displacement_mm",
    "exact_conical",
    "example_rows",
    "figures",
    "parse_angle",
    "parse_length",
    "reading_evidence",
    "recompute",
    "series_conical",
    "series_rows",
]

EXAMPLE_AS_PRINTED = ("30'", "15'")  # as the OCR (and perhaps the print) has it
EXAMPLE_READING = ("30°", "15°")  # the reading the printed coefficients support
EXAMPLE_LENGTH_M = 0.5  # « En supposant l = 0^m,5 »
SERIES_ORDERS = (0, 2, 4, 6)
_ARCSEC = math.pi / (180 * 3600)

# ---------------------------------------------------------------- input parsing

_ANGLE_UNITS = {
    "rad": 1.0,
    "deg": math.pi / 180,
    "°": math.pi / 180,
    "arcmin": math.pi / (180 * 60),
    "'": math.pi / (180 * 60),
    "′": math.pi / (180 * 60),
    "arcsec": _ARCSEC,
    "''": _ARCSEC,
    "″": _ARCSEC,
    '"': _ARCSEC,
}
_ANGLE_FORMS = "30°, 30deg, 30', 30arcmin, 90'', 90arcsec, 0.52rad or 1°7'33''"
_NUMBER_UNIT = re.compile(r"^\s*([+-]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][+-]?\d+)?)\s*(\S*)\s*$")
_SEXAGESIMAL = re.compile(r"^\s*\d+\s*°\s*\d+\s*['′](\s*\d+(?:[.,]\d+)?\s*(''|″|\"))?\s*$")


def parse_angle(text: str, name: str = "angle") -> float:
    """An angle with its unit (30°, 30deg, 30', 30arcmin, 90arcsec, 0.52rad, 1°7'33''), in rad."""
    if not isinstance(text, str) or not text.strip():
        raise PendcliError(f"{name} is empty; write an angle with its unit, e.g. {_ANGLE_FORMS}")
    s = text.strip().replace("’", "'")
    if _SEXAGESIMAL.match(s):
        from pendcli.core.numbers import parse_printed

        return math.radians(parse_printed(s).value)
    m = _NUMBER_UNIT.match(s)
    if not m:
        raise PendcliError(f"{name} = {text!r} is not an angle; write e.g. {_ANGLE_FORMS}")
    number, unit = m.groups()
    if not unit:
        raise PendcliError(f"{name} = {text!r} has no unit; write e.g. {_ANGLE_FORMS}")
    factor = _ANGLE_UNITS.get(unit.lower())
    if factor is None:
        raise PendcliError(
            f"{name} = {text!r}: unknown unit {unit!r}; accepted forms are {_ANGLE_FORMS}"
        )
    value = float(number.replace(",", ".")) * factor
    if not math.isfinite(value):
        raise PendcliError(f"{name} = {text!r} is not finite")
    return value


def parse_length(value: float) -> float:
    """Pendulum length in metres: finite and positive."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise PendcliError(f"length = {value!r} is not a number; give metres, e.g. 0.5")
    if not 0.0 < value <= 1e6:
        raise PendcliError(f"length = {value!r} m is out of range; valid range is 0 < l <= 1e6 m")
    return float(value)


def amplitudes(theta0: str, theta1: str) -> tuple[float, float]:
    """Parse and validate θ0 and θ1 (radians), with one-line range messages."""
    a = parse_angle(theta0, "theta0")
    b = parse_angle(theta1, "theta1")
    if not 0.0 < a < 0.5 * math.pi:
        raise PendcliError(f"theta0 = {theta0} is out of range; valid range is 0 < theta0 < 90°")
    if not 0.0 <= b <= a:
        raise PendcliError(
            f"theta1 = {theta1} is out of range; valid range is 0 <= theta1 <= theta0 = {theta0}"
        )
    return check_amplitudes(a, b)


# ---------------------------------------------------------------- Tisserand's series


def series_conical(theta0_rad: float, theta1_rad: float, order: int = 6) -> ConicalMotion:
    """k', k'', Ω and the coefficients of ψ and φ' from Tisserand's summary (I), (II), (V).

    ``order`` n in (0, 2, 4, 6) keeps in every printed series the terms of degree <= n in
    (u0, u1); terms Tisserand did not print are absent (so n = 6 only adds the sixth-order
    term of k'). Ω = (3/8) u0 u1 k''/k' per unit k't, as (V) writes it.
    (I)   k' = k / [1 + (u0²+u1²)/16 + (25(u0⁴+u1⁴) - 26u0²u1²)/1024
                    + (225(u0⁶+u1⁶) - 313u0²u1²(u0²+u1²))/16384]
          k'' = k' [1 + 9(u0²+u1²)/32 + (151(u0⁴+u1⁴) + 58u0²u1²)/1024]
    (II)  ψ = k't - (u0²-u1²)(3/32 + 11(u0²+u1²)/256) sin 2k't + (u0²-u1²)²/4096 sin 4k't
    (V)   φ' = (3/8) u0 u1 k'' t + u0 u1 (u0²-u1²)(17/512) sin 2k't
    """
    theta0, theta1 = check_amplitudes(theta0_rad, theta1_rad)
    if order not in SERIES_ORDERS:
        raise PendcliError(
            f"order = {order!r} is not available; "
            f"choose one of {', '.join(map(str, SERIES_ORDERS))}"
        )
    u0, u1 = math.sin(theta0), math.sin(theta1)
    p0, p1 = u0 * u0, u1 * u1
    s, e, prod = p0 + p1, (u0 - u1) * (u0 + u1), p0 * p1

    def upto(*terms: tuple[int, float]) -> float:
        return sum(value for degree, value in terms if degree <= order)

    k_over_k1 = 1.0 + upto(
        (2, s / 16),
        (4, (25 * (p0 * p0 + p1 * p1) - 26 * prod) / 1024),
        (6, (225 * (p0**3 + p1**3) - 313 * prod * s) / 16384),
    )
    k2_over_k1 = 1.0 + upto((2, 9 * s / 32), (4, (151 * (p0 * p0 + p1 * p1) + 58 * prod) / 1024))
    k1 = 1.0 / k_over_k1
    b1 = -upto((2, e * 3 / 32), (4, e * 11 * s / 256))
    b2 = upto((4, e * e / 4096))
    c1 = upto((4, u0 * u1 * e * 17 / 512))
    return ConicalMotion(
        theta0=theta0,
        theta1=theta1,
        k1=k1,
        k2=k1 * k2_over_k1,
        precession=0.375 * u0 * u1 * k2_over_k1,
        psi_coeffs=(b1, b2),
        phi_coeffs=(c1,),
        method=f"Tisserand (I), (II), (V) to order {order}",
    )


def displacement_mm(motion: ConicalMotion, length_m: float) -> float:
    """Largest shift of the bob along the circle through the ends of the major axis (radius
    l sin θ0) due to the periodic term c_1 sin 2k't of φ': l sin θ0 |c_1|, in millimetres."""
    return 1000.0 * length_m * math.sin(motion.theta0) * abs(motion.phi_coeffs[0])


def periodic_excursion_mm(theta0: float, theta1: float, length_m: float = EXAMPLE_LENGTH_M):
    """max over t of |φ' - Ω k't| (exact motion, 8 harmonics) times l sin θ0, in mm."""
    import numpy as np

    motion = exact_conical(theta0, theta1, harmonics=8)
    tau = np.linspace(0.0, 0.5 * math.pi, 2001)
    periodic = sum(c * np.sin(2 * (n + 1) * tau) for n, c in enumerate(motion.phi_coeffs))
    return 1000.0 * length_m * math.sin(theta0) * float(np.max(np.abs(periodic)))


# ---------------------------------------------------------------- the claims


def _example_angles(reading: tuple[str, str] = EXAMPLE_READING) -> tuple[float, float]:
    return amplitudes(*reading)


def _deg(rad: float) -> float:
    return math.degrees(rad)


def angle_text(rad: float) -> str:
    """1°7'33.14'' for readable angles; seconds in scientific notation below 0.01''."""
    from pendcli.render.views import sexagesimal

    if abs(rad) < 0.01 * _ARCSEC:
        return f"{rad / _ARCSEC:.2e}''"
    return sexagesimal(_deg(rad), seconds_decimals=2)


def resal_rate_limit() -> float:
    """Ω/(u0 u1) of the exact motion at zero amplitude: eq. (5) minus dφ1/dψ, per u0 u1,
    averaged over ψ (the integrand is regular there, see :mod:`pendcli.numerics.spherical`)."""
    import numpy as np

    from pendcli.numerics.spherical import integrands

    psi = np.arange(64) * (math.pi / 64)
    _, q = integrands(0.0, 0.0, psi)
    return float(q.mean())


@dataclass(frozen=True)
class ReadingRow:
    reading: str
    theta0: str
    theta1: str
    b1: float  # rad, series (II)
    b2: float
    c1: float  # rad, series (V)
    displacement_mm: float


def reading_evidence(length_m: float = EXAMPLE_LENGTH_M) -> list[ReadingRow]:
    """Tisserand's series under both readings of the printed « θ0 = 30', θ1 = 15' »."""
    rows = []
    for label, reading in (
        ("as printed (arcmin)", EXAMPLE_AS_PRINTED),
        ("degrees", EXAMPLE_READING),
    ):
        series = series_conical(*_example_angles(reading), order=6)
        rows.append(
            ReadingRow(
                reading=label,
                theta0=reading[0],
                theta1=reading[1],
                b1=series.psi_coeffs[0],
                b2=series.psi_coeffs[1],
                c1=series.phi_coeffs[0],
                displacement_mm=displacement_mm(series, length_m),
            )
        )
    return rows


def _reading_note() -> str:
    minutes, degrees = reading_evidence()
    return (
        f"Under the printed reading 30', 15' the series give {angle_text(minutes.b1)}, "
        f"{angle_text(minutes.b2)}, {angle_text(minutes.c1)} and "
        f"{minutes.displacement_mm:.2e} mm; with 30°, 15°: {angle_text(degrees.b1)}, "
        f"{angle_text(degrees.b2)}, {angle_text(degrees.c1)}, "
        f"{degrees.displacement_mm:.4f} mm."
    )


def recompute() -> dict[str, Recomputed]:
    """The example's printed numbers and Resal's rate, from (I)-(V) and from the exact motion."""
    theta0, theta1 = _example_angles()
    series = series_conical(theta0, theta1, order=6)
    exact = exact_conical(theta0, theta1, method="quad")
    check = exact_conical(theta0, theta1, method="ode")
    agreement = max(
        abs(a - b)
        for a, b in zip(
            exact.psi_coeffs + exact.phi_coeffs, check.psi_coeffs + check.phi_coeffs, strict=True
        )
    )
    methods = (
        "Tisserand's (II)/(V) at θ0 = 30°, θ1 = 15°; exact: quadrature of (4)-(5) "
        f"(ODE agrees to {agreement:.1e} rad)"
    )
    reading = _reading_note()

    def err(s: float, x: float) -> str:
        return f"series {angle_text(s)}, exact {angle_text(x)} (series error {(s - x) / x:+.1%})."

    b1s, b1x = series.psi_coeffs[0], exact.psi_coeffs[0]
    b2s, b2x = series.psi_coeffs[1], exact.psi_coeffs[1]
    c1s, c1x = series.phi_coeffs[0], exact.phi_coeffs[0]
    shift_series = displacement_mm(series, EXAMPLE_LENGTH_M)
    shift_exact = displacement_mm(exact, EXAMPLE_LENGTH_M)
    # the printed bound « au plus un cinquième de millimètre », read from the table
    from pendcli.core.tables import load_paper_table

    bound = {c.id: c.number.value for c in load_paper_table("tisserand").claims}[
        "tisserand.example.displacement"
    ]
    limit = resal_rate_limit()
    ratio_exact = exact.precession / (math.sin(theta0) * math.sin(theta1))
    return {
        "tisserand.example.psi_sin2": Recomputed(
            value=_deg(b1s), exact=_deg(b1x), method=methods, note=err(b1s, b1x) + " " + reading
        ),
        "tisserand.example.psi_sin4": Recomputed(
            value=_deg(b2s), exact=_deg(b2x), method=methods, note=err(b2s, b2x)
        ),
        "tisserand.example.phi_sin2": Recomputed(
            value=_deg(c1s), exact=_deg(c1x), method=methods, note=err(c1s, c1x)
        ),
        "tisserand.example.displacement": Recomputed(
            value=shift_series,
            exact=shift_exact,
            method="l sin θ0 |c_1| with c_1 from (V) (value) and from the exact motion (exact)",
            note=(
                f"Series {shift_series:.4f} mm {'<=' if shift_series <= bound else '>'} 1/5 mm; "
                f"exact motion {shift_exact:.4f} mm "
                f"{'<=' if shift_exact <= bound else '>'} 1/5 mm (all harmonics of the exact "
                f"periodic part of φ': at most {periodic_excursion_mm(theta0, theta1):.4f} mm)."
            ),
        ),
        "tisserand.resal.rate": Recomputed(
            value=limit,
            method="exact dφ'/dψ of eq. (5), per u0 u1, at zero amplitude",
            note=(
                f"At 30°, 15° the exact Ω/(u0 u1) is {ratio_exact:.5f} "
                f"({(ratio_exact / limit - 1):+.1%} from 3/8); Tisserand's k''/k' gives "
                f"{series.precession / (math.sin(theta0) * math.sin(theta1)):.5f}."
            ),
        ),
    }


# ---------------------------------------------------------------- views for the CLI


def example_rows(theta0: float, theta1: float, length_m: float = EXAMPLE_LENGTH_M) -> list[dict]:
    """Series against exact motion (two methods) for every quantity of the example."""
    theta0, theta1 = check_amplitudes(theta0, theta1)
    length_m = parse_length(length_m)
    series = series_conical(theta0, theta1, order=6)
    quad = exact_conical(theta0, theta1, method="quad")
    try:
        ode: ConicalMotion | None = exact_conical(theta0, theta1, method="ode")
        ode_note = ""
    except PendcliError as exc:
        ode, ode_note = None, str(exc)
    try:
        elliptic: ConicalMotion | None = exact_conical(theta0, theta1, method="elliptic")
    except PendcliError as exc:
        elliptic, ode_note = None, "; ".join(filter(None, (ode_note, str(exc))))
    printed = _printed_for(theta0, theta1, length_m)

    def pick(m: ConicalMotion | None, key: str) -> float | None:
        if m is None:
            return None
        return {
            "k1": m.k1,
            "radial_period": m.radial_period,
            "apsidal_advance": m.apsidal_advance,
            "k2": m.k2,
            "precession": m.precession,
            "b1": m.psi_coeffs[0],
            "b2": m.psi_coeffs[1],
            "c1": m.phi_coeffs[0],
            "shift": displacement_mm(m, length_m),
        }[key]

    quantities = (
        ("k1", "k'/k (mean motion of ψ)", "", False),
        ("radial_period", "k T_r: radial period, θ0 → θ1 → θ0 (= π k/k')", "", False),
        ("apsidal_advance", "rotation of the major axis per radial period, Δφ - π", "angle", True),
        ("k2", "k''/k (eq. V)", "", False),
        ("precession", "Ω: rotation of the major axis per unit k't", "rad", False),
        ("b1", "ψ: coefficient of sin 2k't", "angle", True),
        ("b2", "ψ: coefficient of sin 4k't", "angle", True),
        ("c1", "φ': coefficient of sin 2k't", "angle", True),
        (
            "shift",
            f"largest shift on the circle of radius l sin θ0 (l = {length_m:g} m)",
            "mm",
            False,
        ),
    )
    rows = []
    for key, label, unit, is_angle in quantities:
        s, x, o = pick(series, key), pick(quad, key), pick(ode, key)
        row = {
            "quantity": label,
            "published": printed.get(key, ""),
            "series": s,
            "exact": x,
            "exact_ode": o,
            "methods_diff": None if o is None else o - x,
            "elliptic_rel_diff": _elliptic_rel_diff(elliptic, key, x),
            "series_error": s - x,
            "series_rel_error": (s - x) / x if x else None,
            "unit": "rad" if is_angle else unit,
        }
        if is_angle:
            row["series_text"] = angle_text(s)
            row["exact_text"] = angle_text(x)
        rows.append(row)
    if ode_note:
        rows.append({"quantity": "methods refused", "published": "", "note": ode_note})
    return rows


def _elliptic_rel_diff(elliptic: ConicalMotion | None, key: str, exact: float) -> float | None:
    """(elliptic - quadrature)/quadrature for the quantities the elliptic method gives."""
    if elliptic is None or not exact:
        return None
    value = {
        "k1": elliptic.k1,
        "radial_period": elliptic.radial_period,
        "apsidal_advance": elliptic.apsidal_advance,
        "k2": elliptic.k2,
        "precession": elliptic.precession,
    }.get(key)
    return None if value is None else value / exact - 1.0


def _printed_for(theta0: float, theta1: float, length_m: float) -> dict[str, str]:
    """The printed strings, when the amplitudes are the example's (either reading)."""
    from pendcli.core.tables import load_paper_table

    readings = [_example_angles(EXAMPLE_READING), _example_angles(EXAMPLE_AS_PRINTED)]
    if not any(
        math.isclose(theta0, a, rel_tol=1e-12) and math.isclose(theta1, b, rel_tol=1e-12)
        for a, b in readings
    ):
        return {}
    claims = {c.id: c.published for c in load_paper_table("tisserand").claims}
    out = {
        "b1": claims["tisserand.example.psi_sin2"],
        "b2": claims["tisserand.example.psi_sin4"],
        "c1": claims["tisserand.example.phi_sin2"],
    }
    if math.isclose(length_m, EXAMPLE_LENGTH_M):
        out["shift"] = "<= " + claims["tisserand.example.displacement"]
    return out


def series_rows(ratio: float = 0.5, order: int = 6, theta0_degrees=None) -> list[dict]:
    """k', k'' and Ω from the series against the exact motion, θ1 = ratio·θ0, over θ0."""
    if isinstance(ratio, bool) or not isinstance(ratio, (int, float)) or not 0 <= ratio <= 1:
        raise PendcliError(f"ratio = {ratio!r} is out of range; valid range is 0 <= ratio <= 1")
    grid = theta0_degrees or (0.5, 1, 2, 5, 10, 15, 20, 30, 45, 60, 75, 85, 89)
    rows = []
    for deg in grid:
        theta0 = math.radians(deg)
        theta1 = ratio * theta0
        s = series_conical(theta0, theta1, order)
        x = exact_conical(theta0, theta1, method="quad")
        row = {"theta0_deg": float(deg), "theta1_deg": math.degrees(theta1)}
        for key, a, b in (
            ("k1", s.k1, x.k1),
            ("k2", s.k2, x.k2),
            ("precession", s.precession, x.precession),
        ):
            row[f"{key}_series"] = a
            row[f"{key}_exact"] = b
            row[f"{key}_rel_error"] = (a - b) / b if b else None
        rows.append(row)
    return rows


# ---------------------------------------------------------------- figures


def figures(outdir) -> list[Path]:
    """(1) the projected path over several turns with the series' ellipse; (2) series errors."""
    outdir = Path(outdir)
    return [
        plot_path(outdir / "tisserand_path.png"),
        plot_series_error(outdir / "tisserand_series_error.png"),
    ]


def series_path(theta0: float, theta1: float, kt):
    """(x, y)/l from (II)-(VI): ψ, φ1, sin θ and φ = φ1 + φ' at times kt."""
    import numpy as np

    s = series_conical(theta0, theta1, order=6)
    u0, u1 = math.sin(theta0), math.sin(theta1)
    tau = s.k1 * np.asarray(kt)
    psi = tau + s.psi_coeffs[0] * np.sin(2 * tau) + s.psi_coeffs[1] * np.sin(4 * tau)
    phi_prime = s.precession * tau + s.phi_coeffs[0] * np.sin(2 * tau)
    # (III)-(IV): the point (u0 cos ψ, u1 sin ψ) of the ellipse, turned by φ'.
    ex, ey = u0 * np.cos(psi), u1 * np.sin(psi)
    return (
        ex * np.cos(phi_prime) - ey * np.sin(phi_prime),
        ex * np.sin(phi_prime) + ey * np.cos(phi_prime),
    )


def plot_path(path, theta0: float | None = None, theta1: float | None = None, turns: int = 6):
    """The bob's projection over ``turns`` radial periods: exact path, series path, ellipses."""
    import numpy as np

    from pendcli.core.plotting import new_figure

    if theta0 is None or theta1 is None:
        theta0, theta1 = _example_angles()
    theta0, theta1 = check_amplitudes(theta0, theta1)
    exact = exact_conical(theta0, theta1)
    series = series_conical(theta0, theta1, order=6)
    kt = np.linspace(0.0, turns * exact.radial_period, 120 * turns + 1)
    x, y = projected_path(theta0, theta1, kt)
    xs, ys = series_path(theta0, theta1, kt)
    u0, u1 = math.sin(theta0), math.sin(theta1)
    angle = np.linspace(0, 2 * math.pi, 361)
    with new_figure(path, size=(6.5, 6.5)) as (_fig, ax):
        ax.plot(x, y, "-", color="tab:blue", lw=1.0, label="exact motion (ODE)")
        ax.plot(xs, ys, "--", color="tab:red", lw=0.9, label="Tisserand (II)-(VI)")
        for j in range(turns + 1):
            rot = series.precession * series.k1 * j * exact.radial_period
            ex, ey = u0 * np.cos(angle), u1 * np.sin(angle)
            ax.plot(
                ex * math.cos(rot) - ey * math.sin(rot),
                ex * math.sin(rot) + ey * math.cos(rot),
                ":",
                color="gray",
                lw=0.6,
                label="series ellipse, each radial period" if j == 0 else None,
            )
        ax.set_aspect("equal")
        ax.set_xlabel("x / l")
        ax.set_ylabel("y / l")
        ax.set_title(
            f"Projected path, θ0 = {math.degrees(theta0):g}°, θ1 = {math.degrees(theta1):g}°, "
            f"{turns} radial periods"
        )
        ax.legend(loc="lower left", fontsize=8)
        ax.grid(True, alpha=0.3)
    return Path(path)


def plot_series_error(path, ratio: float = 0.5):
    """|series - exact|/|exact| for k', k'', Ω and the printed coefficients, against θ0."""
    import numpy as np

    from pendcli.core.plotting import new_figure

    degrees = np.geomspace(0.5, 85.0, 40)
    curves: dict[str, list[float]] = {
        "k'": [],
        "k''": [],
        "Ω": [],
        "sin 2k't in ψ": [],
        "sin 4k't in ψ": [],
        "sin 2k't in φ'": [],
    }
    for deg in degrees:
        theta0 = math.radians(deg)
        s = series_conical(theta0, ratio * theta0, 6)
        x = exact_conical(theta0, ratio * theta0)
        pairs = (
            (s.k1, x.k1),
            (s.k2, x.k2),
            (s.precession, x.precession),
            (s.psi_coeffs[0], x.psi_coeffs[0]),
            (s.psi_coeffs[1], x.psi_coeffs[1]),
            (s.phi_coeffs[0], x.phi_coeffs[0]),
        )
        for name, (a, b) in zip(curves, pairs, strict=True):
            curves[name].append(abs(a - b) / abs(b) if b != 0 else math.nan)
    with new_figure(path, size=(7.0, 4.8)) as (_fig, ax):
        for name, values in curves.items():
            # k'' and Ω = (3/8) u0 u1 k''/k' carry the same relative error: draw Ω dashed.
            style = "--" if name == "Ω" else "-"
            label = "Ω (same error as k'')" if name == "Ω" else name
            ax.plot(degrees, values, style, lw=1.2, label=label)
        ax.axvline(30.0, color="gray", ls=":", lw=0.8)
        ax.text(31.5, 1e-9, "example θ0 = 30°", rotation=90, fontsize=7, color="gray")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(1e-16, 10)
        ax.set_xlabel(
            "θ0 (degrees), θ1 = θ0/2" if ratio == 0.5 else f"θ0 (degrees), θ1 = {ratio}·θ0"
        )
        ax.set_ylabel("relative error of the series")
        ax.set_title("Tisserand's series (I), (II), (V) against the exact motion")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    return Path(path)
