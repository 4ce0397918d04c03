"""Which formula of a row's lines its ``printed`` form (or its statement) is.

The ledger writes a row's formula in sympy syntax (``k*sqrt(2)*dt = ...``), the OCR in TeX
(``k\\sqrt{2}\\,dt = ...``). Both are read here as a bag of *atoms*: numbers, Latin letters,
Greek letters and the functions, spelt one way (``\\varphi`` and ``phi`` are ``phi``,
``\\operatorname{tang}`` and ``tan`` are ``tan``, ``kp`` is ``k``, as the ledger spells k′).
:func:`best_pieces` gives, for each formula of the printed form, the piece of the row's lines
(a display formula, one of its lines or equations, or an inline formula) whose bag is
nearest, and how near (the share of atoms in common, 0 to 1).
"""

from __future__ import annotations

import itertools
import re
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from pendcli.output.html.math import MathSegment

__all__ = [
    "Piece",
    "atoms_of_printed",
    "atoms_of_tex",
    "best_pieces",
    "formula_parts",
    "nearness",
    "pieces_of",
]

_GREEK = (
    "varepsilon|epsilon|varphi|lambda|Lambda|theta|Theta|alpha|gamma|Gamma|Delta|delta|omega|"
    "Omega|sigma|beta|zeta|kappa|phi|Phi|psi|Psi|rho|eta|tau|chi|mu|nu|xi|pi|Pi"
)
_FUNCTIONS = (
    "Integral|Derivative|besselj|partial|sqrt|asin|acos|atan|sin|cos|tan|tang|tg|exp|log|arc|lam"
)
_SPELLING = {"varepsilon": "epsilon", "varphi": "phi", "tang": "tan", "tg": "tan", "asin": "sin",
             "acos": "cos", "atan": "tan", "Integral": "int", "Derivative": "d", "lam": "lambda",
             "exp": "e", "besselj": "J", "oo": "infty"}  # fmt: skip
# TeX commands that carry no atom of the formula (layout, grouping, spacing).
_LAYOUT = {"frac", "dfrac", "tfrac", "left", "right", "quad", "qquad", "cdot", "text", "mathrm",
           "mathbf", "operatorname", "begin", "end", "dots", "cdots", "ldots", "big", "Big",
           "bigg", "Bigg", "circ", "prime", "limits", "displaystyle", "mathit", "arc"}  # fmt: skip
_PRINTED_WORDS = {"arcmin", "arcsec", "degree"}  # the units of a printed angle
_TEX_ATOM = re.compile(r"(\\[A-Za-z]+|[A-Za-z])'*(?:_(?:\{([A-Za-z0-9]+)\}|([A-Za-z0-9])))?|(\d+)")
_TEX_NAMED = re.compile(r"\\(?:mathbf|mathrm|mathit|operatorname)\s*\{([^{}]*)\}")
_TEX_FUNCTION = {"arctang": "tan", "arctg": "tan", "tang": "tan", "tg": "tan", "arcsin": "sin"}
_TEX_UNIT = re.compile(r"\^\s*(?:\{\s*(?:sec|m|mm|h|min|s)\s*\}|m\b)")
_PRINTED_IDENT = re.compile(r"[A-Za-z_][A-Za-z_0-9]*|\d+")
_DERIVATIVE = re.compile(rf"\bd(\d*)((?:{_GREEK})|[A-Za-z])(\w*?)_d([A-Za-z])(\d*)\b")
_IDENT_PARTS = re.compile(rf"({_GREEK}|{_FUNCTIONS})|([A-Za-z])|(\d+)")
# the ledger's th_u, th_uk for ∂θ/∂u, ∂²θ/∂u∂k (the memoir's partial derivatives of θ)
_PARTIAL = re.compile(r"\bth_([A-Za-z]+)\b")
# ∫dx spelt Integral(1, (x, …)): the integrand 1 is not printed
_UNIT_INTEGRAND = re.compile(r"\bIntegral\(\s*1\s*,")


def _named(m: re.Match[str]) -> str:
    """``\\operatorname{arc tang}`` as the function it names, ``\\mathbf{E}`` as E."""
    name = re.sub(r"\\[,;!]|\s", "", m.group(1))
    return f"\\{_TEX_FUNCTION[name]}" if name in _TEX_FUNCTION else name


