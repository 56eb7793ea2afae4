"""`gearrep ltca` on design files: the files it writes, the pitch position solved and its pressure
against ISO 6336-2's closed form for an unmodified spur pair (within the validation study's
tolerance), the loads balancing the torque at every position, the library route's numbers, the
CATT example, and the refusals of bad load and material input (exit 2, one line, no output
directory) and of the families the loaded analysis does not take."""

from __future__ import annotations

import json
import math

import numpy as np
import pandas as pd
import pytest
import yaml
from _command import run, write
from conftest import ROOT

from gearrep import ltca
from gearrep.cli.design import check, json_schema
from gearrep.cli.families import REGISTRY, register
from gearrep.cli.family import Design, PairFamily
from gearrep.cli.keys import ANALYSIS, MISALIGNMENT, head
from gearrep.cli.loaded import pitch_position, positions_table
from gearrep.replications.ltca.checks import PRESSURE_RTOL

EXAMPLES = ROOT / "examples"
SPUR = EXAMPLES / "spur.yaml"
#: relative tolerance of the load sums: the contact problem balances the torque exactly at every
#: iterate (the validation's load-balance bound, docs/ltca.md)
BALANCE_RTOL = 1e-9


def example(name) -> dict:
    return yaml.safe_load((EXAMPLES / name).read_text())


@pytest.fixture(scope="module")
def spur_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("ltca") / "spur"
    rc, stdout, err = run("ltca", SPUR, "-o", out, "--no-progress")
    assert rc == 0, err
    assert "41 of 41 positions converged" in stdout
    return out


def _iso_pitch_stress(doc) -> float:
    """ISO 6336-2's sigma_H0 (Z_eps = Z_beta = 1) of the example spur pair from its file's numbers."""
    m, b = doc["module_mm"], doc["face_width_mm"]
    z1, z2 = doc["pinion"]["teeth"], doc["gear"]["teeth"]
    alpha = math.radians(doc["pressure_angle_deg"])
    d1 = m * z1
    F_t = 2000.0 * doc["load"]["torque_Nm"] / d1
    mat = doc["pinion"]["material"]
    Z_E = ltca.iso.elasticity_factor(mat["E_MPa"], mat["poisson"])
    return ltca.iso.pitch_point_stress_MPa(F_t, d1, b, z2 / z1, ltca.iso.zone_factor(alpha), Z_E)


def test_ltca_writes_the_tables_figures_summary_page_and_sidecars(spur_run):
    files = {p.relative_to(spur_run).as_posix() for p in spur_run.rglob("*") if p.is_file()}
    results = {f for f in files if not f.endswith(".prov.json")}
    assert results == {
        "ltca_positions.csv",
        "ltca_summary.csv",
        "ltca_pressure_map.csv",
        "summary.html",
        "design.yaml",
        "figures/loaded_transmission_error.png",
        "figures/load_sharing.png",
        "figures/pressure_pattern.png",
    }
    for f in results:
        prov = json.loads((spur_run / f"{f}.prov.json").read_text())
        assert prov["command"] == "ltca" and prov["file"] == f.split("/")[-1]
    s = pd.read_csv(spur_run / "ltca_summary.csv")
    assert len(s) == 1
    needed = {
        "torque_Nm",
        "normal_load_N",
        "lte_peak_to_peak_urad",
        "mesh_stiffness_mean_N_per_mm_um",
        "single_pair_stiffness_max_N_per_mm_um",
        "max_contact_pressure_MPa",
        "pitch_point_pressure_MPa",
        "pitch_point_pairs_loaded",
    }
    assert needed <= set(s.columns)
    html = (spur_run / "summary.html").read_text()
    assert "pitch_point_pressure_MPa" in html and "data:image/png;base64," in html and "ltca_positions.csv" in html
    p = pd.read_csv(spur_run / "ltca_positions.csv")
    assert len(p) == 41 and (p["status"] == "converged").all()
    assert {"phi1_rad", "lte_urad", "lte_um", "te_unloaded_urad", "load_pair_0_N", "max_pressure_MPa"} <= set(p.columns)
    assert {"tip_edge_load_N", "face_end_load_N", "mesh_stiffness_N_per_mm_um"} <= set(p.columns)
    m = pd.read_csv(spur_run / "ltca_pressure_map.csv")
    worst = s["max_pressure_phi1_rad"].iloc[0]
    assert (m["phi1_rad"] == worst).all() and m["pressure_MPa"].max() == s["max_contact_pressure_MPa"].iloc[0]


