"""Seed 000 ch. 4 (curvilinear gear, ZA hob): run gearrep.replications.tseng_curvature for the parts
named in the rule's params and write one CSV per table (Snakemake script; all numerics in the
library). Design data from data/published/params_000_*.csv, settings from the config section
`tseng_curvature:`."""

import time
from pathlib import Path

from gearrep import published
from gearrep.replications import tseng_curvature as tc

smk = snakemake  # noqa: F821  (provided by Snakemake)

pub = published.load(smk.config["published_dir"])
params = dict(smk.params.settings)
params.update(tc.design_from_published(pub.params))
t0 = time.perf_counter()
tables = tc.run(params, parts=list(smk.params.parts))
elapsed = time.perf_counter() - t0
expected = {Path(f).stem: f for f in smk.output}
missing = set(expected) - set(tables)
if missing:
    raise RuntimeError(f"tseng_curvature.run did not return tables {sorted(missing)}")
for name, path in expected.items():
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    tables[name].to_csv(path, index=False, float_format="%.15g")
Path(smk.log[0]).write_text(f"tseng_curvature.run(parts={list(smk.params.parts)}): {elapsed:.2f} s; "
                            f"tables: {sorted(expected)}\n")
