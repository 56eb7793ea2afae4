"""Seed 003 (thesis): run the replication and write its tables to results/thesis/ (Snakemake script).

All numerics are in gearrep.replications.thesis.run; this script takes the `thesis:` config section (rule params) and
writes CSV files (one per table returned by run)."""

import time

import replication_io
from gearrep.replications import thesis

smk = snakemake  # noqa: F821  (provided by Snakemake)

params = dict(smk.params.thesis)
t0 = time.perf_counter()
tables = thesis.run(params)
replication_io.write_tables(tables, smk.output, smk.log[0], "thesis.run", time.perf_counter() - t0)
