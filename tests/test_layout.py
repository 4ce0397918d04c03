"""The README's layout section names every module of the tree (issue 11): computed, not typed."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _layout_section() -> str:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    match = re.search(r"## Layout\n\n```\n(.*?)```", text, re.S)
    assert match, "README has no Layout section"
    return match.group(1)


def test_every_module_is_in_the_readme_layout() -> None:
    section = _layout_section()
    named = set(re.findall(r"[\w]+\.py|[\w]+/", section))
    missing = []
    for path in sorted((ROOT / "pendcli").rglob("*.py")):
        rel = path.relative_to(ROOT / "pendcli")
        if path.name in ("__init__.py", "__main__.py") and len(rel.parts) > 1:
            continue
        if path.name == "__main__.py":
            continue
        if path.name not in named and path.name != "__init__.py":
            missing.append(str(rel))
        for folder in rel.parts[:-1]:
            if f"{folder}/" not in named:
                missing.append(f"{folder}/")
    assert not missing, f"README layout lacks {sorted(set(missing))}"


def test_every_paper_has_its_own_folder() -> None:
    from pendcli.papers.registry import PAPERS

    for key in PAPERS:
        folder = ROOT / "pendcli" / "papers" / key
        for part in ("__init__", "model", "claims", "formulas", "speed", "stability"):
            assert (folder / f"{part}.py").is_file(), f"{key} has no {part}.py"


def test_the_star_imported_reference_modules_name_nothing_twice() -> None:
    """lecornu/equations.py star-imports its reference modules: a name two of them define
    would silently take the later one's meaning (a19's and b19's reference_elongation_condition
    did, and (12) was judged against (23)'s condition)."""
    import ast
    import importlib

    source = (ROOT / "pendcli" / "papers" / "lecornu" / "equations.py").read_text()
    starred, explicit = [], []
    for node in ast.parse(source).body:
        if isinstance(node, ast.ImportFrom) and node.module:
            names = [a.name for a in node.names]
            (starred.append(node.module) if names == ["*"] else explicit.extend(names))
    assert len(starred) >= 2
    seen: dict[str, str] = {name: "equations.py" for name in explicit}
    for module in starred:
        for name in importlib.import_module(module).__all__:
            assert name not in seen, f"{name} is exported by {module} and {seen[name]}"
            seen[name] = module
