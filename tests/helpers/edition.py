"""The HTML edition's rows and the checks of where their marks sit, read from the tables and
the paper's text here (not by the code under test): shared by the edition's tests."""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Sequence

from helpers.ledgers import committed_ledger
from pendcli.data.tables import load_paper_table
from pendcli.output.html.marks import Placement, place_marks
from pendcli.output.html.math import math_segments


def edition_rows(paper: str) -> tuple[list[dict[str, object]], list[dict[str, object]]]:
    """The rows as the tables print them (no computation: placement needs only the strings)."""
    claims: list[dict[str, object]] = [
        {"id": c.id, "published": c.published, "as_printed": c.as_printed, "ocr": c.ocr,
         "source": c.source, "note": c.note, "verdict": "agrees", "lines": c.lines}
        for c in load_paper_table(paper).claims
    ]  # fmt: skip
    equations: list[dict[str, object]] = [
        {"id": r.id, "equation": r.equation, "section": r.section, "statement": r.statement,
         "status": r.status, "wrong_term": r.wrong_term, "note": r.note or "",
         "lines": r.lines, "quote": r.quote, "reading": r.reading, "corrected": r.corrected,
         "printed": r.printed}
        for r in committed_ledger(paper).rows
    ]  # fmt: skip
    return claims, equations


_QUOTED = re.compile(r"«\s*(.+?)\s*»")


def _own_strings(row: dict[str, object]) -> set[str]:
    """What a row may be marked by, read from the row here (not by the code under test): a
    claim's printed forms and the words its OCR note quotes, a ledger row's wrong term,
    label and quoted words."""
    fields = ("source", "section", "ocr", "statement", "note")
    quoted = {q for k in fields for q in _QUOTED.findall(str(row.get(k) or ""))}
    term = row.get("wrong_term")
    terms = {term} if isinstance(term, str) else set(term or ())  # type: ignore[arg-type]
    own = {str(row.get(k) or "") for k in ("published", "as_printed", "equation")}
    return {s for s in own | terms | quoted if s}


def _quotes_of(row: dict[str, object]) -> list[str]:
    """The row's ``quote`` field (a string or a list), read here."""
    value = row.get("quote")
    return [value] if isinstance(value, str) else [str(q) for q in value or ()]  # type: ignore[attr-defined]


def quote_is_printed(text: str, row: dict[str, object], mark: Placement,
                      marks: Sequence[Placement]) -> bool:  # fmt: skip
    """The pieces of a quote's mark lie within one verbatim occurrence of the quote inside
    the row's lines (counted here) and cover every word of it: what they leave uncovered
    is no more than the $ of a formula, blanks and punctuation."""
    quote, (first, last) = mark.forms[0], row["lines"]  # type: ignore[misc]
    pieces = [(o.start, o.end) for o in marks
              if (o.row_id, o.how, o.forms) == (mark.row_id, "quote", mark.forms)]  # fmt: skip
    lines = text.split("\n")
    lo = sum(len(line) + 1 for line in lines[: first - 1])
    hi = lo + len("\n".join(lines[first - 1 : last]))
    at = text.find(quote, lo, hi)
    while at >= 0:
        if all(at <= a and b <= at + len(quote) for a, b in pieces):
            left = list(text[at : at + len(quote)])
            for a, b in pieces:
                left[a - at : b - at] = " " * (b - a)
            return not re.search(r"\w", "".join(left))
        at = text.find(quote, at + 1, hi)
    return False


def _digits(s: str) -> Counter[str]:
    return Counter(re.findall(r"\d+", s))


# A number of the ledger's sympy syntax: not the digits of a name (A31, d2U_dz2, theta0), which
# tell letters apart or spell a derivative the TeX prints with primes or subscripts.
_NUMBER_TOKEN = re.compile(r"(?<![A-Za-z_0-9])\d+")
_SUBSCRIPTED = re.compile(r"\b(?:[a-z]|theta|phi|psi|rho|omega|varphi|alpha|beta)(\d)\b")


