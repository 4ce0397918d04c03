"""The paper contract (pendcli/papers/paper.py): hooks named by place, resolved by one loader.

A paper's ``__init__.py`` is its citation and its list of hooks: every place must resolve
(a missing module or name is a load error naming the paper and the place), and the paper
package imports no module of the program above it (its CLI sub-app is a place).
"""

from __future__ import annotations

import ast
from dataclasses import replace
from pathlib import Path

import pytest
from helpers.sources import parsed_file

from pendcli.base.errors import PendcliError
from pendcli.papers.paper import check_hooks, hook, merged, modules
from pendcli.papers.registry import PAPERS, paper

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("key", sorted(PAPERS))
def test_every_hook_of_every_paper_resolves(key: str) -> None:
    assert check_hooks(paper(key)) == []


@pytest.mark.parametrize("key", sorted(PAPERS))
def test_a_misspelt_hook_is_a_load_error_naming_it(key: str) -> None:
    broken = replace(paper(key), figures=hook(f"pendcli.papers.{key}.figures:figurez"))
    (problem,) = check_hooks(broken)
    assert key in problem and "figurez" in problem
    with pytest.raises(PendcliError, match="has no 'figurez'"):
        broken.figures(Path("."))  # type: ignore[misc]


def test_a_missing_module_is_a_load_error() -> None:
    with pytest.raises(PendcliError, match="no module"):
        hook("pendcli.papers.nowhere:recompute")()


def test_a_table_is_returned_a_function_called_mappings_merged() -> None:
    assert hook("pendcli.papers.registry:PAPERS")() == PAPERS
    assert hook("pendcli.data.numbers:parse_printed")("0,5").value == 0.5
    left, right = "pendcli.papers.lecornu.formula_figures", "pendcli.papers.lecornu.figures"
    both = merged(f"{left}:CAPTIONS", f"{right}:CAPTIONS")()
    from pendcli.papers.lecornu import figures, formula_figures

    assert both == {**formula_figures.CAPTIONS, **figures.CAPTIONS}
    assert modules("pendcli.papers.lecornu.claims")() is None


@pytest.mark.parametrize("key", sorted(PAPERS))
def test_a_paper_package_imports_nothing_above_it(key: str) -> None:
    """No module of a paper imports the CLI, the registry or the orchestration (imports inside
    functions included): the program calls the paper, never the other way round."""
    above = ("pendcli.cli", "pendcli.papers.registry", "pendcli.run", "pendcli.api")
    engines = ("pendcli.run.tradeoff_engine", "pendcli.run.stability")  # generic, registry-free
    found = []
    for path in sorted((ROOT / "pendcli" / "papers" / key).glob("*.py")):
        for node in ast.walk(parsed_file(path)):
            names = [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            names += [a.name for a in node.names] if isinstance(node, ast.Import) else []
            found += [
                f"{path.name}: {n}" for n in names if n.startswith(above) and n not in engines
            ]
    assert found == []


@pytest.mark.parametrize("key", sorted(PAPERS))
def test_a_paper_init_defines_no_wrapper_function(key: str) -> None:
    tree = parsed_file(ROOT / "pendcli" / "papers" / key / "__init__.py")
    assert not [n.name for n in tree.body if isinstance(n, ast.FunctionDef)]
