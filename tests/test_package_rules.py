"""What each package may import, as its docstring says (docs/ARCHITECTURE.md): read from the
source (imports inside functions included), never by running it."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from helpers.sources import parsed_file, walked_file

ROOT = Path(__file__).resolve().parents[1] / "pendcli"

# package -> the pendcli modules it must never import (prefixes)
FORBIDDEN = {
    "numerics": ("pendcli.papers", "pendcli.cli", "pendcli.data.tables", "pendcli.run"),
    "verify": (
        "pendcli.cli",
        "pendcli.run",
        "pendcli.output.report",
        "pendcli.api",
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
    "run": ("pendcli.cli", "pendcli.api"),
}

# The layers, bottom up: a module of the first four imports only its own layer or one below
# (imports inside functions and under TYPE_CHECKING included). The papers, the run, the outputs
# and the CLI above have their own rules (FORBIDDEN, tests/papers/test_paper_contract.py).
LAYERS = ("base", "data", "verify", "numerics", "papers", "output", "run", "cli")
CHECKED_LAYERS = ("base", "data", "verify", "numerics")
# module -> the modules of a higher layer it still imports, each named: the ledger's loader
# refuses a row by the engine's rules (its kind, blame, companions' shape, formulas, step)
GOING_UP: dict[str, set[str]] = {
    "pendcli.data.ledger": {
        "pendcli.verify.check_kinds",
        "pendcli.verify.ledger_blame",
        "pendcli.verify.ledger_companions",
        "pendcli.verify.ledger_formulas",
        "pendcli.verify.ledger_step",
    },
}


def layer(module: str) -> int:
    """The rank of a pendcli module's layer; ``pendcli.api`` and ``pendcli`` itself are above
    every layer."""
    parts = module.split(".")
    return LAYERS.index(parts[1]) if len(parts) > 1 and parts[1] in LAYERS else len(LAYERS)


def imports_going_up(root: Path, layers: tuple[str, ...]) -> dict[str, set[str]]:
    """module -> the pendcli modules of a higher layer it imports."""
    found: dict[str, set[str]] = {}
    for name in layers:
        for path in sorted((root / name).rglob("*.py")):
            parts = path.relative_to(root.parent).with_suffix("").parts
            module = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
            up = {
                target
                for target in imported(path)
                if (target == "pendcli" or target.startswith("pendcli."))
                and layer(target) > layer(module)
            }
            if up:
                found[module] = up
    return found


def test_an_import_only_goes_down_the_layers_but_the_named_ones() -> None:
    assert imports_going_up(ROOT, CHECKED_LAYERS) == GOING_UP


def test_an_import_going_up_is_found(tmp_path: Path) -> None:
    package = tmp_path / "pendcli"
    for name, text in {
        "base/__init__.py": "",
        "base/files.py": "from pendcli.data.tables import read\n",
        "data/__init__.py": "",
        "data/tables.py": "def f():\n    from pendcli.verify import verdict\n",
        "verify/__init__.py": "",
        "verify/verdict.py": "from pendcli.data import tables\nfrom pendcli.base import files\n",
    }.items():
        (package / name).parent.mkdir(parents=True, exist_ok=True)
        (package / name).write_text(text, encoding="utf-8")
    assert imports_going_up(package, CHECKED_LAYERS) == {
        "pendcli.base.files": {"pendcli.data.tables"},
        "pendcli.data.tables": {"pendcli.verify"},
    }


# The run's modules, and what of them an output may import when it runs: the report lists the
# regenerated tables (regression.regenerated_tables). Its result's type (ReproduceResult) is
# named under TYPE_CHECKING only, which never imports it.
THE_RUN = ("reproduce", "regression")
RUNS_WITH_THE_RUN = {"report.py": {"regression"}}


def type_only(nodes: tuple[ast.AST, ...]) -> set[ast.AST]:
    """The import statements inside ``if TYPE_CHECKING:`` blocks among a tree's ``nodes``."""
    return {
        node
        for block in nodes
        if isinstance(block, ast.If) and ast.unparse(block.test) == "TYPE_CHECKING"
        for stmt in block.body
        for node in ast.walk(stmt)
        if isinstance(node, ast.Import | ast.ImportFrom)
    }


def run_imports(path: Path) -> set[str]:
    """The run's modules that ``path`` imports when it runs (a function's imports included)."""
    nodes = walked_file(path)
    skip = type_only(nodes)
    names = [
        name
        for node in nodes
        if node not in skip
        for name in (
            [node.module or ""] if isinstance(node, ast.ImportFrom)
            else [a.name for a in node.names] if isinstance(node, ast.Import)
            else []
        )
    ]  # fmt: skip
    return {n.rsplit(".", 1)[-1] for n in names if n.rsplit(".", 1)[-1] in THE_RUN}


def imported(path: Path) -> list[str]:
    names = []
    for node in walked_file(path):
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
    """The outputs render rows: only the report, which lists the regenerated tables, imports
    a module of the run when it runs."""
    found = {
        path.relative_to(ROOT / "output").as_posix(): run
        for path in sorted((ROOT / "output").rglob("*.py"))
        if (run := run_imports(path))
    }
    assert found == RUNS_WITH_THE_RUN


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
    "package",
    [
        "base",
        "data",
        "verify",
        "numerics",
        "papers",
        "output",
        "output/html",
        "cli",
        "run",
        "../tools",
    ],
)
def test_every_package_opens_with_a_docstring(package: str) -> None:
    doc = ast.get_docstring(parsed_file(ROOT / package / "__init__.py"))
    assert doc and "TODO" not in doc and len(doc) > 80