@pytest.mark.numerics
def test_pitch_pressure_of_the_unmodified_spur_pair_is_iso_6336_2_within_the_validation_tolerance(spur_run):
    s = pd.read_csv(spur_run / "ltca_summary.csv").iloc[0]
    ref = _iso_pitch_stress(example("spur.yaml"))
    assert s["pitch_point_status"] == "converged"
    assert s["pitch_point_pressure_iso_MPa"] == pytest.approx(ref, rel=1e-12)  # the same closed form
    # one tooth pair alone (ISO 6336-2's case), and here also with every pair free: the neighbours
    # do not touch at the pitch position under this load
    assert abs(s["pitch_point_pressure_single_pair_MPa"] / ref - 1.0) <= PRESSURE_RTOL
    assert s["pitch_point_pairs_loaded"] == 1 and s["pitch_point_load_share"] == pytest.approx(1.0, abs=1e-12)
    assert abs(s["pitch_point_pressure_MPa"] / ref - 1.0) <= PRESSURE_RTOL


@pytest.mark.numerics
def test_the_pitch_position_is_solved_where_the_contact_meets_the_pitch_circle():
    """Solved, not assumed: the contact there lies on the pitch circle (to the contact solve's
    tolerance), and for an unmodified pair it is the library's mid-face pitch position."""
    d = check(example("spur.yaml"))
    phi, status = pitch_position(d)
    assert status == "converged"
    c = d.family.contact_at(d, [phi])
    r_w = d.family.pitch_radius_mm(d)
    assert r_w == pytest.approx(20.0, rel=1e-15)
    assert abs(np.hypot(c.position[0, 0], c.position[0, 1]) - r_w) < 1e-9  # solve tol 1e-10 mm
    # the involute's contact radius moves by r_b tan(alpha) ~ 7 mm/rad: 1e-9 mm is ~1e-10 rad
    assert phi == pytest.approx(ltca.cycle_positions(d.pair, 3)[1], abs=1e-9)


def test_the_pitch_position_is_refused_where_the_contact_never_reaches_the_pitch_circle():
    d = check(example("spur.yaml"))
    d.family = type(d.family)()
    d.family.pitch_radius_mm = lambda d: 30.0  # outside the 20/40 pinion (tip radius 22 mm)
    phi, status = pitch_position(d)
    assert math.isnan(phi) and "off the pitch circle 30 mm" in status


@pytest.mark.numerics
def test_loads_sum_to_the_applied_load_at_every_position(spur_run):
    p = pd.read_csv(spur_run / "ltca_positions.csv")
    s = pd.read_csv(spur_run / "ltca_summary.csv").iloc[0]
    doc = example("spur.yaml")
    T = doc["load"]["torque_Nm"]
    r_b1 = 0.5 * doc["module_mm"] * doc["pinion"]["teeth"] * math.cos(math.radians(doc["pressure_angle_deg"]))
    pairs = p[[c for c in p.columns if c.startswith("load_pair_")]].sum(axis=1)
    np.testing.assert_allclose(pairs, p["normal_load_N"], rtol=BALANCE_RTOL, atol=0)
    assert (p["torque_balance_residual"].abs() <= BALANCE_RTOL).all()
    assert s["max_torque_balance_residual"] <= BALANCE_RTOL
    free = p["tip_edge_load_N"] == 0  # on the line of action: every load's moment arm is r_b1
    assert free.sum() >= 20 and (~free).sum() >= 1  # the corners of the neighbours close under load
    np.testing.assert_allclose(p.loc[free, "normal_load_N"], 1000.0 * T / r_b1, rtol=BALANCE_RTOL, atol=0)


