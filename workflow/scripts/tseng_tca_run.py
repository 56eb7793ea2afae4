"""Seed 000 ch. 5 (tseng_tca): run the TCA replication and write its tables (Snakemake script).

The Examples' design and assembly data are read from data/published (params_000_*.csv); the
numerics are in gearrep.replications.tseng_tca.run."""

import time

import replication_io
from gearrep import published
from gearrep.replications import tseng_tca

smk = snakemake  # noqa: F821  (provided by Snakemake)

params = dict(smk.params.settings)
pub_params = published.load(smk.config["published_dir"]).params
params["cases"] = tseng_tca.cases_from_published(pub_params)
params.update(tseng_tca.ellipse_data_from_published(pub_params))
t0 = time.perf_counter()
tables = tseng_tca.run(params)
replication_io.write_tables(tables, smk.output, smk.log[0], "tseng_tca.run", time.perf_counter() - t0)
