"""The README's layout section names every module of the tree: computed, not typed."""

from __future__ import annotations

import re
from pathlib import Path

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
    """Lecornu's references are gathered from its section tables (``REFERENCES`` of each
    references_*.py): a name two of them define would silently take the later one's meaning
    (two builders named reference_elongation_condition once did, and (12) was judged against
    (23)'s condition). The gathered table is every section's, whole."""
    from pendcli.papers.lecornu.references import REFERENCES, SECTIONS

    seen: dict[str, str] = {}
    for module in SECTIONS:
        for name in module.REFERENCES:
            assert name not in seen, f"{name} is given by {module.__name__} and {seen[name]}"
            seen[name] = module.__name__
    assert list(REFERENCES) == list(seen)
    folder = ROOT / "pendcli" / "papers" / "lecornu"
    with_tables = {p.stem for p in folder.glob("references_*.py") if "REFERENCES" in p.read_text()}
    assert with_tables == {m.__name__.rsplit(".", 1)[1] for m in SECTIONS}
