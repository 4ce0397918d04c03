"""Regeneration is deterministic: the same bytes whatever the process count, and a
fresh copy of the committed tables is left as it is.

Each run is a fresh process, so nothing one run leaves behind (a global mpmath precision, a
cache, an import) can reach the other. The one-job side is the computation of every table the
run shares (tests/helpers/regenerated.py: a fresh process, one job); the two-job side is the
same computation in another fresh process with two jobs (a forked worker beside it), done once
for both tests; each is written or printed by the real command in a fresh process of its own.

Found: the committed formula tables had been written on a CPU whose BLAS and SIMD kernels
round differently; the adaptive ODE steps carry those last bits to ~1e-9 in an observed order.
Where the two runs here agree but the committed tables do not, that is the cause: `make regen`
on the machine that checks them.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from helpers.regenerated import COMPUTE_TWO_JOBS, SERVED_CLI, TWO_JOBS, computed_once, shared_root

import pendcli

TABLES = Path(pendcli.__file__).parent / "_tables"


@pytest.fixture(scope="session")
def computed_with_two_jobs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Every table's computation from the committed tables in a fresh process with two jobs,
    done once per run for all workers (beside the one-job computation of ``computed_tables``)."""
    root = shared_root(tmp_path_factory, os.environ.get("PYTEST_XDIST_WORKER", "master"))
    return computed_once(root, TWO_JOBS, COMPUTE_TWO_JOBS)


def pendcli(served: Path | None) -> list[str]:
    """`pendcli` in a fresh process: computing, or served the one-job computation ``served``."""
    return [*SERVED_CLI, str(served)] if served else [sys.executable, "-m", "pendcli"]


def regenerate(tmp: Path, jobs: int, served: Path | None = None) -> dict[str, bytes]:
    """`pendcli check --update` on a fresh copy of the committed tables: the bytes it leaves."""
    copy = tmp / f"tables-{jobs}"
    shutil.copytree(TABLES, copy)
    env = {**os.environ, "PENDCLI_TABLES": str(copy), "PENDCLI_JOBS": str(jobs)}
    done = subprocess.run(
        [*pendcli(served), "check", "--update", "-q"],
        env=env,
        capture_output=True,
        text=True,
        cwd=tmp,
    )
    assert done.returncode == 0, done.stderr
    return {p.name: p.read_bytes() for p in sorted((copy / "regenerated").iterdir())}


def committed() -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted((TABLES / "regenerated").iterdir())}


def changed_lines(old: bytes, new: bytes) -> list[str]:
    pairs = zip(old.decode().splitlines(), new.decode().splitlines(), strict=False)
    return [f"- {a}\n+ {b}" for a, b in pairs if a != b][:5]


@pytest.mark.slow
def test_check_update_on_a_fresh_copy_changes_no_byte_with_one_or_two_processes(
    tmp_path: Path, computed_tables: Path, computed_with_two_jobs: Path
) -> None:
    one = regenerate(tmp_path, 1, computed_tables)
    two = regenerate(tmp_path, 2, computed_with_two_jobs)
    assert one.keys() == two.keys()
    for name in one:
        assert one[name] == two[name], (name, changed_lines(one[name], two[name]))
    tables = committed()
    for name, new in two.items():
        if not name.startswith("."):  # the lock file beside the set
            assert tables.get(name) == new, (name, changed_lines(tables.get(name, b""), new))


def reproduce_json(jobs: int, served: Path | None = None) -> bytes:
    env = {**os.environ, "PENDCLI_JOBS": str(jobs)}
    env.pop("PENDCLI_TABLES", None)
    done = subprocess.run(
        [*pendcli(served), "reproduce", "-f", "json", "--equations"],
        env=env,
        capture_output=True,
    )
    assert done.returncode == 0, done.stderr.decode()
    return done.stdout


@pytest.mark.slow
def test_reproduce_json_with_equations_is_the_same_bytes_with_one_or_two_processes(
    computed_tables: Path, computed_with_two_jobs: Path
) -> None:
    assert reproduce_json(1, computed_tables) == reproduce_json(2, computed_with_two_jobs)
