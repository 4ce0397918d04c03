"""Every table-printing command at 80 and 120 columns: the numbers as the terminal promises them.

Each command is rendered as a user's terminal shows it (COLUMNS, which pendcli's console reads
when its output is not a terminal; and once through a real pseudo-terminal of 80 columns) and
its text is read back, token by token:

* at most 7 significant digits in any number the terminal formats (the README's promise; JSON
  and CSV keep every digit). A number quoted inside a string of the command's own JSON (a
  note, a formula as found) is the library's text, not the terminal's formatting, and is left
  to the notes;
* a number and its unit on one line (« 7.6e-07 s/evaluation »), as at 1000 columns;
* the value recomputed beside a printed sexagesimal angle (``-1°7'33''``) is sexagesimal too;
* a table's title on one line.
"""

from __future__ import annotations

import itertools
import json
import os
import re
import subprocess
import sys

import pytest
from helpers.cli import PENDCLI, invoke

COMMANDS = [
    ("reproduce",),
    ("reproduce", "--notes"),
    ("list",),
    ("formulas",),
    ("equations",),
    ("explain",),
    ("tisserand", "claims"),
    ("tisserand", "example"),
    ("tisserand", "series"),
    ("charbonnier", "table"),
    ("charbonnier", "integral", "5"),
    ("charbonnier", "integral", "5", "--tol", "1e-10"),
    ("lecornu", "claims"),
    ("lecornu", "zeros"),
    ("lecornu", "example"),
    ("lecornu", "ode-check"),
    ("lecornu", "g-sensitivity"),
    ("lecornu", "series"),
    ("lecornu", "zero-length"),
]
TERMINAL_DIGITS = 7  # the README: "the terminal shows floats to 7 significant digits"

_NUMBER = re.compile(r"[-+]?\d+\.\d+(?:e[-+]?\d+)?")
# A printed angle as the papers print one, whole seconds: -1°7'33'', 2'42'', 2''.
_PRINTED_ANGLE = re.compile(r"[-+]?(?:\d+°)?(?:\d+')?\d+''")
_ANGLE = re.compile(r"[-+]?(?:\d+°)?(?:\d+')?\d+(?:\.\d+)?''")
# A number followed by a unit word in one cell (one space; columns are two apart).
_WITH_UNIT = re.compile(r"(?<!\S)(\d[\d.]*(?:e[-+]?\d+)?) ([a-z][a-z/²]{0,13})(?=[\s,;.)]|$)")


def _render(args, width, monkeypatch, cache, *extra):
    monkeypatch.setenv("COLUMNS", str(width))
    monkeypatch.setenv("PENDCLI_CACHE", str(cache))
    code, out, err = invoke(*args, *extra, utf8=True)
    assert code == 0, err
    return out


def _strings(node: object) -> list[str]:
    """Every string of a JSON document."""
    if isinstance(node, str):
        return [node]
    if isinstance(node, dict):
        return [s for v in node.values() for s in _strings(v)]
    if isinstance(node, list):
        return [s for v in node for s in _strings(v)]
    return []


def _library_text(args, monkeypatch, cache) -> str:
    """The command's strings (notes, formulas as found) from its JSON, or "" without one."""
    monkeypatch.setenv("PENDCLI_CACHE", str(cache))
    code, out, _ = invoke(*args, "-f", "json", utf8=True)
    return "\n".join(_strings(json.loads(out))) if code == 0 else ""


def significant_digits(token: str) -> int:
    mantissa = token.lstrip("-+").split("e")[0].replace(".", "").lstrip("0")
    return len(mantissa)


def too_many_digits(out: str, library: str) -> list[str]:
    quoted = {m.group(0) for m in _NUMBER.finditer(library)}
    return [
        t
        for t in out.split()
        if _NUMBER.fullmatch(t) and significant_digits(t) > TERMINAL_DIGITS and t not in quoted
    ]


def decimal_beside_angle(out: str) -> list[tuple[str, str]]:
    """Each printed angle (whole seconds) standing as a cell (two blanks or the line's end on
    each side, not a word of prose) whose next number, the recomputed value beside or under
    it, is written as a decimal."""
    numbers: list[tuple[str, bool]] = []
    for line in out.splitlines():
        padded = f"  {line}  "
        for m in re.finditer(r"\S+", padded):
            token = m.group(0)
            if _ANGLE.fullmatch(token) or _NUMBER.fullmatch(token):
                cell = padded[m.start() - 2 : m.start()] == "  " and (
                    padded[m.end() : m.end() + 2] == "  " or not padded[m.end() :].strip()
                )
                numbers.append((token, cell))
    return [
        (a, b)
        for (a, cell), (b, _) in itertools.pairwise(numbers)
        if cell and _PRINTED_ANGLE.fullmatch(a) and not _ANGLE.fullmatch(b)
    ]


def units_apart(out: str, wide: str) -> list[str]:
    """The « number unit » pairs of the wide render that the narrow one splits."""
    pairs = {m.group(0) for m in _WITH_UNIT.finditer(wide)}
    flat = " ".join(line.strip() for line in out.splitlines())
    return sorted(p for p in pairs if p not in out and p in flat)