@pytest.mark.numerics
def test_ltca_equals_the_library_route(spur_run):
    """The command's summary is gearrep.ltca's on the same pair built by hand (two constructions of
    one involute pair: the solves agree to their tolerance 1e-10, well inside 1e-8)."""
    from gearrep.surfaces.involute import InvoluteGearData, mating_flanks, standard_centre_distance
    from gearrep.tca import GearPair

    g1 = InvoluteGearData(20, 2.0, math.radians(20.0), 20.0)
    g2 = InvoluteGearData(40, 2.0, math.radians(20.0), 20.0)
    f1, f2 = mating_flanks(g1, g2)
    pair = GearPair(f1, f2, 20, 40, standard_centre_distance(g1, g2))
    r = ltca.loaded_contact(pair, 120.0, ltca.cycle_positions(pair, 41), materials=ltca.STEEL)
    s = pd.read_csv(spur_run / "ltca_summary.csv").iloc[0]
    lib = r.summary()
    for k in ("normal_load_N", "lte_peak_to_peak_urad", "mesh_stiffness_mean_N_per_mm_um", "max_contact_pressure_MPa"):
        assert s[k] == pytest.approx(getattr(lib, k), rel=1e-8), k
    assert s["single_pair_stiffness_max_N_per_mm_um"] == pytest.approx(
        lib.single_pair_stiffness_max_N_per_mm_um, rel=1e-8
    )
    assert s["tip_edge_contact_positions"] == lib.tip_edge_contact_positions and s["n_failed"] == 0
    p = pd.read_csv(spur_run / "ltca_positions.csv")
    np.testing.assert_allclose(p["lte_urad"], r.lte_urad, rtol=1e-8, atol=1e-6)


def test_rerun_gives_identical_tables(spur_run, tmp_path):
    rc, _, err = run("ltca", SPUR, "-o", tmp_path / "b", "--no-progress")
    assert rc == 0, err
    for name in ("ltca_positions.csv", "ltca_summary.csv", "ltca_pressure_map.csv"):
        assert (tmp_path / "b" / name).read_bytes() == (spur_run / name).read_bytes(), name


def test_positions_not_converged_are_nan_with_their_status():
    """A cycle whose fixed-point iteration is cut after one step (maxiter=1): its positions keep a
    status and every result of theirs is NaN in the table."""
    d = check(example("spur.yaml"))
    res = ltca.loaded_contact(d.pair, 120.0, ltca.cycle_positions(d.pair, 5), maxiter=1)
    assert not res.converged.all()
    t = positions_table(d, res, [-1, 0, 1])
    bad = t["status"] != "converged"
    assert set(t.loc[bad, "status"]) <= {"not_converged"}
    for col in ("lte_urad", "normal_load_N", "load_pair_0_N", "max_pressure_MPa", "mesh_stiffness_N_per_mm_um"):
        assert t.loc[bad, col].isna().all(), col
    assert t.loc[bad, "pairs_loaded"].isna().all()


@pytest.mark.numerics
def test_the_catt_example_runs_through_the_command(tmp_path):
    rc, _, err = run("ltca", EXAMPLES / "catt.yaml", "-o", tmp_path / "c", "--no-progress")
    assert rc == 0, err
    s = pd.read_csv(tmp_path / "c" / "ltca_summary.csv").iloc[0]
    p = pd.read_csv(tmp_path / "c" / "ltca_positions.csv")
    assert s["family"] == "catt" and s["torque_Nm"] == 3000.0 and s["n_failed"] == 0
    assert s["pitch_point_status"] == "converged" and math.isnan(s["pitch_point_pressure_iso_MPa"])
    assert (p["torque_balance_residual"].abs() <= BALANCE_RTOL).all()
    pairs = p[[c for c in p.columns if c.startswith("load_pair_")]].sum(axis=1)
    np.testing.assert_allclose(pairs, p["normal_load_N"], rtol=BALANCE_RTOL, atol=0)
    assert s["max_contact_pressure_MPa"] > s["pitch_point_pressure_MPa"] > 0


