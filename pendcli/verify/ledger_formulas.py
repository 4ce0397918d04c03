"""The ledger's formulas: its ``[symbols]`` table (name -> dimension) and each row's
``printed``, ``reading_formula`` and ``corrected_formula``, parsed and dimension-checked.

Every formula is checked by the notation's grammar when a ledger is loaded (its words, its
tree and its bounds: data/formula_grammar), so a typo or an undeclared name is a load error
naming the row; its sympy expression is built when first used (a row judged from its live
reference, its dimensions where the store does not keep them, a formula check), once per
text and symbol table.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendcli.base.errors import PendcliError
from pendcli.base.recent import Recent
from pendcli.data.formula_grammar import plain_name
from pendcli.data.printed import (
    ELLIPSIS,
    FUNCTIONS,
    Formula,
    check_formula,
    parse_dimension,
    parse_formula,
)

if TYPE_CHECKING:
    from pendcli.data.ledger_rows import LedgerRow
    from pendcli.verify.dimensions import DimensionCheck
    from pendcli.verify.printed_check import Reference

__all__ = [
    "FORMULA_FIELDS",
    "printed_status",
    "row_dimensions",
    "row_formula",
    "validate_formulas",
]

FORMULA_FIELDS = ("printed", "reading_formula", "corrected_formula")
_RESERVED = (
    *FUNCTIONS,
    ELLIPSIS,
    "pi",
    "oo",
    "Rational",
    "Integer",
    "Float",
    "Symbol",
    "Function",
    "Integral",
    "Derivative",
)


def validate_symbols(path: Path, raw: object) -> tuple[tuple[str, str], ...]:
    """``[symbols]`` as (name, dimension) pairs, each dimension parsed once to check it; a
    name is plain (letters, digits, ``_``, from a letter; no keyword) and new (no function
    of the notation)."""
    if raw is None:
        return ()
    if not isinstance(raw, dict):
        raise PendcliError(f'{path}: [symbols] must be a table of name = "dimension"')
    key = repr(raw)
    if _SYMBOLS.get(key) is None:  # a table found valid is not checked again
        _check_symbols(path, raw)
        _SYMBOLS.put(key, True)
    return tuple(sorted(raw.items()))


# repr of a [symbols] table -> True: the tables :func:`_check_symbols` found valid
_SYMBOLS = Recent(64)


def _check_symbols(path: Path, raw: dict[str, Any]) -> None:
    for name, dim in raw.items():
        bare = name.removesuffix("()")
        if not plain_name(bare) or bare in _RESERVED or not isinstance(dim, str):
            raise PendcliError(
                f"{path}: [symbols] {name!r}: a new name (ASCII letters, digits and _, from a "
                'letter; not a keyword) = "L T^-2" or "1"'
            )
        parse_dimension(f"{path}: [symbols] {name}", dim)


def validate_scopes(
    path: Path, raw: object, symbols: Mapping[str, str]
) -> tuple[tuple[tuple[int, int], tuple[tuple[str, str], ...]], ...]:
    """``[[scope]]`` tables (``lines = [first, last]``, ``what``, ``symbols = {...}``): the
    letters a stretch of the text uses with another meaning; each name must be one [symbols]
    declares too (a scope changes what a name means, never adds one silently)."""
    if raw is None:
        return ()
    if not isinstance(raw, list):
        raise PendcliError(f"{path}: [[scope]] must be an array of tables")
    out = []
    for index, scope in enumerate(raw):
        where = f"{path}: [[scope]] {index + 1}"
        lines = scope.get("lines") if isinstance(scope, dict) else None
        if not (isinstance(lines, list) and len(lines) == 2
                and all(type(n) is int for n in lines) and 1 <= lines[0] <= lines[1]):  # fmt: skip
            raise PendcliError(f"{where}: lines = [first, last], 1 <= first <= last")
        unknown = sorted(set(scope) - {"lines", "what", "symbols"})
        if unknown or not isinstance(scope.get("what"), str) or not scope["what"].strip():
            raise PendcliError(f"{where}: keys lines, what (why the letters differ), symbols")
        names = validate_symbols(Path(where), scope.get("symbols"))
        undeclared = [n for n, _ in names if n not in symbols]
        if undeclared or not names:
            raise PendcliError(f"{where}: names not in [symbols]: {undeclared or 'none given'}")
        out.append(((lines[0], lines[1]), names))
    return tuple(out)


def validate_formulas(
    path: Path, rows: Iterable[LedgerRow], symbols_for: Callable[[LedgerRow], Mapping[str, str]]
) -> None:
    """Check every formula field of every row by the notation's grammar (in the symbols of its
    place in the text; nothing is built); the first bad one is an error naming it."""
    for row in rows:
        symbols = symbols_for(row)
        for field in FORMULA_FIELDS:
            if getattr(row, field) is not None:
                if not symbols:
                    raise PendcliError(f"{path}: {row.id}: {field} needs a [symbols] table")
                check_formula(f"{path}: {row.id}: {field}", getattr(row, field), symbols)
                read = row.read(field)  # as the engine judges it, the reading table applied
                if read is not None and read != getattr(row, field):
                    check_formula(f"{path}: {row.id}: {field} (read)", read, symbols)
        if row.reference is not None and row.printed is None:
            raise PendcliError(f"{path}: {row.id}: a reference checks a printed form; none")
        if row.reading_formula is not None and row.status != "misprint":
            raise PendcliError(f"{path}: {row.id}: 'reading_formula' is for misprint rows")
        if row.corrected_formula is not None and row.status != "fails":
            raise PendcliError(f"{path}: {row.id}: 'corrected_formula' is for fails rows")


def row_formula(where: str, text: str, symbols: Mapping[str, str]) -> Formula:
    """``text`` parsed in ``symbols`` (once per text and symbol table: data/printed)."""
    return parse_formula(where, text, symbols)


@cache
def _dims(symbols: tuple[tuple[str, str], ...]) -> dict[str, Any]:
    return {name: parse_dimension(name, dim) for name, dim in symbols}


def row_dimensions(row: LedgerRow, symbols: Mapping[str, str]) -> dict[str, DimensionCheck]:
    """Field -> the dimensional verdict of each formula the row carries."""
    from pendcli.verify.dimensions import check_dimensions

    table = tuple(sorted(symbols.items()))
    out = {}
    for field in FORMULA_FIELDS:
        text = getattr(row, field)
        if text is not None:
            formula = parse_formula(f"{row.id}: {field}", text, symbols)
            out[field] = check_dimensions(formula, _dims(table))
    return out


def printed_status(
    row: LedgerRow, symbols: Mapping[str, str], reference: Reference
) -> tuple[str | None, str]:
    """The status the row's printed form earns against ``reference`` (verify/printed_check),
    each formula read through the paper's reading table."""
    from pendcli.verify.printed_verdict import computed_status

    def parsed(field: str) -> Formula | None:
        text = row.read(field)  # the reading table's replacements made (data/ledger_readings)
        return None if text is None else row_formula(f"{row.id}: {field}", text, symbols)

    printed = parsed("printed")
    assert printed is not None
    return computed_status(
        printed, parsed("reading_formula"), parsed("corrected_formula"), reference
    )
