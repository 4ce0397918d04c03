"""`pendcli check`: drift in a value, a verdict, a published string or a row is caught."""

from __future__ import annotations

import shutil

import pytest

from pendcli.base.errors import PendcliError
from pendcli.run.drift import TOLERANCES, compare_tables

HEADER = (
    "id,published,unit,recomputed,exact,abs_diff,rel_diff,verdict,procedure_verdict,"
    "procedure_value,cause,from,condition\n"
)
ROW = 'x.a,"5,14",,5.135622301840683,,-0.004377698159317,-0.00085,agrees,,,,,\n'


def test_identical_tables_have_no_drift():
    assert compare_tables("t.csv", HEADER + ROW, HEADER + ROW) == []


def test_last_bit_noise_is_within_tolerance():
    noisy = ROW.replace("5.135622301840683", "5.135622301840684")
    assert compare_tables("t.csv", HEADER + ROW, HEADER + noisy) == []


@pytest.mark.parametrize(
    ("changed", "column"),
    [
        (ROW.replace("5.135622301840683", "5.1357"), "recomputed"),
        (ROW.replace("agrees", "truncated"), "verdict"),
        (ROW.replace('"5,14"', '"5,15"'), "published"),
        (ROW.replace("agrees,,", "agrees,slip,"), "procedure_verdict"),
    ],
)
def test_real_changes_are_drift(changed, column):
    drifts = compare_tables("t.csv", HEADER + ROW, HEADER + changed)
    assert [d.column for d in drifts] == [column]
    assert drifts[0].id == "x.a"


def test_added_and_removed_rows():
    other = ROW.replace("x.a", "x.b")
    drifts = compare_tables("t.csv", HEADER + ROW, HEADER + other)
    assert {(d.id, d.now) for d in drifts} == {("x.a", "gone"), ("x.b", "new")}


@pytest.mark.parametrize(
    "bad",
    [
        "nonsense\n1,2\n",
        HEADER + "x.a,1\n",
        HEADER + ROW + ROW,
        HEADER + ROW.replace("5.135622301840683", "five"),
    ],
)
def test_malformed_committed_table_names_the_file(bad):
    with pytest.raises(PendcliError) as err:
        compare_tables("t.csv", bad, HEADER + ROW)
    assert "t.csv" in str(err.value)


@pytest.mark.parametrize(
    ("bad", "message"),
    [
        ("", "empty table; expected the header line id,published,unit"),
        (HEADER.replace("verdict", "verdicts") + ROW, "line 1: header"),
        (HEADER.replace("unit,", "") + ROW, "line 1: header"),
        (HEADER + ROW + "x.b,1\n", "line 3 has 2 fields; expected 13"),
        (HEADER + ROW.replace("agrees", "agrees,extra"), "line 2 has 14 fields"),
        (HEADER + ROW + ROW, "line 3 repeats id 'x.a'"),
        (HEADER + ROW.replace("x.a", ""), "line 2 has an empty id"),
        (HEADER + ROW + ROW.replace("x.a", "x.b").replace("-0.00085", '"0,1"'), "line 3, column"),
        (HEADER + ROW.replace('"5,14"', '"5,14'), "malformed CSV"),
    ],
)
def test_committed_table_validation_names_file_and_line(bad, message):
    with pytest.raises(PendcliError) as err:
        compare_tables("lecornu-claims.csv", bad, HEADER + ROW, where="tables/x/lecornu-claims.csv")
    assert str(err.value).startswith("tables/x/lecornu-claims.csv: ")
    assert message in str(err.value)
    assert "\n" not in str(err.value)


def test_a_formulas_table_needs_the_formula_header():
    with pytest.raises(PendcliError, match=r"regenerated lecornu-formulas\.csv: line 1: header"):
        compare_tables("lecornu-formulas.csv", HEADER + ROW, HEADER + ROW)


@pytest.mark.parametrize("token", ["inf", "-inf", "nan", "1e400", "-1e400", "Infinity"])
@pytest.mark.parametrize("column_value", ["5.135622301840683", "-0.00085"])
def test_a_non_finite_committed_value_is_drift(token, column_value):
    tampered = ROW.replace(column_value, token)
    drifts = compare_tables("t.csv", HEADER + tampered, HEADER + ROW)
    assert [(d.committed, d.difference) for d in drifts] == [(token, "non-finite")]
    # and the other way round: the code starts producing a non-finite value
    drifts = compare_tables("t.csv", HEADER + ROW, HEADER + tampered)
    assert [(d.now, d.difference) for d in drifts] == [(token, "non-finite")]


@pytest.mark.parametrize("token", ["inf", "-inf", "nan"])
def test_the_same_non_finite_token_on_both_sides_is_no_drift(token):
    row = ROW.replace("-0.00085", token)
    assert compare_tables("t.csv", HEADER + row, HEADER + row) == []
    other = {"inf": "1e400", "-inf": "-1e400", "nan": "inf"}[token]
    assert compare_tables("t.csv", HEADER + row, HEADER + ROW.replace("-0.00085", other))


