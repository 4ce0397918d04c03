"""Zeros of J_1 and J_2 by every method, against mpmath at 40 digits (findroot on besselj)."""

from __future__ import annotations

import inspect
import math

import mpmath
import numpy as np
import pytest

from pendcli.base.errors import PendcliError
from pendcli.numerics.besselzeros import (
    MAX_COUNT,
    METHODS,
    ascending_series,
    bessel_zeros,
    bessel_zeros_at,
    iter_bessel_zeros,
    series_safe_limit,
)
from pendcli.papers.lecornu.model import lecornu_series

REF_DPS = 40


def reference_zero(order: int, s: int) -> mpmath.mpf:
    """Independent reference: Newton on mpmath.besselj at 40 digits from McMahon's β."""
    with mpmath.workdps(REF_DPS):
        beta = (s + order / 2 - mpmath.mpf(1) / 4) * mpmath.pi
        start = beta - (4 * order**2 - 1) / (8 * beta)
        return mpmath.findroot(lambda x: mpmath.besselj(order, x), start)


def ulp_error(value: float, ref: mpmath.mpf) -> float:
    with mpmath.workdps(REF_DPS):
        return float((mpmath.mpf(value) - ref) / np.spacing(float(ref)))


@pytest.fixture(scope="module")
def references():
    return {order: [reference_zero(order, s) for s in range(1, 41)] for order in (1, 2)}


def test_signature_and_methods():
    params = list(inspect.signature(bessel_zeros).parameters)
    assert params == ["order", "count", "method"]
    assert inspect.signature(bessel_zeros).parameters["method"].default == "auto"
    assert set(METHODS) == {"auto", "scipy", "mcmahon", "mcmahon-newton", "mpmath", "series"}


# (method, count, largest allowed error in ulp over the first `count` zeros)
ULP_LIMITS = [
    ("auto", 40, 0.5),  # correctly rounded
    ("mpmath", 40, 0.5),
    ("scipy", 40, 1.0),  # measured up to 0.87 ulp
    ("mcmahon-newton", 40, 2.0),  # measured up to 1.1 ulp (scipy jv near a zero)
]


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize(("method", "count", "max_ulp"), ULP_LIMITS)
def test_zeros_against_mpmath(references, order, method, count, max_ulp):
    zeros = bessel_zeros(order, count, method)
    assert zeros.shape == (count,)
    errors = [ulp_error(z, references[order][k]) for k, z in enumerate(zeros)]
    assert max(abs(e) for e in errors) <= max_ulp, errors


@pytest.mark.parametrize("order", [1, 2])
def test_mcmahon_bad_at_first_zeros_exact_beyond(references, order):
    zeros = bessel_zeros(order, 40, "mcmahon")
    errors = [ulp_error(z, references[order][k]) for k, z in enumerate(zeros)]
    # Truncation: the asymptotic expansion is off by many ulp at s = 1 ...
    assert abs(errors[0]) > 1e6
    # ... and correctly rounded from s = 16 on (measured: the first >0.5 ulp is at s <= 15).
    assert max(abs(e) for e in errors[15:]) <= 0.5


@pytest.mark.parametrize("order", [1, 2])
def test_series_method_in_its_range(references, order):
    zeros = bessel_zeros(order, 6, "series")
    for k, z in enumerate(zeros):
        assert abs(z - float(references[order][k])) < 1e-8


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("z", [0.5, 3.0, 8.0, 12.0])
def test_lecornu_series_is_bessel(order, z):
    x = z * z / 4
    s = float(lecornu_series(order, x))
    value = s * 2 / z if order == 1 else s * x  # (10): φ = √x J1(2√x); (13): J2(2√x)/x
    # Rounding error of an alternating sum: a few ε times the sum of |terms| = I_ν(z).
    bound = 4 * np.finfo(float).eps * float(mpmath.besseli(order, z))
    assert abs(value - float(mpmath.besselj(order, z))) <= bound


@pytest.mark.parametrize(
    ("order", "count", "method"),
    [
        (0, 5, "auto"),
        (3, 5, "auto"),
        (True, 5, "auto"),
        (1, 0, "auto"),
        (1, -3, "auto"),
        (1, MAX_COUNT + 1, "auto"),
        (1, 2.5, "auto"),
        (2, 5, "newton"),
        (2, 50_000, "mpmath"),
        (2, 8, "series"),
    ],
)
def test_bad_input(order, count, method):
    with pytest.raises(PendcliError, match=r"range|one of|unknown|must be|expected"):
        bessel_zeros(order, count, method)


