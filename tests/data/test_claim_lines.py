"""Each printed number says where the paper prints it: ``lines = [first, last]`` of its
``[[claim]]``, 1-based lines of ``papers/<paper>.txt``, validated as the ledger's are."""

from __future__ import annotations

from pathlib import Path

import pytest

from pendcli.base.errors import PendcliError
from pendcli.data.tables import clear_table_cache, load_paper_table, tables_dir
from pendcli.papers.registry import PAPERS

TABLE = """
[paper]
key = "demo"
citation = "A. Author, Demo"
seed = "demo.txt"

[[claim]]
id = "demo.x"
source = "p. 1"
quantity = "x"
published = "5,14"
lines = {lines}
"""


def _root(tmp_path: Path, lines: str, text: str | None = "one\ntwo 5,14\nthree\n") -> Path:
    (tmp_path / "published").mkdir()
    (tmp_path / "published" / "demo.toml").write_text(TABLE.format(lines=lines), "utf-8")
    if text is not None:
        (tmp_path / "papers").mkdir()
        (tmp_path / "papers" / "demo.txt").write_text(text, "utf-8")
    clear_table_cache()
    return tmp_path


def test_a_claims_lines_are_read(tmp_path: Path) -> None:
    assert load_paper_table("demo", _root(tmp_path, "[2, 2]")).claims[0].lines == (2, 2)


@pytest.mark.parametrize(
    ("lines", "message"),
    [
        ("[2, 9]", r"'lines' = \[2, 9\] must satisfy 1 <= first <= last <= 3"),
        ("[0, 1]", r"must satisfy 1 <= first <= last"),
        ("[3, 2]", r"must satisfy 1 <= first <= last"),
        ("[2]", r"'lines' must be \[first, last\]"),
        ('"2"', r"'lines' must be \[first, last\]"),
    ],
)
def test_lines_outside_the_text_or_malformed_are_refused(
    tmp_path: Path, lines: str, message: str
) -> None:
    with pytest.raises(PendcliError, match=rf"demo\.toml: claim 'demo\.x'.*{message}"):
        load_paper_table("demo", _root(tmp_path, lines))


def test_without_the_text_only_the_shape_is_checked(tmp_path: Path) -> None:
    assert load_paper_table("demo", _root(tmp_path, "[2, 9]", None)).claims[0].lines == (2, 9)


@pytest.mark.parametrize("paper", PAPERS)
def test_every_committed_claim_has_lines_holding_its_printed_form(paper: str) -> None:
    """Each claim's lines hold its printed string (or the OCR's own text of it), the OCR's
    spacing aside: a claim whose lines point elsewhere is caught."""
    text = (tables_dir() / "papers" / f"{paper}.txt").read_text("utf-8").split("\n")
    for claim in load_paper_table(paper).claims:
        assert claim.lines is not None, claim.id
        first, last = claim.lines
        span = "".join(text[first - 1 : last]).replace(" ", "")
        forms = [f.replace(" ", "").replace("$", "") for f in (claim.as_printed, claim.published)]
        assert any(f and f in span.replace("$", "") for f in forms), claim.id
