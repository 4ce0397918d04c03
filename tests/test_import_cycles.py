"""No circle of imports among pendcli's modules, except those named in :data:`ALLOWED`.

Read from the source, never by running it: every ``import`` and ``from ... import`` of a
pendcli module anywhere in a file counts (inside functions and ``if TYPE_CHECKING:`` blocks
too), relative imports resolved. ``from pendcli.run import tradeoff`` is an import of the
module ``pendcli.run.tradeoff``; ``from pendcli.verify.claims import ClaimRow`` of
``pendcli.verify.claims``. A package's ``__init__`` is a module of its own, reached only when
named. Places named as text (a paper's ``hook("pendcli.papers.x.claims:recompute")``,
``importlib.import_module``) are not imports and are not followed.

A circle is a strongly connected group of two modules or more (each reaches every other).
"""

from __future__ import annotations

import ast
import functools
from collections.abc import Iterator, Mapping
from pathlib import Path

from helpers.sources import walked_file

PACKAGE = Path(__file__).resolve().parents[1] / "pendcli"

# The circles that remain, each as the whole group of its modules: none. A circle found is
# broken, never listed here (the ledger's once was: its types are in data/ledger_rows.py, its
# evaluation in verify/ledger_evaluation.py, and the engine sees a paper through a protocol).
ALLOWED: tuple[frozenset[str], ...] = ()


def modules(package: Path) -> dict[str, Path]:
    """Dotted module name -> its file, for every ``.py`` under ``package``."""
    found = {}
    for path in sorted(package.rglob("*.py")):
        parts = list(path.relative_to(package.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        found[".".join(parts)] = path
    return found


def _nearest(name: str, known: Mapping[str, Path]) -> str | None:
    """The module ``name`` is, or the nearest package above it; None outside ``known``."""
    while name and name not in known:
        name = name.rpartition(".")[0]
    return name or None


def _imported(
    nodes: tuple[ast.AST, ...], here: str, known: Mapping[str, Path]
) -> Iterator[str | None]:
    """Every module of ``known`` an import among a tree's ``nodes`` names (``here``: the
    file's package). ``from a import b``: the module ``a.b`` when there is one, else ``a`` (b
    is a name in it)."""
    for node in nodes:
        if isinstance(node, ast.Import):
            yield from (_nearest(alias.name, known) for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:  # relative: from the package ``here`` is in
                parent = here.split(".")[: len(here.split(".")) - node.level + 1]
                base = ".".join([*parent, base] if base else parent)
            for alias in node.names:
                whole = f"{base}.{alias.name}"
                yield whole if whole in known else _nearest(base, known)


def import_graph(package: Path) -> dict[str, set[str]]:
    """Module -> the modules of ``package`` it imports (itself left out)."""
    known = modules(package)
    graph: dict[str, set[str]] = {}
    for name, path in known.items():
        here = name if path.name == "__init__.py" else name.rpartition(".")[0]
        nodes = walked_file(path)
        graph[name] = {t for t in _imported(nodes, here, known) if t is not None} - {name}
    return graph


def circles(graph: Mapping[str, set[str]]) -> list[frozenset[str]]:
    """The strongly connected groups of two modules or more (Tarjan, without recursion)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[frozenset[str]] = []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            step = next((s for s in successors if s not in index or s in on_stack), None)
            if step is not None and step not in index:
                index[step] = low[step] = len(index)
                stack.append(step)
                on_stack.add(step)
                work.append((step, iter(sorted(graph.get(step, ())))))
                continue
            if step is not None:
                low[node] = min(low[node], index[step])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = set()
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.add(member)
                    if member == node:
                        break
                if len(group) > 1:
                    found.append(frozenset(group))
    return found


@functools.cache
def _pendcli_graph() -> dict[str, set[str]]:
    return import_graph(PACKAGE)


def _described(group: frozenset[str], graph: Mapping[str, set[str]]) -> str:
    ties = [f"{a} -> {b}" for a in sorted(group) for b in sorted(graph[a] & group)]
    return "; ".join(ties)


def test_no_circle_of_imports_but_the_allowed_ones() -> None:
    graph = _pendcli_graph()
    new = [group for group in circles(graph) if not any(group <= a for a in ALLOWED)]
    assert not new, "\n".join(_described(group, graph) for group in new)


def test_every_allowed_circle_is_still_one() -> None:
    """A circle broken is struck from :data:`ALLOWED`, so the list says what remains."""
    found = circles(_pendcli_graph())
    gone = [sorted(a) for a in ALLOWED if not any(group <= a and len(group) > 1 for group in found)]
    assert gone == []


def _write(root: Path, files: Mapping[str, str]) -> Path:
    for name, text in files.items():
        path = root / "pkg" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return root / "pkg"


def test_a_circle_through_an_import_inside_a_function_is_found(tmp_path: Path) -> None:
    package = _write(
        tmp_path,
        {
            "__init__.py": "",
            "a.py": "from pkg.sub import b\n",
            "sub/__init__.py": "",
            "sub/b.py": "def f():\n    from .. import c\n",
            "c.py": "import typing\nif typing.TYPE_CHECKING:\n    import pkg.a\n",
            "d.py": "from pkg import a\n",  # reaches the circle, is not in it
        },
    )
    graph = import_graph(package)
    assert graph["pkg.sub.b"] == {"pkg.c"}
    assert graph["pkg.d"] == {"pkg.a"}
    assert circles(graph) == [frozenset({"pkg.a", "pkg.sub.b", "pkg.c"})]


def test_a_module_and_a_name_imported_from_a_package_are_told_apart(tmp_path: Path) -> None:
    package = _write(
        tmp_path,
        {
            "__init__.py": "",
            "run/__init__.py": "from pkg.run.x import VALUE\n",
            "run/x.py": "VALUE = 1\n",
            "y.py": "from pkg.run import x, VALUE\nfrom pkg.run.x import VALUE as V\n",
        },
    )
    graph = import_graph(package)
    assert graph["pkg.y"] == {"pkg.run", "pkg.run.x"}
    assert graph["pkg.run"] == {"pkg.run.x"}
    assert circles(graph) == []


def reached(graph: Mapping[str, set[str]], start: str) -> set[str]:
    """Every module ``start`` imports, directly or through others."""
    seen: set[str] = set()
    todo = [start]
    while todo:
        for target in graph.get(todo.pop(), ()):
            if target not in seen:
                seen.add(target)
                todo.append(target)
    return seen


def test_no_module_of_a_paper_reaches_the_registry() -> None:
    """A paper is called by the registry, never the other way round: not even through the
    generic engines it uses (``pendcli.run.tradeoff_engine``, ``pendcli.run.stability``)."""
    graph = _pendcli_graph()
    papers = [m for m in graph if m.startswith("pendcli.papers.") and m.count(".") >= 3]
    assert len(papers) > 30  # every module of the three papers, found
    found = [m for m in papers if "pendcli.papers.registry" in reached(graph, m)]
    assert found == []
