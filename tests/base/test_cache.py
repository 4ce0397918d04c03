"""The result cache (pendcli/base/cache.py): a warm run prints the cold run's bytes, any byte
changed in the code or the tables is a miss, and a damaged, disabled or unwritable cache
never changes an output or fails a run."""

from __future__ import annotations

import json
import multiprocessing
import os
import re
import shutil
import tomllib
from pathlib import Path

import numpy as np
import pytest
from helpers.cli import invoke

import pendcli.papers.registry as registry
from pendcli.base import cache as cache_module
from pendcli.base.cache import FORMAT, ResultCache, cache_folder, rows_from_json, rows_to_json
from pendcli.base.cache_key import folders_digest
from pendcli.data.rows import ClaimRow, EquationRow, FormulaRow
from pendcli.data.tables import clear_table_cache, tables_dir

FORMATS = ("table", "json", "csv", "markdown")
# tisserand, with its ledger cut to one row of each kind (_small_tables): every cached unit
EQUATIONS = ("equations", "-p", "tisserand")
REPRODUCE = ("reproduce", "-p", "tisserand", "--equations", "--stability", "--notes")


def _small_tables(root: Path) -> Path:
    """A copy of tables/ in ``root`` whose Tisserand ledger keeps the first row of each kind
    (status and formula fields: holds, misprint with its reading, a definition, and a fails row
    with its correction where the ledger has one; since every row has a printed form, no check
    without one), so that every
    field an equation row caches is cached: what these tests are about, in about a tenth of
    the whole ledger's sympy."""
    tables = root / "tables"
    shutil.copytree(tables_dir(), tables)
    path = tables / "equations" / "tisserand.toml"
    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    kinds: dict[tuple[object, ...], dict[str, object]] = {}
    for row in raw["equation"]:
        kinds.setdefault((row["status"], *sorted(k for k in row if k in SHAPE)), row)
    # every status the ledger has (Tisserand's: holds, misprint, definition, not-checkable;
    # no fails since its line 180 is a misprint): the cache stores a row's fields whatever they
    assert {kind[0] for kind in kinds} == {row["status"] for row in raw["equation"]}
    assert {kind[0] for kind in kinds} >= {"holds", "misprint", "definition"}
    parts = [_toml_table("[ledger]", raw["ledger"]), _toml_table("[symbols]", raw["symbols"])]
    for name in sorted(set(raw) - {"ledger", "symbols", "equation"}):  # readings, assumptions
        parts += [_toml_table(f"[[{name}]]", table) for table in raw[name]]
    named = {i for t in raw.get("assumption", []) for i in t.get("rows", [])}  # must exist
    kept = {id(row) for row in kinds.values()}
    kept |= {id(row) for row in raw["equation"] if row["id"] in named}
    parts += [_toml_table("[[equation]]", r) for r in raw["equation"] if id(r) in kept]
    path.write_text("\n\n".join(parts) + "\n", encoding="utf-8")
    # the reading record names rows the cut ledger lacks; without one, no paragraph is read
    (tables / "papers" / "tisserand.reading.toml").unlink()
    return tables


SHAPE = ("kind", "reference", "printed", "reading_formula", "corrected_formula")


def _toml_table(header: str, table: dict[str, object]) -> str:
    # a JSON string, integer or list of integers is the same TOML value; keys bare where they
    # may be (as the committed ledger writes them), else quoted ("E()")
    lines = [f"{_key(k)} = {_value(v)}" for k, v in table.items()]
    return "\n".join([header, *lines])


def _value(value: object) -> str:
    # a mapping (a row's domain, each_case) is an inline TOML table; the rest as JSON
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(v)}" for k, v in value.items()) + "}"
    if isinstance(value, list) and any(isinstance(v, dict) for v in value):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    return json.dumps(value, ensure_ascii=False)


def _key(name: str) -> str:
    return name if re.fullmatch(r"[A-Za-z0-9_-]+", name) else json.dumps(name)


