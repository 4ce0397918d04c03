"""mpmath precision only through context managers (issues 20, 23).

A global ``mp.dps = …`` makes a result depend on what ran before it in the process (a check
that ran first leaves its 30 digits to every later mpmath call), so the committed tables would
depend on the order and the split of the work.
"""

from __future__ import annotations

import ast
from pathlib import Path

import mpmath
import pytest

import pendcli

PACKAGE = Path(pendcli.__file__).parent
SOURCES = sorted(PACKAGE.rglob("*.py"))


def global_precision_assignments(source: str) -> list[int]:
    """Lines that assign (or augment) an attribute named dps or prec of something named mp."""
    found = []
    for node in ast.walk(ast.parse(source)):
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
    offenders = {
        str(path.relative_to(PACKAGE)): lines
        for path in SOURCES
        if (lines := global_precision_assignments(path.read_text(encoding="utf-8")))
    }
    assert offenders == {}, f"use mpmath.workdps/workprec instead: {offenders}"


CHECKS_THAT_SET_THE_PRECISION = [
    "eq_10",
    "eq_11",
    "result_eq13_is_j2",
    "eq_14",
    "result_amplitude_j0",
    "result_limit_u_at_zero",
    "eq_18_integral",
    "result_c_equals_4_over_pi",
    "eq_19_integral",
    "result_small_x_asymptotics",
    "result_amplitude_factor",
]


@pytest.mark.parametrize("name", CHECKS_THAT_SET_THE_PRECISION)
def test_a_lecornu_check_leaves_the_precision_as_it_found_it(name: str) -> None:
    """The checks that used to set mp.dps = 20..30 and leave it there for whatever came next."""
    from pendcli.papers.lecornu import equations

    before = (mpmath.mp.dps, mpmath.mp.prec)
    check = getattr(equations, name)()
    assert check.method  # it ran and said how it checked
    assert (mpmath.mp.dps, mpmath.mp.prec) == before
