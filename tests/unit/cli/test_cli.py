"""The `gearrep` command on design files: results equal the library route, refusals name the key
(exit 2, no traceback, no output directory), provenance sidecars, identical re-runs, flank export,
and the sweep's shards (split-independent numbers; the workflow's jobs and resources)."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
import yaml
from _command import run, write
from conftest import ROOT

from gearrep.cli import main
from gearrep.cli.design import check, json_schema

EXAMPLES = ROOT / "examples"
DESIGNS = sorted(p for p in EXAMPLES.glob("*.yaml") if not p.name.startswith("sweep"))
ENV = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "MPLBACKEND": "Agg"}


def example(name) -> dict:
    return yaml.safe_load((EXAMPLES / name).read_text())


def test_at_least_three_example_designs_of_the_required_kinds_pass_check():
    kinds = set()
    for p in DESIGNS:
        rc, out, err = run("check", p)
        assert rc == 0, err
        d = yaml.safe_load(p.read_text())
        kinds.add((d["family"], d.get("helix_angle_deg", 0) > 0))
    assert {("involute", False), ("involute", True)} <= kinds
    assert kinds & {("novikov", True), ("catt", False)}


def test_schema_file_is_generated_from_the_declarations():
    assert json.loads((EXAMPLES / "design.schema.json").read_text()) == json_schema(), "run: gearrep schema --write"
    families = [alt["properties"]["family"]["enum"][0] for alt in json_schema()["oneOf"]]
    assert families == ["involute", "novikov", "catt", "hobbed_curvilinear", "bevel"]
    inv = json_schema()["oneOf"][0]
    assert {"family", "module_mm", "face_width_mm", "pinion", "gear"} <= set(inv["required"])
    assert inv["properties"]["pinion"]["required"] == ["teeth"]
    assert inv["additionalProperties"] is False


@pytest.fixture(scope="module")
def spur_run(tmp_path_factory):
    base = tmp_path_factory.mktemp("tca")
    rc, out, err = run("tca", EXAMPLES / "crowned_spur.yaml", "-o", base / "a", "--no-progress")
    assert rc == 0, err
    return base / "a"


def test_tca_equals_the_library_route_of_the_readme(spur_run):
    """The command's contact ratio and TE are those of meshing_cycle on the pair built by hand."""
    from gearrep.meshing import meshing_cycle
    from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
    from gearrep.tca import GearPair, Misalignment
    from gearrep.units import rad2arcsec

    d = example("crowned_spur.yaml")
    g1 = InvoluteGearData(52, 1.0, np.radians(20), 11.42)
    g2 = InvoluteGearData(72, 1.0, np.radians(20), 11.42)
    f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(d["pinion"]["crowning"]["crown_mm"] / (11.42 / 2) ** 2))
    pair = GearPair(
        f1, f2, 52, 72, standard_centre_distance(g1, g2), misalignment=Misalignment(d_gamma_out=np.radians(0.05))
    )
    from gearrep.cli.design import check

    # the same solve tolerance: the design's analysis.tol (declared default unless the file sets it)
    cyc = meshing_cycle(pair, n_points=d["analysis"]["n_points"], tol=check(d).analysis["tol"])
    s = pd.read_csv(spur_run / "summary.csv").iloc[0]
    assert s["contact_ratio"] == cyc.contact_ratio
    assert s["te_peak_to_peak_arcsec"] == pytest.approx(rad2arcsec(cyc.te_peak_to_peak), rel=1e-12, abs=0)
    te = pd.read_csv(spur_run / "te_cycle.csv")
    np.testing.assert_array_equal(te["phi1_rad"], cyc.phi1)
    path = pd.read_csv(spur_run / "contact_path.csv")
    assert (path["status"] == "converged").all() and len(path) == d["analysis"]["n_points"]
    assert path["ellipse_semi_major_mm"].gt(path["ellipse_semi_minor_mm"]).all()


