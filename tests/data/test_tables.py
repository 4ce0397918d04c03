"""The published-table loader: every malformed table names its file and entry."""

import shutil
from pathlib import Path

import pytest

from pendcli.base.errors import PendcliError
from pendcli.data.tables import load_paper_table, tables_dir
from pendcli.papers.registry import PAPERS
from pendcli.verify.claims import Recomputed, join_claims

GOOD = """
[paper]
key = "demo"
citation = "A. Author, A paper (1900)"
seed = "x.txt"

[[claim]]
id = "demo.a"
source = "p. 1"
quantity = "a"
published = "5,14"
"""


def write(tmp_path: Path, text: str) -> Path:
    (tmp_path / "published").mkdir(exist_ok=True)
    (tmp_path / "published" / "demo.toml").write_text(text, encoding="utf-8")
    return tmp_path


def test_good_table_loads(tmp_path):
    table = load_paper_table("demo", write(tmp_path, GOOD))
    assert table.claims[0].number.value == pytest.approx(5.14)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (GOOD.replace('published = "5,14"', 'published = "5;14"'), "demo.a"),
        (GOOD.replace('published = "5,14"', ""), "'published'"),
        (GOOD.replace('id = "demo.a"', 'id = "other.a"'), "must start with"),
        (GOOD + GOOD.split("[[claim]]")[1].join(["[[claim]]", ""]), "duplicate id"),
        (GOOD.replace('key = "demo"', 'key = "else"'), "[paper]"),
        (GOOD.replace('quantity = "a"', 'quantity = "a"\ncolour = "red"'), "unknown field"),
        (GOOD.replace('quantity = "a"', "quantity = 3"), "'quantity'"),
        (GOOD + "\n[[claim]\n", "not valid TOML"),
        (GOOD.split("[[claim]]")[0], "no [[claim]]"),
        (
            GOOD.replace('published = "5,14"', 'published = "5,14"\ncomparison = "about"'),
            "comparison",
        ),
    ],
)
def test_malformed_tables_name_file_and_entry(tmp_path, text, message):
    root = write(tmp_path, text)
    with pytest.raises(PendcliError) as err:
        load_paper_table("demo", root)
    assert "demo.toml" in str(err.value)
    assert message in str(err.value)
    assert "\n" not in str(err.value)


def test_missing_table(tmp_path):
    (tmp_path / "published").mkdir()
    with pytest.raises(PendcliError, match="missing"):
        load_paper_table("demo", tmp_path)


def test_join_requires_a_computation_for_every_claim(tmp_path):
    table = load_paper_table("demo", write(tmp_path, GOOD))
    with pytest.raises(PendcliError, match="no computation"):
        join_claims(table, {})
    with pytest.raises(PendcliError, match=r"demo\.toml: no claim 'demo\.b'.*renamed"):
        join_claims(table, {"demo.a": Recomputed(5.14), "demo.b": Recomputed(1.0)})


@pytest.mark.parametrize("key", PAPERS)
def test_shipped_tables_load(key):
    table = load_paper_table(key)
    assert table.claims
    assert all(c.id.startswith(key + ".") for c in table.claims)


def test_tables_dir_override(tmp_path, monkeypatch):
    shutil.copytree(tables_dir() / "published", tmp_path / "published")
    monkeypatch.setenv("PENDCLI_TABLES", str(tmp_path))
    assert tables_dir() == tmp_path


def test_precision_exact_makes_a_decimal_exact(tmp_path):
    text = GOOD.replace('published = "5,14"', 'published = "5"\nprecision = "exact"')
    number = load_paper_table("demo", write(tmp_path, text)).claims[0].number
    assert number.is_exact
    assert number.resolution is None
    other = tmp_path / "other"
    other.mkdir()
    with pytest.raises(PendcliError, match="precision"):
        load_paper_table("demo", write(other, text.replace('"exact"', '"loose"')))


