# Every target works on a fresh clone with nothing but Python 3.11+.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
OUT ?= out

.PHONY: install reproduce test test-browser check regen lint bench api clean

install: $(STAMP)

# Reinstall only when pyproject.toml changes (or the venv is missing).
$(STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[test]'
	@touch $(STAMP)

reproduce: $(STAMP)
	$(BIN)/pendcli reproduce --out $(OUT) --format json > /dev/null

# Two workers (this project's machines have 2 cores); tests use tmp_path, never shared paths.
# PENDCLI_JOBS=1: with both cores busy running tests, reproduce's own forks only add work
# (tests/test_report.py runs the forked paths explicitly).
test: $(STAMP)
	PENDCLI_JOBS=1 $(BIN)/python -m pytest -q -n 2 --dist worksteal

# The HTML report in headless Chromium (Debian package chromium); skipped where it is absent.
test-browser: $(STAMP)
	$(BIN)/python -m pytest -q -m browser

check: $(STAMP)
	$(BIN)/pendcli check
	$(BIN)/python -m pendcli.docs --check

regen: $(STAMP)
	$(BIN)/pendcli check --update
	$(BIN)/python -m pendcli.docs

lint: $(STAMP)
	$(BIN)/ruff check pendcli tests
	$(BIN)/ruff format --check pendcli tests
	$(BIN)/mypy pendcli

bench: $(STAMP)
	$(BIN)/python -m pendcli.bench --write docs/benchmarks.md

# The API page (docs/api/pendcli.html): pdoc over the names `import pendcli` offers. They load
# lazily, so they are fetched first (pdoc reads the module's __dict__).
api: $(STAMP)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[docs]'
	$(BIN)/python -c "import pathlib, pdoc, pdoc.render, pendcli; \
	  [getattr(pendcli, n) for n in pendcli.__all__ if n != '__version__']; \
	  pdoc.render.configure(search=False, show_source=False); \
	  pdoc.pdoc('pendcli', 'pendcli.api', output_directory=pathlib.Path('docs/api'))"

clean:
	rm -rf $(OUT) .pytest_cache build *.egg-info
