"""Seed 000 ch. 4: check records for every value of Tables 4.3/4.4 and the chapter-4 claims
(Snakemake script)."""

import replication_io
from gearrep import published
from gearrep.replications import tseng_curvature as tc

smk = snakemake  # noqa: F821  (provided by Snakemake)

tables = replication_io.read_tables(smk.input.tables)
pub = published.load(smk.config["published_dir"])
replication_io.write_checks(tc.checks(tables, pub), smk.output[0], smk.log[0])
