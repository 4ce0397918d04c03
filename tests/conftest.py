"""Shared test settings: a pinned console width so rendered tables are stable."""

import os

os.environ.setdefault("COLUMNS", "160")
os.environ["NO_COLOR"] = "1"

# No wall-clock limit in any test: every hypothesis test, in any file, runs without a
# deadline; its work is bounded by example counts, so a loaded machine is slower, never red.
from hypothesis import settings

settings.register_profile("pendcli", deadline=None)
settings.load_profile("pendcli")


# The result cache (pendcli/base/cache.py) is off in every test and every process a test
# starts: no test is served a result stored outside it (the user's ~/.cache/pendcli), nor one
# an earlier test stored, which would make a test of determinism, of the forked workers or of
# an interrupt compare a computation with a copy of itself. tests/base/test_cache.py gives each of
# its tests a folder of its own; the tests of an output's form share one (shared_result_cache).
os.environ["PENDCLI_CACHE"] = "off"

# The collector runs every 50,000 allocations, not every 700: each test process keeps sympy's,
# mpmath's and the tables' objects for the whole run, and the default thresholds had the
# collector walk them about 1,500 times in tests/papers/lecornu and tests/data (1.1 s of their
# 18 s of CPU; 0.35 s so). Only this process: a child a test starts keeps Python's defaults.
import gc  # noqa: E402

gc.set_threshold(50_000, 20, 20)

from collections import defaultdict  # noqa: E402
from fnmatch import fnmatchcase  # noqa: E402
from functools import cache  # noqa: E402

import pytest  # noqa: E402
from helpers import suite_split  # noqa: E402

# Per-test wall and CPU seconds (--timings-file), read by tests/helpers/durations.py (the 2 s rule).
from helpers.timing import (  # noqa: E402, F401
    pytest_addoption,
    pytest_collection_finish,
    pytest_runtest_call,
    pytest_runtest_setup,
    pytest_runtest_teardown,
)