def test_tca_writes_tidy_tables_with_units_and_a_sidecar_per_file(spur_run):
    files = [p for p in spur_run.rglob("*") if p.is_file() and not p.name.endswith(".prov.json")]
    names = {p.relative_to(spur_run).as_posix() for p in files}
    assert {"contact_path.csv", "te_cycle.csv", "summary.csv", "summary.html", "flank_pinion.csv"} <= names
    assert {"flank_gear.stl", "figures/transmission_error.png", "figures/contact_path.png"} <= names
    d = check(example("crowned_spur.yaml"), contact=False)
    from gearrep.cli.design import canonical_hash, split_settings

    design, settings = split_settings(d.values)
    for p in files:
        prov = json.loads(p.with_name(p.name + ".prov.json").read_text())
        assert prov["gearrep_version"] and prov["commit"] and prov["created_utc"].endswith("Z")
        assert prov["design_sha256"] == canonical_hash(design)
        assert prov["settings_sha256"] == canonical_hash(settings)
    cols = pd.read_csv(spur_run / "contact_path.csv").columns
    assert {"phi1_rad", "te_arcsec", "x_mm", "ellipse_semi_major_mm", "pinion_radius_mm"} <= set(cols)
    html = (spur_run / "summary.html").read_text()
    assert "contact_ratio" in html and "data:image/png;base64," in html


def test_rerun_gives_identical_numbers(spur_run, tmp_path):
    rc, _, err = run("tca", EXAMPLES / "crowned_spur.yaml", "-o", tmp_path / "b", "--no-progress")
    assert rc == 0, err
    for p in spur_run.glob("*.csv"):
        assert (tmp_path / "b" / p.name).read_bytes() == p.read_bytes(), p.name
    for p in spur_run.glob("*.stl"):
        assert (tmp_path / "b" / p.name).read_bytes() == p.read_bytes(), p.name


def test_flank_cloud_normals_are_unit_and_normal_to_the_grid_and_stl_is_closed_form(spur_run):
    cloud = pd.read_csv(spur_run / "flank_gear.csv")
    n = cloud[["normal_x", "normal_y", "normal_z"]].to_numpy()
    assert np.abs(np.linalg.norm(n, axis=1) - 1).max() < 1e-12
    pts = cloud[["x_mm", "y_mm", "z_mm"]].to_numpy().reshape(25, 25, 3)
    nn = n.reshape(25, 25, 3)
    t_u = (pts[2:, 1:-1] - pts[:-2, 1:-1]) / np.linalg.norm(pts[2:, 1:-1] - pts[:-2, 1:-1], axis=-1, keepdims=True)
    t_v = (pts[1:-1, 2:] - pts[1:-1, :-2]) / np.linalg.norm(pts[1:-1, 2:] - pts[1:-1, :-2], axis=-1, keepdims=True)
    assert np.abs(np.sum(t_u * nn[1:-1, 1:-1], -1)).max() < 1e-3  # central difference on a 25-point grid
    assert np.abs(np.sum(t_v * nn[1:-1, 1:-1], -1)).max() < 1e-9  # straight face lines of a spur flank
    stl = (spur_run / "flank_gear.stl").read_text().splitlines()
    assert stl[0].startswith("solid") and stl[-1].startswith("endsolid")
    assert sum(line.strip().startswith("facet normal") for line in stl) == 2 * 24 * 24


def test_curvature_of_the_uncrowned_gear_is_the_involute_curvature(tmp_path):
    rc, _, err = run("curvature", EXAMPLES / "crowned_spur.yaml", "-o", tmp_path / "k")
    assert rc == 0, err
    t = pd.read_csv(tmp_path / "k" / "curvatures.csv")
    g = t[t["member"] == "gear"]
    r_b = 36.0 * np.cos(np.radians(20))
    rho = np.sqrt(g["radius_mm"] ** 2 - r_b**2)
    k = np.where(np.abs(g["k1_per_mm"]) > np.abs(g["k2_per_mm"]), g["k1_per_mm"], g["k2_per_mm"])
    np.testing.assert_allclose(np.abs(k), 1 / rho, rtol=1e-6)
    assert (k < 0).all()  # convex tooth, curvature positive toward the outward normal
    other = np.where(np.abs(g["k1_per_mm"]) > np.abs(g["k2_per_mm"]), g["k2_per_mm"], g["k1_per_mm"])
    assert np.abs(other).max() < 1e-9
    assert (tmp_path / "k" / "curvatures.csv.prov.json").is_file()


