"""Parse numbers as the papers print them, keeping the precision the print implies.

A printed string fixes its own precision: ``5,14`` is known to 0.01, ``-0,130``
to 0.001, ``1°7'33''`` to one second of arc, ``2/3`` and ``2·4/(1·3·5)`` are
exact. :func:`parse_printed` returns the value together with that resolution
(the unit in the last printed place), which the verdict engine then uses.

Accepted forms (all found in the three papers):

* decimals with a comma or a point, optional sign: ``5,14``, ``+0,072``, ``0.25``;
* old French unit-in-the-middle decimals: ``0^m,35``, ``2^{sec},86`` (value 0.35, 2.86);
* sexagesimal angles: ``1°7'33''``, ``2'42''``, ``2''``, ``30'`` (value in degrees);
* exact expressions of integers, ``·``, ``*``, ``/``, parentheses and ``π``:
  ``1/5``, ``2·2·4/(1·3·5)``, ``π·1·3/(2·4)``.

A printed string is read within bounds (``MAX_PRINTED_*``, documented in ``tables/README.md``)
and its value must be one the verdict can judge in double precision: a finite, normal number,
and a rounded value of at most ``MAX_SIGNIFICANT_DIGITS`` digits in units of its last place.
Anything else is a :class:`PendcliError` naming the bound, never an infinite or zero value.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass
from fractions import Fraction

from pendcli.base.errors import PendcliError

__all__ = [
    "MAX_PRINTED_CHARS",
    "MAX_PRINTED_DIGITS",
    "MAX_PRINTED_FACTORS",
    "MAX_PRINTED_NESTING",
    "MAX_SIGNIFICANT_DIGITS",
    "PrintedNumber",
    "edition_angle",
    "edition_minus",
    "edition_number",
    "edition_quantity",
    "edition_text",
    "exact_number",
    "fixed",
    "fixed_decimals",
    "paper_decimals",
    "parse_printed",
    "sexagesimal_text",
    "significant",
]


# Bounds on a printed string. The committed tables' longest is 15 characters
# (π·1·3·5/(2·4·6)), their longest run of digits 5 (0,00313), their deepest parentheses 1 and
# their most factors 7: each bound is several times that, and far below what would make the
# parse recurse, overflow or slow down.
MAX_PRINTED_CHARS = 100  # characters of the printed string
MAX_PRINTED_DIGITS = 30  # digits of one number (one run of digits)
MAX_PRINTED_NESTING = 8  # parentheses within parentheses
MAX_PRINTED_FACTORS = 50  # integers and π of an exact expression
# A rounded value (a decimal, an angle) counted in units of its last place: the verdict judges
# in double precision, which holds 15 significant decimal digits (the committed tables: 4).
MAX_SIGNIFICANT_DIGITS = sys.float_info.dig


@dataclass(frozen=True)
class PrintedNumber:
    """A printed value and the precision its printed form implies."""

    text: str
    value: float
    resolution: float | None  # unit in the last printed place; None when exact
    kind: str  # "decimal", "sexagesimal" or "exact"
    exact: Fraction | None = None  # rational part of an exact expression
    pi_power: int = 0  # exact expressions are exact * pi**pi_power
    decimals: int | None = None  # printed decimals (decimal kind only)

    @property
    def is_exact(self) -> bool:
        return self.kind == "exact"


_DECIMAL = re.compile(r"^([+-]?)(\d+)(?:[.,](\d+))?$")
# 0^m,35 or 2^{sec},86: the unit is written between the integer and the decimals.
_UNIT_MIDDLE = re.compile(r"^([+-]?)(\d+)\^\{?([a-zA-Z]+)\}?\s*(?:[.,]\s*(\d+))?$")
_SEXAGESIMAL = re.compile(
    r"^([+-]?)(?:(\d+)\s*°)?\s*(?:(\d+)\s*(?:'|′)(?!'))?\s*(?:(\d+(?:[.,]\d+)?)\s*(?:''|″|\"))?$"
)
_EXPR_TOKEN = re.compile(r"\s*(\d+|π|pi|[()·*/×.])")


def _normalise(text: str) -> str:
    return text.strip().replace("\u2212", "-").replace("’", "'")


def parse_printed(text: str) -> PrintedNumber:
    """Parse one printed number; raise :class:`PendcliError` naming the string if it is not one."""
    if not isinstance(text, str) or not text.strip():
        raise PendcliError(
            f"empty printed value {_shown(text)}; expected e.g. '5,14', '1°7\\'33\\'\\'', '1/5'"
        )
    _check_size(text)
    s = _normalise(text)
    m = _DECIMAL.match(s) or _UNIT_MIDDLE.match(s)
    if m:
        return _decimal(text, m)
    if any(c in s for c in "°'″\""):
        return _sexagesimal(text, s)
    exact, pi_power = _parse_exact(s, text)
    return PrintedNumber(
        text=text,
        value=_exact_value(text, exact, pi_power),
        resolution=None,
        kind="exact",
        exact=exact,
        pi_power=pi_power,
    )


def _shown(text: str, most: int = 60) -> str:
    """The printed string as an error line quotes it: escaped, and cut so that its escaped
    form stays within ``most`` characters (one character can take ten: '\\U0001e960')."""
    if len(repr(text)) <= most:
        return repr(text)
    cut = text[:most]
    while len(repr(cut)) > most:
        cut = cut[: len(cut) // 2 if len(repr(cut)) > 2 * most else -1]
    return f"{cut!r}… ({len(text)} characters)"


def _check_size(text: str) -> None:
    """The bounds every printed string keeps: its length and the digits of each number."""
    if len(text) > MAX_PRINTED_CHARS:
        raise PendcliError(
            f"printed value {_shown(text)} is too long: at most {MAX_PRINTED_CHARS} characters"
        )
    longest = max((len(run) for run in re.findall(r"\d+", text)), default=0)
    if longest > MAX_PRINTED_DIGITS:
        raise PendcliError(
            f"printed value {_shown(text)} has a number of {longest} digits: "
            f"at most {MAX_PRINTED_DIGITS} digits per number"
        )


def _check_significant(text: str, units: Fraction) -> None:
    """A rounded value, ``units`` of its last place, within what a double holds exactly."""
    digits = len(str(abs(round(units))))
    if digits > MAX_SIGNIFICANT_DIGITS:
        raise PendcliError(
            f"printed value {_shown(text)} has {digits} significant digits: the verdict "
            f"compares in double precision, at most {MAX_SIGNIFICANT_DIGITS} digits"
        )


def _exact_value(text: str, exact: Fraction, pi_power: int) -> float:
    """exact * π**pi_power as a double: finite and, unless 0, a normal number (no underflow)."""
    try:
        value = float(exact) * math.pi**pi_power
    except OverflowError:
        value = math.inf
    if not math.isfinite(value) or (exact != 0 and abs(value) < sys.float_info.min):
        raise PendcliError(
            f"printed value {_shown(text)} cannot be represented in double precision: its "
            f"magnitude must lie between {sys.float_info.min:.1e} and {sys.float_info.max:.1e}"
        )
    return value


def _decimal(text: str, m: re.Match[str]) -> PrintedNumber:
    """``5,14``, ``-0,130``, ``0^m,35``: the unit of the last place is 10^-(decimals)."""
    groups = m.groups()
    sign, whole, frac = groups[0], groups[1], groups[-1] or ""
    _check_significant(text, Fraction(int(whole + frac)))
    magnitude = float(f"{whole}.{frac}") if frac else float(whole)
    return PrintedNumber(
        text=text,
        value=-magnitude if sign == "-" else magnitude,
        resolution=10.0 ** (-len(frac)),
        kind="decimal",
        decimals=len(frac),
    )


def _sexagesimal(text: str, s: str) -> PrintedNumber:
    """``1°7'33''``, ``2'42''``, ``30'``: degrees, known to the last printed unit of arc."""
    m = _SEXAGESIMAL.match(s)
    if not (m and any(m.group(i) for i in (2, 3, 4))):
        raise PendcliError(
            f"malformed sexagesimal angle {_shown(text)}; expected e.g. 1°7'33'' or 2'42''"
        )
    sign, deg, minutes, seconds = m.groups()
    value = 0.0
    resolution = 1.0
    exact, unit = Fraction(0), Fraction(1)  # the angle in units of its last place, checked
    if deg:
        value += int(deg)
        exact += int(deg)
    if minutes:
        value += int(minutes) / 60
        resolution = 1 / 60
        exact, unit = exact + Fraction(int(minutes), 60), Fraction(1, 60)
    if seconds:
        sec_text = seconds.replace(",", ".")
        value += float(sec_text) / 3600
        decimals = len(sec_text.split(".")[1]) if "." in sec_text else 0
        resolution = 10.0 ** (-decimals) / 3600
        exact, unit = exact + Fraction(sec_text) / 3600, Fraction(1, 3600 * 10**decimals)
    _check_significant(text, exact / unit)
    if sign == "-":
        value = -value
    return PrintedNumber(text=text, value=value, resolution=resolution, kind="sexagesimal")


