"""The gear families of the `gearrep` command come from one registry: a family added through it
(here a toy family defined in this file) works in `check` and `tca` with no other file changed;
the command has no branch on a family's name; every registered family has an example design and
its place in the generated schema; the bevel family builds the thesis's pairs."""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from _command import run, write
from conftest import ROOT

from gearrep import settings as st
from gearrep.cli.design import check, json_schema
from gearrep.cli.families import REGISTRY, register
from gearrep.cli.family import Design, PairFamily
from gearrep.cli.keys import ANALYSIS, MISALIGNMENT, head
from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
from gearrep.tca import GearPair

CLI = ROOT / "src" / "gearrep" / "cli"
EXAMPLES = ROOT / "examples"


class ToyFamily(PairFamily):
    """A toy family: a spur pair of standard involute flanks whose pinion carries a parabolic
    crown, declared with nothing but its keys and its pair (every analysis from PairFamily)."""

    name = "toy_crowned_spur"
    keys = st.declare(
        **head("toy_crowned_spur", "module"),
        pressure_angle_deg=st.number(20.0, "deg", "pressure angle", ge=15, le=25),
        crown_mm=st.number(0.02, "mm", "pinion crown at the face edges", gt=0, le=0.1),
        pinion=st.group("member 1", teeth=st.integer(None, "1", "teeth", ge=18, le=200)),
        gear=st.group("member 2", teeth=st.integer(None, "1", "teeth", ge=18, le=200)),
        misalignment=MISALIGNMENT,
        analysis=ANALYSIS,
    )
    param_names = ("radius_mm", "axial_mm")

    def build(self, values: dict) -> Design:
        m, b, alpha = values["module_mm"], values["face_width_mm"], math.radians(values["pressure_angle_deg"])
        n1, n2 = values["pinion"]["teeth"], values["gear"]["teeth"]
        g1, g2 = InvoluteGearData(n1, m, alpha, b), InvoluteGearData(n2, m, alpha, b)
        f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(values["crown_mm"] / (0.5 * b) ** 2))
        pair = GearPair(f1, f2, n1, n2, g1.r_p + g2.r_p, misalignment=self.misalignment(values))
        return Design(values, self, pair)


TOY = {
    "family": "toy_crowned_spur",
    "name": "toy 23/41",
    "module_mm": 3.0,
    "face_width_mm": 25.0,
    "crown_mm": 0.02,
    "pinion": {"teeth": 23},
    "gear": {"teeth": 41},
}
#: the same pair as an involute design
INVOLUTE = {
    "family": "involute",
    "name": "spur 23/41",
    "module_mm": 3.0,
    "face_width_mm": 25.0,
    "pinion": {"teeth": 23, "crowning": {"kind": "parabolic", "crown_mm": 0.02}},
    "gear": {"teeth": 41},
}


@pytest.fixture
def toy():
    family = register(ToyFamily())
    yield family
    REGISTRY.pop(family.name)


def test_a_toy_family_added_through_the_registry_works_in_check_and_tca(toy, tmp_path):
    rc, out, err = run("check", write(tmp_path, "toy.yaml", TOY))
    assert rc == 0, err
    assert "toy_crowned_spur, 23/41 teeth" in out
    rc, _, err = run("tca", write(tmp_path, "toy.yaml", TOY), "-o", tmp_path / "o", "--no-progress")
    assert rc == 0, err
    s = pd.read_csv(tmp_path / "o" / "summary.csv").iloc[0]
    path = pd.read_csv(tmp_path / "o" / "contact_path.csv")
    assert s["family"] == "toy_crowned_spur" and (path["status"] == "converged").all() and len(path) == 41
    assert {"pinion_radius_mm", "gear_axial_mm", "edge_contact"} <= set(path.columns)
    assert (tmp_path / "o" / "figures" / "transmission_error.png").is_file()
    assert (tmp_path / "o" / "flank_pinion.stl").is_file()
    # the toy's pair is the involute family's 23/41 design: the same engagement limits (both solved
    # on the flank boundaries to analysis.tol = 1e-10 mm from the same contact at phi1 = 0)
    inv = check(INVOLUTE)
    b, e = inv.family.engagement(inv)
    assert s["phi1_begin_rad"] == pytest.approx(b, abs=1e-9) and s["phi1_end_rad"] == pytest.approx(e, abs=1e-9)
    assert s["contact_ratio_method"] == "engagement limits solved on the flank boundaries"
    # and its keys are checked and in the schema
    rc, _, err = run("check", write(tmp_path, "bad.yaml", {**TOY, "crown_mm": 0.5}))
    assert rc == 2 and "design.crown_mm: got 0.5" in err and "allowed" in err
    assert "toy_crowned_spur" in [alt["properties"]["family"]["enum"][0] for alt in json_schema()["oneOf"]]