def atoms_of_tex(tex: str) -> Counter[str]:
    """The atoms of a TeX formula: ``\\frac{3}{8} u_0 u_1`` is 3, 8, u_0, u_1 (a subscript
    belongs to its letter)."""
    tex = re.sub(r"\\text\s*\{[^{}]*\}", " ", tex)  # words between the formulas
    tex = re.sub(r"\\(?:begin|end)\s*\{\w+\*?\}", " ", tex)  # \begin{aligned}: no atoms
    tex = _TEX_UNIT.sub(" ", tex)  # 0^{sec}, 94 and 0^m, 35: the unit is no atom
    tex = _TEX_NAMED.sub(_named, tex)
    out: Counter[str] = Counter()
    for base, group, single, number in _TEX_ATOM.findall(tex):
        if number:
            out[number] += 1
            continue
        name = base.lstrip("\\")
        if base.startswith("\\") and name in _LAYOUT:
            continue
        name = _SPELLING.get(name, name)
        out[f"{name}_{group or single}" if group or single else name] += 1
    return out


def atoms_of_printed(printed: str) -> Counter[str]:
    """The atoms of a formula in the ledger's sympy syntax: ``3/8*u0*u1*kpp*t`` is 3, 8,
    u_0, u_1, k, t (trailing digits or ``_x`` are a subscript, a trailing ``p`` a prime)."""
    # a derivative spelt as one name: d2theta_dt2 is d 2 theta d t 2, as d²θ/dt² prints
    printed = _DERIVATIVE.sub(r"d \1 \2\3 d \4 \5", printed)
    printed = _PARTIAL.sub(_partial, _UNIT_INTEGRAND.sub("Integral(", printed))
    out: Counter[str] = Counter()
    for ident in _PRINTED_IDENT.findall(printed):
        if ident in _PRINTED_WORDS:
            continue
        head, *subscripts = ident.split("_")
        atoms = _ident_atoms(head)
        for sub in subscripts:
            # Δ is an operator: Delta_T is Δ T, as the TeX prints it
            subscripted = atoms and atoms[-1] not in ("Delta", "delta") and "_" not in atoms[-1]
            if subscripted and re.fullmatch(r"\d+|[A-Za-z]", sub):
                atoms[-1] += f"_{sub}"
            else:
                atoms += _ident_atoms(sub)
        out.update(atoms)
    return out


def _partial(m: re.Match[str]) -> str:
    """``th_uk`` as ∂²θ/∂u∂k prints: partial 2 theta partial u partial k (``th_uu`` as
    ∂²θ/∂u²: partial 2 theta partial u 2)."""
    variables = m.group(1)
    order = f" {len(variables)}" if len(variables) > 1 else ""
    runs = [(v, len(list(g))) for v, g in itertools.groupby(variables)]
    below = " ".join(f"partial {v}" + (f" {n}" if n > 1 else "") for v, n in runs)
    return f" partial{order} theta {below} "


def _ident_atoms(part: str) -> list[str]:
    """One piece of a name: its letters, Greek letters and functions, its digits a subscript
    of the letter before (``theta0`` is theta_0), a trailing ``p`` its prime (``kp`` is k)."""
    if part.isdigit():
        return [part]
    part = re.sub(rf"^((?:{_GREEK})|[A-Za-z])p+(?=\d*$)", r"\1", part)
    atoms: list[str] = []
    for word, letter, number in _IDENT_PARTS.findall(part):
        if number and atoms:
            atoms[-1] += f"_{number}"
        else:
            atoms.append(_SPELLING.get(word or letter or number, word or letter or number))
    return atoms


def nearness(a: Counter[str], b: Counter[str]) -> float:
    """The share of atoms two bags have in common (multiset Jaccard): 1 when equal; or, if
    nearer, the share once both are read as letters alone (:func:`_letters`)."""
    return max(_jaccard(a, b), _jaccard(_letters(a), _letters(b)))


def _jaccard(a: Counter[str], b: Counter[str]) -> float:
    union = sum((a | b).values())
    return sum((a & b).values()) / union if union else 0.0


