"""The reading record of the prose (tables/papers/<paper>.reading.toml): every paragraph of a
read text accounted for by the rows holding its claims or a reason it has none; the record is
refused when it disagrees with the text or the ledger; labels printed twice are listed."""

from __future__ import annotations

import json
import math
import re
import shutil
import tomllib
from pathlib import Path

import pytest
from helpers.ledgers import committed_ledger, paragraphs_by_hand

from pendcli.base.errors import PendcliError
from pendcli.data.ledger_labels import label_lines
from pendcli.data.reading import load_reading, parse_reading, prose_paragraphs, reading_coverage

TABLES = Path(__file__).resolve().parents[2] / "tables"
# the papers whose every paragraph is read: one left unread fails
COMPLETE = ("tisserand", "charbonnier")
WITH_RECORD = ("tisserand", "charbonnier")


@pytest.mark.parametrize("paper", ["tisserand", "lecornu", "charbonnier"])
def test_paragraphs_are_the_runs_of_prose_between_blank_lines_and_formulas(paper: str) -> None:
    text = (TABLES / "papers" / f"{paper}.txt").read_text(encoding="utf-8")
    assert list(prose_paragraphs(text)) == paragraphs_by_hand(text)


def test_paragraphs_of_a_small_text() -> None:
    text = "A title\n\nOne line,\nits second\n$$x = 1$$\nthen $$y$$ words\n\n$$a\nb$$\nend"
    assert prose_paragraphs(text) == ((1, 1), (3, 4), (6, 6), (10, 10))


@pytest.mark.parametrize("paper", COMPLETE)
def test_every_paragraph_of_a_read_paper_is_accounted_for(paper: str) -> None:
    reading = load_reading(paper, TABLES)
    assert reading is not None
    assert reading.missing == ()
    coverage = reading_coverage(paper, TABLES)
    assert coverage.read == coverage.paragraphs == len(reading.paragraphs)


@pytest.mark.parametrize("paper", WITH_RECORD)
def test_each_row_a_paragraph_names_quotes_it_within_its_lines(paper: str) -> None:
    """Independently of the loader: each named row exists and one of its quotes is printed
    within the paragraph's lines, and a claim row's quote lies in a paragraph naming it."""
    raw = tomllib.loads((TABLES / "papers" / f"{paper}.reading.toml").read_text("utf-8"))
    lines = (TABLES / "papers" / f"{paper}.txt").read_text(encoding="utf-8").split("\n")
    rows = {r.id: r for r in committed_ledger(paper).rows}
    named: dict[str, list[tuple[int, int]]] = {}
    for entry in raw["paragraph"]:
        first, last = entry["lines"]
        words = "\n".join(lines[first - 1 : last])
        for row_id in entry.get("rows", []):
            assert any(q in words for q in rows[row_id].quotes), (row_id, first)
            named.setdefault(row_id, []).append((first, last))
    for row_id, spans in named.items():
        for quote in rows[row_id].quotes:
            where = [s for s in spans if quote in "\n".join(lines[s[0] - 1 : s[1]])]
            assert where, f"{row_id}: quote {quote!r} in no paragraph naming the row"


# --- refusals: one line naming the file -------------------------------------------------------


def _copy(tmp_path: Path, paper: str = "tisserand") -> Path:
    root = tmp_path / "tables"
    for sub in ("papers", "equations", "published"):
        (root / sub).mkdir(parents=True)
    for name in (f"{paper}.txt", f"{paper}.reading.toml"):
        shutil.copy(TABLES / "papers" / name, root / "papers" / name)
    shutil.copy(TABLES / "equations" / f"{paper}.toml", root / "equations" / f"{paper}.toml")
    return root


def _parse(raw: dict[str, object]) -> object:
    text = (TABLES / "papers" / "tisserand.txt").read_text(encoding="utf-8")
    quotes = {r.id: r.quotes for r in committed_ledger("tisserand").rows}
    path = Path("tisserand.reading.toml")
    return parse_reading(raw, "tisserand", path, text, quotes, "tables/papers/tisserand.txt")


def _raw() -> dict[str, object]:
    return tomllib.loads((TABLES / "papers" / "tisserand.reading.toml").read_text("utf-8"))


def _with(index: int, **changes: object) -> dict[str, object]:
    raw = _raw()
    entry = raw["paragraph"][index]  # type: ignore[index]
    for key, value in changes.items():
        if value is None:
            entry.pop(key, None)
        else:
            entry[key] = value
    return raw


def _index(first: int) -> int:
    return next(i for i, e in enumerate(_raw()["paragraph"]) if e["lines"][0] == first)  # type: ignore[attr-defined]


REFUSED = [
    ("an unknown key", _with(0, reason="x"), r"unknown key\(s\) 'reason'"),
    ("lines inside a paragraph", _with(_index(9), lines=[9, 9]), r"\[9, 9\] are not a paragraph"),
    ("lines over a formula", _with(_index(32), lines=[32, 36]), r"overlaps \[\[32, 32\]\]"),
    ("both", _with(_index(30), none="x"), "either 'rows' or 'none'"),
    ("neither", _with(_index(5), none=None), "either 'rows' or 'none'"),
    ("a reason of two lines", _with(_index(5), none="a\nb"), "one line"),
    ("an unknown row", _with(_index(30), rows=["tisserand.result.nowhere"]), "not in the ledger"),
    # a row whose quote is printed elsewhere (line 180, not 178)
    ("a quote elsewhere", _with(_index(178), rows=["tisserand.result.resal-rate"]),
     r"'tisserand.result.resal-rate' has no quote within these lines"),
    ("a row without a quote", _with(_index(32), none=None, rows=["tisserand.result.k-definition"]),
     "has no quote"),
]  # fmt: skip


