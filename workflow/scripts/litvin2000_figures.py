"""Seed 002 (NASA report): figures from results/litvin2000/ (Snakemake script).

Computed values are lines, published values open markers (gearrep.plotting):
TE functions of the profile-crowned pair under 3 arcmin errors (figs 2.8.3-2.8.4, 5.5.1-2,
5.5.6-7) with TE_max against sec. 5.5; contact ellipses of Table 6.2.4 in their principal axes;
sensitivity to dE (Table 6.2.3); contact paths on the pinion (fig. 1.10).

Inputs (generic figures rule): ``snakemake.input.tables`` (every table of the study, named by
file stem), ``snakemake.input.published`` (the CHECK_DATA files of gearrep.replications.litvin2000;
the values files are read); outputs ``snakemake.output.<key>`` for each key of litvin2000.FIGURES."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from replication_io import save_figure  # noqa: E402

from gearrep import plotting  # noqa: E402

smk = snakemake  # noqa: F821  (provided by Snakemake)
plotting.use_style()
inp, out = smk.input, smk.output
T = {Path(f).stem: f for f in inp.tables}
pub = pd.concat(
    [pd.read_csv(f, dtype={"seed": str}) for f in inp.published if Path(f).name.startswith("values_")],
    ignore_index=True,
).set_index("id")
LABEL = {
    "dgamma_plus": "dgamma = +3'",
    "dgamma_minus": "dgamma = -3'",
    "dlambda_helix_plus": "dlambda = +3' (lead)",
    "dlambda_helix_minus": "dlambda = -3' (lead)",
    "aligned": "aligned",
    "dE_0.001in": "dE = 0.001 in",
    "dgamma_intersecting": "3' in the plane of the axes",
}


# TE functions and TE_max
cyc = pd.read_csv(T["te_cycle"])
summ = pd.read_csv(T["te_summary"]).set_index("case")
fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 4.2))
for case in ("dgamma_plus", "dlambda_helix_plus", "aligned"):
    c = cyc[cyc["case"] == case]
    for k, g in c.groupby("tooth"):
        plotting.computed(
            ax,
            np.degrees(g["phi1_rad"]),
            g["te_arcsec"],
            LABEL[case] if k == 0 else None,
            color={"dgamma_plus": "C0", "dlambda_helix_plus": "C1", "aligned": "C2"}[case],
        )
plotting.label_axes(ax, "phi1 [deg]", "TE [arcsec]", "Profile crowning only: TE over three meshing cycles")
plotting.finish(ax)
cases = ["dgamma_plus", "dgamma_minus", "dlambda_helix_plus", "dlambda_helix_minus"]
x = np.arange(len(cases))
plotting.computed(ax2, x, [summ.loc[c, "te_max_arcsec"] for c in cases], "computed TE_max (peak-to-peak)")
pv = pub.loc["002-S5.5-crowning=profile;tool=worm;misalignment=dgamma_3arcmin-TE_max", "value"]
plotting.published(ax2, x, [pv] * len(cases), "Sec 5.5", "printed 40.48 for both errors")
ax2.set_xticks(x, [LABEL[c] for c in cases], rotation=15)
plotting.label_axes(ax2, "misalignment case [-]", "TE_max [arcsec]", "Maximal TE per cycle")
plotting.finish(ax2)
# worm-ground (plunged) pinion: TE over the cycle (figs 5.5.8-5.5.10)
wc = pd.read_csv(T["worm_cycle"])
ws = pd.read_csv(T["worm_summary"]).set_index("case")
fig_w, (ax, ax2w) = plt.subplots(1, 2, figsize=(12, 4.2))
for case, col in (("worm_aligned", "C2"), ("worm_dgamma_plus", "C0"), ("worm_dgamma_minus", "C1")):
    g = wc[wc["case"] == case].sort_values("phi1_rad")
    plotting.computed(
        ax, np.degrees(g["phi1_rad"]), g["te_arcsec"], case.replace("worm_", "worm: "), color=col, marker=None
    )
plotting.label_axes(ax, "phi1 [deg]", "TE [arcsec]", "Plunging worm: TE over one meshing cycle")
plotting.finish(ax)
wcases = ["worm_aligned", "worm_dgamma_plus", "worm_dgamma_minus", "worm_dlambda_plus", "worm_dlambda_minus"]
xw = np.arange(len(wcases))
plotting.computed(ax2w, xw, [ws.loc[c, "te_max_arcsec"] for c in wcases], "computed TE_max")
# printed: aligned, dgamma = 3', dlambda = 3' (read as a turn about the centre line = dgamma -3'); the literal lead
# errors (last two) have no printed counterpart
pubw = [
    pub.loc[f"002-S5.5-crowning=worm;misalignment={m}-TE_max", "value"]
    for m in ("none", "dgamma_3arcmin", "dlambda_3arcmin")
]
plotting.published(ax2w, xw[:3], pubw, "Sec 5.5", "printed (dlambda as a turn)")
ax2w.set_xticks(
    xw,
    ["aligned", "dgamma +3'", "dgamma -3' (= dlambda turn)", "dlambda +3' (lead)", "dlambda -3' (lead)"],
    rotation=15,
)
plotting.label_axes(ax2w, "case [-]", "TE_max [arcsec]", "Worm-ground pinion: maximal TE")
plotting.finish(ax2w)
save_figure(fig_w, out.worm)
save_figure(fig, out.te)

# contact ellipses (principal axes, major along x)
ell = pd.read_csv(T["ellipse"])
fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
t = np.linspace(0, 2 * np.pi, 200)
for ax, (v, zone) in zip(axes, ((1, "single"), (2, "pinion_addendum"), (3, "single"))):
    r = ell[(ell["version"] == v) & (ell["zone"] == zone) & (ell["case"] == "design")].iloc[0]
    a, b = r["major_2a_in"] / 2, r["minor_2b_in"] / 2
    plotting.computed(ax, a * np.cos(t), b * np.sin(t), f"computed 2a={2 * a:.4f}, 2b={2 * b:.4f}", marker=None)
    pa = pub.loc[f"002-T6.2.4-version={v}-major_axis_2a", "value"] / 2
    pb = pub.loc[f"002-T6.2.4-version={v}-minor_axis_2b", "value"] / 2
    plotting.published(ax, [-pa, pa, 0, 0], [0, 0, -pb, pb], "Table 6.2.4", "printed axes")
    ax.set_aspect("equal", adjustable="datalim")
    plotting.label_axes(ax, "along major axis [in]", "along minor axis [in]", f"version {v}")
    plotting.finish(ax, loc="lower center")
save_figure(fig, out.ellipses)

# sensitivity to dE (Table 6.2.3)
sens = pd.read_csv(T["sensitivity"])
fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4))
for method, style in (("tca", {}), ("eq2.8.7_decrease", {"linestyle": "--"})):
    s = sens[(sens["method"] == method) & (sens["step"] == "0.001in")].sort_values("version")
    plotting.computed(ax, s["version"], s["delta_alpha_deg"], f"{method}, dE = 0.001 in", **style)
    plotting.computed(ax2, s["version"], s["delta_1"], f"{method}, dE = 0.001 in", **style)
vs = [1, 2, 3]
plotting.published(ax, vs, [pub.loc[f"002-T6.2.3-version={v}-delta_alpha", "value"] for v in vs], "Table 6.2.3")
plotting.published(ax2, vs, [pub.loc[f"002-T6.2.3-version={v}-delta_1", "value"] for v in vs], "Table 6.2.3")
ax.set_yscale("log")
ax2.set_yscale("log")
plotting.label_axes(ax, "version [-]", "pressure-angle change [deg]", "Sensitivity to dE")
plotting.label_axes(ax2, "version [-]", "shift / active height [-]")
plotting.finish(ax)
plotting.finish(ax2)
save_figure(fig, out.sensitivity)

# contact paths on the pinion (rack profile parameter vs axial position), fig. 1.10
sg = pd.read_csv(T["te_single"])
fig, ax = plt.subplots()
for case in ("aligned", "dE_0.001in", "dgamma_plus", "dlambda_helix_plus"):
    s = sg[(sg["case"] == case) & sg["on_face"].astype(bool)]
    plotting.computed(ax, s["z_in"], s["u1_in"], LABEL[case])
plotting.label_axes(
    ax,
    "axial position of the contact point [in]",
    "pinion rack profile parameter u [in]",
    "Contact paths on the pinion (u = 0: helix through Q)",
)
plotting.finish(ax)
save_figure(fig, out.paths)
Path(smk.log[0]).parent.mkdir(parents=True, exist_ok=True)
Path(smk.log[0]).write_text("litvin2000 figures: " + ", ".join(str(f) for f in out) + "\n")
