"""Resource limits, odd paths and closed pipes: each ends in one whole line or a quiet exit.

A count that would need gigabytes is refused before anything is allocated; the limit of open
files (``ulimit -n``) and of memory (``ulimit -v``) reached are one line naming that limit,
exit 2, never an internal error, and leave no temporary folder; a newline in a path is shown
escaped, so the error line stays whole; a reader that stops early ends the run quietly with
status 141. The limits are set in real processes (``preexec_fn`` with
``resource.setrlimit``), and peak memory is read with ``os.wait4``.
"""

from __future__ import annotations

import gc
import os
import resource
import signal
import subprocess
import sys
import textwrap
from collections.abc import Callable
from pathlib import Path

import pytest
from helpers.cli import CliResult, assert_clean_error, child_env, invoke
from helpers.forked import in_a_child

from pendcli.base.errors import out_of_memory

PENDCLI = (sys.executable, "-m", "pendcli")
CHEAP = ("reproduce", "-p", "tisserand", "--no-formulas", "--no-equations", "--no-stability")
README = Path(__file__).resolve().parents[2] / "docs" / "usage.md"
MB = 1 << 20


def limited_env(**extra: str) -> dict[str, str]:
    # two BLAS threads, as on the 2-core machines this was measured on: the address space
    # OpenBLAS reserves grows with its threads (and below ~250 MB its start-up never returns)
    return child_env(OPENBLAS_NUM_THREADS="2", **extra)


def limited(kind: int, value: int) -> Callable[[], None]:
    return lambda: resource.setrlimit(kind, (value, value))


def run(
    *args: str, limit: Callable[[], None] | None = None, **env: str
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*PENDCLI, *args],
        env=limited_env(**env),
        capture_output=True,
        text=True,
        preexec_fn=limit,
        timeout=300,  # a hang guard only
    )


def one_line(proc: subprocess.CompletedProcess[str], *words: str) -> str:
    assert_clean_error(proc.returncode, proc.stderr)
    line = proc.stderr.strip()
    assert all(w in line for w in words), line
    return line


def one_line_here(result: CliResult, *words: str) -> str:
    """:func:`one_line` of a run in this process."""
    assert_clean_error(result.code, result.err)
    line = result.err.strip()
    assert all(w in line for w in words), line
    return line


# --- lecornu zeros: memory bounded whatever the count ------------------------------------


def test_scipy_zeros_beyond_their_bound_are_refused_before_allocating():
    # 10^7 zeros by scipy took 2.9 GB (a MemoryError, exit 3, under a 1 GB limit)
    proc = run(
        "lecornu", "zeros", "--count", "10000000", "--method", "scipy", "-f", "csv",
        limit=limited(resource.RLIMIT_AS, 1024 * MB),
    )  # fmt: skip
    one_line(proc, "--count: 10000000 is too large for method 'scipy'", "<= 1000000")
    assert proc.stdout == ""


def test_series_zeros_beyond_their_safe_range_are_refused_before_allocating():
    # the series made 10^7 guesses (704 MB) before refusing all but six of them
    proc = run(
        "lecornu", "zeros", "--count", "10000000", "--method", "series", "-f", "json",
        limit=limited(resource.RLIMIT_AS, 450 * MB),
    )  # fmt: skip
    one_line(proc, "--count: 10000000 is beyond the safe range", "1 <= --count <= 6")
    assert proc.stdout == ""  # refused before the document began