def test_a_huge_finite_change_is_drift():
    row = ROW.replace("5.135622301840683", "1.7e308")
    assert compare_tables(
        "t.csv", HEADER + row, HEADER + ROW.replace("5.135622301840683", "-1.7e308")
    )


def test_every_committed_column_has_an_explicit_tolerance():
    from pendcli.run.drift import CLAIM_COLUMNS, FORMULA_COLUMNS

    for col in set(CLAIM_COLUMNS + FORMULA_COLUMNS) - {"id"}:
        assert col in TOLERANCES


def test_missing_and_extra_committed_tables_are_drift(tmp_path):
    from pendcli.run.drift import find_drifts

    (tmp_path / "old.csv").write_text(HEADER + ROW, encoding="utf-8")
    (tmp_path / "same.csv").write_text(HEADER + ROW, encoding="utf-8")
    tables = {"same.csv": HEADER + ROW, "new.csv": HEADER + ROW}
    found = {(d.table, d.committed, d.now) for d in find_drifts(tmp_path, tables)}
    assert found == {
        ("old.csv", "committed", "no longer produced"),
        ("new.csv", "missing", "produced"),
    }


def test_a_number_that_appears_or_vanishes_is_drift():
    empty = ROW.replace("5.135622301840683", "")
    drifts = compare_tables("t.csv", HEADER + ROW, HEADER + empty)
    assert [(d.column, d.difference) for d in drifts] == [("recomputed", "appeared/vanished")]


def test_check_passes_untouched_and_fails_tampered(tmp_path, monkeypatch):
    """Untouched, `pendcli check` passes and never reads the result cache (it is the CI's
    drift detector: the cache's key cannot see an environment that changes a BLAS kernel, so
    it always computes); one run with a printed value edited, a committed verdict and a
    committed ledger status tampered names each of the three drifts by its row. The second
    check computes the claims and formulas again and is served the first one's ledgers (the
    tampered ledger table is a committed one: what the ledger computes is unchanged; the
    edited published value would only make Charbonnier's ledger derived afresh)."""
    from dataclasses import replace

    from helpers.cli import invoke

    from pendcli.api import check
    from pendcli.base.cache import ResultCache
    from pendcli.data.tables import clear_table_cache, tables_dir
    from pendcli.run import reproduce

    computed, first = reproduce.reproduce_all, []

    def kept(*args, **kwargs):  # type: ignore[no-untyped-def]
        first.append(computed(*args, **kwargs))
        return first[-1]

    def ledgers_kept(keys, formulas, quiet, jobs, equations):  # type: ignore[no-untyped-def]
        assert equations and set(keys) == set(first[0].equations)
        result = computed(keys, formulas=formulas, quiet=quiet, jobs=jobs, equations=False)
        return replace(result, equations=first[0].equations)

    shutil.copytree(tables_dir(), tmp_path / "tables")
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path / "tables"))
    clear_table_cache()
    try:
        reads: list[object] = []
        with monkeypatch.context() as spied:
            spied.setattr(ResultCache, "get", lambda self, *args: reads.append(args))
            spied.setenv("PENDCLI_CACHE", str(tmp_path / "cache"))
            spied.setattr(reproduce, "reproduce_all", kept)
            result = invoke("check", "--format", "json")
        assert result.code == 0, result.err
        assert reads == [] and not any((tmp_path / "cache").rglob("*"))
        path = tmp_path / "tables" / "published" / "charbonnier.toml"
        text = path.read_text(encoding="utf-8")
        path.write_text(text.replace('published = "2·2/(1·3)"', 'published = "2·2/(1·5)"'), "utf-8")
        regenerated = tmp_path / "tables" / "regenerated"
        claims = regenerated / "tisserand-claims.csv"
        claims.write_text(claims.read_text("utf-8").replace("agrees", "discrepant", 1), "utf-8")
        ledger = regenerated / "lecornu-equations.csv"
        lines = ledger.read_text("utf-8").splitlines(keepends=True)
        row = next(i for i, line in enumerate(lines) if ",holds," in line)
        tampered_id = lines[row].split(",", 1)[0]
        lines[row] = lines[row].replace(",holds,", ",fails,")
        ledger.write_text("".join(lines), "utf-8")
        clear_table_cache()
        assert len(first) == 1
        monkeypatch.setattr(reproduce, "reproduce_all", ledgers_kept)
        drifts = {(d.table, d.id, d.column, d.committed, d.now) for d in check()}
        tables = {d[:3] for d in drifts}
        assert ("charbonnier-claims.csv", "charbonnier.I_pi.n2", "published") in tables
        assert ("charbonnier-claims.csv", "charbonnier.I_pi.n2", "verdict") in tables
        assert any(t == "tisserand-claims.csv" and c == "verdict" for t, _, c in tables)
        assert ("lecornu-equations.csv", tampered_id, "status", "fails", "holds") in drifts
    finally:
        clear_table_cache()


