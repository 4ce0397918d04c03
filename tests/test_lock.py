"""The locked environment: every dependency pinned in the lock files, within
pyproject's bounds, and what is installed here is what the lock says."""

from __future__ import annotations

import re
import tomllib
from importlib.metadata import version
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name
from packaging.version import Version

ROOT = Path(__file__).resolve().parents[1]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]


def pins(name: str) -> dict[str, list[str]]:
    """{package: [versions]} of a lock file (two versions where Python forks the resolution)."""
    found: dict[str, list[str]] = {}
    text = (ROOT / name).read_text(encoding="utf-8")
    for match in re.finditer(r"^([A-Za-z0-9_.\-]+)==([^\s;\\]+)", text, re.M):
        found.setdefault(canonicalize_name(match[1]), []).append(match[2])
    return found


RUNTIME = [Requirement(r) for r in PROJECT["dependencies"]]
TOOLS = [Requirement(r) for r in PROJECT["optional-dependencies"]["test"]]


@pytest.mark.parametrize(
    ("lock", "wanted"),
    [("requirements.lock", RUNTIME), ("requirements-dev.lock", RUNTIME + TOOLS)],
)
def test_every_dependency_is_pinned_within_its_bounds(lock: str, wanted: list[Requirement]) -> None:
    locked = pins(lock)
    for requirement in wanted:
        versions = locked.get(canonicalize_name(requirement.name))
        assert versions, f"{requirement.name} is not in {lock}: run make lock"
        for pinned in versions:
            assert requirement.specifier.contains(Version(pinned)), (requirement, pinned)


def test_the_runtime_lock_has_no_test_tool_and_agrees_with_the_dev_lock() -> None:
    runtime, dev = pins("requirements.lock"), pins("requirements-dev.lock")
    assert not {canonicalize_name(t.name) for t in TOOLS} & set(runtime)
    for name, versions in runtime.items():
        assert dev.get(name) == versions, name


def test_what_is_installed_is_what_is_locked() -> None:
    """So the tests, and the tables they check, run on the versions the lock names."""
    locked = pins("requirements.lock")
    for requirement in RUNTIME:
        name = canonicalize_name(requirement.name)
        assert version(requirement.name) in locked[name], (name, locked[name])
