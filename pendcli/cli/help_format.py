"""How every help of pendcli is laid out: at the terminal's width, with no word or value cut
across two lines, and each value named for a reader (``--count K``, not ``--count <int>``).

click wraps help at 80 columns at most (``max_content_width``) and breaks lines after a
hyphen, so a value a user copies came out as ``mcmahon-`` / ``newton`` and a default as
``[default:`` / ``5]``. Here the help is wrapped at the terminal's width ($COLUMNS, else the
terminal's own, else 80), and the tokens that must stay whole are bound before wrapping (a
hyphen between two characters of a word, the spaces of a bracketed note, of a comparison
such as ``1 <= K <= 10^7``) and unbound in the finished text.
"""

from __future__ import annotations

import functools
import re
from typing import Any

__all__ = [
    "ARGUMENTS",
    "EXAMPLES",
    "METAVARS",
    "epilog",
    "keep_whole",
    "metavar",
    "name_values",
    "restore",
    "whole_words_context",
]

# a width far above any terminal's: click then takes the terminal's own (minus its margin)
MAX_CONTENT_WIDTH = 10_000
_SPACE, _HYPHEN = "\u00a0", "\u2011"  # no-break space and hyphen, while wrapping only
_WORD_HYPHEN = re.compile(r"(?<=[\w.'])-(?=[\w.])")
_BRACKETED = re.compile(r"\[[^\[\]\n]{1,60}\]")
_COMPARISON = re.compile(r"[^\s(]+ (?:<=|>=|<|>|=|≤|≥) [^\s,;)]+(?: (?:<=|<|≤) [^\s,;)]+)?")

# The value a user types, as each option and argument names it in help, by parameter name
# (else by type: a number, a whole number, a text, a file).
METAVARS = {
    "amplitude": "DEGREES",
    "claim": "CLAIM",
    "count": "K",
    "family": "FAMILY",
    "fail_on": "VERDICT[,...]",
    "floor": "FRACTION",
    "g": "G",
    "length": "METRES",
    "method": "METHOD",
    "n": "N",
    "n_max": "N",
    "order": "ORDER",
    "out": "DIR",
    "paper": "PAPER",
    "ratio": "RATIO",
    "speed": "B",
    "status": "STATUS",
    "theta0": "ANGLE",
    "theta1": "ANGLE",
    "tol": "TOL",
    "write_tables": "DIR",
    "x": "X",
}
# the positional arguments, named in an error as in help
ARGUMENTS = {name: METAVARS[name] for name in ("claim", "family", "n")}
_BY_TYPE = {"int": "INTEGER", "float": "NUMBER", "str": "TEXT"}


def keep_whole(text: str) -> str:
    """``text`` with its values bound: a wrap never cuts them (see :func:`restore`)."""
    text = _WORD_HYPHEN.sub(_HYPHEN, text)
    for pattern in (_BRACKETED, _COMPARISON):
        text = pattern.sub(lambda m: m.group(0).replace(" ", _SPACE), text)
    return text


def restore(text: str) -> str:
    """The text :func:`keep_whole` bound, as written (plain spaces and hyphens)."""
    return text.replace(_SPACE, " ").replace(_HYPHEN, "-")


def metavar(param: Any) -> str | None:
    """The name of the value ``param`` takes, for its help; None for a flag or a choice
    (click shows a choice's values) or a parameter that names its own."""
    if getattr(param, "metavar", None) or getattr(param, "is_flag", False):
        return None
    descriptor = getattr(param, "type_descriptor", None)
    if descriptor is not None and descriptor.is_choice:
        return None
    name = param.name or ""
    if name in METAVARS:
        return METAVARS[name]
    if name == "plot":  # a file, or the folder of a command drawing several figures
        return "DIR" if "folder" in (param.help or "") or "DIR" in (param.help or "") else "FILE"
    annotation = getattr(descriptor, "annotation", None)
    return _BY_TYPE.get(getattr(annotation, "__name__", ""), "VALUE")


@functools.cache
def _whole_words_formatter(base: Any) -> type:
    """``base`` (click's HelpFormatter) writing text and definition lists with values bound."""

    def write_text(self: Any, text: str) -> None:
        base.write_text(self, keep_whole(text))

    def write_dl(self: Any, rows: Any, *args: Any, **kwargs: Any) -> None:
        bound = [(first, keep_whole(second)) for first, second in rows]
        base.write_dl(self, bound, *args, **kwargs)

    def getvalue(self: Any) -> str:
        return restore(base.getvalue(self))

    methods = {"write_text": write_text, "write_dl": write_dl, "getvalue": getvalue}
    return type(f"WholeWords{base.__name__}", (base,), methods)


@functools.cache
def whole_words_context(base: Any) -> Any:
    """``base`` (click's Context) whose help formatter keeps values whole, at the terminal's
    full width."""

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("max_content_width", MAX_CONTENT_WIDTH)
        base.__init__(self, *args, **kwargs)

    attributes = {
        "__init__": __init__,
        "formatter_class": _whole_words_formatter(base.formatter_class),
    }
    return type(f"WholeWords{base.__name__}", (base,), attributes)


