"""The OCR's TeX as MathML, converted at build time, and a legible plain form where it fails.

The texts in ``tables/papers/`` write mathematics as ``$$…$$`` (display) and ``$…$``
(inline) TeX. :func:`to_mathml` converts one formula with latex2mathml, so the pages need no
script and no network; a formula it cannot convert (an exception, or a command it leaves as
raw text) is rendered by :func:`plain_math`, a cleaned plain-text reading (``\\frac{a}{b}``
as ``(a)/(b)``, Greek letters as Unicode), and counted. Marks are kept inside a formula by
wrapping their TeX in ``{\\color{#fe0NNN} …}``: the converter turns that into an
``<mstyle mathcolor>`` that :func:`mark_mathml` replaces by the mark's element.

The converter copies ``\\text{…}`` verbatim and keeps ``\\href``, so the text's TeX could
carry markup into the page: :func:`sanitise_mathml` parses its output and writes back only
MathML elements and attributes of an allowlist, every text and value escaped; a formula with
anything else (an element not of MathML, ``</math>`` inside it) is not converted.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from html.parser import HTMLParser

__all__ = [
    "MATH",
    "MathSegment",
    "mark_mathml",
    "math_segments",
    "plain_math",
    "sanitise_mathml",
    "to_mathml",
    "typeset",
    "wrap_marks",
]

# A display formula $$…$$ (may span lines) or an inline one $…$ (within a line).
MATH = re.compile(r"\$\$(.+?)\$\$|\$([^$\n]+?)\$", re.DOTALL)
_COLOUR = "#fe{:04x}"
_MSTYLE = re.compile(r'<mstyle mathcolor="#fe([0-9a-f]{4})">|<mstyle\b[^>]*>|</mstyle>')


@dataclass(frozen=True)
class MathSegment:
    """One formula of the text: the span of its TeX (inside the dollars) and its kind."""

    start: int  # first character of the $ or $$
    end: int  # after the closing $ or $$
    tex_start: int
    tex_end: int
    display: bool


def math_segments(text: str) -> list[MathSegment]:
    """Every formula of ``text`` in reading order."""
    out = []
    for m in MATH.finditer(text):
        group = 1 if m.group(1) is not None else 2
        out.append(MathSegment(m.start(), m.end(), m.start(group), m.end(group), group == 1))
    return out


# A pure function of its arguments: a page, its statistics and its marked copy convert the
# same formulas (3,000 in the three papers), each once per process.
@lru_cache(maxsize=8192)
def to_mathml(tex: str, display: bool) -> str | None:
    """``tex`` as a ``<math>`` element, or None where latex2mathml cannot render it."""
    from latex2mathml.converter import convert

    # latex2mathml reads aligned as plain text with literal &: an array aligns the same way.
    tex = re.sub(r"\\begin\{(?:aligned|align\*?|split)\}", r"\\begin{array}{rlrlrlrl}", tex)
    tex = re.sub(r"\\end\{(?:aligned|align\*?|split)\}", r"\\end{array}", tex)
    # a unit printed as an exponent of a number (0^{sec}, 94; 1^m, 21) is a word, upright
    tex = _UNIT.sub(lambda m: "^{\\text{" + (m.group(1) or m.group(2)) + "}}", tex)
    # a decimal comma (5,14; 0^{sec},94) is part of its number: TeX's {,}, no space after it
    tex = _AFTER_UNIT.sub(r"\1{,}", _DECIMAL_COMMA.sub("{,}", tex))
    try:
        mathml = convert(tex.strip(), display="block" if display else "inline")
    except Exception:
        return None
    # An unknown command comes out as a token holding its backslash: not rendered.
    if re.search(r"<m[io][^>]*>(?:\\|&(?![#\w]+;))", mathml) or "<merror" in mathml:
        return None
    return sanitise_mathml(typeset(decimal_numbers(mathml)))


_UNIT = re.compile(r"(?<=\d)\^\s*(?:\{\s*(sec|m|mm|h|min|s)\s*\}|(?<!\{)(m|h|s)(?![A-Za-z]))")
_DECIMAL_COMMA = re.compile(r"(?<=\d),(?=\d)")
_AFTER_UNIT = re.compile(r"(\^\{\\text\{[a-z]+\}\}),(?=\s*\d)")
_GROUPED_COMMA = "<mrow><mo>&#x0002C;</mo></mrow>"


def decimal_numbers(mathml: str) -> str:
    """A decimal comma in latex2mathml's MathML (``{,}``: an operator, set with a space after
    it, « 5, 14 ») as the paper prints it: one number ``<mn>5,14</mn>``, or, after a unit set
    as an exponent (0ˢᵉᶜ,94) or beside a mark's edge, a comma with no space around it."""
    out = re.sub(rf"<mn>(\d+)</mn>{_GROUPED_COMMA}<mn>(\d+)</mn>", r"<mn>\1,\2</mn>", mathml)
    return out.replace(_GROUPED_COMMA, '<mo lspace="0" rspace="0">,</mo>')