def _digit_share(marked: str, part: str) -> float:
    """The share of the printed formula's numbers (its digits, exponents and subscripts)
    that the marked TeX prints too."""
    part = re.sub(r"\bIntegral\(\s*1\s*,", "Integral(", part)  # ∫dx: no integrand 1 printed
    wanted = Counter(_NUMBER_TOKEN.findall(part))  # its numbers, and a name's subscript digit
    wanted += Counter(m.group(1) for m in _SUBSCRIPTED.finditer(part))
    return sum((wanted & _digits(marked)).values()) / sum(wanted.values()) if wanted else 1.0


def formula_is_printed(marked: str, part: str, others: Sequence[str] = ()) -> bool:
    """The marked TeX prints most of the formula's numbers, and no other formula of the
    row's lines more of them: a neighbouring formula misses some."""
    share = _digit_share(marked, part)
    return share >= 0.75 and all(_digit_share(o, part) <= share for o in others)


def misplaced(paper: str, text: str, claims: list[dict[str, object]],
               equations: list[dict[str, object]]) -> list[str]:  # fmt: skip
    """The marks that are not their row's printed string, wrong term, label, quoted words or
    printed formula, or that lie outside their row's lines (lines counted here)."""
    rows = {str(r["id"]): r for r in [*claims, *equations]}
    segments = [(s.tex_start, s.tex_end) for s in math_segments(text)]
    bad = []
    marks = place_marks(text, claims, equations)[0]
    bad += [f"{r} not marked" for r in rows if r not in {m.row_id for m in marks}]
    for m in marks:
        row, marked = rows[m.row_id], text[m.start : m.end]
        if m.how == "formula":  # a formula printed over several displays: all of them
            marked = " ".join(text[o.start : o.end] for o in marks
                              if (o.row_id, o.forms) == (m.row_id, m.forms))  # fmt: skip
        first, last = row["lines"]  # type: ignore[misc]
        if not first <= line_of(text, m.start) <= line_of(text, m.end - 1) <= last:
            bad.append(f"{m.key}: lines {line_of(text, m.start)} not in {row['lines']}")
        elif m.how == "formula":
            parts = [p.strip() for p in str(row.get("printed") or row["statement"]).split(";")]
            inside = any(a <= m.start and m.end <= b for a, b in segments)
            others = [text[a:b] for a, b in segments
                      if line_of(text, a) >= first and line_of(text, b) <= last]  # fmt: skip
            printed_ok = not row.get("printed") or formula_is_printed(marked, m.forms[0], others)
            if not (inside and m.forms[0] in parts and printed_ok):
                bad.append(f"{m.key}: {marked!r} is not {m.forms[0]!r}")
        elif m.how == "quote" and m.forms[0] in _quotes_of(row):
            if not quote_is_printed(text, row, m, marks):
                bad.append(f"{m.key}: {marked!r} is not {m.forms[0]!r} within its lines")
        elif m.how == "first":
            if row.get("printed"):  # a row with a printed form is placed by it
                bad.append(f"{m.key}: at the first formula of its lines, not by its printed form")
        elif not any(same_form(marked, form) for form in _own_strings(row)):
            bad.append(f"{m.key}: {marked!r} is none of {sorted(_own_strings(row))}")
    return bad


def same_form(printed: str, form: str) -> bool:
    """The printed text is the form, up to the OCR's spacing and TeX spelling."""

    def squash(s: str) -> str:
        s = re.sub(r"\\q?quad|\\[,;!]|\s|\$", "", s)
        for tex, char in (("\\theta", "θ"), ("\\pi", "π"), ("\\cdot", "·"), ("^{\\circ}", "°")):
            s = s.replace(tex, char)
        return s

    return squash(printed) == squash(form)


def line_of(text: str, at: int) -> int:
    return text[:at].count("\n") + 1
