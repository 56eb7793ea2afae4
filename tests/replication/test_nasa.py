"""Seed 002 (NASA CR-2000-209415, Novikov-Wildhaber gears): the replication in its fast setting.

Runs :func:`gearrep.replications.nasa.run` once with ``FAST_PARAMS`` and checks the issue's
acceptance items (curvatures by two methods agree to 1e-8, aligned TE zero to 1e-6 arcsec),
regression values of our own numbers, and the expected status of every published seed-002
value and claim (tests/replication/expected_nasa.csv, with the reason)."""

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from gearrep.replications import nasa

EXPECTED = Path(__file__).with_name("expected_nasa.csv")


@pytest.fixture(scope="module")
def tables(published):
    return nasa.run({"design": nasa.design_from_published(published), **nasa.FAST_PARAMS})


@pytest.fixture(scope="module")
def records(tables, published):
    return nasa.checks(tables, published)


def test_every_published_item_has_its_expected_status(records, published):
    exp = pd.read_csv(EXPECTED)
    ids = set(published.values.loc[published.values["seed"] == "002", "id"]) | set(
        published.claims.loc[published.claims["seed"] == "002", "id"])
    assert set(records["id"]) == ids
    assert set(exp["id"]) == ids, "expected_nasa.csv must list every seed-002 value and claim"
    assert exp["reason"].notna().all() and (exp["reason"].str.len() > 5).all()
    got = records.set_index("id")["status"]
    wrong = {i: (s, got[i]) for i, s in zip(exp["id"], exp["status"]) if got[i] != s}
    assert not wrong, f"status changed (expected, got): {wrong}"


def test_curvatures_two_methods_agree(tables):
    cur = tables["curvatures"]
    assert (cur["max_rel_diff"] < 1e-8).all()
    assert (tables["path_curvatures"].groupby("member")[["kappa_I_per_in", "kappa_II_per_in"]].agg(np.ptp) < 1e-10).all().all()


def test_aligned_pair_has_zero_te(tables):
    s = tables["te_single"]
    al = s[s["case"] == "aligned"]
    assert (al["status"] == "converged").all()
    assert np.max(np.abs(al["te_arcsec"])) < 1e-6
    assert np.max(np.abs(al["u1_in"])) < 1e-8


def test_regression_own_numbers(tables):
    cur = tables["curvatures"].set_index(["case", "member"])
    np.testing.assert_allclose(cur.loc[("design", "pinion"), ["kappa_I_per_in", "kappa_II_per_in"]].to_numpy(float),
                               [0.012537886531791553, 1.5604994926080131], rtol=1e-9)
    np.testing.assert_allclose(cur.loc[("design", "gear"), ["kappa_I_per_in", "kappa_II_per_in"]].to_numpy(float),
                               [-0.008300305907457006, 0.5938938106217597], rtol=1e-9)
    ell = tables["ellipse"].set_index(["version", "zone", "case"])
    np.testing.assert_allclose(ell.loc[(3, "single", "design"), ["major_2a_in", "minor_2b_in", "area_in2"]].to_numpy(float),
                               [1.0341912583806292, 0.04504746886939616, 0.03658989285208967], rtol=1e-9)
    np.testing.assert_allclose(ell.loc[(1, "single", "design"), "major_2a_in"], 0.28353576678746956, rtol=1e-9)
    te = tables["te_summary"].set_index("case")
    assert te.loc["dgamma_plus", "te_max_arcsec"] == pytest.approx(40.4813, abs=2e-3)
    assert te.loc["dgamma_minus", "te_max_arcsec"] == pytest.approx(40.4540, abs=2e-3)
    assert te.loc["dlambda_helix_plus", "te_max_arcsec"] == pytest.approx(45.9095, abs=2e-3)
    assert te.loc["dE_0.001in", "te_max_arcsec"] < 1e-6
    sens = tables["sensitivity"]
    tca3 = sens[(sens["version"] == 3) & (sens["step"] == "0.001in") & (sens["method"] == "tca")].iloc[0]
    assert tca3["delta_alpha_deg"] == pytest.approx(0.670536, abs=1e-5)


def test_worm_ground_pinion(tables):
    w = tables["worm_summary"].set_index("case")
    assert w.loc["worm_aligned", "all_converged"]
    assert w.loc["worm_aligned", "te_max_arcsec"] == pytest.approx(8.5011, abs=5e-3)
    assert w.loc["worm_dgamma_plus", "te_max_arcsec"] == pytest.approx(12.9614, abs=5e-3)
    assert w.loc["worm_dlambda_plus", "te_max_arcsec"] == pytest.approx(16.5607, abs=5e-3)
    single = tables["worm_single"]
    al = single[(single["case"] == "worm_aligned") & (single["status"] == "converged")]
    # TE vanishes at the design point (phi1 = 0, feed l = 0, no plunge there)
    assert abs(al.loc[al["phi1_rad"].abs().idxmin(), "te_arcsec"]) < 1e-6


def test_bench_case_runs(published):
    case = nasa.bench_cases({"design": nasa.design_from_published(published)})["te_max"]
    assert case["error_unit"] == "arcsec" and case["error_target"] == pytest.approx(5e-4)
    res = case["run"]({"te_points_per_cycle": 8, "tol": 1e-10})
    assert res == pytest.approx(40.4813, abs=1e-3)


def test_params_are_validated(published):
    d = nasa.design_from_published(published)
    with pytest.raises(ValueError, match="design"):
        nasa.validate_params({})
    with pytest.raises(ValueError, match="unknown key"):
        nasa.validate_params({"design": d, "te_points": 5})
    with pytest.raises(ValueError, match="face_width_over_axial_pitch"):
        nasa.validate_params({"design": d, "face_width_over_axial_pitch": 0.5})
    with pytest.raises(ValueError, match="pinion_hand"):
        nasa.validate_params({"design": d, "pinion_hand": "up"})
    with pytest.raises(ValueError, match="tol"):
        nasa.validate_params({"design": d, "tol": 1e-3})