BAD = [
    ("load.torque_Nm", -1.0, "got -1.0; allowed: a finite number in (0, 1e+07] N m"),
    ("load.torque_Nm", 0, "got 0; allowed: a finite number in (0, 1e+07] N m"),
    ("load.torque_Nm", float("nan"), "got nan; allowed"),
    ("load.torque_Nm", "120", "got '120'; allowed"),
    ("load.torque_Nm", 1e8, "got 100000000.0; allowed: a finite number in (0, 1e+07] N m"),
    ("load.driving", "wheel", "got 'wheel'; allowed: one of ['pinion', 'gear']"),
    ("pinion.material.E_MPa", -206000.0, "got -206000.0; allowed: a finite number in [100, 1.2e+06] MPa"),
    ("gear.material.E_MPa", float("inf"), "got inf; allowed"),
    ("gear.material.poisson", 0.7, "got 0.7; allowed: a finite number in [0, 0.5]"),
    ("pinion.material.nu", 0.3, "under an unknown key"),
]


@pytest.mark.parametrize("key, value, message", BAD)
def test_bad_load_and_material_input_is_refused_before_any_work(tmp_path, key, value, message):
    doc = example("spur.yaml")
    node = doc
    *parents, last = key.split(".")
    for part in parents:
        node = node.setdefault(part, {})
    node[last] = value
    rc, out, err = run("ltca", write(tmp_path, "bad.yaml", doc), "-o", tmp_path / "out")
    assert rc == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"gearrep ltca: refused: design.{key}: ")
    assert message in lines[0]
    assert not (tmp_path / "out").exists()


def test_the_torque_is_required_by_ltca_alone(tmp_path):
    """A design without ``load`` passes check and tca; ltca refuses it naming the key."""
    doc = example("crowned_spur.yaml")
    assert "load" not in doc
    rc, _, err = run("check", write(tmp_path, "d.yaml", doc))
    assert rc == 0, err
    rc, _, err = run("ltca", write(tmp_path, "d.yaml", doc), "-o", tmp_path / "out")
    assert rc == 2 and not (tmp_path / "out").exists()
    assert err.strip() == (
        "gearrep ltca: refused: design.load.torque_Nm: missing; allowed: a finite number in (0, 1e+07] N m "
        "(gearrep ltca needs it)"
    )
    schema = json_schema()["oneOf"][0]["properties"]["load"]
    assert "required" not in schema and "N m" in schema["properties"]["torque_Nm"]["description"]
    mat = json_schema()["oneOf"][0]["properties"]["pinion"]["properties"]["material"]["properties"]
    assert mat["E_MPa"]["default"] == 206000.0 and mat["poisson"]["default"] == 0.3


@pytest.mark.parametrize("name", ["straight_bevel.yaml", "novikov.yaml", "hobbed_curvilinear.yaml"])
def test_families_the_loaded_analysis_does_not_take_are_refused_with_the_reason(tmp_path, name):
    rc, _, err = run("ltca", EXAMPLES / name, "-o", tmp_path / "out")
    family = example(name)["family"]
    lines = err.strip().splitlines()
    assert rc == 2 and len(lines) == 1 and not (tmp_path / "out").exists()
    assert lines[0].startswith(f"gearrep ltca: refused: design.family: got {family!r}; allowed: for ltca")
    assert f"gearrep.ltca refuses {family} flanks: " in lines[0] and "tooth section" in lines[0]


def test_the_families_with_ltca_are_the_library_s_and_declare_its_keys():
    loaded = {name for name, f in REGISTRY.items() if "ltca" in f.analyses}
    assert loaded == set(ltca.SUPPORTED)
    for name in loaded:
        keys = REGISTRY[name].keys
        assert {"torque_Nm", "driving"} == set(keys["load"].fields)
        assert all(set(keys[m].fields["material"].fields) == {"E_MPa", "poisson"} for m in ("pinion", "gear"))


