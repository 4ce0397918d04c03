# Every target works on a fresh clone with nothing but Python 3.11+: the venv's pip fetches uv
# (a fast installer), and uv installs the exact versions of the lock files.
#   requirements.lock      what pendcli runs with (make reproduce, check, regen, bench)
#   requirements-dev.lock  the same plus the test and lint tools (make install, test, lint)
# The committed tables were regenerated with these versions; `make lock` resolves anew.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
UV := $(BIN)/uv
UV_VERSION := 0.13.9
RUNTIME := $(VENV)/.runtime
STAMP := $(VENV)/.installed
OUT ?= out
# One resolution for Python 3.11 to 3.14 where it can (fewest versions): the tables then do
# not depend on which Python made the venv.
LOCK_FLAGS := --universal --fork-strategy fewest --python-version 3.11 --generate-hashes -q

.PHONY: help install reproduce test test-slow test-all test-durations test-browser check regen lint bench lock api clean

install: $(STAMP)

$(UV):
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check uv==$(UV_VERSION)

# Reinstall only when a lock or pyproject.toml changes (or the venv is missing).
$(RUNTIME): requirements.lock pyproject.toml | $(UV)
	$(UV) pip install --quiet --python $(BIN)/python -r requirements.lock
	$(UV) pip install --quiet --python $(BIN)/python --no-deps -e .
	@touch $(RUNTIME)

$(STAMP): requirements-dev.lock $(RUNTIME)
	$(UV) pip install --quiet --python $(BIN)/python -r requirements-dev.lock
	@touch $(STAMP)

# Resolve anew (newest versions within pyproject.toml's bounds), then `make regen` and review
# the tables' diff: a new numpy, scipy or mpmath may move the last digits.
lock: | $(UV)
	$(UV) pip compile pyproject.toml --extra test $(LOCK_FLAGS) --upgrade -o requirements-dev.lock
	$(UV) pip compile pyproject.toml $(LOCK_FLAGS) -c requirements-dev.lock -o requirements.lock

reproduce: $(RUNTIME)
	$(BIN)/pendcli reproduce --out $(OUT) --format json > /dev/null

# Two workers (this project's machines have 2 cores); tests use tmp_path, never shared paths.
# PENDCLI_JOBS=1: with both cores busy running tests, reproduce's own forks only add work
# (tests/output/test_report.py runs the forked paths explicitly). Bytecode is kept in .venv/pycache:
# where PYTHONDONTWRITEBYTECODE is set, each worker and each CLI subprocess a test starts would
# otherwise compile sympy, scipy, matplotlib and the tests from source again (3x the CPU).
PYTEST := env -u PYTHONDONTWRITEBYTECODE PYTHONPYCACHEPREFIX=$(abspath $(VENV))/pycache \
	PENDCLI_JOBS=1 $(BIN)/python -m pytest -q
XDIST := -n 2 --dist worksteal
TIMINGS := $(abspath $(VENV))/test-timings.jsonl

# The fast suite: every test but those marked slow (tests/conftest.py names the slow families
# and why) and the browser test. Each test's CPU and wall seconds go to $(TIMINGS).
test: $(STAMP)
	rm -f $(TIMINGS)
	$(PYTEST) $(XDIST) -m "not slow and not browser" --timings-file $(TIMINGS)

# The 2 s rule, from the last `make test`'s timings (run first if there are none): lists the
# tests not marked slow over 2 s of CPU, exit 1 if any. No limit is put inside a test. CPU
# seconds grow on a crowded machine (1.5-3x at a load of 10 on 2 cores), and under xdist the
# first test to use a shared cache pays for it: so each test over the limit is rerun alone,
# RECHECK times, after its file's cheapest other test, and is over only if over every time
# (tests/helpers/durations.py --recheck).
DURATION_LIMIT ?= 2
RECHECK ?= 2
test-durations: $(STAMP)
	@test -f $(TIMINGS) || $(MAKE) test
	env -u PYTHONDONTWRITEBYTECODE PYTHONPYCACHEPREFIX=$(abspath $(VENV))/pycache \
	  $(BIN)/python tests/helpers/durations.py $(TIMINGS) --limit $(DURATION_LIMIT) --recheck $(RECHECK)

# Only the slow tests: whole regenerations, real processes stopped by signals, mpmath references.
# Each test's CPU and wall seconds go to $(SLOW_TIMINGS) (tests/helpers/durations.py --slow
# lists where the run spends).
SLOW_TIMINGS := $(abspath $(VENV))/test-slow-timings.jsonl
test-slow: $(STAMP)
	rm -f $(SLOW_TIMINGS)
	$(PYTEST) $(XDIST) -m "slow and not browser" --timings-file $(SLOW_TIMINGS)

# Everything: the fast and the slow tests in one run (one collection per worker, and each
# reference a worker builds serves the fast and the slow cases that cite it), then the
# browser test. Its timings feed `make test-durations` as `make test`'s do (slow ones exempt).
test-all: $(STAMP)
	rm -f $(TIMINGS)
	$(PYTEST) $(XDIST) -m "not browser" --timings-file $(TIMINGS)
	$(MAKE) test-browser

# The HTML report in headless Chromium (Debian package chromium); skipped where it is absent.
# Only its file is collected (collecting and deselecting the whole suite's 5,000 tests cost 2 s
# of CPU and 5-10 s of wall time, of 18-20 s CPU in all).
BROWSER_TESTS := tests/output/html/test_browser.py
test-browser: $(STAMP)
	$(PYTEST) -m browser $(BROWSER_TESTS)

check: $(RUNTIME)
	$(BIN)/pendcli check
	$(BIN)/python -m tools.docs --check

# One process, one run: the regenerated tables and the README's sections written as one set
# (pendcli.base.files.write_set), so an interrupt leaves all old or all new.
regen: $(RUNTIME)
	$(BIN)/python -m tools.docs --tables

lint: $(STAMP)
	$(BIN)/ruff check pendcli tools tests
	$(BIN)/ruff format --check pendcli tools tests
	$(BIN)/mypy pendcli tools

bench: $(STAMP)
	$(BIN)/python -m tools.bench --write docs/benchmarks.md --summary docs/install.md

# The API page (docs/api/pendcli.html): pdoc over the names `import pendcli` offers. They load
# lazily, so they are fetched first (pdoc reads the module's __dict__).
api: $(STAMP)
	$(UV) pip install --quiet --python $(BIN)/python -e '.[docs]'
	$(BIN)/python -c "import pathlib, pdoc, pdoc.render, pendcli; \
	  [getattr(pendcli, n) for n in pendcli.__all__ if n != '__version__']; \
	  pdoc.render.configure(search=False, show_source=False); \
	  pdoc.pdoc('pendcli', 'pendcli.api', output_directory=pathlib.Path('docs/api'))"

clean:
	rm -rf $(OUT) .pytest_cache build *.egg-info

help:
	@echo "make install         the venv from the lock files"
	@echo "make reproduce       every table and figure into out/ (OUT=...)"
	@echo "make test            the fast suite: all but the slow and the browser tests"
	@echo "make test-slow       only the slow tests (families named in tests/conftest.py)"
	@echo "make test-browser    the HTML report in headless Chromium (skipped without it)"
	@echo "make test-all        the fast and the slow tests, then the browser test"
	@echo "make test-durations  tests not marked slow over 2 s of CPU in the last make test"
	@echo "make check | regen | lint | bench | lock | api | clean"