def test_a_toy_family_gets_the_curvature_table_and_the_sweep_metrics_and_its_analyses_are_kept(toy, tmp_path):
    from gearrep.cli.analysis import sweep_point

    rc, _, err = run("curvature", write(tmp_path, "toy.yaml", TOY), "-o", tmp_path / "k")
    assert rc == 0, err
    k = pd.read_csv(tmp_path / "k" / "curvatures.csv")
    inv = pd.read_csv(_curvatures(tmp_path, INVOLUTE))
    pin = k["member"] == "pinion"
    assert len(k) == len(inv) and k.loc[pin, "radius_mm"].min() < inv.loc[pin, "radius_mm"].min()  # the whole box
    m = sweep_point(check(TOY), 41)
    assert m["converged"] >= 40 and m["solves"] == 41 + toy.engagement_solves
    toy.analyses = ("tca",)
    rc, _, err = run("curvature", write(tmp_path, "toy.yaml", TOY), "-o", tmp_path / "k2")
    assert rc == 2 and "design.family: got 'toy_crowned_spur'; allowed: for curvature, a family that supports it" in err
    assert not (tmp_path / "k2").exists()


def _curvatures(tmp_path, doc) -> Path:
    rc, _, err = run("curvature", write(tmp_path, "inv.yaml", doc), "-o", tmp_path / "inv")
    assert rc == 0, err
    return tmp_path / "inv" / "curvatures.csv"


def test_a_family_missing_from_the_registry_is_refused_naming_the_registered_ones(tmp_path):
    rc, _, err = run("check", write(tmp_path, "toy.yaml", TOY))
    assert rc == 2 and "design.family: got 'toy_crowned_spur'; allowed: one of" in err
    assert all(name in err for name in REGISTRY)


def test_register_refuses_a_taken_name_and_keys_that_do_not_name_the_family(toy):
    with pytest.raises(ValueError, match="registered already"):
        register(ToyFamily())
    other = ToyFamily()
    other.name = "another"
    with pytest.raises(ValueError, match="must declare family"):
        register(other)


def test_the_command_never_branches_on_a_family_name():
    """No `family ==` (nor `!=`, nor a family name compared or looked up) in the command's code:
    what differs by family lives in the family's module under cli/families/."""
    found = []
    names = set(REGISTRY)
    for path in sorted(CLI.rglob("*.py")):
        text = path.read_text()
        if "family ==" in text or "family !=" in text:
            found.append(f"{path.relative_to(CLI)}: family ==")
        if path.parent.name == "families":
            continue
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Compare) and any(
                isinstance(c, ast.Constant) and c.value in names for c in [node.left, *node.comparators]
            ):
                found.append(f"{path.relative_to(CLI)}:{node.lineno} compares with a family name")
            if isinstance(node, ast.Dict) and any(isinstance(k, ast.Constant) and k.value in names for k in node.keys):
                found.append(f"{path.relative_to(CLI)}:{node.lineno} a table keyed by family names")
    assert not found, found


def test_every_family_has_an_example_design_that_passes_check():
    families = {
        yaml.safe_load(p.read_text())["family"] for p in EXAMPLES.glob("*.yaml") if not p.name.startswith("sweep")
    }
    assert families == set(REGISTRY)
    for name, family in REGISTRY.items():
        assert family.name == name and family.keys["family"].choices == (name,)
        assert len(family.param_names) == 2 and set(family.analyses) <= {"tca", "curvature", "sweep", "ltca"}


def _published_bevel():
    from gearrep import published
    from gearrep.replications.temirkhan2023.design import params_from_published

    pub = published.load(ROOT / "data" / "published", [str(ROOT / "data" / "published" / "params_003_*.csv")])
    return params_from_published(pub)


