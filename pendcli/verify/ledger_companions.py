"""The companions of a corrected or read formula: what else in the text depends on it.

When a row's reading or correction changes a formula (a ``misprint`` or ``fails`` row that
restates no other, or a row an OCR reading of ``[[reading]]`` changes), every later row and
sentence that depends on it must be judged against the changed form, not left as printed.
A *companion* of such a *source* row is found two ways:

* **it cites the source's label**: a later row whose lines, or a sentence of prose outside
  every row's lines, cite the label (« la formule (13) »); a citation of a label the text
  prints twice counts only where the reading record's ``[[citation]]`` says it means the
  source's printing (:mod:`pendcli.data.reading_citations`);
* **it shares a symbol the source introduces**: a name of the ledger's symbols that no
  earlier row's formulas use and the source's printed form defines (``name = …``), used by a
  later row's formulas before a later row defines it again.

Each companion is *judged* one way, in this order: ``restates`` or ``carries`` (its own row
names the source: ``restates``, ``carries``, ``step_from``), ``used_at`` (the source's later
use, ``used_at``, falls on its lines: the slip carried in a ``fails`` row, the right form
taken in a ``misprint`` one), ``checked`` (its status is computed against its reference, the
model, so a companion that took the wrong form would not hold; but a flawed companion whose
own wrong term is the source's has written the wrong form again, which the blame rule calls
carried, so its computed status alone does not judge it), ``independent`` (the ledger's
``[[companion]]`` table says why it does not depend on the slip) or else ``left as printed``:
an unexamined companion, which ``tests/verify/test_ledger_companions.py`` refuses.

``[[companion]]`` entries of ``tables/equations/<paper>.toml``: ``of`` (the source row's id),
``row`` (the companion's id) or ``line`` (the line of a sentence citing the source), and
``why`` (one line); exactly these keys, each naming a companion the rule above finds.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError
from pendcli.data.vocabulary import CHECKED_STATUSES, EquationStatus

if TYPE_CHECKING:
    from pendcli.data.ledger_rows import Ledger, LedgerRow

__all__ = [
    "COMPANION_KEYS",
    "Companion",
    "companions_of",
    "ledger_companions",
    "parse_companions",
    "unexamined",
]

COMPANION_KEYS = ("of", "row", "line", "why")
MAX_WHY = 300
LEFT = "left as printed"
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_FORMULAS = ("printed", "reading_formula", "corrected_formula")
_FLAWED = (EquationStatus.MISPRINT, EquationStatus.FAILS)


@dataclass(frozen=True)
class Companion:
    """A row (``row``) or a sentence (``row`` None, at ``line``) depending on ``source``."""

    source: str
    row: str | None
    line: int
    link: str  # "cites (13)", "shares theta_pi2"
    judged: str  # restates, carries, used_at, checked, independent, left as printed
    why: str

    def shown(self) -> str:
        where = self.row or f"the sentence of line {self.line}"
        return f"{where} ({self.link}): {self.judged}: {self.why}"


@dataclass(frozen=True)
class Independent:
    """A ``[[companion]]`` entry: ``of``'s companion (a row, or a sentence's line) does not
    depend on its slip, for the reason ``why``."""

    of: str
    row: str | None
    line: int | None
    why: str


def _is_source(row: LedgerRow) -> bool:
    flawed = row.status in _FLAWED
    return (flawed and not row.restated) or bool(row.readings and row.equation)


def _names(row: LedgerRow, symbols: Mapping[str, str]) -> set[str]:
    found: set[str] = set()
    for name in _FORMULAS:
        text = row.read(name)
        if text:
            found |= set(_NAME.findall(text)) & set(symbols)
    return found


def _defined(row: LedgerRow, symbols: Mapping[str, str]) -> set[str]:
    """The names the row's printed form defines: the bare left side of an equation."""
    out = set()
    for part in (row.printed or "").split(";"):
        if "=" in part and not any(sign in part for sign in "<>"):
            left = part.split("=", 1)[0].strip()
            if left in symbols:
                out.add(left)
    return out


@dataclass(frozen=True)
class _Names:
    """Per row id: the ledger's names its formulas use, and those its printed form defines."""

    used: Mapping[str, set[str]]
    defined: Mapping[str, set[str]]


def _index(ledger: Ledger) -> _Names:
    used = {r.id: _names(r, ledger.symbols_for(r)) for r in ledger.rows}
    return _Names(used, {r.id: _defined(r, ledger.symbols_for(r)) for r in ledger.rows})


