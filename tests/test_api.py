"""The Python API: `import pendcli` offers documented functions, and imports nothing heavy."""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction

import mpmath
import pytest

import pendcli


@pytest.mark.parametrize("n", [-1, 0, 1, 3, 4, 17, 250])
def test_integral_pi_matches_mpmath_quadrature(n):
    with mpmath.workdps(40):
        reference = mpmath.quad(lambda t: mpmath.sin(t) ** (n + 1), [0, mpmath.pi])
        assert pendcli.integral_pi(n) == float(reference)


@pytest.mark.parametrize("n", [0, 3, 4, 9])
def test_integral_pi_exact_is_rational_times_a_power_of_pi(n):
    exact = pendcli.integral_pi_exact(n)
    assert isinstance(exact.rational, Fraction)
    assert exact.pi_power == n % 2
    with mpmath.workdps(40):
        reference = mpmath.quad(lambda t: mpmath.sin(t) ** (n + 1), [0, mpmath.pi])
        value = mpmath.mpf(exact.rational.numerator) / exact.rational.denominator
        assert abs(value * mpmath.pi**exact.pi_power - reference) < mpmath.mpf(10) ** -35


def test_bessel_zeros_are_zeros_of_j1():
    zeros = pendcli.bessel_zeros(1, 5)
    with mpmath.workdps(30):
        for s, z in enumerate(zeros, start=1):
            assert z == pytest.approx(float(mpmath.besseljzero(1, s)), rel=1e-15)


def test_reproduce_returns_typed_rows():
    import pendcli.api
    import pendcli.run.reproduce  # the orchestration module, imported, hides no API name

    assert pendcli.reproduce is pendcli.api.reproduce
    result = pendcli.reproduce(paper="charbonnier", formulas=False)
    rows = result.claims["charbonnier"]
    assert rows
    assert all(isinstance(r.verdict, str) and r.id.startswith("charbonnier.") for r in rows)


def test_every_public_name_is_documented_and_listed():
    for name in pendcli.__all__:
        if name == "__version__":
            continue
        obj = getattr(pendcli, name)
        assert (obj.__doc__ or "").strip(), name
        assert name in dir(pendcli)
    with pytest.raises(AttributeError):
        _ = pendcli.no_such_name


def test_import_pendcli_loads_no_scipy_and_api_names_load_lazily():
    code = (
        "import sys, pendcli\n"
        "heavy = ('scipy', 'mpmath', 'sympy', 'matplotlib', 'rich')\n"
        "assert not [m for m in heavy if m in sys.modules], sys.modules.keys()\n"
        "pendcli.integral_pi(3)\n"
        "assert 'scipy' not in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
