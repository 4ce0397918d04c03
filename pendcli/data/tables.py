"""Load and validate the published tables (``tables/published/<paper>.toml``).

Each file holds one paper's printed values, transcribed exactly as printed; the format is
documented in ``tables/README.md``. Every problem (missing file, bad TOML, a missing or
mistyped field, an unparsable printed value, a duplicate id) raises :class:`PendcliError`
naming the file and the entry.
"""

from __future__ import annotations

import copy
import math
import os
import re
import tomllib
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

from pendcli.base.errors import PendcliError
from pendcli.base.recent import Recent
from pendcli.data.numbers import PrintedNumber, exact_number, parse_printed
from pendcli.data.text_blocks import Span, validate_span
from pendcli.data.vocabulary import CAUSES  # why a printed value disagrees (tables/README.md)

__all__ = [
    "CAUSES",
    "MAX_TOML_DEPTH",
    "PaperConstant",
    "PaperTable",
    "PublishedValue",
    "assuming",
    "clear_table_cache",
    "inside_tables",
    "load_paper_table",
    "missing_claim",
    "paper_constant",
    "paper_text",
    "parse_toml",
    "read_table_text",
    "read_toml",
    "tables_dir",
]

_SECTIONS = ("paper", "claim")  # top level: [paper] and [[claim]], nothing else
_REQUIRED = ("id", "source", "quantity", "published")
_OPTIONAL = ("unit", "note", "ocr", "as_printed", "comparison", "precision", "cause")
_CLAIM_FIELDS = (*_REQUIRED, *_OPTIONAL, "from", "lines")
_PAPER_FIELDS = ("key", "citation", "seed", "assumptions", "constants")
# A constant declares the range its value must lie in (ends included), beside it in its table:
# physically plausible values, inside which the models are meant to work (and terminate). A
# value outside it, not finite, or a constant with no declared range is refused when read.
_CONSTANT_FIELDS = ("value", "unit", "range", "source")
# Deeper nesting than any table needs is refused (tomllib itself would recurse without end).
MAX_TOML_DEPTH = 8
# A table file's size: the largest committed is 110 kB (lecornu.toml); a larger one is
# refused before it is read, so a stray huge file cannot fill the memory.
MAX_TABLE_BYTES = 16_000_000
# Characters no table or text may hold, raw or as a TOML escape: the control characters but
# tab and newline (ESC would drive the terminal a table is shown on, CR overwrite its line)
# and the bidirectional overrides and isolates, which reorder what a reader sees.
_HIDDEN = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")
_PRECISIONS = ("printed", "exact")
# [paper] seed names the OCR file the text was made from: a bare file name, never a path.
_SEED = re.compile(r"[A-Za-z0-9_-][A-Za-z0-9_.-]{0,99}")
_COMPARISONS = ("equal", "upper-bound")


@dataclass(frozen=True)
class PublishedValue:
    """One printed number with its provenance."""

    id: str
    paper: str
    source: str
    quantity: str
    published: str  # the printed string, exactly as printed (normalised notation noted in ocr)
    number: PrintedNumber
    unit: str = ""
    note: str = ""
    ocr: str = ""  # OCR correction and its reason, if any
    as_printed: str = ""  # the OCR text, when `published` normalises its notation
    comparison: str = "equal"
    cause: str | None = None  # why it disagrees (one of CAUSES), when known
    cause_from: tuple[str, ...] = ()  # the claims it inherits an error from ("propagated")
    lines: Span | None = None  # the 1-based lines of papers/<paper>.txt where it is printed


@dataclass(frozen=True)
class PaperConstant:
    """A number the paper fixes or the model assumes (g, a speed), with where it comes from."""

    name: str
    value: float
    unit: str
    source: str  # "printed, II (15)" or "assumption: ..."
    range: tuple[float, float] = (-math.inf, math.inf)  # the declared plausible range


