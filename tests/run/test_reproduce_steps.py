"""How a run shares its work: a ledger judged alone (``pendcli equations``) computes its
paper's formula checks once, however many parts of the ledger are judged."""

from __future__ import annotations

import pytest


def test_a_ledger_judged_alone_computes_its_formula_checks_once(
    monkeypatch: pytest.MonkeyPatch, tmp_path
) -> None:
    """Tisserand's ledger names formula checks (``measured``) and is judged in two parts; the
    checks are computed once and both parts read them: the observed orders are those the
    checks measure."""
    import pendcli.papers.tisserand.formulas as formulas
    from pendcli.base.cache import ResultCache
    from pendcli.data.ledger import load_ledger
    from pendcli.data.tables import tables_dir
    from pendcli.run.reproduce import LEDGER_PARTS, reproduce_all

    real, calls = formulas.formula_checks, []

    def counted() -> list:
        calls.append(1)
        return real()

    monkeypatch.setattr(formulas, "formula_checks", counted)
    empty = ResultCache(tmp_path / "cache", tables_dir())
    result = reproduce_all(("tisserand",), formulas=False, equations=True, jobs=1, cache=empty)
    assert LEDGER_PARTS > 1 and len(calls) == 1
    checks = {row.id: row.observed_order for row in real()}
    names = {row.id: row.measured for row in load_ledger("tisserand").rows if row.measured}
    judged = {row.id: row.observed_order for row in result.equations["tisserand"]}
    assert names and set(names) <= set(judged)
    for row_id, wanted in names.items():
        orders = [checks[f"tisserand.{i}"] for i in wanted]  # each named check exists
        orders = [o for o in orders if o is not None]
        assert judged[row_id] == (pytest.approx(min(orders)) if orders else None)


@pytest.mark.parametrize("jobs", [1, 2])
@pytest.mark.parametrize("asked", [True, False])
def test_a_ledger_s_formula_checks_run_once_in_a_step_of_the_shared_queue(
    monkeypatch: pytest.MonkeyPatch, tmp_path, jobs: int, asked: bool
) -> None:
    """The formula checks run once, in a step (with the ledger's first part when they are
    asked for too; else their own, no longer before the fork), whichever process takes the
    ledger's parts (the other used to run them all again): every row that names a check
    carries the order it measures and its id, in every part."""
    import os

    import pendcli.papers.tisserand.formulas as formulas
    from pendcli.data.ledger import load_ledger
    from pendcli.run.reproduce import LEDGER_PARTS, reproduce_all

    real, log = formulas.formula_checks, tmp_path / "calls"

    def counted() -> list:
        with log.open("a", encoding="utf-8") as fh:  # a worker's call reaches the file too
            fh.write(f"{os.getpid()}\n")
        return real()

    monkeypatch.setattr(formulas, "formula_checks", counted)
    result = reproduce_all(("tisserand",), formulas=asked, equations=True, jobs=jobs)
    assert LEDGER_PARTS > 1 and len(log.read_text(encoding="utf-8").split()) == 1
    checks = {row.id: row.observed_order for row in real()}
    ledger = load_ledger("tisserand").rows
    names = {row.id: row.measured for row in ledger if row.measured}
    judged = {row.id: row for row in result.equations["tisserand"]}
    later = {row.id for row in ledger[len(ledger) // LEDGER_PARTS :]}
    assert names.keys() & later  # rows that name a check in a part after the first
    for row_id, wanted in names.items():
        orders = [checks[f"tisserand.{i}"] for i in wanted]
        orders = [o for o in orders if o is not None]
        assert judged[row_id].observed_order == (pytest.approx(min(orders)) if orders else None)
        assert all(f"tisserand.{i} " in (judged[row_id].measured or "") for i in wanted)