@pytest.mark.parametrize(
    "example, case, crown_per_length, mis",
    [
        ("straight_bevel.yaml", "straight_bevel_39_32", 0.0008, {"d_E": 0.1}),
        ("spiral_bevel.yaml", "spiral_bevel_17_17", 0.005, {"d_E": 0.05}),
    ],
)
def test_the_bevel_examples_are_the_thesis_pairs_of_the_replication(tmp_path, example, case, crown_per_length, mis):
    """The examples' inputs are the published sec. 5.1-5.2 data (and the replication's readings:
    20 deg for the spiral pair, its convex flank driving), and the command's TCA is the library's
    meshing cycle on the replication's own pair (gearrep.replications.temirkhan2023.bevel.bevel_pair):
    the same engagement limits and TE to the solves' tolerance (1e-10 mm residuals against radii of
    about 10-60 mm: 1e-9 rad; TE in arcsec 1e-9 rad / 4.8e-6 ~ 2e-4 arcsec)."""
    from gearrep.meshing import meshing_cycle
    from gearrep.replications.temirkhan2023.bevel import bevel_pair
    from gearrep.tca import BevelMisalignment
    from gearrep.units import ARCSEC

    design = _published_bevel()
    p = design.pairs[case]
    doc = yaml.safe_load((EXAMPLES / example).read_text())
    assert (doc["pinion"]["teeth"], doc["gear"]["teeth"]) == (p["n1"], p["n2"])
    assert (doc["module_mm"], doc["face_width_mm"]) == (p["module"], p["face_width"])
    assert (doc["pressure_angle_deg"], doc["shaft_angle_deg"]) == (p["pressure_angle_deg"], p["shaft_angle_deg"])
    assert doc.get("spiral_angle_deg", 0.0) == p["spiral_angle_deg"]
    half = 0.5 * doc["face_width_mm"]
    assert doc["pinion"]["crowning"]["crown_mm"] == pytest.approx(crown_per_length * half**2, rel=1e-12)
    rc, _, err = run("tca", EXAMPLES / example, "-o", tmp_path / "o", "--no-progress")
    assert rc == 0, err
    s = pd.read_csv(tmp_path / "o" / "summary.csv").iloc[0]
    pair = bevel_pair(design, case, crown=crown_per_length, misalignment=BevelMisalignment(**mis))
    cyc = meshing_cycle(pair, n_points=41, tol=1e-10)
    assert s["phi1_begin_rad"] == pytest.approx(cyc.begin.phi1, abs=1e-9)
    assert s["phi1_end_rad"] == pytest.approx(cyc.end.phi1, abs=1e-9)
    assert s["te_peak_to_peak_arcsec"] == pytest.approx(cyc.te_peak_to_peak / ARCSEC, abs=2e-4)
    assert s["points_converged"] == s["points_total"] == 41 and not s["line_contact"]


def test_an_aligned_unmodified_bevel_pair_is_in_line_contact_with_zero_te(tmp_path):
    doc = yaml.safe_load((EXAMPLES / "spiral_bevel.yaml").read_text())
    doc["pinion"].pop("crowning")
    doc.pop("misalignment")
    rc, _, err = run("tca", write(tmp_path, "line.yaml", doc), "-o", tmp_path / "o")
    assert rc == 0, err
    s = pd.read_csv(tmp_path / "o" / "summary.csv").iloc[0]
    assert bool(s["line_contact"]) and abs(s["te_peak_to_peak_arcsec"]) < 1e-6  # conjugate flanks
    path = pd.read_csv(tmp_path / "o" / "contact_path.csv")
    assert (path["status"] == "converged").all() and path["ellipse_semi_major_mm"].isna().all()
    # traced at the mean cone distance
    g = check(doc, contact=False).pair.flank1.gear
    assert np.all(path["pinion_cone_distance_mm"] == g.mean_cone_distance)


@pytest.mark.parametrize("family", ["involute", "bevel"])
def test_a_relieved_profile_in_line_contact_is_refused_before_any_work(tmp_path, family):
    doc = yaml.safe_load(
        (EXAMPLES / ("crowned_spur.yaml" if family == "involute" else "straight_bevel.yaml")).read_text()
    )
    doc["pinion"].pop("crowning")
    doc.pop("misalignment")
    doc["pinion"]["tip_relief"] = {"amount_mm": 0.01, "length_mm": 0.5}
    rc, _, err = run("tca", write(tmp_path, "d.yaml", doc), "-o", tmp_path / "o")
    assert rc == 2 and "design.pinion.tip_relief.amount_mm: got 0.01; allowed: 0 while neither member" in err
    assert not (tmp_path / "o").exists()


def test_bevel_crown_limit_is_the_tooth_half_thickness_at_the_inner_end():
    """The crown's limit is the half thickness along the normal at the face cone of the inner end:
    the spherical involute's azimuth from the tooth's centre there times v sin(a_b); a crown just
    below it builds, just above it is refused naming the key."""
    from gearrep.settings import SettingError
    from gearrep.surfaces.bevel import BevelGearData, spherical_involute_azimuth

    doc = yaml.safe_load((EXAMPLES / "spiral_bevel.yaml").read_text())
    g = BevelGearData(17, 17, 1.0, math.radians(20), 4.8, spiral_angle=math.radians(35))
    a_b = g.base_cone_angle
    half = (
        math.pi / 34
        + spherical_involute_azimuth(g.pitch_cone_angle, a_b)
        - spherical_involute_azimuth(g.face_cone_angle, a_b)
    )
    most = float(half * (g.outer_cone_distance - 4.8) * math.sin(a_b))
    doc["pinion"]["crowning"]["crown_mm"] = 0.99 * most
    check(doc, contact=False)
    doc["pinion"]["crowning"]["crown_mm"] = 1.01 * most
    with pytest.raises(SettingError, match=r"design\.pinion\.crowning\.crown_mm: got .*; allowed: below"):
        check(doc, contact=False)