CONSTANTS = """
[paper.constants.g]
value = 9.81
unit = "m/s²"
range = [1.0, 100.0]
source = "assumption: the value used in the paper's time"
"""


def _with_constants(text: str) -> str:
    return GOOD.replace('seed = "x.txt"\n', 'seed = "x.txt"\n' + text)


def test_constants_and_claims_are_looked_up_by_name(tmp_path, monkeypatch):
    table = load_paper_table("demo", write(tmp_path, _with_constants(CONSTANTS)))
    assert table.constant("g") == 9.81
    assert table.constants[0].unit == "m/s²"
    assert table.claim("demo.a").published == "5,14"
    with pytest.raises(PendcliError, match=r"no constant 'speed'.*known: g"):
        table.constant("speed")
    with pytest.raises(PendcliError, match=r"demo\.toml: no claim 'demo\.b'.*renamed"):
        table.claim("demo.b")


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (CONSTANTS.replace("value = 9.81", 'value = "9.81"'), "value must be a number"),
        (CONSTANTS.replace("value = 9.81", "value = true"), "value must be a number"),
        (
            CONSTANTS.replace(
                'source = "assumption: the value used in the paper\'s time"', 'source = ""'
            ),
            "source must say where the value comes from",
        ),
        (
            CONSTANTS + 'colour = "red"\n',
            "unknown field(s) 'colour'; valid: value, unit, range, source",
        ),
        ("[paper.constants]\ng = 9.81\n", "must be a table with value, unit, source"),
    ],
)
def test_malformed_constants_name_the_constant(tmp_path, text, message):
    with pytest.raises(PendcliError) as err:
        load_paper_table("demo", write(tmp_path, _with_constants(text)))
    assert "demo.toml" in str(err.value) and message in str(err.value)
    assert "\n" not in str(err.value)


SECOND = """
[[claim]]
id = "demo.b"
source = "p. 2"
quantity = "b"
published = "2,5"
"""


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (GOOD.replace("[[claim]]", "[[claims]]") + SECOND, "top-level section(s) 'claims'"),
        (GOOD + "\n[extra]\nx = 1\n", "top-level section(s) 'extra'"),
        (GOOD.replace('seed = "x.txt"', 'seed = "x.txt"\nasumptions = []'), "'asumptions'"),
        (GOOD.replace('quantity = "a"', 'quantity = "a"\nnotes = "x"'), "claim 'demo.a'"),
        (GOOD.replace('quantity = "a"', 'quantity = "a"\nnotes = "x"'), "valid: id, source"),
    ],
)
def test_unknown_sections_and_keys_are_refused(tmp_path, text, message):
    with pytest.raises(PendcliError) as err:
        load_paper_table("demo", write(tmp_path, text))
    assert "demo.toml" in str(err.value) and message in str(err.value)
    assert "\n" not in str(err.value)


def _caused(cause: str, sources: str | None) -> str:
    extra = f'cause = "{cause}"' + (f"\nfrom = {sources}" if sources is not None else "")
    return GOOD + SECOND.replace('published = "2,5"', 'published = "2,5"\n' + extra)


def test_cause_and_from_are_read(tmp_path):
    table = load_paper_table("demo", write(tmp_path, _caused("propagated", '["demo.a"]')))
    assert table.claim("demo.b").cause == "propagated"
    assert table.claim("demo.b").cause_from == ("demo.a",)
    assert table.claim("demo.a").cause is None and table.claim("demo.a").cause_from == ()
    other = tmp_path / "other"
    other.mkdir()
    table = load_paper_table("demo", write(other, _caused("misprint", None)))
    assert table.claim("demo.b").cause == "misprint"


