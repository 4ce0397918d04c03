"""The package's one exception type: the CLI turns it into one red line and exit code 2."""

from __future__ import annotations


class PendcliError(Exception):
    """Bad input, a malformed table, an unknown claim: a message meant for the user.

    ``parameter``: the name of the input at fault, when the message starts with it, so the
    CLI can name the option as the user typed it (``--method`` for ``method``).
    """

    def __init__(self, message: str, parameter: str | None = None) -> None:
        super().__init__(message)
        self.parameter = parameter


def invalid_value(parameter: str, value: object, expected: str) -> PendcliError:
    """The one wording of a refused value: ``parameter: 'value' is not valid; expected ...``."""
    return PendcliError(f"{parameter}: {value!r} is not valid; expected {expected}", parameter)


def out_of_range(parameter: str, value: object, expected: str, what: str = "") -> PendcliError:
    """The one wording of a value outside its domain: ``parameter: value is out of range;
    expected lo <= parameter <= hi`` (``what``: the method or table whose domain it is)."""
    return PendcliError(
        f"{parameter}: {value} is out of range{what}; expected {expected}", parameter
    )