def _moved(text: str, row: int, column: str, by: float) -> str:
    """``text`` (a committed CSV) with one numeric cell moved by ``by``, written as to_csv does."""
    import csv
    import io

    records = list(csv.reader(io.StringIO(text)))
    col = records[0].index(column)
    records[row][col] = repr(float(records[row][col]) + by)
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows(records)
    return out.getvalue()


def test_check_update_keeps_what_moved_only_within_the_tolerance(tmp_path) -> None:
    """Another CPU's kernels move an observed order by ~1e-9: a committed row whose every cell
    is within its tolerance stays byte for byte; a row moved beyond it is rewritten, the rest
    of the table kept (check --update on a fresh clone changes no byte)."""
    from pendcli.data.tables import tables_dir
    from pendcli.run.regression import kept_within_tolerance

    name = "lecornu-formulas.csv"
    committed = (tables_dir() / "regenerated" / name).read_text(encoding="utf-8")
    folder = tmp_path / "regenerated"
    folder.mkdir()
    (folder / name).write_text(committed, encoding="utf-8")
    limit = TOLERANCES["observed_order"][1]
    noise = _moved(committed, 1, "observed_order", 1e-9)
    assert noise != committed
    assert kept_within_tolerance(folder, {name: noise}) == {name: committed}
    real = _moved(noise, 2, "observed_order", 2 * limit)  # row 2 moves beyond, row 1 noise
    kept = kept_within_tolerance(folder, {name: real})[name].splitlines()
    assert kept[1] == committed.splitlines()[1]  # the noise is not recorded
    assert kept[2] == real.splitlines()[2] != committed.splitlines()[2]  # the change is
    assert kept[3:] == committed.splitlines()[3:]


def test_check_update_leaves_a_set_that_holds_its_bytes_as_it_is(
    tmp_path, monkeypatch, capsys, computed_tables
):
    """Untouched, `check --update` swaps nothing: the folder and each file keep their inode and
    time, and it says so; with one committed cell moved beyond its tolerance it rewrites the
    set, and that cell is the regenerated one again. What is tested is the writing: the
    computation is served, done once for the run (tests/helpers/regenerated.py)."""
    from helpers.regenerated import served

    from pendcli.data.tables import clear_table_cache, tables_dir
    from pendcli.run import reproduce
    from pendcli.run.regression import run_check

    monkeypatch.setattr(reproduce, "reproduce_all", served(computed_tables))

    shutil.copytree(tables_dir(), tmp_path / "tables")
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path / "tables"))
    monkeypatch.setenv("COLUMNS", "200")
    folder = tmp_path / "tables" / "regenerated"
    clear_table_cache()

    def stamps() -> dict[str, tuple[int, int]]:
        paths = [folder, *folder.glob("*.csv")]
        return {p.name: (p.stat().st_ino, p.stat().st_mtime_ns) for p in paths}

    try:
        before = stamps()
        assert run_check(update=True) == 0
        assert "no table rewritten" in capsys.readouterr().out
        assert stamps() == before
        path = folder / "lecornu-formulas.csv"
        committed = path.read_text("utf-8")
        path.write_text(_moved(committed, 1, "observed_order", 0.5), "utf-8")
        clear_table_cache()
        assert run_check(update=True) == 0
        assert f"rewrote {len(before) - 1} tables" in capsys.readouterr().out
        assert stamps()[folder.name][0] != before[folder.name][0]  # the set swapped
        assert path.read_text("utf-8") == committed
    finally:
        clear_table_cache()


