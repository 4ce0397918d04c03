"""The package's one exception type: the CLI turns it into one red line and exit code 2.

Also the wording of an error line itself: :func:`one_line` (a newline in a path shown as
``\\n``, so the line stays whole) and :func:`out_of_memory` (a run that ran out of memory).
"""

from __future__ import annotations

import gc
import re
from collections.abc import Iterable


class PendcliError(Exception):
    """Bad input, a malformed table, an unknown claim: a message meant for the user.

    ``parameter``: the name of the input at fault, when the message starts with it, so the
    CLI can name the option as the user typed it (``--method`` for ``method``).
    """

    def __init__(self, message: str, parameter: str | None = None) -> None:
        super().__init__(message)
        self.parameter = parameter


def either(values: Iterable[object]) -> str:
    """``values`` as a reader lists them: ``1 or 2``, ``auto, scipy or series``."""
    names = [str(v) for v in values]
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} or {names[-1]}"


def invalid_value(parameter: str, value: object, expected: str) -> PendcliError:
    """The one wording of a refused value: ``parameter must be EXPECTED, got 'value'``."""
    return PendcliError(f"{parameter} must be {expected}, got {value!r}", parameter)


# ``lo <= name <= hi unit``, ``0 < l <= 1e6 m``: a range as the models write it
_RANGE = re.compile(r"^(?P<lo>\S+) (?P<a><=?) [^\s|]+ (?P<b><=?) (?P<hi>[^\s,;]+)(?P<rest>.*)$")
_BOUND = re.compile(r"^\S+ (?P<op>[<>]=?) (?P<limit>\S+)$")
_DOTS = re.compile(r"^(?P<lo>[^.\s]+)\.\.(?P<hi>[^.\s]+(?:\.\d+)?)$")


def _condition(expected: str) -> str:
    """``lo <= x <= hi m`` as ``in [lo, hi] m``; ``x > 0`` as ``> 0``; ``1..20`` as
    ``in [1, 20]``; anything else as ``such that EXPECTED``."""
    if found := _RANGE.match(expected):
        left = "[" if found["a"] == "<=" else "("
        right = "]" if found["b"] == "<=" else ")"
        return f"in {left}{found['lo']}, {found['hi']}{right}{found['rest']}"
    if found := _BOUND.match(expected):
        return f"{found['op']} {found['limit']}"
    if found := _DOTS.match(expected):
        return f"in [{found['lo']}, {found['hi']}]"
    return f"such that {expected}"


def out_of_range(parameter: str, value: object, expected: str, what: str = "") -> PendcliError:
    """The one wording of a value outside its domain: ``parameter must be in [lo, hi], got
    value`` (``expected``: the domain as ``lo <= parameter <= hi``; ``what``: the method or
    table whose domain it is)."""
    return PendcliError(f"{parameter} must be {_condition(expected)}{what}, got {value}", parameter)


# Characters that would end or rewrite a line on a terminal: C0 and C1 controls (newline,
# carriage return, escape...) and the Unicode line and paragraph separators.
_LINE_BREAKING = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029]")


def one_line(message: str) -> str:
    """``message`` as one whole line: a newline (in a path, say) or another control character
    is shown escaped as Python writes it (``\\n``, ``\\x1b``), never acted on."""
    return _LINE_BREAKING.sub(lambda m: m.group().encode("unicode_escape").decode(), message)


# How the loader says a library could not be mapped for lack of address space (ulimit -v).
_NO_MEMORY = re.compile(r"failed to map segment|cannot allocate memory|out of memory", re.I)


def out_of_memory(exc: BaseException) -> str | None:
    """One line for a run that ran out of memory: a MemoryError, a library that could not be
    loaded for lack of it (an ImportError), or, under an address-space limit, a library that
    failed without saying why (a SystemError); None for any other error."""
    if isinstance(exc, MemoryError):
        detail = str(exc) or "an allocation failed"
        # the failed work's frames (and what they held) freed before anything more is asked:
        # the line below must not run out of the same memory
        exc.__traceback__ = None
        gc.collect()
    elif isinstance(exc, ImportError) and (found := _NO_MEMORY.search(str(exc))):
        detail = f"cannot load {exc.path or exc.name or 'a library'} ({found.group()})"
    elif isinstance(exc, SystemError) and str(exc) == _UNSAID and _address_space_limit():
        # a C function that failed without setting an exception: under ulimit -v, an
        # allocation refused in code that does not say so (a module's initialisation while
        # another one loads, seen at 300 MB); without a limit, a bug, said as one
        detail = (
            f"a library failed without saying why, as when an allocation is refused ({_UNSAID})"
        )
    else:
        return None
    return f"out of memory{_address_space_limit()}: {detail}"


_UNSAID = "error return without exception set"


def _address_space_limit() -> str:
    """The soft ``ulimit -v``, from /proc, read as bytes: loading the resource module, or the
    codec a text file is read with (imported on first use), may itself need the memory that is
    missing; if even this fails for lack of it, the line says no limit."""
    try:
        with open("/proc/self/limits", "rb") as limits:
            soft = next(ln for ln in limits if ln.startswith(b"Max address space")).split()[3]
    except (OSError, MemoryError, StopIteration, IndexError, ValueError):
        return ""
    if not soft.isdigit():  # unlimited
        return ""
    return f" (the address space is limited to {int(soft) >> 20} MB: ulimit -v)"