# The slow families: `make test` runs the rest, `make test-slow` these, CI both. A
# test is in a family when its id without parameters (file::function) matches a pattern, or
# when it asks for a fixture named below; each says why it cannot be fast. Whatever the
# families miss, `make test-durations` lists (a test not marked slow over 2 s).
SLOW_FAMILIES = {
    "tests/verify/test_derivation_store.py::test_float64_decides_only_as_*": "every stored item "
    "judged by the exact engine too",
    "tests/verify/test_derivation_store.py::test_a_run_says_once_*": "Tisserand's ledger derived "
    "afresh, in a process",
    "*::test_*check_update*": "a `check --update` in a process, computing every table or "
    "served the run's shared computation of them",
    "tests/run/test_regression.py::test_check_passes_untouched_and_fails_tampered": "two checks",
    "tests/run/test_reproduce_steps.py::*": "Tisserand's claims and ledger judged whole",
    "tests/run/test_regression.py::test_check_fails_naming_the_row_whose_*": "Tisserand's ledger "
    "derived once for two checks",
    "tests/papers/lecornu/test_prose_lecornu_from_line_462.py::test_the_reference_of_*": "the "
    "table after (26), sympy",
    "tests/papers/lecornu/test_prose_scales.py::test_the_engine_judges_*": "four inequalities "
    "judged, sympy",
    "tests/run/test_determinism.py::*": "regenerates everything in a fresh process",
    "tests/output/test_reader_scan.py::test_the_pages_of_a_whole_report_*": "a whole report",
    "tests/output/test_terminal_fit.py::*": "each command's whole output at two widths",
    "tests/output/test_terminal_render.py::test_render_*": "each command's whole output at three "
    "widths",
    "tests/output/test_summary.py::test_reproduce_fits_80_columns_*": "a whole reproduce's view, "
    "served the run's one computation of every table",
    "tests/output/test_summary.py::test_only_failing_*": "a reproduce of a paper, served the "
    "run's one computation of every table",
    "tests/cli/test_cli.py::test_ascii_only_locale": "each command in a fresh process",
    "tests/cli/test_cli.py::test_file_size_limit_names_the_plot_*": "a figure drawn in a process",
    "tests/output/test_report.py::test_report_of_one_paper_*": "a report's figures in forked "
    "workers",
    "tests/papers/charbonnier/test_charbonnier.py::test_formulas_figure_*": "every formula row's "
    "figure",
    "tests/attacks/test_fuzz.py::test_formulas_plot_folder": "each example draws and writes a "
    "figure",
    "tests/attacks/test_fuzz.py::test_plot_paths": "each example draws and writes a figure",
    "tests/papers/tisserand/test_tisserand.py::test_figures_written": "draws and writes the "
    "paper's figures",
    "tests/output/test_json_schema.py::test_reproduce_*json_*": "a whole reproduce -f json",
    "tests/output/test_summary.py::test_equations_command_*": "every Charbonnier check, via the "
    "CLI",
    "tests/output/html/test_html_report.py::test_pdf_printing_*": "whole reports, before Chromium "
    "is sought",
    "tests/papers/tisserand/test_tisserand.py::test_quadrature_against_mpmath_elsewhere": "mpmath "
    "at 25 digits",
    "tests/papers/tisserand/test_tisserand.py::test_series_error_figure_against_mpmath": "mpmath "
    "at 25 digits",
    "tests/papers/tisserand/test_tisserand_extremes.py::test_near_planar_fourier_*": "mpmath at 25 "
    "digits",
    "tests/papers/lecornu/test_lecornu_extremes.py::test_largest_count_correctly_rounded": "mpmath "
    "zeros",
    "tests/papers/charbonnier/test_charbonnier_extremes.py::test_quad_domain_is_measured": "a grid "
    "of quadratures",
    "tests/verify/test_formulas.py::test_lecornu_reference_second_method_radau": "an implicit ODE",
    "tests/output/test_summary.py::test_ledger_parts_*": "the whole ledger, in two processes",
    "tests/papers/tisserand/test_equations_tisserand.py::test_resals_rate_*": "two ODE "
    "integrations of the apsidal motion and the series of the motion to fifth order",
    "tests/base/test_cache.py::test_a_changed_ledger_is_recomputed_not_served_stale": "two cold "
    "`equations` runs of a ledger in one test (2.1-2.3 s)",
    "tests/attacks/test_attack_edition.py::test_reproduce_out_of_tables_full_of_markup": "a whole "
    "`reproduce --out` of one paper, its ledger checked, in a process (10 s of CPU)",
    "tests/attacks/test_attack_misc.py::test_reproduce_out_at_the_limit_of_open_files": "a report "
    "with its figures, in a process (4 s of CPU)",
    "tests/attacks/test_attack_misc.py::test_scipy_zeros_are_written_a_chunk_at_a_time": "400,000 "
    "zeros by scipy and a baseline run, in two processes (2.2 s of CPU)",
    "tests/output/test_equation_fields.py::"
    "test_every_json_row_carries_the_engines_verdict": "every paper's whole ledger, served the "
    "run's one computation of every table (10 s of CPU, paid by the first test to ask)",
    "tests/attacks/test_fuzz.py::test_check_never_tracebacks": "whole `check` runs in this "
    "process, served the run's one computation of every table and of the derivations (30 s "
    "of CPU, paid by the first test to ask)",
    "tests/verify/test_engine_mutations.py::test_the_correct_engine_*": "54 sampled ledger rows "
    "judged as committed and with 123 data mutations (15 s of CPU with their references)",
    "tests/verify/test_engine_mutations.py::test_an_engine_mutation_is_caught_by_many_rows": "one "
    "engine mutation judged over the sampled rows it applies to (up to 1.6 s of CPU each)",
    "tests/attacks/test_attack_signals.py::test_a_worker_killed_stops_the_run_*": "a cold "
    "`equations` in two processes, until its worker computes",
    "tests/attacks/test_attack_signals.py::test_a_stop_while_a_worker_computes_*": "a cold "
    "`equations` in two processes, until its worker computes",
}
# Single cases of a parametrized test (its id without parameters, then a part of the
# parameters' id): the heavy rows of a family whose other rows are fast.
LEDGER_STATUS = "tests/data/test_ledger.py::test_the_engine_computes_the_recorded_status"
SLOW_CASES = {
    # of the two edits of lines 448-460, the logarithm's coefficient costs 2.6 s alone; the
    # other, 0.8 s alone, is the family's fast case
    ("tests/papers/lecornu/test_printed_lecornu_finite_and_conical.py::"
     "test_a_changed_growing_part_is_refused",
     "1/4*log(x)"): "the small-x residual's growing parts with a changed logarithm (2.6 s)",
    (LEDGER_STATUS, "lecornu.result.am_series]"): "the amplitude series' reference, its "
     "integrals with the scale in their limits judged by sympy's series (2.5 s)",
    ("tests/output/html/test_html_report.py::"
     "test_each_mark_is_what_its_row_prints_and_lies_within_its_lines",
     "lecornu"): "every Lecornu row and claim matched to its place in 1,135 lines of text",
}  # fmt: skip
SLOW_FIXTURES = {
    "charbonnier_report": "reproduces Charbonnier with its ledger and writes the whole report",
    "example_exact": "Tisserand's example solved exactly twice, by quadrature and by ODE",
    "lecornu_across_g": "Lecornu's claims evaluated, each judged across the range of g",
    "edition_pages": "the three papers' pages built whole, every formula as MathML",
    "computed_tables": "every table computed, once for the run (shared by the workers)",
}
# The long families of like cases: one case per committed ledger row, or one edit of
# the ledger that must be refused. `make test-slow` (and CI) runs every case; `make test` keeps
# the cases of rank 0, n, 2n, ... (n below) in the order of the parameters, among those not slow
# already: the first case always, and the rest spread over the list (a ledger's rows run in
# the order of the paper's lines, so its fast cases span the paper). tests/suite/test_suite_split.py
# checks that each family keeps a fast case and leaves the rest to the slow run.
REPRESENTATIVES = {
    LEDGER_STATUS: 6,
    "tests/data/test_printed.py::test_a_changed_coefficient_stops_a_row_holding": 3,
    "tests/papers/charbonnier/test_printed_charbonnier.py::"
    "test_a_changed_coefficient_stops_a_row_holding": 4,
    "tests/papers/charbonnier/test_printed_charbonnier.py::"
    "test_a_changed_coefficient_stops_a_prose_row_*": 4,
    "tests/papers/charbonnier/test_printed_charbonnier.py::"
    "test_a_misprint_whose_printed_form_is_its_reading_*": 2,
    "tests/papers/charbonnier/test_printed_charbonnier.py::"
    "test_every_misprint_printed_as_its_reading_is_refused": 3,
    "tests/papers/charbonnier/test_printed_charbonnier.py::"
    "test_a_changed_coefficient_of_a_reading_is_refused": 3,
    "tests/papers/lecornu/test_printed_lecornu_small_oscillations.py::"
    "test_a_changed_coefficient_is_refused": 3,
    "tests/papers/lecornu/test_printed_lecornu_small_oscillations.py::"
    "test_a_misprint_printed_as_its_reading_is_refused": 2,
    "tests/papers/lecornu/test_printed_lecornu_small_oscillations.py::test_to_line_420_*": 2,
    "tests/papers/lecornu/test_printed_lecornu_finite_and_conical.py::"
    "test_a_changed_coefficient_*": 4,
    "tests/papers/lecornu/test_printed_lecornu_finite_and_conical.py::"
    "test_a_misprint_whose_printed_form_is_its_reading_*": 3,
    "tests/verify/test_printed_numeric.py::"
    "test_an_edit_of_the_printed_form_is_refused_naming_the_row": 3,
    "tests/verify/test_printed_numeric.py::test_one_printed_digit_changed_in_a_holds_row_*": 2,
    "tests/papers/tisserand/test_printed_tisserand.py::test_one_changed_coefficient_is_refused": 4,
    "tests/papers/tisserand/test_printed_tisserand.py::"
    "test_a_changed_coefficient_of_a_citing_sentence_*": 3,
    # the fault families: each case edits or damages a copy of tables/ and runs a command
    "tests/attacks/test_faults.py::test_a_cut_or_damaged_committed_table_is_a_named_error": 2,
    "tests/attacks/test_faults.py::test_renamed_id_through_the_cli_is_one_line_exit_2": 2,
    "tests/attacks/test_attack_signals.py::test_a_set_interrupted_is_all_old_or_all_new": 2,
}