def peak_memory(*args: str) -> int:
    """Peak resident memory (bytes) of one run of `pendcli ARGS`, output discarded."""
    proc = subprocess.Popen(
        [*PENDCLI, *args], env=limited_env(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE
    )
    _, status, usage = os.wait4(proc.pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    assert proc.stderr is not None and proc.stderr.read() == b""
    proc.stderr.close()
    return usage.ru_maxrss * 1024


def test_scipy_zeros_are_written_a_chunk_at_a_time():
    """scipy's zeros come at once, but their text is made a chunk at a time: 400,000 zeros
    cost 28 MB above 10 of them (13 MB of them is scipy's own four arrays); when the whole
    text was made at once, 111 MB."""
    zeros = ("lecornu", "zeros", "--method", "scipy", "-f", "csv", "--count")
    extra = peak_memory(*zeros, "400000") - peak_memory(*zeros, "10")
    assert extra < 60 * MB, extra / MB


# --- the limit of open files ----------------------------------------------------------


FILL_UNTIL_EMFILE = textwrap.dedent(
    """
    import os, resource, sys
    from pathlib import Path
    from pendcli.base.errors import PendcliError
    from pendcli.base.owned_folders import replace_owned_folder

    font = Path(sys.argv[1])  # a file only read, as matplotlib reads its fonts

    def fill(tmp):
        (tmp / "a").mkdir()
        (tmp / "a" / "report.md").write_text("half")
        held = []
        while True:  # open until the limit is reached, and keep them all open
            held.append(open(font, "rb"))

    resource.setrlimit(resource.RLIMIT_NOFILE, (24, 24))
    try:
        replace_owned_folder(Path(sys.argv[2]), fill, "--out")
    except PendcliError as exc:
        print(exc)
    """
)


def test_the_limit_of_open_files_is_named_and_the_half_folder_removed(tmp_path):
    font = tmp_path / "DejaVuSans.ttf"
    font.write_bytes(b"font")
    out = tmp_path / "out"
    proc = subprocess.run(
        [sys.executable, "-c", FILL_UNTIL_EMFILE, str(font), str(out)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0 and proc.stderr == "", proc.stderr
    line = proc.stdout.strip()
    assert line.startswith("too many open files (EMFILE: the limit, ulimit -n, is 24)"), line
    assert f"opening {font}" in line and "cannot write" not in line  # it was only read
    assert sorted(p.name for p in tmp_path.iterdir()) == ["DejaVuSans.ttf"]  # nothing left


def test_reproduce_out_at_the_limit_of_open_files(tmp_path):
    out = tmp_path / "out"
    proc = run(*CHEAP, "-q", "--out", str(out), limit=limited(resource.RLIMIT_NOFILE, 7))
    line = one_line(proc, "too many open files (EMFILE: the limit, ulimit -n, is 7)")
    assert "cannot write" not in line and str(out) not in line, line  # a font it only reads
    assert list(tmp_path.iterdir()) == []  # neither the folder nor its temporary


# --- a newline in a path ----------------------------------------------------------------


def test_a_newline_in_a_path_is_shown_escaped_in_one_whole_line(tmp_path):
    """Through the entry point in this process: the line is made by the error's printer,
    which a fresh process runs alike (the real process's one line is the limits' tests')."""
    tables = tmp_path / "my\ntables"
    line = one_line_here(invoke("list", env={"PENDCLI_TABLES": str(tables)}), "published table")
    assert str(tables).replace("\n", "\\n") in line, line
    plot = tmp_path / "no\nsuch" / "p.png"
    line = one_line_here(invoke("tisserand", "example", "--plot", str(plot)), "does not exist")
    assert "no\\nsuch" in line, line


def test_every_control_character_of_a_message_is_escaped():
    from pendcli.base.errors import one_line as whole

    assert whole("a\nb\r\x1b[31mc\u2028d θ ≤ é\t") == "a\\nb\\r\\x1b[31mc\\u2028d θ ≤ é\\t"


# --- out of memory ------------------------------------------------------------------------


@pytest.mark.parametrize(
    "args",
    [("reproduce", "-q", "-f", "json"), ("tisserand", "example", "--plot", "PLOT")],
    ids=["reproduce", "figure"],
)
def test_out_of_memory_is_one_line_not_an_internal_error(tmp_path, args):
    """At 300 MB a library cannot be mapped (an ImportError) or an allocation is refused (a
    MemoryError, or C++'s bad_alloc): both were exit 3, "internal error"."""
    args = tuple(str(tmp_path / "p.png") if a == "PLOT" else a for a in args)
    proc = run(*args, limit=limited(resource.RLIMIT_AS, 300 * MB))
    one_line(proc, "out of memory (the address space is limited to 300 MB: ulimit -v)")


@pytest.mark.parametrize(
    ("error", "said"),
    [
        (MemoryError("Unable to allocate 2.9 GiB"), "out of memory: Unable to allocate 2.9 GiB"),
        (MemoryError(), "out of memory: an allocation failed"),
        (
            ImportError("x.so: failed to map segment from shared object", path="/lib/x.so"),
            "out of memory: cannot load /lib/x.so (failed to map segment)",
        ),
    ],
)
def test_a_memory_error_anywhere_is_one_line_and_exit_2(monkeypatch, error, said):
    from pendcli.numerics import besselzeros

    def fails(*args: object, **kwargs: object) -> None:
        raise error

    monkeypatch.setattr(besselzeros, "iter_bessel_zeros", fails)
    # The line frees the failed work with a full collection: here it would walk every object
    # this test process holds (sympy's, the tables': 0.1-0.2 s). They are frozen out of it,
    # so it walks what the run made, as in a fresh process.
    gc.freeze()
    try:
        code, _, err = invoke("lecornu", "zeros", "--count", "5")
    finally:
        gc.unfreeze()
    assert_clean_error(code, err)
    assert err.strip() == f"pendcli: error: {said}"


def _said_of_a_silent_failure(limit: int) -> str | None:
    hard = resource.getrlimit(resource.RLIMIT_AS)[1]
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    return out_of_memory(SystemError("error return without exception set"))


def test_a_library_failing_silently_under_a_memory_limit_is_out_of_memory():
    """At 300 MB a Cython module's initialisation, loading another module, failed without an
    exception set (a SystemError, exit 3): under a limit that is an allocation refused; with
    none it stays a bug (None: the internal error)."""
    said = in_a_child(lambda: _said_of_a_silent_failure(64 << 30))
    assert said == (
        "out of memory (the address space is limited to 65536 MB: ulimit -v): a library failed "
        "without saying why, as when an allocation is refused (error return without exception set)"
    )
    if resource.getrlimit(resource.RLIMIT_AS)[1] == resource.RLIM_INFINITY:
        unlimited = resource.RLIM_INFINITY
        assert in_a_child(lambda: _said_of_a_silent_failure(unlimited)) is None
    assert out_of_memory(SystemError("another bug")) is None


# --- a reader that stops early ------------------------------------------------------------


def test_a_reader_that_stops_early_ends_the_run_quietly_with_141():
    """`pendcli lecornu zeros --count 100000 -f csv | head -1`: quiet, status 141, as the
    README says (it said one line and exit 2, which the code never did)."""
    proc = subprocess.Popen(
        [*PENDCLI, "lecornu", "zeros", "--count", "100000", "-f", "csv"],
        env=limited_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    assert proc.stdout is not None and proc.stderr is not None
    assert proc.stdout.readline() == b"k,zero\n"
    proc.stdout.close()  # head -1 exits
    err = proc.stderr.read()
    proc.stderr.close()
    assert proc.wait(timeout=120) == 128 + signal.SIGPIPE
    assert err == b""
    said = " ".join(README.read_text(encoding="utf-8").split())
    assert "`pendcli reproduce | head -1`) is no error" in said
    assert "quietly with status 141" in said and "broken stdout" not in said


def test_a_reader_of_standard_error_that_stops_early_costs_no_output():
    """`pendcli lecornu zeros 2>&1 >zeros.txt | head -0`: the status line has no reader; the
    run goes on without it (rich's answer was exit 1, standard output sent to /dev/null)."""
    read, write = os.pipe()
    os.close(read)
    proc = subprocess.run(
        [*PENDCLI, "lecornu", "zeros", "--count", "5"],
        env=limited_env(),
        stdout=subprocess.PIPE,
        stderr=write,
        timeout=120,
    )
    os.close(write)
    assert proc.returncode == 0
    assert proc.stdout.count(b"\n") >= 5 and b"17.95982" in proc.stdout


# Out of memory with every import refused: the line must not need a module not yet loaded
# (reading /proc/self/limits as text imported its codec, and at the limit that import failed
# in turn, a traceback instead of the line).
NO_IMPORT = """
import resource, sys
resource.setrlimit(resource.RLIMIT_AS, (2048 << 20, resource.RLIM_INFINITY))
from pendcli.base.errors import out_of_memory

class NoMemory:
    def find_spec(self, name, path, target=None):
        raise MemoryError(f"importing {name}")

sys.meta_path.insert(0, NoMemory())
print(out_of_memory(MemoryError()))
"""


def test_the_out_of_memory_line_imports_nothing_more():
    done = subprocess.run(
        [sys.executable, "-c", NO_IMPORT], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout == (
        "out of memory (the address space is limited to 2048 MB: ulimit -v): an allocation failed\n"
    )
