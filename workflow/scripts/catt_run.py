"""Seed 004 (CATT gears, Ma et al. 2021): run the replication and write its tables to results/catt/.

All numerics are in gearrep.replications.catt.run; this script reads the config section `catt:`
and the design data of data/published/params_004_examples.csv, and writes one CSV per table."""

import time

import pandas as pd

import replication_io
from gearrep import published
from gearrep.replications import catt

smk = snakemake  # noqa: F821  (provided by Snakemake)

pub = published.load(smk.config["published_dir"])
params = dict(smk.params.catt)
params.update(catt.common_from_published(pub.params))
params["designs"] = catt.designs_from_published(pub.params)
t0 = time.perf_counter()
tables = catt.run(params)
elapsed = time.perf_counter() - t0
tables["run_info"] = pd.DataFrame([{"table": "all", "run_seconds": elapsed, "n_designs": len(params["designs"]),
                                    "n_cycle_rows": len(tables["cycle"])}])
replication_io.write_tables(tables, smk.output, smk.log[0], "catt.run", elapsed)
