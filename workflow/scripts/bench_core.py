"""Benchmarks of the contact core (Snakemake script of the `bench` target; not in the default run).

Writes
* throughput.csv: one row per gear family the library and the CLI know (involute spur and
  helical, straight and spiral bevel, CATT, Novikov-Wildhaber with rack-generated, worm-ground and
  disk-ground pinions, hob-cut curvilinear) and TCA formulation (both where both exist): contact
  solves vectorised (one call for all points) and single-point (one call per point), in seconds
  and in elements of the fixed reference kernel (gearrep.benchmark.reference_kernel: 20 sin/cos
  and 300 multiply-adds per element) timed in the same interleaved run, so that the ratios hold on
  a loaded machine; the mean Newton iterations; the starts' cost; the family's targets by surface
  kind (gearrep.benchmark.FAMILY_TARGETS); the stricter targets of the README pair; for the
  README pair also the same solves with scipy.optimize.root point by point (the baseline a user
  would write) and the ratio; the
  thesis's own timing of the README pair (seed 003 Table 10, Mathematica: total time for 5000
  converged points, from data/published) per point over ours; the machine load before and after
  each row;
* core_tca.csv + figure: run time against error of the TE of a crowned, misaligned spur pair
  for the solver knobs (tolerance, formulation), against a reference at tol = 1e-14.
"""

import platform
import time
from pathlib import Path

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from gearrep import benchmark, plotting, published
from gearrep.published import load
from gearrep.replications import load as load_study
from gearrep.settings import defaults
from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
from gearrep.tca import GearPair, Misalignment, default_start, solve_contact
from gearrep.units import ARCMIN, DEG

matplotlib.use("Agg")
smk = snakemake  # noqa: F821  (provided by Snakemake)
N_VEC = int(smk.params.n_vectorised)
N_SINGLE = int(smk.params.n_single)
REPEATS = int(smk.params.repeats)
PUBLISHED = Path(smk.input.published_dir)


def spur(crowned=False, mis=None):
    """The README pair: seed 003 Table 10 spur pair (52/72, m = 1 mm, 20 deg, b = 11.42 mm,
    a1 = 0.002857 per mm)."""
    g1, g2 = InvoluteGearData(52, 1.0, 20 * DEG, 11.42), InvoluteGearData(72, 1.0, 20 * DEG, 11.42)
    c1 = ParabolicCrowning(0.002857) if crowned else None
    f1, f2 = mating_flanks(g1, g2, crowning1=c1)
    return GearPair(f1, f2, 52, 72, standard_centre_distance(g1, g2), misalignment=mis)


def study(name):
    """Default settings and design data of a replication (as its jobs get them)."""
    mod = load_study(name)
    design = mod.params_from_published(published.load(PUBLISHED, [str(PUBLISHED / f) for f in mod.DESIGN_DATA]))
    return defaults(mod.SETTINGS), design


def angles(pair, n, rng):
    """Member-1 angles over about one angular pitch around phi1 = -pi/(2 N1)."""
    p = 2 * np.pi / pair.n1
    return -np.pi / (2 * pair.n1) + rng.uniform(-0.4 * p, 0.4 * p, n)


def readme_case(rng, n, formulation):
    pair = spur(True, Misalignment(d_gamma_out=0.05 * DEG))
    phi = angles(pair, n, rng)
    return pair, phi, lambda: default_start(pair, phi, formulation), {}


