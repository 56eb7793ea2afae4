"""Seed 004 (CATT gears): check records for every claim of claims_004.csv, and the verdict of each
claim for each flank pair and reading of phi1 (Snakemake script)."""

from pathlib import Path

import pandas as pd

from gearrep import checks, published
from gearrep.replications import catt

smk = snakemake  # noqa: F821  (provided by Snakemake)

tables = {Path(f).stem: pd.read_csv(f) for f in smk.input.tables}
pub = published.load(smk.config["published_dir"])
verdicts = catt.claim_verdicts(tables)
records = checks.validate_checks(catt.checks(tables, pub, verdicts=verdicts))
Path(smk.output.checks).parent.mkdir(parents=True, exist_ok=True)
records.to_csv(smk.output.checks, index=False)
verdicts.to_csv(smk.output.readings, index=False)
Path(smk.log[0]).write_text(f"{len(records)} check records: {records['status'].value_counts().to_dict()}\n")