@pytest.mark.parametrize(("what", "raw", "message"), REFUSED, ids=[r[0] for r in REFUSED])
def test_a_record_that_disagrees_is_refused(
    what: str, raw: dict[str, object], message: str
) -> None:
    with pytest.raises(PendcliError, match=message) as caught:
        _parse(raw)
    assert "\n" not in str(caught.value) and "tisserand.reading.toml" in str(caught.value)


def test_a_paragraph_listed_twice_or_out_of_order_is_refused() -> None:
    raw = _raw()
    paragraphs = raw["paragraph"]
    assert isinstance(paragraphs, list)
    raw["paragraph"] = [*paragraphs[:3], paragraphs[2], *paragraphs[3:]]
    with pytest.raises(PendcliError, match=r"listed again or out of order"):
        _parse(raw)
    raw["paragraph"] = [paragraphs[1], paragraphs[0], *paragraphs[2:]]
    with pytest.raises(PendcliError, match=r"listed again or out of order"):
        _parse(raw)


def test_a_paragraph_left_out_is_unread_and_counted(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    path = root / "papers" / "tisserand.reading.toml"
    text = path.read_text(encoding="utf-8")
    cut = re.sub(r"\[\[paragraph\]\]\nlines = \[178, 178\]\nrows = \[[^\]]*\]\n", "", text)
    assert cut != text
    path.write_text(cut, encoding="utf-8")
    reading = load_reading("tisserand", root)
    assert reading is not None and reading.missing == ((178, 178),)
    coverage = reading_coverage("tisserand", root)
    assert (coverage.read, coverage.paragraphs) == (53, 54)
    assert coverage.as_dict()["unread_paragraphs"] == [[178, 178]]


def test_a_header_naming_another_text_is_refused() -> None:
    raw = _raw()
    raw["reading"] = {"paper": "tisserand", "text": "tables/papers/lecornu.txt"}
    with pytest.raises(PendcliError, match="the ledger's text"):
        _parse(raw)


def test_a_paper_without_a_record_has_every_paragraph_unread(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    (root / "papers" / "tisserand.reading.toml").unlink()
    assert load_reading("tisserand", root) is None
    coverage = reading_coverage("tisserand", root)
    assert coverage.read == 0 and coverage.paragraphs == 54


# --- labels printed more than once -------------------------------------------------------------


def test_labels_are_listed_with_the_line_of_each_printing() -> None:
    text = "intro (3) cited\n$$(1) \\quad a = b$$\n\n$$x = y \\quad (2)$$\nprose\n$$(1) \\quad c$$"
    assert label_lines(text) == {"(1)": (2, 6), "(2)": (4,)}


def test_the_labels_printed_twice_are_lecornus_18_to_22() -> None:
    """An independent count: a label opening a display formula line, per printing."""
    for paper, expected in (("tisserand", {}), ("charbonnier", {}), ("lecornu", None)):
        text = (TABLES / "papers" / f"{paper}.txt").read_text(encoding="utf-8")
        twice = {k: v for k, v in label_lines(text).items() if len(v) > 1}
        opening = re.findall(r"^\$\$\s*\((\d+)\)", text, flags=re.M)
        counted = {f"({n})" for n in opening if opening.count(n) > 1}
        assert counted <= set(twice)
        if expected is not None:
            assert twice == expected
        else:
            assert sorted(twice) == ["(18)", "(19)", "(20)", "(21)", "(22)"]
            assert all(len(v) == 2 for v in twice.values())
    coverage = reading_coverage("lecornu", TABLES).as_dict()
    assert json.loads(json.dumps(coverage))["labels_printed_twice"]["(18)"] == [266, 384]


# --- a claim checked two ways: the sense of the axis's turn (line 180) -------------------------


def _apse_advance(h_sign: float) -> float:
    """The azimuth gained between the highest and the lowest point of the spherical pendulum,
    less π/2 (what the ellipse's quarter turn gives), by scipy's ODE, θ0 = 0.5, θ1 = 0.25."""
    from scipy.integrate import solve_ivp

    theta0, theta1, k = 0.5, 0.25, 1.0
    c0, c1 = math.cos(theta0), math.cos(theta1)
    h = h_sign * k * math.sqrt(2 * (1 - c0**2) * (1 - c1**2) / (c0 + c1))

    def rhs(_t: float, y: list[float]) -> list[float]:
        theta, dtheta, _phi = y
        dphi = h / math.sin(theta) ** 2
        return [dtheta, math.sin(theta) * math.cos(theta) * dphi**2 - k**2 * math.sin(theta), dphi]

    def lowest(_t: float, y: list[float]) -> float:
        return y[1]

    lowest.direction = 1  # type: ignore[attr-defined]
    lowest.terminal = True  # type: ignore[attr-defined]  # the first lowest point is the one read
    run = solve_ivp(rhs, (0, 50), [theta0, 0, 0], events=lowest, rtol=1e-9, atol=1e-11)
    (_, _, phi) = run.y_events[0][0]
    return float(abs(phi) - math.pi / 2) * math.copysign(1, phi)


def test_the_axis_turns_in_the_sense_of_the_pendulum() -> None:
    """« tourne … dans le sens même du mouvement du pendule »: from the highest to the lowest
    point the azimuth gains more than the quarter turn, in whichever sense the bob goes."""
    forward, backward = _apse_advance(1.0), _apse_advance(-1.0)
    assert forward > 0 > backward
    assert forward == pytest.approx(-backward, rel=1e-6)
    # (3/8)u0u1 per unit of k't over a quarter period (k't ≈ π/2): the same sign and size
    u0, u1 = math.sin(0.5), math.sin(0.25)
    assert forward == pytest.approx(3 / 8 * u0 * u1 * math.pi / 2, rel=0.3)
