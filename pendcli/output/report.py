"""Write the reproduction report: ``out/report.md`` plus its tables and figures.

Everything written here is byte-identical run to run on the same machine (no timestamps,
fixed plot metadata): the work-precision tables under ``out/tradeoff/`` are copies of the
committed ``tables/tradeoff/*.csv`` (measured by ``make bench``, on the date the report names)
unless ``--measure`` times them now, which the report then says.

The folder is built beside ``out`` and swapped in whole (:func:`pendcli.base.files.
replace_directory`); the figures are drawn in two forked processes where two cores exist
(``PENDCLI_JOBS=1`` draws them here), the costliest first, while the same processes render
the HTML pages without their figures and write the introduction; each page then gets its
figures.

This module writes the folder; the text of report.md is :mod:`~pendcli.output.report_sections`,
the figures :mod:`~pendcli.output.report_figures`, the copy kept in the result cache
:mod:`~pendcli.output.report_store`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING

from pendcli.base.errors import PendcliError
from pendcli.output.json import to_json
from pendcli.output.report_figures import Drawing, figure_caption, figure_tasks, shared_order
from pendcli.output.report_sections import (
    environment_section,
    introduction,
    paper_section,
    stability_section,
    tradeoff_section,
)
from pendcli.output.report_store import pack, result_digest, unpack

if TYPE_CHECKING:
    from pendcli.base.cache import ResultCache
    from pendcli.output.html.report import Pages
    from pendcli.run.reproduce import ReproduceResult
    from pendcli.run.tradeoff_engine import Point

__all__ = ["write_report"]


def check_out_folder(out: Path | str) -> Path:
    """Refuse an unusable output folder before any computation (one line, exit 2).

    The folder is replaced as a whole, so it must not be the current folder (or hold it), nor a
    file, nor a folder pendcli did not make (:func:`pendcli.base.owned_folders.check_owned`: its
    manifest lists every file in it), nor one another run is writing; its nearest existing
    parent must be a writable folder. A symlink is followed: the folder it names is written.
    """
    text = str(out)
    if text.strip() in ("", "."):
        raise PendcliError(
            f"--out {text!r} is the current folder; give a folder of its own, e.g. --out out"
        )
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise PendcliError(f"--out {text!r} is a file, not a folder; give a folder name")
    here = Path.cwd().resolve()
    if path.resolve() in (here, *here.parents):
        raise PendcliError(f"--out {text!r} holds the current folder; give a folder of its own")
    from pendcli.base.owned_folders import check_owned, probe_lock, write_through

    check_owned(write_through(path, "--out"), "--out")
    probe_lock(path, "--out")
    parent = path.resolve().parent
    while not parent.exists():
        parent = parent.parent
    from pendcli.base.plotting import cannot_create_in

    problem = "is not a folder" if not parent.is_dir() else cannot_create_in(parent)
    if problem is not None:
        raise PendcliError(f"--out: cannot create folder {text!r}: {parent}: {problem}")
    return path


def _rel(path: Path, out: Path) -> str:
    return path.resolve().relative_to(out.resolve()).as_posix()


class _Writer:
    """Writes files under the (temporary) output folder; remembers each one, relative to it."""

    def __init__(self, out: Path, quiet: bool) -> None:
        self.out = out
        self.quiet = quiet
        self.written: list[Path] = []

    def text(self, name: str, text: str) -> Path:
        path = self.out / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        self.written.append(Path(name))
        return path

    def add(self, paths: list[Path]) -> None:
        self.written += [p.relative_to(self.out) for p in paths]

    def status(self, message: str) -> None:
        if not self.quiet:
            from pendcli.base.console import console

            console(stderr=True).print(f"report: {message}")

    def figure_lines(self, figures: list[Path]) -> list[str]:
        """Each figure already written: its image (relative to the report), its caption."""
        lines = []
        for figure in figures:
            caption = figure_caption(figure)
            lines += [f"![{caption}]({_rel(figure, self.out)})", "", f"*{caption}*", ""]
        return lines


def write_report(
    result: ReproduceResult,
    out: Path | str,
    quiet: bool = True,
    measure: bool = False,
    jobs: int | None = None,
    pdf: bool = False,
    cache: ResultCache | None = None,
) -> list[Path]:
    """Write report.md, claims.json, the per-paper CSVs and every figure into ``out`` (and,
    with ``pdf``, each HTML page printed to PDF by headless Chromium).

    With a ``cache`` (:func:`pendcli.run.reproduce.result_cache`), the report's files are read
    from it when a report of the same result was stored (its key: every field of every row
    of ``result``, and the code, tables and versions), else written and stored; never with
    ``measure`` (timings of now) or ``pdf`` (Chromium's output is not pendcli's).

    The whole folder is built beside ``out`` and swapped in at the end, under ``out``'s lock
    (a concurrent run is refused): files of an earlier report that this one does not write
    are gone, and a failure leaves the old ``out`` as it was. The folder's manifest
    (``pendcli-manifest.txt``) lists every file written, and only such a folder is replaced.
    ``measure`` times the speed/accuracy families now instead of reading the committed
    work-precision tables; ``jobs`` processes draw the figures (default: up to 2).
    """
    from pendcli.base.owned_folders import MANIFEST, replace_owned_folder
    from pendcli.data.tables import paper_text

    target = check_out_folder(out)
    if pdf:  # refused before anything is written, not after
        from pendcli.output.html.report import require_chromium

        require_chromium()
    for key in result.papers:  # the HTML pages show them: missing or empty is an error
        paper_text(key)
    written: list[Path] = []

    params = None if cache is None or measure or pdf else {"result": result_digest(result)}

    def fill(folder: Path) -> None:
        stored = cache.get("report", params) if cache is not None and params else None
        if stored is None or not unpack(stored, folder, written):
            written.extend(_fill(result, folder, quiet, measure, jobs, pdf))
            if cache is not None and params:
                cache.put("report", params, pack(folder, written))

    replace_owned_folder(target, fill, "--out")
    return [target / p for p in (*written, Path(MANIFEST))]


def _fill(
    result: ReproduceResult,
    folder: Path,
    quiet: bool,
    measure: bool,
    jobs: int | None,
    pdf: bool = False,
) -> list[Path]:
    """Every file of the report, written into ``folder``; their paths relative to it. The
    figures are drawn while the pages are rendered without them (and the introduction
    written), all shared by the processes (report_figures.Drawing), claims.json and the
    tables written here while the workers take their first figures; the pages are then
    finished with their figures."""
    from pendcli.output.html.report import (
        markdown_for_a_reader,
        page_without_figures,
        pages_for_result,
    )
    from pendcli.run.regression import regenerated_tables

    writer = _Writer(folder, quiet)
    tradeoff = _tradeoff_data(result.papers, measure, writer)  # timings first, alone
    figure_sets = figure_tasks(result, folder, tradeoff.points if tradeoff else None)
    made = pages_for_result(result, result.equations)
    pages = [(p or "", "page", page_without_figures, (made, p)) for p in made.order()]
    intro = ("", "introduction", introduction, (result,))
    writer.status(f"drawing {len(figure_sets)} sets of figures")

    def tables() -> None:  # written here while the workers take their first figures
        writer.text("claims.json", to_json(result.document()))
        for name, table in regenerated_tables(result).items():
            writer.text(f"tables/{name}", table)

    with Drawing(shared_order(figure_sets, pages[:-1], [intro, pages[-1]]), jobs) as drawing:
        figures, done = drawing.results(first=tables)
    drew = sum(p.suffix == ".png" for ps in figures.values() for p in ps)
    writer.status(f"drew {drew} figures")
    markdown = _markdown(result, writer, figures, tradeoff, done["", "introduction"])
    writer.text("report.md", markdown_for_a_reader(markdown))
    rendered = [done[p or "", "page"] for p in made.order()]
    writer.add(_html_pages(made, rendered, folder, figures))
    if pdf:  # inside the folder being built, so the manifest lists the PDFs too
        from pendcli.output.html.report import print_pdfs

        writer.status(f"printing {len(pages)} pages to PDF")
        writer.add(print_pdfs(folder))
    return writer.written


def _markdown(
    result: ReproduceResult,
    writer: _Writer,
    figures: dict[str, list[Path]],
    tradeoff: _Tradeoff | None,
    intro: list[str],
) -> str:
    """report.md: its sections (``intro``: its introduction), each paper's figures (and the
    speed figures) listed as written."""
    lines = list(intro)
    for key in result.papers:
        drawn = figures.get(key, [])
        writer.add(drawn)
        lines += paper_section(result, key, writer.figure_lines(drawn))
    lines += stability_section(result)
    if tradeoff is not None:
        drawn = figures.get("tradeoff", [])
        writer.add(drawn)
        images = [f for f in drawn if f.suffix == ".png"]
        lines += tradeoff_section(tradeoff.provenance, writer.figure_lines(images))
    return "\n".join([*lines, *environment_section()])


def _html_pages(
    made: Pages, rendered: list[str], folder: Path, figures: dict[str, list[Path]]
) -> list[Path]:
    """report.html and one annotated page per paper (``rendered`` without their figures, by
    the processes that drew them), figures embedded with their captions."""
    from pendcli.output.html.report import Figure, write_pages

    captioned = {
        ("" if key == "tradeoff" else key): [
            Figure(p, figure_caption(p)) for p in paths if p.suffix == ".png"
        ]
        for key, paths in figures.items()
    }
    return write_pages(folder, made, rendered, captioned)


@dataclass
class _Tradeoff:
    """The work-precision points of the chosen papers and where their timings come from."""

    points: list[Point]
    provenance: str


def _tradeoff_data(keys: tuple[str, ...], measure: bool, writer: _Writer) -> _Tradeoff | None:
    """The families' tables, copied from the committed ones or (``measure``) measured now,
    written under ``tradeoff/``."""
    from pendcli.run import tradeoff, tradeoff_engine

    names = tradeoff.family_names(keys)
    if not names:
        return None
    points: list[Point] = []
    fresh = []
    for name in names:
        committed = tradeoff_engine.table_path(name)
        if measure or not committed.is_file():
            writer.status(f"measuring {name}")
            measured = tradeoff.measure_family(name)
            tradeoff_engine.write_table(measured, writer.out / "tradeoff" / f"{name}.csv")
            writer.written.append(Path("tradeoff") / f"{name}.csv")
            points += measured
            fresh.append(name)
        else:  # validated (UTF-8, every cell) before it is copied
            points += tradeoff_engine.read_points(committed)
            writer.text(f"tradeoff/{name}.csv", committed.read_text(encoding="utf-8"))
    return _Tradeoff(points, _provenance(tradeoff_engine, names, fresh))


def _provenance(tradeoff: ModuleType, names: list[str], fresh: list[str]) -> str:
    if len(fresh) == len(names):
        return "measured now, by this run, on the machine that wrote this report"
    date = tradeoff.measured_on()
    when = f"measured {date} by `make bench`" if date else "measured by `make bench`"
    text = f"committed tables `tables/tradeoff/<family>.csv`, {when}"
    if fresh:
        text += f" (measured now: {', '.join(fresh)}, whose committed table is missing)"
    return text + "; `pendcli reproduce --out DIR --measure` measures them again"
