"""Replication of seed 004 (Ma et al. 2021, CATT gears) with the test settings (study_settings:
declared values, config/config.yaml, config/test.yaml).

Every claim of claims_004.csv keeps the status on file in expected_ma2021.csv (with its reason), and
our own numbers are pinned: the pitch-point ellipse against the closed form (acceptance 1e-6,
actually ~1e-13), the TCA path (middle section, zero TE), and regression values along the path."""

from __future__ import annotations

import dataclasses
import io
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from conftest import study_settings

from gearrep import checks as C
from gearrep import settings as S
from gearrep.replications import ma2021

#: statuses and values of the studies: run again by the portability passes (tests/README.md)
pytestmark = pytest.mark.numerics

ROOT = Path(__file__).parents[2]
EXPECTED = pd.read_csv(Path(__file__).with_name("expected_ma2021.csv"))


@pytest.fixture(scope="module")
def pub(published):
    return published


@pytest.fixture(scope="module")
def design(pub):
    return ma2021.params_from_published(pub)


def _through_csv(tables):
    """Tables as the workflow's checks read them (written with to_csv(index=False), read back)."""
    return {k: pd.read_csv(io.StringIO(v.to_csv(index=False))) for k, v in tables.items()}


@pytest.fixture(scope="module")
def tables(design):
    return _through_csv(ma2021.run(study_settings("ma2021"), design))


@pytest.fixture(scope="module")
def outputs(tables, pub):
    return ma2021.checks(tables, pub)


@pytest.fixture(scope="module")
def records(outputs):
    return C.validate_checks(outputs["checks"])


def test_every_claim_has_a_record(records, pub):
    ids = set(pub.claims.loc[pub.claims["seed"] == "004", "id"])
    assert set(records["id"]) == ids
    assert set(EXPECTED["id"]) == ids
    assert (EXPECTED["reason"].str.len() > 10).all()


@pytest.mark.parametrize("cid", EXPECTED["id"].tolist())
def test_expected_status(records, cid):
    exp = EXPECTED.set_index("id").loc[cid]
    got = records.set_index("id").loc[cid]
    assert got["status"] == exp["status"], f"{cid}: {got['status']} != {exp['status']} ({exp['reason']})\n{got['note']}"
    assert len(str(got["note"])) > 20  # the numbers behind the verdict


def test_pitch_point_closed_form(tables, pub):
    """Acceptance: S at the pitch point, full pipeline vs closed form 2 pi delta / sqrt(k_ax k_prof), 1e-6."""
    pp = tables["pitch_point"]
    assert (pp["status"] == "converged").all()
    assert pp["S_rel_err"].abs().max() < 1e-9
    # independent closed form for the sec 4 pair, typed from the design data
    d, al, m, R1, R2, RT = 0.00632, np.radians(20), 8.0, 8.0 * 19 / 2, 8.0 * 31 / 2, 500.0
    q = np.pi * m / 4
    k_ax = np.cos(al) * (1 / (RT - q) - 1 / (RT + q))
    k_pr = (1 / R1 + 1 / R2) / np.sin(al)
    S = 2 * np.pi * d / np.sqrt(k_ax * k_pr)
    got = pp.loc[pp["design"] == "sec4_3d_model", "S_pipeline_mm2"].to_numpy()
    np.testing.assert_allclose(got, S, rtol=1e-10)
    np.testing.assert_allclose(got, 23.1933403, rtol=1e-8)  # regression


def test_path_middle_section_zero_te(tables):
    c = tables["cycle"]
    on = c[c["on_path"]]
    assert (on["status"] == "converged").all()
    assert on["z_mm"].abs().max() < 1e-9
    assert on["te_arcsec"].abs().max() < 1e-6
    assert on["S_rel_diff_closed_form"].abs().max() < 1e-10
    assert (on["S_mm2"] / on["S_tensor_mm2"] - 1).abs().max() < 1e-10  # core library vs tensor route
    assert set(np.round(on["sigma_true_deg"], 6)) == {90.0}
    # seed 004 eq (23)-(24) with the true sigma (Litvin) give the same relative curvatures: 2A, 2B
    assert (2 * on["A_eq23"] / on["kappa_long_per_mm"] - 1).abs().max() < 1e-10
    assert (2 * on["B_eq24"] / on["kappa_short_per_mm"] - 1).abs().max() < 1e-10


