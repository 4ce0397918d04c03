"""The status a printed form earns: the engine's verdict on a ledger row.

A printed form that passes holds; one that fails is a ``misprint`` when its reading passes
(judged against the reference the reading cites, if the reference names one), ``fails``
when its correction passes, and earns no status the ledger may record otherwise. Printed
numbers (a :class:`~pendcli.core.printed_numeric.Numbers` reference) are judged by their
printed digits instead (:mod:`pendcli.core.printed_numeric`).
"""

from __future__ import annotations

from pendcli.core.printed import Formula
from pendcli.core.printed_check import Reference, judged
from pendcli.core.printed_numeric import Numbers, numeric_status

__all__ = ["computed_status"]


def computed_status(
    printed: Formula, reading: Formula | None, corrected: Formula | None, reference: Reference
) -> tuple[str | None, str]:
    """The status the printed form earns (None: none the ledger may record) and why."""
    if isinstance(reference, Numbers):  # printed numbers, judged by their printed digits
        return numeric_status(printed, reading, corrected, reference)
    ok, why = judged(printed, reference)
    if ok:
        return "holds", f"the printed form holds: {why}"
    for status, other in (("misprint", reading), ("fails", corrected)):
        if other is not None:
            against = reference.reading if status == "misprint" and reference.reading else reference
            other_ok, other_why = judged(other, against)
            if other_ok:
                return status, f"the printed form fails ({why}); the {status} form holds"
            return None, f"the printed form fails ({why}) and so does its {status} ({other_why})"
    return None, f"the printed form fails ({why}) and the row gives no reading or correction"