@pytest.mark.parametrize(
    "name, key, value, named",
    [
        ("crowned_spur.yaml", "module_mm", -1, "design.module_mm"),
        ("crowned_spur.yaml", "pinion.teeth", 12, "design.pinion.teeth"),
        ("crowned_spur.yaml", "pinion.teeth", "52", "design.pinion.teeth"),
        ("crowned_spur.yaml", "colour", "red", "design.colour"),
        ("crowned_spur.yaml", "misalignment.d_gamma_out_deg", 4.0, "design.misalignment.d_gamma_out_deg"),
        ("helical.yaml", "pinion.crowning.crown_mm", 10.0, "design.pinion.crowning.crown_mm"),
        ("catt.yaml", "cutter_radius_mm", 39.0, "design.cutter_radius_mm"),
        ("catt.yaml", "pinion.teeth", 9, "design.pinion.teeth"),
        ("novikov.yaml", "gear.rack_radius_modules", 5.0, "design.gear.rack_radius_modules"),
        ("novikov.yaml", "helix_angle_deg", None, "design.helix_angle_deg"),
        ("hobbed_curvilinear.yaml", "module_mm", -1, "design.module_mm"),
        ("hobbed_curvilinear.yaml", "pinion.cutter_radius_mm", 20.0, "design.pinion.cutter_radius_mm"),
        ("hobbed_curvilinear.yaml", "gear.cutter_radius_mm", 100.0, "design.gear.cutter_radius_mm"),
        ("hobbed_curvilinear.yaml", "pinion.teeth", 12, "design.pinion.teeth"),
        ("hobbed_curvilinear.yaml", "hob_pitch_radius_mm", 6.0, "design.hob_pitch_radius_mm"),
        ("hobbed_curvilinear.yaml", "misalignment.dC_mm", 3.0, "design.misalignment.dC_mm"),
        ("hobbed_curvilinear.yaml", "analysis.ke_table.step_deg", 3.0, "design.analysis.ke_table.step_deg"),
    ],
)
def test_bad_designs_are_refused_naming_key_value_and_range(tmp_path, name, key, value, named):
    from gearrep.cli.design import set_dotted

    doc = set_dotted(example(name), key, value)
    if value is None:  # a missing key
        doc.pop(key)
    rc, out, err = run("tca", write(tmp_path, "bad.yaml", doc), "-o", tmp_path / "out")
    assert rc == 2
    line = err.strip()
    assert "\n" not in line and named in line and "allowed" in line
    if value is not None and key != "colour":
        assert repr(value).strip("'") in line or str(value) in line
    assert not (tmp_path / "out").exists()


def test_missing_key_is_named(tmp_path):
    doc = example("crowned_spur.yaml")
    del doc["gear"]
    rc, _, err = run("check", write(tmp_path, "bad.yaml", doc))
    assert rc == 2 and "design.gear.teeth: missing" in err


def test_unreadable_and_malformed_files_are_refused_naming_the_file(tmp_path):
    rc, _, err = run("check", tmp_path / "nope.yaml")
    assert rc == 2 and "nope.yaml" in err
    p = tmp_path / "broken.yaml"
    p.write_text("family: involute\nmodule_mm: [1\n")
    rc, _, err = run("check", p)
    assert rc == 2 and "broken.yaml" in err and "line" in err
    p.write_text("family: involute\nfamily: catt\n")
    rc, _, err = run("check", p)
    assert rc == 2 and "repeated" in err


def test_yaml_exponent_floats_are_numbers(tmp_path):
    doc = (
        (EXAMPLES / "crowned_spur.yaml")
        .read_text()
        .replace("elastic_approach_mm: 0.00632", "elastic_approach_mm: 6.32e-3")
    )
    p = tmp_path / "d.yaml"
    p.write_text(doc)
    rc, _, err = run("check", p)
    assert rc == 0, err


