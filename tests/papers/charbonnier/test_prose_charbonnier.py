"""Charbonnier's prose read as claims (tables/papers/charbonnier.reading.toml): a misprint of
the sentences set to its reading is refused, the misnamed acceleration of line 113 is
dimensionally inconsistent, and each slip found in the sentences is verified a second way,
numerically and without the engine (mpmath, scipy's solve_ivp). The claims that hold are
mutated in tests/papers/charbonnier/test_printed_charbonnier.py (PROSE_CHANGES), with every row that
holds."""

from __future__ import annotations

import mpmath
import pytest
from helpers.ledgers import committed_ledger, committed_row
from helpers.mutations import altered_row

from pendcli.papers.registry import paper
from pendcli.verify.ledger_formulas import row_dimensions
from pendcli.verify.ledger_references import verify_printed

REFERENCES = paper("charbonnier").references()

# (row, old, new): the printed form of a misprint set to its reading
READINGS = [
    ("charbonnier.result.speed-of-m", "printed = 'v_M = ", "printed = 'v_n = "),
    (
        "charbonnier.result.perturbing-acceleration-named",
        "printed = 'epsilon*phi(theta, dtheta_dt, t) = a_arc'",
        "printed = 'epsilon*phi(theta, dtheta_dt, t) = a_arc/l0'",
    ),
    ("charbonnier.result.resistance-opposes", "*l0*d2theta_dt2 < 0'", "*v < 0'"),
    (
        "charbonnier.result.in-pi-table-odd-label",
        "printed = 'I(-1, pi) = pi*1/2; I(-1, pi) = pi*1*3/(2*4)'",
        "printed = 'I(1, pi) = pi*1/2; I(3, pi) = pi*1*3/(2*4)'",
    ),
    (
        "charbonnier.result.in-pi-table-odd-label-498",
        "printed = 'I(-1, pi) = ",
        "printed = 'I(5, pi) = ",
    ),
]


@pytest.mark.parametrize(("row_id", "old", "new"), READINGS)
def test_a_misprint_of_the_prose_set_to_its_reading_is_refused(
    row_id: str, old: str, new: str
) -> None:
    row, symbols = altered_row("charbonnier", row_id, old, new, within=row_id)
    _, problem = verify_printed(row, symbols, REFERENCES)
    assert problem is not None
    assert problem.startswith("recorded misprint, but the printed form gives holds")


def test_the_perturbing_acceleration_named_has_the_wrong_dimension() -> None:
    """Line 113: εφ (T^-2) called an acceleration along the arc (L T^-2): the printed form is
    dimensionally inconsistent, its reading εφ = a_arc/l0 consistent."""
    row = committed_row("charbonnier.result.perturbing-acceleration-named")
    checks = row_dimensions(row, committed_ledger("charbonnier").symbols_for(row))
    assert checks["printed"].verdict == "inconsistent"
    assert "T^-2" in checks["printed"].detail
    assert checks["reading_formula"].verdict == "consistent"


# --- the slips of the sentences, verified numerically, without the engine ------------------


def test_the_speed_of_m_is_not_l_dtheta_dt_when_the_length_varies() -> None:
    """Line 54: M at (l sin θ, −l cos θ) with l = 1 + 0.3t, θ = 0.4 sin 1.7t (mpmath's
    numerical derivative at t = 0.6): the speed differs from l θ' by far more than the
    differentiation's error, while the moment x y' − y x' is l²θ' and the velocity's part
    normal to the thread is l θ'."""
    with mpmath.workdps(30):
        t0 = mpmath.mpf("0.6")
        ell = lambda t: 1 + mpmath.mpf("0.3") * t  # noqa: E731
        angle = lambda t: mpmath.mpf("0.4") * mpmath.sin(mpmath.mpf("1.7") * t)  # noqa: E731
        x = lambda t: ell(t) * mpmath.sin(angle(t))  # noqa: E731
        y = lambda t: -ell(t) * mpmath.cos(angle(t))  # noqa: E731
        dx, dy = mpmath.diff(x, t0), mpmath.diff(y, t0)
        transverse = ell(t0) * mpmath.diff(angle, t0)
        speed = mpmath.sqrt(dx**2 + dy**2)
        moment = x(t0) * dy - y(t0) * dx
        normal = dx * mpmath.cos(angle(t0)) + dy * mpmath.sin(angle(t0))
        assert abs(speed - transverse) > mpmath.mpf("0.01")
        assert abs(moment - ell(t0) * transverse) < mpmath.mpf(10) ** -20
        assert abs(normal - transverse) < mpmath.mpf(10) ** -20