_PRIMES = r"<mi>(?P<p>(?:&#x0203[234];)+)</mi>"
_ONE = r"<mi>[^<]*</mi>|<mn>[^<]*</mn>|<mrow>(?:(?!</?mrow>).)*</mrow>"
_FUNCTION = r"<mi>(?:sin|cos|tan|cot|sec|log|exp)</mi>"
# sin(x), sin[…] take no space; nor a function ending its group
_NOT_AN_ARGUMENT = r"(?!(?:<mrow>)?<mo[^>]*>(?:&#x00028;|&#x0005B;)|</)"


def typeset(mathml: str) -> str:
    """latex2mathml's MathML as TeX sets it, where Chromium would not: a prime (T', φ'_0) is
    the prime glyph after its letter (as a superscript it is set twice raised and tiny, far
    from the letter); sin, cos … have TeX's thin spaces around them (Chromium sets
    ``<mi>l</mi><mi>cos</mi><mi>ω</mi>`` as one word, "lcosω")."""
    prime = r'<mo lspace="0" rspace="0">\g<p></mo>'
    out = re.sub(rf"<msup>({_ONE}){_PRIMES}</msup>", r"\1" + prime, mathml)
    out = re.sub(rf"<msubsup>({_ONE})({_ONE}){_PRIMES}</msubsup>",
                 r"<msub><mrow>\1" + prime + r"</mrow>\2</msub>", out)  # fmt: skip
    function = rf"({_FUNCTION}|<msup>{_FUNCTION}(?:{_ONE})</msup>)"
    out = re.sub(function + _NOT_AN_ARGUMENT, r'\1<mspace width="0.1667em" />', out)
    # and after a letter or number before it: l sin θ, not "lsin θ"
    before = rf"(</mi>|</mn>|</msub>|</msup>)(?=<msup>{_FUNCTION}|{_FUNCTION})"
    return re.sub(before, r'\1<mspace width="0.1667em" />', out)


def wrap_marks(tex: str, spans: list[tuple[int, int, int]]) -> str:
    """``tex`` with each (start, end, number) span wrapped in its colour group.

    Spans are relative to ``tex``, each disjoint from the others or holding them whole (a
    wrong table entry around its claim's mark), the outer first where two are equal; a span
    whose braces do not balance (it would break the formula) is widened to the enclosing
    balanced text by the caller.
    """
    # at one place: groups close before others open, inner ones close first, outer open first
    events = sorted(
        [(start, 1, -end, rank, number) for rank, (start, end, number) in enumerate(spans)]
        + [(end, 0, -start, -rank, number) for rank, (start, end, number) in enumerate(spans)]
    )
    out, pos = [], 0
    for at, opens, _, _, number in events:
        out.append(tex[pos:at])
        out.append("{\\color{" + _COLOUR.format(number) + "}" if opens else "}")
        pos = at
    out.append(tex[pos:])
    return "".join(out)