def _introduced(source: LedgerRow, ledger: Ledger, names: _Names) -> set[str]:
    """The names ``source`` defines that no row printed before it uses."""
    assert source.lines is not None
    earlier: set[str] = set()
    for row in ledger.rows:
        if row.lines is not None and row.lines[0] < source.lines[0]:
            earlier |= names.used[row.id]
    return names.defined[source.id] - earlier


def _cited_lines(source: LedgerRow, citations: Iterable[tuple[str, int, int | None]]) -> list[int]:
    """The lines after ``source`` citing its label (a doubled label: where it means it)."""
    assert source.lines is not None
    return [
        line
        for label, line, printing in citations
        if label == source.equation
        and line > source.lines[1]
        and (printing is None or source.lines[0] <= printing <= source.lines[1])
    ]


def _links(
    source: LedgerRow, ledger: Ledger, cited: list[int], names: _Names, text: list[str]
) -> list[tuple[LedgerRow, str]]:
    """Each later row depending on ``source``, with how: it cites the label, prints the
    source's wrong term again, or shares a name the source introduces (until a later row
    defines that name again)."""
    assert source.lines is not None
    live = _introduced(source, ledger, names)
    later = sorted(
        (r for r in ledger.rows if r.lines is not None and r.lines[0] > source.lines[1]),
        key=lambda r: r.lines or (0, 0),
    )
    found = []
    for row in later:
        assert row.lines is not None
        how = []
        if any(row.lines[0] <= line <= row.lines[1] for line in cited):
            how.append(f"cites {source.equation}")
        words = "\n".join(text[row.lines[0] - 1 : row.lines[1]])
        if any(term in words for term in source.wrong_terms):
            how.append("prints its wrong term")
        shared = live & names.used[row.id]
        if shared:
            how.append(f"shares {', '.join(sorted(shared))}")
        if how:
            found.append((row, "; ".join(how)))
        live = live - names.defined[row.id]
    return found


def _judged(source: LedgerRow, row: LedgerRow) -> tuple[str, str] | None:
    """How ``row`` was judged against ``source``'s changed form by its own record, or None."""
    assert row.lines is not None
    if source.id in row.restated:
        return "restates", f"{row.id} restates {source.id}: its status, {row.status.value}"
    if source.id in (row.carries, row.step_from):
        return "carries", f"{row.id} carries {source.id}'s printed form ({row.status.value})"
    if row.status in _FLAWED and set(row.wrong_terms) & set(source.wrong_terms):
        return None  # the source's wrong form written again: carried, unless said otherwise
    used = [n for n in source.used_at or () if row.lines[0] <= n <= row.lines[1]]
    what = "the slip carried" if source.status is EquationStatus.FAILS else "the form taken"
    later = f"{source.id}'s later use at line {used[0]}: {what}" if used else ""
    if row.status in CHECKED_STATUSES:
        checked = f"{row.status.value} against {row.reference}, the model, not the print"
        return "checked", f"{checked}; on its lines, {later}" if later else checked
    return ("used_at", later) if later else None


def companions_of(
    ledger: Ledger,
    citations: Iterable[tuple[str, int, int | None]],
    covered: Iterable[tuple[int, int]],
    text: list[str],
    independent: Iterable[Independent] = (),
) -> dict[str, tuple[Companion, ...]]:
    """Every source row of ``ledger`` with its companions judged. ``citations``: (label,
    prose line, the printing meant or None) of each citation in the text; ``covered``: the
    rows' line spans (a citation outside them is a sentence of its own); ``text``: the
    text's lines."""
    citations, covered = list(citations), list(covered)
    said = {(i.of, i.row, i.line): i.why for i in independent}
    names = _index(ledger)
    out: dict[str, tuple[Companion, ...]] = {}
    for source in ledger.rows:
        if source.lines is None or not _is_source(source):
            continue
        cited = _cited_lines(source, citations) if source.equation else []
        found = []
        for row, link in _links(source, ledger, cited, names, text):
            assert row.lines is not None
            judged = _judged(source, row) or _said(said, source.id, row.id, None)
            found.append(Companion(source.id, row.id, row.lines[0], link, *judged))
        for line in cited:
            if any(a <= line <= b for a, b in covered):
                continue
            used = ("used_at", f"{source.id}'s later use")
            take = used if line in (source.used_at or ()) else _said(said, source.id, None, line)
            found.append(Companion(source.id, None, line, f"cites {source.equation}", *take))
        out[source.id] = tuple(found)
    return out


def _said(said: Mapping[tuple[str, str | None, int | None], str], *key: Any) -> tuple[str, str]:
    why = said.get(key)
    if why is not None:
        return "independent", why
    return LEFT, "no record judges it against the changed form"