def test_an_acceleration_along_the_arc_enters_theta_divided_by_the_length() -> None:
    """Line 113: a constant force of acceleration a = 0.05 m/s² along the arc of a pendulum of
    length l0 = 2 m (Newton along the tangent, s'' = −g sin(s/l0) − a, s = l0θ, solve_ivp)
    moves θ as θ'' + (g/l0) sin θ + εφ = 0 with εφ = a/l0, not with εφ = a (the name of line
    113), which gives θ off by more than a hundred times the integration's error at t = 1.5 s."""
    g, l0, a = 9.81, 2.0, 0.05
    angle_of_arc = _swing_from(l0 * -0.1, g, l0, a) / l0
    as_read = _angle(g, l0, a / l0)
    as_named = _angle(g, l0, a)
    assert abs(as_read - angle_of_arc) < 1e-9
    assert abs(as_named - angle_of_arc) > 1e-3


def _swing_from(s0: float, g: float, l0: float, a: float) -> float:
    """s at t = 1.5 s of s'' = −g sin(s/l0) − a from rest at s0."""
    import math

    from scipy.integrate import solve_ivp

    run = solve_ivp(
        lambda _t, y: [y[1], -g * math.sin(y[0] / l0) - a],
        (0.0, 1.5),
        [s0, 0.0],
        rtol=1e-12,
        atol=1e-14,
    )
    return float(run.y[0][-1])


def _angle(g: float, l0: float, eps_phi: float) -> float:
    """θ at t = 1.5 s of θ'' + (g/l0) sin θ + εφ = 0 from rest at θ = −0.1."""
    import math

    from scipy.integrate import solve_ivp

    run = solve_ivp(
        lambda _t, y: [y[1], -g / l0 * math.sin(y[0]) - eps_phi],
        (0.0, 1.5),
        [-0.1, 0.0],
        rtol=1e-12,
        atol=1e-14,
    )
    return float(run.y[0][-1])


def test_the_resistance_opposes_the_speed_not_the_acceleration() -> None:
    """Line 309: θ'' + k²θ + (c/l0)F(l0θ') = 0, F(v) = 0.1 + v², integrated (solve_ivp) over the
    first simple oscillation from −α to the next rest: the resistance's acceleration −cF(v)
    along the arc has the sign opposite to the speed at every step, but the sign of l0θ'' on a
    large part of the swing after the lowest point (M slowing down)."""
    import numpy as np
    from scipy.integrate import solve_ivp

    k, alpha, l0, c = 1.0, 0.3, 1.0, 0.01
    force = lambda v: 0.1 + v * v  # noqa: E731

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        return [y[1], -(k**2) * y[0] - c / l0 * force(l0 * y[1])]

    rest = lambda _t, y: y[1]  # noqa: E731
    rest.terminal, rest.direction = True, -1  # type: ignore[attr-defined]
    run = solve_ivp(rhs, (0, 10), [-alpha, 0.0], rtol=1e-11, atol=1e-13, events=rest,
                    dense_output=True)  # fmt: skip
    end = float(run.t_events[0][0])
    times = np.linspace(0.01 * end, 0.99 * end, 400)
    states = run.sol(times)
    speeds = l0 * states[1]
    resistance = -c * force(speeds)
    arc_accel = l0 * np.array([rhs(0.0, s)[1] for s in states.T])
    assert np.all(resistance * speeds < 0)
    same_sense = resistance * arc_accel > 0
    assert same_sense.mean() > 0.3
    assert np.all(same_sense[times > 0.6 * end])


def test_the_odd_row_of_the_table_is_i_n_not_i_minus_1() -> None:
    """Lines 495, 498: the values π·1/2, π·1·3/(2·4), π·1·3·5/(2·4·6) are ∫₀^π sinⁿ⁺¹x dx for
    n = 1, 3, 5 (mpmath quadrature), while I_(−1)(π) = ∫₀^π dx = π is none of them."""
    with mpmath.workdps(30):
        pi = mpmath.pi
        values = (pi / 2, pi * 3 / 8, pi * 15 / 48)
        i_minus_1 = mpmath.quad(lambda x: 1, [0, pi])
        for n, value in zip((1, 3, 5), values, strict=True):
            i_n = mpmath.quad(lambda x, m=n: mpmath.sin(x) ** (m + 1), [0, pi])
            assert abs(i_n - value) < mpmath.mpf(10) ** -25
            assert abs(i_minus_1 - value) > mpmath.mpf("0.5")