@pytest.mark.parametrize("args", COMMANDS, ids=lambda a: " ".join(a))
def test_render_numbers_at_80_and_120_columns(
    args, monkeypatch, shared_result_cache, reproduce_computed_once
):
    library = _library_text(args, monkeypatch, shared_result_cache)
    wide = _render(args, 1000, monkeypatch, shared_result_cache)
    for width in (80, 120):
        out = _render(args, width, monkeypatch, shared_result_cache)
        assert not too_many_digits(out, library), f"{width}: {too_many_digits(out, library)}"
        assert not decimal_beside_angle(out), f"{width}: {decimal_beside_angle(out)}"
        assert not units_apart(out, wide), f"{width}: {units_apart(out, wide)}"


@pytest.mark.parametrize("width", [80, 120])
def test_render_verdict_tables_with_angles_sexagesimal(width, monkeypatch, shared_result_cache):
    for fmt in ("table", "markdown"):
        out = _render(("reproduce", "-p", "tisserand"), width, monkeypatch, shared_result_cache,
                      "-f", fmt)  # fmt: skip
        claim = re.compile(r"example\.(psi_sin2|psi_sin4|phi_sin2)\b")
        rows = [line for line in out.splitlines() if claim.search(line)]
        assert rows, out
        for row in rows:
            angles = [t for t in row.replace("|", " ").split() if _ANGLE.fullmatch(t)]
            assert len(angles) >= 2, row  # printed and recomputed, both sexagesimal


@pytest.mark.parametrize("width", [80, 120])
def test_render_title_wider_than_its_table_on_one_line(width, monkeypatch, shared_result_cache):
    out = _render(("reproduce",), width, monkeypatch, shared_result_cache)
    assert "Where errors enter, and the rows that carry them" in out


def test_the_checks_fail_on_the_old_renders():
    """The checks themselves, on lines pendcli printed before the number style."""
    old = "example.psi_sin2      -1°7'33''    -1.12587  agrees  —"
    assert decimal_beside_angle(old) == [("-1°7'33''", "-1.12587")]
    assert decimal_beside_angle(old.replace("-1.12587", "-1°7'33.14''")) == []
    prose = "note  With his 2'42'' the shift is just under 1/5 mm. Series 0.1966 mm"
    assert decimal_beside_angle(prose) == []
    assert too_many_digits("recurrence  3.1415926535897931", "") == ["3.1415926535897931"]
    assert too_many_digits("note 0.9044908133 s", "gives 0.9044908133 s") == []
    narrow = "error 2.9e-13 <= tol 1e-10 in integral_pi, 7.6e-07\n    s/evaluation"
    wide = "error 2.9e-13 <= tol 1e-10 in integral_pi, 7.6e-07 s/evaluation"
    assert units_apart(narrow, wide) == ["7.6e-07 s/evaluation"]


@pytest.mark.skipif(sys.platform == "win32", reason="a POSIX pseudo-terminal")
def test_render_through_a_real_terminal_of_80_columns(tmp_path):
    """Through a pseudo-terminal (the console's terminal path, its width from the tty)."""
    import fcntl
    import pty
    import struct
    import termios

    leader, follower = pty.openpty()
    fcntl.ioctl(follower, termios.TIOCSWINSZ, struct.pack("HHHH", 50, 80, 0, 0))
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")}
    env.update(NO_COLOR="1", PENDCLI_CACHE=str(tmp_path), TERM="xterm")
    with subprocess.Popen(
        [*PENDCLI, "charbonnier", "integral", "5", "--tol", "1e-10"],
        stdin=follower, stdout=follower, stderr=subprocess.DEVNULL, env=env,
    ) as child:  # fmt: skip
        os.close(follower)
        chunks = []
        while True:
            try:
                chunk = os.read(leader, 4096)
            except OSError:  # the child closed the terminal
                break
            if not chunk:
                break
            chunks.append(chunk)
        assert child.wait() == 0
    os.close(leader)
    out = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", b"".join(chunks).decode()).replace("\r", "")
    assert max(map(len, out.splitlines())) <= 80
    assert re.search(r"\de-\d+ s/evaluation", out), out  # the time per evaluation and its unit
    assert not too_many_digits(out, "")


def test_prose_wraps_at_spaces_keeping_a_number_with_its_unit():
    from rich.text import Text

    from pendcli.output.table import wrapped

    prose = (
        "gammaln (exp(gammaln diff)): cheapest with measured worst error 2.9e-13 <= tol 1e-10 "
        "in integral_pi, 7.6e-07 s/evaluation; a shift of 0.1966 mm at θ0 = 0.4 rad"
    )
    words = prose.split()
    for width in range(12, len(prose) + 2):
        lines = wrapped(Text(prose), width).plain.split("\n")
        assert " ".join(lines).split() == words  # nothing lost, nothing cut inside a word
        for line in lines:
            assert len(line) <= width or " " not in line.replace("7.6e-07 s/", "")
        for pair in ("7.6e-07 s/evaluation", "0.1966 mm", "0.4 rad"):
            assert any(pair in line for line in lines), (width, lines)