def test_existing_output_directory_is_refused(spur_run):
    rc, _, err = run("tca", EXAMPLES / "crowned_spur.yaml", "-o", spur_run)
    assert rc == 2 and "-o" in err


def test_parquet_without_pyarrow_is_refused_before_work(tmp_path):
    pytest.importorskip("numpy")
    import importlib.util

    if importlib.util.find_spec("pyarrow") or importlib.util.find_spec("fastparquet"):
        rc, _, err = run("curvature", EXAMPLES / "catt.yaml", "-o", tmp_path / "p", "--parquet")
        assert rc == 0 and (tmp_path / "p" / "curvatures.parquet").is_file()
    else:
        rc, _, err = run("curvature", EXAMPLES / "catt.yaml", "-o", tmp_path / "p", "--parquet")
        assert rc == 2 and "pyarrow" in err and not (tmp_path / "p").exists()


@pytest.mark.parametrize("name", ["novikov.yaml", "catt.yaml", "helical.yaml"])
def test_tca_of_every_family_writes_its_tables(tmp_path, name):
    rc, _, err = run("tca", EXAMPLES / name, "-o", tmp_path / "o")
    assert rc == 0, err
    s = pd.read_csv(tmp_path / "o" / "summary.csv").iloc[0]
    assert 1.0 < s["contact_ratio"] < 3.0
    assert np.isfinite(s["te_peak_to_peak_arcsec"])
    path = pd.read_csv(tmp_path / "o" / "contact_path.csv")
    ok = path["status"] == "converged"
    assert ok.sum() >= 10 and path.loc[ok, "residual"].max() < 1e-9


def test_acceptance_subprocess_tca_and_module_minus_one(tmp_path):
    """As a new user would: `python -m gearrep tca` writes CSV tables; module -1 exits 2 naming the
    key, with no traceback and no directory."""
    r = subprocess.run(
        [sys.executable, "-m", "gearrep", "tca", str(EXAMPLES / "catt.yaml"), "-o", str(tmp_path / "ok")],
        env=ENV,
        capture_output=True,
        text=True,
    )
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "ok" / "contact_path.csv").is_file()
    doc = example("catt.yaml")
    doc["module_mm"] = -1
    r = subprocess.run(
        [sys.executable, "-m", "gearrep", "tca", str(write(tmp_path, "bad.yaml", doc)), "-o", str(tmp_path / "bad")],
        env=ENV,
        capture_output=True,
        text=True,
    )
    assert r.returncode == 2
    assert "design.module_mm" in r.stderr and "-1" in r.stderr and "Traceback" not in r.stderr
    assert not (tmp_path / "bad").exists()


# ----------------------------------------------------------------------------------------------
# sweeps
# ----------------------------------------------------------------------------------------------
def _small_sweep(tmp_path, **kw):
    doc = {
        "design": str(EXAMPLES / "crowned_spur.yaml"),
        "grid": {"misalignment.d_gamma_out_deg": [0.0, 0.05, 3.0], "pinion.crowning.crown_mm": [0.05, 0.1]},
        "phi1_points": 41,
        "solves_per_shard": 162,  # 81 solves per point (engagement limits + path): 2 points per shard
        **kw,
    }
    return write(tmp_path, "sweep.yaml", doc)


