"""The HTML edition in a real browser: headless Chromium (marker ``browser``).

Skipped where Chromium is absent (Debian package ``chromium``); ``make test-browser`` runs it.
Each page is copied with a small script appended that reads what the browser rendered: the
page's visible text (no raw TeX may show), every mark's box (visible, inside the text, with
its note in the same paragraph's margin) and every in-page link (it lands on an element);
Chromium's ``--dump-dom`` returns the page after the script ran. Links between pages are
checked against the ids of the page they point to. A screenshot of each page at 1280 px is
kept in the test's temporary folder (the path is printed) for a person to look at.
"""

from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest

from pendcli.data.ledger import load_ledger
from pendcli.data.tables import load_paper_table
from pendcli.output.html.report import chromium, write_for_result
from pendcli.papers.registry import PAPERS
from pendcli.run.reproduce import reproduce_all

pytestmark = pytest.mark.browser

CHROMIUM = chromium()
RAW_TEX = ("$$", "\\frac", "\\sqrt", "\\quad")

PROBE = """
<script>
const visible = (e) => { const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0
  && getComputedStyle(e).visibility !== "hidden"; };
const marks = [...document.querySelectorAll(".hl[id^='at-']")].map((m) => {
  const key = m.id.slice(3), blk = m.closest(".blk"), own = m.dataset.note || key;
  // a later piece of a quote or formula shares its first piece's note, wherever that is
  const note = own === key ? blk && blk.querySelector(`[id="note-${CSS.escape(key)}"]`)
    : document.getElementById(`note-${own}`);
  return [key, visible(m), !!m.closest(".edition .txt"), !!note && visible(note),
          m.dataset.row || "", m.dataset.lines || ""];
});
// Chromium throttles a page past ~200 navigations: the first 150 links are clicked, every
// link's target must exist and be visible.
const links = [...document.querySelectorAll("a[href^='#']")].map((a, i) => {
  const href = a.getAttribute("href"), id = decodeURIComponent(href.slice(1));
  const target = document.getElementById(id);
  if (i < 150) a.click();
  return [id, !!target && visible(target) && (i >= 150 || location.hash === href)];
});
const text = document.body.innerText;
document.body.insertAdjacentHTML("beforeend", "<pre id='probe'></pre>");
document.getElementById("probe").textContent = JSON.stringify({marks, links, text});
</script>
"""


def _chromium(*args: str) -> str:
    assert CHROMIUM is not None
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={profile}", *args],
            capture_output=True, text=True, timeout=300, check=False,
        )  # fmt: skip
    return done.stdout


@pytest.fixture(scope="module")
def pages(tmp_path_factory: pytest.TempPathFactory) -> Path:
    if CHROMIUM is None:
        pytest.skip("Chromium is not installed (apt-get install chromium)")
    out = tmp_path_factory.mktemp("html")
    result = reproduce_all(PAPERS, equations=True)
    write_for_result(result, out, {}, result.equations)
    return out


def _probe(page: Path, script: str | None = None) -> dict[str, list]:  # type: ignore[type-arg]
    """What a script (PROBE unless given) finds in the page as Chromium draws it at 1280 px."""
    probe = page.with_name(f"{page.stem}-probe.html")
    probe.write_text(
        page.read_text("utf-8").replace("</body>", (script or PROBE) + "</body>"), "utf-8"
    )
    dom = _chromium("--window-size=1280,2000", "--dump-dom", probe.as_uri())
    probe.unlink()
    found = re.search(r"<pre id=\"probe\">(.*?)</pre>", dom, re.S)
    assert found, "the probe script did not run"
    return json.loads(html.unescape(found.group(1)))  # type: ignore[no-any-return]


def _ids(page: Path) -> set[str]:
    return set(map(html.unescape, re.findall(r'id="([^"]+)"', page.read_text("utf-8"))))


