"""The terminal view of `reproduce`: 80 columns, no broken token, the propagation tree."""

from __future__ import annotations

from pendcli.output.summary import disagrees, propagation_tree


def test_tree_draws_each_root_with_what_inherits_from_it():
    rows = [
        {"id": "p.a", "cause": "arithmetic-slip", "from": []},
        {"id": "p.b", "cause": "propagated", "from": ["p.a"]},
        {"id": "p.c", "cause": "propagated", "from": ["p.b", "p.d"]},
        {"id": "p.d", "cause": "rounding", "from": []},
        {"id": "p.e", "cause": None, "from": []},
    ]
    assert propagation_tree(rows) == [
        "a (arithmetic-slip)",
        "  └ b (propagated)",
        "    └ c (propagated)",
        "d (rounding)",
        "  └ c (propagated)",
    ]


def test_disagrees_covers_claims_formulas_and_equations():
    assert [disagrees({"verdict": v}) for v in ("agrees", "last-digit", "holds", "fails")] == [
        False,
        True,
        False,
        True,
    ]
    assert disagrees({"status": "misprint"}) and not disagrees({"status": "definition"})


def _reproduce(*args: str) -> str:
    """`pendcli reproduce ARGS` at 80 columns, in this process (its computation served by
    ``reproduce_computed_once``: what is tested is the view)."""
    from helpers.cli import invoke

    code, out, err = invoke("reproduce", *args, env={"COLUMNS": "80"}, utf8=True)
    assert code == 0, err
    return out


def test_reproduce_fits_80_columns_with_every_id_whole_and_a_summary(reproduce_computed_once):
    from pendcli.papers.registry import PAPERS
    from pendcli.run.reproduce import reproduce_all

    text = _reproduce()
    lines = text.splitlines()
    assert max(len(line) for line in lines) <= 80
    result = reproduce_all(PAPERS, jobs=1)
    words = set(text.split())
    for row in [*result.claim_dicts(), *result.formula_dicts()]:
        assert str(row["id"]).split(".", 1)[1] in words  # whole, not folded over two lines
    assert "Summary: printed numbers" in text and "--notes" in lines[-1]
    # the root slips of the tree are the rows the causes name, each once per descendant chain
    assert "example.time.2 (arithmetic-slip)" in text
    assert "└ example.interval.1 (propagated)" in text
    # the two verdicts side by side: against the truth, against his own procedure
    by_id: dict[str, list[str]] = {}
    for line in lines:  # the claims table's line of each id (the tree names some again)
        if line.strip():
            by_id.setdefault(line.split()[0], line.split())
    assert by_id["example.time.3"][3:] == ["last-digit", "faithful", "inputs"]
    assert by_id["example.time.2"][3:] == ["discrepant", "slip", "slip"]
    assert by_id["j2_zeros.2"][3:] == ["truncated", "—", "chopped"]  # no procedure known
    assert len(lines) < 260  # no notes: 3,336 lines before the compact table


def test_only_failing_keeps_just_what_does_not_hold(reproduce_computed_once):
    text = _reproduce("--only-failing", "--paper", "tisserand")
    assert "Tisserand: printed numbers" not in text  # all five agree
    assert "Summary: printed numbers" in text


def test_equations_command_lists_each_label_and_filters_by_status(monkeypatch, shared_result_cache):
    import json

    from helpers.cli import assert_clean_error, invoke

    monkeypatch.setenv("PENDCLI_CACHE", shared_result_cache)  # the ledger once, then filtered
    code, out, err = invoke("equations", "--paper", "charbonnier")
    assert code == 0, err
    for label in [f"({n})" for n in range(1, 10)] + ["(p)", "(q)"]:
        assert label in out.split()
    args = ("equations", "--paper", "charbonnier", "--status", "misprint", "-f", "json")
    code, out, err = invoke(*args)
    rows = json.loads(out)["equations"]
    assert rows and {r["status"] for r in rows} == {"misprint"}
    # each read (the evident reading, in words and as a formula) and its blame recorded (a
    # row restating another's slip records none: the restated row does)
    assert all(r["reading_note"] and r["reading"] for r in rows)
    assert all(r["later_use"] for r in rows if not r["restates"])
    assert any(r["restates"] for r in rows)  # the I_(-1) label printed again, line 498
    assert_clean_error(*invoke("equations", "--status", "wrong")[::2])


def test_ledger_parts_in_two_processes_give_the_ledger_in_order():
    # reproduce cuts each ledger in parts run in two processes; the rows must come back
    # whole and in the ledger's order, equal to one direct evaluation.
    from pendcli.papers.registry import equation_rows
    from pendcli.run.reproduce import reproduce_all

    direct = equation_rows(["charbonnier"])
    for jobs in (1, 2):
        result = reproduce_all(("charbonnier",), equations=True, jobs=jobs)
        assert result.equations["charbonnier"] == direct


def test_formula_rows_are_shared_only_inside_the_block():
    from pendcli.papers.registry import formula_checks
    from pendcli.verify.claims import sharing_formula_rows

    with sharing_formula_rows("tisserand", []):
        assert formula_checks("tisserand") == []
    assert formula_checks("charbonnier")  # computed again once the block is left
