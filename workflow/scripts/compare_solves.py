"""Old against new contact solves: the same solves run on two source trees must agree (a check for
refactorings and speed work on gearrep.tca / gearrep.solve; not part of the workflow).

    python workflow/scripts/compare_solves.py OLD_SRC NEW_SRC [--keep DIR]

OLD_SRC, NEW_SRC: ``src`` directories of two checkouts (e.g. of main and of a branch). Each is
imported in its own process (``python compare_solves.py dump SRC OUT.npz``), which solves
* the README pair (crowned 52/72 spur, 0.05 deg out of plane) over 1.2 angular pitches, reduced and
  conventional, vectorised and one point per call, with a fixed v1 and with the numeric Jacobian;
* the thesis Table 10 convergence starts (2000 random starts over both flanks: converging,
  diverging, singular and off-flank rows), both formulations and every solve variant;
* the seed 002 Novikov-Wildhaber pair and the seed 004 CATT pair from their studies' starts
  (conventional);
and stores every field of the contact records. The comparison: statuses and iteration counts
equal; solutions, positions, normals and TE equal to 1e-12 relative (to max(1, |old|)); the same
NaN pattern. Residuals and condition numbers are reported, not required equal. Exit status 1 on a
mismatch.
"""

import subprocess
import sys
import tempfile
from pathlib import Path

if len(sys.argv) > 1 and sys.argv[1] == "dump":
    sys.path.insert(0, str(Path(sys.argv[2]).resolve()))
import numpy as np  # noqa: E402

PUBLISHED = Path(__file__).resolve().parents[2] / "data" / "published"


def study(name):
    """Default settings and design data of a replication study (as its jobs get them)."""
    from gearrep import published
    from gearrep.replications import load as load_study
    from gearrep.settings import defaults

    mod = load_study(name)
    design = published.load(PUBLISHED, [str(PUBLISHED / f) for f in mod.DESIGN_DATA])
    return defaults(mod.SETTINGS), mod.params_from_published(design)


def put(res, tag, c):
    """Every field of the contact record ``c`` into ``res`` under ``tag``."""
    for k in ("u1", "v1", "u2", "v2", "phi2", "te", "residual", "iterations", "status", "condition"):
        res[f"{tag}:{k}"] = np.asarray(getattr(c, k))
    res[f"{tag}:position"] = c.position
    res[f"{tag}:normal"] = c.normal


def cases(res, tag, pair, phi, st, form, kw, nsingle):
    """The solves vectorised and, for the first ``nsingle`` points, one point per call."""
    from gearrep.tca import ContactPoints, solve_contact

    def one(i):
        kwi = {k: (v[i : i + 1] if isinstance(v, np.ndarray) else v) for k, v in kw.items()}
        return solve_contact(pair, phi[i : i + 1], st[i : i + 1], formulation=form, **kwi)

    with np.errstate(all="ignore"):
        put(res, tag + ":vec", solve_contact(pair, phi, st, formulation=form, **kw))
        put(res, tag + ":single", ContactPoints.concatenate([one(i) for i in range(nsingle)]))


def readme_cases(res):
    from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
    from gearrep.tca import GearPair, Misalignment, default_start
    from gearrep.units import DEG

    g1, g2 = InvoluteGearData(52, 1.0, 20 * DEG, 11.42), InvoluteGearData(72, 1.0, 20 * DEG, 11.42)
    f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(0.002857))
    pair = GearPair(f1, f2, 52, 72, standard_centre_distance(g1, g2), misalignment=Misalignment(d_gamma_out=0.05 * DEG))
    p = 2 * np.pi / 52
    phi = -np.pi / 104 + np.random.default_rng(7).uniform(-0.6 * p, 0.6 * p, 3000)
    for form in ("reduced", "conventional"):
        cases(res, "readme-" + form, pair, phi, default_start(pair, phi, form), form, {}, 300)
        st = default_start(pair, phi[:500], form)
        cases(res, "readme-v1-" + form, pair, phi[:500], st, form, {"v1": np.linspace(-5, 5, 500)}, 100)
        st = default_start(pair, phi[:300], form)
        cases(res, "readme-numjac-" + form, pair, phi[:300], st, form, {"jacobian": "numeric"}, 50)


def thesis_cases(res):
    """Table 10's random starts over both flanks (divergent, singular and off-flank rows too)."""
    from gearrep.replications.temirkhan2023 import convergence as tc
    from gearrep.tca import CONVENTIONAL_VARIANTS, REDUCED_VARIANTS, solve_variant

    settings, design = study("temirkhan2023")
    tp, _, ref, st = tc.table10_starts(settings, design)
    st = st[:2000]
    kw = {"tol": settings["tol"], "maxiter": settings["maxiter"]}
    for form in ("reduced", "conventional"):
        w = 2 if form == "reduced" else 5
        cases(res, "t10-" + form, tp, np.full(len(st), ref.phi1), st[:, :w], form, kw, 200)
    for v in tuple(REDUCED_VARIANTS) + tuple(CONVENTIONAL_VARIANTS):
        with np.errstate(all="ignore"):
            x, status, it = solve_variant(
                tp, ref.phi1, st[:1000], v, drop=ref.drop, margin=settings["domain_margin"], **kw
            )[:3]
        res[f"t10-variant-{v}:x"], res[f"t10-variant-{v}:status"], res[f"t10-variant-{v}:iterations"] = x, status, it