def novikov_case(rng, n, pinion="rack"):
    """Seed 002: the profile-crowned Novikov-Wildhaber pair (rack-generated flanks, ``pinion``
    "rack"), or with the worm-ground (``"worm"``, sec. 5.4) or disk-ground (``"disk"``, sec. 4.2,
    at the middle of the study's bracket of the disk-pinion distance E_d) pinion, under the
    study's 3 arcmin dgamma, from the aligned contact moved by the offset of a solved contact
    (gearrep.tca.offset_start, whose reference solves are in the row's start cost): for the
    rack-generated pair the offset solved at one angle (the study's starts), for the ground pinions,
    whose aligned start drifts from the contact along the path, the offset quadratic in the angle
    through three solved ones (order=2), and with the study's solver settings."""
    from gearrep.replications.litvin2000 import geometry as ng
    from gearrep.replications.litvin2000.bench import crowned_pair
    from gearrep.surfaces.novikov import aligned_start
    from gearrep.tca import offset_start

    settings, design = study("litvin2000")
    mis = Misalignment(d_gamma_out=settings["misalignment_arcmin"] * ARCMIN)
    if pinion == "worm":
        pair = ng.make_worm_pair(design, settings, misalignment=mis)
    elif pinion == "disk":
        pair = ng.make_disk_pair(design, settings, float(np.mean(settings["disk_E_d_bracket_in"])), misalignment=mis)
    else:
        pair = crowned_pair(settings, design, mis)
    per = 2 * np.pi / pair.n1
    phi = rng.uniform(-0.5 * per, 0.5 * per, n)
    kw = {"tol": settings["tol"], "maxiter": settings["maxiter"]}
    nominal = {"worm": ng.worm_start, "disk": ng.disk_start, "rack": aligned_start}[pinion]
    order = 0 if pinion == "rack" else 2
    return pair, phi, lambda: offset_start(pair, phi, nominal, order=order, **kw), kw


def catt_case(rng, n):
    """Seed 004: the sec. 4 CATT pair, primary flanks, over its real path, the study's starts."""
    from gearrep.replications.ma2021.assembly import PRIMARY
    from gearrep.replications.ma2021.bench import BENCH_DESIGN
    from gearrep.replications.ma2021.design import merged_params
    from gearrep.surfaces import catt as ca

    settings, design = study("ma2021")
    q = merged_params(settings, design)
    mesh = ca.assemble(design.by_name(BENCH_DESIGN), PRIMARY[0], q)
    lim = ca.path_limits(mesh)
    phi = rng.uniform(lim["phi1_lo"], lim["phi1_hi"], n)
    kw = {"tol": q["tol"], "maxiter": q["maxiter"]}
    return mesh.gear_pair, phi, lambda: ca.starts(mesh, phi, q["start_offset_mm"]), kw


def bevel_case(rng, n, formulation="reduced", case="spiral_bevel_17_17"):
    """Seed 003 sec. 5: the crowned spiral (17/17, Table 12) or straight (39/32, Table 11) bevel
    pair of the convergence study, aligned, from the default starts, at angles where the tooth pair
    they start on is in contact (spiral: from half an angular pitch before phi1 = -pi/(2 N1), the
    aligned pair's pitch-cone contact, to 0.05 of one after it, its contact ends about 0.09 after; straight: 0.4 of a pitch either
    side of it)."""
    from gearrep.replications.temirkhan2023.bevel_convergence import convergence_pair

    settings, design = study("temirkhan2023")
    pair = convergence_pair(settings, design, case)
    p = 2 * np.pi / pair.n1
    if case.startswith("spiral"):
        phi = rng.uniform(-0.45 * p, 0.05 * p, n)
    else:
        phi = angles(pair, n, rng)
    return pair, phi, lambda: default_start(pair, phi, formulation), {"tol": settings["tol"]}


def helical_case(rng, n, formulation):
    """Seed 003 Table 9: the profile-crowned helical pair 25/77 under the study's in-plane
    misalignment, from the default starts, over 0.8 of an angular pitch around phi1 = -pi/(2 N1); the thesis's solver tolerance."""
    from gearrep.replications.temirkhan2023.design import design_pair

    settings, design = study("temirkhan2023")
    pair = design_pair(
        design, "helical_25_77", Misalignment(d_gamma_in=float(design.helical_misalignment_arcmin) * ARCMIN)
    )
    # the angles at which the tooth pair the default start is on meets inside both flanks
    grid = -np.pi / (2 * pair.n1) + np.linspace(-1.0, 1.0, 401) * 2 * np.pi / pair.n1
    ok = solve_contact(pair, grid, default_start(pair, grid, formulation), formulation=formulation).converged
    phi = rng.uniform(grid[ok].min(), grid[ok].max(), n)
    return pair, phi, lambda: default_start(pair, phi, formulation), {"tol": settings["tol"]}


