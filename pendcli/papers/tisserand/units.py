"""Angles and lengths as the user types them and as Tisserand prints them (sexagesimal)."""

from __future__ import annotations

import math
import re

from pendcli.base.errors import PendcliError, out_of_range
from pendcli.numerics.spherical import check_amplitudes

__all__ = ["ARCSEC", "amplitudes", "angle_text", "parse_angle", "parse_length"]

ARCSEC = math.pi / (180 * 3600)  # one second of arc, in radians

_ANGLE_UNITS = {
    "rad": 1.0,
    "deg": math.pi / 180,
    "°": math.pi / 180,
    "arcmin": math.pi / (180 * 60),
    "'": math.pi / (180 * 60),
    "′": math.pi / (180 * 60),
    "arcsec": ARCSEC,
    "''": ARCSEC,
    "″": ARCSEC,
    '"': ARCSEC,
}
_ANGLE_FORMS = "30°, 30deg, 30', 30arcmin, 90'', 90arcsec, 0.52rad or 1°7'33''"
_NUMBER_UNIT = re.compile(r"^\s*([+-]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][+-]?\d+)?)\s*(\S*)\s*$")
_SEXAGESIMAL = re.compile(r"^\s*\d+\s*°\s*\d+\s*['′](\s*\d+(?:[.,]\d+)?\s*(''|″|\"))?\s*$")


def parse_angle(text: str, name: str = "angle") -> float:
    """An angle with its unit (30°, 30deg, 30', 30arcmin, 90arcsec, 0.52rad, 1°7'33''), in rad."""
    if not isinstance(text, str) or not text.strip():
        raise PendcliError(f"{name} is empty; write an angle with its unit, e.g. {_ANGLE_FORMS}")
    s = text.strip().replace("’", "'")
    if _SEXAGESIMAL.match(s):
        from pendcli.data.numbers import parse_printed

        return math.radians(parse_printed(s).value)
    m = _NUMBER_UNIT.match(s)
    if not m:
        raise PendcliError(f"{name}: {text!r} is not an angle; write e.g. {_ANGLE_FORMS}")
    number, unit = m.groups()
    if not unit:
        raise PendcliError(f"{name} = {text!r} has no unit; write e.g. {_ANGLE_FORMS}")
    factor = _ANGLE_UNITS.get(unit.lower())
    if factor is None:
        raise PendcliError(
            f"{name} = {text!r}: unknown unit {unit!r}; accepted forms are {_ANGLE_FORMS}"
        )
    value = float(number.replace(",", ".")) * factor
    if not math.isfinite(value):
        raise PendcliError(f"{name}: {text!r} is not finite")
    return value


def parse_length(value: float) -> float:
    """Pendulum length in metres: finite and positive."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise PendcliError(f"length: {value!r} is not a number; give metres, e.g. 0.5")
    if not 0.0 < value <= 1e6:
        raise out_of_range("length", f"{value!r} m", "0 < l <= 1e6 m")
    return float(value)


def amplitudes(theta0: str, theta1: str) -> tuple[float, float]:
    """Parse and validate θ0 and θ1 (radians), with one-line range messages."""
    a = parse_angle(theta0, "theta0")
    b = parse_angle(theta1, "theta1")
    if not 0.0 < a < 0.5 * math.pi:
        raise out_of_range("theta0", f"{theta0}", "0 < theta0 < 90°")
    if not 0.0 <= b <= a:
        raise out_of_range("theta1", f"{theta1}", f"0 <= theta1 <= theta0 = {theta0}")
    return check_amplitudes(a, b)


def angle_text(rad: float) -> str:
    """1°7'33.14'' for readable angles; seconds in scientific notation below 0.01''."""
    from pendcli.output.views import sexagesimal

    if abs(rad) < 0.01 * ARCSEC:
        return f"{rad / ARCSEC:.2e}''"
    return sexagesimal(math.degrees(rad), seconds_decimals=2)
