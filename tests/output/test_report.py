"""The report's pieces: the digest of what does not hold, the tally, refused output folders."""

from __future__ import annotations

from dataclasses import replace

import pytest
from helpers.cli import invoke

from pendcli.base.errors import PendcliError
from pendcli.output import report_figures
from pendcli.output.report import check_out_folder, write_report
from pendcli.output.report_sections import disagreement_digest
from pendcli.run.reproduce import ReproduceResult
from pendcli.verify.claims import ClaimRow, FormulaRow


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
            replace(
                _claim("demo.b", "truncated", "OCR: read 8,41. Chopped, not rounded. More."),
                cause="truncation",
            ),
        ]
    },
    formulas={"demo": [_formula("demo.f", "holds"), _formula("demo.g", "fails")]},
)


def test_digest_lists_each_claim_and_formula_that_does_not_hold():
    assert disagreement_digest(RESULT) == [
        "- **demo.b** (p. 1): printed `8,41`, recomputed 8.4172: **truncated** (truncation); "
        "no procedure of his known. read 8,41.",
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
            "faithful": 0,
            "faithful if chopped": 0,
            "faithful if rounded": 0,
            "faithful if he kept more digits": 0,
            "slip": 0,
            "no procedure": 2,
            "formulas holding": 1,
            "formulas failing": 1,
            "root causes": 1,
            "propagated": 0,
        }
    ]


def test_report_refuses_a_file_as_its_folder(tmp_path):
    target = tmp_path / "a_file"
    target.write_text("x", encoding="utf-8")
    with pytest.raises(PendcliError, match="is a file, not a folder") as err:
        write_report(RESULT, target)
    assert "\n" not in str(err.value)
    assert target.read_text(encoding="utf-8") == "x"


