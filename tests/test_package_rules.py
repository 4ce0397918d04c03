"""What each package may import, as its docstring says (docs/ARCHITECTURE.md): read from the
source (imports inside functions included), never by running it."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1] / "pendcli"

# package -> the pendcli modules it must never import (prefixes)
FORBIDDEN = {
    "numerics": ("pendcli.papers", "pendcli.cli", "pendcli.core.tables", "pendcli.reproduce"),
    "core": (
        "pendcli.cli",
        "pendcli.reproduce",
        "pendcli.output.report",
        "pendcli.api",
        "pendcli.regression",
        "pendcli.tradeoff",
        "pendcli.papers.lecornu",
        "pendcli.papers.tisserand",
        "pendcli.papers.charbonnier",
    ),
    "output": (
        "pendcli.cli",
        "pendcli.api",
        "pendcli.papers.lecornu",
        "pendcli.papers.tisserand",
        "pendcli.papers.charbonnier",
        "tools",
    ),
}

# output modules that may know the run (its result, the regenerated tables), and what of it
THE_RUN = ("reproduce", "regression")
KNOWS_THE_RUN = {
    "report.py": {"reproduce", "regression"},  # ReproduceResult (a type), the tables' names
    "html/report.py": {"reproduce"},  # ReproduceResult, a type only
}


def imported(path: Path) -> list[str]:
    names = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module:
            names.append(node.module)
        elif isinstance(node, ast.Import):
            names += [a.name for a in node.names]
    return names


@pytest.mark.parametrize("package", sorted(FORBIDDEN))
def test_a_package_imports_nothing_its_docstring_forbids(package: str) -> None:
    found = [
        f"{path.name}: {name}"
        for path in sorted((ROOT / package).rglob("*.py"))
        for name in imported(path)
        if name.startswith(FORBIDDEN[package])
    ]
    assert found == []


def test_output_knows_the_run_only_in_the_report() -> None:
    """The outputs render rows; only the report (which lists the regenerated tables) and the
    HTML report's types name the run's modules."""
    found: dict[str, set[str]] = {}
    for path in sorted((ROOT / "output").rglob("*.py")):
        run = {n.rsplit(".", 1)[-1] for n in imported(path) if n.rsplit(".", 1)[-1] in THE_RUN}
        if run:
            found[path.relative_to(ROOT / "output").as_posix()] = run
    assert found == KNOWS_THE_RUN


def test_nothing_installed_imports_the_developer_tools() -> None:
    """`tools/` (make bench, make regen) is not in the wheel: a pendcli module importing it
    would fail once installed."""
    found = [
        f"{path.relative_to(ROOT)}: {name}"
        for path in sorted(ROOT.rglob("*.py"))
        for name in imported(path)
        if name == "tools" or name.startswith("tools.")
    ]
    assert found == []


@pytest.mark.parametrize(
    "package", ["core", "numerics", "papers", "output", "output/html", "cli", "../tools"]
)
def test_every_package_opens_with_a_docstring(package: str) -> None:
    doc = ast.get_docstring(ast.parse((ROOT / package / "__init__.py").read_text("utf-8")))
    assert doc and "TODO" not in doc and len(doc) > 80
