"""`pendcli check --format json|junit`, GitHub annotations, `check --update`'s change list,
and `reproduce --fail-on`: what a CI job sees."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest
from helpers.cli import assert_clean_error, invoke

from pendcli.output.check_formats import (
    changed_cells,
    github_annotations,
    to_json,
    to_junit,
)
from pendcli.run.drift import find_drifts

HEADER = (
    "id,published,unit,recomputed,exact,abs_diff,rel_diff,verdict,procedure_verdict,"
    "procedure_value,cause,from,condition\n"
)
ROW_A = 'x.a,"5,14",,5.135622301840683,,-0.0043776,-0.00085,agrees,,,,,\n'
ROW_B = 'x.b,"2,5",,2.5,,0.0,0.0,agrees,,,,,\n'
NAME = "p-claims.csv"


def _committed(tmp_path, text):
    (tmp_path / NAME).write_text(text, encoding="utf-8")
    return tmp_path


def test_junit_has_one_testcase_per_row_and_table_and_fails_only_the_drifted_row(tmp_path):
    folder = _committed(tmp_path, HEADER + ROW_A + ROW_B)
    now = {NAME: HEADER + ROW_A + ROW_B.replace("2.5,,0.0", "2.6,,0.1")}
    drifts = find_drifts(folder, now)
    root = ET.fromstring(to_junit(drifts, now))
    cases = {c.get("name"): c for c in root.iter("testcase")}
    assert set(cases) == {"(table)", "x.a", "x.b"}
    assert cases["x.b"].find("failure") is not None
    assert "recomputed '2.5' -> '2.6'" in cases["x.b"].find("failure").text
    assert cases["x.a"].find("failure") is None
    assert root.get("failures") == "1"


def test_junit_of_a_clean_check_has_no_failure(tmp_path):
    folder = _committed(tmp_path, HEADER + ROW_A)
    now = {NAME: HEADER + ROW_A}
    root = ET.fromstring(to_junit(find_drifts(folder, now), now))
    assert not list(root.iter("failure"))
    assert len(list(root.iter("testcase"))) == 2


def test_json_lists_drifts_with_their_tolerance(tmp_path):
    folder = _committed(tmp_path, HEADER + ROW_A)
    now = {NAME: HEADER + ROW_A.replace("5.135622301840683", "5.1357")}
    doc = json.loads(to_json(find_drifts(folder, now), now))
    assert doc["passed"] is False
    assert [(d["id"], d["column"], d["tolerance"]) for d in doc["drifts"]] == [
        ("x.a", "recomputed", "rel 1e-09")
    ]
    assert doc["tolerances"]["observed_order"] == {"kind": "abs", "tolerance": 0.05}


def test_github_annotation_points_at_the_committed_row(tmp_path):
    folder = _committed(tmp_path, HEADER + ROW_A + ROW_B)
    now = {NAME: HEADER + ROW_A + ROW_B.replace("agrees", "discrepant")}
    (line,) = github_annotations(find_drifts(folder, now), folder)
    assert line.startswith("::error file=")
    assert ",line=3," in line  # header is line 1, x.a line 2
    assert "x.b" in line
    assert "\n" not in line


def test_update_lists_every_changed_value_even_within_tolerance(tmp_path):
    folder = _committed(tmp_path, HEADER + ROW_A + ROW_B)
    noisy = ROW_A.replace("5.135622301840683", "5.135622301840684")
    now = {NAME: HEADER + noisy + ROW_B.replace("agrees", "truncated"), "q-claims.csv": HEADER}
    found = {(d.table, d.id, d.column, d.difference) for d in changed_cells(folder, now)}
    assert found == {
        (NAME, "x.a", "recomputed", "noise"),
        (NAME, "x.b", "verdict", "changed"),
        ("q-claims.csv", "(table)", "(file)", ""),
    }


def test_update_of_an_unreadable_committed_table_says_so(tmp_path):
    folder = _committed(tmp_path, "garbage\n")
    (change,) = changed_cells(folder, {NAME: HEADER + ROW_A})
    assert (change.committed, change.now) == ("unreadable", "rewritten")


@pytest.mark.slow
def test_check_json_and_junit_from_the_command_line(reproduce_computed_once):
    code, out, _ = invoke("check", "--format", "json")
    assert code == 0
    assert json.loads(out)["passed"] is True
    code, out, _ = invoke("check", "-f", "junit")
    assert code == 0
    assert len(list(ET.fromstring(out).iter("testcase"))) > 100


def test_check_update_with_a_data_format_is_refused():
    code, _, err = invoke("check", "--update", "--format", "json")
    assert_clean_error(code, err)
    assert "--format: 'json'" in err


def test_fail_on_a_bad_name_names_the_valid_ones():
    code, _, err = invoke("reproduce", "-p", "charbonnier", "--fail-on", "agrees,nope")
    assert_clean_error(code, err)
    assert "--fail-on" in err and "'nope'" in err
    assert "discrepant" in err and "misprint" in err


def test_fail_on_exits_1_only_when_a_row_has_the_verdict():
    # Charbonnier's table of I_n(pi) agrees throughout, and its formulas hold (the committed
    # regenerated table says so); asking to fail on "agrees" must then fail.
    args = ("reproduce", "-p", "charbonnier", "--no-formulas", "-f", "json")
    code, out, _ = invoke(*args, "--fail-on", "discrepant,truncated,last-digit")
    verdicts = {c["verdict"] for c in json.loads(out)["claims"]}
    assert code == (1 if verdicts - {"agrees"} else 0)
    code, _, err = invoke(*args, "--fail-on", "agrees")
    assert code == 1
    assert "--fail-on:" in err
