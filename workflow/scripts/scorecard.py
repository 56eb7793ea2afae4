"""Write results/scorecard.{csv,md} from the replications' check files (Snakemake script)."""

from pathlib import Path

import pandas as pd

from gearrep import checks, published
from gearrep.replications import REGISTRY

smk = snakemake  # noqa: F821  (provided by Snakemake)

data_dir = Path(smk.input.manifest).parent
pub = published.load(data_dir)
tables = {
    Path(f).stem: pd.read_csv(f, dtype=checks.TEXT_COLUMNS, keep_default_na=False, na_values=[""])
    for f in smk.input.checks
}
card = checks.scorecard(tables, pub.values, pub.claims)
# the paper of each row; a validation study's rows carry the study's title
titles = {study.key: study.document for study in REGISTRY.values() if study.validation}
card["paper"] = card["seed"].map(published.PAPERS).fillna(card["replication"].map(titles))
# every published value and claim of the manifest has its row: nothing dropped silently
expected = published.scored_rows_per_seed(published.verify_manifest(data_dir))
got = card[card["seed"] != checks.VALIDATION].groupby("seed").size().to_dict()
if {s: n for s, n in expected.items() if n} != got:
    raise RuntimeError(f"scorecard rows per seed {got} differ from the manifest's {expected} ({smk.input.manifest})")


def md_table(df: pd.DataFrame) -> str:
    cols = list(df.columns)
    lines = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for _, r in df.iterrows():
        cells = ["" if pd.isna(r[c]) else (f"{r[c]:.6g}" if isinstance(r[c], float) else str(r[c])) for c in cols]
        lines.append("| " + " | ".join(c.replace("|", "/").replace("\n", " ") for c in cells) + " |")
    return "\n".join(lines)


is_result = card["status"].isin(checks.RESULT_STATUSES)
by_paper = checks.summary(card, by=("seed",))
by_paper.insert(1, "paper", by_paper["seed"].map(published.PAPERS).fillna("validation of the library (not a paper)"))
by_paper.insert(1, "name", by_paper["seed"].map(published.PAPER_NAMES).fillna("-"))
by_source = checks.summary(card, by=("seed", "source"))
rows = card[
    [
        "id",
        "seed",
        "source",
        "row",
        "quantity",
        "unit",
        "published",
        "computed",
        "abs_err",
        "tolerance",
        "status",
        "tolerance_basis",
        "note",
    ]
]

text = (
    "\n\n".join(
        [
            "# gearrep replication scorecard",
            f"{len(card)} published values and claims: {int(is_result.sum())} results (statuses: "
            + ", ".join(f"{k} {v}" for k, v in card.loc[is_result, "status"].value_counts().items())
            + f") and {int((~is_result).sum())} printed design inputs (status `{checks.INPUT}`: used as printed, "
            "neither results nor gaps; column `results` of the counts excludes them)",
            "## Counts by paper",
            md_table(by_paper),
            "## Counts by table",
            md_table(by_source),
            "## Every value",
            md_table(rows),
        ]
    )
    + "\n"
)

Path(smk.output.csv).parent.mkdir(parents=True, exist_ok=True)
card.to_csv(smk.output.csv, index=False)
Path(smk.output.md).write_text(text)
Path(smk.log[0]).write_text(f"{len(card)} rows written\n")
