"""The HTML report in a real browser: headless Chromium clicks every mark (marker ``browser``).

Skipped where Chromium is absent (Debian package ``chromium``); ``make test-browser`` runs it.
Each page is copied with a small script appended that clicks every highlighted number and
equation label, and records whether the click landed on an existing row; Chromium's
``--dump-dom`` returns the page after the script ran. A screenshot of each page is kept in
the test's temporary folder (the path is printed) for a person to look at.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from pendcli.html_report import write_for_result
from pendcli.papers.registry import PAPERS
from pendcli.reproduce import reproduce_all

pytestmark = pytest.mark.browser

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")

CLICK_EVERY_MARK = """
<script>
const results = [];
for (const a of document.querySelectorAll("a.hl")) {
  a.click();
  const id = a.getAttribute("href").slice(1);
  results.push([a.id.slice(3), location.hash === "#" + id && !!document.getElementById(id)]);
}
document.body.insertAdjacentHTML("beforeend",
  "<pre id='click-results'>" + JSON.stringify(results) + "</pre>");
</script>
"""


def _chromium(*args: str) -> str:
    assert CHROMIUM is not None
    done = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", *args],
        capture_output=True,
        text=True,
        timeout=120,
    )
    return done.stdout


@pytest.fixture(scope="module")
def pages(tmp_path_factory: pytest.TempPathFactory) -> Path:
    if CHROMIUM is None:
        pytest.skip("Chromium is not installed (apt-get install chromium)")
    out = tmp_path_factory.mktemp("html")
    write_for_result(reproduce_all(PAPERS), out, {})
    return out


@pytest.mark.parametrize("paper", PAPERS)
def test_every_claim_is_on_the_page_and_every_mark_clicks_to_its_row(
    pages: Path, paper: str
) -> None:
    page = pages / "papers" / f"{paper}.html"
    probe = page.with_name(f"{paper}-probe.html")
    probe.write_text(page.read_text("utf-8").replace("</body>", CLICK_EVERY_MARK + "</body>"))
    dom = _chromium("--dump-dom", probe.as_uri())
    found = re.search(r"<pre id=\"click-results\">(.*?)</pre>", dom, re.S)
    assert found, "the click script did not run"
    clicks = dict(json.loads(found.group(1).replace("&quot;", '"')))
    ids = set(re.findall(r'<tr id="row-([^"]+)"', dom))
    result = reproduce_all((paper,))
    claim_ids = {row.id for row in result.claims[paper]}
    assert claim_ids <= ids  # every claim has its row in the rendered page
    assert claim_ids <= set(clicks)  # and a mark in the text (every claim is located)
    assert all(clicks.values()), [k for k, ok in clicks.items() if not ok]
    shot = pages / f"{paper}.png"
    _chromium("--window-size=1280,1800", f"--screenshot={shot}", page.as_uri())
    assert shot.stat().st_size > 10_000
    print(f"screenshot: {shot}")