def hobbed_case(rng, n):
    """Seed 000 ch. 5: the hob-cut curvilinear pair of Table 5.4's example (its assembly errors),
    the 9-unknown envelope-pair TCA (gearrep.tca.solve_envelope_points) at angles over the
    study's phi1' grid, each from the first-order path predictor off the nearest point of the
    study's path on that grid (continuation and path not timed)."""
    from gearrep.replications.hobcut_tca import TABLE_EXAMPLE
    from gearrep.replications.hobcut_tca.studies import assembly_of, phi1_grid
    from gearrep.tca import hobbed_continue_to, predict_envelope_contact, solve_envelope_points, trace_envelope_path

    settings, design = study("hobcut_tca")
    case = design.cases[TABLE_EXAMPLE["5.4"]]
    tol = settings["tol"]
    pair, s0 = hobbed_continue_to(
        design.gears, case["R_cp_mm"], case["R_cg_mm"], assembly_of(case), steps=settings["continuation_steps"], tol=tol
    )
    grid = phi1_grid(settings)
    path = trace_envelope_path(pair, s0, grid, tol=tol)
    phi = rng.uniform(grid.min(), grid.max(), n)
    j = np.abs(phi[:, None] - grid[None, :]).argmin(axis=1)  # the nearest grid point on the path
    return (
        pair,
        phi,
        lambda: predict_envelope_contact(pair, path.x[j], grid[j], phi),
        {"solve": lambda ph, st: solve_envelope_points(pair, ph, st, tol=tol)},
    )


