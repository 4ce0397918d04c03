"""What the HTML edition reads of a row, and the notes it writes beside a mark.

The accessors here are the only places that know the rows' keys (row dicts, ``as_dict()``
of the rows): :mod:`~pendcli.output.html.locate`, :mod:`~pendcli.output.html.marks`,
:mod:`~pendcli.output.html.paper` and :mod:`~pendcli.output.html.report` read rows through
them, and they know the report's keys, not pendulums.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from pendcli.data.vocabulary import (
    CLAIM_VERDICTS,
    STATUSES,
)

Row = Mapping[str, object]

VERDICT_CLASSES = CLAIM_VERDICTS
STATUS_CLASSES = STATUSES
# The cause of an equation row follows from its status (pendcli.verify.causes' vocabulary).
EQUATION_CAUSE = {"fails": "derivation-error", "misprint": "misprint"}


# --- accessors: the only places that know the rows' keys ------------------------------------


def word_of(value: object) -> str:
    """A verdict, status or cause as its word (an enum's value, or the string)."""
    value = getattr(value, "value", value)
    return "" if value is None else str(value)


def id_of(row: Row) -> str:
    return str(row["id"])


def verdict_of(row: Row) -> str:
    return word_of(row.get("verdict") or row.get("status"))


def text_of(row: Row, key: str) -> str:
    value = row.get(key)
    return "" if value is None else str(value)


def sources_of(row: Row) -> list[str]:
    """The ids a propagated row inherits from (its ``from`` key)."""
    value = row.get("from")
    return [str(s) for s in value] if isinstance(value, list | tuple) else []


def own_of(row: Row) -> str:
    """A claim against the author's procedure on his printed inputs, and his value."""
    from pendcli.data.numbers import edition_number

    verdict, his = word_of(row.get("procedure_verdict")), row.get("procedure_value")
    if not verdict or not isinstance(his, float | int):
        return "no procedure known"
    return f"{verdict}: {text_of(row, 'procedure')} = {edition_number(his, 6)}"


def number_text(value: object) -> str:
    """A recomputed number as the papers write theirs (decimal comma): the edition is French."""
    from pendcli.data.numbers import edition_number

    return edition_number(value)


def disagrees(row: Row) -> bool:
    return verdict_of(row) in ("truncated", "last-digit", "discrepant", "fails", "misprint")


def css_of(row: Row) -> str:
    word = verdict_of(row)
    return f"v-{word}" if word in VERDICT_CLASSES else f"s-{word}"


def lines_of(row: Row) -> tuple[int, int] | None:
    """The row's ``lines = [first, last]`` (1-based lines of the paper's text), if recorded."""
    value = row.get("lines")
    if isinstance(value, list | tuple) and len(value) == 2:
        return int(value[0]), int(value[1])
    return None


def quotes_of(row: Row) -> list[str]:
    """The words of the text the row rests on (its ``quote``: a string or a list)."""
    value = row.get("quote")
    if isinstance(value, str):
        return [value] if value else []
    return [str(v) for v in value] if isinstance(value, list | tuple) else []


_QUOTE = re.compile(r"«\s*(.+?)\s*»")


def quoted_in(text: str) -> list[str]:
    """The words a note quotes between « »."""
    return _QUOTE.findall(text)


def quoted_words(row: Row) -> list[str]:
    """The words the row's source, section and notes quote between « »."""
    keys = ("source", "section", "ocr", "statement", "reading_note", "corrected_note", "note")
    return [q for key in keys for q in quoted_in(text_of(row, key))]


# --- the notes beside a mark ----------------------------------------------------------------


def clauses(text: str, count: int) -> str:
    """The first ``count`` clauses of a note (split at "; "): what fits in the margin."""
    parts = text.split("; ")
    return "; ".join(parts[:count]) + (" …" if len(parts) > count else "")


def printed_terms(row: Row) -> list[str]:
    """The wrong term as the OCR prints it (the ledger's ``wrong_term``), when recorded."""
    value = row.get("wrong_term")
    if isinstance(value, str):
        return [value] if value else []
    return [str(v) for v in value] if isinstance(value, list | tuple) else []


def printed_form(published: str) -> str:
    """A printed number as the paper sets it, not as TeX: ``0^{sec},94`` is 0ˢᵉᶜ,94, and
    ``-1,27`` is −1,27 (the typeset minus of the page)."""
    from pendcli.data.numbers import edition_minus
    from pendcli.data.reader_text import UNIT_FORMS, UNIT_TEX

    return edition_minus(UNIT_TEX.sub(lambda m: UNIT_FORMS[m.group(1)], published))


def claim_note(row: Row) -> str:
    recomputed = number_text(row.get("recomputed"))
    unit = text_of(row, "unit")
    printed = printed_form(text_of(row, "published"))
    text = f"printed {printed}, recomputed {recomputed} {unit}".rstrip()
    cause = word_of(row.get("cause"))
    own = f"; against his procedure, {own_of(row)}" if row.get("procedure_verdict") else ""
    # a verdict that turns on an unstated assumption names each side, as the ledger's rows do
    condition = f"; {text_of(row, 'condition')}" if row.get("condition") else ""
    return f"{text}{own}{condition}; {cause}" if cause and disagrees(row) else text + condition


def equation_note(row: Row) -> str:
    correction = correction_of(row)
    if correction:
        return correction
    readings = text_of(row, "readings")  # the OCR's substitutions the row is read through
    return f"OCR, read: {readings}" if readings else ""


def correction_of(row: Row) -> str:
    """The reading of a misprint or the correction of a failure, once."""
    if text_of(row, "reading"):
        return f"read {text_of(row, 'reading')}"
    if text_of(row, "corrected"):
        return f"corrected: {text_of(row, 'corrected')}"
    return ""
