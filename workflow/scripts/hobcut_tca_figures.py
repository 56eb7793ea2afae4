"""Seed 000 ch. 5 (hobcut_tca): figures (Snakemake script of the generic figures rule).

KE against phi1' for the five surviving tables (computed lines, printed values as markers),
the contact position Z_p along the path, the KE of the ideal pair against the hob pitch radius
(Fig 5.5) and a/b against R_c (Fig 5.7). Inputs: ``tables`` (every table of the study),
``published`` (the study's CHECK_DATA files); one output per key of hobcut_tca.FIGURES."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402
from replication_io import save_figure  # noqa: E402

from gearrep import plotting  # noqa: E402

smk = snakemake  # noqa: F821  (provided by Snakemake)
plotting.use_style()
tables = {Path(f).stem: pd.read_csv(f) for f in smk.input.tables}
values = pd.concat(
    [
        pd.read_csv(f, dtype=str, keep_default_na=False)
        for f in smk.input.published
        if Path(f).name.startswith("values_")
    ],
    ignore_index=True,
)
values["value"] = pd.to_numeric(values["value"], errors="coerce")
SURVIVING = ["5.3", "5.4", "5.7", "5.8", "5.9"]


def printed(table, quantity):
    v = values[(values["source"] == f"Table {table}") & (values["quantity"] == quantity)].copy()
    v["phi1_deg"] = v["row"].str.split("=").str[1].astype(float)
    return v.sort_values("phi1_deg")


for key, col, q, ylabel in (("ke", "KE_arcsec", "KE", "KE [arcsec]"), ("zp", "Z_p_mm", "Z_p", "Z_p [mm]")):
    fig, ax = plt.subplots(figsize=(7.2, 4.6))
    for i, tab in enumerate(SURVIVING):
        c = f"C{i}"
        t = tables[f"ke_table_{tab.replace('.', '_')}"]
        plotting.computed(ax, t["phi1_deg"], t[col], f"computed, Table {tab} conditions", color=c)
        p = printed(tab, q)
        plotting.published(ax, p["phi1_deg"], p["value"], f"Table {tab}", color=c)
    if key == "ke":
        t = tables["ke_table_5_2"]
        plotting.computed(ax, t["phi1_deg"], t[col], "computed, Table 5.2 (ideal, no data)", color="k", linestyle=":")
    plotting.label_axes(
        ax,
        "phi1' [deg]",
        ylabel,
        "seed 000 Tables 5.2-5.9: " + ("kinematic error" if key == "ke" else "contact position on the pinion face"),
    )
    save_figure(plotting.finish(ax, loc="upper center" if key == "ke" else "best"), smk.output[key])

h = tables["ke_vs_hob_radius"]
fig, ax = plt.subplots()
for r, g in h.groupby("hob_pitch_radius_mm"):
    plotting.computed(ax, g["phi1_deg"], g["KE_arcsec"], f"r_h = {r:g} mm")
plotting.label_axes(ax, "phi1' [deg]", "KE [arcsec]", "Fig 5.5: ideal 110/110 pair, KE by hob pitch radius")
save_figure(plotting.finish(ax), smk.output["hob"])
er = tables["ellipse_ratio"]
fig, ax = plt.subplots()
for i, (a, g) in enumerate(er.groupby("alpha_n_deg")):
    g = g.sort_values("R_cp_mm")
    plotting.computed(
        ax, g["R_cp_mm"], g["a_over_b"], f"alpha_n = {a:g} deg, R_cg = R_cp + 1 mm, pitch point", color=f"C{i}"
    )
    v = values[(values["quantity"] == "a_over_b") & values["row"].str.contains(f"alpha_n_deg={a:g};")]
    plotting.published(ax, [110.0] * len(v), v["value"], "Fig 5.7 text", label=f"{a:g} deg", color=f"C{i}")
plotting.label_axes(ax, "R_c [mm]", "a/b [-]", "Fig 5.7: contact-ellipse axis ratio (curvature method)")
save_figure(plotting.finish(ax), smk.output["ab"])
Path(smk.log[0]).write_text("figures: " + ", ".join(str(f) for f in smk.output) + "\n")
