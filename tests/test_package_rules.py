"""What each package may import, as its docstring says (docs/ARCHITECTURE.md): read from the
source (imports inside functions included), never by running it."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1] / "pendcli"

# package -> the pendcli modules it must never import (prefixes)
FORBIDDEN = {
    "numerics": ("pendcli.papers", "pendcli.cli", "pendcli.core.tables", "pendcli.run"),
    "core": (
        "pendcli.cli",
        "pendcli.run",
        "pendcli.output.report",
        "pendcli.api",
        "pendcli.papers.lecornu",
        "pendcli.papers.tisserand",
        "pendcli.papers.charbonnier",
    ),
    "run": ("pendcli.cli", "pendcli.api"),
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
        for path in sorted((ROOT / package).glob("*.py"))
        for name in imported(path)
        if name.startswith(FORBIDDEN[package])
    ]
    assert found == []


@pytest.mark.parametrize("package", ["core", "numerics", "papers", "render", "cli", "run"])
def test_every_package_opens_with_a_docstring(package: str) -> None:
    doc = ast.get_docstring(ast.parse((ROOT / package / "__init__.py").read_text("utf-8")))
    assert doc and "TODO" not in doc and len(doc) > 80