def _screenshot(pages: Path, page: Path) -> None:
    shot = pages / f"{page.stem}.png"
    _chromium("--window-size=1280,2000", f"--screenshot={shot}", page.as_uri())
    assert shot.stat().st_size > 10_000
    print(f"screenshot: {shot}")


@pytest.mark.parametrize("paper", PAPERS)
def test_a_paper_page_shows_no_tex_and_every_mark_and_link_lands(pages: Path, paper: str) -> None:
    page = pages / "papers" / f"{paper}.html"
    seen = _probe(page)
    shown = [t for t in RAW_TEX if t in seen["text"]]
    assert not shown, f"raw TeX in the rendered text: {shown}"
    assert len(seen["marks"]) > 10
    bad = [m for m in seen["marks"] if not all(m[1:4])]
    assert not bad, f"marks not visible, outside the text or without their note: {bad[:5]}"
    lost = [link for link, ok in seen["links"] if not ok]
    assert not lost, f"links that do not land: {lost[:5]}"
    rows = set(map(html.unescape, re.findall(r'<tr id="row-([^"]+)"', page.read_text("utf-8"))))
    claims = {row.id for row in reproduce_all((paper,), formulas=False).claims[paper]}
    assert claims <= rows  # every claim has its row on the page
    shown_at: dict[str, list[tuple[int, int]]] = {}
    for _, *_, row, lines in seen["marks"]:
        first, last = map(int, lines.split("-"))
        shown_at.setdefault(row, []).append((first, last))
    placed = [*load_ledger(paper).rows, *load_paper_table(paper).claims]
    outside = [
        (r.id, r.lines, shown_at.get(r.id))
        for r in placed
        if r.lines is None or not _within(r.lines, shown_at.get(r.id, []))
    ]
    assert not outside, f"rows with no visible mark within their lines: {outside[:5]}"
    _screenshot(pages, page)


# The edition's layout as drawn: the gap between consecutive paragraphs of text (the margin
# notes must not hold the text apart), each note box against the text's right edge, against
# the note before it, and against the top of its own paragraph (a note may run on below its
# paragraph, never start above it).
LAYOUT = """
<script>
const box = (e) => e.getBoundingClientRect();
const drawn = (e) => {
  const r = document.createRange(); r.selectNodeContents(e); return r.getBoundingClientRect(); };
// the gaps between paragraphs, not across a page break of the edition (set apart on purpose)
const gaps = []; let before = null;
for (const e of document.querySelectorAll(".edition .txt, .edition .pagebreak")) {
  const r = drawn(e);
  if (e.classList.contains("pagebreak")) { before = null; continue; }
  if (r.height === 0) continue;
  if (before) gaps.push([Math.round(r.top - before.bottom), Math.round(r.top + scrollY)]);
  // a dense paragraph's notes follow it (set apart on purpose, as a page break is)
  before = e.parentElement.classList.contains("dense") ? null : r;
}
const right = Math.max(...[...document.querySelectorAll(".edition .txt")].map((t) => box(t).right));
const notes = [...document.querySelectorAll(".edition .blk:not(.dense) > .notes")];
// a dense paragraph's notes: below its text, inside the text column
const below = [...document.querySelectorAll(".edition .blk.dense > .notes")].filter((n) => {
  const t = box(n.parentElement.querySelector(".txt"));
  return box(n).top < t.bottom - 1 || box(n).right > right + 1;
}).length;
const own = (n) => box(n.parentElement.querySelector(".txt")).top;
const over = notes.filter((n) => box(n).left < right).length;
const stacked = notes.filter((n, i) => i && box(n).top < box(notes[i - 1]).bottom - 0.5).length;
const early = notes.filter((n) => box(n).top < own(n) - 1).length;
const drift = Math.max(0, ...notes.map((n) => box(n).top - own(n)));
// a mark around a whole formula holds the formula's box (not slivers beside it)
const slivers = [...document.querySelectorAll(".edition .hl.whole")].filter((h) => {
  const m = h.querySelector("math"); if (!m) return false;
  const a = box(h), b = box(m);
  return a.left > b.left + 1 || a.right < b.right - 1
    || a.top > b.top + 1 || a.bottom < b.bottom - 1;
}).map((h) => h.id);
// a table wider than the page hides its last columns behind a scroll
const hidden = [...document.querySelectorAll(".wide")].filter((w) => w.scrollWidth > w.clientWidth)
  .map((w) => w.previousElementSibling ? w.previousElementSibling.textContent.slice(0, 40) : "");
document.body.insertAdjacentHTML("beforeend", "<pre id='probe'></pre>");
document.getElementById("probe").textContent = JSON.stringify(
  {gaps, over, stacked, early, drift, below, hidden, slivers, notes: notes.length});
</script>
"""
MAX_GAP = 40  # px at 1280 px: a paragraph's margins and a displayed formula's padding
# px: a margin note starts at most this far below its paragraph (beside it, not a screen
# later); was 722 px beside Lecornu's tables before their notes were set below them
MAX_DRIFT = 250


