"""pendcli's Python API: the functions ``import pendcli`` offers (see :data:`pendcli.__all__`).

Each is a thin, documented entry to the library the CLI uses; nothing here computes on its
own. The heavy libraries (scipy, mpmath, sympy, matplotlib) load only when a function needs
them, so ``import pendcli`` stays cheap.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    import numpy as np

    from pendcli.run.regression import Drift
    from pendcli.run.reproduce import ReproduceResult

__all__ = [
    "ExactIntegral",
    "bessel_zeros",
    "check",
    "integral_pi",
    "integral_pi_exact",
    "period",
    "period_ratio",
    "reproduce",
]


class ExactIntegral(NamedTuple):
    """I_n(π) = ``rational`` · π ** ``pi_power`` exactly; ``pi_power`` is 0 (even n) or 1 (odd n).

    >>> integral_pi_exact(4)  # ∫₀^π sin⁵ = 16/15
    ExactIntegral(rational=Fraction(16, 15), pi_power=0)
    >>> integral_pi_exact(3)  # ∫₀^π sin⁴ = 3π/8
    ExactIntegral(rational=Fraction(3, 8), pi_power=1)
    """

    rational: Fraction
    pi_power: int

    def value(self) -> float:
        """The float nearest to ``rational · π**pi_power`` (to a rounding of the product)."""
        import math

        return float(self.rational) * (math.pi if self.pi_power else 1.0)


def integral_pi(n: int) -> float:
    """Charbonnier's I_n(π) = ∫₀^π sin^(n+1)(t) dt = B(½, (n+2)/2) (his no. 15), correctly
    rounded (the double nearest the exact value).

    ``n`` is an integer, -1 <= n <= 10**15 (I_-1(π) = π). Out of range: :class:`PendcliError`.

    >>> integral_pi(1)  # ∫ sin² = π/2
    1.5707963267948966
    """
    from pendcli.papers.charbonnier.wallis import integral_pi as wallis_integral_pi

    return wallis_integral_pi(n)


def integral_pi_exact(n: int) -> ExactIntegral:
    """I_n(π) exactly, by Charbonnier's recurrence I_n = n/(n+1) · I_(n-2): a rational times
    π to the power 0 (even n) or 1 (odd n); see :class:`ExactIntegral`. ``n`` up to the
    limit of exact evaluation (a :class:`PendcliError` names it)."""
    from pendcli.papers.charbonnier.model import integral_pi_exact as exact

    rational, pi_power = exact(n)
    return ExactIntegral(rational, pi_power)


def bessel_zeros(order: int, count: int, method: str = "auto") -> np.ndarray:
    """The first ``count`` positive zeros of the Bessel function J_order (order 1 or 2; the
    zeros Lecornu tabulates), as a float64 array.

    ``method``: ``auto`` (mpmath for the first zeros, McMahon's expansion beyond, both to
    full float accuracy), ``scipy``, ``mcmahon``, ``mcmahon-newton``, ``mpmath`` or
    ``series``. A bad order, count or method: :class:`PendcliError`.
    """
    from pendcli.numerics.besselzeros import bessel_zeros as zeros

    return zeros(order, count, method)


def period_ratio(amplitude: float, method: str = "agm") -> float:
    """T/T0 of the planar pendulum released at rest from ``amplitude`` degrees (0 <= θ0 < 180):
    (2/π) K(sin²(θ0/2)), with T0 = 2π√(l/g) the small-swing period. ``method``: ``agm``
    (default), ``ellipk``, ``ellipkm1``, ``quad`` or ``series``. An array gives an array."""
    from pendcli.numerics.planar import period_ratio as ratio

    return ratio(amplitude, method)


def period(amplitude: float, length: float = 1.0, g: float | None = None) -> float:
    """The exact period in seconds of a pendulum of ``length`` metres released from
    ``amplitude`` degrees; ``g`` in m/s² (default: the standard 9.80665)."""
    from pendcli.numerics.planar import G_STANDARD
    from pendcli.numerics.planar import period as exact_period

    return exact_period(amplitude, length, G_STANDARD if g is None else g)


def reproduce(
    paper: str | None = None, formulas: bool = True, equations: bool = False
) -> ReproduceResult:
    """Recompute every printed number of ``paper`` (default: all three) and judge it.

    Returns a :class:`pendcli.run.reproduce.ReproduceResult`: ``.claims[paper]`` is a list of
    typed claim rows (published string, recomputed value, verdict, cause, source...),
    ``.formulas[paper]`` the derived-formula checks (with ``formulas``), ``.equations[paper]``
    the equation ledger (with ``equations``, about 10 s); ``.document()`` is what
    ``pendcli reproduce --format json`` prints. Runs in this process (no fork), silently.
    """
    from pendcli.papers.registry import resolve_papers
    from pendcli.run.reproduce import reproduce_all

    keys = resolve_papers(paper)
    return reproduce_all(keys, formulas=formulas, equations=equations, quiet=True, jobs=1)


def check(tables: str | Path | None = None) -> list[Drift]:
    """Regenerate every table and compare it with the committed ones in
    ``tables/regenerated`` (or ``<tables>/regenerated``): the list of drifts beyond the
    tolerances (:data:`pendcli.run.regression.TOLERANCES`), empty when everything holds."""
    from pendcli.data.tables import tables_dir
    from pendcli.papers.registry import PAPERS
    from pendcli.run.regression import find_drifts, regenerated_tables
    from pendcli.run.reproduce import reproduce_all

    folder = (Path(tables) if tables is not None else tables_dir()).resolve() / "regenerated"
    result = reproduce_all(PAPERS, formulas=True, equations=True, quiet=True, jobs=1)
    return find_drifts(folder, regenerated_tables(result))
