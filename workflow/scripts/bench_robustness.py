"""Start robustness of the library's TCA (Snakemake script of the `bench` target; not in the
default run): robustness.csv, one row per gear family, formulation and assembly (aligned or
misaligned; the involute, bevel, Novikov-Wildhaber, CATT and hob-cut pairs of the replications):
starts (u1, v1) uniform over flank 1 at five angles of the meshing cycle, solved by
gearrep.tca.robust_contact (the hob-cut pair: gearrep.tca.robust_envelope_points), classified against the reference contact traced by continuation from
the family's nominal start and verified (gearrep.tca.reference_contacts); correct, wrong-root and
not-converged percentages (and the correct percentage of the same starts without the strategy's
restarts: start_alone_correct_pct), mean Newton iterations and the cost per solve (wall seconds of the
batch, and in elements of the fixed reference kernel timed in the same run, which holds on a
loaded machine)."""

import time
from importlib import import_module
from pathlib import Path

import numpy as np
import pandas as pd

from gearrep import benchmark, published, tca
from gearrep.replications import load as load_study
from gearrep.settings import defaults
from gearrep.tca import default_start, reference_contacts, robust_contact, start_robustness

smk = snakemake  # noqa: F821  (provided by Snakemake)
N_PER_ANGLE = int(smk.params.n_per_angle)
PUBLISHED = Path(smk.input.published_dir)


def study(name):
    """Default settings and design data of a replication (as its jobs get them)."""
    mod = load_study(name)
    design = mod.params_from_published(published.load(PUBLISHED, [str(PUBLISHED / f) for f in mod.DESIGN_DATA]))
    return defaults(mod.SETTINGS), design


def element_seconds() -> float:
    """Seconds per element of the reference kernel (gearrep.benchmark.reference_kernel), now."""
    n = 200_000
    t0 = time.perf_counter()
    benchmark.reference_kernel(n)
    return (time.perf_counter() - t0) / n


def cases():
    """Every family's robustness cases with the settings of its study."""
    for name in ("temirkhan2023", "litvin2000", "ma2021", "hobcut_tca"):
        settings, design = study(name)
        for case in import_module(f"gearrep.replications.{name}.bench").robustness_cases(settings, design):
            yield settings, case


def envelope_row(settings, case, row, rng):
    """The row of a pair of generated envelopes (9-unknown TCA): reference by continuation from the
    solved start and the physical tangency (gearrep.tca.hobbed_physical_contact), starts (l_p, psi_p)
    uniform over the case's pinion box solved by gearrep.tca.robust_envelope_points."""
    pair, phi, tol, nominal = case["pair"], case["phi1"], case["tol"], case["nominal"]
    ref = tca.hobbed_physical_contact(pair, tca.trace_envelope_path(pair, case["start"], phi, tol=tol), tol=tol)
    if not ref.converged.all():
        return row | {"reference": f"no verified reference contact (status {list(ref.status_name)})"}

    def solve(p, ph, u1, v1, fallback=True):
        return tca.robust_envelope_points(p, ph, u1, v1, nominal, tol=tol, fallback=fallback)

    kw = dict(box=case["box"], classify=tca.classify_envelope_points)
    seed = rng.integers(2**32)
    r = start_robustness(pair, ref, N_PER_ANGLE, np.random.default_rng(seed), solve, **kw)
    alone = start_robustness(
        pair, ref, N_PER_ANGLE, np.random.default_rng(seed), lambda *a: solve(*a, fallback=False), **kw
    )
    return row | r | {"start_alone_correct_pct": alone["correct_pct"]}


rows = []
for settings, case in cases():
    pair, phi, nominal = case["pair"], case["phi1"], case.get("nominal")
    tol, maxiter = case.get("tol", settings.get("tol")), case.get("maxiter", settings.get("maxiter"))
    rng = np.random.default_rng([int(settings.get("seed", 0)), 31, len(rows)])
    if "start" in case:  # generated envelopes: the 9-unknown TCA
        el_before = element_seconds()
        r = envelope_row(
            settings,
            case,
            dict(family=case["family"], formulation="envelope pair (9 unknowns)", misalignment=case["misalignment"]),
            rng,
        )
        el = 0.5 * (el_before + element_seconds())
        r |= dict(
            elements_per_solve=r.get("seconds_per_solve", np.nan) / el,
            phi1_min_rad=float(phi.min()),
            phi1_max_rad=float(phi.max()),
            reference=r.get("reference", "traced by continuation from the solved start; physical tangency"),
            load_average=benchmark.load_average(),
        )
        rows.append(r)
        print(r["family"], r["misalignment"], f"{r.get('correct_pct', np.nan):.1f} %", flush=True)
        continue
    for form in case.get("formulations", ("reduced", "conventional")):
        row = dict(family=case["family"], formulation=form, misalignment=case["misalignment"])
        start = (default_start(pair, phi[2:3], form) if nominal is None else nominal(pair, phi[2:3]))[0]
        try:
            ref = reference_contacts(pair, phi, start, formulation=form, nominal=nominal, tol=tol)
        except ValueError as err:  # a failed row is NaN, with the reason
            rows.append(row | {"reference": str(err)})
            continue

        def solve(p, ph, u1, v1, form=form, fallback=True):
            kw = dict(formulation=form, tol=tol, maxiter=maxiter, nominal=nominal, fallback=fallback)
            return robust_contact(p, ph, u1, v1, **kw)

        seed = rng.integers(2**32)
        el_before = element_seconds()
        r = start_robustness(pair, ref, N_PER_ANGLE, np.random.default_rng(seed), solve)
        el = 0.5 * (el_before + element_seconds())
        alone = start_robustness(
            pair, ref, N_PER_ANGLE, np.random.default_rng(seed), lambda *a: solve(*a, fallback=False)
        )
        r["start_alone_correct_pct"] = alone["correct_pct"]
        rows.append(
            row
            | r
            | dict(
                elements_per_solve=r["seconds_per_solve"] / el,
                phi1_min_rad=float(phi.min()),
                phi1_max_rad=float(phi.max()),
                reference="traced by continuation from the nominal start; verified",
                load_average=benchmark.load_average(),
            )
        )
        print(row["family"], form, row["misalignment"], f"{r['correct_pct']:.1f} %", flush=True)
out = Path(smk.output[0])
out.parent.mkdir(parents=True, exist_ok=True)
pd.DataFrame(rows).to_csv(out, index=False)
Path(smk.log[0]).write_text(f"robustness rows {len(rows)}, {N_PER_ANGLE} starts per angle, at {time.ctime()}\n")