def test_the_ledger_table_carries_each_rows_status_and_a_changed_one_is_a_drift() -> None:
    """A reproduce result with ledger rows gives ``<paper>-equations.csv`` (id, label, lines,
    status, dimensions, observed order); a status, a dimension verdict or a row that changes
    is a drift naming the row, an observed order within 0.05 is not."""
    from pendcli.data.rows import EquationRow
    from pendcli.data.vocabulary import EquationStatus
    from pendcli.run.regression import regenerated_tables
    from pendcli.run.reproduce import ReproduceResult

    def row(
        rid: str,
        status: str,
        order: float | None,
        dims: str = "consistent",
        condition: str | None = None,
    ) -> EquationRow:
        return EquationRow(
            rid,
            "p",
            "(1)",
            "§ 1",
            "x = y",
            EquationStatus(status),
            "series",
            order,
            "",
            lines=(3, 4),
            dimensions=dims,
            finding=status in ("fails", "misprint"),
            condition=condition,
        )

    def table(*rows: EquationRow) -> str:
        result = ReproduceResult(papers=("p",), equations={"p": list(rows)})
        return regenerated_tables(result)["p-equations.csv"]

    then = table(row("p.a", "holds", 2.0), row("p.b", "misprint", None), row("p.c", "holds", 1.0))
    assert then.splitlines() == [
        "id,equation,lines,status,kind,dimensions,observed_order,finding,condition",
        "p.a,(1),3-4,holds,series,consistent,2.0,,",
        "p.b,(1),3-4,misprint,series,consistent,,yes,",
        "p.c,(1),3-4,holds,series,consistent,1.0,,",
    ]
    side = "holds for g <= 9.80, fails for g > 9.80"
    now = table(
        row("p.a", "fails", 2.04, condition=side), row("p.b", "misprint", None, "inconsistent")
    )
    drifts = compare_tables("p-equations.csv", then, now)
    found = {(d.id, d.column, d.committed, d.now) for d in drifts}
    assert found == {
        ("p.a", "status", "holds", "fails"),
        ("p.a", "finding", "", "yes"),
        ("p.a", "condition", "", side),
        ("p.b", "dimensions", "consistent", "inconsistent"),
        ("p.c", "(row)", "present", "gone"),
    }  # fmt: skip


def test_check_fails_naming_the_row_whose_stored_derivation_the_code_no_longer_derives(
    tmp_path, monkeypatch, capsys
):
    """`pendcli check` derives the ledger again (Tisserand's here) and compares it with
    tables/derivations: one stored residual changed makes it fail before any table is
    recomputed, naming the row and its reference; the untouched store passes this step.
    The code and tables are the same for both checks: the ledger is derived once (the first
    check's derivation served to the second), the second compares a tampered store."""

    from pendcli.papers import registry
    from pendcli.run import regression
    from pendcli.verify import derivation_store, ledger_references

    monkeypatch.setattr(registry, "ledger_papers", lambda: ["tisserand"])
    derived = ledger_references.derivation_records
    fresh: dict[str, dict] = {}

    def derived_once(paper, root=None):  # type: ignore[no-untyped-def]
        assert root is None
        if paper.key not in fresh:
            fresh[paper.key] = derived(paper)
        return fresh[paper.key]

    monkeypatch.setattr(ledger_references, "derivation_records", derived_once)
    assert regression._derivations(False, None) == []
    assert list(fresh) == ["tisserand"]  # derived here, not forked away
    tables, rows = derivation_store.text_records("tisserand")  # each expression as srepr
    row_id, record = next(
        (k, v) for k, v in sorted(rows.items()) if "live" not in v and "forms" in v
    )
    item = record["forms"]["printed"]["items"][0]
    original = item["expr"]
    item["expr"] = f"Add({original}, Integer(1))"
    tampered = tmp_path / "tisserand.json"
    monkeypatch.setattr(derivation_store, "store_path", lambda paper: tampered)
    derivation_store.write_store("tisserand", tables, rows)
    try:
        assert regression.run_check() == 1
    finally:  # written once more where it was, which empties the store's memo before the
        # package's own store is read again
        item["expr"] = original
        derivation_store.write_store("tisserand", tables, rows)
    err = capsys.readouterr().err
    assert f"{row_id}: the stored derivation differs from the code's {record['reference']}" in err


def _drift_in_turn(key: str) -> list[str]:
    """A stand-in for one paper's derivation drift: Lecornu's waits (30 s at most) until
    another paper's has been derived, so the two processes both derive some."""
    import os
    import time
    from pathlib import Path

    sign = Path(os.environ["DRIFT_SIGN"])
    if key == "lecornu":
        until = time.monotonic() + 30
        while not sign.exists() and time.monotonic() < until:
            time.sleep(0.01)
    else:
        sign.touch()
    return [f"{key}|{os.getpid()}|{sign.exists()}"]


def test_the_derivations_are_compared_in_two_processes_and_said_in_the_ledgers_order(
    tmp_path, monkeypatch
):
    """`check` derives the ledgers again in this process and a forked worker (Lecornu's, the
    costliest, beside the others); the lines come back in the ledgers' order."""
    import os

    from pendcli.run import regression

    monkeypatch.setenv("PENDCLI_JOBS", "2")
    monkeypatch.setenv("DRIFT_SIGN", str(tmp_path / "derived"))
    monkeypatch.setattr(regression, "_drift", _drift_in_turn)
    lines = [
        line.split("|") for line in regression._drift_lines(["tisserand", "lecornu", "charbonnier"])
    ]
    assert [key for key, _, _ in lines] == ["tisserand", "lecornu", "charbonnier"]
    assert len({pid for _, pid, _ in lines}) == 2 and str(os.getpid()) in {p for _, p, _ in lines}
    assert all(seen == "True" for _, _, seen in lines)
