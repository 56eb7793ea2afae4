"""Seed 000 ch. 5 (tseng_tca): check records against the published numbers (Snakemake script)."""

import replication_io
from gearrep import published
from gearrep.replications import tseng_tca

smk = snakemake  # noqa: F821  (provided by Snakemake)

tables = replication_io.read_tables(smk.input.tables)
pub = published.load(smk.config["published_dir"])
replication_io.write_checks(tseng_tca.checks(tables, pub), smk.output[0], smk.log[0])
