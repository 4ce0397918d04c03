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
