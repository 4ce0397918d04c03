"""The status a printed form earns: the engine's verdict on a ledger row.

A printed form that passes holds; one that fails is a ``misprint`` when its reading passes
(judged against the reference the reading cites, if the reference names one), ``fails``
when its correction passes, and earns no status the ledger may record otherwise. Printed
numbers (a :class:`~pendcli.verify.printed_numeric.Numbers` reference) are judged by their
printed digits instead (:mod:`pendcli.verify.printed_numeric`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from pendcli.data.printed import Formula
from pendcli.verify.derived import Derived, passes
from pendcli.verify.printed_check import Reference, derive, judged
from pendcli.verify.printed_numeric import Numbers, numeric_status

__all__ = ["FORMS", "computed_status", "derived_forms", "status_of", "stored_status"]

# the forms of a row the engine judges, in the order it judges them
FORMS = ("printed", "reading", "corrected")

# form -> (passes, why), or None when the row has no such form
Judge = Callable[[str], "tuple[bool, str] | None"]


def computed_status(
    printed: Formula, reading: Formula | None, corrected: Formula | None, reference: Reference
) -> tuple[str | None, str]:
    """The status the printed form earns (None: none the ledger may record) and why."""
    if isinstance(reference, Numbers):  # printed numbers, judged by their printed digits
        return numeric_status(printed, reading, corrected, reference)
    formulas = dict(zip(FORMS, (printed, reading, corrected), strict=True))

    def judge(form: str) -> tuple[bool, str] | None:
        formula = formulas[form]
        return None if formula is None else judged(formula, _against(form, reference))

    return status_of(judge)


def derived_forms(
    printed: Formula, reading: Formula | None, corrected: Formula | None, reference: Reference
) -> dict[str, Derived]:
    """Each form of the row derived against its reference: what the store keeps."""
    formulas = dict(zip(FORMS, (printed, reading, corrected), strict=True))
    return {f: derive(x, _against(f, reference)) for f, x in formulas.items() if x is not None}


def stored_status(forms: Mapping[str, Derived]) -> tuple[str | None, str]:
    """The status from the stored derivations of a row's forms (verify/derivation_store)."""
    return status_of(lambda form: passes(forms[form]) if form in forms else None)


def _against(form: str, reference: Reference) -> Reference:
    # the reading is judged against the equation the text should have cited, if it names one
    return reference.reading if form == "reading" and reference.reading else reference


def status_of(judge: Judge) -> tuple[str | None, str]:
    """The rule: ``holds`` when the printed form passes; else ``misprint`` when its reading
    passes, ``fails`` when its correction does; else no status the ledger may record."""
    ok, why = judge("printed") or (False, "no printed form")
    if ok:
        return "holds", f"the printed form holds: {why}"
    for status, form in (("misprint", "reading"), ("fails", "corrected")):
        other = judge(form)
        if other is not None:
            other_ok, other_why = other
            if other_ok:
                return status, f"the printed form fails ({why}); the {status} form holds"
            return None, f"the printed form fails ({why}) and so does its {status} ({other_why})"
    return None, f"the printed form fails ({why}) and the row gives no reading or correction"