@dataclass(frozen=True)
class PaperTable:
    key: str
    citation: str
    seed: str
    assumptions: tuple[str, ...]
    claims: tuple[PublishedValue, ...]
    constants: tuple[PaperConstant, ...] = ()
    path: Path | None = None  # the file it was read from, for error messages

    @property
    def where(self) -> str:
        return str(self.path) if self.path is not None else f"published/{self.key}.toml"

    def constant(self, name: str) -> float:
        """The value of constant ``name`` from ``[paper.constants]`` (or the one
        :func:`assuming` puts in its place)."""
        for c in self.constants:
            if c.name == name:
                return _ASSUMED.get((self.key, name), c.value)
        raise PendcliError(
            f"{self.where}: no constant {name!r} in [paper.constants] (the code needs it); "
            f"known: {', '.join(c.name for c in self.constants) or 'none'}"
        )

    def constant_range(self, name: str) -> tuple[float, float]:
        """The declared range of constant ``name`` (ends included)."""
        self.constant(name)  # an unknown name: the error naming the known ones
        return next(c.range for c in self.constants if c.name == name)

    def claim(self, claim_id: str, needed_for: str = "") -> PublishedValue:
        """The published entry ``claim_id`` (a printed intermediate the model reuses)."""
        for c in self.claims:
            if c.id == claim_id:
                return c
        raise missing_claim(self.where, claim_id, needed_for)

    def claims_by_id(
        self, claim_ids: Iterable[str], needed_for: str = ""
    ) -> dict[str, PublishedValue]:
        """The entries ``claim_ids``, by id; a missing one is a :func:`missing_claim` error."""
        return {cid: self.claim(cid, needed_for) for cid in claim_ids}


def missing_claim(where: str, claim_id: str, needed_for: str = "") -> PendcliError:
    """The error for a claim id the code needs but the published table lacks (renamed?)."""
    purpose = f" for {needed_for}" if needed_for else ""
    return PendcliError(
        f"{where}: no claim {claim_id!r} (the code needs it{purpose}); "
        "was it renamed or removed? Restore the id or update the code that uses it"
    )


def tables_dir() -> Path:
    """Where the tables live: $PENDCLI_TABLES, else the copy shipped with the package."""
    override = os.environ.get("PENDCLI_TABLES")
    if override:
        return Path(override)
    return _PACKAGE_TABLES


_PACKAGE_TABLES = Path(__file__).resolve().parent.parent / "_tables"


# (paper, constant) -> the value put in place of the table's while a verdict is computed
# across the range of an assumption the paper does not state (data/ledger_conditions)
_ASSUMED: dict[tuple[str, str], float] = {}


@contextmanager
def assuming(key: str, name: str, value: float) -> Iterator[None]:
    """Within the block, constant ``name`` of paper ``key`` is ``value`` (inside the
    constant's declared range; outside it, an error naming both): what a ledger row's verdict
    is at another value of an assumption its paper leaves open (g, for Lecornu)."""
    low, high = load_paper_table(key).constant_range(name)
    if not (math.isfinite(value) and low <= value <= high):
        raise PendcliError(f"{key}: {name} = {value!r} is outside its range [{low}, {high}]")
    before = _ASSUMED.get((key, name))
    _ASSUMED[key, name] = value
    try:
        yield
    finally:
        if before is None:
            del _ASSUMED[key, name]
        else:
            _ASSUMED[key, name] = before


def paper_constant(key: str, name: str) -> float:
    """Constant ``name`` of paper ``key`` (e.g. ``paper_constant("lecornu", "g")``)."""
    return load_paper_table(key).constant(name)


def paper_text(key: str, root: Path | None = None) -> str:
    """The OCR text of paper ``key`` (``papers/<key>.txt``): missing or empty is an error, and
    so is one that leads out of the tables folder (:func:`inside_tables`)."""
    folder = root or tables_dir()
    path = folder / "papers" / f"{key}.txt"
    return read_table_text(inside_tables(path, folder, f"paper text {path}"), "paper text")


def inside_tables(path: Path, root: Path, where: str) -> Path:
    """``path``, checked to lie inside the tables folder ``root`` once every symlink of both is
    resolved: a file a table names (``[ledger] text``) or the code reads there never leads out
    of it (no ``..``, no absolute path, no symlink out). ``where`` names the file and the key."""
    try:
        real, base = path.resolve(), root.resolve()
    except (OSError, RuntimeError) as exc:  # a symlink loop
        raise PendcliError(f"{where}: cannot be resolved ({exc})") from None
    if real == base or not real.is_relative_to(base):
        raise PendcliError(
            f"{where}: resolves to {real}, outside the tables folder {base}; every table "
            "file and every file a table names must lie inside it (no '..', no absolute "
            "path, no symlink out)"
        )
    return path


def read_table_text(path: Path, what: str) -> str:
    """The UTF-8 text of a table file; missing, not a file, unreadable, not UTF-8 (the byte
    named) or empty: one line naming ``what`` and the file."""
    if not path.is_file():
        problem = "is not a file" if path.exists() else "is missing"
        raise PendcliError(f"{what} {path} {problem}")
    try:
        with path.open("rb") as stream:
            data = stream.read(MAX_TABLE_BYTES + 1)
    except OSError as exc:
        raise PendcliError(f"cannot read {what} {path}: {exc.strerror or exc}") from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise PendcliError(
            f"{what} {path} is not UTF-8 text: byte {exc.start} (0x{data[exc.start]:02x}) "
            f"cannot be decoded ({exc.reason})"
        ) from None
    if len(data) > MAX_TABLE_BYTES:
        raise PendcliError(f"{what} {path} is over {MAX_TABLE_BYTES:,} bytes, the limit of a table")
    if not text.strip():
        raise PendcliError(f"{what} {path} is empty")
    _refuse_hidden(text, f"{what} {path}")
    return text


