"""Text for a historian: the tables' and the ledger's notation as the pages show it.

The notes of the tables and the ledger are written for their editors: a printed number keeps
the OCR's TeX (``0^{sec},94``, ``1^m,21``), a formula the ledger's linear notation
(``∫_(x0)^(x1)``, ``j_(1,1)``, ``I_{-1}``), and a note may name the module that judged it
(``(verify/printed_numeric)``) or the reference it cites by its builder's name
(``reference_in_kpt_order_4``). What a reader sees (``report.md``, ``report.html``, the
edition) passes through here: units raised as the page prints them (0ˢᵉᶜ,94, 1ᵐ,21),
subscripts and superscripts set (Unicode where every character has one, else ``<sub>`` and
``<sup>``), module paths dropped, and a reference named by what it models.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from html import escape, unescape

__all__ = [
    "figure_text",
    "for_reader",
    "html_for_reader",
    "markdown_for_reader",
    "printed_units",
    "reference_descriptions",
    "wrapped",
]

# A unit the tables keep in the OCR's TeX (0^{sec},94; 1^m,22), raised as the paper sets it
UNIT_FORMS = {"sec": "ˢᵉᶜ", "m": "ᵐ", "h": "ʰ", "s": "ˢ", "\\circ": "°"}
UNIT_TEX = re.compile(r"\^\{?(sec|m|h|s|\\circ)\}?")
_UNIT_AFTER_DIGIT = re.compile(r"(?<=\d)\^\{?(sec|m|h|s|\\circ)\}?(?![A-Za-z])")

_SUB = dict(
    zip(
        "0123456789+-−=()aehijklmnoprstuvxβγρφχ",
        "₀₁₂₃₄₅₆₇₈₉₊₋₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓᵦᵧᵨᵩᵪ",
        strict=True,
    )
)
_SUP = dict(
    zip(
        "0123456789+-−=()abcdefghijklmnoprstuvwxyzβγδθφχ",
        "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁻⁼⁽⁾ᵃᵇᶜᵈᵉᶠᵍʰⁱʲᵏˡᵐⁿᵒᵖʳˢᵗᵘᵛʷˣʸᶻᵝᵞᵟᶿᵠᵡ",
        strict=True,
    )
)
# x_(…), x_{…}, x^{…}, x^(…): one level of nested parentheses inside
_SCRIPT = re.compile(r"([_^])(?:\(((?:[^()]|\([^()]*\))*)\)|\{((?:[^{}]|\{[^{}]*\})*)\})")
# a module named in a note, « (verify/printed_numeric) »: the reader needs what, not where
_MODULE = re.compile(r"\s*\((?:pendcli/)?(?:base|data|verify|output|run|numerics|papers)/[\w/.]+\)")


def printed_units(text: str) -> str:
    """``0^{sec},94`` -> 0ˢᵉᶜ,94, ``1^m,21`` -> 1ᵐ,21: a printed number's unit as the page
    raises it (only after a digit: ``e^{p2 t}`` is no unit)."""
    return _UNIT_AFTER_DIGIT.sub(lambda m: UNIT_FORMS[m.group(1)], text)


def _scripted(content: str, table: Mapping[str, str]) -> str | None:
    """``content`` in Unicode sub- or superscripts (a comma kept), None if one has none."""
    out = []
    for ch in content.replace(" ", ""):
        if ch == ",":
            out.append(",")
        elif ch in table:
            out.append(table[ch])
        else:
            return None
    return "".join(out)


def _scripts(text: str, html: bool, plain: bool = False) -> str:
    """Subscripts and superscripts set: Unicode where each character has one; otherwise
    ``<sub>``/``<sup>`` in HTML, and in Markdown too for a subscript (a superscript keeps
    the linear ``^(…)``, which reads as a power)."""

    def one(m: re.Match[str]) -> str:
        mark, content = m.group(1), m.group(2) if m.group(2) is not None else m.group(3)
        content = _scripts(content, html, plain)  # nested ones first
        table = _SUB if mark == "_" else _SUP
        tag = "sub" if mark == "_" else "sup"
        if html:
            return f"<{tag}>{content}</{tag}>"
        unicode = _scripted(content, table)
        if unicode is not None:
            return unicode
        if plain:  # a terminal: lim_(z→0) reads lim(z→0)
            return f"({content})" if mark == "_" else f"^({content})"
        return f"<sub>{content}</sub>" if mark == "_" else f"^({content})"

    return _SCRIPT.sub(one, text)


def for_reader(
    text: str, references: Mapping[str, str] | None = None, html: bool = False, plain: bool = False
) -> str:
    """``text`` (a note, a quote, a printed value; HTML text already escaped when ``html``)
    as a reader reads it: units raised, scripts set, module paths dropped, and each reference
    named in ``references`` (builder name -> what it models) replaced by what it models;
    ``plain`` (a terminal): a script Unicode lacks in parentheses, never a tag."""
    text = _MODULE.sub("", printed_units(text))
    for name, what in (references or {}).items():
        shown = escape(what, quote=False) if html else what
        text = re.sub(rf"(?<![\w.]){re.escape(name)}(?![\w])", f"“{shown}”", text)
    return _scripts(text, html, plain)


# HTML: only the text between tags, outside MathML, styles, scripts and code
_TAG = re.compile(r"(<[^>]*>)")
_KEEP = ("math", "style", "script", "code", "pre")


def html_for_reader(page: str, references: Mapping[str, str] | None = None) -> str:
    """Every text node of ``page`` (escaped HTML) through :func:`for_reader`, and every
    image's alt text, which a screen reader speaks."""
    out: list[str] = []
    inside: list[str] = []
    for piece in _TAG.split(page):
        if piece.startswith("<"):
            name = re.match(r"</?\s*([A-Za-z][\w-]*)", piece)
            tag = name.group(1).lower() if name else ""
            if tag in _KEEP and not piece.endswith("/>"):
                if piece.startswith("</"):
                    if tag in inside:
                        inside.remove(tag)
                else:
                    inside.append(tag)
            out.append(
                piece if inside or ' alt="' not in piece else _alt_for_reader(piece, references)
            )
        elif inside or not piece.strip():
            out.append(piece)
        else:
            out.append(for_reader(piece, references, html=True))
    return "".join(out)


