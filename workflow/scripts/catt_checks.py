"""Seed 004 (CATT gears): check records for every claim of claims_004.csv, and the verdict of each
claim for each flank pair and reading of phi1 (Snakemake script)."""

import replication_io
from gearrep import published
from gearrep.replications import catt

smk = snakemake  # noqa: F821  (provided by Snakemake)

tables = replication_io.read_tables(smk.input.tables)
pub = published.load(smk.config["published_dir"])
verdicts = catt.claim_verdicts(tables)
replication_io.write_checks(catt.checks(tables, pub, verdicts=verdicts), smk.output.checks, smk.log[0])
verdicts.to_csv(smk.output.readings, index=False)
