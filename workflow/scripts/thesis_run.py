"""Seed 003 (thesis): run the replication and write its tables to results/thesis/ (Snakemake script).

All numerics are in gearrep.replications.thesis.run; this script takes the `thesis:` config section (rule params) and
writes CSV files (one per table returned by run)."""

import time
from pathlib import Path

from gearrep.replications import thesis

smk = snakemake  # noqa: F821  (provided by Snakemake)

params = dict(smk.params.thesis)
t0 = time.perf_counter()
tables = thesis.run(params)
out = Path(smk.output.convergence).parent
out.mkdir(parents=True, exist_ok=True)
expected = {Path(f).stem for f in smk.output}
missing = expected - set(tables)
if missing:
    raise RuntimeError(f"thesis.run did not return tables {sorted(missing)}")
for name in sorted(expected):
    tables[name].to_csv(out / f"{name}.csv", index=False)
Path(smk.log[0]).write_text(f"thesis.run: {time.perf_counter() - t0:.1f} s; tables: {sorted(expected)}\n")
