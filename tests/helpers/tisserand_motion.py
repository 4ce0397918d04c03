"""Tisserand's motion by mpmath at 30+ digits, from his equations as printed: (1)-(2) in the
variable z = cos θ and (4)-(5) in ψ, by formulas other than those of pendcli.numerics.spherical
(Gauss-Legendre/tanh-sinh quadrature instead of the trapezoidal rule, the Kapteyn-type form
b_n = (1/nπ)∫ cos 2nτ(ψ) dψ instead of the by-parts form). The independent references of
Tisserand's tests (the small oscillations and the extremes)."""

from __future__ import annotations

import mpmath


def mp_mean_motions(theta0: float, theta1: float, dps: int = 40) -> tuple[float, float]:
    """k'/k and Ω from (1)-(2) in z = cos θ, z = c0 + (c1 - c0) sin² s (no singularity)."""
    with mpmath.workdps(dps):
        t0, t1 = mpmath.mpf(theta0), mpmath.mpf(theta1)
        c0, c1 = mpmath.cos(t0), mpmath.cos(t1)
        u0u1 = mpmath.sin(t0) * mpmath.sin(t1)

        def z(s):
            return c0 + (c1 - c0) * mpmath.sin(s) ** 2

        def d(zz):
            return 1 + zz * c0 + zz * c1 + c0 * c1

        # dz / sqrt((z - c0)(c1 - z)) = 2 ds
        half_time = mpmath.sqrt((c0 + c1) / 2) * mpmath.quad(
            lambda s: 2 / mpmath.sqrt(d(z(s))), [0, mpmath.pi / 2]
        )
        half_phi = u0u1 * mpmath.quad(
            lambda s: 2 / ((1 - z(s) ** 2) * mpmath.sqrt(d(z(s)))), [0, mpmath.pi / 2]
        )
        k1 = mpmath.pi / (2 * half_time)
        omega = (2 * half_phi - mpmath.pi) / mpmath.pi
        return float(k1), float(omega)


def _mp_integrands(theta0: float, theta1: float):
    """k dt/dψ of (4) and dφ'/dψ = (5) minus dφ1/dψ = u0 u1/u², as mpmath functions of ψ."""
    t0, t1 = mpmath.mpf(theta0), mpmath.mpf(theta1)
    u0, u1 = mpmath.sin(t0), mpmath.sin(t1)
    c0, c1 = mpmath.cos(t0), mpmath.cos(t1)

    def common(psi):
        uu = u0**2 * mpmath.cos(psi) ** 2 + u1**2 * mpmath.sin(psi) ** 2
        c = mpmath.sqrt(1 - uu)
        return uu, c, 1 + c * c0 + c * c1 + c0 * c1

    def kdt(psi):  # eq. (4) divided by √2
        _, c, dd = common(psi)
        return mpmath.sqrt((c + c0) * (c + c1) * (c0 + c1)) / (c * mpmath.sqrt(2 * dd))

    def dphi_prime(psi):
        uu, c, dd = common(psi)
        dphi = u0 * u1 / (uu * c) * mpmath.sqrt((c + c0) * (c + c1) / dd)
        return dphi - u0 * u1 / uu

    return kdt, dphi_prime


def _remembered(function):
    """``function`` of one mpf, each value kept: the quadratures over [0, π] of one degree
    evaluate their integrands at the same nodes (every harmonic's, b_n's and c_n's)."""
    values: dict = {}

    def at(x):
        if x not in values:
            values[x] = function(x)
        return values[x]

    return at


def _mp_mean_anomaly(kdt, dps: int):
    """τ = k't as a function of ψ: the Fourier series of ∫ k dt/dψ, divided by its mean."""
    kdt = _remembered(kdt)
    pi = mpmath.pi
    a0 = mpmath.quad(kdt, [0, pi]) / pi
    coeffs = []
    for m in range(1, 60):
        am = 2 / pi * mpmath.quad(lambda p, m=m: kdt(p) * mpmath.cos(2 * m * p), [0, pi])
        coeffs.append(am / (2 * m * a0))
        if abs(am) < mpmath.mpf(10) ** (-dps + 2):
            break
    return _remembered(
        lambda psi: (
            psi + mpmath.fsum(a * mpmath.sin(2 * (j + 1) * psi) for j, a in enumerate(coeffs))
        )
    )


def mp_fourier(theta0: float, theta1: float, harmonics: int = 2, dps: int = 30):
    """b_n and c_n from (4)-(5) as printed, by the Kapteyn-type form and mpmath.quad:
    b_n = (1/nπ)∫_0^π cos 2nτ(ψ) dψ, c_n = (1/nπ)∫_0^π (dφ'/dψ) cos 2nτ(ψ) dψ."""
    with mpmath.workdps(dps):
        kdt, dphi_prime = _mp_integrands(theta0, theta1)
        tau = _mp_mean_anomaly(kdt, dps)
        nodes = [0, mpmath.pi / 2, mpmath.pi]

        def coefficient(weight, n):
            integral = mpmath.quad(lambda p: weight(p) * mpmath.cos(2 * n * tau(p)), nodes)
            return float(integral / (n * mpmath.pi))

        b = [coefficient(lambda p: 1, n) for n in range(1, harmonics + 1)]
        c = [coefficient(dphi_prime, n) for n in range(1, harmonics + 1)]
        return b, c