@pytest.mark.parametrize("out", ["", ".", "a_file/sub", "others"])
def test_unusable_out_folders_are_refused_before_any_work(tmp_path, monkeypatch, out):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a_file").write_text("x", encoding="utf-8")
    (tmp_path / "others").mkdir()
    (tmp_path / "others" / "notes.txt").write_text("keep", encoding="utf-8")
    with pytest.raises(PendcliError) as err:
        check_out_folder(out)
    assert "\n" not in str(err.value) and repr(out) in str(err.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a_file", "others"]
    assert (tmp_path / "others" / "notes.txt").read_text(encoding="utf-8") == "keep"


def test_cli_refuses_a_file_as_out_with_one_line_and_exit_2(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a_file").write_text("x", encoding="utf-8")
    for out in ("a_file", ""):
        code, stdout, err = invoke("reproduce", "--paper", "charbonnier", "--out", out)
        assert code == 2 and stdout == "" and len(err.strip().splitlines()) == 1, err
    assert [p.name for p in tmp_path.iterdir()] == ["a_file"]


# The demo rows under a real paper's name: its citation and tradeoff tables exist.
ONE_PAPER = ReproduceResult(
    papers=("charbonnier",),
    claims={"charbonnier": RESULT.claims["demo"]},
    formulas={"charbonnier": RESULT.formulas["demo"]},
)


def _stub_figures(monkeypatch):
    """Figures drawn as empty files in this process: the folder logic, not matplotlib."""

    def draw(function, args):
        # a paper's hook by its place (module:function), or a function of the report's own
        name = getattr(function, "__name__", "") or function.places[0].rsplit(".", 1)[1]
        name = name.replace(":", "_")
        folder = args[-1] if name == "plot_tradeoff" else args[0]
        path = folder if name == "plot_tradeoff" else folder / f"{name.strip('_')}.png"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(b"")
        return [path]

    monkeypatch.setattr(report_figures, "_draw", draw)


def _earlier_manifest(out, *names):
    """The manifest an earlier run wrote (its files listed): the folder is pendcli's."""
    from pendcli.base import owned_folders

    (out / owned_folders.MANIFEST).write_text(owned_folders.manifest_text(list(names)), "utf-8")


def test_report_replaces_the_folder_as_a_whole(tmp_path, monkeypatch):
    _stub_figures(monkeypatch)
    out = tmp_path / "out"
    out.mkdir()
    (out / "report.md").write_text("old", encoding="utf-8")
    (out / "stale.csv").write_text("old", encoding="utf-8")
    _earlier_manifest(out, "report.md", "stale.csv")
    written = write_report(ONE_PAPER, out, jobs=1)
    assert not (out / "stale.csv").exists()
    assert sorted(p.relative_to(out).as_posix() for p in written) == sorted(
        p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file()
    )
    assert "# pendcli reproduction report" in (out / "report.md").read_text(encoding="utf-8")
    assert [p.name for p in tmp_path.iterdir()] == ["out"]  # no temporary folder left


def test_a_failure_while_writing_leaves_the_old_folder_intact(tmp_path, monkeypatch):
    def broken(*_args):
        raise PendcliError("cannot write figure: disk full")

    monkeypatch.setattr(report_figures, "_draw", broken)
    out = tmp_path / "out"
    out.mkdir()
    (out / "report.md").write_text("old report", encoding="utf-8")
    _earlier_manifest(out, "report.md")
    with pytest.raises(PendcliError, match="disk full"):
        write_report(ONE_PAPER, out, jobs=1)
    assert sorted(p.name for p in out.iterdir()) == ["pendcli-manifest.txt", "report.md"]
    assert (out / "report.md").read_text(encoding="utf-8") == "old report"
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


def test_report_of_one_paper_times_only_its_families_from_the_committed_tables(tmp_path):
    from pendcli.run import tradeoff, tradeoff_engine

    result = ReproduceResult(papers=("charbonnier",))
    out = tmp_path / "out"
    written = write_report(result, out, jobs=2)  # figures drawn in forked workers
    assert sorted(written) == sorted(p for p in out.rglob("*") if p.is_file())
    csvs = sorted(p.stem for p in (out / "tradeoff").glob("*.csv"))
    assert csvs == sorted(tradeoff.family_names(("charbonnier",)))
    assert set(csvs).isdisjoint(tradeoff.family_names(("lecornu", "tisserand")))
    for name in csvs:  # copied byte for byte, not measured again
        committed = tradeoff_engine.table_path(name).read_bytes()
        assert (out / "tradeoff" / f"{name}.csv").read_bytes() == committed
    text = (out / "report.md").read_text(encoding="utf-8")
    assert "committed tables" in text and "by `make bench`" in text
    assert not (out / "figures" / "lecornu").exists()


def test_the_two_lanes_give_what_one_process_gives():
    from pendcli.run.reproduce import reproduce_all

    keys = ("tisserand", "charbonnier")
    forked, alone = reproduce_all(keys, jobs=2), reproduce_all(keys, jobs=1)
    assert forked.document() == alone.document() and forked.papers == keys
    assert set(forked.claims) == set(forked.formulas) == set(keys)


@pytest.fixture(scope="module")
def charbonnier_report(tmp_path_factory):
    from pendcli.run.reproduce import reproduce_all

    out = tmp_path_factory.mktemp("report") / "out"
    result = reproduce_all(("charbonnier",), equations=True, jobs=1)
    write_report(result, out, jobs=1)
    return result, out


def test_report_has_the_ledger_coverage_and_every_failing_equation(charbonnier_report):
    result, out = charbonnier_report
    text = (out / "report.md").read_text("utf-8")
    assert "### Equation ledger" in text
    wrong = [r for r in result.equations["charbonnier"] if r.status in ("fails", "misprint")]
    assert wrong  # Charbonnier (9) fails
    from pendcli.data.reader_text import for_reader  # ∫_(−α)^θ shown set, as a reader reads

    for row in wrong:
        assert for_reader(row.statement) in text
    assert "seed `" not in text and "tables/papers/charbonnier.txt" in text


def test_every_report_figure_has_a_written_caption(charbonnier_report):
    import re

    _, out = charbonnier_report
    text = (out / "report.md").read_text("utf-8")
    images = re.findall(r"!\[(.*?)\]\((.*?)\)", text)
    assert images
    for caption, path in images:
        assert (out / path).is_file()
        assert len(caption) > 60 and f"*{caption}*" in text  # a sentence, printed under it


def test_report_html_pages_are_written_with_the_report(charbonnier_report):
    _, out = charbonnier_report
    page = (out / "papers" / "charbonnier.html").read_text("utf-8")
    # (9) is a misprint: n° 17 computes with E_s(π/2) (tables/README.md, Blame)
    assert 'id="row-charbonnier.eq.9"' in page and 'class="hl s-misprint"' in page
    assert "data:image/png;base64," in page  # figures embedded: the page stands alone
    assert 'href="papers/charbonnier.html' in (out / "report.html").read_text("utf-8")


def test_a_report_shared_by_two_processes_is_the_one_written_in_one(charbonnier_report, tmp_path):
    """Figures and pages rendered by two processes: every file byte for byte as one writes
    it (a page given to the wrong paper, or a figure missing from a page, differs)."""
    result, alone = charbonnier_report
    shared = tmp_path / "out"
    write_report(result, shared, jobs=2)

    def files(folder):
        return sorted(p.relative_to(folder) for p in folder.rglob("*") if p.is_file())

    assert files(shared) == files(alone)
    for name in files(alone):
        assert (shared / name).read_bytes() == (alone / name).read_bytes(), name


def test_a_saved_figure_is_drawn_once_after_its_layout(tmp_path, monkeypatch):
    """tight_layout measures the figure without drawing it; savefig then draws it once (an
    engine left behind by tight_layout would make savefig draw everything twice)."""
    from matplotlib.figure import Figure

    from pendcli.base.plotting import new_figure

    draws: list[float] = []
    draw = Figure.draw

    def counted(self, renderer):
        draws.append(self.dpi)
        return draw(self, renderer)

    monkeypatch.setattr(Figure, "draw", counted)
    with new_figure(tmp_path / "f.png", nrows=2) as (_fig, axes):
        for ax in axes.flat:
            ax.plot([1, 2, 3], [3, 1, 2])
            ax.set_title("a title tight_layout makes room for")
    assert draws == [120]  # once, at the saved resolution
    assert (tmp_path / "f.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_saved_figure_is_measured_and_drawn_by_one_renderer(tmp_path, monkeypatch):
    """tight_layout and savefig share one renderer (the figure's resolution is the file's), so
    the text measured for the layout is not measured again to be drawn."""
    from matplotlib.backends.backend_agg import RendererAgg

    from pendcli.base.plotting import new_figure

    made: list[float] = []
    init = RendererAgg.__init__

    def counted(self, width, height, dpi):
        made.append(dpi)
        init(self, width, height, dpi)

    monkeypatch.setattr(RendererAgg, "__init__", counted)
    with new_figure(tmp_path / "f.png", nrows=2) as (_fig, axes):
        for ax in axes.flat:
            ax.plot([1, 2, 3], [3, 1, 2])
            ax.set_title("a title tight_layout makes room for")
    assert made == [120]