def unexamined(found: Mapping[str, tuple[Companion, ...]]) -> list[Companion]:
    """The companions left as printed."""
    return [c for items in found.values() for c in items if c.judged == LEFT]


def parse_companions(where: str, entries: object) -> tuple[Independent, ...]:
    """The ``[[companion]]`` entries of a ledger, shape only (their match with the companions
    found: :func:`ledger_companions`); one line naming the file per problem."""
    if entries is None:
        return ()
    if not isinstance(entries, list):
        raise PendcliError(f"{where}: 'companion' must be an array of tables ([[companion]])")
    out = []
    for index, entry in enumerate(entries):
        at = f"{where}: [[companion]] #{index + 1}"
        if not isinstance(entry, dict):
            raise PendcliError(f"{at} is not a table")
        unknown = sorted(set(entry) - set(COMPANION_KEYS))
        if unknown:
            raise PendcliError(
                f"{at}: unknown key(s) {', '.join(map(repr, unknown))}; "
                f"valid: {', '.join(COMPANION_KEYS)}"
            )
        of, row, line, why = (entry.get(k) for k in COMPANION_KEYS)
        if not isinstance(of, str) or (row is None) == (line is None):
            raise PendcliError(f"{at}: give 'of' (a row id) and one of 'row' or 'line'")
        if (row is not None and not isinstance(row, str)) or (
            line is not None and type(line) is not int
        ):
            raise PendcliError(f"{at}: 'row' is a row id, 'line' a line number")
        if not isinstance(why, str) or not why.strip() or "\n" in why or len(why) > MAX_WHY:
            raise PendcliError(f"{at}: 'why' must be one line of at most {MAX_WHY} characters")
        out.append(Independent(of, row, line, why))
    return tuple(out)


_CACHE: dict[Path, tuple[Ledger, dict[str, tuple[Companion, ...]]]] = {}


def ledger_companions(ledger: Ledger) -> dict[str, tuple[Companion, ...]]:
    """Every source row of the loaded ``ledger`` with its companions, judged with the
    ledger's ``[[companion]]`` entries and the reading record's citations; an entry naming no
    companion the rule finds, or one the row's own record already judges, is refused."""
    cached = _CACHE.get(ledger.path)
    if cached is not None and cached[0] is ledger:
        return cached[1]
    from pendcli.data.tables import read_table_text, read_toml

    raw: dict[str, Any] = read_toml(ledger.path, "equation ledger")
    independent = parse_companions(f"{ledger.path}", raw.get("companion"))
    text = read_table_text(ledger.text, "paper text")
    lines = text.split("\n")
    found = companions_of(ledger, _citations(ledger, text), _spans(ledger), lines, independent)
    _check_entries(f"{ledger.path}", independent, found)
    _CACHE[ledger.path] = (ledger, found)
    return found


def _spans(ledger: Ledger) -> list[tuple[int, int]]:
    return [row.lines for row in ledger.rows if row.lines is not None]


def _citations(ledger: Ledger, text: str) -> list[tuple[str, int, int | None]]:
    """(label, line, printing meant or None) of every citation of a label in the prose, the
    printing meant read from the reading record's ``[[citation]]`` entries."""
    from pendcli.data.ledger_labels import label_lines
    from pendcli.data.reading_citations import parse_citations, prose_citations, reading_path
    from pendcli.data.tables import read_toml

    labels = label_lines(text)
    path = reading_path(ledger.paper, ledger.path.parent.parent)
    entries = read_toml(path, "reading record").get("citation") if path.exists() else None
    twice = {k: v for k, v in labels.items() if len(v) > 1}
    meant = {
        (c.label, c.line): c.printing for c in parse_citations(f"{path}", entries, text, twice)
    }
    return [
        (label, line, meant.get((label, line))) for label, line in prose_citations(text, labels)
    ]


def _check_entries(
    where: str, entries: tuple[Independent, ...], found: Mapping[str, tuple[Companion, ...]]
) -> None:
    for entry in entries:
        at = f"{where}: [[companion]] of {entry.of} ({entry.row or f'line {entry.line}'})"
        match = [
            c
            for c in found.get(entry.of, ())
            if (c.row, c.line if c.row is None else None) == (entry.row, entry.line)
        ]
        if not match:
            raise PendcliError(f"{at}: names no companion of a corrected or read row")
        if match[0].judged != "independent":
            raise PendcliError(f"{at}: already judged by its record ({match[0].judged})")
