"""mpmath precision only through context managers.

A global ``mp.dps = …`` makes a result depend on what ran before it in the process (a check
that ran first leaves its 30 digits to every later mpmath call), so the committed tables would
depend on the order and the split of the work.
"""

from __future__ import annotations

import ast
from pathlib import Path

import mpmath
import pytest
from helpers.sources import walked

import pendcli

PACKAGE = Path(pendcli.__file__).parent
SOURCES = sorted(PACKAGE.rglob("*.py"))


def global_precision_assignments(source: str) -> list[int]:
    """Lines that assign (or augment) an attribute named dps or prec of something named mp."""
    found = []
    for node in walked(source):
        targets: list[ast.expr] = []
        if isinstance(node, ast.Assign):
            targets = list(node.targets)
        elif isinstance(node, ast.AugAssign | ast.AnnAssign):
            targets = [node.target]
        elif isinstance(node, ast.Call) and getattr(node.func, "id", "") == "setattr":
            targets = [ast.Attribute(value=node.args[0], attr=getattr(node.args[1], "value", ""))]
        for target in targets:
            if isinstance(target, ast.Attribute) and target.attr in ("dps", "prec"):
                owner = target.value
                name = owner.attr if isinstance(owner, ast.Attribute) else getattr(owner, "id", "")
                if name == "mp":
                    found.append(node.lineno)
    return found


@pytest.mark.parametrize(
    "source",
    [
        "import mpmath\nmpmath.mp.dps = 30\n",
        "from mpmath import mp\nmp.prec = 100\n",
        "from mpmath import mp\nmp.dps += 5\n",
        "import mpmath\nsetattr(mpmath.mp, 'dps', 20)\n",
    ],
)
def test_the_scan_finds_each_form_of_a_global_assignment(source: str) -> None:
    assert global_precision_assignments(source) == [2]


def test_the_scan_allows_the_context_managers() -> None:
    source = "import mpmath\nwith mpmath.workdps(30):\n    x = mpmath.mp.dps\n"
    assert global_precision_assignments(source) == []


def test_no_module_assigns_the_global_precision() -> None:
    assert len(SOURCES) > 50  # the package was found
    # a module that never writes "dps" or "prec" has no such assignment (the scan matches
    # those attribute names, and setattr's literal name): it is not parsed
    texts = {path: path.read_text(encoding="utf-8") for path in SOURCES}
    offenders = {
        str(path.relative_to(PACKAGE)): lines
        for path, text in texts.items()
        if ("dps" in text or "prec" in text) and (lines := global_precision_assignments(text))
    }
    assert offenders == {}, f"use mpmath.workdps/workprec instead: {offenders}"


# Lecornu's references that compute with mpmath at 30 or 40 digits (the checks that once set
# mp.dps and left it there are gone; these took their computations over)
MPMATH_REFERENCES = [
    "numbers_j2_roots",
    "numbers_j1_roots",
    "numbers_table_j0",
    "reference_elongation_root",
    "reference_at_beta",
]


@pytest.mark.parametrize("name", MPMATH_REFERENCES)
def test_a_lecornu_reference_leaves_the_precision_as_it_found_it(name: str) -> None:
    from pendcli.papers.registry import paper

    before = (mpmath.mp.dps, mpmath.mp.prec)
    assert paper("lecornu").references()[name]() is not None
    assert (mpmath.mp.dps, mpmath.mp.prec) == before
