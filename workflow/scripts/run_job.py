"""One job of a study (Snakemake script of the job rules in workflow/rules/replications.smk):
compute the job's tables from its settings and the published design data, write one CSV each.

The numerics are in ``gearrep.replications.<study>``; this script only reads and writes."""

from pathlib import Path

import replication_io

from gearrep import published
from gearrep.replications import load

smk = snakemake  # noqa: F821  (provided by Snakemake)

with replication_io.logged(smk.log[0]):
    study = load(smk.params.study)
    job = study.JOBS[smk.params.job]
    # exactly the design-data files the rule declares as inputs
    design = study.params_from_published(published.load(Path(smk.input.design[0]).parent, smk.input.design))
    seconds, tables = replication_io.timed(job.compute, dict(smk.params.settings), design)
    replication_io.write_tables(tables, list(smk.output), smk.log[0], f"{smk.params.study}.{smk.params.job}", seconds)