@pytest.fixture(scope="module")
def small_tables(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """_small_tables, shared by the tests that only read it."""
    return _small_tables(tmp_path_factory.mktemp("small"))


def _entries(folder: Path) -> list[Path]:
    return sorted(folder.glob("pendcli-*.json")) if folder.is_dir() else []


def _refuse_to_compute(monkeypatch: pytest.MonkeyPatch) -> None:
    """From here on, computing a claim, a formula check, a ledger or the stability table
    fails the test: what follows must come from the cache."""

    def computed(*_args: object, **_kwargs: object) -> None:
        raise AssertionError("computed, not read from the cache")

    # imported before the registry is patched: imported after, pendcli.run.reproduce would bind
    # the patched functions by its `from ... import`, and the monkeypatch's undo would then
    # restore them, failing every later test of this worker (seen under -n 2)
    import pendcli.run.reproduce  # noqa: F401

    for name in ("claim_rows", "formula_checks", "equation_rows", "stability_rows"):
        monkeypatch.setattr(registry, name, computed)
    monkeypatch.setattr("pendcli.run.reproduce.claim_rows", computed)
    monkeypatch.setattr("pendcli.run.reproduce.formula_checks", computed)


@pytest.mark.slow
@pytest.mark.parametrize("command", [EQUATIONS, REPRODUCE], ids=["equations", "reproduce"])
def test_a_warm_run_prints_the_cold_bytes_in_every_format(
    tmp_path, monkeypatch, command, small_tables
):
    env = {"PENDCLI_CACHE": str(tmp_path / "cache"), "PENDCLI_TABLES": str(small_tables)}
    cold = {f: invoke(*command, "-f", f, "--no-cache", env=env) for f in FORMATS}
    assert _entries(tmp_path / "cache") == []  # --no-cache neither reads nor writes
    first = invoke(*command, "-f", "json", env=env)
    assert first.code == 0, first.err
    assert first.out == cold["json"].out
    assert _entries(tmp_path / "cache")
    _refuse_to_compute(monkeypatch)
    for fmt in FORMATS:
        warm = invoke(*command, "-f", fmt, env=env)
        assert (warm.code, warm.err) == (0, "")
        assert warm.out == cold[fmt].out, fmt


def test_without_the_cache_the_run_computes(tmp_path, monkeypatch):
    """The test above would pass if _refuse_to_compute refused nothing: here it must fail."""
    env = {"PENDCLI_CACHE": str(tmp_path / "cache")}
    _refuse_to_compute(monkeypatch)
    result = invoke(*EQUATIONS, "-f", "json", env=env)
    assert result.code != 0 and "computed, not read from the cache" in result.err


def _copy_tables(tmp_path: Path) -> Path:
    copy = tmp_path / "tables"
    shutil.copytree(tables_dir(), copy)
    return copy


def test_one_byte_changed_in_a_table_is_a_miss(tmp_path):
    tables = _copy_tables(tmp_path)
    before = ResultCache(tmp_path, tables).key("equations", {"paper": "charbonnier"})
    ledger = tables / "equations" / "charbonnier.toml"
    data = bytearray(ledger.read_bytes())
    data[-2] ^= 0x01
    ledger.write_bytes(bytes(data))
    after = ResultCache(tmp_path, tables).key("equations", {"paper": "charbonnier"})
    assert before != after
    (tables / "papers" / "new.txt").write_bytes(b"")  # a new file, even empty
    assert ResultCache(tmp_path, tables).key("equations", {"paper": "charbonnier"}) != after


def test_one_byte_changed_in_a_source_file_is_a_miss(tmp_path):
    package = tmp_path / "pendcli"
    shutil.copytree(Path(cache_module.__file__).parent.parent, package, symlinks=True)
    before = folders_digest([("pendcli", package)])
    source = package / "verify" / "verdict.py"
    data = bytearray(source.read_bytes())
    data[len(data) // 2] ^= 0x01
    source.write_bytes(bytes(data))
    assert folders_digest([("pendcli", package)]) != before
    # a paper's own package (tests' sample paper) is part of the key the same way
    paper = tmp_path / "paper"
    paper.mkdir()
    (paper / "model.py").write_text("X = 1\n", encoding="utf-8")
    key = ResultCache(tmp_path, tables_dir(), [paper]).key("claims", {"paper": "p"})
    (paper / "model.py").write_text("X = 2\n", encoding="utf-8")
    assert ResultCache(tmp_path, tables_dir(), [paper]).key("claims", {"paper": "p"}) != key


def test_the_parameters_and_the_tables_folder_are_in_the_key(tmp_path):
    cache = ResultCache(tmp_path, tables_dir())
    assert cache.key("claims", {"paper": "a"}) != cache.key("claims", {"paper": "b"})
    assert cache.key("claims", {"paper": "a"}) != cache.key("formulas", {"paper": "a"})


def test_a_changed_ledger_is_recomputed_not_served_stale(tmp_path):
    tables = _small_tables(tmp_path)
    env = {"PENDCLI_CACHE": str(tmp_path / "cache"), "PENDCLI_TABLES": str(tables)}
    first = invoke(*EQUATIONS, "-f", "json", env=env)
    assert first.code == 0, first.err
    ledger = tables / "equations" / "tisserand.toml"
    text = ledger.read_text(encoding="utf-8")
    statement = json.loads(first.out)["equations"][0]["statement"]
    assert text.count(f'statement = "{statement}"') == 1
    ledger.write_text(text.replace(statement, statement + " (edited)", 1), encoding="utf-8")
    clear_table_cache()
    second = invoke(*EQUATIONS, "-f", "json", env=env)
    assert json.loads(second.out)["equations"][0]["statement"] == statement + " (edited)"


@pytest.mark.parametrize("damage", ["truncated", "garbage", "empty", "other-json", "folder"])
def test_a_damaged_entry_is_recomputed(tmp_path, damage, small_tables):
    env = {"PENDCLI_CACHE": str(tmp_path / "cache"), "PENDCLI_TABLES": str(small_tables)}
    cold = invoke(*EQUATIONS, "-f", "json", env=env)
    entries = _entries(tmp_path / "cache")
    assert entries
    for entry in entries:
        data = entry.read_bytes()
        if damage == "folder":
            entry.unlink()
            entry.mkdir()
            continue
        entry.write_bytes(
            {
                "truncated": data[: len(data) // 2],
                "garbage": b"\xff\xfe not json",
                "empty": b"",
                "other-json": b'{"format": 1, "kind": "equations", "value": [{"id": 3}]}',
            }[damage]
        )
    again = invoke(*EQUATIONS, "-f", "json", env=env)
    assert (again.code, again.out) == (0, cold.out), again.err
    if damage != "folder":  # rewritten whole
        for entry in entries:
            assert entry.read_bytes().startswith(f"pendcli result cache {FORMAT} ".encode())


def test_off_never_writes(tmp_path, small_tables):
    home, xdg = tmp_path / "home", tmp_path / "xdg"
    env = {"PENDCLI_CACHE": "off", "HOME": str(home), "XDG_CACHE_HOME": str(xdg)}
    env["PENDCLI_TABLES"] = str(small_tables)
    result = invoke(*EQUATIONS, "-f", "json", env=env)
    assert result.code == 0, result.err
    assert not home.exists() and not xdg.exists()
    assert cache_folder(env) is None


def test_where_the_cache_lives():
    assert cache_folder({"PENDCLI_CACHE": "/x/c"}) == Path("/x/c")
    assert cache_folder({"PENDCLI_CACHE": "OFF"}) is None
    assert cache_folder({"XDG_CACHE_HOME": "/x/xdg"}) == Path("/x/xdg/pendcli")
    assert cache_folder({"XDG_CACHE_HOME": "relative"}) == Path.home() / ".cache" / "pendcli"
    assert cache_folder({}) == Path.home() / ".cache" / "pendcli"


def test_an_unwritable_folder_still_computes_with_one_status_line(tmp_path, small_tables):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder", encoding="utf-8")
    tables = {"PENDCLI_TABLES": str(small_tables)}
    env = {"PENDCLI_CACHE": str(blocker / "cache"), **tables}
    fresh = invoke(*EQUATIONS, "-f", "json", "--no-cache", env=tables)
    result = invoke(*EQUATIONS, "-f", "json", env=env)
    assert (result.code, result.out) == (0, fresh.out)
    lines = [line for line in result.err.splitlines() if line.strip()]
    assert len(lines) == 1 and "cache" in lines[0] and "Traceback" not in result.err
    quiet = invoke(*EQUATIONS, "-f", "json", "--quiet", env=env)
    assert (quiet.code, quiet.err) == (0, "")


def _put_many(folder: str, value: int) -> None:
    cache = ResultCache(Path(folder), tables_dir())
    for _ in range(20):
        cache.put("claims", {"paper": "race"}, {"writer": value, "pad": "x" * 20000})


def test_concurrent_writers_leave_a_whole_entry(tmp_path):
    context = multiprocessing.get_context("fork")
    writers = [context.Process(target=_put_many, args=(str(tmp_path), i)) for i in range(4)]
    for w in writers:
        w.start()
    for w in writers:
        w.join()
    assert all(w.exitcode == 0 for w in writers)
    value = ResultCache(tmp_path, tables_dir()).get("claims", {"paper": "race"})
    assert value["writer"] in range(4) and len(value["pad"]) == 20000
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []  # no temporaries


def test_rows_round_trip_exactly():
    from pendcli.papers.registry import claim_rows, formula_checks

    claims, formulas = claim_rows("charbonnier"), formula_checks("charbonnier")
    for cls, rows in ((ClaimRow, claims), (FormulaRow, formulas)):
        back = rows_from_json(cls, json.loads(json.dumps(rows_to_json(rows))))
        assert back == rows
        assert [type(r.verdict) for r in back] == [type(r.verdict) for r in rows]
    equation = EquationRow("a.eq.1", "a", "(1)", "I", "s", "holds", "", 2.0, "", (3, 4))
    (back,) = rows_from_json(EquationRow, json.loads(json.dumps(rows_to_json([equation]))))
    assert back.lines == (3, 4) and back.observed_order == 2.0


def test_a_numpy_scalar_is_not_cached_as_a_float():
    row = EquationRow("a.eq.1", "a", "(1)", "I", "s", "holds", "", np.float64(2.0), "")
    with pytest.raises(TypeError, match="float64"):
        rows_to_json([row])


# `pendcli check` never reads the cache: tests/run/test_regression.py spies on its untouched run
# (a whole check, shared with the test that it passes).


def test_cache_clear(tmp_path, small_tables):
    env = {"PENDCLI_CACHE": str(tmp_path / "cache"), "PENDCLI_TABLES": str(small_tables)}
    invoke(*EQUATIONS, "-f", "json", env=env)
    count = len(_entries(tmp_path / "cache"))
    assert count
    result = invoke("cache", "clear", env=env)
    assert result.code == 0, result.err
    assert str(count) in result.err
    assert _entries(tmp_path / "cache") == []


def test_the_cache_keeps_the_most_recent_entries(tmp_path, monkeypatch):
    monkeypatch.setattr(cache_module, "KEEP", 3)
    cache = ResultCache(tmp_path, tables_dir())
    for i in range(5):
        cache.put("claims", {"paper": f"p{i}"}, [i])
        os.utime(cache.entry_path("claims", {"paper": f"p{i}"}), (i, i))
    cache.put("claims", {"paper": "last"}, [9])
    assert len(_entries(tmp_path)) == 3
    assert cache.get("claims", {"paper": "last"}) == [9]
    assert cache.get("claims", {"paper": "p0"}) is None


@pytest.mark.slow
def test_a_warm_report_is_the_cold_report(tmp_path, monkeypatch):
    env = {"PENDCLI_CACHE": str(tmp_path / "cache")}
    args = ("reproduce", "-p", "tisserand", "-q", "-f", "json")
    cold = invoke(*args, "--out", str(tmp_path / "cold"), env=env)
    assert cold.code == 0, cold.err
    _refuse_to_compute(monkeypatch)
    monkeypatch.setattr("pendcli.output.report._fill", lambda *a: pytest.fail("report not cached"))
    warm = invoke(*args, "--out", str(tmp_path / "warm"), env=env)
    assert (warm.code, warm.out) == (0, cold.out), warm.err
    names = sorted(p.relative_to(tmp_path / "cold") for p in (tmp_path / "cold").rglob("*"))
    assert names == sorted(p.relative_to(tmp_path / "warm") for p in (tmp_path / "warm").rglob("*"))
    for name in names:
        if (tmp_path / "cold" / name).is_file():
            cold_bytes = (tmp_path / "cold" / name).read_bytes()
            assert (tmp_path / "warm" / name).read_bytes() == cold_bytes, name


@pytest.mark.slow
def test_the_bench_measures_cold_and_warm_against_the_floor(monkeypatch):
    import sys

    from tools import bench_startup

    quick = [sys.executable, "-c", "pass"]
    monkeypatch.setattr(
        bench_startup,
        "_floor_commands",
        lambda folder: dict.fromkeys((bench_startup.FLOOR, *bench_startup.FLOOR_TARGETS), quick),
    )
    times = bench_startup.floor_times(runs=1)
    assert set(times) == {
        (bench_startup.FLOOR, ""),
        *((label, mode) for label in bench_startup.FLOOR_TARGETS for mode in ("cold", "warm")),
    }
    text = "\n".join(bench_startup.floor_lines(times, 1))
    for label in bench_startup.FLOOR_TARGETS:
        assert f"| `{label}` | cold |" in text and f"| `{label}` | warm |" in text


def test_another_version_of_a_library_is_another_key(tmp_path, monkeypatch):
    """The key names the libraries pendcli computes with and what they require: a library
    upgraded (its dist-info renamed) is a miss, never a result of the old one; a test tool
    installed beside them (`make test` adds pytest, ruff, mypy) keeps the key."""
    import sys

    from pendcli.base import cache, versions

    site = tmp_path / "site"
    (site / "fakelib").mkdir(parents=True)
    (site / "fakelib" / "__init__.py").write_text("")
    (site / "fakelib-1.0.dist-info").mkdir()
    monkeypatch.syspath_prepend(str(site))
    monkeypatch.setattr(versions, "DEPENDENCIES", ("fakelib",))
    sys.modules.pop("fakelib", None)

    def key() -> str:
        return cache.ResultCache(tmp_path / "c", tmp_path / "tables").key("claims", {})

    (tmp_path / "tables").mkdir()
    before = key()
    (site / "pytest-9.0.dist-info").mkdir()  # a test tool, required by nothing pendcli uses
    assert key() == before
    (site / "fakelib-1.0.dist-info").rename(site / "fakelib-1.1.dist-info")
    assert key() != before
    assert key() == key()


def _distribution(site: Path, name: str, *requires: str) -> None:
    info = site / f"{name}.dist-info"
    info.mkdir(parents=True)
    lines = [f"Name: {name.split('-')[0]}", *(f"Requires-Dist: {r}" for r in requires)]
    (info / "METADATA").write_text("\n".join([*lines, "", "Requires-Dist: in the body"]))


def test_the_key_follows_what_the_libraries_require_and_no_extra(tmp_path):
    from pendcli.base.cache_key import required_distributions

    _distribution(tmp_path, "scipy-1.0", "numpy>=1.25", "Foo.Bar (>=2)", 'pytest; extra == "test"')
    _distribution(tmp_path, "numpy-2.0", 'colorama; platform_system == "Windows"')
    _distribution(tmp_path, "foo_bar-2.1", "numpy")
    _distribution(tmp_path, "pytest-9.0", "pluggy")
    _distribution(tmp_path, "pluggy-1.6")
    (tmp_path / "old_style-0.1-py3.11.egg-info").mkdir()
    found = required_distributions(tmp_path, ["scipy", "Old.Style", "absent"])
    assert found == [
        "foo_bar-2.1.dist-info",
        "numpy-2.0.dist-info",
        "old_style-0.1-py3.11.egg-info",
        "scipy-1.0.dist-info",
    ]


def test_the_installed_closure_is_what_importlib_metadata_says() -> None:
    """Against an independent reading: importlib.metadata's own requirement lists."""
    import re
    from importlib.metadata import PackageNotFoundError, requires

    from pendcli.base.cache_key import installed_signature
    from pendcli.base.versions import DEPENDENCIES

    def project(name: str) -> str:
        return re.sub(r"[-_.]+", "-", name).lower()

    closure, queue = set(), [project(d) for d in DEPENDENCIES]
    while queue:
        name = queue.pop()
        if name in closure:
            continue
        try:
            found = requires(name) or []
        except PackageNotFoundError:
            continue
        closure.add(name)
        queue += [project(re.split(r"[ ;<>=!~\[(]", r, maxsplit=1)[0])
                  for r in found if "extra ==" not in r]  # fmt: skip
    listed = {
        project(line.rsplit("/", 1)[1].rsplit(".", 1)[0].split("-", 1)[0])
        for line in installed_signature().splitlines()
        if line.endswith((".dist-info", ".egg-info"))
    }
    assert listed == closure
    assert "pytest" not in listed and "ruff" not in listed
