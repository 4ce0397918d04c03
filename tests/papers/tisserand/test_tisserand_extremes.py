"""Tisserand: the exact motion far from Tisserand's small oscillations.

theta1 -> 0 (near-planar: φ jumps by π at the vertical), theta0 -> 90° (the integrand of (4)
peaks like 1/cos θ0) and theta0 = theta1 (conical: no radial oscillation, ψ undefined). Each
result is checked against an independent computation: mpmath at 30-50 digits (the complete
elliptic integral, the textbook conical pendulum, Tisserand's (1)-(2) in z = cos θ), or the
method must refuse with a PendcliError saying why.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from helpers.tisserand_motion import mp_fourier, mp_mean_motions

from pendcli.base.errors import PendcliError
from pendcli.numerics.spherical import conical_limit, exact_conical, planar_limit_k1
from pendcli.papers.tisserand.model import series_conical

pytestmark = pytest.mark.extremes


def mp_planar_k1(theta0: float) -> float:
    """θ1 = 0: T_r is half the plane pendulum's period 4K(m)/k, m = sin²(θ0/2)."""
    with mpmath.workdps(30):
        m = mpmath.sin(mpmath.mpf(theta0) / 2) ** 2
        return float(mpmath.pi / (2 * mpmath.ellipk(m)))


def mp_conical(theta0: float) -> tuple[float, float]:
    """Conical pendulum: φ' = ω_c = √(g/(l cos α)); radial frequency ω_c √(1 + 3 cos²α);
    ψ advances π per radial period, so k'/k = ω_r/(2k) and Ω = ω_c/k' - 1."""
    with mpmath.workdps(30):
        c = mpmath.cos(mpmath.mpf(theta0))
        omega_c = 1 / mpmath.sqrt(c)
        omega_r = omega_c * mpmath.sqrt(1 + 3 * c * c)
        k1 = omega_r / 2
        return float(k1), float(omega_c / k1 - 1)


# ------------------------------------------------------------ theta1 -> 0


@pytest.mark.parametrize("theta0_deg", [5.0, 40.0, 80.0])
@pytest.mark.parametrize("theta1", [0.0, 1e-12, 1e-6])
def test_near_planar_mean_motion(theta0_deg, theta1):
    theta0 = math.radians(theta0_deg)
    m = exact_conical(theta0, theta1)
    # k' moves from the planar value by O(θ1²): below 1e-11 here.
    assert m.k1 == pytest.approx(mp_planar_k1(theta0), rel=1e-13)
    assert planar_limit_k1(theta0) == pytest.approx(mp_planar_k1(theta0), rel=1e-14)
    assert math.isfinite(m.k2) and m.k2 > 0


@pytest.mark.parametrize("theta1", [1e-9, 1e-4])
def test_near_planar_precession_against_mpmath(theta1):
    theta0 = math.radians(40)
    m = exact_conical(theta0, theta1)
    k1, omega = mp_mean_motions(theta0, theta1, dps=50)
    assert m.k1 == pytest.approx(k1, rel=1e-14)
    # Ω ∝ u0 u1 → 0, but relative accuracy is kept (no cancellation in the integrand).
    assert m.precession == pytest.approx(omega, rel=1e-12)


def test_near_planar_fourier_against_mpmath():
    theta0, theta1 = math.radians(40), 1e-9
    m = exact_conical(theta0, theta1)
    b, c = mp_fourier(theta0, theta1, harmonics=2, dps=30)
    assert m.psi_coeffs[:2] == pytest.approx(b, rel=1e-12)
    assert m.phi_coeffs[:2] == pytest.approx(c, rel=1e-9)


def test_planar_limit_exactly():
    m = exact_conical(math.radians(40), 0.0)
    assert m.precession == 0.0
    assert m.phi_coeffs == (0.0, 0.0, 0.0)


def test_ode_refuses_near_planar():
    with pytest.raises(PendcliError, match="near-planar"):
        exact_conical(math.radians(40), 1e-6, method="ode")


def test_ode_still_right_at_its_near_planar_limit():
    theta0 = math.radians(40)
    theta1 = 1.01e-3 * theta0
    quad, ode = exact_conical(theta0, theta1), exact_conical(theta0, theta1, method="ode")
    assert ode.k1 == pytest.approx(quad.k1, rel=1e-12)
    assert abs(ode.precession - quad.precession) < 1e-12
    for a, b in zip(
        quad.psi_coeffs + quad.phi_coeffs, ode.psi_coeffs + ode.phi_coeffs, strict=True
    ):
        assert abs(a - b) < 1e-10


