"""The edition's paragraphs as the paper prints them, not as the OCR broke them.

The OCR text breaks a paragraph where the printed page ended a line or a page: a word cut
at its hyphen (« résis- », a blank line, « tance »), a sentence cut in two paragraphs (« un
mètre de », a blank line, « longueur »), or the two halves of a word on either side of a
running head (« quan- », the journal's foot, « tités »). A paragraph of the text is a run of
non-blank lines (:func:`pendcli.core.reading.prose_paragraphs`); here the edition joins a
paragraph to the one before when it continues it (the one before ends without a full stop,
the next begins in lower case), removing the hyphen of a cut word, and sets the page break
that fell inside after the joined paragraph. Within a paragraph, lines are joined by a space
(or by nothing, at a cut word); a line of a table (a tab) or of a list keeps its break.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable

__all__ = ["continues", "join_continued", "prose_html"]

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
