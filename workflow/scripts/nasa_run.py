"""Seed 002 (NASA report): run the replication and write its tables to results/nasa/ (Snakemake script).

Reads the config section ``nasa`` and the design data in data/published (params_002_*, Tables
6.2.1-6.2.2 values); all numerics are in gearrep.replications.nasa.run."""

import time

import replication_io
from gearrep import published
from gearrep.replications import nasa

smk = snakemake  # noqa: F821  (provided by Snakemake)

params = dict(smk.params.settings)
params["design"] = nasa.design_from_published(published.load(smk.config["published_dir"]))
t0 = time.perf_counter()
tables = nasa.run(params)
replication_io.write_tables(tables, smk.output, smk.log[0], "nasa.run", time.perf_counter() - t0)