def _tokens(s: str, original: str) -> list[str]:
    tokens: list[str] = []
    pos = 0
    while pos < len(s):
        m = _EXPR_TOKEN.match(s, pos)
        if not m:
            raise PendcliError(
                f"cannot read printed value {_shown(original)} at {_shown(s[pos:], 30)}; "
                "expected a decimal (5,14), an angle (1°7'33''), "
                "or an exact expression (2·4/(1·3·5), π·1/2)"
            )
        tokens.append(m.group(1))
        pos = m.end()
        while pos < len(s) and s[pos].isspace():
            pos += 1
    return tokens


def _parse_exact(s: str, original: str) -> tuple[Fraction, int]:
    """Evaluate an exact expression: integers, π, products, quotients, parentheses."""
    tokens = _tokens(s, original)
    _check_shape(tokens, original)
    parser = _ExactParser(tokens, original)
    result = parser.expr()
    if parser.index != len(parser.tokens):
        raise PendcliError(f"unbalanced parenthesis in printed value {_shown(original)}")
    return result


def _check_shape(tokens: list[str], original: str) -> None:
    """An exact expression's bounds: its factors (integers and π) and its nesting."""
    factors = sum(1 for tok in tokens if tok not in ("(", ")", "·", "*", "/", "×", "."))
    if factors > MAX_PRINTED_FACTORS:
        raise PendcliError(
            f"printed value {_shown(original)} has {factors} factors: "
            f"at most {MAX_PRINTED_FACTORS} integers and π in an exact expression"
        )
    depth = deepest = 0
    for tok in tokens:
        depth += (tok == "(") - (tok == ")")
        deepest = max(deepest, depth)
    if deepest > MAX_PRINTED_NESTING:
        raise PendcliError(
            f"printed value {_shown(original)} nests {deepest} parentheses deep: "
            f"at most {MAX_PRINTED_NESTING}"
        )


