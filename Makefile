# The two commands of the README: `make reproduce` and `make test`.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
CORES  ?= 2
export MPLBACKEND := Agg

# The pinned environment: exact versions and hashes of every dependency (core + test + docs extras)
# and of the build backend that installs gearrep itself (setuptools, wheel).
LOCK   := requirements.lock
# the tool that writes it (installed only into a throwaway venv by `make lock`)
PIP_TOOLS := pip-tools==7.6.2
# the Python the lock is made for (the project's target version)
LOCK_PYTHON ?= python3.11
PIP    := $(BIN)/python -m pip install --quiet --disable-pip-version-check

.PHONY: setup bytecode reproduce test docs test-all test-portability test-cluster lint format schema stress bench screenshot clean lock

$(STAMP): $(LOCK) pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(PIP) --require-hashes -r $(LOCK)
	$(PIP) --no-deps --no-build-isolation -e .
	touch $(STAMP)

# Regenerate the lock from pyproject.toml for $(LOCK_PYTHON) (the target version), with pip-tools
# in a throwaway venv. Pins already in the lock are kept where pyproject.toml still allows them;
# `make lock UPGRADE=1` moves every package to the newest version allowed.
lock:
	set -e; tmp=$$(mktemp -d); trap 'rm -rf "$$tmp"' EXIT; \
	$(LOCK_PYTHON) -m venv "$$tmp/venv"; \
	"$$tmp/venv/bin/python" -m pip install --quiet --disable-pip-version-check $(PIP_TOOLS); \
	"$$tmp/venv/bin/pip-compile" --quiet --generate-hashes --allow-unsafe --strip-extras \
	    --extra test --extra docs --build-deps-for editable --no-emit-index-url --no-emit-find-links $(if $(UPGRADE),--upgrade) \
	    --output-file $(LOCK) pyproject.toml

setup: $(STAMP)

# The bytecode of gearrep and of the workflow's scripts, written where stale (a few ms when none is).
# Python writes it lazily only where PYTHONDONTWRITEBYTECODE is unset (it is set on the CI machines):
# otherwise every process compiles them again, about 0.35 s of each Snakemake start (no-op 3.74 ->
# 3.38 s median) and of every test worker and Snakemake run of the tests.
bytecode: $(STAMP)
	$(BIN)/python -m compileall -q src workflow

reproduce: bytecode
	$(BIN)/snakemake --cores $(CORES)

test: lint bytecode
	$(BIN)/python -m pytest

# The API reference (Sphinx, numpydoc docstrings) as HTML in build/docs/html; a warning fails the
# build (tests/unit/docs/test_docs.py builds it too, so `make test` fails on one).
docs: $(STAMP)
	$(BIN)/sphinx-build -W --keep-going -q -b html docs/api build/docs/html
	@echo "API reference: build/docs/html/index.html"

# Formatting and lint (configured in pyproject.toml): checked by `make test`, applied by `make format`.
lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .
	$(BIN)/snakefmt --check Snakefile workflow/rules src/gearrep/cli/sweep.smk

format: $(STAMP)
	$(BIN)/ruff check --fix .
	$(BIN)/ruff format .
	$(BIN)/snakefmt Snakefile workflow/rules src/gearrep/cli/sweep.smk

# config/schema.json from the settings declarations (a test keeps them equal).
schema: $(STAMP)
	$(BIN)/python workflow/lib/wfconfig.py --write-schema config/schema.json

# The number-comparing tests (marker `numerics`: one code path against another, the scorecard
# against its accepted reference) run twice more, as on another machine: on design inputs moved by
# a few ulps (GEARREP_PERTURB_ULPS, see docs/validation.md) and with numpy's best SIMD group off.
test-portability: bytecode
	GEARREP_PERTURB_ULPS=4 $(BIN)/python -m pytest -m "numerics and not slow and not bench and not cluster"
	NPY_DISABLE_CPU_FEATURES="$$($(BIN)/python .ci/simd_off.py)" $(BIN)/python -m pytest -m "numerics and not slow and not bench and not cluster"

test-all: bytecode
	$(BIN)/python -m pytest -m ''

# `gearrep sweep` through Snakemake's cluster-generic executor with a local submit script (needs
# snakemake-executor-plugin-cluster-generic, a test extra; skipped with that reason without it).
test-cluster: bytecode
	$(BIN)/python -m pytest -n 0 -m cluster

# Numerical stress suite, full version (the default `make test` runs its fast subset).
stress: bytecode
	$(BIN)/python -m pytest -n 0 -m stress tests/stress

# Run time against error and throughput (results/bench/).
bench: bytecode
	$(BIN)/snakemake --cores $(CORES) bench
	CORES=$(CORES) $(BIN)/python -m gearrep.cli.bench results/bench/sweep_throughput.csv

# Screenshot of the report in headless Chromium (needs the Debian package `chromium`).
screenshot: bytecode
	$(BIN)/snakemake --cores $(CORES) results/report.png

clean:
	rm -rf results .snakemake
