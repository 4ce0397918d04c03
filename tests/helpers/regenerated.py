"""Every table's computation (what `pendcli check` regenerates: ``reproduce_all`` of every
paper with its formulas and ledger), done once per test run in a fresh process with one job,
and shared by the tests that need its result but test something else: the writer of `check
--update` under a kill, a signal, a full disk or a read-only folder, the comparison of damaged
committed cells, the one-job side of the determinism tests, and the tests of `check`'s output
(its formats, its widths, its command line fuzzed). xdist workers share one computation through
a file lock in the run's common temporary folder.

The same holds for `check`'s other computation, the stored derivations of each ledger derived
again (``derivation_drift``: 20 s of CPU), done once per run in its own fresh process when a
test first asks for it (:func:`serve_shared`).

:data:`SERVED_CLI` runs `pendcli ARGS` in a fresh process as ``python -m pendcli`` does, with
``reproduce_all`` answering from that file: the process, its signal handlers, its lock, its
writer and its output are the real ones; only the computation before them is served.
"""

from __future__ import annotations

import fcntl
import os
import pickle
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from helpers.served_cli import holds, stand_in

SERVED_CLI = (sys.executable, str(Path(__file__).with_name("served_cli.py")))
NAME = "reproduce-all.pickle"
COMPUTE = """
import pickle, sys
from pendcli.papers.registry import keys
from pendcli.run.reproduce import reproduce_all
asked = {"keys": tuple(keys()), "formulas": True, "equations": True, "stability": False}
result = reproduce_all(keys(), formulas=True, equations=True, stability=False, quiet=True, jobs=1)
sys.stdout.buffer.write(pickle.dumps((asked, result)))
"""
# the same computation in two processes (a forked worker beside the computing one): the
# two-process side of the determinism tests, shared by them
TWO_JOBS = "reproduce-all-two-jobs.pickle"
COMPUTE_TWO_JOBS = COMPUTE.replace("jobs=1)", "jobs=2)")
DRIFT = "derivation-drift.pickle"
COMPUTE_DRIFT = """
import pickle, sys
from pendcli.papers.registry import keys, paper
from pendcli.verify.ledger_references import derivation_drift
sys.stdout.buffer.write(pickle.dumps({key: derivation_drift(paper(key)) for key in keys()}))
"""


def shared_root(factory: pytest.TempPathFactory, worker: str) -> Path:
    """The folder every worker of this run shares (the run's own folder without xdist)."""
    base = factory.getbasetemp()
    return base if worker == "master" else base.parent


# Run in the background by :func:`start_early`: computes ``script`` into ROOT/NAME under the
# same lock as :func:`computed_once`, or records why it failed beside it.
RUNNER = """
import fcntl, os, subprocess, sys
root, name, script = sys.argv[1:4]
path = os.path.join(root, name)
with open(path + ".lock", "w") as lock:
    fcntl.flock(lock, fcntl.LOCK_EX)
    if not os.path.exists(path):
        done = subprocess.run([sys.executable, "-c", script], capture_output=True)
        if done.returncode == 0:
            with open(path + ".tmp", "wb") as out:
                out.write(done.stdout)
            os.replace(path + ".tmp", path)
        else:
            with open(path + ".failed", "wb") as out:
                out.write(done.stderr)
"""
_STARTED: list[subprocess.Popen[bytes]] = []


def _child_env() -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "PENDCLI_TABLES"}
    return {**env, "PENDCLI_JOBS": "1"}


