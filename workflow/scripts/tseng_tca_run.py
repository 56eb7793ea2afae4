"""Seed 000 ch. 5 (tseng_tca): run the TCA replication and write its tables (Snakemake script).

The Examples' design and assembly data are read from data/published (params_000_*.csv); the
numerics are in gearrep.replications.tseng_tca.run."""

import time
from pathlib import Path

from gearrep import published
from gearrep.replications import tseng_tca

smk = snakemake  # noqa: F821  (provided by Snakemake)

params = dict(smk.params.settings)
pub_params = published.load(smk.config["published_dir"]).params
params["cases"] = tseng_tca.cases_from_published(pub_params)
params.update(tseng_tca.ellipse_data_from_published(pub_params))
t0 = time.perf_counter()
tables = tseng_tca.run(params)
expected = {Path(f).stem: f for f in smk.output}
missing = set(expected) - set(tables)
if missing:
    raise RuntimeError(f"tseng_tca.run did not return tables {sorted(missing)}")
for name, f in expected.items():
    Path(f).parent.mkdir(parents=True, exist_ok=True)
    tables[name].to_csv(f, index=False)
Path(smk.log[0]).write_text(f"tseng_tca.run: {time.perf_counter() - t0:.2f} s; tables: {sorted(expected)}\n")
