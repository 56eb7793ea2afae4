"""Benchmarks of the contact core (Snakemake script of the `bench` target; not in the default run).

Writes
* throughput.csv: contact solves per second for each TCA formulation and gear family, vectorised
  (one call for all points) and single-point (one call per point), with the thesis's own timings
  (seed 003: seconds per solve in Mathematica, from data/published) as a ratio;
* core_tca.csv + figure: run time against error of the TE of a crowned, misaligned spur pair
  for the solver knobs (tolerance, formulation), against a reference at tol = 1e-14.
"""

import time
from pathlib import Path

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from gearrep import benchmark, plotting
from gearrep.published import load
from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
from gearrep.tca import GearPair, Misalignment, default_start, solve_contact
from gearrep.units import DEG

matplotlib.use("Agg")
smk = snakemake  # noqa: F821  (provided by Snakemake)
N_VEC = int(smk.params.n_vectorised)
N_SINGLE = int(smk.params.n_single)
REPEATS = int(smk.params.repeats)


def spur(crowned=False, mis=None):
    """Seed 003 Table 10 spur pair (52/72, m = 1 mm, 20 deg, b = 11.42 mm, a1 = 0.002857 per mm)."""
    g1, g2 = InvoluteGearData(52, 1.0, 20 * DEG, 11.42), InvoluteGearData(72, 1.0, 20 * DEG, 11.42)
    c1 = ParabolicCrowning(0.002857) if crowned else None
    f1, f2 = mating_flanks(g1, g2, crowning1=c1)
    return GearPair(f1, f2, 52, 72, standard_centre_distance(g1, g2), misalignment=mis)


def helical(crowned=False, mis=None):
    """Seed 003 Table 2 helical pair (40/37, m_n = 1 mm, 20 deg, beta = 14 deg, b = 20 mm)."""
    g1 = InvoluteGearData(40, 1.0, 20 * DEG, 20.0, helix_angle=14 * DEG)
    g2 = InvoluteGearData(37, 1.0, 20 * DEG, 20.0, helix_angle=14 * DEG)
    f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(0.002) if crowned else None)
    return GearPair(f1, f2, 40, 37, standard_centre_distance(g1, g2), misalignment=mis)


def angles(pair, n, rng):
    """Member-1 angles over about one angular pitch around the pitch-point position."""
    p = 2 * np.pi / pair.n1
    return -np.pi / (2 * pair.n1) + rng.uniform(-0.4 * p, 0.4 * p, n)


CASES = {
    "spur 52/72 aligned": (spur(), None),
    "spur 52/72 crowned, 0.05 deg out-of-plane": (spur(True, Misalignment(d_gamma_out=0.05 * DEG)), None),
    "helical 40/37 crowned, 0.05 deg out-of-plane": (helical(True, Misalignment(d_gamma_out=0.05 * DEG)), None),
}

rows = []
rng = np.random.default_rng(7)
for family, (pair, _) in CASES.items():
    line_contact = "aligned" in family
    for form in ("reduced", "conventional"):
        phi = angles(pair, N_VEC, rng)
        v1 = rng.uniform(-3.0, 3.0, N_VEC) if line_contact else None
        start = default_start(pair, phi, form)
        kw = {"formulation": form, "v1": v1}
        res, t = benchmark.time_call(lambda: solve_contact(pair, phi, start, **kw), repeats=REPEATS)
        ok = float(np.mean(res.converged))
        rows.append(
            {
                "family": family,
                "formulation": form,
                "mode": "vectorised",
                "n_solves": N_VEC,
                "seconds_per_solve": t.median_s / N_VEC,
                "solves_per_s": N_VEC / t.median_s,
                "converged_fraction": ok,
                "load_1min": t.load_1min,
            }
        )
        idx = np.arange(N_SINGLE)

        def loop():
            out = []
            for i in idx:
                out.append(
                    solve_contact(
                        pair,
                        phi[i : i + 1],
                        start[i : i + 1],
                        formulation=form,
                        v1=None if v1 is None else v1[i : i + 1],
                    )
                )
            return out

        res1, t1 = benchmark.time_call(loop, repeats=REPEATS)
        ok1 = float(np.mean([r.converged[0] for r in res1]))
        rows.append(
            {
                "family": family,
                "formulation": form,
                "mode": "single-point",
                "n_solves": N_SINGLE,
                "seconds_per_solve": t1.median_s / N_SINGLE,
                "solves_per_s": N_SINGLE / t1.median_s,
                "converged_fraction": ok1,
                "load_1min": t1.load_1min,
            }
        )
thr = pd.DataFrame(rows)

# the thesis's own timings (Mathematica, seconds per solve), as published
pub = load(Path(smk.input.published_dir))
timing = pub.values[(pub.values["seed"] == "003") & (pub.values["unit"] == "s")]
for _, r in timing.iterrows():
    thr[f"ratio_to {r['id']}"] = float(r["value"]) / thr["seconds_per_solve"]
out = Path(smk.output.throughput)
out.parent.mkdir(parents=True, exist_ok=True)
thr.to_csv(out, index=False)

# run time against error: TE of a crowned misaligned spur pair over a meshing cycle
pair = spur(True, Misalignment(d_gamma_out=0.05 * DEG))
phi = angles(pair, 2000, np.random.default_rng(3))
starts = {f: default_start(pair, phi, f) for f in ("reduced", "conventional")}


def run(s):
    c = solve_contact(
        pair, phi, starts[s["formulation"]], formulation=s["formulation"], tol=s["tol"], maxiter=s["maxiter"]
    )
    return c


def err(res, ref):
    bad = ~res.converged
    if bad.any():
        return float("nan")
    return float(np.max(np.abs(res.te_arcsec - ref.te_arcsec)))


frames = []
for form in ("reduced", "conventional"):
    settings = [{"formulation": form, "tol": tol, "maxiter": 50} for tol in (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13)]
    sw = benchmark.sweep(run, settings, {"formulation": form, "tol": 1e-14, "maxiter": 100}, err, repeats=REPEATS)
    frames.append(sw)
sweep = pd.concat(frames, ignore_index=True)
sweep.to_csv(smk.output.sweep, index=False)

plotting.use_style()
fig, ax = plt.subplots(figsize=(6, 4))
for form, g in sweep.groupby("formulation"):
    ax.loglog(g["time_s"], np.maximum(g["error"], 1e-16), "o-", label=f"{form} (solver tol swept)")
    k = g[g["knee"]]
    ax.loglog(k["time_s"], np.maximum(k["error"], 1e-16), "k*", ms=12)
    for _, r in g.iterrows():
        ax.annotate(f"{r['tol']:.0e}", (r["time_s"], max(r["error"], 1e-16)), fontsize=7)
plotting.label_axes(ax, "run time, 2000 contact solves [s]", "max TE error vs tol 1e-14 [arcsec]")
ax.set_title("Crowned spur 52/72, 0.05 deg misalignment (knee: star)")
ax.legend()
fig.savefig(smk.output.figure, dpi=120, bbox_inches="tight")
Path(smk.log[0]).write_text(f"throughput rows {len(thr)}, sweep rows {len(sweep)}, at {time.ctime()}\n")
