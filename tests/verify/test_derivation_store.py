"""The ledger's derivations as data (pendcli/verify/derivation_store.py, float_verdict.py).

The store is read by a closed grammar (code in it is refused, sizes bounded); it is used only
for the tables it was derived from, and never read from a tables folder given by
PENDCLI_TABLES; float64 decides an item only where the exact engine would say the same; and
its verdicts on expressions of known expansion are checked against mpmath.
"""

from __future__ import annotations

import json
from dataclasses import replace
from functools import cache
from pathlib import Path

import mpmath
import pytest
import sympy as sp

from pendcli.base.errors import PendcliError
from pendcli.data.ledger import load_ledger
from pendcli.data.printed import ledger_symbols
from pendcli.data.stored_expr import StoredExpr, read_expr
from pendcli.papers.registry import ledger_papers, paper
from pendcli.verify import float_verdict, ledger_references
from pendcli.verify.derivation_store import row_record, store_path, stored_nodes, stored_rows
from pendcli.verify.derived import Item, item_passes, relation_points
from pendcli.verify.ledger_references import row_printed_status

# --- the closed grammar ---------------------------------------------------------------------

REFUSED = [
    "__import__('os').system('true')",
    "Symbol('x').__class__",
    "(lambda: 1)()",
    "open('/etc/passwd')",
    "Pow(Integer(10), Integer(100000000))",
    "factorial(Integer(100000))",
    "Integer(" + "9" * 80 + ")",
    "Add(" * 300 + "Integer(1)" + ")" * 300,
    "Symbol(**{'name': 'x'})",
    "[Integer(1)]",
    "Add(Integer(1), 'x' + 'y')",
    "Integer(1",
]


@pytest.mark.parametrize("text", REFUSED)
def test_the_grammar_refuses_what_is_not_a_stored_expression(text: str) -> None:
    with pytest.raises(PendcliError) as raised:
        read_expr("a row", text)
    assert str(raised.value).startswith("a row: ") and "\n" not in str(raised.value)


# a table's nodes: a compound's arguments earlier nodes, leaves' literals of their head
_X = ["Symbol", "x", {"real": True}]
REFUSED_TABLES = [
    ([_X, ["Add", 0, 2]], "arguments it does not take"),  # a later node: no cycle can form
    ([["Add", 0]], "arguments it does not take"),  # itself
    ([_X, ["eval", 0]], "the grammar refuses"),
    ([_X, ["Integer", 10**61]], "arguments it does not take"),
    ([_X, ["Rational", 1, 0]], "arguments it does not take"),
    ([_X, ["Symbol", "y", {"real": "yes"}]], "arguments it does not take"),
    ([_X, ["Apply", 0, 0]], "no Function"),
    # each node twice the last: 2**30 nodes in the tree the last one stands for
    ([_X, *(["Add", k, k] for k in range(30))], "more than 200000 nodes"),
    ([_X, *(["sin", k] for k in range(250))], "more than 200 deep"),
    ("not a list", "must be a list"),
]


@pytest.mark.parametrize(("nodes", "why"), REFUSED_TABLES)
def test_a_table_of_nodes_is_refused_unless_every_node_is_of_the_grammar(
    nodes: object, why: str
) -> None:
    from pendcli.data.stored_expr import read_nodes

    with pytest.raises(PendcliError, match=why) as raised:
        read_nodes("a store", nodes)
    assert str(raised.value).startswith("a store") and "\n" not in str(raised.value)


def test_a_shared_node_is_one_expression_and_reads_back() -> None:
    """sin(x)**2 + sin(x): sin(x) written once, read back as sympy builds it, and compiled
    to numpy values that mpmath computes alike."""
    from pendcli.data.stored_expr import NodeWriter, StoredExpr
    from pendcli.verify.float_compile import compile_expr

    x = ledger_symbols("x")[0]
    expr = sp.sin(x) ** 2 + sp.sin(x)
    writer = NodeWriter()
    index = writer.encode("e", sp.srepr(expr))
    assert sum(1 for n in writer.nodes if n[0] == "sin") == 1
    table = writer.table("e")
    assert table.expr(index) == expr and table.text(index) == sp.srepr(expr)
    value = compile_expr(StoredExpr(table, index)).value({"x": 0.3}, 1)[0]
    assert value == pytest.approx(float(mpmath.sin(0.3) ** 2 + mpmath.sin(0.3)), rel=1e-15)