def novikov_catt_cases(res):
    """Seed 002's profile-crowned Novikov-Wildhaber pair and seed 004's CATT pair (as the bench)."""
    from gearrep.replications.litvin2000 import geometry as ng
    from gearrep.replications.ma2021.assembly import PRIMARY
    from gearrep.replications.ma2021.bench import BENCH_DESIGN
    from gearrep.replications.ma2021.design import merged_params
    from gearrep.surfaces import catt as ca
    from gearrep.surfaces.novikov import aligned_start
    from gearrep.tca import Misalignment
    from gearrep.units import ARCMIN

    settings, design = study("litvin2000")
    mis = Misalignment(d_gamma_out=settings["misalignment_arcmin"] * ARCMIN)
    Pn, an, beta, lead = ng.basics(design)
    rho_c, rho_t = design["rho_c_times_Pn"] / Pn, design["rho_t_times_Pn"] / Pn
    pair = ng.make_pair(
        design, rho_c, rho_t, an, lead, beta, tol=settings["tol"], hand=settings["pinion_hand"], misalignment=mis
    )
    per = 2 * np.pi / pair.n1
    rng = np.random.default_rng(3)
    phi = rng.uniform(-0.5 * per, 0.5 * per, 200)
    kw = {"tol": settings["tol"], "maxiter": settings["maxiter"]}
    cases(res, "novikov", pair, phi, aligned_start(pair, phi), "conventional", kw, 20)
    settings, design = study("ma2021")
    q = merged_params(settings, design)
    mesh = ca.assemble(design.by_name(BENCH_DESIGN), PRIMARY[0], q)
    lim = ca.path_limits(mesh)
    phi = rng.uniform(lim["phi1_lo"], lim["phi1_hi"], 1000)
    st = ca.starts(mesh, phi, q["start_offset_mm"])
    cases(res, "catt", mesh.gear_pair, phi, st, "conventional", {"tol": q["tol"], "maxiter": q["maxiter"]}, 100)


def dump(out):
    """Solve the cases of the module docstring with the gearrep of ``sys.argv[2]``; save to ``out``."""
    import gearrep

    if not gearrep.__file__.startswith(str(Path(sys.argv[2]).resolve())):
        raise SystemExit(f"gearrep imported from {gearrep.__file__}, not from {sys.argv[2]}")
    res = {}
    readme_cases(res)
    thesis_cases(res)
    novikov_catt_cases(res)
    np.savez(out, **res)


def compare(a, b) -> bool:
    """Compare two dumps (see the module docstring); prints a summary, returns True if they agree."""
    A, B = np.load(a), np.load(b)
    if sorted(A.files) != sorted(B.files):
        raise SystemExit(f"the dumps hold different cases: {sorted(set(A.files) ^ set(B.files))}")
    worst = {"solution": 0.0, "residual/condition": 0.0}
    bad, identical = [], 0
    for k in A.files:
        x, y = A[k], B[k]
        identical += bool(np.array_equal(x, y, equal_nan=x.dtype.kind == "f"))
        if k.endswith(("status", "iterations")):
            if not np.array_equal(x, y):
                bad.append((k, f"{int(np.sum(x != y))} rows differ"))
            continue
        x, y = x.astype(float), y.astype(float)
        m = np.isfinite(x) & np.isfinite(y)
        loose = k.endswith(("residual", "condition"))  # reported only: rounding-level quantities
        rel = np.abs(x[m] - y[m]) / np.maximum(np.abs(x[m]), 1e-300 if loose else 1.0)
        d = float(np.max(rel, initial=0.0))
        key = "residual/condition" if loose else "solution"
        worst[key] = max(worst[key], d)
        if not np.array_equal(np.isnan(x), np.isnan(y)):
            bad.append((k, "NaN pattern differs"))
        elif not loose and d > 1e-12:
            bad.append((k, f"relative difference {d:.2e}"))
    print(
        f"{len(A.files)} arrays, {identical} bit-identical; largest relative difference: solutions and geometry "
        f"{worst['solution']:.2e}, residuals and condition numbers {worst['residual/condition']:.2e}; "
        f"mismatches: {bad or 'none'}"
    )
    return not bad


def main(argv):
    if len(argv) >= 3 and argv[0] == "dump":
        dump(argv[2])
        return 0
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] != "--keep"):
        print(__doc__)
        return 2
    out = Path(argv[3]) if len(argv) == 4 else Path(tempfile.mkdtemp(prefix="compare_solves_"))
    out.mkdir(parents=True, exist_ok=True)
    files = []
    for tag, srcdir in (("old", argv[0]), ("new", argv[1])):
        f = out / f"{tag}.npz"
        subprocess.run([sys.executable, __file__, "dump", srcdir, str(f)], check=True)
        files.append(f)
    return 0 if compare(*files) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
