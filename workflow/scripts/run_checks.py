"""Check records of a study (Snakemake script of the checks rules in workflow/rules/replications.smk):
compare every table of the study with the published values and claims of its seed, write the
checks and their extra tables."""

from pathlib import Path

import replication_io

from gearrep import published
from gearrep.replications import load

smk = snakemake  # noqa: F821  (provided by Snakemake)

with replication_io.logged(smk.log[0]):
    study = load(smk.params.study)
    tables = replication_io.read_tables(smk.input.tables)
    # exactly the published files the rule declares as inputs
    pub = published.load(Path(smk.input.published[0]).parent, smk.input.published)
    out = study.checks(tables, pub)
    missing = sorted(set(study.CHECK_OUTPUTS) - set(out))
    if missing:
        raise RuntimeError(f"{smk.params.study}.checks returned no {missing}")
    for name in study.CHECK_OUTPUTS:
        if name == "checks":
            replication_io.write_checks(out[name], smk.output[name], smk.log[0])
        else:
            replication_io.write_table(out[name], smk.output[name])
