"""Seed 002 (NASA report): check records against the published numbers (Snakemake script)."""

from pathlib import Path

import pandas as pd

from gearrep import checks, published
from gearrep.replications import nasa

smk = snakemake  # noqa: F821  (provided by Snakemake)

tables = {Path(f).stem: pd.read_csv(f) for f in smk.input.tables}
pub = published.load(smk.config["published_dir"])
records = checks.validate_checks(nasa.checks(tables, pub))
Path(smk.output[0]).parent.mkdir(parents=True, exist_ok=True)
records.to_csv(smk.output[0], index=False)
Path(smk.log[0]).write_text(f"{len(records)} check records: {records['status'].value_counts().to_dict()}\n")