def test_the_grammar_reads_back_what_srepr_writes() -> None:
    x, t = sp.Symbol("x", real=True), sp.Symbol("t", real=True)
    expr = sp.besselj(0, x) * sp.Integral(sp.sin(t) / t, (t, 0, sp.pi)) - sp.Rational(3, 7) * x**2
    assert read_expr("here", sp.srepr(expr)) == expr


def test_a_store_is_bounded_and_must_be_json(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    from pendcli.verify import derivation_store

    bad = tmp_path / "x-derivations.json"
    monkeypatch.setattr(derivation_store, "store_path", lambda key: bad)
    derivation_store._raw_store.cache_clear()
    bad.write_text("{not json")
    with pytest.raises(PendcliError, match="not JSON"):
        stored_rows("x", "digest")
    derivation_store._raw_store.cache_clear()
    monkeypatch.setattr(derivation_store, "_MAX_BYTES", 10)
    bad.write_text('{"format": 1, "rows": {}}')
    with pytest.raises(PendcliError, match="more than 10 bytes"):
        stored_rows("x", "digest")
    derivation_store._raw_store.cache_clear()


def test_a_malformed_record_names_its_row() -> None:
    with pytest.raises(PendcliError, match=r"^row 7 printed: "):
        row_record("row 7", {"kind": "identity", "forms": {"printed": {"items": [{"call": "x"}]}}})


# --- used only for its own tables -------------------------------------------------------------


def _row(paper_key: str, status: str) -> tuple[object, dict[str, str]]:
    ledger = load_ledger(paper_key)
    row = next(r for r in ledger.rows if r.status == status and r.kind == "identity")
    return row, ledger.symbols_for(row)


def test_a_foreign_store_is_never_read(tables: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A tables folder of one's own may carry a store that says a failing row holds: it is
    not read (only the package's is), and the row is judged from the same tables as before."""
    key = "charbonnier"
    row, symbols = _row(key, "misprint")
    committed = json.loads(store_path(key).read_text())
    committed["rows"][row.id]["forms"]["printed"]["items"] = []  # nothing to judge: "holds"
    (tables / "derivations" / f"{key}.json").write_text(json.dumps(committed))
    ledger_references._clear_reference_caches()
    status, _ = row_printed_status(row, symbols, paper(key).references())
    assert status == "misprint"


def test_an_edited_row_is_derived_afresh_and_said_once(
    tables: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """An edited ledger makes the store stale for these tables: every row is derived from its
    live reference, and stderr says so once."""
    key = "tisserand"
    ledger_file = tables / "equations" / f"{key}.toml"
    ledger_file.write_text(ledger_file.read_text() + "\n# an edit\n")
    ledger_references._clear_reference_caches()
    ledger_references._SAID.clear()
    rows = load_ledger(key).rows[:3]
    for row in rows:
        if row.reference:
            row_printed_status(row, load_ledger(key).symbols_for(row), paper(key).references())
    assert capsys.readouterr().err.count("derived afresh") == 1


# --- float64 against the exact engine ---------------------------------------------------------


def _exact(item: Item, monkeypatch: pytest.MonkeyPatch) -> tuple[bool, str]:
    with monkeypatch.context() as patch:
        patch.setattr(float_verdict, "quick_verdict", lambda item: None)
        patch.setattr(float_verdict, "certain_margins", lambda *args: set())
        return item_passes(item)


def _stored_items() -> list[tuple[str, Item]]:
    out = []
    for key in ledger_papers():
        for row_id, (_, record) in stored_rows(key, ledger_references.paper_digest(key)).items():
            if "live" in record:
                continue
            for form, derived in row_record(row_id, record, stored_nodes(key))[1].items():
                out += [(f"{row_id} {form} {item.where[:40]}", item) for item in derived.items]
    return out


def _content(item: Item) -> tuple[object, ...]:
    """What an item's verdict is a function of (every field but ``where``, the name a failure
    gives it: the engine's random points are seeded), each expression as the store keeps it."""

    def text(value: object) -> object:
        return value.text() if isinstance(value, StoredExpr) else value

    rooted = None if item.rooted is None else (text(item.rooted[0]), item.rooted[1])
    domain = sorted((str(k), repr(v)) for k, v in item.domain.items())
    return (item.call, text(item.source), str(item.scale), item.order, repr(domain),
            item.strict, repr(rooted), text(item.taylor), text(item.limit))  # fmt: skip


@cache
def _distinct_items() -> tuple[list[tuple[str, Item, int]], frozenset[str]]:
    """The stored items of every paper's store, one of each content (the first named: a
    formula shared by several rows or forms is one item) with the count of items of that
    content, and those of them float64 shows at some points: once per process, for every part."""
    distinct: dict[tuple[object, ...], tuple[str, Item, int]] = {}
    for name, item in _stored_items():
        first, kept, count = distinct.get(_content(item), (name, item, 0))
        distinct[_content(item)] = (first, kept, count + 1)
    items = list(distinct.values())
    return items, frozenset(_shown_at_points([(name, item) for name, item, _ in items]))


# the stored items dealt into parts (every PARTS-th item from a start), so that the run's
# workers share them and no one case is the run's tail
PARTS = 6


@pytest.mark.parametrize("part", range(PARTS))
def test_float64_decides_only_as_the_exact_engine_does(
    part: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every stored item float64 decides (by itself, by a series or limit stored for it, or
    at some of a relation's points), judged again by the exact engine alone (mpmath at 20
    digits, Cauchy at 40, sympy): the same verdict, every time. Each case judges its part
    of the items of every paper's store, each content once (the engine's verdict is a
    function of it)."""
    every, shown = _distinct_items()
    assert sum(count for _, _, count in every) > 700 and len(every) > 500
    assert shown  # float64 alone: some relation is decided at some points
    items = every[part::PARTS]
    decided, disagree = 0, []
    for name, item, count in items:
        quick = float_verdict.quick_verdict(item)
        if quick is None and name in shown:  # float64 at some points, exact at others
            quick = item_passes(item)
        elif quick is None:
            continue
        decided += count  # the stored items it stands for
        if quick[0] != _exact(item, monkeypatch)[0]:
            disagree.append(name)
    assert disagree == []
    assert decided > 0.95 * sum(count for _, _, count in items)


def _shown_at_points(items: list[tuple[str, Item]]) -> set[str]:
    """The relations float64 does not decide whole but shows to hold at some of their points."""
    shown = set()
    for name, item in items:
        if item.call != "relation" or float_verdict.quick_verdict(item) is not None:
            continue
        points = relation_points(item)
        if not isinstance(points, str) and float_verdict.certain_margins(item, points, 1e-15):
            shown.add(name)
    return shown


# --- float64 against mpmath, on expressions of known expansion --------------------------------

S, X = ledger_symbols("s", "x")


def _item(expr: sp.Expr, order: int | None = None, domain: dict | None = None) -> Item:
    scale = S if order is not None else None
    return Item("equation", "e", expr, scale, order, domain or {})


def test_an_identity_holds_and_a_slip_is_measured() -> None:
    assert float_verdict.quick_verdict(_item(sp.sin(X) ** 2 + sp.cos(X) ** 2 - 1)) == (
        True,
        "vanishes at 8 random points to 1e-14 of its terms (float64)",
    )
    ok, why = float_verdict.quick_verdict(_item(sp.sin(2 * X) - 2 * sp.sin(X)))
    x = mpmath.mpf(why.split("x=")[1].split(" ")[0].split("/")[0]) / mpmath.mpf(
        why.split("x=")[1].split(" ")[0].split("/")[1]
    )
    assert not ok and float(why.split()[1]) == pytest.approx(
        float(mpmath.sin(2 * x) - 2 * mpmath.sin(x)), rel=1e-6
    )


def test_a_series_coefficient_below_the_order_is_named_with_its_value() -> None:
    residual = sp.exp(S) - (1 + S + S**2 / 2)
    assert float_verdict.quick_verdict(_item(residual, order=3))[0] is True
    ok, why = float_verdict.quick_verdict(_item(residual, order=4))
    coefficient = float(mpmath.taylor(mpmath.exp, 0, 3)[3])  # 1/6 by mpmath
    assert not ok and "s**3" in why
    assert float(why.split(" is ")[1].split()[0]) == pytest.approx(
        coefficient, rel=1e-5
    )  # six digits shown


@pytest.mark.parametrize(
    "residual",
    [
        sp.sqrt(S) - sp.sqrt(S),  # trivially 0: holds
        sp.sqrt(S) * (1 + S) - sp.sqrt(S),  # a branch at 0: undecided, the exact engine follows it
        sp.Abs(S - 1) - (1 - S),  # not analytic in a complex scale: undecided
        sp.sin(3 / S) * S**4,  # an essential singularity: undecided
    ],
)
def test_what_float64_cannot_follow_is_left_to_the_exact_engine(residual: sp.Expr) -> None:
    verdict = float_verdict.quick_verdict(_item(residual, order=2))
    assert verdict is None or (verdict[0] is True and residual == 0)


def test_an_integral_is_integrated_and_compared() -> None:
    t = sp.Symbol("t", real=True)
    exact = mpmath.quad(lambda u: mpmath.sqrt(u) * mpmath.exp(-u), [0, 1])
    integral = sp.Integral(sp.sqrt(t) * sp.exp(-t), (t, 0, 1))
    assert float_verdict.quick_verdict(_item(integral - sp.Float(str(exact), 30)))[0] is True
    ok, _ = float_verdict.quick_verdict(_item(integral - sp.Float(str(exact), 30) * 1.001))
    assert ok is False


def test_a_run_says_once_that_it_derives_afresh(tables: Path) -> None:
    """The workers a run forks inherit that the line was said: one line, not one per worker."""
    import os
    import subprocess
    import sys

    ledger_file = tables / "equations" / "tisserand.toml"
    ledger_file.write_text(ledger_file.read_text() + "\n# an edit\n")
    env = {**os.environ, "PENDCLI_TABLES": str(tables), "PENDCLI_CACHE": "off", "PENDCLI_JOBS": "2"}
    out = subprocess.run(
        [sys.executable, "-m", "pendcli", "equations", "-p", "tisserand", "-f", "json"],
        capture_output=True, text=True, env=env,
    )  # fmt: skip
    assert out.returncode == 0, out.stderr
    assert out.stderr.count("derived afresh") == 1


# --- what float64 judges beside the residual: derived once, or at some points -----------------


def test_a_series_cauchy_cannot_follow_is_judged_by_its_terms_derived_once(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """√(1 + s⁻²) = √(1 + s²)/s for s > 0 (mpmath at a point), a branch on the complex circle:
    Cauchy's integral decides nothing; its terms below the order, derived once, hold; the
    same with s² added do not, and the exact engine words that failure."""
    from dataclasses import replace

    from pendcli.verify.derived import derived_once

    s = sp.Symbol("s", positive=True)
    residual = sp.sqrt(1 + s**-2) - sp.sqrt(1 + s**2) / s
    assert mpmath.sqrt(1 + mpmath.mpf(0.3) ** -2) == pytest.approx(mpmath.sqrt(1.09) / 0.3)
    for extra, holds in ((0, True), (s**2, False)):
        item = Item("equation", "e", residual + extra, s, 3, {})
        assert float_verdict.quick_verdict(item) is None
        stored = replace(item, **derived_once(item))
        assert stored.taylor is not None
        quick = float_verdict.quick_verdict(stored)
        assert (quick is not None and quick[0] and "stored series" in quick[1]) is holds
        assert _exact(stored, monkeypatch)[0] is holds


def test_a_bounded_residual_is_judged_by_its_limit_derived_once() -> None:
    """1/s − cot s → 0 (mpmath) stays finite and holds by its stored limit; 1/s² − cot s
    diverges: its stored limit is infinite and the exact engine judges."""
    from dataclasses import replace

    from pendcli.verify.derived import derived_once

    near = mpmath.mpf("1e-8")
    assert abs(1 / near - mpmath.cot(near)) < 1e-7
    for residual, holds in (
        (1 / S - sp.cos(S) / sp.sin(S), True),
        (1 / S**2 - sp.cos(S) / sp.sin(S), False),
    ):
        item = Item("bounded", "e", residual, S, None, {})
        assert float_verdict.quick_verdict(item) is None
        stored = replace(item, **derived_once(item))
        quick = float_verdict.quick_verdict(stored)
        assert (quick == (True, "finite as s -> 0+ (float64, stored limit)")) is holds
        assert quick is None or holds


def test_an_undefined_function_holds_only_where_its_terms_cancel() -> None:
    """F(x(1 + x)) − F(x + x²) vanishes for every F (the arguments expand alike); F(x) − F(2x)
    does not, and float64 leaves it to the exact engine instead of failing it."""
    f = sp.Function("F")
    assert sp.expand(X * (1 + X) - (X + X**2)) == 0
    assert float_verdict.quick_verdict(_item(f(X * (1 + X)) - f(X + X**2)))[0] is True
    assert float_verdict.quick_verdict(_item(f(X) - f(2 * X))) is None


def test_a_quadrature_is_refined_until_two_steps_agree() -> None:
    """∫₀^{π/2} e^(−tan(w)/2)/cos³w dw (an essential singularity at π/2, where steps 1/16 and
    1/32 differ by more than 1e-13) against mpmath's ∫₀^∞ √(1 + λ²) e^(−λ/2) dλ, the same
    integral by λ = tan w."""
    w = sp.Symbol("w", real=True)
    exact = mpmath.quad(lambda u: mpmath.sqrt(1 + u**2) * mpmath.exp(-u / 2), [0, mpmath.inf])
    integral = sp.Integral(sp.exp(-sp.tan(w) / 2) / sp.cos(w) ** 3, (w, 0, sp.pi / 2))
    for printed, holds in ((exact, True), (exact * (1 + 1e-5), False)):
        residual = integral - sp.Float(str(printed), 30)
        # given as the store keeps it (srepr): written with its terms in sympy's printing
        # order, srepr integrates the Integral numerically to sort them (0.17 s each)
        item = replace(_item(residual), text=sp.srepr(residual, order="none"))
        assert float_verdict.quick_verdict(item)[0] is holds


def test_a_relation_is_computed_again_only_where_float64_does_not_show_it(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """x − 3/10 + |x − 3/10| ≥ 0 is 0 below 3/10: float64 decides nothing, shows the margin
    positive at the points above, and the exact engine, judging the rest, agrees with itself
    judging all 32."""
    margin = X - sp.Rational(3, 10) + sp.Abs(X - sp.Rational(3, 10))
    item = Item("relation", "e", margin, None, None, {"x": (sp.Rational(1, 10), sp.Rational(1, 2))})
    assert float_verdict.quick_verdict(item) is None
    points = relation_points(item)
    assert not isinstance(points, str)
    shown = float_verdict.certain_margins(item, points, 1e-15)
    assert shown == {i for i, p in enumerate(points) if p[X] > sp.Rational(3, 10)}
    assert 0 < len(shown) < len(points)
    assert (
        item_passes(item)
        == _exact(item, monkeypatch)
        == (
            True,
            "the inequality holds at 32 random points",
        )
    )


def test_a_factorial_of_a_huge_integer_is_not_multiplied_out_in_float64() -> None:
    """factorial(10**40) + x: float64 leaves it undecided (a double holds no factorial past
    170!) instead of asking sympy for its forty-digit-long product; x! of a small integer is
    evaluated (5! = 120 by hand)."""
    x = "Symbol('x', real=True)"
    huge = Item("equation", "e", text=f"Add(factorial(Integer({10**40})), {x})")
    assert float_verdict.quick_verdict(huge) is None
    small = Item("equation", "e", text="Add(factorial(Integer(5)), Integer(-120))")
    assert float_verdict.quick_verdict(small) == (
        True,
        "vanishes at 8 random points to 1e-14 of its terms (float64)",
    )
