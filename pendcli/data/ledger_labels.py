"""The equation labels a paper's text prints: in display mathematics, at the start of a formula
line, in a ``\\tag`` or in the margin at its end (:func:`labels_in_text`); and the format a
ledger row's ``equation`` must have (:data:`LABEL_FORMAT`); the lines of each printing of a
label (:func:`label_lines`)."""

from __future__ import annotations

import re

__all__ = ["LABEL_FORMAT", "label_lines", "label_offsets", "labels_in_text"]

# An equation label: an arabic number (with an optional letter and primes: (42'), (17a)),
# a roman numeral (I)-(XXXIX), or a single lower-case letter ((p), (q)); an OCR prime may be
# a typewriter quote or a TeX ^{\prime}.
_LABEL = r"(?:\d{1,3}[a-z]?|[IVX]{1,6}|[a-z])(?:'|’|\^\{?\\prime\}?)*"
_LABEL_TOKEN = re.compile(rf"\(({_LABEL})\)")
LABEL_FORMAT = re.compile(rf"^\({_LABEL}\)$")
# Where a label sits in display mathematics: at its start (after $$, a line break \\ or a
# \begin{...}), in a \tag{...}, or at its end after a \quad (a label "in the margin").
_OPENERS = r"(?:\$\$|\\\\|\\begin\{[a-zA-Z*]+\}(?:\{[^}]*\})?)"
_AT_START = re.compile(rf"{_OPENERS}\s*\(({_LABEL})\)(?=\s|\\|\{{|$)")
_TAGGED = re.compile(rf"\\tag\*?\{{\(?({_LABEL})\)?\}}")
_AT_END = re.compile(rf"\\q?quad\s*\(({_LABEL})\)\s*(?:[.,;]\s*)?(?=\$\$|\\\\|\\end\{{)")
_DISPLAY = re.compile(r"\$\$(.*?)\$\$", re.DOTALL)


def _normalise(label: str) -> str:
    return re.sub(r"’|\^\{?\\prime\}?", "'", label)


def labels_in_text(text: str) -> list[str]:
    """Every equation label the text prints, as ``"(41)"``, in order, repeats kept.

    Only labels placed in display mathematics count (at the start of a formula line, in a
    ``\\tag``, or in the margin at its end): a reference in the prose ("la formule (5)"), a
    year, a page number or a citation is never a label.
    """
    return [label for _, label in label_offsets(text)]


def label_offsets(text: str) -> list[tuple[int, str]]:
    """(character offset, label) of every label :func:`labels_in_text` finds, in order."""
    found: list[tuple[int, str]] = []
    for display in _DISPLAY.finditer(text):
        body = "$$" + display.group(1) + "$$"
        offset = display.start()
        for pattern in (_AT_START, _TAGGED, _AT_END):
            for match in pattern.finditer(body):
                found.append((offset + match.start(1), f"({_normalise(match.group(1))})"))
    return sorted(set(found))


def label_lines(text: str) -> dict[str, tuple[int, ...]]:
    """Each equation label the text prints (``labels_in_text``), with the line of each
    printing, in the order of first printing."""
    found: dict[str, list[int]] = {}
    for offset, label in label_offsets(text):
        found.setdefault(label, []).append(text.count("\n", 0, offset) + 1)
    return {label: tuple(lines) for label, lines in found.items()}