def _refuse_hidden(text: str, where: str) -> None:
    """One line naming the line, column and code point of a character :data:`_HIDDEN` lists."""
    found = _HIDDEN.search(text)
    if found is not None:
        line = text.count("\n", 0, found.start()) + 1
        column = found.start() - (text.rfind("\n", 0, found.start()) + 1) + 1
        raise PendcliError(
            f"{where}: line {line}, column {column}: U+{ord(found.group()):04X} is a control or "
            "direction character; a table holds printable text, tabs and newlines only"
        )


def _strings(value: object) -> Iterable[str]:
    """Every string of a parsed TOML document, keys included (iteratively)."""
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, str):
            yield item
        elif isinstance(item, dict):
            yield from (k for k in item if isinstance(k, str))
            stack += list(item.values())
        elif isinstance(item, list):
            stack += item


def read_toml(path: Path, what: str) -> dict[str, Any]:
    """A TOML table file, parsed; every problem one line naming ``what`` and the file."""
    return parse_toml(read_table_text(path, what), path, what)


# Each table's text parsed and checked once, whichever step reads it (a cold `equations`
# reads each ledger and reading record two or three times); each caller gets its own copy.
_PARSED_TOML = Recent(32)


def parse_toml(text: str, path: Path, what: str) -> dict[str, Any]:
    """``text``, read from the table file ``path`` (:func:`read_table_text`), parsed as
    :func:`read_toml` parses it."""
    kept: dict[str, Any] | None = _PARSED_TOML.get(text)
    if kept is None:
        kept = _checked_toml(text, path, what)
        _PARSED_TOML.put(text, kept)
    return copy.deepcopy(kept)


def _checked_toml(text: str, path: Path, what: str) -> dict[str, Any]:
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise PendcliError(f"{what} {path} is not valid TOML: {exc}") from None
    except RecursionError:
        raise PendcliError(
            f"{what} {path} is nested too deeply (at most {MAX_TOML_DEPTH} levels)"
        ) from None
    if _depth(raw) > MAX_TOML_DEPTH:
        raise PendcliError(f"{what} {path} is nested too deeply (at most {MAX_TOML_DEPTH} levels)")
    for string in _strings(raw):  # a TOML escape ("\u001b") is a control character too
        _refuse_hidden(string, f"{what} {path}: the string {string[:40]!r}")
    return raw


def _depth(value: object) -> int:
    """How deeply tables and arrays nest in ``value`` (iteratively: no recursion to exhaust)."""
    deepest = 0
    stack: list[tuple[object, int]] = [(value, 0)]
    while stack:
        item, level = stack.pop()
        children = list(item.values()) if isinstance(item, dict) else item
        if isinstance(children, list):
            deepest = max(deepest, level + 1)
            stack += [(child, level + 1) for child in children]
    return deepest


def _constant_value(where: str, entry: dict[str, Any]) -> tuple[float, tuple[float, float]]:
    """The constant's value and its declared range, checked: a finite number within it."""
    value = entry.get("value")
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise PendcliError(f"{where}: value must be a number")
    low, high = _declared_range(where, entry.get("range"))
    number = float(value)
    if not (math.isfinite(number) and low <= number <= high):
        unit = entry.get("unit", "")
        raise PendcliError(
            f"{where}: value = {value!r} is out of range; valid range is "
            f"{low:g} <= value <= {high:g} {unit}".rstrip()
        )
    return number, (low, high)


def _declared_range(where: str, raw: object) -> tuple[float, float]:
    """``range = [low, high]``: two finite numbers, low < high."""
    if raw is None:
        raise PendcliError(f"{where}: no declared range for this constant (range = [low, high])")
    numbers = raw if isinstance(raw, list) else []
    if not (
        len(numbers) == 2
        and all(isinstance(x, int | float) and not isinstance(x, bool) for x in numbers)
        and all(math.isfinite(x) for x in numbers)
        and numbers[0] < numbers[1]
    ):
        raise PendcliError(f"{where}: range must be [low, high], two finite numbers, low < high")
    return float(numbers[0]), float(numbers[1])


