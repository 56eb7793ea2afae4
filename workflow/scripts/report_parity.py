"""Draw the parity plots of one paper for the report (Snakemake script of results/parity/{seed}).

The job runs as soon as the check files of the seed's studies exist: it builds the seed's
scorecard rows from them and from the seed's published values and claims (gearrep.checks.scorecard,
as the scorecard job does) and draws one parity plot per source with computed numbers
(gearrep.report.parity_pngs). The output directory holds the PNG files and ``index.csv``
(columns ``source``, ``png``: the file of each source's plot); the report job embeds them as they
are and draws nothing itself.
"""

from pathlib import Path

import pandas as pd

from gearrep import checks, published, report

smk = snakemake  # noqa: F821  (provided by Snakemake)

seed = smk.wildcards.seed
pub = published.load(smk.params.published_dir, files=smk.input.published)
tables = {
    Path(f).stem: pd.read_csv(f, dtype=checks.TEXT_COLUMNS, keep_default_na=False, na_values=[""])
    for f in smk.input.checks
}
card = checks.scorecard(tables, pub.values, pub.claims)
if set(card["seed"]) != {seed}:
    raise RuntimeError(f"parity plots of seed {seed}: the inputs hold seeds {sorted(set(card['seed']))}")

out = Path(smk.output[0])
out.mkdir(parents=True, exist_ok=True)
index = []
for k, (source, png) in enumerate(report.parity_pngs(card).items()):
    name = f"{k:02d}.png"
    (out / name).write_bytes(png)
    index.append({"source": source, "png": name})
pd.DataFrame(index, columns=["source", "png"]).to_csv(out / "index.csv", index=False)
Path(smk.log[0]).write_text(f"seed {seed}: {len(index)} parity plots from {len(card)} scorecard rows\n")