@pytest.fixture
def tables(tmp_path, monkeypatch):  # type: ignore[no-untyped-def]
    """A copy of the committed tables/, in use through $PENDCLI_TABLES: the attack suites edit
    it (the committed tables stay untouched); the table cache is cleared around the test."""
    import shutil
    from pathlib import Path

    from pendcli.data.tables import clear_table_cache

    copy = tmp_path / "tables"
    committed = Path(__file__).resolve().parent.parent / "tables"
    # the files' bytes and modes (shutil.copy), not their times and attributes (copy2): half
    # the copy's CPU, and nothing reads a table's times
    shutil.copytree(committed, copy, ignore=shutil.ignore_patterns(".*"), copy_function=shutil.copy)
    monkeypatch.setenv("PENDCLI_TABLES", str(copy))
    clear_table_cache()
    yield copy
    clear_table_cache()


@pytest.fixture(scope="session")
def shared_result_cache(tmp_path_factory: pytest.TempPathFactory) -> str:
    """A result cache folder shared by the tests of an output's form (its schema, filters,
    layout), which set PENDCLI_CACHE to it: a paper's ledger is then computed once per
    worker, not once per such test. A warm run prints the cold run's bytes in every format
    (tests/base/test_cache.py); no test of a computation uses it."""
    return str(tmp_path_factory.mktemp("shared-result-cache"))


