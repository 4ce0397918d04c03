"""A reference never holds a copy of the printed form it judges: the module that builds a row's
reference (the paper's ``Paper.references``) does not type the row's printed formula, its
reading or its correction. A copy would make the engine compare the text with itself.

A reference may type an earlier equation it rests on (a definition, the preceding step): that
is another row's printed form, and its own row is judged against a reference built elsewhere.
The comparison is textual, on the Python source with whitespace and the ``sp.``/``np.``
prefixes removed, for each side of each equation of at least 16 characters that holds a name
or a power (shorter sides are symbols and small products any derivation writes)."""

from __future__ import annotations

import inspect
import re
import tomllib
from functools import cache
from pathlib import Path

import pytest

from pendcli.papers.registry import paper

TABLES = Path(__file__).resolve().parents[2] / "tables"
FIELDS = ("printed", "reading_formula", "corrected_formula")
_SIDES = re.compile(r";|(?<![<>=!])=(?!=)")


def normalised(text: str) -> str:
    return re.sub(r"\b(?:sp|sympy|mpmath|np|math)\.", "", re.sub(r"\s+", "", text))


@cache
def module_source(path: str) -> str:
    return normalised(Path(path).read_text(encoding="utf-8"))


def copied_sides(entry: dict[str, object], source: str) -> list[str]:
    """The sides of the row's formulas that ``source`` (normalised) holds verbatim."""
    found = []
    for field in FIELDS:
        text = entry.get(field)
        for part in _SIDES.split(text) if isinstance(text, str) else ():
            side = normalised(part)
            if len(side) >= 16 and re.search(r"[a-z]{2}|\*\*", side) and side in source:
                found.append(f"{field}: {side}")
    return found


def _entries(key: str) -> list[dict[str, object]]:
    with (TABLES / "equations" / f"{key}.toml").open("rb") as file:
        return [e for e in tomllib.load(file)["equation"] if "reference" in e]


@pytest.mark.parametrize("key", ["tisserand", "lecornu", "charbonnier"])
def test_no_reference_module_types_the_printed_form_it_judges(key: str) -> None:
    table = paper(key).references()
    copies = []
    for entry in _entries(key):
        builder = table[str(entry["reference"])]
        source = module_source(inspect.getfile(inspect.unwrap(builder)))
        copies += [f"{entry['id']} {c}" for c in copied_sides(entry, source)]
    assert not copies, copies


def test_a_copy_is_found() -> None:
    """The comparison sees a printed form pasted into a module, spaces and prefixes aside."""
    entry = {"printed": "theta = sin(tau) - (p*tau/4)*(3*sin(tau) + tau*cos(tau))"}
    pasted = normalised("x = sp.sin(tau) - (p * tau / 4) * (3 * sp.sin(tau) + tau * sp.cos(tau))")
    assert copied_sides(entry, pasted) == ["printed: sin(tau)-(p*tau/4)*(3*sin(tau)+tau*cos(tau))"]
    assert copied_sides(entry, normalised("x = sp.sin(tau) - p * tau")) == []