def _constants(path: Path, raw: object, paper: str) -> tuple[PaperConstant, ...]:
    if raw is None:
        return ()
    if not isinstance(raw, dict):
        raise PendcliError(f"{path}: [paper.constants] must be a table")
    out = []
    for name, entry in raw.items():
        where = f"{path}: [paper.constants.{name}]"
        if not isinstance(entry, dict):
            raise PendcliError(f"{where} must be a table with value, unit, source")
        _refuse_unknown(where, "field(s)", entry, _CONSTANT_FIELDS)
        for field in ("unit", "source"):
            if not isinstance(entry.get(field, ""), str):
                raise PendcliError(f"{where}: {field} must be a string")
        if not entry.get("source"):
            raise PendcliError(f"{where}: source must say where the value comes from")
        value, declared = _constant_value(where, entry)
        out.append(PaperConstant(name, value, entry.get("unit", ""), entry["source"], declared))
    return tuple(out)


def load_paper_table(key: str, root: Path | None = None) -> PaperTable:
    """Read and validate ``published/<key>.toml`` under ``root`` (default :func:`tables_dir`).

    Tables are read once per process; :func:`clear_table_cache` forgets them.
    """
    return _cached_table(key, _resolved(str(root or tables_dir())))


@cache  # a model reads its printed numbers through here in its inner loops (60,000 calls)
def _resolved(root: str) -> Path:
    """``root`` with every symlink resolved (forgotten with the tables)."""
    return Path(root).resolve()


def clear_table_cache() -> None:
    """Forget every table read (after a table file or ``$PENDCLI_TABLES`` changes), and what
    was computed from them (the ledger's references, which may read the published numbers)."""
    _cached_table.cache_clear()
    _resolved.cache_clear()
    for clear in _DEPENDENT_CACHES:
        clear()


# cache_clear of the caches computed from the tables (registered by their modules)
_DEPENDENT_CACHES: list[Callable[[], None]] = []


def on_table_change(clear: Callable[[], None]) -> None:
    """Have :func:`clear_table_cache` call ``clear`` too."""
    _DEPENDENT_CACHES.append(clear)


@cache
def _cached_table(key: str, root: Path) -> PaperTable:
    path = root / "published" / f"{key}.toml"
    raw = read_toml(inside_tables(path, root, f"published table {path}"), "published table")
    _refuse_unknown(str(path), "top-level section(s)", raw, _SECTIONS)
    paper = _paper_header(path, raw.get("paper"), key)
    return PaperTable(
        key=key,
        citation=paper["citation"],
        seed=paper["seed"],
        assumptions=tuple(paper.get("assumptions", [])),
        claims=_claims_in_text(path, _claims(path, raw.get("claim"), key), root, key),
        constants=_constants(path, paper.get("constants"), key),
        path=path,
    )


def _refuse_unknown(where: str, what: str, entry: dict[str, Any], valid: tuple[str, ...]) -> None:
    """A key the format does not know (a typo such as ``asumptions``) is an error, not ignored."""
    unknown = sorted(set(entry) - set(valid))
    if unknown:
        raise PendcliError(
            f"{where}: unknown {what} {', '.join(map(repr, unknown))}; valid: {', '.join(valid)}"
        )


def _paper_header(path: Path, paper: object, key: str) -> dict[str, Any]:
    """The ``[paper]`` table, checked: its key, citation, seed, assumptions, no other field."""
    if not isinstance(paper, dict) or paper.get("key") != key:
        raise PendcliError(f"{path}: [paper] must be a table with key = {key!r}")
    _refuse_unknown(f"{path}: [paper]", "field(s)", paper, _PAPER_FIELDS)
    for field in ("citation", "seed"):
        if not isinstance(paper.get(field), str):
            raise PendcliError(f"{path}: [paper] needs a string {field!r}")
    if not _SEED.fullmatch(paper["seed"]):
        raise PendcliError(
            f"{path}: [paper] seed = {paper['seed']!r} must be a bare file name (letters, "
            "digits, '_', '-', '.', not starting with '.'): it names a file, never a path"
        )
    assumptions = paper.get("assumptions", [])
    if not isinstance(assumptions, list) or not all(isinstance(a, str) for a in assumptions):
        raise PendcliError(f"{path}: [paper] assumptions must be a list of strings")
    return paper


