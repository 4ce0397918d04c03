"""What `pendcli charbonnier table` and `pendcli charbonnier integral` show, as rows."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

from pendcli.base.errors import out_of_range
from pendcli.data.tables import load_paper_table
from pendcli.papers.charbonnier.model import (
    exact_text,
    integral,
    integral_method,
    integral_pi_array,
    integral_pi_exact,
    integral_pi_sequence,
    integral_recurrence_sequence,
    printed_closed_form_sequence,
)

__all__ = ["TABLE_N_MAX", "integral_row", "table_rows"]

TABLE_N_MAX = 10_000  # the exact rationals of the table grow like n digits: keep it quick


def table_rows(n_max: int = 5) -> list[dict[str, Any]]:
    """n = -1..n_max: printed (n <= 5), the printed closed form, the recurrence, the beta form.

    Linear in the number of rows: the exact rationals, the printed products and the floating
    recurrence each carry their state from one row to the next (one step per row), and the
    beta form is evaluated for all n at once.
    """
    if isinstance(n_max, bool) or not isinstance(n_max, int) or not -1 <= n_max <= TABLE_N_MAX:
        raise out_of_range("n_max", n_max, f"-1 <= n_max <= {TABLE_N_MAX}")
    import numpy as np

    printed = {c.id: c for c in load_paper_table("charbonnier").claims}
    recurrence = integral_recurrence_sequence(n_max, math.pi)
    beta = integral_pi_array(np.arange(-1, n_max + 1)).tolist()
    rows = []
    exact = integral_pi_sequence(n_max)
    closed = printed_closed_form_sequence(n_max)
    for (n, q, p), (_, num, den, closed_p) in zip(exact, closed, strict=True):
        entry = printed.get(f"charbonnier.I_pi.n{n}")
        rows.append(
            {
                "n": n,
                "published": entry.published if entry else "",
                "exact": exact_text(q, p),
                "closed_form_matches_recurrence": closed_p == p and _same_ratio(num, den, q),
                "recurrence_float": recurrence[n + 1],
                "beta": beta[n + 1],
            }
        )
    return rows


def _odd_part(k: int) -> tuple[int, int]:
    """(k without its factors 2, how many there were), k > 0."""
    twos = (k & -k).bit_length() - 1
    return k >> twos, twos


def _same_ratio(num: int, den: int, q: Fraction) -> bool:
    """num/den == q exactly, the unreduced products never divided: num·q.den == den·q.num.

    Powers of two compared apart: one side's odd part is then 1 (Wallis' rationals have a
    power of two above or below), which halves the big multiplications of a long table.
    """
    (a, i), (b, j) = _odd_part(num), _odd_part(q.denominator)
    (c, k), (d, m) = _odd_part(den), _odd_part(q.numerator)
    return i + j == k + m and a * b == c * d


def integral_row(
    n: int, x: float, tol: float | None = None, method: str | None = None
) -> dict[str, Any]:
    """I_n(x) with the method used; the exact rational too at x = π (n <= 10000).

    ``tol`` or ``method`` pick a method of the speed/accuracy tables (:mod:`.speed`);
    otherwise :func:`.model.integral` is used.  A method known to have lost digits at (n, x)
    adds a ``warning``.
    """
    if method is not None or tol is not None:
        from pendcli.papers.charbonnier.speed import integral_with_choice_checked

        value, label, warning = integral_with_choice_checked(n, x, tol=tol, method=method)
    else:
        value, label, warning = integral(n, x), integral_method(n, x), None
    row: dict[str, Any] = {"n": n, "x": x, "value": value, "method": label}
    if warning is not None:
        row["warning"] = warning
    if x == math.pi and -1 <= n <= TABLE_N_MAX:  # beyond, Python refuses to print such integers
        q, p = integral_pi_exact(n)
        row["exact"] = exact_text(q, p)
    return row