@pytest.fixture
def shared_claims(monkeypatch: pytest.MonkeyPatch) -> None:
    """For the tests of a command's output form (its shape, formats, one-line errors): the
    registry's ``claim_rows`` serves the committed tables' claims computed once per process
    (tests/helpers/evaluated.py), so the command runs whole but does not compute its paper's claims
    again for each such test. No test of a computation uses it."""
    from helpers.evaluated import committed_claims

    from pendcli.papers import registry

    monkeypatch.setattr(registry, "claim_rows", lambda key: list(committed_claims(key)))


def _worker() -> str:
    """This xdist worker's name ("master" without xdist): from xdist's variable, not its
    ``worker_id`` fixture, which a run with ``-p no:xdist`` (the 2 s rule's reruns) lacks."""
    return os.environ.get("PYTEST_XDIST_WORKER", "master")


@pytest.fixture
def reproduce_computed_once(
    monkeypatch: pytest.MonkeyPatch, tmp_path_factory: pytest.TempPathFactory
) -> None:
    """For the tests of a command's output form that run it several times (at several widths,
    in several formats): ``reproduce_all`` and ``derivation_drift`` (each paper's stored
    derivations derived again) answer from the run's one computation of every table and of
    the derivations (tests/helpers/regenerated.py, shared by the workers) where asked for
    that, of the committed tables; any other call is computed once in the test and served
    again. So `check`, which never reads the result cache, does not compute every table and
    derivation again for each form. No test of a computation uses it."""
    from helpers.regenerated import serve_shared, shared_root

    serve_shared(monkeypatch, shared_root(tmp_path_factory, _worker()))


@pytest.fixture(scope="session", autouse=True)
def shared_computations_started(  # type: ignore[no-untyped-def]
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
):
    """The run's shared computations its selected tests will read (tests/helpers/regenerated.py)
    started in the background at the first test, so no worker waits idle for one; waited
    for at the end. Nothing is started for a run that reads none (make test)."""
    from helpers.regenerated import shared_root, start_early, wait_started

    start_early(request.session.items, shared_root(tmp_path_factory, _worker()))
    yield
    wait_started()


