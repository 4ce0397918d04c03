"""Every file fits in a reading and every function on a screen: no Python file of the package,
the tools or the tests over 600 lines, no function of the package or the tools over 60."""

from __future__ import annotations

import ast
from pathlib import Path

from helpers.sources import walked

ROOT = Path(__file__).resolve().parent.parent
MAX_LINES, MAX_FUNCTION = 600, 60


def python_files(*folders: str) -> list[Path]:
    return [
        p for f in folders for p in sorted((ROOT / f).rglob("*.py")) if "__pycache__" not in p.parts
    ]


def long_functions(text: str) -> list[str]:
    """``line name (n lines)`` of each function in ``text`` over MAX_FUNCTION lines."""
    found = []
    for node in walked(text):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            length = (node.end_lineno or node.lineno) - node.lineno + 1
            if length > MAX_FUNCTION:
                found.append(f"{node.lineno} {node.name} ({length} lines)")
    return found


def test_no_file_is_over_600_lines() -> None:
    sizes = {
        p: len(p.read_text(encoding="utf-8").splitlines())
        for p in python_files("pendcli", "tools", "tests")
    }
    assert len(sizes) > 300
    assert [f"{p.relative_to(ROOT)} ({n})" for p, n in sizes.items() if n > MAX_LINES] == []


def test_no_function_is_over_60_lines() -> None:
    found = [
        f"{p.relative_to(ROOT)}:{line}"
        for p in python_files("pendcli", "tools")
        for line in long_functions(p.read_text(encoding="utf-8"))
    ]
    assert found == []


def test_the_function_measure_counts_a_function_from_its_def_to_its_last_line() -> None:
    """60 lines pass, 61 do not (the def line and 59 or 60 of body), nested ones too."""

    def source(name: str, body_lines: int, indent: str = "") -> str:
        body = "\n".join(f"{indent}    x{i} = {i}" for i in range(body_lines))
        return f"{indent}def {name}():\n{body}\n"

    text = source("fits", MAX_FUNCTION - 1) + source("over", MAX_FUNCTION)
    text += "class C:\n" + source("method_over", MAX_FUNCTION, "    ")
    assert [f.split(" ")[1] for f in long_functions(text)] == ["over", "method_over"]
