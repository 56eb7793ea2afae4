"""The robust start strategy (gearrep.tca.robust_contact; gearrep.tca.robust_envelope_points for
the hob-cut pair) against the reference contact traced by continuation and verified
(gearrep.tca.reference_contacts): 100 % correct roots from starts uniform over flank 1 for every
pair of the robustness table, aligned and misaligned, each formulation; a small sample here, the full table (results/bench/robustness.csv, >= 1000 starts
per row) under the ``bench`` marker."""

import numpy as np
import pandas as pd
import pytest
from conftest import run_target

from gearrep.replications import load
from gearrep.settings import defaults
from gearrep.tca import (
    ROBUSTNESS_COLUMNS,
    classify_contacts,
    default_start,
    project_starts,
    reference_contacts,
    robust_contact,
    solve_contact,
    start_robustness,
)


@pytest.fixture(scope="module")
def cases(published):
    """(settings, case) of every row of the robustness table: the thesis's involute and bevel
    pairs, the Novikov-Wildhaber and the CATT pair, aligned and misaligned."""
    from importlib import import_module

    out = []
    for name in ("temirkhan2023", "litvin2000", "ma2021"):
        mod = load(name)
        s = defaults(mod.SETTINGS)
        design = mod.params_from_published(published)
        out += [(s, c) for c in import_module(f"gearrep.replications.{name}.bench").robustness_cases(s, design)]
    return out


#: rows of the robustness table: 10 thesis pairs, 2 Novikov-Wildhaber, 2 CATT
N_CASES = 14


def test_every_family_is_in_the_table(cases):
    assert len(cases) == N_CASES
    families = " ".join(c["family"] for _, c in cases)
    for word in ("spur", "helical", "straight bevel", "convex1", "concave1", "Novikov", "CATT"):
        assert word in families
    assert {c["misalignment"] == "aligned" for _, c in cases} == {True, False}


@pytest.mark.parametrize("i", range(N_CASES))
def test_all_starts_reach_the_reference(cases, i):
    s, c = cases[i]
    pair, phi, nominal = c["pair"], c["phi1"], c.get("nominal")
    tol, maxiter = c.get("tol", s["tol"]), c.get("maxiter", int(s["maxiter"]))
    for formulation in c.get("formulations", ("reduced", "conventional")):
        start = (default_start(pair, phi[2:3], formulation) if nominal is None else nominal(pair, phi[2:3]))[0]
        ref = reference_contacts(pair, phi, start, formulation=formulation, nominal=nominal, tol=tol)
        row = start_robustness(
            pair,
            ref,
            10,
            np.random.default_rng([41, i]),
            lambda p, ph, u1, v1, f=formulation: robust_contact(
                p, ph, u1, v1, formulation=f, tol=tol, maxiter=maxiter, nominal=nominal
            ),
        )
        assert set(row) == set(ROBUSTNESS_COLUMNS)
        assert row["n_starts"] == 50
        assert row["correct_pct"] == 100.0, (c["family"], c["misalignment"], formulation, row)


@pytest.fixture(scope="module")
def envelope_cases(published):
    """(settings, case) of the hob-cut pair's rows (9-unknown envelope TCA)."""
    from gearrep.replications.hobcut_tca.bench import robustness_cases

    mod = load("hobcut_tca")
    s = defaults(mod.SETTINGS)
    return [(s, c) for c in robustness_cases(s, mod.params_from_published(published))]


