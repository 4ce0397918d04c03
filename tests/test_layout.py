"""The README's layout section names every module of the tree: computed, not typed."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def _layout_section() -> str:
    text = (ROOT / "docs" / "layout.md").read_text(encoding="utf-8")
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


def test_the_reference_tables_name_nothing_twice() -> None:
    """Lecornu's references are gathered from its section modules (their public reference_*
    and numbers_* functions, verify/ledger_references.builders): a name two of them define would
    silently take the later one's meaning (two builders named reference_elongation_condition
    once did, and (12) was judged against (23)'s condition), so it is refused; and every
    references_*.py module that defines a builder is a section."""
    import types

    from pendcli.papers.lecornu.references import SECTIONS
    from pendcli.verify.ledger_references import builders

    modules = [types.ModuleType(name) for name in ("first", "second")]
    for module in modules:
        exec("def reference_twice():\n    return None", module.__dict__)
    with pytest.raises(ValueError, match="two references named 'reference_twice'"):
        builders(*modules)
    assert list(builders(modules[0])) == ["reference_twice"]
    folder = ROOT / "pendcli" / "papers" / "lecornu"
    defining = {
        p.stem
        for p in folder.glob("references_*.py")
        if re.search(r"^def (reference|numbers)_", p.read_text(), re.M)
    }
    assert defining == {m.__name__.rsplit(".", 1)[1] for m in SECTIONS}