def test_sweep_shards_give_the_same_numbers_however_the_grid_is_split(tmp_path):
    from gearrep.cli import load_yaml
    from gearrep.cli.sweep import aggregate, resolve_sweep, run_shard

    raw = load_yaml(_small_sweep(tmp_path))
    tables = []
    for per_shard in (162, 10**6):
        spec = resolve_sweep({**raw, "solves_per_shard": per_shard}, load_yaml(raw["design"]))
        sp = tmp_path / f"spec{per_shard}.json"
        sp.write_text(json.dumps(spec))
        shards = [tmp_path / f"s{per_shard}_{i}.csv" for i in range(spec["n_shards"])]
        for i, p in enumerate(shards):
            run_shard(sp, i, p)
        aggregate(sp, shards, tmp_path / f"sweep{per_shard}.csv")
        tables.append((tmp_path / f"sweep{per_shard}.csv").read_bytes())
        assert spec["n_shards"] == (3 if per_shard == 162 else 1)
    assert tables[0] == tables[1]
    t = pd.read_csv(tmp_path / "sweep162.csv")
    assert len(t) == 6 and list(t["point"]) == list(range(6))
    refused = t[t["misalignment__d_gamma_out_deg"] == 3.0]
    assert (refused["status"] == "refused").all()
    assert refused["message"].str.contains("design.misalignment.d_gamma_out_deg").all()
    ok = t[t["status"] == "ok"]
    assert (ok["solves"] == 81).all() and ok["contact_ratio"].between(1.5, 2.0).all()
    prov = json.loads((tmp_path / "sweep162.csv.prov.json").read_text())
    assert {"gearrep_version", "commit", "design_sha256", "settings_sha256", "sweep_sha256", "created_utc"} <= set(prov)


@pytest.mark.parametrize(
    "change, named",
    [
        ({"grid": {"pinion.colour": [1]}}, "sweep.grid.pinion.colour"),
        ({"grid": {"module_mm": [1.0, -2.0]}}, "sweep.grid.module_mm[1]"),
        ({"grid": {"module_mm": {"start": 1, "stop": 2}}}, "sweep.grid.module_mm"),
        ({"phi1_points": 3}, "sweep.phi1_points"),
        ({"resources": {"mem_mb": -5}}, "sweep.resources.mem_mb"),
        ({"shards": 4}, "sweep.shards"),
    ],
)
def test_bad_sweeps_are_refused_before_any_directory(tmp_path, change, named):
    rc, _, err = run("sweep", _small_sweep(tmp_path, **change), "-o", tmp_path / "out")
    assert rc == 2 and named in err and "Traceback" not in err
    assert not (tmp_path / "out").exists()


def test_sweep_workflow_declares_shard_jobs_with_resources(tmp_path):
    """Dry run of the packaged Snakefile: one job per shard, threads/mem_mb/runtime declared,
    aggregation local."""
    from gearrep.cli.sweep import SNAKEFILE

    text = SNAKEFILE.read_text()
    assert "localrules" in text and "mem_mb=" in text and "runtime=" in text and "threads:" in text
    r = subprocess.run(
        [sys.executable, "-m", "gearrep", "sweep", str(_small_sweep(tmp_path)), "-o", str(tmp_path / "o"), "--dry-run"],
        env=ENV,
        capture_output=True,
        text=True,
    )
    assert r.returncode == 0, r.stderr
    import re

    assert re.search(r"^shard\s+3$", r.stdout, flags=re.M) and re.search(r"^aggregate\s+1$", r.stdout, flags=re.M)
    shard_resources = re.findall(r"rule shard:(?:\n    .*)*?\n    resources: (.*)", r.stdout)
    assert len(shard_resources) == 3
    assert all("runtime=60" in x and "mem_mb=1000" in x for x in shard_resources)
    assert json.loads((tmp_path / "o" / "sweep.json").read_text())["n_shards"] == 3


def test_console_script_and_profiles_are_declared():
    import importlib
    import tomllib

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())
    module, func = project["project"]["scripts"]["gearrep"].split(":")
    assert getattr(importlib.import_module(module), func) is main
    assert "cli/sweep.smk" in project["tool"]["setuptools"]["package-data"]["gearrep"]
    extras = project["project"]["optional-dependencies"]
    core = " ".join(project["project"]["dependencies"])
    assert "executor-plugin" not in core and "pyarrow" not in core
    assert any("cluster-generic" in x for x in extras["cluster"]) and any("slurm" in x for x in extras["slurm"])
    prof = yaml.safe_load((ROOT / "profiles" / "slurm" / "config.yaml").read_text())
    assert prof["executor"] == "slurm" and {"mem_mb", "runtime"} <= set(prof["default-resources"])


def test_replicate_refuses_a_directory_without_the_workflow(tmp_path):
    rc, _, err = run("replicate", "--directory", tmp_path)
    assert rc == 2 and "Snakefile" in err and "Traceback" not in err