rng = np.random.default_rng(7)
README = "involute spur 52/72 crowned, 0.05 deg out-of-plane (README pair)"
HELICAL = "involute helical 25/77 profile-crowned, in-plane misaligned (seed 003 Table 9)"
SPIRAL = "spiral bevel pair of seed 003 sec. 5 (17/17, crowned)"
STRAIGHT = "straight bevel pair of seed 003 sec. 5 (39/32, crowned)"
NOVIKOV = "Novikov-Wildhaber profile-crowned pair (seed 002)"
# (family, formulation, case, points per single-point run): the surfaces of the ground Novikov
# pinions and of the hob-cut pair are envelopes solved at every evaluation, so those run on fewer
# points (the disk-ground pinion's surface is a spline of its grinding line carried by a screw motion,
# the generated kind too: its grinding line is solved from the tool, once, on a grid)
N_GEN, N_GEN_SINGLE = max(N_VEC // 50, 20), max(N_SINGLE // 20, 5)
CASES = [
    (README, "reduced", readme_case(rng, N_VEC, "reduced"), N_SINGLE),
    (README, "conventional", readme_case(rng, N_VEC, "conventional"), N_SINGLE),
    (HELICAL, "reduced", helical_case(rng, N_VEC, "reduced"), N_SINGLE),
    (HELICAL, "conventional", helical_case(rng, N_VEC, "conventional"), N_SINGLE),
    (SPIRAL, "reduced", bevel_case(rng, N_VEC), N_SINGLE),
    (SPIRAL, "conventional", bevel_case(rng, N_VEC, "conventional"), N_SINGLE),
    (STRAIGHT, "reduced", bevel_case(rng, N_VEC, "reduced", "straight_bevel_39_32"), N_SINGLE),
    (STRAIGHT, "conventional", bevel_case(rng, N_VEC, "conventional", "straight_bevel_39_32"), N_SINGLE),
    ("CATT pair of seed 004 sec. 4", "conventional", catt_case(rng, N_VEC), N_SINGLE),
    (NOVIKOV, "conventional", novikov_case(rng, N_VEC), N_SINGLE),
    (
        "hob-generated: worm-ground Novikov pinion (seed 002 sec. 5.4)",
        "conventional",
        novikov_case(rng, N_GEN, "worm"),
        N_GEN_SINGLE,
    ),
    (
        "generated: disk-ground Novikov pinion (seed 002 sec. 4.2)",
        "conventional",
        novikov_case(rng, N_GEN, "disk"),
        N_GEN_SINGLE,
    ),
    (
        "hob-cut curvilinear pair (seed 000 ch. 5, Table 5.4 example)",
        "envelope pair (9 unknowns)",
        hobbed_case(rng, N_GEN),
        N_GEN_SINGLE,
    ),
]

rows = []
for family, form, (pair, phi, start_of, kw), n_single in CASES:
    readme = "README" in family
    kw = dict(kw)
    own = kw.pop("solve", None)
    with np.errstate(all="ignore"):
        t0 = time.process_time()
        start = start_of()
        start_s = time.process_time() - t0
        r = benchmark.tca_throughput(
            pair,
            phi,
            start,
            formulation=form,
            n_single=min(n_single, len(phi)),
            repeats=REPEATS,
            solve_kwargs=kw,
            scipy_points=min(n_single, 50, len(phi)) if readme else 0,
            solve=own,
        )
    # the starts' cost, timed once (for the Novikov pairs it holds the reference solves of
    # gearrep.tca.offset_start)
    r = {"family": family, **r, "start_elements_per_point": start_s / len(phi) / r["reference_s_per_element"]}
    if readme:
        r["target_vectorised_elements"] = benchmark.THROUGHPUT_TARGETS[form]
        r["target_single_elements"] = benchmark.THROUGHPUT_TARGETS["single"]
    r["surface_kind"] = "generated" if "generated" in family or "hob-cut" in family else "analytic"
    r["family_target_vectorised_elements"] = benchmark.FAMILY_TARGETS[r["surface_kind"]]["vectorised"]
    r["family_target_single_elements"] = benchmark.FAMILY_TARGETS[r["surface_kind"]]["single"]
    r["machine"] = (
        f"{platform.machine()} {platform.processor() or platform.system()}, {__import__('os').cpu_count()} cores"
    )
    rows.append(r)
thr = pd.DataFrame(rows)

# the thesis's own timings (Mathematica, seconds per solve), as published
pub = load(PUBLISHED)
# the thesis timed the README pair itself (Table 10, spur 52/72): total wall time for 5000 converged
# points (the table's footnote a and the notes of values_003_T10.csv), i.e. seconds per converged
# point = total / 5000; compared on the README rows only, for both of our modes
T10_POINTS = 5000
timing = pub.values[
    pub.values["id"].str.startswith("003-T10-case=spur_52_72") & (pub.values["quantity"] == "total_time")
]
readme_rows = thr["family"].str.contains("README")
for _, r in timing.iterrows():
    per_point = float(r["value"]) / T10_POINTS
    for mode, col in (("vectorised", "vectorised_s_per_solve"), ("single", "single_s_per_call")):
        thr[f"thesis_per_point_over_ours {r['id']} ({mode})"] = np.where(readme_rows, per_point / thr[col], np.nan)
out = Path(smk.output.throughput)
out.parent.mkdir(parents=True, exist_ok=True)
thr.to_csv(out, index=False)

# run time against error: TE of a crowned misaligned spur pair over a meshing cycle
pair = spur(True, Misalignment(d_gamma_out=0.05 * DEG))
phi = angles(pair, 2000, np.random.default_rng(3))
starts = {f: default_start(pair, phi, f) for f in ("reduced", "conventional")}


def run(setting):
    c = solve_contact(
        pair,
        phi,
        starts[setting["formulation"]],
        formulation=setting["formulation"],
        tol=setting["tol"],
        maxiter=setting["maxiter"],
    )
    return c


def err(res, ref):
    """Max TE error over the angles the reference solved (at tol = 1e-14 the conventional solve
    stops short of the tolerance at a few angles: its residual floor is about 1e-14); NaN if the
    setting failed at any of them."""
    ok = ref.converged
    if (~res.converged[ok]).any():
        return float("nan")
    return float(np.max(np.abs(res.te_arcsec[ok] - ref.te_arcsec[ok])))


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