# The ledger tells apart letters the memoir reuses (U for the u of (30), A31 for the A after
# (31), beta_e for β, th_u for ∂θ/∂u): read as the letter printed, in lower case, without a
# subscript, and a derivative's d and order digit dropped (the TeX prints primes).
def _letters(bag: Counter[str]) -> Counter[str]:
    out: Counter[str] = Counter()
    for atom, n in bag.items():
        base = atom.split("_")[0]
        if base.isdigit() or base == "d":
            continue
        out[base if len(base) > 1 else base.lower()] += n
    return out


def formula_parts(printed: str) -> list[str]:
    """The formulas of a printed form: split at ``;`` (the ledger's separator)."""
    return [p.strip() for p in printed.split(";") if p.strip()]


@dataclass(frozen=True)
class Piece:
    """A stretch of TeX a mark may cover, and the formula it belongs to."""

    start: int
    end: int
    segment: MathSegment
    whole: bool  # the whole formula


def _depth_zero_cuts(tex: str, separator: re.Pattern[str]) -> list[tuple[int, int]]:
    """``tex`` cut at each match of ``separator`` outside braces: the stretches between."""
    depth, cuts, pos = 0, [], 0
    level = [0] * (len(tex) + 1)
    for i, c in enumerate(tex):
        level[i] = depth
        if i == 0 or tex[i - 1] != "\\":  # \{ and \} are printed braces, not groups
            depth += (c == "{") - (c == "}")
    for m in separator.finditer(tex):
        if level[m.start()] == 0:
            cuts.append((pos, m.start()))
            pos = m.end()
    cuts.append((pos, len(tex)))
    return cuts


_ROWS = re.compile(r"\\\\")
_EQUATIONS = re.compile(r"[,;]?\s*(?:\\q?quad\b|&(?=\s*[^=\s]))")
_LEAD = re.compile(r"(?:\s|&|\\left\\\{|\\q?quad\b|\(\w{1,4}'?\)|,|\\begin\{\w+\*?\}(?:\{\w+\})?)+")
_TRAIL = re.compile(r"(?:\s|&|[.,;]|\\q?quad\b|\\end\{\w+\*?\}|\\\\)+$")


def pieces_of(text: str, segment: MathSegment) -> list[Piece]:
    """A formula whole, and its lines (``\\\\``) and its equations (cut at ``\\quad``) where
    it has several, each without its label, separators and final punctuation."""
    a, b = segment.tex_start, segment.tex_end
    out = [Piece(a, b, segment, True)]
    tex = text[a:b]
    stretches = []
    for x, y in _depth_zero_cuts(tex, _ROWS):
        stretches.append((x, y))
        inner = _depth_zero_cuts(tex[x:y], _EQUATIONS)
        if len(inner) > 1:
            stretches.extend((x + u, x + v) for u, v in inner)
    for x, y in stretches if len(stretches) > 1 else []:
        lead = _LEAD.match(tex, x, y)
        x = lead.end() if lead else x
        trail = _TRAIL.search(tex[x:y])
        y = x + trail.start() if trail else y
        if "=" in tex[x:y] or re.search(r"\d", tex[x:y]):
            out.append(Piece(a + x, a + y, segment, False))
    return out


def best_pieces(
    text: str, segments: Sequence[MathSegment], region: tuple[int, int], printed: str
) -> list[tuple[Piece, float, int]]:
    """For each formula of ``printed`` (numbered in order), the piece of the formulas inside
    ``region`` nearest to it, and how near: the nearest pairs are matched first, each piece
    to one formula; none where the region holds no formula."""
    lo, hi = region
    pieces = [p for s in segments if lo <= s.tex_start and s.tex_end <= hi
              for p in pieces_of(text, s)]  # fmt: skip
    scored = []
    for number, part in enumerate(formula_parts(printed)):
        atoms = atoms_of_printed(part)
        for p in pieces:
            scored.append((nearness(atoms, atoms_of_tex(text[p.start : p.end])), p, number))
    # nearest pairs first (of equals, a piece rather than the whole, then the earliest), each
    # formula and each piece taken once
    scored.sort(key=lambda sp: (-sp[0], sp[1].whole, sp[1].start, sp[2]))
    out: list[tuple[Piece, float, int]] = []
    used: set[tuple[int, int]] = set()
    done: set[int] = set()
    for score, piece, number in scored:
        if number not in done and (piece.start, piece.end) not in used:
            used.add((piece.start, piece.end))
            done.add(number)
            out.append((piece, score, number))
    return sorted(out, key=lambda psn: psn[2])
