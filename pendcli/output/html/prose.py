"""The edition's paragraphs as the paper prints them, not as the OCR broke them.

The OCR text breaks a paragraph where the printed page ended a line or a page: a word cut
at its hyphen (« résis- », a blank line, « tance »), a sentence cut in two paragraphs (« un
mètre de », a blank line, « longueur »), or the two halves of a word on either side of a
running head (« quan- », the journal's foot, « tités »). A paragraph of the text is a run of
non-blank lines (:func:`pendcli.data.reading.prose_paragraphs`); here the edition joins a
paragraph to the one before when it continues it (the one before ends without a full stop,
the next begins in lower case), removing the hyphen of a cut word, and sets the page break
that fell inside after the joined paragraph. Within a paragraph, lines are joined by a space
(or by nothing, at a cut word); a line of a table (a tab) or of a list keeps its break.

The text's lines that are not the paper's prose are told apart here too: a page's running head
or foot (:func:`page_breaks`), a title (:func:`is_heading`), the digitisation's cover page
(:func:`front_matter_end`).
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable, Sequence

__all__ = [
    "continues",
    "front_matter_end",
    "is_heading",
    "join_continued",
    "page_breaks",
    "prose_html",
    "split_at_heads",
]

# a line, or a paragraph, that ends a sentence, a display formula or a title
_ENDED = re.compile(r"[.:;?!»)\]$*]\s*$")
# a word cut at its line end: a letter, the hyphen, perhaps the close of an emphasis
_CUT = re.compile(r"(?<=[^\W\d_])-(\**)\s*$")
# the same in the rendered HTML: the hyphen before closing tags
_CUT_HTML = re.compile(r"(?<=[^\W\d_])-((?:</[a-z]+>)*)\s*$")
# a compound's second word: the hyphen is the word's own (« peut-être », « dit-il »)
_COMPOUND = re.compile(r"(?:être|à|dire|il|elle|on|ils|elles|même|mêmes|ci|là)\b")
_TABULAR = "\u2003"  # a tab of the text, as the edition sets it


def continues(before: str, after: str) -> str | None:
    """How the paragraph ``after`` continues ``before``: ``"cut"`` (a word cut at its
    hyphen), ``"hyphen"`` (a compound cut at its own hyphen, kept), ``"space"`` (a sentence
    cut), or None (a paragraph of its own)."""
    b, a = before.rstrip(), after.lstrip()
    if not b or not a or a.startswith("$$") or not a[0].islower():
        return None
    if _CUT.search(b):
        return "hyphen" if _COMPOUND.match(a) else "cut"
    return None if _ENDED.search(b) else "space"


def prose_html(html: str, heading: bool = False) -> str:
    """A paragraph's rendered lines joined: a space between lines, nothing at a cut word;
    a heading's lines and a table's or a list's rows keep their break."""
    lines = html.strip().split("\n")
    out = lines[0]
    for before, line in itertools.pairwise(lines):
        kept = heading or _TABULAR in before or _TABULAR in line
        if kept or line.lstrip().startswith(("- ", "— ")) or not line.strip():
            out += "<br>" + line
        elif _CUT_HTML.search(out) and line.lstrip()[:1].islower():
            out = _CUT_HTML.sub(r"\1", out) + line.lstrip()
        else:
            out += " " + line.lstrip()
    return out


Block = dict[str, object]


def join_continued(
    blocks: list[Block], texts: list[str], dense: Callable[[list[dict[str, object]]], bool]
) -> list[Block]:
    """``blocks`` (each with its text in ``texts``) with each prose paragraph that continues
    the one before joined to it, and a page break between the two set after them."""
    out: list[Block] = []
    held: list[Block] = []  # page breaks inside the paragraph being joined
    last = ""  # the text of the last prose block of ``out``
    for block, text in zip(blocks, texts, strict=True):
        if block["pagebreak"]:
            (held if out and _prose(out[-1]) else out).append(block)
            continue
        how = continues(last, text) if out and _prose(out[-1]) and _prose(block) else None
        if how is None:
            out += held
            held = []
            out.append(block)
        else:
            out[-1] = _joined(out[-1], block, how, dense)
        last = text
    return out + held


def _prose(block: Block) -> bool:
    return not (block["pagebreak"] or block["heading"] or block["figure"] or block["front"])


def _joined(
    first: Block, second: Block, how: str, dense: Callable[[list[dict[str, object]]], bool]
) -> Block:
    from markupsafe import Markup

    head = str(first["html"])
    if how == "cut":
        head = _CUT_HTML.sub(r"\1", head)
    elif how == "space":
        head += " "
    notes = [*first["notes"], *second["notes"]]  # type: ignore[misc]
    return {**first, "html": Markup(head + str(second["html"])), "notes": notes,
            "dense": dense(notes)}  # fmt: skip


# --- the text's other lines: running heads, titles, the cover page --------------------------


# A running head or foot the OCR kept as a line of the text: the journal's foot at the bottom
# of a signature's first page ("Ann. de Mathémat., 4^e série, t. VIII. (Avril 1908.) 10"),
# or a page number alone ("( 146 )", "— 146 —").
_RUNNING_HEAD = re.compile(
    r"^[ \t]*(?:Ann\. de Math[ée]mat\.,[^\n$]*\(\w+ \d{4}\.?\)[ \t]*\d*"
    r"|\([ \t]*\d{1,3}[ \t]*\)|— \d{1,3} —)[ \t]*$",
    re.MULTILINE,
)


def page_breaks(text: str) -> list[tuple[int, int]]:
    """The lines of ``text`` that are a page's running head or foot, not the paper's text."""
    return [m.span() for m in _RUNNING_HEAD.finditer(text)]


def split_at_heads(
    text: str, spans: Sequence[tuple[int, int]], cuts: Sequence[tuple[int, int]]
) -> list[tuple[int, int]]:
    """The paragraphs, each running head inside one cut out as a block of its own."""
    out = []
    for a, b in spans:
        for x, y in (c for c in cuts if a <= c[0] and c[1] <= b):
            out += [(a, x), (x, y)]
            a = y
        out.append((a, b))
    return [(a, b) for a, b in out if text[a:b].strip()]


_NUMERAL = re.compile(r"[IVX]+\.(?:\s*—.*)?")


def is_heading(paragraph: str) -> bool:
    """A title of the paper or of a part: a Markdown heading, or one line in capitals
    (« SUR LE PENDULE DE LONGUEUR VARIABLE », « II. — LE MOUVEMENT … ») or a part's numeral
    alone (« I. »)."""
    line = paragraph.strip()
    if line.startswith("#"):
        return True
    if "$" in line or len(line) > 120 or line.count("\n") > 2:
        return False
    letters = [c for c in line if c.isalpha()]
    return bool(_NUMERAL.fullmatch(line)) or (len(letters) >= 4 and line.upper() == line)


# The digitisation's cover page (NUMDAM's title page, copyright and terms of use) ends with
# the archive's address, within the first lines of the text.
_COVER_END = re.compile(r"^<?https?://www\.numdam\.org/?>?[ \t]*$", re.MULTILINE)


def front_matter_end(text: str, within: int = 40) -> int:
    """Where the digitisation's cover page ends (0 where the text has none): after the last
    line of the first ``within`` lines that is the archive's bare address."""
    head = "\n".join(text.split("\n")[:within])
    ends = [m.end() for m in _COVER_END.finditer(head)]
    return ends[-1] if ends else 0
