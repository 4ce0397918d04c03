"""Lecornu far outside the paper's range.

Zeros of J_1, J_2 up to index 10^7, Lecornu's series where cancellation destroys it, and the
shortening pendulum at zero length and at very large speeds.
"""

from __future__ import annotations

import math
import time

import mpmath
import numpy as np
import pytest

from pendcli.base.errors import PendcliError
from pendcli.data.tables import paper_constant
from pendcli.numerics.besselzeros import (
    MAX_COUNT,
    SERIES_MAX_ERROR,
    bessel_zeros,
    series_error_bound,
    series_safe_limit,
)
from pendcli.papers.lecornu import explore, model
from pendcli.papers.lecornu.model import lecornu_series

pytestmark = pytest.mark.extremes

G = paper_constant("lecornu", "g")
B = paper_constant("lecornu", "speed")  # 0,35 m/s
L = paper_constant("lecornu", "length")  # 1 m at t = 0


def ulp_errors(order: int, zeros: np.ndarray, indices) -> list[float]:
    out = []
    # 30 digits: a zero's error in ulps comes out as at 40 to 15 digits (the worst, 0.4935 ulp,
    # is judged against 0.5), in two thirds of the CPU
    with mpmath.workdps(30):
        for s in indices:
            ref = mpmath.besseljzero(order, int(s))
            out.append(float((mpmath.mpf(zeros[s - 1]) - ref) / np.spacing(float(ref))))
    return out


@pytest.mark.parametrize("order", [1, 2])
def test_zeros_to_1e5_correctly_rounded_and_fast(order):
    bessel_zeros(order, 10)  # the cached mpmath head, once
    start = time.process_time()  # CPU, not wall: competing load cannot fail it
    zeros = bessel_zeros(order, 100_000)
    elapsed = time.process_time() - start
    assert elapsed < 0.5  # measured ~6 ms; scipy's jn_zeros takes ~0.4 s here
    rng = np.random.default_rng(7)
    sample = sorted({1, 2, 31, 32, 33, 1000, 99_999, 100_000, *rng.integers(1, 100_001, 40)})
    errors = ulp_errors(order, zeros, sample)
    assert max(abs(e) for e in errors) <= 0.5, errors
    assert np.all(np.diff(zeros) > 3.0)  # strictly increasing, spacing ~π


@pytest.mark.parametrize("order", [1, 2])
def test_largest_count_correctly_rounded(order):
    zeros = bessel_zeros(order, MAX_COUNT)
    sample = [MAX_COUNT // 3, MAX_COUNT - 1, MAX_COUNT]
    assert max(abs(e) for e in ulp_errors(order, zeros, sample)) <= 0.5


@pytest.mark.parametrize("order", [1, 2])
def test_scipy_jn_zeros_not_correctly_rounded_at_1e5(order):
    # the reason "auto" does not call scipy: at 10^5 it is off by more than half an ulp
    zeros = bessel_zeros(order, 100_000, "scipy")
    errors = ulp_errors(order, zeros, [100_000])
    assert 0.5 < abs(errors[0]) <= 1.0


def test_series_cancellation_destroys_it_beyond_the_safe_range():
    rows = {(r["order"], r["z"]): r for r in explore.series_cancellation((10, 20, 30, 40))}
    for order in (1, 2):
        assert rows[(order, 10.0)]["abs_error_of_J"] < 1e-12
        assert rows[(order, 20.0)]["abs_error_of_J"] < 1e-8  # Lecornu's range: still fine
        assert rows[(order, 40.0)]["abs_error_of_J"] > 1e-2  # no correct digit left
        for z in (10.0, 20.0, 30.0, 40.0):
            # the measured error stays below ε·I_ν(z), the bound the safe range is built on
            assert rows[(order, z)]["abs_error_of_J"] <= 2e-16 * rows[(order, z)]["sum_abs_terms_I"]


@pytest.mark.parametrize("order", [1, 2])
def test_series_zeros_within_their_bound(order):
    limit = series_safe_limit(order)
    zeros = bessel_zeros(order, 6, "series")
    with mpmath.workdps(30):
        for s, z in enumerate(zeros, start=1):
            err = abs(z - float(mpmath.besseljzero(order, s)))
            assert err <= max(float(series_error_bound(order, z)), 1e-14)
    assert float(series_error_bound(order, limit)) == pytest.approx(SERIES_MAX_ERROR, rel=1e-6)
    with pytest.raises(PendcliError, match="safe range"):
        bessel_zeros(order, 7, "series")


def test_series_has_no_digit_at_50():
    x = 50.0**2 / 4
    value = float(lecornu_series(1, x)) * 2 / 50.0
    assert abs(value - float(mpmath.besselj(1, 50))) > 1.0  # garbage, hence the refusal


def test_zero_length_amplitude_grows_like_one_over_length():
    rows = explore.zero_length_behaviour(B, L, G, floors=(1e-4, 1e-5, 1e-6))
    for r in rows:  # the integration tracks the exact solution down to the floor
        assert r["end_ratio_ode"] == pytest.approx(r["end_ratio_bessel"], rel=1e-5)
    # θ·l tends to a constant: unbounded θ as l → 0 (the Y_1 part, b ≠ Lecornu's speed)
    assert rows[2]["end_ratio_bessel"] > 1e4
    assert rows[2]["end_ratio_times_length"] == pytest.approx(
        rows[1]["end_ratio_times_length"], rel=0.05
    )


def test_zero_length_bounded_at_lecornus_speed():
    with mpmath.workdps(30):
        j25 = mpmath.besseljzero(2, 5)
        limit = float(1 / mpmath.besselj(0, j25))  # θ/θ0 → 1/J0(j_(2,5))
    b5 = 2 * math.sqrt(G) / float(j25)
    run = model.integrate_shortening(b5, L, G, 1e-6, rtol=1e-11, floor_fraction=1e-6)
    assert run.end_theta / 1e-6 == pytest.approx(limit, rel=1e-3)


@pytest.mark.parametrize("speed", [10.0, 100.0, 1000.0])
def test_fast_shortening(speed):
    # « un raccourcissement de dix mètres par seconde »: x = gl/b² < the first zero of J2's
    # argument, so no elongation after the release; θ grows like 1/l near zero length.
    rest = model.from_rest_model(speed, L, G, floor_fraction=1e-6)
    assert list(rest.elongation_times) == [0.0]
    run = model.integrate_shortening(speed, L, G, 1e-6, rtol=1e-10, floor_fraction=1e-6)
    np.testing.assert_allclose(run.passage_times, rest.passage_times, atol=1e-9)
    rows = explore.zero_length_behaviour(speed, L, G, floors=(1e-7, 1e-8))
    assert rows[1]["end_ratio_times_length"] == pytest.approx(
        rows[0]["end_ratio_times_length"], rel=0.05
    )


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: model.integrate_shortening(B, L, G, 1e-3, floor_fraction=0.0), "floor"),
        (lambda: model.integrate_shortening(B, L, G, 1e-3, floor_fraction=-1), "floor"),
        (lambda: model.integrate_shortening(B, L, G, math.nan), "theta0"),
        (lambda: model.integrate_shortening(B, L, G, 4.0), "theta0"),
        (lambda: model.elongation_times(0.005, L, G, "ode"), "speed"),
        (lambda: model.from_rest_model(1e-3, 1000.0, G), "speed"),
    ],
)
def test_refuses_rather_than_returns_garbage(call, match):
    with pytest.raises(PendcliError, match=match):
        call()