class _ExactParser:
    """Recursive descent: expr := factor (('·' | '*' | '×' | '.' | '/' | juxtaposition) factor)*,
    factor := integer | π | '(' expr ')'. A value is (rational, power of π)."""

    def __init__(self, tokens: list[str], original: str) -> None:
        self.tokens = tokens
        self.original = original
        self.index = 0

    def factor(self) -> tuple[Fraction, int]:
        if self.index >= len(self.tokens):
            raise PendcliError(f"printed value {self.original!r} ends too early")
        tok = self.tokens[self.index]
        self.index += 1
        if tok == "(":
            val = self.expr()
            if self.index >= len(self.tokens) or self.tokens[self.index] != ")":
                raise PendcliError(f"unbalanced parenthesis in printed value {self.original!r}")
            self.index += 1
            return val
        if tok in ("π", "pi"):
            return Fraction(1), 1
        if tok.isdigit():
            return Fraction(int(tok)), 0
        raise PendcliError(f"unexpected {tok!r} in printed value {self.original!r}")

    def expr(self) -> tuple[Fraction, int]:
        val, power = self.factor()
        while self.index < len(self.tokens) and self.tokens[self.index] != ")":
            op = self.tokens[self.index]
            if op in ("·", "*", "×", ".", "/"):
                self.index += 1
            rhs, rp = self.factor()  # juxtaposition, as in "2 2/(1·3)" printed for 2·2/(1·3)
            if op != "/":
                val, power = val * rhs, power + rp
            elif rhs == 0:
                raise PendcliError(f"division by zero in printed value {self.original!r}")
            else:
                val, power = val / rhs, power - rp
        return val, power


