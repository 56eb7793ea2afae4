"""Seed 002 (NASA report): run the replication and write its tables to results/nasa/ (Snakemake script).

Reads the config section ``nasa`` and the design data in data/published (params_002_*, Tables
6.2.1-6.2.2 values); all numerics are in gearrep.replications.nasa.run."""

import time
from pathlib import Path

from gearrep import published
from gearrep.replications import nasa

smk = snakemake  # noqa: F821  (provided by Snakemake)

params = dict(smk.params.settings)
params["design"] = nasa.design_from_published(published.load(smk.config["published_dir"]))
t0 = time.perf_counter()
tables = nasa.run(params)
out = Path(smk.output.curvatures).parent
out.mkdir(parents=True, exist_ok=True)
expected = {Path(f).stem for f in smk.output}
missing = expected - set(tables)
if missing:
    raise RuntimeError(f"nasa.run did not return tables {sorted(missing)}")
for name in sorted(expected):
    tables[name].to_csv(out / f"{name}.csv", index=False)
Path(smk.log[0]).write_text(f"nasa.run: {time.perf_counter() - t0:.1f} s; tables: {sorted(expected)}\n")