# An image's alt text, which a screen reader speaks (escaped HTML, in double quotes)
_ALT = re.compile(r'(\salt=")([^"]*)(")')


def _alt_for_reader(tag: str, references: Mapping[str, str] | None) -> str:
    """``tag`` with its alt text read as a reader reads it: plain (no tag can stand in an
    attribute), escaped again, quotes included."""

    def read(match: re.Match[str]) -> str:
        shown = for_reader(unescape(match.group(2)), references, plain=True)
        return f"{match.group(1)}{escape(shown, quote=True)}{match.group(3)}"

    return _ALT.sub(read, tag)


def markdown_for_reader(text: str, references: Mapping[str, str] | None = None) -> str:
    """A Markdown page through :func:`for_reader`, outside fenced blocks and code spans,
    where a subscript or superscript is set in Unicode when it has one."""
    out: list[str] = []
    fenced = False
    for line in text.split("\n"):
        if line.startswith("```"):
            fenced = not fenced
        if fenced or line.startswith("```"):
            out.append(line)
            continue
        parts = re.split(r"(`[^`]*`)", line)
        out.append(
            "".join(
                _code_for_reader(p, references) if p.startswith("`") else for_reader(p, references)
                for p in parts
            )
        )
    return "\n".join(out)


def _code_for_reader(span: str, references: Mapping[str, str] | None) -> str:
    """A code span: its printed units raised and scripts set in Unicode where they have one
    (a tag would show as text inside the span); the rest as written."""
    inner = _MODULE.sub("", printed_units(span[1:-1]))
    for name, what in (references or {}).items():
        inner = re.sub(rf"(?<![\w.]){re.escape(name)}(?![\w])", what, inner)

    def one(m: re.Match[str]) -> str:
        content = m.group(2) if m.group(2) is not None else m.group(3)
        unicode = _scripted(content, _SUB if m.group(1) == "_" else _SUP)
        return unicode if unicode is not None else m.group(0)

    return f"`{_SCRIPT.sub(one, inner)}`"


def reference_descriptions(
    texts: list[str], tables: Mapping[str, Mapping[str, Callable[[], object]]]
) -> dict[str, str]:
    """Builder name -> what it models, for each reference of ``tables`` (paper -> its
    reference table) that one of ``texts`` names; only those are built."""
    joined = "\n".join(texts)
    out: dict[str, str] = {}
    for table in tables.values():
        for name, builder in table.items():
            if re.search(rf"(?<![\w.]){re.escape(name)}(?![\w])", joined):
                what = getattr(builder(), "what", "")
                if what:
                    out[name] = str(what)
    return out


# a one-character script in a figure's words (b_n v^n, I_n(π)): not in notes, where an id's
# part (eq_8) would be taken for one
_ONE = re.compile(r"(?:(?<=[^\W_])|(?<=[∫₀-₉)]))([_^])([^\W_])(?!\w)")


def figure_text(text: str) -> str:
    """A figure's title or label without the ledger's notation: ``j_(ν,s)`` -> j$_{ν,s}$
    (mathtext where Unicode has no such script), ``∫_0^x sin^(n+1)`` -> ∫₀ˣ sinⁿ⁺¹,
    ``b_n v^n`` -> bₙ vⁿ, units raised."""

    def one(m: re.Match[str]) -> str:
        content = next(g for g in m.groups()[1:] if g is not None)
        unicode = _scripted(content, _SUB if m.group(1) == "_" else _SUP)
        if unicode is not None:
            return unicode
        spaced = content.replace(" ", "\\ ")  # a space mathtext keeps
        return f"${m.group(1)}{{{spaced}}}$"

    text = _SCRIPT.sub(one, printed_units(text))
    return _ONE.sub(one, text)


def wrapped(text: str, width: int) -> str:
    """``text`` in lines of at most ``width`` characters, broken only at a space outside
    parentheses and mathtext (« (n, β) » and « j$_{ν,s}$ » stay whole)."""
    words: list[str] = []
    depth, dollars, word = 0, 0, ""
    for ch in text:
        depth += (ch in "([") - (ch in ")]")
        dollars += ch == "$"
        if ch == " " and depth <= 0 and dollars % 2 == 0:
            words.append(word)
            word = ""
        else:
            word += ch
    lines: list[str] = []
    for w in [*words, word]:
        if lines and len(lines[-1]) + 1 + len(w) <= width:
            lines[-1] += " " + w
        else:
            lines.append(w)
    return "\n".join(lines)