def exact_number(printed: PrintedNumber) -> PrintedNumber:
    """The same printed number taken as exact (a count, a definition), not as a rounded value."""
    if printed.is_exact:
        return printed
    if printed.kind != "decimal":
        raise PendcliError(f"only a decimal can be declared exact, not {printed.text!r}")
    scale = 10 ** (printed.decimals or 0)
    exact = Fraction(round(printed.value * scale), scale)
    return PrintedNumber(
        text=printed.text, value=printed.value, resolution=None, kind="exact", exact=exact
    )


# --- numbers written as the papers write them --------------------------------------------

_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def significant(
    value: float,
    digits: int,
    decimal: str = ".",
    minus: str = "-",
    typeset_power: bool = False,
) -> str:
    """``value`` to ``digits`` significant digits, trailing zeros dropped (``%g``), with the
    given decimal mark and minus sign; a power of ten as ``e-05`` or, typeset, ``·10⁻⁵``.
    The one place a number's digits are chosen for a reader: every output style calls it."""
    mantissa, _, exponent = f"{value:.{digits}g}".partition("e")
    text = mantissa.replace(".", decimal).replace("-", minus)
    if exponent and typeset_power:
        return text + "·10" + str(int(exponent)).translate(_SUPERSCRIPT)
    return f"{text}e{exponent}" if exponent else text


def fixed_decimals(value: float, digits: int) -> int:
    """The decimals that show ``value`` in fixed notation with ``digits`` significant digits
    (0 for a number with at least that many digits before the point)."""
    if value == 0 or not math.isfinite(value):
        return max(digits - 1, 0)
    return max(digits - 1 - math.floor(math.log10(abs(value))), 0)


def fixed(value: float, decimals: int, decimal: str = ".", minus: str = "-") -> str:
    """``value`` in fixed notation with ``decimals`` places, trailing zeros kept."""
    text = f"{value:.{decimals}f}"
    if text.lstrip("-").strip("0.") == "":  # a rounded zero has no sign
        text = text.lstrip("-")
    return text.replace(".", decimal).replace("-", minus)


def sexagesimal_text(
    degrees: float,
    decimals: int = 2,
    marks: tuple[str, str, str] = ("°", "'", "''"),
    decimal: str = ".",
    minus: str = "-",
) -> str:
    """An angle in degrees as the papers print one: ``-1°7'33.14''``, ``2'42.20''``, ``1.69''``
    (Tisserand's 1°7'33'', 2'42'', 2''): the seconds to ``decimals`` places, the leading zero
    parts left out as the paper leaves them out, rounding carried into minutes and degrees."""
    units = round(abs(degrees) * 3600 * 10**decimals)
    whole, fraction = divmod(units, 10**decimals)
    deg, rest = divmod(whole, 3600)
    minutes, seconds = divmod(rest, 60)
    parts = [f"{deg}{marks[0]}" if deg else "", f"{minutes}{marks[1]}" if deg or minutes else ""]
    second = f"{seconds}{decimal}{fraction:0{decimals}d}" if decimals else f"{seconds}"
    return (minus if degrees < 0 and units else "") + "".join(parts) + second + marks[2]


