"""Write results/report.html: verdict and findings per paper, design data, per-table rows in the
paper's order with parity plots, key figures with captions, errata, environment.

Every figure is drawn beforehand by its own job (the parity plots per seed by report_parity.py,
results/parity/<seed>/index.csv naming each source's PNG); this job only assembles the page.

Before writing, every rendered notebook and the report itself are scanned for absolute paths of
this machine (gearrep.report.absolute_paths): a page that would show one is refused.
"""

import hashlib
import platform
import subprocess
from importlib.metadata import version
from pathlib import Path

import pandas as pd
import yaml

from gearrep import published, report

smk = snakemake  # noqa: F821  (provided by Snakemake)

card = pd.read_csv(smk.input.scorecard, dtype={"seed": str}, keep_default_na=False, na_values=[""])
card["replication"] = card["replication"].astype(object).fillna("").astype(str)
pub = published.load(Path(smk.input.manifest).parent)
order = published.document_order(pub.values, pub.claims)
design = published.design_table(pub.params)
errata = pd.read_csv(smk.input.errata, dtype=str, keep_default_na=False)
notebooks = {Path(f).stem: "notebooks/" + Path(f).name for f in smk.input.notebooks}
parity = {}
for d in map(Path, smk.input.parity):
    index = pd.read_csv(d / "index.csv", dtype=str, keep_default_na=False)
    parity[d.name] = {r.source: (d / r.png).read_bytes() for r in index.itertuples()}

# key figures: the caption says what the figure shows (workflow/report/captions.yaml) and whether it
# agrees, counted from the check records of the sources it shows
captions = yaml.safe_load(Path(smk.input.captions).read_text(encoding="utf-8")) or {}
figures = {}
for f in smk.input.figures:
    key = str(Path(f).relative_to("results"))
    study = Path(f).parent.parent.name
    spec = captions.get(key)
    if spec is None:
        text = f"{study}: {Path(f).stem.replace('_', ' ')} (no caption written yet in workflow/report/captions.yaml)."
    else:
        text = f"{study}: {spec['shows'].strip()}"
        shown = pd.Series(False, index=card.index)
        for src in spec.get("sources", []):
            shown |= card["source"].str.contains(src, regex=False)
        rows = card[shown & (card["replication"] == study)]
        rows = rows[rows["status"].isin(report.result_statuses())]
        if len(rows):
            agree = int(rows["status"].isin(report.AGREE).sum())
            word = "agrees" if agree == len(rows) else ("agrees in part" if agree else "does not agree")
            text += (
                f" Agreement ({', '.join(spec['sources'])}): {agree} of {len(rows)} checks reproduced or holding,"
                f" so the figure {word}."
            )
        elif spec.get("agreement"):
            text += " " + spec["agreement"].strip()
    figures[text] = Path(f).read_bytes()

try:
    commit = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, check=True
    ).stdout.strip()
    dirty = subprocess.run(
        ["git", "status", "--porcelain", "--untracked-files=no"], capture_output=True, text=True, check=True
    ).stdout.strip()
    commit += " (with uncommitted changes)" if dirty else ""
except (OSError, subprocess.CalledProcessError):
    commit = "unknown (not a git checkout)"

env = {
    "gearrep commit": commit,
    "config sha256": hashlib.sha256(Path(smk.input.config).read_bytes()).hexdigest()[:16],
    "requirements.lock sha256": hashlib.sha256(Path(smk.input.lock).read_bytes()).hexdigest(),
    "python": platform.python_version(),
    "platform": platform.platform(),
}
for pkg in ("numpy", "scipy", "pandas", "matplotlib", "snakemake", "papermill", "nbconvert"):
    env[pkg] = version(pkg)

runtime = 0.0
for tsv in Path("results/benchmarks").rglob("*.tsv"):
    b = pd.read_csv(tsv, sep="\t")
    runtime += float(b["s"].iloc[-1])

# hand-written headline findings, each checked against the records it names (gearrep.report.highlight)
highlights = yaml.safe_load(Path(smk.input.highlights).read_text(encoding="utf-8")) or {}
stale = [
    (seed, h["text"][:60])
    for seed, specs in highlights.items()
    for h in specs
    if not report.highlight(card[card["seed"] == seed], h["text"], h.get("ids"), h.get("statuses"))[0]
]
html = report.render(
    card,
    figures,
    errata,
    env,
    notebooks=notebooks,
    runtime_s=runtime,
    order=order,
    design=design,
    parity=parity,
    highlights=highlights,
)
pages = {smk.output[0]: html} | {f: Path(f).read_text(encoding="utf-8") for f in smk.input.notebooks}
leaks = {p: sorted(set(report.absolute_paths(t)))[:5] for p, t in pages.items() if report.absolute_paths(t)}
if leaks:
    raise RuntimeError(f"absolute paths of this machine in rendered pages: {leaks}")
Path(smk.output[0]).write_text(html, encoding="utf-8")
Path(smk.log[0]).write_text(
    f"report: {len(card)} rows, {len(figures)} figures, runtime {runtime:.1f} s\n"
    + "".join(f"highlight no longer supported by its records (struck through): seed {s} {t!r}\n" for s, t in stale)
)
