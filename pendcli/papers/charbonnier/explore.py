"""What `pendcli charbonnier table` and `pendcli charbonnier integral` show, as rows."""

from __future__ import annotations

import math
from typing import Any

from pendcli.core.errors import PendcliError
from pendcli.core.tables import load_paper_table
from pendcli.papers.charbonnier.model import (
    MAX_EXACT_N,
    exact_text,
    integral,
    integral_method,
    integral_pi,
    integral_pi_exact,
    integral_recurrence,
    printed_closed_form,
)

__all__ = ["TABLE_N_MAX", "integral_row", "table_rows"]

TABLE_N_MAX = 10_000  # the exact rationals of the table grow like n digits: keep it quick


def table_rows(n_max: int = 5) -> list[dict[str, Any]]:
    """n = -1..n_max: printed (n <= 5), the printed closed form, the recurrence, the beta form."""
    if isinstance(n_max, bool) or not isinstance(n_max, int) or not -1 <= n_max <= TABLE_N_MAX:
        raise PendcliError(f"--n-max = {n_max} is out of range; valid range is -1..{TABLE_N_MAX}")
    printed = {c.id: c for c in load_paper_table("charbonnier").claims}
    rows = []
    for n in range(-1, n_max + 1):
        q, p = integral_pi_exact(n)
        entry = printed.get(f"charbonnier.I_pi.n{n}")
        rows.append(
            {
                "n": n,
                "published": entry.published if entry else "",
                "exact": exact_text(q, p),
                "closed_form_matches_recurrence": printed_closed_form(n) == (q, p),
                "recurrence_float": integral_recurrence(n, math.pi),
                "beta": integral_pi(n),
            }
        )
    return rows


def integral_row(
    n: int, x: float, tol: float | None = None, method: str | None = None
) -> dict[str, Any]:
    """I_n(x) with the method used; the exact rational too at x = π (n <= 100000).

    ``tol`` or ``method`` pick a method of the speed/accuracy tables (:mod:`.speed`);
    otherwise :func:`.model.integral` is used.
    """
    if method is not None or tol is not None:
        from pendcli.papers.charbonnier.speed import integral_with_choice

        value, label = integral_with_choice(n, x, tol=tol, method=method)
    else:
        value, label = integral(n, x), integral_method(n, x)
    row: dict[str, Any] = {"n": n, "x": x, "value": value, "method": label}
    if x == math.pi and -1 <= n <= MAX_EXACT_N:
        q, p = integral_pi_exact(n)
        row["exact"] = exact_text(q, p)
    return row
