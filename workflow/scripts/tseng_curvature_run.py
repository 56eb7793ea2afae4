"""Seed 000 ch. 4 (curvilinear gear, ZA hob): run gearrep.replications.tseng_curvature for the parts
named in the rule's params and write one CSV per table (Snakemake script; all numerics in the
library). Design data from data/published/params_000_*.csv, settings from the config section
`tseng_curvature:`."""

import time

import replication_io
from gearrep import published
from gearrep.replications import tseng_curvature as tc

smk = snakemake  # noqa: F821  (provided by Snakemake)

pub = published.load(smk.config["published_dir"])
params = dict(smk.params.settings)
params.update(tc.design_from_published(pub.params))
t0 = time.perf_counter()
tables = tc.run(params, parts=list(smk.params.parts))
replication_io.write_tables(tables, smk.output, smk.log[0], f"tseng_curvature.run(parts={list(smk.params.parts)})",
                            time.perf_counter() - t0, float_format="%.15g")