@pytest.mark.parametrize("i", range(2))
def test_hob_cut_starts_reach_the_reference(envelope_cases, i):
    """The hob-cut pair, aligned and with the Table 5.4 example's errors: starts uniform over the
    pinion flank's box reach the physical contact traced by continuation."""
    from gearrep import tca

    s, c = envelope_cases[i]
    pair, phi, tol = c["pair"], c["phi1"], c["tol"]
    ref = tca.hobbed_physical_contact(pair, tca.trace_envelope_path(pair, c["start"], phi, tol=tol), tol=tol)
    assert ref.converged.all()
    row = start_robustness(
        pair,
        ref,
        10,
        np.random.default_rng([43, i]),
        lambda p, ph, l_p, psi_p: tca.robust_envelope_points(p, ph, l_p, psi_p, c["nominal"], tol=tol),
        box=c["box"],
        classify=tca.classify_envelope_points,
    )
    assert row["n_starts"] == 50
    assert row["correct_pct"] == 100.0, (c["misalignment"], row)


def test_the_spiral_pair_needs_the_strategy(cases):
    """Plain reduced Newton from the same kind of starts misses the spiral pair's contact often
    (the reason for the strategy): the classification sees those as not converged, not correct."""
    s, c = next((s, c) for s, c in cases if "convex1" in c["family"] and c["misalignment"] == "aligned")
    pair, phi = c["pair"], c["phi1"]
    ref = reference_contacts(pair, phi, default_start(pair, phi[2:3], "reduced")[0], formulation="reduced")
    rng = np.random.default_rng(5)
    n = 200
    u1 = rng.uniform(pair.lower1[0], pair.upper1[0], n)
    v1 = rng.uniform(pair.lower1[1], pair.upper1[1], n)
    idx = np.repeat(np.arange(len(phi)), n // len(phi))
    with np.errstate(all="ignore"):
        plain = solve_contact(pair, phi[idx], np.column_stack([u1, v1]), damped=False, tol=s["tol"])
    out = classify_contacts(plain, ref.take(idx))
    assert (out == "correct").mean() < 0.9
    assert set(out) <= {"correct", "wrong_root", "not_converged"}
    robust = robust_contact(pair, phi[idx], u1, v1, tol=s["tol"])
    assert (classify_contacts(robust, ref.take(idx)) == "correct").all()
    # the projected start alone (no restart) already does better than plain Newton, not all
    alone = classify_contacts(robust_contact(pair, phi[idx], u1, v1, tol=s["tol"], fallback=False), ref.take(idx))
    assert (out == "correct").mean() < (alone == "correct").mean() < 1.0


def test_projection_stays_on_flank_1(cases):
    pair = next(c for _, c in cases if "concave1" in c["family"])["pair"]
    u1 = np.array([-1.0, 0.5 * (pair.lower1[0] + pair.upper1[0]), 10.0, np.nan])
    v1 = np.array([0.0, 1e3, -1e3, np.nan])
    pu, pv = project_starts(pair, 0.0, u1, v1)
    assert np.all((pu >= pair.lower1[0]) & (pu <= pair.upper1[0]))
    assert np.all((pv >= pair.lower1[1]) & (pv <= pair.upper1[1]))


def test_bad_input_is_refused_before_work(cases):
    pair = cases[0][1]["pair"]
    with pytest.raises(ValueError, match="formulation"):
        robust_contact(pair, 0.0, [1.0], [0.0], formulation="other")
    with pytest.raises(ValueError, match="same length"):
        robust_contact(pair, 0.0, [1.0, 2.0], [0.0])
    with pytest.raises(ValueError, match="increasing"):
        reference_contacts(pair, np.array([0.1, 0.0]), default_start(pair, 0.0)[0])


@pytest.mark.bench
def test_robustness_table_full_size(tmp_path_factory):
    """results/bench/robustness.csv: every family, formulation and assembly row 100 % correct from
    at least 1000 starts, the spiral pair on both flank pairs."""
    t = pd.read_csv(run_target(tmp_path_factory.mktemp("robust"), "results/bench/robustness.csv"))
    assert len(t) == 26
    assert (t["n_starts"] >= 1000).all()
    assert (t["correct_pct"] == 100.0).all(), t[t["correct_pct"] != 100.0]
    assert t["family"].str.contains("concave1").any() and t["family"].str.contains("convex1").any()