@pytest.mark.parametrize(
    ("cause", "sources", "message"),
    [
        ("typo", None, "cause 'typo' is not one of rounding, truncation"),
        ("propagated", None, "needs 'from'"),
        ("propagated", "[]", "needs 'from'"),
        ("propagated", '"demo.a"', "needs 'from'"),
        ("propagated", '["demo.zz"]', "'from' names 'demo.zz'"),
        ("propagated", '["demo.b"]', "'from' names 'demo.b'"),
        ("propagated", '["demo.a", "demo.a"]', "repeats"),
        ("rounding", '["demo.a"]', "only for cause"),
    ],
)
def test_bad_cause_or_from_is_refused(tmp_path, cause, sources, message):
    with pytest.raises(PendcliError) as err:
        load_paper_table("demo", write(tmp_path, _caused(cause, sources)))
    assert "demo.toml" in str(err.value) and "demo.b" in str(err.value)
    assert message in str(err.value)


# ---------------------------------------------------------------------------------------------
# tables/tradeoff/<family>.csv: what `--tol` chooses from

TRADEOFF_HEADER = "family,method,setting,seconds,error,evaluations,note\n"
TRADEOFF_ROWS = "demo,fast,n=1,1e-06,0.001,12,\ndemo,exact,,0.0001,0,,\ndemo,naive,,,,,fails: x\n"


@pytest.mark.parametrize("name", sorted(p.stem for p in (tables_dir() / "tradeoff").glob("*.csv")))
def test_shipped_tradeoff_tables_are_valid(name):
    from pendcli.run import tradeoff_engine

    points = tradeoff_engine.read_points(tables_dir() / "tradeoff" / f"{name}.csv")
    assert points and all(p.family == name for p in points)


def test_a_valid_tradeoff_table_reads(tmp_path):
    from pendcli.run import tradeoff_engine

    path = tmp_path / "demo.csv"
    path.write_text(TRADEOFF_HEADER + TRADEOFF_ROWS, encoding="utf-8")
    points = tradeoff_engine.read_points(path)
    assert [(p.method, p.error, p.evaluations) for p in points] == [
        ("fast", 0.001, 12),
        ("exact", 0.0, None),
        ("naive", None, None),
    ]
    assert tradeoff_engine.choose("demo", 0.01, points).method == "fast"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("", "line 1: header ''"),
        (TRADEOFF_HEADER.replace("error", "err") + TRADEOFF_ROWS, "line 1: header"),
        (TRADEOFF_HEADER, "no measured point"),
        (TRADEOFF_HEADER + "demo,fast,n=1,1e-06\n", "line 2 has 4 fields; expected 7"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("demo,naive", "other,naive"), "line 4: family"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("demo,fast", "demo,"), "method non-empty"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("1e-06", "inf"), "seconds = 'inf'"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("1e-06", "1e400"), "seconds = '1e400'"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("1e-06", "0"), "positive number"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("1e-06", "-1e-06"), "positive number"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("1e-06", "fast"), "seconds = 'fast'"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("0.001", "nan"), "error = 'nan'"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("0.001", "-0.001"), "a number >= 0"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("0.001", ""), "both empty"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace(",12,", ",1.5,"), "positive integer"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace(",12,", ",0,"), "positive integer"),
        (TRADEOFF_HEADER + TRADEOFF_ROWS.replace("n=1", '"n=1'), "malformed CSV"),
    ],
)
def test_a_bad_tradeoff_table_names_file_and_line(tmp_path, text, message):
    from pendcli.run import tradeoff_engine

    path = tmp_path / "demo.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(PendcliError) as err:
        tradeoff_engine.read_points(path)
    assert str(err.value).startswith(f"{path}: ")
    assert message in str(err.value)
    assert "\n" not in str(err.value)


def test_a_tradeoff_table_that_is_not_text_is_an_error(tmp_path):
    from pendcli.run import tradeoff_engine

    path = tmp_path / "demo.csv"
    path.write_bytes(b"\xff\xfe" + TRADEOFF_HEADER.encode())
    with pytest.raises(PendcliError, match="not UTF-8"):
        tradeoff_engine.read_points(path)
    with pytest.raises(PendcliError, match="cannot read"):
        tradeoff_engine.read_points(tmp_path)  # a folder where the file should be