# ------------------------------------------------------------ theta0 -> 90°


@pytest.mark.parametrize("theta0_deg", [85.0, 89.9, 89.99])
def test_near_horizontal_against_mpmath(theta0_deg):
    theta0, theta1 = math.radians(theta0_deg), math.radians(30)
    m = exact_conical(theta0, theta1)
    k1, omega = mp_mean_motions(theta0, theta1, dps=40)
    assert m.k1 == pytest.approx(k1, rel=1e-13)
    assert m.precession == pytest.approx(omega, rel=1e-13)


def test_near_horizontal_fourier_two_methods():
    theta0, theta1 = math.radians(89.9), math.radians(30)
    quad, ode = exact_conical(theta0, theta1), exact_conical(theta0, theta1, method="ode")
    for a, b in zip(
        quad.psi_coeffs + quad.phi_coeffs, ode.psi_coeffs + ode.phi_coeffs, strict=True
    ):
        assert abs(a - b) < 1e-10


def test_too_close_to_horizontal_is_refused():
    with pytest.raises(PendcliError, match="too close to 90°"):
        exact_conical(math.radians(89.9999), math.radians(30))
    with pytest.raises(PendcliError, match=r"theta0 <= 89\.99°"):
        exact_conical(math.radians(89.995), math.radians(30), method="ode")
    with pytest.raises(PendcliError, match="<= theta0 < 90°"):
        exact_conical(math.pi / 2, 0.3)


def test_series_meaningless_near_horizontal():
    # The series stay finite but are wrong by tens of per cent: an expected disagreement.
    theta0, theta1 = math.radians(89), math.radians(44.5)
    s, x = series_conical(theta0, theta1, 6), exact_conical(theta0, theta1)
    assert abs(s.k2 / x.k2 - 1) > 0.2
    assert abs(s.phi_coeffs[0] / x.phi_coeffs[0] - 1) > 0.5


# ------------------------------------------------------------ theta0 = theta1


@pytest.mark.parametrize("theta0_deg", [1.0, 30.0, 60.0, 89.0, 89.9999])
def test_conical_against_textbook(theta0_deg):
    theta0 = math.radians(theta0_deg)
    k1, omega = mp_conical(theta0)
    for m in (exact_conical(theta0, theta0), conical_limit(theta0)):
        assert m.k1 == pytest.approx(k1, rel=1e-13)
        assert m.precession == pytest.approx(omega, rel=1e-13)
        assert all(abs(b) < 1e-15 for b in m.psi_coeffs + m.phi_coeffs)


def test_near_conical_is_continuous():
    theta0 = math.radians(60)
    k1, omega = mp_conical(theta0)
    m = exact_conical(theta0, theta0 * (1 - 1e-9))
    assert m.k1 == pytest.approx(k1, rel=1e-8)
    assert m.precession == pytest.approx(omega, rel=1e-8)


def test_ode_refuses_conical():
    with pytest.raises(PendcliError, match="conical"):
        exact_conical(math.radians(60), math.radians(60), method="ode")
    with pytest.raises(PendcliError, match="conical"):
        exact_conical(math.radians(60), math.radians(60) * (1 - 1e-7), method="ode")


def test_elliptic_refuses_near_planar_and_is_right_just_above():
    theta0 = math.radians(40)
    with pytest.raises(PendcliError, match="near-planar"):
        exact_conical(theta0, 1e-7 * theta0, method="elliptic")
    theta1 = 2e-6 * theta0
    m = exact_conical(theta0, theta1, method="elliptic")
    k1, omega = mp_mean_motions(theta0, theta1, dps=50)
    assert m.k1 == pytest.approx(k1, rel=1e-14)
    assert m.precession == pytest.approx(omega, rel=1e-8)


@pytest.mark.parametrize("theta0_deg", [30.0, 89.9999])
def test_elliptic_conical(theta0_deg):
    theta0 = math.radians(theta0_deg)
    k1, omega = mp_conical(theta0)
    m = exact_conical(theta0, theta0, method="elliptic")
    assert m.k1 == pytest.approx(k1, rel=1e-13)
    assert m.precession == pytest.approx(omega, rel=1e-13)