def _layout(page: Path) -> dict[str, object]:
    return _probe(page, LAYOUT)


@pytest.mark.parametrize("paper", PAPERS)
def test_the_notes_do_not_hold_the_text_apart_nor_cover_it_nor_a_table_hide(
    pages: Path, paper: str
) -> None:
    seen = _layout(pages / "papers" / f"{paper}.html")
    gaps = sorted(seen["gaps"], reverse=True)  # type: ignore[call-overload]
    assert gaps[0][0] <= MAX_GAP, f"white gaps between lines of text (px, at y): {gaps[:5]}"
    assert seen["notes"], "no margin notes drawn"
    assert seen["over"] == 0, f"{seen['over']} notes reach into the text column"
    assert seen["stacked"] == 0, f"{seen['stacked']} notes overlap the note before them"
    assert seen["early"] == 0, f"{seen['early']} notes start above their paragraph"
    assert seen["below"] == 0, f"{seen['below']} dense paragraphs' notes not below their text"
    assert seen["drift"] <= MAX_DRIFT, f"a margin note {seen['drift']:.0f} px below its paragraph"
    assert not seen["hidden"], f"tables wider than the page at 1280 px: {seen['hidden']}"
    assert not seen["slivers"], f"marks not around their formula: {seen['slivers'][:5]}"
    print(f"{paper}: largest gap {gaps[0][0]} px, a note at most {seen['drift']:.0f} px below")


def _within(lines: tuple[int, int], shown: list[tuple[int, int]]) -> bool:
    """A mark the browser shows lies within the row's lines (its data-lines)."""
    return any(lines[0] <= a and b <= lines[1] for a, b in shown)


def test_the_report_shows_no_tex_and_every_link_lands(pages: Path) -> None:
    page = pages / "report.html"
    seen = _probe(page)
    assert not [t for t in RAW_TEX if t in seen["text"]]
    assert not [link for link, ok in seen["links"] if not ok]
    source = page.read_text("utf-8")
    targets = re.findall(r'href="papers/([a-z]+)\.html#([^"]+)"', source)
    assert targets
    ids = {p: _ids(pages / "papers" / f"{p}.html") for p in {p for p, _ in targets}}
    missing = [(p, t) for p, t in targets if html.unescape(t) not in ids[p]]
    assert not missing, missing[:5]
    _screenshot(pages, page)


def test_a_paper_page_prints_to_pdf(pages: Path) -> None:
    from pendcli.output.html.report import print_pdfs

    folder = pages / "print"
    (folder / "papers").mkdir(parents=True)
    shutil.copy(pages / "papers" / "tisserand.html", folder / "papers" / "tisserand.html")
    (printed,) = print_pdfs(folder)
    assert printed == folder / "papers" / "tisserand.pdf"
    assert printed.read_bytes()[:5] == b"%PDF-" and printed.stat().st_size > 50_000