def balanced(tex: str) -> bool:
    """Braces and \\left/\\right pairs balance in ``tex`` (so it can be wrapped in a group)."""
    depth = 0
    for c in re.sub(r"\\[{}]", "", tex):
        depth += (c == "{") - (c == "}")
        if depth < 0:
            return False
    left = len(re.findall(r"\\left\b", tex))
    return depth == 0 and left == len(re.findall(r"\\right\b", tex)) and "&" not in tex


def mark_mathml(
    mathml: str, open_tag: Callable[[int], str], after: Callable[[int], str], count: int
) -> str:
    """Replace each colour group numbered n (0 <= n < ``count``, the first group of that
    number) by ``open_tag(n)`` … ``</mrow>`` ``after(n)``; another group of a mark's colour
    (written in the text's own TeX) stays the ``<mstyle>`` it is."""
    out, pos, stack, used = [], 0, [], set()
    for m in _MSTYLE.finditer(mathml):
        out.append(mathml[pos : m.start()])
        pos = m.end()
        number = int(m.group(1), 16) if m.group(1) is not None else -1
        if 0 <= number < count and number not in used:
            used.add(number)
            stack.append(number)
            out.append(open_tag(number))
        elif m.group(0).startswith("<mstyle"):
            stack.append(-1)
            out.append(m.group(0))
        else:
            number = stack.pop() if stack else -1
            out.append("</mstyle>" if number < 0 else "</mrow>" + after(number))
    out.append(mathml[pos:])
    return "".join(out)


# --- the converter's MathML, filtered through an allowlist ------------------------------------

# Presentation MathML only: no <semantics>/<annotation-xml> (which may hold HTML), no <maction>.
MATHML_ELEMENTS = frozenset({
    "math", "mrow", "mi", "mn", "mo", "ms", "mtext", "mspace", "msub", "msup", "msubsup",
    "mfrac", "msqrt", "mroot", "mstyle", "mpadded", "mphantom", "mfenced", "menclose", "munder",
    "mover", "munderover", "mmultiscripts", "mprescripts", "none", "mtable", "mtr", "mtd",
})  # fmt: skip
_LENGTH = (
    r"[+-]?(?:\d{1,6}(?:\.\d{0,6})?|\.\d{1,6})(?:em|ex|px|pt|pc|in|cm|mm|mu|%)?"
    r"|(?:negative)?(?:very){0,2}(?:thin|thick)mathspace|(?:negative)?mediummathspace"
)
_BOOLEAN = "true|false"


def _list_of(pattern: str, most: int = 16) -> str:
    """One to ``most`` values matching ``pattern``, a space apart."""
    return f"(?:{pattern})(?: (?:{pattern})){{0,{most - 1}}}"