def test_series_refusal_names_the_limit():
    limit = series_safe_limit(2)
    with pytest.raises(PendcliError, match=r"count: 7 .*; expected 1 <= count <= 6"):
        bessel_zeros(2, 7, "series")
    assert 22.0 < limit < 24.0
    assert math.isfinite(series_safe_limit(1))


# --- chunks, arbitrary indices, and a numerics module free of any paper -------------------


@pytest.mark.parametrize("method", ["auto", "mcmahon", "mcmahon-newton"])
@pytest.mark.parametrize("order", [1, 2])
def test_chunks_and_indices_are_bit_for_bit_the_whole_array(order, method):
    whole = bessel_zeros(order, 5000, method)
    chunks = list(iter_bessel_zeros(order, 5000, method, chunk=777))
    assert max(len(c) for c in chunks) == 777
    assert np.array_equal(np.concatenate(chunks), whole)
    picks = np.array([4999, 1, 31, 30, 32, 2500])
    assert np.array_equal(bessel_zeros_at(order, picks, method), whole[picks - 1])


def test_zeros_at_large_indices_against_mpmath():
    s = np.array([10**5, 3 * 10**6, 10**8])  # beyond MAX_COUNT too: McMahon holds there
    got = bessel_zeros_at(2, s)
    for k, value in zip(s.tolist(), got.tolist(), strict=True):
        assert value == float(reference_zero(2, k))


def test_zero_indices_are_checked():
    with pytest.raises(PendcliError, match="index must be >= 1, got 0"):
        bessel_zeros_at(1, np.array([0, 3]))
    with pytest.raises(PendcliError, match=r"count must be in \[1, "):
        iter_bessel_zeros(1, 0)  # checked at the call, before any chunk


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("z", [0.5, 3.0, 7.5])
def test_ascending_series_is_bessel(order, z):
    x = z * z / 4
    expected = mpmath.sqrt(x) * mpmath.besselj(1, z) if order == 1 else mpmath.besselj(2, z) / x
    # below z ~ 8 cancellation costs under three digits (series_error_bound)
    assert float(ascending_series(order, x)) == pytest.approx(float(expected), rel=1e-13, abs=1e-13)


def test_numerics_depends_on_no_paper():
    import pathlib

    import pendcli.numerics

    for path in pathlib.Path(pendcli.numerics.__file__).parent.glob("*.py"):
        text = path.read_text(encoding="utf-8")
        assert "from pendcli.papers" not in text and "import pendcli.papers" not in text, path


def test_cli_streams_zeros_exactly_in_the_json_layout():
    import json

    from helpers.cli import invoke

    count = 70_000  # two chunks
    result = invoke("lecornu", "zeros", "--order", "1", "--count", str(count), "-f", "json")
    assert result.code == 0, result.out
    doc = json.loads(result.out)
    assert list(doc) == ["order", "method", "method_reason", "zeros"]
    assert [r["k"] for r in doc["zeros"]] == list(range(1, count + 1))
    assert np.array_equal([r["zero"] for r in doc["zeros"]], bessel_zeros(1, count))  # repr exact
    table = invoke("lecornu", "zeros", "--count", "6000").out.splitlines()
    assert table[:2] == ["Zeros of J_2 (auto)", "   k                   j"]  # plain text, aligned
    assert table[-1] == f"6000  {float(bessel_zeros(2, 6000)[-1])!r:>18}"


def test_mpmath_method_refuses_counts_that_would_run_for_minutes():
    # 20,000 mpmath zeros took 73 s here: refused at once with the valid range, exit 2.
    import time

    from helpers.cli import assert_clean_error, invoke

    from pendcli.numerics.besselzeros import MPMATH_MAX_COUNT

    start = time.process_time()  # CPU, not wall: competing load cannot fail it
    count = str(MPMATH_MAX_COUNT + 1)
    code, _out, err = invoke("lecornu", "zeros", "--method", "mpmath", "--count", count)
    assert time.process_time() - start < 5
    assert_clean_error(code, err)
    assert f"count <= {MPMATH_MAX_COUNT}" in err