def edition_number(value: object, digits: int = 10) -> str:
    """A recomputed number as the three papers print theirs, for the annotated edition.

    A decimal comma (``5,135622302``, as the paper prints ``5,14``), the typeset minus sign
    (``−0,130``) and no grouping of digits: none of the three papers groups its digits (the
    longest printed decimal, 0,00313, has five). A power of ten is written ``1,2·10⁻⁵``, not
    ``1.2e-05``. ``digits`` significant digits, trailing zeros dropped. Integers and text pass
    through; the JSON and CSV outputs keep their machine form and do not use this.
    """
    if value is None:
        return ""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return str(value)
    if isinstance(value, int):
        return str(value).replace("-", "\u2212")
    if not math.isfinite(value):
        return str(value)
    return significant(value, digits, ",", "\u2212", typeset_power=True)


def edition_angle(degrees: float, decimals: int = 2) -> str:
    """An angle in degrees as the edition prints one, sexagesimal: ``−1°7′33,14″``,
    ``2′42,00″``, ``1,69″`` (see :func:`sexagesimal_text`)."""
    return sexagesimal_text(degrees, decimals, ("°", "′", "″"), ",", "\u2212")


def edition_quantity(value: object, unit: str = "", digits: int = 10) -> str:
    """A recomputed value with its unit as the edition shows it: an ``angle`` (degrees) in
    sexagesimal form, any other number with a decimal comma (``digits`` significant digits)
    followed by its unit."""
    if unit == "angle" and isinstance(value, float) and math.isfinite(value):
        return edition_angle(value)
    return f"{edition_number(value, digits)} {unit}".strip() if value is not None else ""


# A minus sign written as a hyphen before a number, at the start or after a blank, a bracket,
# "=" or a separator: not a range (1°-2°), an exponent (1e-12) or a word's hyphen.
_HYPHEN_MINUS = re.compile(r"(?<![^\s(\[=,;:«])-(?=\d)")
# A number with a decimal point in a detail string (1.99, -1.286, 6.08e-02): not part of an
# identifier (lecornu.eq.25, table26.first), a version (1.2.3), a word (DOP853, 1e-12) or
# a product printed with points (2.4…n, 1.3.5…).
_POINT_NUMBER = re.compile(r"(?<![\w.])(\d+)\.(\d+)(?:e([+-]?\d+))?(?!\w|\.\d|…)")


def edition_minus(text: str) -> str:
    """A printed value or form with the typeset minus (−1,27) where it has a hyphen-minus."""
    return _HYPHEN_MINUS.sub("\u2212", text)


# A separator « , » beside a number with a decimal comma (« 0, 0,91, 1,66 »), where the two
# commas would read alike: before another number, or after one.
_LIST_COMMA = re.compile(r"(\d,\d+), (?=[-+\u2212]?\d)|(?<=\d), (?=[-+\u2212]?\d+,\d)")


def paper_decimals(text: str) -> str:
    """A note written with decimal points, in the paper's decimal comma: ``1.286`` ->
    ``1,286``, ``6.08e-02`` -> ``6,08·10⁻²``, and a list of numbers separated by « ; »
    (``[1.84, 1.98]`` -> ``[1,84 ; 1,98]``: « 1,84, 1,98 » would read as three numbers).
    Identifiers, versions and code words are left as they are; the minus is not touched."""

    def comma(m: re.Match[str]) -> str:
        text = f"{m.group(1)},{m.group(2)}"
        if m.group(3):
            text += "·10" + str(int(m.group(3))).translate(_SUPERSCRIPT)
        return text

    commas = _POINT_NUMBER.sub(comma, text)
    return _LIST_COMMA.sub(lambda m: f"{m.group(1) or ''} ; ", commas)


def edition_text(detail: str) -> str:
    """A note's detail string as the edition shows it: its numbers with a decimal comma
    (``order 1,99``, ``6,08·10⁻²``, lists separated by « ; ») and the typeset minus;
    identifiers, versions and code words are left as they are. The JSON and CSV outputs keep
    the string as it is."""
    return edition_minus(paper_decimals(detail))
