# The two commands of the README: `make reproduce` and `make test`.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
CORES  ?= 2
export PATH := $(abspath $(BIN)):$(PATH)
export MPLBACKEND := Agg

.PHONY: setup reproduce test test-all stress bench screenshot clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[test]'
	touch $(STAMP)

setup: $(STAMP)

reproduce: $(STAMP)
	$(BIN)/snakemake --cores $(CORES)

test: $(STAMP)
	$(BIN)/python -m pytest

test-all: $(STAMP)
	$(BIN)/python -m pytest -m ''

# Numerical stress suite, full version (the default `make test` runs its fast subset).
stress: $(STAMP)
	$(BIN)/python -m pytest -m stress tests/stress

# Run time against error and throughput (results/bench/).
bench: $(STAMP)
	$(BIN)/snakemake --cores $(CORES) bench

# Screenshot of the report in headless Chromium (needs the Debian package `chromium`).
screenshot: $(STAMP)
	$(BIN)/snakemake --cores $(CORES) results/report.png

clean:
	rm -rf results .snakemake