_ALIGN = _list_of("left|center|right|top|bottom|baseline|axis")
_LINES = _list_of("none|solid|dashed")
_FENCE = r"[()\[\]{}|‖⟨⟩⌊⌋⌈⌉.,;]{0,3}"
# Each allowed attribute and the values it may take: words, numbers, lengths, colours; never
# a URL, a style or a script (href, style, class, on* are not in the list).
MATHML_ATTRIBUTES: dict[str, re.Pattern[str]] = {
    name: re.compile(pattern)
    for names, pattern in (
        ("xmlns", re.escape("http://www.w3.org/1998/Math/MathML")),
        ("display", "block|inline"),
        ("mathvariant", "normal|bold|italic|bold-italic|double-struck|bold-fraktur|script|"
         "bold-script|fraktur|sans-serif|bold-sans-serif|sans-serif-italic|"
         "sans-serif-bold-italic|monospace|initial|tailed|looped|stretched"),
        ("displaystyle stretchy fence separator symmetric largeop movablelimits accent "
         "accentunder", _BOOLEAN),
        ("form", "prefix|infix|postfix"),
        ("scriptlevel", r"[+-]?\d{1,2}"),
        ("lspace rspace width height depth voffset minsize maxsize", _LENGTH),
        ("linethickness", rf"{_LENGTH}|thin|medium|thick"),
        ("mathcolor mathbackground", r"#[0-9a-fA-F]{3}|#[0-9a-fA-F]{6}|[a-zA-Z]{1,20}"),
        ("columnalign rowalign", _ALIGN),
        ("columnlines rowlines frame", _LINES),
        ("rowspacing columnspacing", _list_of(_LENGTH)),
        ("columnspan rowspan", r"\d{1,3}"),
        ("linebreak", "auto|newline|nobreak|goodbreak|badbreak|indentingnewline"),
        ("notation", _list_of("[a-z]{1,20}", 6)),
        ("open close separators", _FENCE),
    )
    for name in names.split()
}  # fmt: skip
_ENTITIES = frozenset({"amp", "lt", "gt", "quot", "apos"})
_CHARREF = re.compile(r"x[0-9a-fA-F]{1,6}|[0-9]{1,7}")


class UnsafeMathML(ValueError):
    """The converter's output holds what the allowlist does not (or does not parse)."""


def _xml_char(code: int) -> bool:
    """A character XML 1.0 allows in a document."""
    allowed = (0x20, 0xD7FF), (0xE000, 0xFFFD), (0x10000, 0x10FFFF)
    return code in (0x9, 0xA, 0xD) or any(low <= code <= high for low, high in allowed)


def _escape(text: str) -> str:
    if not all(_xml_char(ord(c)) for c in text):
        raise UnsafeMathML("a character XML does not allow")
    text = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return text.replace('"', "&quot;").replace("\r", " ").replace("\n", " ")


