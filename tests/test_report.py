"""The report's pieces: the digest of what does not hold, the tally, refused output folders."""

from __future__ import annotations

import pytest

from pendcli.core.claims import ClaimRow, FormulaRow
from pendcli.core.errors import PendcliError
from pendcli.report import disagreement_digest, write_report
from pendcli.reproduce import ReproduceResult


def _claim(cid: str, verdict: str, note: str = "") -> ClaimRow:
    return ClaimRow(
        id=cid,
        paper="demo",
        source="p. 1",
        quantity="q",
        unit="",
        published="8,41",
        published_value=8.41,
        recomputed=8.417198,
        verdict=verdict,
        abs_diff=0.0072,
        rel_diff=0.00086,
        digits=3.07,
        exact=None,
        method="m",
        note=note,
    )


def _formula(fid: str, verdict: str) -> FormulaRow:
    return FormulaRow(fid, "demo", "(9)", "a + b", "a − b", verdict, 2.0, 1.0, "")


RESULT = ReproduceResult(
    papers=("demo",),
    claims={
        "demo": [
            _claim("demo.a", "agrees"),
            _claim("demo.b", "truncated", "OCR: read 8,41. Chopped, not rounded. More."),
        ]
    },
    formulas={"demo": [_formula("demo.f", "holds"), _formula("demo.g", "fails")]},
)


def test_digest_lists_each_claim_and_formula_that_does_not_hold():
    assert disagreement_digest(RESULT) == [
        "- **demo.b** (p. 1): printed `8,41`, recomputed 8.4172: **truncated**. read 8,41.",
        "- **demo.g** (9): `a + b` fails; found `a − b`.",
    ]


def test_digest_when_everything_holds():
    result = ReproduceResult(papers=("demo",), claims={"demo": [_claim("demo.a", "agrees")]})
    assert disagreement_digest(result) == ["Every printed number and formula holds."]


def test_tally_and_summary_count_each_verdict():
    assert RESULT.tally("demo") == "1 agrees, 1 truncated, 1 formula holds, 1 formula fails"
    assert RESULT.summary_rows() == [
        {
            "paper": "demo",
            "agrees": 1,
            "truncated": 1,
            "last-digit": 0,
            "discrepant": 0,
            "formulas holding": 1,
            "formulas failing": 1,
        }
    ]


def test_report_refuses_a_file_as_its_folder(tmp_path):
    target = tmp_path / "a_file"
    target.write_text("x", encoding="utf-8")
    with pytest.raises(PendcliError, match="cannot create output folder") as err:
        write_report(RESULT, target)
    assert "\n" not in str(err.value)
    assert target.read_text(encoding="utf-8") == "x"