def test_regression_values(tables):
    c = tables["cycle"]

    def S(design, pair, reading, phi, col="S_mm2"):
        r = c[
            (c["design"] == design)
            & (c["pair"] == pair)
            & (c["reading"] == reading)
            & np.isclose(c["phi_paper_deg"], phi)
        ]
        assert len(r) == 1
        return float(r[col].iloc[0])

    assert S("fig12_module_sweep_m8", "B", "R1", 0.0) == pytest.approx(23.58382805, rel=1e-8)
    assert S("fig12_module_sweep_m8", "B", "R1", -10.0) == pytest.approx(19.68088337, rel=1e-8)
    assert S("fig12_module_sweep_m8", "B", "R1", 10.0) == pytest.approx(23.25619984, rel=1e-8)
    assert S("fig12_module_sweep_m8", "B", "R1", 13.0, "S_clipped_mm2") == pytest.approx(21.19, rel=2e-3)
    d = tables["designs"].set_index(["design", "pair", "reading"])
    assert d.loc[("fig12_module_sweep_m8", "B", "R1"), "path_start_deg"] == pytest.approx(-14.108096, abs=1e-6)
    assert d.loc[("fig12_module_sweep_m8", "B", "R1"), "path_end_deg"] == pytest.approx(13.449691, abs=1e-6)
    th = tables["thickness"].set_index(["R_T_mm", "section_mm"])["thickness_mm"]
    assert th[(300.0, 45.0)] == pytest.approx(12.422502, abs=1e-6)
    assert th[(800.0, 0.0)] == pytest.approx(4 * np.pi, abs=1e-10)


def test_verdicts_reported_for_every_reading(outputs):
    v = outputs["claim_readings"]
    per = v.groupby("id").size()
    assert (per == 4).all()
    assert v.groupby("id")["primary"].sum().eq(1).all()
    assert set(ma2021.CHECK_OUTPUTS) == set(outputs)


def test_every_job_writes_only_its_tables(tables):
    """One job per table: each job's tables are the declared ones (run_jobs checks it) and
    together they are every table the checks and figures read."""
    assert set(tables) == {n for j in ma2021.JOBS.values() for n in j.tables}
    assert {p for j in ma2021.JOBS.values() for p in j.tables.values()} == {f"ma2021/{n}.csv" for n in tables}


def _with_param(pub, example, parameter, value):
    p = pub.params.copy()
    p.loc[(p["seed"] == "004") & (p["example"] == example) & (p["parameter"] == parameter), "value"] = value
    return dataclasses.replace(pub, params=p)


def test_bad_design_data_and_settings_are_refused(pub, design):
    with pytest.raises(ValueError, match="elastic_approach"):
        ma2021.params_from_published(_with_param(pub, "figs12-15_common", "elastic_approach", -1.0))
    with pytest.raises(ValueError, match="tooth_line_radius"):
        ma2021.params_from_published(_with_param(pub, "sec4_3d_model", "tooth_line_radius", 10.0))
    with pytest.raises(S.SettingError, match="ma2021.bogus"):
        S.resolve(ma2021.SETTINGS, {"bogus": 1}, where="ma2021")
    with pytest.raises(S.SettingError, match="ma2021.maxiter"):
        S.resolve(ma2021.SETTINGS, {"maxiter": 0}, where="ma2021")
    good = study_settings("ma2021")
    ma2021.validate(good, design)
    bad = [
        ({"section_check": {**good["section_check"], "design": "nope"}}, "ma2021.section_check.design"),
        ({"gap_check": {**good["gap_check"], "design": "nope"}}, "ma2021.gap_check.design"),
        ({"thickness": {**good["thickness"], "sections_mm": [0.0, 150.0]}}, "ma2021.thickness.sections_mm"),
        ({"near_top_eval_deg": 20.0}, "ma2021.near_top_eval_deg"),
        ({"near_top_deg": 40.0}, "ma2021.near_top_deg"),
    ]
    for change, key in bad:
        with pytest.raises(S.SettingError, match=key):
            ma2021.run({**good, **change}, design, jobs=["settings"])


def test_bench_cases_contract(design):
    """bench_cases follows workflow/scripts/bench_replication.py: knob settings, a reference, an error
    that is 0 for the reference itself and small for the configured setting."""
    cases = ma2021.bench_cases(study_settings("ma2021"), design)
    assert set(cases) == {"tca_S", "truncation"}
    for c in cases.values():
        assert {"run", "settings", "reference", "error", "error_unit", "error_target", "current"} <= set(c)
        assert all(list(s) == list(c["reference"]) for s in c["settings"])
        assert list(c["current"]) == list(c["reference"])
    c = cases["tca_S"]
    ref = c["run"](c["reference"])
    assert (ref["status"] == "converged").all()
    assert c["error"](ref, ref) == 0.0
    assert c["error"](c["run"](c["current"]), ref) < c["error_target"]


def test_workflow_setting_keeps_expected_statuses(pub, design):
    """The settings of config/config.yaml (what the workflow runs) give the statuses on file too."""
    import yaml

    cfg = (yaml.safe_load((ROOT / "config" / "config.yaml").read_text()) or {}).get("ma2021")
    t = _through_csv(ma2021.run(S.resolve(ma2021.SETTINGS, cfg, where="ma2021"), design))
    got = C.validate_checks(ma2021.checks(t, pub)["checks"]).set_index("id")["status"]
    exp = EXPECTED.set_index("id")["status"]
    assert got.sort_index().equals(exp.sort_index()), (got[got != exp.reindex(got.index)]).to_dict()