def computed_once(root: Path, name: str = NAME, script: str = COMPUTE) -> Path:
    """The file holding every table's computation from the committed tables (or what
    ``script`` prints): computed by the first worker to ask, or already started in the
    background (:func:`start_early`); the others wait on the lock, then read it."""
    path = root / name
    with open(root / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        failed = root / f"{name}.failed"
        assert not failed.exists(), failed.read_bytes().decode()
        if not path.exists():
            done = subprocess.run(
                [sys.executable, "-c", script], env=_child_env(), capture_output=True, check=False
            )
            assert done.returncode == 0, done.stderr.decode()
            tmp = path.with_name(f"{name}.tmp")
            tmp.write_bytes(done.stdout)
            os.replace(tmp, path)
    return path


def start_early(items: list[pytest.Item], root: Path) -> None:
    """Start in the background, once for the run's workers, the shared computations the
    selected ``items`` will read: every table's (a test asking for ``computed_tables`` or
    ``reproduce_computed_once``) and the derivations' (a test of `check`'s output, its id
    naming check, asking for ``reproduce_computed_once``). A worker asking for one then
    finds it done or under way, instead of both workers waiting idle on one computation. The
    same computation with two jobs (the determinism tests' ``computed_with_two_jobs``) too."""
    served = [i for i in items if "reproduce_computed_once" in getattr(i, "fixturenames", ())]
    tables = served or [i for i in items if "computed_tables" in getattr(i, "fixturenames", ())]
    wanted = [(NAME, COMPUTE)] if tables else []
    wanted += [(DRIFT, COMPUTE_DRIFT)] if any("check" in i.nodeid for i in served) else []
    two = any("computed_with_two_jobs" in getattr(i, "fixturenames", ()) for i in items)
    wanted += [(TWO_JOBS, COMPUTE_TWO_JOBS)] if two else []
    for name, script in wanted:
        try:
            os.close(os.open(root / f"{name}.started", os.O_CREAT | os.O_EXCL | os.O_WRONLY))
        except FileExistsError:  # another worker started it
            continue
        runner = [sys.executable, "-c", RUNNER, str(root), name, script]
        _STARTED.append(subprocess.Popen(runner, env=_child_env(), stdout=subprocess.DEVNULL))


def wait_started() -> None:
    """Wait for the computations this process started (their CPU is then counted as its
    children's, and none outlives the run)."""
    while _STARTED:
        _STARTED.pop().wait()


def served(path: Path) -> Callable[..., Any]:
    """A stand-in for ``reproduce_all`` in this process, answering from ``path``."""
    return stand_in(path)


def serve_shared(monkeypatch: pytest.MonkeyPatch, root: Path) -> None:
    """For the tests of a command's output form that run it several times: in this test,
    ``reproduce_all``, ``ledger_rows`` and ``derivation_drift`` answer from the run's shared
    computations (in ``root``, made when first asked) where asked for what those hold (every
    table or a part of it: fewer papers, no formulas, no ledger) of the package's own tables;
    anything else is computed once in the test and served again (the stability table,
    another tables folder). The claims, formula checks and explanations of the committed
    tables are computed once per process."""
    from pendcli.data.tables import tables_dir
    from pendcli.run import reproduce
    from pendcli.verify import ledger_references
    from pendcli.verify.derivation_store import stores_here

    computed, rows, derived = (
        reproduce.reproduce_all,
        reproduce.ledger_rows,
        ledger_references.derivation_drift,
    )
    done: dict[str, object] = {}
    drifts: dict[tuple[str, str], list[str]] = {}

    def once(*args: object, **kwargs: object) -> object:
        if stores_here(tables_dir()) and _run_holds(computed, args, kwargs):
            return served(computed_once(root))(*args, **kwargs)
        key = repr((args, sorted(kwargs.items())))
        if key not in done:
            done[key] = computed(*args, **kwargs)  # type: ignore[arg-type]
        return done[key]

    def ledger_once(keys, *args, **kwargs):  # type: ignore[no-untyped-def]
        if not stores_here(tables_dir()):
            return rows(keys, *args, **kwargs)
        result = served(computed_once(root))(tuple(keys), formulas=False, equations=True)
        return [row for key in keys for row in result.equations[key]]

    def drift_once(paper):  # type: ignore[no-untyped-def]
        if stores_here(tables_dir()):
            shared = computed_once(root, DRIFT, COMPUTE_DRIFT)
            return list(pickle.loads(shared.read_bytes())[paper.key])
        key = (paper.key, str(tables_dir()))
        if key not in drifts:
            drifts[key] = derived(paper)
        return list(drifts[key])

    monkeypatch.setattr(reproduce, "reproduce_all", once)
    monkeypatch.setattr(reproduce, "ledger_rows", ledger_once)
    monkeypatch.setattr(ledger_references, "derivation_drift", drift_once)
    _serve_committed_rows(monkeypatch)


def _run_holds(
    function: Callable[..., Any], args: tuple[object, ...], kwargs: dict[str, object]
) -> bool:
    """Whether the run's computation (:data:`COMPUTE`) holds what a call of ``reproduce_all``
    asks for: not the stability table."""
    import inspect

    from pendcli.papers.registry import keys

    bound = inspect.signature(function).bind(*args, **kwargs)
    bound.apply_defaults()
    asked = {k: bound.arguments[k] for k in ("keys", "formulas", "equations")}
    computed = {"keys": tuple(keys()), "formulas": True, "equations": True}
    return holds(computed, asked, bool(bound.arguments["stability"]))


# (paper, claim id or None) -> its explained rows, of the committed tables
_EXPLAINED: dict[tuple[str, str | None], list[Any]] = {}


def _serve_committed_rows(monkeypatch: pytest.MonkeyPatch) -> None:
    """The committed tables' claims, formula checks and explanations (the rows of `list`,
    `formulas` and `explain`), each computed once per process (tests/helpers/evaluated.py)
    and served again; with a tables folder of the test's own, computed as usual."""
    from helpers.evaluated import committed_claims, committed_formulas
    from pendcli.papers import registry
    from pendcli.verify import explain

    claims, formulas, explained = registry.claim_rows, registry.formula_checks, explain.explain_rows

    def committed() -> bool:
        return not os.environ.get("PENDCLI_TABLES")

    def explain_once(key: str, *args: Any, **kwargs: Any) -> list[Any]:
        claim = args[2] if len(args) > 2 else kwargs.get("claim_id")
        if not committed():
            return explained(key, *args, **kwargs)
        if (key, claim) not in _EXPLAINED:
            _EXPLAINED[key, claim] = explained(key, *args, **kwargs)
        return list(_EXPLAINED[key, claim])

    monkeypatch.setattr(
        registry,
        "claim_rows",
        lambda key: list(committed_claims(key)) if committed() else claims(key),
    )
    monkeypatch.setattr(
        registry,
        "formula_checks",
        lambda key: list(committed_formulas(key)) if committed() else formulas(key),
    )
    monkeypatch.setattr(explain, "explain_rows", explain_once)