@pytest.mark.slow  # parses the whole replication workflow (~5-15 s)
def test_replicate_wraps_the_repository_workflow():
    r = subprocess.run(
        [
            sys.executable,
            "-m",
            "gearrep",
            "replicate",
            "results/checks/ma2021.csv",
            "--directory",
            str(ROOT),
            "--",
            "-n",
        ],
        env=ENV,
        capture_output=True,
        text=True,
    )
    assert r.returncode == 0, r.stderr
    assert "catt" in r.stdout


def test_aligned_unmodified_pair_is_line_contact_with_the_closed_form_contact_ratio(tmp_path):
    from gearrep.meshing import contact_ratio_closed_form
    from gearrep.surfaces.involute import InvoluteGearData

    doc = {
        "family": "involute",
        "module_mm": 2.0,
        "face_width_mm": 20.0,
        "pinion": {"teeth": 20},
        "gear": {"teeth": 40},
    }
    rc, _, err = run("tca", write(tmp_path, "line.yaml", doc), "-o", tmp_path / "o")
    assert rc == 0, err
    s = pd.read_csv(tmp_path / "o" / "summary.csv").iloc[0]
    g1, g2 = (InvoluteGearData(n, 2.0, np.radians(20), 20.0) for n in (20, 40))
    closed = contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, g1.r_p + g2.r_p, g1.base_pitch)
    assert bool(s["line_contact"]) and s["contact_ratio"] == pytest.approx(closed, rel=1e-12)
    assert abs(s["te_peak_to_peak_arcsec"]) < 1e-6  # conjugate flanks
    path = pd.read_csv(tmp_path / "o" / "contact_path.csv")
    assert path["ellipse_semi_major_mm"].isna().all()  # no ellipse for line contact


def test_a_modified_copy_of_an_example_gives_its_own_results(spur_run, tmp_path):
    """The README's new-user path: copy an example, change the crowning, analyse both."""
    text = (EXAMPLES / "crowned_spur.yaml").read_text().replace("crown_mm: 0.09315", "crown_mm: 0.2")
    assert "crown_mm: 0.2" in text
    p = tmp_path / "my_pair.yaml"
    p.write_text(text)
    rc, _, err = run("tca", p, "-o", tmp_path / "mine")
    assert rc == 0, err
    a = pd.read_csv(spur_run / "contact_path.csv")["ellipse_semi_major_mm"].max()
    b = pd.read_csv(tmp_path / "mine" / "contact_path.csv")["ellipse_semi_major_mm"].max()
    assert b < a  # more crowning, shorter contact ellipse
    prov = [
        json.loads((d / "summary.csv.prov.json").read_text())["design_sha256"] for d in (spur_run, tmp_path / "mine")
    ]
    assert prov[0] != prov[1]


# ----------------------------------------------------------------------------------------------
# the hobbed_curvilinear family (seed 000): an adapter onto the library's TCA of envelopes
# ----------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def hob_run(tmp_path_factory):
    """`gearrep tca` on the example with coarse grids (11 path points, 5 x 5 flank clouds)."""
    base = tmp_path_factory.mktemp("hob")
    doc = example("hobbed_curvilinear.yaml")
    doc["analysis"] = {**doc.get("analysis", {}), "n_points": 11, "flank_grid": [5, 5]}
    rc, _, err = run("tca", write(base, "hob.yaml", doc), "-o", base / "o", "--no-progress")
    assert rc == 0, err
    return base / "o"


@pytest.fixture(scope="module")
def seed000():
    from gearrep import published
    from gearrep.replications import hobcut_tca as T

    pub = published.load(ROOT / "data" / "published")
    return pub, T.params_from_published(pub)