class _Filter(HTMLParser):
    """Re-writes a ``<math>`` element: allowed elements with their allowed attributes, each
    end tag closing the element open, text and references escaped; raises on anything else."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=False)  # references come back as they were written
        self.out: list[str] = []
        self.open: list[str] = []
        self.closed = False  # the <math> element has ended: nothing may follow it

    def _tag(self, tag: str, attrs: list[tuple[str, str | None]], end: str) -> None:
        if tag not in MATHML_ELEMENTS or self.closed or (tag == "math") == bool(self.open):
            raise UnsafeMathML(f"element <{tag}> here")
        kept: dict[str, str] = {}  # a repeated attribute: the first, as HTML reads it
        for name, value in attrs:
            if name not in kept and value is not None and name in MATHML_ATTRIBUTES:
                kept[name] = value
        written = "".join(
            f' {name}="{_escape(value)}"'
            for name, value in kept.items()
            if MATHML_ATTRIBUTES[name].fullmatch(value)
        )
        self.out.append(f"<{tag}{written}{end}")

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self._tag(tag, attrs, ">")
        self.open.append(tag)

    def handle_startendtag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if not self.open:
            raise UnsafeMathML("an empty formula")
        self._tag(tag, attrs, " />")

    def handle_endtag(self, tag: str) -> None:
        if not self.open or self.open[-1] != tag:
            raise UnsafeMathML(f"</{tag}> closes no open element")
        self.out.append(f"</{self.open.pop()}>")
        self.closed = not self.open

    def handle_data(self, data: str) -> None:
        if self.open:
            self.out.append(_escape(data))
        elif data.strip():
            raise UnsafeMathML("text outside <math>")

    def handle_charref(self, name: str) -> None:
        if not self.open or not _CHARREF.fullmatch(name):
            raise UnsafeMathML(f"character reference &#{name};")
        if not _xml_char(int(name[1:], 16) if name.startswith("x") else int(name)):
            raise UnsafeMathML(f"character reference &#{name};")
        self.out.append(f"&#{name};")

    def handle_entityref(self, name: str) -> None:
        if not self.open or name not in _ENTITIES:
            raise UnsafeMathML(f"entity &{name};")
        self.out.append(f"&{name};")

    def unknown_decl(self, data: str) -> None:
        raise UnsafeMathML("a declaration")

    def handle_decl(self, decl: str) -> None:
        raise UnsafeMathML("a declaration")

    def handle_comment(self, data: str) -> None:
        raise UnsafeMathML("a comment")

    def handle_pi(self, data: str) -> None:
        raise UnsafeMathML("a processing instruction")


def sanitise_mathml(mathml: str) -> str | None:
    """``mathml`` re-written through the allowlist (:data:`MATHML_ELEMENTS`,
    :data:`MATHML_ATTRIBUTES`: an attribute not listed, or with a value its pattern refuses,
    is dropped), or None where it holds another element or does not parse as one ``<math>``
    element: such a formula is shown as its plain reading, escaped."""
    parser = _Filter()
    try:
        parser.feed(mathml)
        parser.close()
    except UnsafeMathML:
        return None
    return "".join(parser.out) if parser.closed else None


# --- the plain reading of a formula that does not convert ------------------------------------

_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "varepsilon": "ε", "epsilon": "ε",
    "theta": "θ", "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ",
    "sigma": "σ", "tau": "τ", "varphi": "φ", "phi": "φ", "psi": "ψ", "omega": "ω",
    "Delta": "Δ", "Gamma": "Γ", "Omega": "Ω", "Phi": "Φ", "Psi": "Ψ", "partial": "∂",
    "infty": "∞", "int": "∫", "cdot": "·", "dots": "…", "cdots": "…", "ldots": "…",
    "geq": "≥", "leq": "≤", "circ": "°", "prime": "′", "times": "×", "pm": "±", "sum": "Σ",
}  # fmt: skip
_SUPERSCRIPT = str.maketrans("0123456789+-n", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻ⁿ")
_SUBSCRIPT = str.maketrans("0123456789+-", "₀₁₂₃₄₅₆₇₈₉₊₋")
_GROUP = r"\{((?:[^{}]|\{[^{}]*\})*)\}"


def plain_math(tex: str) -> str:
    """A legible plain-text reading of ``tex``: no backslash commands, no braces."""
    s = tex
    for _ in range(4):  # nested fractions and roots, innermost first
        s = re.sub(rf"\\[dt]?frac\s*{_GROUP}\s*{_GROUP}", r"(\1)/(\2)", s)
        s = re.sub(rf"\\sqrt\s*{_GROUP}", r"√(\1)", s)
    s = re.sub(r"\\(?:left|right|big|Big|bigg)\s*([()\[\]|.]|\\[{}])", r"\1", s)
    s = re.sub(r"\\(?:q?quad|[,;:!]|\\)", " ", s)
    s = re.sub(r"\\(?:begin|end)\{[^}]*\}", " ", s)
    s = re.sub(r"\\(?:text|mathrm|mathbf|operatorname|overline|bar)\s*" + _GROUP, r"\1", s)
    s = re.sub(r"\\([A-Za-z]+)", lambda m: _GREEK.get(m.group(1), m.group(1)), s)
    s = re.sub(r"\^\{?([0-9+\-n]{1,3})\}?(?![0-9])", lambda m: _sup(m.group(1)), s)
    s = re.sub(r"_\{?([0-9+\-]{1,3})\}?(?![0-9])", lambda m: m.group(1).translate(_SUBSCRIPT), s)
    s = s.replace("\\{", "{").replace("\\}", "}").replace("{", "").replace("}", "")
    s = s.replace("&", "").replace("\\", "")
    return re.sub(r"[ \t]+", " ", s).strip()


def _sup(digits: str) -> str:
    return digits.translate(_SUPERSCRIPT)
