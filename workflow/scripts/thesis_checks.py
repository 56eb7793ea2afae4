"""Seed 003 (thesis): check records against the published numbers (Snakemake script)."""

import replication_io
from gearrep import published
from gearrep.replications import thesis

smk = snakemake  # noqa: F821  (provided by Snakemake)

tables = replication_io.read_tables(smk.input.tables)
pub = published.load(smk.config["published_dir"])
replication_io.write_checks(thesis.checks(tables, pub), smk.output[0], smk.log[0])
