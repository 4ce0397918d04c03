"""Which printing a citation of a doubled label means.

A text may print one equation label twice (Lecornu prints (18)-(22) in § I and again in
§ II). A citation of such a label in the prose (« la formule (18) ») is ambiguous until the
reader says which printing it means. The reading record (``tables/papers/<paper>.reading.toml``)
says it in ``[[citation]]`` entries: ``label`` (as printed, ``"(18)"``), ``line`` (the line
of the prose that cites it: every citation of the label on that line) and ``printing`` (the
line where the meant formula is printed, one of the label's printings), with ``why``, one
line saying what in the sentence decides it. :func:`parse_citations` validates them against
the text; :func:`unsaid_citations` lists the citations of a doubled label no entry covers;
:func:`reading_path` is the record's file.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pendcli.base.errors import PendcliError

__all__ = [
    "CITATION_KEYS",
    "Citation",
    "parse_citations",
    "prose_citations",
    "reading_path",
    "unsaid_citations",
]

CITATION_KEYS = ("label", "line", "printing", "why")
MAX_WHY = 300
_DISPLAY = re.compile(r"\$\$.*?\$\$", re.DOTALL)


@dataclass(frozen=True)
class Citation:
    """The citations of ``label`` on ``line`` mean the formula printed on ``printing``."""

    label: str
    line: int
    printing: int
    why: str


def prose_citations(
    text: str, labels: Mapping[str, tuple[int, ...]]
) -> tuple[tuple[str, int], ...]:
    """(label, line) of every citation in the prose (outside ``$$ … $$``) of a label of
    ``labels`` (each with the lines of its printings), once per line, in the text's order."""
    prose = _DISPLAY.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    found: list[tuple[str, int]] = []
    for number, line in enumerate(prose.split("\n"), 1):
        for label in labels:
            if label in line and (label, number) not in found:
                found.append((label, number))
    return tuple(sorted(found, key=lambda c: (c[1], c[0])))


def parse_citations(
    where: str, entries: object, text: str, twice: Mapping[str, tuple[int, ...]]
) -> tuple[Citation, ...]:
    """Validate the ``[[citation]]`` entries of a reading record against the text and the
    labels it prints more than once (``twice``): one line naming the file per problem."""
    if entries is None:
        return ()
    if not isinstance(entries, list):
        raise PendcliError(f"{where}: 'citation' must be an array of tables ([[citation]])")
    cited = set(prose_citations(text, twice))
    citations: list[Citation] = []
    for index, entry in enumerate(entries):
        citation = _citation(f"{where}: [[citation]] #{index + 1}", entry, twice, cited)
        if any((c.label, c.line) == (citation.label, citation.line) for c in citations):
            raise PendcliError(
                f"{where}: the citation of {citation.label} on line {citation.line} is listed twice"
            )
        citations.append(citation)
    return tuple(citations)


def _citation(
    where: str, entry: Any, twice: Mapping[str, tuple[int, ...]], cited: set[tuple[str, int]]
) -> Citation:
    if not isinstance(entry, dict):
        raise PendcliError(f"{where} is not a table")
    unknown = sorted(set(entry) - set(CITATION_KEYS))
    if unknown or set(entry) != set(CITATION_KEYS):
        raise PendcliError(
            f"{where}: keys must be exactly {', '.join(CITATION_KEYS)}"
            + (f" (unknown: {', '.join(map(repr, unknown))})" if unknown else "")
        )
    label, line, printing, why = (entry[k] for k in CITATION_KEYS)
    if not isinstance(label, str) or label not in twice:
        raise PendcliError(f"{where}: label {label!r} is not one the text prints twice")
    if type(line) is not int or (label, line) not in cited:
        raise PendcliError(f"{where}: line {line!r} cites no {label} in the prose")
    if type(printing) is not int or printing not in twice[label]:
        raise PendcliError(
            f"{where}: printing {printing!r} is not a line printing {label} "
            f"({', '.join(map(str, twice[label]))})"
        )
    if not isinstance(why, str) or not why.strip() or "\n" in why or len(why) > MAX_WHY:
        raise PendcliError(f"{where}: 'why' must be one line of at most {MAX_WHY} characters")
    return Citation(label, line, printing, why)


def unsaid_citations(
    text: str, twice: Mapping[str, tuple[int, ...]], citations: tuple[Citation, ...]
) -> tuple[tuple[str, int], ...]:
    """The (label, line) citations of a doubled label that no ``[[citation]]`` says."""
    said = {(c.label, c.line) for c in citations}
    return tuple(c for c in prose_citations(text, twice) if c not in said)


def reading_path(paper: str, root: Path | None = None) -> Path:
    from pendcli.data.tables import tables_dir

    return (root or tables_dir()) / "papers" / f"{paper}.reading.toml"