def test_hobbed_example_is_the_published_seed000_example_5_4(seed000):
    """The example's inputs are those of data/published (Table 5.1, Example 5.4)."""
    _, design = seed000
    d = example("hobbed_curvilinear.yaml")
    g, case = design.gears, design.cases["5.4"]
    assert (d["pinion"]["teeth"], d["gear"]["teeth"], d["face_width_mm"]) == (g.n_pinion, g.n_gear, g.face_width_mm)
    assert d["module_mm"] == g.hob.module_mm and d["hob_pitch_radius_mm"] == g.hob.pitch_radius_mm
    assert np.radians(d["pressure_angle_deg"]) == pytest.approx(g.hob.pressure_angle_rad, rel=1e-15)
    assert (d["pinion"]["cutter_radius_mm"], d["gear"]["cutter_radius_mm"]) == (case["R_cp_mm"], case["R_cg_mm"])
    assert d["misalignment"] == {"dgamma_h_deg": case["dgamma_h_arcmin"] / 60.0}
    assert case["dgamma_v_arcmin"] == case["dC_mm"] == case["dZ_mm"] == 0.0


def test_hobbed_tca_ke_equals_the_replication_route_and_table_5_4(hob_run, seed000):
    """The command's KE table is the hobcut_tca route (continuation, path, physical contact, eq 5.12)
    on the same pair, and it reproduces the printed Table 5.4 to its 3 decimals."""
    from gearrep.replications import hobcut_tca as T
    from gearrep.tca import ke_table

    pub, design = seed000
    settings = {"phi1_start_deg": -10.0, "phi1_end_deg": 10.0, "phi1_step_deg": 2.0}
    pair, sol = T.compute_case(design.gears, design.cases["5.4"], T.phi1_grid(settings), tol=1e-11, steps=4)
    ref = ke_table(sol, pair.ratio)
    ours = pd.read_csv(hob_run / "ke_table.csv")
    assert (ours["status"] == "converged").all()
    np.testing.assert_array_equal(ours["phi1_deg"].round(9), ref["phi1_deg"].round(9))
    # the design file gives 0.05 deg, the replication 3 arcmin: the same angle to rounding (1e-19 rad)
    np.testing.assert_allclose(ours["KE_arcsec"], ref["KE_arcsec"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(ours[["Z_p_mm", "l_p_mm", "Z_g_mm"]], ref[["Z_p_mm", "l_p_mm", "Z_g_mm"]], atol=1e-9)
    printed = pub.values[(pub.values["source"] == "Table 5.4") & (pub.values["quantity"] == "KE")]
    assert len(printed) == 11
    for _, row in printed.iterrows():
        phi1 = float(row["row"].split("=")[1])
        got = float(ours.loc[np.isclose(ours["phi1_deg"], phi1), "KE_arcsec"].iloc[0])
        assert abs(got - float(row["value"])) <= 0.0005 + 1e-12, (phi1, got, row["value"])  # printed to 3 decimals


def test_hobbed_tca_writes_the_tables_of_every_family(hob_run):
    names = {p.relative_to(hob_run).as_posix() for p in hob_run.rglob("*") if p.is_file()}
    for f in ("contact_path.csv", "te_cycle.csv", "summary.csv", "ke_table.csv", "flank_pinion.stl", "summary.html"):
        assert f in names and f + ".prov.json" in names
    assert {"figures/transmission_error.png", "figures/contact_path.png"} <= names
    s = pd.read_csv(hob_run / "summary.csv").iloc[0]
    assert s["family"] == "hobbed_curvilinear" and s["points_converged"] == s["points_total"] == 11
    assert 1.6 < s["contact_ratio"] < 1.7  # tip to tip, seed 000 eq 5.13 (the 110/110 pair: 1.641)
    assert np.isfinite(s["te_peak_to_peak_arcsec"]) and s["max_residual_mm"] < 1e-9
    path = pd.read_csv(hob_run / "contact_path.csv")
    assert path["ellipse_semi_major_mm"].gt(path["ellipse_semi_minor_mm"]).all()
    assert path["pinion_Z_mm"].abs().max() <= 20.0 and path["radius_on_pinion_mm"].max() == pytest.approx(
        33.0, abs=1e-8
    )
    n = path[["normal_x", "normal_y", "normal_z"]].to_numpy()
    assert np.abs(np.linalg.norm(n, axis=1) - 1).max() < 1e-12
    te = pd.read_csv(hob_run / "te_cycle.csv")
    assert te["te_arcsec"].notna().all() and set(te["tooth_pair"]) <= {-1, 0, 1}
    cloud = pd.read_csv(hob_run / "flank_gear.csv")
    assert len(cloud) == 25 and cloud["z_mm"].abs().max() == pytest.approx(20.0, abs=1e-8)


def test_hobbed_misalignment_moving_the_contact_off_the_face_is_refused_with_its_limit(tmp_path):
    doc = example("hobbed_curvilinear.yaml")
    doc["misalignment"] = {"dZ_mm": 2.0}
    rc, _, err = run("tca", write(tmp_path, "bad.yaml", doc), "-o", tmp_path / "out")
    line = err.strip()
    assert rc == 2 and "\n" not in line and not (tmp_path / "out").exists()
    assert line.startswith("gearrep tca: refused: design.misalignment.dZ_mm: got 2.0; allowed: |dZ_mm| below about")
    limit = float(line.split("below about ")[1].split()[0])
    assert 0.1 < limit < 2.0
    doc["misalignment"] = {"dZ_mm": 0.8 * limit}  # inside the estimated limit: accepted
    rc, _, err = run("check", write(tmp_path, "ok.yaml", doc))
    assert rc == 0, err


def test_hobbed_curvature_signs_convex_pinion_concave_gear_trace(tmp_path):
    doc = example("hobbed_curvilinear.yaml")
    doc["analysis"] = {**doc.get("analysis", {}), "curvature_grid": [3, 3]}
    rc, _, err = run("curvature", write(tmp_path, "hob.yaml", doc), "-o", tmp_path / "k")
    assert rc == 0, err
    t = pd.read_csv(tmp_path / "k" / "curvatures.csv")
    assert len(t) == 18 and t[["k1_per_mm", "k2_per_mm"]].notna().all().all()
    pin, gear = t[t["member"] == "pinion"], t[t["member"] == "gear"]
    assert (pin["k1_per_mm"] < 0).all()  # convex tooth: both curvatures away from the outward normal
    assert (gear["k1_per_mm"] > 0).all() and (gear["k2_per_mm"] < 0).all()  # concave along the arc trace
    # lengthwise curvature of the pinion at mid-face (the smaller one): near -1/R_cp times cos(alpha_n)-ish
    mid = pin[pin["z_mm"].abs() < 1e-8]
    assert np.all(np.abs(mid["k1_per_mm"]) < 1 / 110.0)


def test_hobbed_sweep_point_has_the_metrics_of_gearrep_tca(hob_run, tmp_path):
    """A sweep over a hobbed design runs the same adapter: its contact ratio (tip crossings) is the
    command's, and a refused grid point names its key."""
    from gearrep.cli import load_yaml
    from gearrep.cli.sweep import aggregate, resolve_sweep, run_shard

    raw = {
        "design": str(EXAMPLES / "hobbed_curvilinear.yaml"),
        "grid": {"gear.cutter_radius_mm": [113.0, 100.0]},
        "phi1_points": 11,
    }
    spec = resolve_sweep(raw, load_yaml(raw["design"]))
    sp = tmp_path / "spec.json"
    sp.write_text(json.dumps(spec))
    shards = [tmp_path / f"s{i}.csv" for i in range(spec["n_shards"])]
    for i, p in enumerate(shards):
        run_shard(sp, i, p)
    aggregate(sp, shards, tmp_path / "sweep.csv")
    t = pd.read_csv(tmp_path / "sweep.csv")
    s = pd.read_csv(hob_run / "summary.csv").iloc[0]
    assert list(t["status"]) == ["ok", "refused"] and "design.gear.cutter_radius_mm" in t["message"].iloc[1]
    assert t["contact_ratio"].iloc[0] == s["contact_ratio"] and t["converged"].iloc[0] == 11
    assert t["te_peak_to_peak_arcsec"].iloc[0] == pytest.approx(s["te_peak_to_peak_arcsec"], rel=1e-12)