def _claims(path: Path, entries: object, key: str) -> tuple[PublishedValue, ...]:
    if not isinstance(entries, list) or not entries:
        raise PendcliError(f"{path}: no [[claim]] entries")
    claims: list[PublishedValue] = []
    seen: set[str] = set()
    for index, entry in enumerate(entries, start=1):
        claims.append(_claim(path, index, entry, key, seen))
        seen.add(claims[-1].id)
    for claim in claims:
        for source_id in claim.cause_from:
            if source_id not in seen or source_id == claim.id:
                raise PendcliError(
                    f"{path}: claim {claim.id!r}: 'from' names {source_id!r}, which is "
                    "not another claim of this file"
                )
    return tuple(claims)


def _claims_in_text(
    path: Path, claims: tuple[PublishedValue, ...], root: Path, key: str
) -> tuple[PublishedValue, ...]:
    """Each claim's ``lines`` within the paper's text (``papers/<key>.txt`` under ``root``),
    when the text is there to count (as the ledger's rows are checked); a missing text is the
    error of the command that needs it, one that leads out of ``root`` an error here."""
    text = root / "papers" / f"{key}.txt"
    if text.is_file() and any(c.lines is not None for c in claims):
        inside_tables(text, root, f"paper text {text}")
        count = len(read_table_text(text, "paper text").splitlines())
        for claim in claims:
            if claim.lines is not None:
                validate_span(f"{path}: claim {claim.id!r}", list(claim.lines), count)
    return claims


def _claim(path: Path, index: int, entry: object, key: str, seen: set[str]) -> PublishedValue:
    """One ``[[claim]]`` entry, checked field by field; ``seen`` holds the ids before it."""
    where = f"{path}: claim #{index}"
    if not isinstance(entry, dict):
        raise PendcliError(f"{where} is not a table")
    if isinstance(entry.get("id"), str):
        where = f"{path}: claim {entry['id']!r}"
    _check_fields(where, entry)
    if not entry["id"].startswith(f"{key}."):
        raise PendcliError(f"{where}: id must start with {key + '.'!r}")
    if entry["id"] in seen:
        raise PendcliError(f"{where}: duplicate id")
    comparison = entry.get("comparison", "equal")
    if comparison not in _COMPARISONS:
        raise PendcliError(f"{where}: comparison must be one of {', '.join(_COMPARISONS)}")
    return PublishedValue(
        id=entry["id"],
        paper=key,
        source=entry["source"],
        quantity=entry["quantity"],
        published=entry["published"],
        number=_printed_number(where, entry["published"], entry.get("precision", "printed")),
        unit=entry.get("unit", ""),
        note=entry.get("note", ""),
        ocr=entry.get("ocr", ""),
        as_printed=entry.get("as_printed", ""),
        comparison=comparison,
        cause=entry.get("cause"),
        cause_from=_cause_from(where, entry),
        lines=validate_span(where, entry["lines"]) if "lines" in entry else None,
    )


def _cause_from(where: str, entry: dict[str, Any]) -> tuple[str, ...]:
    """``from``: the claims a ``propagated`` error comes from; required then, refused otherwise."""
    cause = entry.get("cause")
    if cause is not None and cause not in CAUSES:
        raise PendcliError(f"{where}: cause {cause!r} is not one of {', '.join(CAUSES)}")
    sources = entry.get("from")
    if cause != "propagated":
        if sources is not None:
            raise PendcliError(f"{where}: 'from' is only for cause = \"propagated\"")
        return ()
    if (
        not isinstance(sources, list)
        or not sources
        or not all(isinstance(s, str) and s for s in sources)
    ):
        raise PendcliError(
            f"{where}: cause = \"propagated\" needs 'from', a non-empty list of claim ids"
        )
    if len(set(sources)) != len(sources):
        raise PendcliError(f"{where}: 'from' repeats a claim id")
    return tuple(sources)


def _check_fields(where: str, entry: dict[str, Any]) -> None:
    """Required fields are non-empty strings, optional ones strings, and no other field."""
    for field in _REQUIRED:
        if not isinstance(entry.get(field), str) or not entry[field].strip():
            raise PendcliError(f"{where}: field {field!r} must be a non-empty string")
    for field in _OPTIONAL:
        if field in entry and not isinstance(entry[field], str):
            raise PendcliError(f"{where}: field {field!r} must be a string")
    _refuse_unknown(where, "field(s)", entry, _CLAIM_FIELDS)


def _printed_number(where: str, published: str, precision: str) -> PrintedNumber:
    if precision not in _PRECISIONS:
        raise PendcliError(f"{where}: precision must be one of {', '.join(_PRECISIONS)}")
    try:
        number = parse_printed(published)
    except PendcliError as exc:
        raise PendcliError(f"{where}: {exc}") from None
    # A count or a definition ("cinq racines", "un mètre"): exact, whatever its digits.
    return exact_number(number) if precision == "exact" else number
