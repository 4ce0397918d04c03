"""The planar pendulum's exact period up to 180° and Lecornu's k⁴ remark.

References: mpmath.ellipk at 50 digits with m formed from the exact amplitude in mpmath, and
direct integration of θ'' = -(g/l) sin θ (no elliptic functions at all).
"""

from __future__ import annotations

import itertools
import math

import mpmath
import numpy as np
import pytest

from pendcli.base.errors import PendcliError
from pendcli.numerics import planar
from pendcli.papers.lecornu.model import lecornu_k4

pytestmark = pytest.mark.extremes

AMPLITUDES = [1e-8, 1.0, 20.0, 90.0, 150.0, 179.0, 179.9999, 180 - 1e-7, 180 - 1e-10, 180 - 1e-13]


def ref_ratio(amplitude: float):
    with mpmath.workdps(50):
        m = mpmath.sin(mpmath.mpf(amplitude) * mpmath.pi / 360) ** 2
        return 2 * mpmath.ellipk(m) / mpmath.pi


def rel(value: float, reference) -> float:
    with mpmath.workdps(50):
        return float(abs((mpmath.mpf(value) - reference) / reference))


@pytest.mark.parametrize("amplitude", AMPLITUDES)
@pytest.mark.parametrize("method", ["agm", "ellipkm1"])
def test_accurate_methods_up_to_180(method, amplitude):
    assert rel(planar.period_ratio(amplitude, method), ref_ratio(amplitude)) < 1e-15


def test_usual_ellipk_call_loses_everything_near_180():
    assert rel(planar.period_ratio(150.0, "ellipk"), ref_ratio(150.0)) < 1e-14
    assert rel(planar.period_ratio(179.9999, "ellipk"), ref_ratio(179.9999)) > 1e-8
    near = 180 - 1e-10
    assert rel(planar.period_ratio(near, "ellipk"), ref_ratio(near)) > 1e-3  # inf or garbage


def test_quad_accurate_away_from_180():
    for amplitude in (20.0, 90.0, 150.0, 179.0):
        assert rel(planar.period_ratio(amplitude, "quad", epsrel=1e-13), ref_ratio(amplitude)) < (
            1e-13
        )


def test_zero_amplitude_is_the_small_oscillation_period():
    length, g = 0.7, 9.81
    for method in planar.METHODS:
        assert planar.period(0.0, length, g, method) == 2 * math.pi * math.sqrt(length / g)


@pytest.mark.parametrize("amplitude", [180.0, -180.0, 181.0, math.nan, math.inf, "90"])
def test_180_and_beyond_refused(amplitude):
    with pytest.raises(PendcliError) as info:
        planar.period(amplitude)
    assert "\n" not in str(info.value)
    if amplitude in (180.0, -180.0):
        assert "infinite" in str(info.value)


@pytest.mark.parametrize("amplitude", [20.0, 90.0, 170.0])
def test_elongation_times_against_direct_integration(amplitude):
    """Release at rest from θ0; the next elongations (θ' = 0) by DOP853 on sin θ itself."""
    from scipy.integrate import solve_ivp

    length, g = 1.0, 9.81

    def rest(_t, y):
        return y[1]

    sol = solve_ivp(
        lambda _t, y: [y[1], -(g / length) * math.sin(y[0])],
        (0.0, 3.5 * planar.period(amplitude, length, g)),
        [math.radians(amplitude), 0.0],
        method="DOP853",
        rtol=1e-12,
        atol=1e-14,
        events=rest,
    )
    found = [t for t in sol.t_events[0] if t > 1e-9][:4]
    expected = planar.elongation_times(amplitude, 4, length, g)
    assert found == pytest.approx(expected, rel=1e-8)


def test_lecornu_k4_remark():
    """k⁴ = sin⁴(θ0/2): 0,00091 at 20° (printed), 0.25 at 90° ('oscillating through 180°')."""
    assert f"{lecornu_k4(20.0):.5f}" == "0.00091"
    assert lecornu_k4(90.0) == pytest.approx(0.25, rel=1e-15)
    # and the period kept to k² is off by less than k⁴ in both cases
    for amplitude in (20.0, 90.0):
        err = rel(planar.series_period_ratio(amplitude, 1), ref_ratio(amplitude))
        assert err < lecornu_k4(amplitude)


def test_series_converges_to_exact():
    for amplitude, order, bound in ((20.0, 8, 1e-15), (90.0, 48, 1e-14), (150.0, 8, 1.0)):
        err = rel(planar.series_period_ratio(amplitude, order), ref_ratio(amplitude))
        assert err < bound
    assert rel(planar.series_period_ratio(150.0, 8), ref_ratio(150.0)) > 1e-2  # slow near 180°


@pytest.mark.parametrize("amplitude", [1.0, 20.0, 90.0, 179.0, 180 - 1e-10])
def test_agm_ellipk_against_mpmath(amplitude):
    """K(m) from the AGM of 1 and k' against mpmath.ellipk; the AGM converges quadratically."""
    kc = planar.complementary_modulus(amplitude)
    with mpmath.workdps(50):
        m = mpmath.sin(mpmath.mpf(amplitude) * mpmath.pi / 360) ** 2
        exact = mpmath.ellipk(m)
    value, used = planar.agm_ellipk(kc)
    assert rel(value, exact) < 4e-16
    assert used <= 8  # even 1e-10° from 180° (k' ~ 1e-12): a handful of steps
    errors = [rel(planar.agm_ellipk(kc, k)[0], exact) for k in (1, 2, 3)]
    for before, after in itertools.pairwise(errors):
        assert after <= max(10 * before**2, 1e-15)  # each step squares the error


# --- arrays of amplitudes ------------------------------------------------------------------

ARRAY_SAMPLE = np.concatenate(
    [np.linspace(-179.5, 179.5, 61), 180 - np.logspace(-13, -1, 7), [0.0, 90.0, 1e-8]]
)


@pytest.mark.parametrize("method", ["agm", "ellipkm1", "ellipk", "series"])
def test_array_is_the_scalar_path_element_wise(method):
    got = planar.period_ratio(ARRAY_SAMPLE.reshape(-1, 1), method)
    assert got.shape == (ARRAY_SAMPLE.size, 1)
    scalar = [planar.period_ratio(float(a), method) for a in ARRAY_SAMPLE]
    assert got.ravel().tolist() == scalar


@pytest.mark.parametrize("method", ["agm", "ellipkm1"])
def test_array_against_mpmath(method):
    got = planar.period_ratio(ARRAY_SAMPLE, method)
    worst = max(
        rel(v, ref_ratio(a)) for v, a in zip(got.tolist(), ARRAY_SAMPLE.tolist(), strict=True)
    )
    assert worst < 1e-15


def test_array_period_and_errors():
    periods = planar.period(np.array([20.0, 90.0]), 2.0, 9.81)
    assert periods.tolist() == [planar.period(20.0, 2.0, 9.81), planar.period(90.0, 2.0, 9.81)]
    assert planar.period_ratio([]).shape == (0,)
    with pytest.raises(PendcliError, match="180° is the unstable"):
        planar.period_ratio(np.array([10.0, -180.0]))
    with pytest.raises(PendcliError, match=r"must be in \[0, 180°\)|must be such that"):
        planar.period_ratio([1.0, float("nan")])