class _NoLoadKeys(PairFamily):
    name = "toy_without_load_keys"
    keys = {
        **head("toy_without_load_keys", "module"),
        "misalignment": MISALIGNMENT,
        "analysis": ANALYSIS,
    }
    analyses = ("tca", "ltca")

    def build(self, values: dict) -> Design:
        raise NotImplementedError


def test_register_refuses_a_family_listing_ltca_without_its_keys():
    with pytest.raises(ValueError, match="lists ltca among its analyses; its keys must declare load"):
        register(_NoLoadKeys())
    assert "toy_without_load_keys" not in REGISTRY


# ----------------------------------------------------------------------------------------------
# the sweep's loaded columns (asked for with ltca: true)
# ----------------------------------------------------------------------------------------------
def _sweep(tmp_path, design=SPUR, **kw) -> dict:
    from gearrep.cli import load_yaml

    doc = {"design": str(design), "grid": {"load.torque_Nm": [60.0, 120.0]}, "phi1_points": 21, **kw}
    return load_yaml(write(tmp_path, "sweep.yaml", doc))


@pytest.mark.numerics
def test_a_sweep_asked_for_ltca_has_the_loaded_cycle_summary_of_each_design(tmp_path, spur_run):
    from gearrep.cli import load_yaml
    from gearrep.cli.loaded import SWEEP_COLUMNS
    from gearrep.cli.sweep import resolve_sweep, run_shard

    raw = _sweep(tmp_path, ltca=True)
    spec = resolve_sweep(raw, load_yaml(raw["design"]))
    # the loaded cycle counts as its section solves: 41 positions x 9 tooth pairs x 21 nodes
    per_point = REGISTRY["involute"].solves_per_point(21) + 41 * 9 * 21
    assert spec["points_per_shard"] == math.ceil(100000 / per_point) and spec["n_shards"] == 1
    sp = tmp_path / "spec.json"
    sp.write_text(json.dumps(spec))
    run_shard(sp, 0, tmp_path / "s1.csv")
    t = pd.read_csv(tmp_path / "s1.csv")
    assert (t["status"] == "ok").all() and list(t["load__torque_Nm"]) == [60.0, 120.0]
    row = t.iloc[1]
    s = pd.read_csv(spur_run / "ltca_summary.csv").iloc[0]  # the same design through gearrep ltca
    for k in set(SWEEP_COLUMNS) - {"ltca_positions_failed"}:
        assert row[k] == pytest.approx(s[k], rel=1e-12, nan_ok=True), k  # one computation in one process
    assert row["ltca_positions_failed"] == 0
    plain = resolve_sweep(_sweep(tmp_path), load_yaml(raw["design"]))
    sp.write_text(json.dumps(plain))
    run_shard(sp, 0, tmp_path / "s0.csv")
    assert not set(SWEEP_COLUMNS) & set(pd.read_csv(tmp_path / "s0.csv").columns)  # not asked for: not computed


@pytest.mark.parametrize(
    "design, named",
    [
        (EXAMPLES / "straight_bevel.yaml", "sweep.ltca: got True; allowed: false for the bevel family"),
        (EXAMPLES / "crowned_spur.yaml", "design.load.torque_Nm: missing"),
    ],
)
def test_a_sweep_asked_for_ltca_is_refused_where_the_loaded_analysis_cannot_run(tmp_path, design, named):
    doc = {"design": str(design), "grid": {"misalignment.d_E_mm": [0.0, 0.01]}, "phi1_points": 21, "ltca": True}
    rc, _, err = run("sweep", write(tmp_path, "sweep.yaml", doc), "-o", tmp_path / "out")
    assert rc == 2 and named in err and "Traceback" not in err
    assert not (tmp_path / "out").exists()