def name_values(params: list[Any]) -> None:
    """Give each option and argument the name of its value (:func:`metavar`); an argument is
    shown by that name alone (``N``, ``[CLAIM]``), not with its Python type."""
    for param in params:
        name = metavar(param)
        if name is None:
            continue
        param.metavar = name
        if param.param_type_name == "argument":
            param.display_type_rich = lambda ctx, **kwargs: None
            shown = name if param.required else f"[{name}]"
            param.get_usage_pieces = lambda ctx, shown=shown: [shown]


# Examples shown at the end of each command's --help (the command path after `pendcli`).
EXAMPLES: dict[str, tuple[str, ...]] = {
    "": (
        "pendcli reproduce                     all papers: printed against recomputed",
        "pendcli reproduce -p lecornu --notes  one paper, every column",
        "pendcli check -f junit > check.xml    CI: a testcase per claim and table",
    ),
    "list": ("pendcli list -p tisserand", "pendcli list -f csv > claims.csv"),
    "reproduce": (
        "pendcli reproduce --only-failing",
        "pendcli reproduce -p charbonnier -f json",
        "pendcli reproduce --out out          report.md, report.html, tables, figures",
        "pendcli reproduce --out out --pdf    the pages printed to PDF too (Chromium)",
        "pendcli reproduce --fail-on discrepant,fails   CI: exit 1 on a bad verdict",
    ),
    "check": (
        "pendcli check",
        "pendcli check -f junit > check.xml",
        "pendcli check --update               then review and commit the tables",
    ),
    "tisserand claims": ("pendcli tisserand claims", "pendcli tisserand claims -f json"),
    "tisserand example": (
        "pendcli tisserand example",
        "pendcli tisserand example --theta0 45° --theta1 20° --plot ex.png",
    ),
    "tisserand series": ("pendcli tisserand series --order 4", "pendcli tisserand series -f csv"),
    "lecornu claims": ("pendcli lecornu claims", "pendcli lecornu claims --g 9.81"),
    "lecornu zeros": (
        "pendcli lecornu zeros --order 1 --count 10",
        "pendcli lecornu zeros --count 1000000 --tol 1e-12 -f csv > zeros.csv",
    ),
    "lecornu example": (
        "pendcli lecornu example",
        "pendcli lecornu example --speed 0.5 --length 2 --plot theta.png",
    ),
    "lecornu ode-check": (
        "pendcli lecornu ode-check",
        "pendcli lecornu ode-check --amplitude 1 --amplitude 10",
    ),
    "lecornu g-sensitivity": ("pendcli lecornu g-sensitivity",),
    "lecornu series": ("pendcli lecornu series -f json",),
    "lecornu zero-length": ("pendcli lecornu zero-length --speed 0.35 --length 1",),
    "charbonnier table": (
        "pendcli charbonnier table",
        "pendcli charbonnier table --n-max 40 --plot table.png",
    ),
    "charbonnier integral": (
        "pendcli charbonnier integral 4              I_4(π) = 16/15",
        "pendcli charbonnier integral 1000 -x 1.5",
        "pendcli charbonnier integral 5 --tol 1e-10  the cheapest method for it",
    ),
    "formulas": (
        "pendcli formulas -p lecornu",
        "pendcli formulas --plot figures/   one residual plot per formula",
    ),
    "equations": (
        "pendcli equations -p tisserand",
        "pendcli equations --status misprint --notes",
    ),
    "tisserand": (
        "pendcli tisserand claims                 the printed numbers, judged",
        "pendcli tisserand example --theta0 45°   θ1 keeps the example's ratio",
        "pendcli tisserand series --order 4",
    ),
    "lecornu": (
        "pendcli lecornu claims --g 9.81",
        "pendcli lecornu zeros --order 1 --count 10",
        "pendcli lecornu example --speed 0,5 --plot theta.png",
        "pendcli lecornu g-sensitivity            which g fits his figures",
    ),
    "charbonnier": (
        "pendcli charbonnier table",
        "pendcli charbonnier integral 4              I_4(π) = 16/15",
        "pendcli charbonnier integral 5 --tol 1e-10",
    ),
    "cache": ("pendcli cache info", "pendcli cache clear"),
    "cache info": ("pendcli cache info",),
    "cache clear": ("pendcli cache clear", "pendcli reproduce --no-cache   all computed afresh"),
    "tradeoff": ("pendcli tradeoff --quick", "pendcli tradeoff integral_pi --plot wp.png"),
    "explain": (
        "pendcli explain -p lecornu     each wrong digit: its mechanism and odds",
        "pendcli explain lecornu.mean_pendulum_coefficient   every step of one",
        "pendcli explain -f json > explanations.json",
    ),
}


def epilog(path: str) -> str | None:
    """The Examples block of a command's help; "\b" keeps click from rewrapping it."""
    lines = EXAMPLES.get(path)
    return "\b\nExamples:\n" + "\n".join(f"  {line}" for line in lines) if lines else None
