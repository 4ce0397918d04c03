"""Explorations behind `pendcli lecornu ...`: the example at any speed, length and g, the ODE
against the Bessel solution, zero length, the series in double precision, and g.

Each returns plain rows (dicts) for the CLI to render; ``None`` for speed, length or g means
the paper's value (``[paper.constants]`` of the published table).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from pendcli.base.checks import real_in_range
from pendcli.numerics.besselzeros import bessel_zeros
from pendcli.papers.lecornu.model import (
    MAX_Z0_ODE,
    ExampleModel,
    FromRestModel,
    check_example,
    constant,
    example_model,
    from_rest_cylinder,
    from_rest_model,
    integrate_shortening,
    lecornu_series,
)

__all__ = [
    "AMPLITUDE_RANGE",
    "G_PARIS",
    "ODE_AMPLITUDES",
    "best_g",
    "example_rows",
    "g_dependent_ids",
    "g_grid",
    "g_sensitivity",
    "g_values",
    "ode_check",
    "series_cancellation",
    "zero_length_behaviour",
]

Row = dict[str, Any]

# Paris (48°50' N, ~60 m): international gravity formula 1930 minus the free-air term.
G_PARIS = (
    9.780490
    * (
        1
        + 0.0052884 * math.sin(math.radians(48.836)) ** 2
        - 0.0000059 * math.sin(math.radians(2 * 48.836)) ** 2
    )
    - 3.086e-6 * 60
)
AMPLITUDE_RANGE = (1e-6, 179.0)  # degrees, for eq. (3) with sin θ
ODE_AMPLITUDES = (1.0, 5.0)  # degrees: small, and 25 times the finite-amplitude effect


def g_grid() -> tuple[float, ...]:
    """The g of `pendcli lecornu g-sensitivity`: around the table's g, Paris's among them."""
    return (9.78, 9.80, G_PARIS, constant("g"), 9.83)


# --- the example --------------------------------------------------------------------------


def _elongation_row(m: ExampleModel, rest: FromRestModel, k: int) -> Row:
    row: Row = {
        "k": k + 1,
        "z": float(m.elongation_z[k]),
        "length_m": float(m.elongation_lengths[k]),
        "time_s": float(m.elongation_times[k]),
        "j0": float(m.j0_at_elongations[k]),
        "ratio": float(m.amplitude_ratios[k]),
        "from_rest_length_m": None,
        "from_rest_time_s": None,
        "from_rest_ratio": None,
    }
    if k < len(rest.elongation_times):
        row["from_rest_length_m"] = float(rest.elongation_lengths[k])
        row["from_rest_time_s"] = float(rest.elongation_times[k])
        row["from_rest_ratio"] = float(rest.amplitude_ratios[k])
    return row


def _passage_rows(m: ExampleModel, rest: FromRestModel) -> list[Row]:
    before_release = int(np.sum(m.passage_times < 0))
    rows = []
    for k in range(len(m.passage_z)):
        # the from-rest passage matching this one: same order counted from the release
        j = k - before_release
        rows.append(
            {
                "k": k + 1,
                "z": float(m.passage_z[k]),
                "length_m": float(m.passage_lengths[k]),
                "time_s": float(m.passage_times[k]),
                "from_rest_time_s": float(rest.passage_times[j])
                if 0 <= j < len(rest.passage_times)
                else None,
            }
        )
    return rows


def _summary_rows(m: ExampleModel, rest: FromRestModel) -> list[Row]:
    return [
        {"quantity": "b²/(4g), eq. (16)", "value": m.coefficient, "unit": "m"},
        {"quantity": "time at zero length L/b", "value": m.zero_length_time, "unit": "s"},
        {
            "quantity": "θ/θ0 at zero length, solution (10)",
            "value": m.zero_length_ratio,
            "unit": "",
        },
        {
            "quantity": "speed making L an elongation, 2√(gL)/j_2 nearest",
            "value": 2 * math.sqrt(m.g * m.length) / float(m.elongation_z[0]),
            "unit": "m/s",
        },
        {
            "quantity": "from rest: weight of the singular part J_2(z0)/Y_2(z0)",
            "value": rest.singular_weight,
            "unit": "",
        },
        {
            "quantity": "from rest: elongations listed down to the floor",
            "value": rest.floor,
            "unit": "m",
        },
    ]


def example_rows(
    speed: float | None = None, length: float | None = None, g: float | None = None
) -> tuple[list[Row], list[Row], list[Row]]:
    """Rows for `pendcli lecornu example`: elongations, vertical passages, summary."""
    m = example_model(speed, length, g)
    rest = from_rest_model(speed, length, g)
    elongations = [_elongation_row(m, rest, k) for k in range(len(m.elongation_z))]
    return elongations, _passage_rows(m, rest), _summary_rows(m, rest)


# --- the ODE against the Bessel solution ----------------------------------------------------


def _ode_row(k: int, bessel: FromRestModel, linear: Any, nonlinear: dict[float, Any]) -> Row:
    row: Row = {
        "k": k,
        "length_m": float(bessel.elongation_lengths[k]),
        "t_bessel_s": float(bessel.elongation_times[k]),
        "t_ode_linear_s": float(linear.elongation_times[k]),
        "linear_minus_bessel_s": float(linear.elongation_times[k] - bessel.elongation_times[k]),
        "ratio_bessel": float(bessel.amplitude_ratios[k]),
        "ratio_ode_linear": float(linear.elongation_angles[k] / linear.elongation_angles[0]),
    }
    for amp, res in nonlinear.items():
        reached = k < len(res.elongation_times)
        row[f"sin_shift_{amp:g}deg_s"] = (
            float(res.elongation_times[k] - bessel.elongation_times[k]) if reached else None
        )
        row[f"theta_{amp:g}deg_at_elongation_deg"] = (
            float(np.degrees(res.elongation_angles[k])) if reached else None
        )
    return row


def ode_check(
    speed: float | None = None,
    length: float | None = None,
    g: float | None = None,
    amplitudes_deg: tuple[float, ...] | None = None,
    floor_fraction: float = 0.02,
) -> list[Row]:
    """Bessel elongation times against solve_ivp (linear, and sin θ at the given amplitudes,
    in degrees; default :data:`ODE_AMPLITUDES`)."""
    if amplitudes_deg is None:
        amplitudes_deg = ODE_AMPLITUDES
    amplitudes = [
        real_in_range("amplitude", a, *AMPLITUDE_RANGE, "degrees") for a in amplitudes_deg
    ]
    bessel = from_rest_model(speed, length, g, floor_fraction)
    linear = integrate_shortening(speed, length, g, 1e-3, rtol=1e-11, floor_fraction=floor_fraction)
    nonlinear = {
        amp: integrate_shortening(
            speed,
            length,
            g,
            math.radians(amp),
            nonlinear=True,
            rtol=1e-11,
            floor_fraction=floor_fraction,
        )
        for amp in amplitudes
    }
    n = min(len(bessel.elongation_times), len(linear.elongation_times))
    return [_ode_row(k, bessel, linear, nonlinear) for k in range(n)]


def zero_length_behaviour(
    speed: float | None = None,
    length: float | None = None,
    g: float | None = None,
    floors: tuple[float, ...] = (1e-2, 1e-3, 1e-4, 1e-5, 1e-6),
) -> list[Row]:
    """|θ|max/θ0 of the linear motion from rest as the length floor goes to 0, ODE and Bessel.

    For a speed other than Lecornu's (J_2(z0) ≠ 0) the Y_1 part of the solution grows like
    1/l: the ratio times the floor tends to a constant. At l → 0 the linear model itself has
    no meaning (the author's remark after (17)); this shows how fast it leaves it.
    """
    b, a, gg, z0 = check_example(speed, length, g, max_z0=MAX_Z0_ODE)
    theta_start = from_rest_cylinder(1, np.array([z0]), z0)[0] / z0
    rows = []
    for frac in floors:
        res = integrate_shortening(b, a, gg, 1e-6, rtol=1e-10, floor_fraction=frac)
        z = 2.0 * math.sqrt(gg * frac * a) / b
        ratio = float(abs(from_rest_cylinder(1, np.array([z]), z0)[0] / z / theta_start))
        rows.append(
            {
                "floor_m": frac * a,
                "max_ratio_ode": res.max_abs_theta / 1e-6,
                "end_ratio_ode": abs(res.end_theta) / 1e-6,
                "end_ratio_bessel": ratio,
                "end_ratio_times_length": ratio * frac * a,
            }
        )
    return rows


# --- Lecornu's series in double precision ------------------------------------------------


def series_cancellation(zs: tuple[float, ...] = (2, 5, 10, 15, 20, 25, 30, 35, 40)) -> list[Row]:
    """J_1 and J_2 from Lecornu's series (10)/(13) in double precision against mpmath."""
    import mpmath as mp

    from pendcli.numerics.besselzeros import series_error_bound

    rows = []
    with mp.workdps(40):
        for z in zs:
            x = z * z / 4.0
            for order in (1, 2):
                s = float(lecornu_series(order, x))
                value = s * 2 / z if order == 1 else s * x  # J_1 = 2φ/z, J_2 = x·(13)
                exact = mp.besselj(order, z)
                rows.append(
                    {
                        "order": order,
                        "z": float(z),
                        "series": value,
                        "mpmath": float(exact),
                        "abs_error_of_J": float(abs(value - exact)),
                        "sum_abs_terms_I": float(mp.besseli(order, z)),
                        "zero_error_bound": float(series_error_bound(order, float(z))),
                    }
                )
    return rows


# --- g ------------------------------------------------------------------------------------


def g_dependent_ids() -> list[str]:
    """The claims whose recomputation depends on the assumed g."""
    ids = [f"lecornu.speed.{k}" for k in range(1, 6)]
    ids += ["lecornu.coefficient_b2_4g"]
    ids += [f"lecornu.example.length.{k}" for k in range(1, 6)]
    ids += [f"lecornu.example.time.{k}" for k in range(1, 6)]
    ids += [f"lecornu.example.interval.{k}" for k in range(1, 6)]
    ids += [f"lecornu.j1_lengths.{k}" for k in range(1, 7)]
    return ids


def g_values(g: float) -> dict[str, float]:
    """The g-dependent claims (author's model) at ``g``, the example's speed and length."""
    length = constant("length")
    m = example_model(constant("speed"), length, g)
    z2 = bessel_zeros(2, 5)
    out = {f"lecornu.speed.{k + 1}": 2 * math.sqrt(g * length) / z2[k] for k in range(5)}
    out["lecornu.coefficient_b2_4g"] = m.coefficient
    for k in range(5):
        out[f"lecornu.example.length.{k + 1}"] = float(m.elongation_lengths[k])
        out[f"lecornu.example.time.{k + 1}"] = float(m.elongation_times[k])
        out[f"lecornu.example.interval.{k + 1}"] = float(m.intervals[k])
    for k in range(6):
        out[f"lecornu.j1_lengths.{k + 1}"] = float(m.passage_lengths[k])
    return out


def g_sensitivity(gs: tuple[float, ...] | None = None) -> list[Row]:
    """Each g-dependent claim recomputed at several g (default :func:`g_grid`), with its
    verdict and d(value)/dg at the table's g."""
    from pendcli.data.tables import load_paper_table
    from pendcli.verify.verdict import judge

    gs = g_grid() if gs is None else gs
    table = load_paper_table("lecornu").claims_by_id(g_dependent_ids(), "lecornu g-sensitivity")
    per_g = {g: g_values(g) for g in gs}
    g0, h = constant("g"), 1e-4
    up, down = g_values(g0 + h), g_values(g0 - h)
    rows = []
    for cid in g_dependent_ids():
        entry = table[cid]
        row: Row = {
            "id": cid,
            "published": entry.published,
            "d_value_dg": (up[cid] - down[cid]) / (2 * h),
        }
        for g in gs:
            v = per_g[g][cid]
            row[f"g={g:.4f}"] = v
            row[f"verdict g={g:.4f}"] = judge(entry.number, v, entry.comparison).verdict.value
        rows.append(row)
    return rows


def _score_and_agreeing(g: float, table: dict[str, Any], ids: list[str]) -> tuple[float, int]:
    """Σ ((recomputed - printed)/u)² and the number of agreeing claims at g."""
    from pendcli.verify.verdict import Verdict, judge

    vals = g_values(g)
    score = sum(((vals[i] - table[i].number.value) / table[i].number.resolution) ** 2 for i in ids)
    agreeing = sum(judge(table[i].number, vals[i]).verdict is Verdict.AGREES for i in ids)
    return float(score), int(agreeing)


def best_g(lo: float = 9.70, hi: float = 9.90, step: float = 0.0005) -> dict[str, Any]:
    """The g that best reproduces the g-dependent printed figures (not used for verdicts).

    Score: Σ ((recomputed - printed)/u)² over the g-dependent claims, u the printed last
    unit; also the g range where the most claims agree, and both at the table's g (the keys
    ``score_at_<g>``, ``agreeing_at_<g>``).
    """
    from pendcli.data.tables import load_paper_table

    ids = g_dependent_ids()
    table = load_paper_table("lecornu").claims_by_id(ids, "the best-fitting g")
    gs = np.round(np.arange(lo, hi + step / 2, step), 6)
    results = [_score_and_agreeing(float(g), table, ids) for g in gs]
    scores = np.array([r[0] for r in results])
    agree = np.array([r[1] for r in results])
    best = int(np.argmin(scores))
    most = agree.max()
    where = gs[agree == most]
    g0 = constant("g")
    score_table_g, agreeing_table_g = _score_and_agreeing(g0, table, ids)
    return {
        "best_g_least_squares": float(gs[best]),
        "score_at_best": float(scores[best]),
        f"score_at_{g0:g}": score_table_g,
        "most_agreeing": int(most),
        "of": len(ids),
        "g_range_most_agreeing": (float(where.min()), float(where.max())),
        f"agreeing_at_{g0:g}": agreeing_table_g,
    }