@pytest.fixture(scope="session")
def computed_tables(tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    """The file holding every table's computation from the committed tables, done once per
    run for all workers (tests/helpers/regenerated.py): for the tests of what `check` does
    with it (write, compare), not of the computation."""
    from helpers.regenerated import computed_once, shared_root

    return computed_once(shared_root(tmp_path_factory, _worker()))


@pytest.fixture(scope="session", autouse=True)
def _committed_rows_shared_by_the_workers(tmp_path_factory: pytest.TempPathFactory) -> None:
    """The committed tables' claims and formula checks (tests/helpers/evaluated.py) computed
    by one worker of the run for all: Lecornu's alone cost 0.6 s and 0.6-2.5 s a computation."""
    from helpers.evaluated import share_across_workers
    from helpers.regenerated import shared_root

    share_across_workers(shared_root(tmp_path_factory, _worker()))


@pytest.hookimpl(tryfirst=True)  # before -m deselects by marker
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    members: dict[str, list[pytest.Item]] = defaultdict(list)
    for item in items:
        family, _, params = item.nodeid.partition("[")
        slow_family, cases, representative = _family(family)
        reasons = list(slow_family)
        reasons += [why for part, why in cases if part in params]
        names = getattr(item, "fixturenames", ())
        reasons += [why for name, why in SLOW_FIXTURES.items() if name in names]
        if reasons:
            _mark_slow(item, reasons[0])
        for pattern in representative:
            members[pattern].append(item)
    split = dict.fromkeys(REPRESENTATIVES, (0, 0))
    for pattern, family_items in members.items():
        # the rank among the family's cases that are not slow already, in parameter order
        # (callspec indices), whatever order the items came in: each xdist worker marks alike
        fast = [i for i in family_items if i.get_closest_marker("slow") is None]
        fast.sort(key=lambda i: (i.nodeid.partition("[")[0], _param_indices(i)))
        stride = REPRESENTATIVES[pattern]
        for rank, item in enumerate(fast):
            if rank % stride:
                _mark_slow(item, "a case of a long family past its fast representatives")
        split[pattern] = (-(-len(fast) // stride), len(family_items))
    config.stash[suite_split.FAMILY_SPLIT] = split
    config.stash[suite_split.COLLECTED] = [item.nodeid for item in items]


@cache  # asked once per family (file::function), not once per case: 5,000 items, 1,100 families
def _family(
    family: str,
) -> tuple[tuple[str, ...], tuple[tuple[str, str], ...], tuple[str, ...]]:
    """The family's reasons to be slow by its id, its slow cases (a part of the parameters'
    id, why) and the REPRESENTATIVES patterns it matches."""
    reasons = tuple(why for pattern, why in SLOW_FAMILIES.items() if fnmatchcase(family, pattern))
    cases = tuple((part, why) for (test, part), why in SLOW_CASES.items() if test == family)
    representative = tuple(p for p in REPRESENTATIVES if fnmatchcase(family, p))
    return reasons, cases, representative


def _param_indices(item: pytest.Item) -> tuple[int, ...]:
    callspec = getattr(item, "callspec", None)
    return tuple(callspec.indices.values()) if callspec is not None else ()


def _mark_slow(item: pytest.Item, reason: str) -> None:
    if item.get_closest_marker("slow") is None:
        item.add_marker(pytest.mark.slow(reason=reason))


def pytest_sessionfinish(session: pytest.Session) -> None:
    """The syntax trees parsed once per process (helpers/sources.py) let go before pytest's
    last full collections, which would walk their million nodes (1.4 s each, profiled)."""
    from helpers.sources import parsed, walked

    walked.cache_clear()
    parsed.cache_clear()


@pytest.hookimpl(tryfirst=True)
def pytest_runtestloop() -> None:
    """What start-up and collection made (the modules of sympy, scipy, matplotlib and of the
    tests, the collected items) lives as long as the process: frozen out of the collector's
    reach, so no full collection during the tests, nor pytest's last one, walks it again."""
    gc.collect()
    gc.freeze()
