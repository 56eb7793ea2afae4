"""Every number the library and the command report is the right one or says why not: failed rows
are NaN, one contact ratio whichever command asks, refusals of what the TCA cannot do, output
folders, and the figures' and summary's conventions. The test pair is an ordinary spur pair
(module 3 mm, 23/41 teeth, 20 deg, 25 mm face, a light parabolic crown for point contact)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from _command import run, write
from conftest import ROOT

from gearrep.cli import load_yaml
from gearrep.cli.design import check
from gearrep.solve import Status
from gearrep.tca import ContactPoints, solve_contact

EXAMPLES = ROOT / "examples"
DESIGNS = sorted(p for p in EXAMPLES.glob("*.yaml") if not p.name.startswith("sweep"))

SPUR = {
    "family": "involute",
    "name": "spur 23/41",
    "module_mm": 3.0,
    "pressure_angle_deg": 20.0,
    "face_width_mm": 25.0,
    "pinion": {"teeth": 23, "crowning": {"kind": "parabolic", "crown_mm": 0.02}},
    "gear": {"teeth": 41},
}


def spur(**changes) -> dict:
    doc = yaml.safe_load(yaml.safe_dump(SPUR))
    for key, value in changes.items():
        node = doc
        *head, last = key.split(".")
        for k in head:
            node = node.setdefault(k, {})
        node[last] = value
    return doc


# ----------------------------------------------------------------------------------------------
# failed rows are NaN
# ----------------------------------------------------------------------------------------------
def _assert_failed_rows_nan(c: ContactPoints):
    bad = ~c.converged
    for f in ContactPoints.CONTACT:
        a = np.asarray(getattr(c, f), float).reshape(len(c), -1)
        assert np.isnan(a[bad]).all(), f
        assert np.isfinite(a[~bad]).all(), f
    assert np.isfinite(c.phi1).all()  # the given angle (a diverged solve has a NaN residual)


def test_solve_contact_failed_rows_are_nan_and_keep_failed_keeps_the_last_iterate():
    pair = check(spur()).pair
    phi = [0.0, 5.0, -0.29, 0.2]
    c = solve_contact(pair, phi)
    assert list(c.status_name) == ["converged", "not_converged", "converged", "off_flank"]
    _assert_failed_rows_nan(c)
    raw = solve_contact(pair, phi, keep_failed=True)
    assert np.isfinite(raw.te).all()  # the solver's iterate, for continuation and boundary searches
    np.testing.assert_array_equal(raw.te[c.converged], c.te[c.converged])


@pytest.mark.parametrize("status", [s for s in Status if s != Status.CONVERGED])
def test_every_status_but_converged_gives_nan_contact_fields(status):
    c = solve_contact(check(spur()).pair, [0.0, 0.05, -0.05], keep_failed=True)
    assert c.converged.all()
    st = c.status.copy()
    st[1] = status
    out = ContactPoints(**{**c.__dict__, "status": st}).failed_as_nan()
    _assert_failed_rows_nan(out)
    assert out.status[1] == status and out.residual[1] == c.residual[1] and out.phi1[1] == c.phi1[1]


def test_singular_and_diverged_solves_are_nan():
    aligned = check(spur(**{"pinion.crowning": {"kind": "none", "crown_mm": 0.0}}), contact=False).pair
    c = solve_contact(aligned, [0.0, 0.1])  # line contact solved as point contact: singular
    assert (c.status == Status.SINGULAR).any()
    _assert_failed_rows_nan(c)
    c = solve_contact(check(spur()).pair, [0.0], np.array([[np.inf, 0.0]]))
    assert not c.converged[0]
    _assert_failed_rows_nan(c)


def test_failed_rows_nan_of_a_table_keeps_only_the_solve_columns():
    from gearrep.cli.analysis import SOLVE_COLUMNS, failed_rows_nan

    t = pd.DataFrame(
        {
            "phi1_rad": [0.0, 0.1],
            "phi2_rad": [0.0, 0.2],
            "te_arcsec": [0.0, 3.0],
            "status": ["converged", "off_flank"],
            "residual": [1e-14, 1e-13],
            "iterations": [3, 4],
            "x_mm": [1.0, 2.0],
            "ellipse_semi_major_mm": [5.0, 6.0],
        }
    )
    out = failed_rows_nan(t)
    for col in t.columns:
        if col in SOLVE_COLUMNS:
            assert (out[col] == t[col]).all()
        else:
            assert np.isnan(out.loc[1, col]) and out.loc[0, col] == t.loc[0, col]


def _csv_failed_rows_hold_no_number(folder: Path):
    from gearrep.cli.analysis import SOLVE_COLUMNS

    seen = 0
    for p in folder.rglob("*.csv"):
        t = pd.read_csv(p)
        if "status" not in t.columns:
            continue
        bad = t["status"] != "converged"
        seen += int(bad.sum())
        for col in t.columns:
            if col not in SOLVE_COLUMNS:
                assert t.loc[bad, col].isna().all(), (p.name, col)
    return seen


def test_tca_csv_rows_that_left_the_flank_hold_no_number(tmp_path):
    """A centre-distance error of the CATT pair carries the ends of its path beyond the flanks:
    those rows are off_flank and every contact column is empty (numbers before)."""
    doc = load_yaml(EXAMPLES / "catt.yaml")
    doc["misalignment"] = {"d_E_mm": 0.5}
    rc, _, err = run("tca", write(tmp_path, "c.yaml", doc), "-o", tmp_path / "o", "--no-progress")
    assert rc == 0, err
    assert _csv_failed_rows_hold_no_number(tmp_path / "o") >= 1


# ----------------------------------------------------------------------------------------------
# one answer per quantity
# ----------------------------------------------------------------------------------------------
def _designs():
    yield "spur 23/41", SPUR
    for p in DESIGNS:
        yield p.stem, load_yaml(p)


@pytest.fixture(scope="module")
def tca_summaries():
    from gearrep.cli.analysis import tca_tables

    return {name: tca_tables(check(doc))["summary"].iloc[0] for name, doc in _designs()}


@pytest.mark.parametrize("n_phi", [41, 101, 401])
@pytest.mark.parametrize("name", [n for n, _ in _designs()])
def test_sweep_gives_the_contact_ratio_of_tca_at_any_number_of_points(tca_summaries, name, n_phi):
    """The same engagement limits (solved on the flank boundaries to the contact tolerance, 1e-12
    here): the sweep and tca agree to 1e-6, whatever the sweep's phi1_points."""
    from gearrep.cli.analysis import sweep_point

    doc = dict(_designs())[name]
    got = sweep_point(check(doc), n_phi)["contact_ratio"]
    assert got == pytest.approx(tca_summaries[name]["contact_ratio"], abs=1e-6)


def test_spur_contact_ratio_is_the_hand_calculation_and_the_iso_ratios_are_in_the_summary(tca_summaries):
    """Path of contact over the base pitch, 1.6549 as quoted (standard involute geometry:
    the tip circles cut the line of action; no overlap for a spur pair)."""
    s = tca_summaries["spur 23/41"]
    rb1, rb2 = 34.5 * np.cos(np.radians(20)), 61.5 * np.cos(np.radians(20))
    path = np.sqrt(37.5**2 - rb1**2) + np.sqrt(64.5**2 - rb2**2) - 96.0 * np.sin(np.radians(20))
    pb = np.pi * 3.0 * np.cos(np.radians(20))
    assert path / pb == pytest.approx(1.6549, abs=1e-4)  # 1.6549 as quoted (truncated: one unit of the last digit)
    assert s["transverse_contact_ratio_iso"] == pytest.approx(path / pb, rel=1e-12)
    assert s["overlap_ratio_iso"] == 0.0
    assert s["total_contact_ratio_iso"] == pytest.approx(path / pb, rel=1e-12)
    # the crowned pair's TCA engagement runs from tip circle to tip circle in the mid section
    assert s["contact_ratio"] == pytest.approx(path / pb, abs=1e-6)


def test_helical_overlap_ratio_is_b_sin_beta_over_pi_mn(tca_summaries):
    doc = load_yaml(EXAMPLES / "helical.yaml")
    s = tca_summaries["helical"]
    beta = np.radians(doc["helix_angle_deg"])
    eps_b = doc["face_width_mm"] * np.sin(beta) / (np.pi * doc["module_mm"])
    assert s["overlap_ratio_iso"] == pytest.approx(eps_b, rel=1e-12)
    assert s["total_contact_ratio_iso"] == pytest.approx(s["transverse_contact_ratio_iso"] + eps_b, rel=1e-12)


def test_every_summary_field_is_explained(tca_summaries):
    from gearrep.cli.output import SUMMARY_FIELDS

    for name, s in tca_summaries.items():
        missing = [k for k in s.index if not SUMMARY_FIELDS.get(k)]
        assert not missing, (name, missing)
    guide = (ROOT / "docs" / "cli.md").read_text()
    assert all(f"`{k}`" in guide for k in SUMMARY_FIELDS), [k for k in SUMMARY_FIELDS if f"`{k}`" not in guide]


# ----------------------------------------------------------------------------------------------
# check knows what tca knows
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "key, value, named, why",
    [
        ("misalignment.d_E_mm", -1.5, "design.misalignment.d_E_mm: got -1.5", "tip interference"),
        ("misalignment.d_E_mm", 3.0, "design.misalignment.d_E_mm: got 3.0", "contact ratio 0.758 < 1"),
        ("misalignment.d_E_mm", 5.5, "design.misalignment.d_E_mm: got 5.5", "contact ratio 0.109 < 1"),
        ("pinion.crowning.crown_mm", 10.0, "design.pinion.crowning.crown_mm: got 10.0", "tooth thickness"),
        ("pinion.tip_relief", {"amount_mm": 2.0, "length_mm": 1.0}, "design.pinion.tip_relief.amount_mm", "thickness"),
    ],
)
@pytest.mark.parametrize("command", ["check", "tca"])
def test_what_tca_cannot_do_is_refused_before_any_work(tmp_path, command, key, value, named, why):
    args = ["-o", tmp_path / "out"] if command == "tca" else []
    rc, out, err = run(command, write(tmp_path, "d.yaml", spur(**{key: value})), *args)
    assert rc == 2, err
    assert named in err and why in err and "allowed:" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists() and not list(tmp_path.glob(".out*"))


def _limits():
    from gearrep.settings import SettingError

    try:
        check(spur(**{"misalignment.d_E_mm": -5.0}))
    except SettingError as e:
        text = str(e)
    lo, hi = text.split("allowed: ")[1].split(" mm")[0].split(" < d_E_mm < ")
    return float(lo), float(hi)


def test_centre_distance_limits_are_where_the_tca_loses_the_flank_or_the_overlap(tmp_path):
    """Just inside the refused range the TCA runs: 0.01 mm above the lower limit the contact starts
    within 1e-4 mm of the pinion's base circle (where the gear tip would leave its involute; the
    start moves by (d sqrt(a^2 - R^2) / da)^2 / (2 r_b) ~ 2e-4 mm per (0.01 mm)^2 of d_E); near
    the upper one the TCA contact ratio is 1 (no overlap left). The limits are printed to 4 digits."""
    from gearrep.meshing import contact_ratio, engagement_limits

    lo, hi = _limits()
    r_b1 = 34.5 * np.cos(np.radians(20))
    d = check(spur(**{"misalignment.d_E_mm": lo + 0.01}))
    b, _ = engagement_limits(d.pair)
    assert b.boundary == "u2_max" and 0 < b.contact.u1[0] - r_b1 < 1e-4
    d = check(spur(**{"misalignment.d_E_mm": hi - 0.001}))
    assert 1.0 < contact_ratio(*d.family.engagement(d), 23) < 1.001
    for outside in (lo - 0.002, hi + 0.001):
        rc, _, err = run("check", write(tmp_path, "d.yaml", spur(**{"misalignment.d_E_mm": outside})))
        assert rc == 2 and "d_E_mm" in err


def test_crown_limit_is_the_tooth_half_thickness_at_the_tip():
    """The limit is r_b cos(beta_b) times the tooth's half angle at the tip circle (an offset of the
    involute along its normal is a turn about the axis)."""
    from gearrep.surfaces.involute import involute_polar_angle

    r_b, r_a, r_p = 34.5 * np.cos(np.radians(20)), 37.5, 34.5
    half = (np.pi * 3.0 / 2) / (2 * r_p) + involute_polar_angle(r_p, r_b) - involute_polar_angle(r_a, r_b)
    most = r_b * half
    assert most == pytest.approx(0.922, abs=5e-4)
    check(spur(**{"pinion.crowning.crown_mm": 0.99 * most}), contact=False)
    from gearrep.settings import SettingError

    with pytest.raises(SettingError, match="crown_mm: got"):
        check(spur(**{"pinion.crowning.crown_mm": 1.01 * most}), contact=False)


# ----------------------------------------------------------------------------------------------
# output folders
# ----------------------------------------------------------------------------------------------
def _siblings(tmp_path, name):
    return sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(f".{name}"))


def test_an_unwritable_output_folder_is_refused_before_any_work(tmp_path, monkeypatch):
    import tempfile

    from gearrep.cli import analysis

    def no_work(*a, **k):
        raise AssertionError("the analysis ran")

    def denied(*a, **k):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(analysis, "curvature_table", no_work)
    monkeypatch.setattr(tempfile, "mkdtemp", denied)
    rc, _, err = run("curvature", write(tmp_path, "d.yaml", SPUR), "-o", tmp_path / "out")
    assert rc == 2 and f"-o {tmp_path / 'out'}: cannot write in {tmp_path}" in err and "Permission denied" in err
    assert not (tmp_path / "out").exists() and not _siblings(tmp_path, "out")


def test_a_result_that_cannot_be_put_in_place_names_the_folder_and_leaves_nothing(tmp_path, monkeypatch):
    import os

    real = os.replace

    def busy(a, b):
        if Path(b).name == "out":
            raise OSError(16, "Device or resource busy")
        return real(a, b)

    monkeypatch.setattr(os, "replace", busy)
    rc, _, err = run("curvature", write(tmp_path, "d.yaml", SPUR), "-o", tmp_path / "out")
    assert rc == 1 and f"-o {tmp_path / 'out'}: the result could not be put in place" in err
    assert "Device or resource busy" in err
    assert not (tmp_path / "out").exists() and not _siblings(tmp_path, "out")


def test_an_existing_empty_folder_receives_the_result_in_place(tmp_path):
    (tmp_path / "out").mkdir()
    inode = (tmp_path / "out").stat().st_ino  # e.g. a mount point: the folder itself is kept
    rc, _, err = run("curvature", write(tmp_path, "d.yaml", SPUR), "-o", tmp_path / "out")
    assert rc == 0, err
    assert (tmp_path / "out" / "curvatures.csv").is_file() and (tmp_path / "out").stat().st_ino == inode
    assert not [p for p in (tmp_path / "out").iterdir() if p.name.startswith(".")] and not _siblings(tmp_path, "out")


def test_overwrite_replaces_a_previous_result_only_when_the_new_one_is_complete(tmp_path, monkeypatch):
    from gearrep.cli import analysis

    d = write(tmp_path, "d.yaml", SPUR)
    assert run("curvature", d, "-o", tmp_path / "out")[0] == 0
    before = (tmp_path / "out" / "curvatures.csv").read_bytes()
    rc, _, err = run("curvature", d, "-o", tmp_path / "out")
    assert rc == 2 and "--overwrite" in err
    real = analysis.curvature_table
    monkeypatch.setattr(analysis, "curvature_table", lambda *a: 1 / 0)
    rc, _, err = run("curvature", d, "-o", tmp_path / "out", "--overwrite")
    assert rc == 1 and (tmp_path / "out" / "curvatures.csv").read_bytes() == before
    monkeypatch.setattr(analysis, "curvature_table", lambda dd: real(dd).assign(k1_per_mm=0.0))
    rc, _, err = run("curvature", d, "-o", tmp_path / "out", "--overwrite")
    assert rc == 0, err
    after = pd.read_csv(tmp_path / "out" / "curvatures.csv")
    assert (after["k1_per_mm"] == 0.0).all() and not _siblings(tmp_path, "out")


# ----------------------------------------------------------------------------------------------
# figures an engineer reads; discoverable
# ----------------------------------------------------------------------------------------------
def test_te_scales_are_the_driven_gears_radians_and_its_base_circle():
    from gearrep.cli.figures import te_scales
    from gearrep.units import ARCSEC

    urad, um = te_scales(check(spur(), contact=False))
    assert urad == pytest.approx(ARCSEC * 1e6, rel=1e-15)
    assert um == pytest.approx(ARCSEC * 61.5 * np.cos(np.radians(20)) * 1e3, rel=1e-14)


def test_te_figure_labels_a_sub_nanometre_te_as_numerically_zero_and_shows_three_cycles():
    import matplotlib.pyplot as plt

    from gearrep.cli.figures import CYCLES_SHOWN, _te_figure, te_scales

    d = check(spur(), contact=False)
    phi = np.linspace(-0.1, 0.1, 21)
    ripple = pd.DataFrame({"phi1_rad": phi, "te_arcsec": 1e-4 * np.sin(40 * phi) + 0.66})  # 0.66 arcsec offset
    _, um = te_scales(d)
    assert 2e-4 * um < 1e-3  # below 1 nm along the line of action
    fig = _te_figure(d, ripple, plt)
    ax = fig.axes[0]
    texts = " ".join(t.get_text() for t in ax.texts)
    assert "numerically zero" in texts and ax.get_ylim() == (-1.0, 1.0)
    line = ax.lines[0]
    assert len(line.get_xdata()) == CYCLES_SHOWN * 21 and np.all(line.get_ydata() == 0.0)
    plt.close(fig)
    big = ripple.assign(te_arcsec=2.0 * np.sin(40 * phi) + 0.66)
    fig = _te_figure(d, big, plt)
    y = fig.axes[0].lines[0].get_ydata()
    assert abs(np.mean(y)) < 1e-9 * np.ptp(y)  # mean removed (0.66 arcsec offset gone), micro-radians
    assert np.ptp(y) == pytest.approx(np.ptp(big["te_arcsec"]) * te_scales(d)[0], rel=1e-12)
    plt.close(fig)


def test_curvature_covers_the_active_profile_and_draws_it(tmp_path):
    """The pinion's grid starts where the gear tip meets it (the start of the engagement the TCA
    solves), not at the base-circle cusp, and the command writes a figure."""
    from gearrep.meshing import engagement_limits

    rc, _, err = run("curvature", write(tmp_path, "d.yaml", SPUR), "-o", tmp_path / "k")
    assert rc == 0, err
    t = pd.read_csv(tmp_path / "k" / "curvatures.csv")
    pin = t[t["member"] == "pinion"]
    b, _ = engagement_limits(check(spur()).pair)
    assert pin["radius_mm"].min() == pytest.approx(b.contact.u1[0], abs=1e-9)
    r_b = 34.5 * np.cos(np.radians(20))
    k_involute = -1.0 / np.sqrt(pin["radius_mm"] ** 2 - r_b**2)  # concave-negative convention of the table
    assert np.allclose(pin["k2_per_mm"], k_involute, rtol=1e-3)  # a light crown: within 1e-3
    assert (tmp_path / "k" / "figures" / "curvatures.png").is_file()


@pytest.mark.parametrize("command", [None, "check", "tca", "curvature", "sweep", "replicate", "schema"])
def test_every_help_has_a_description_and_an_example(command):
    rc, out, _ = run(*([command] if command else []), "--help")
    assert rc == 0
    usage, _, rest = out.partition("\n\n")
    assert len(rest.split("\n\n")[0].split()) >= 8  # a description paragraph after the usage
    assert "example:\n  gearrep " in out


# ----------------------------------------------------------------------------------------------
# edges are results
# ----------------------------------------------------------------------------------------------
def test_an_ellipse_longer_than_the_face_is_cut_at_the_face_edges(tmp_path):
    """elastic_approach_mm 1.0 on the 25 mm face: the Hertz ellipse is far longer than the face; on the
    flank it ends at the face edges (the major axis lies along the face of a crowned spur pair)."""
    rc, _, err = run(
        "tca", write(tmp_path, "d.yaml", spur(**{"analysis.elastic_approach_mm": 1.0})), "-o", tmp_path / "o"
    )
    assert rc == 0, err
    t = pd.read_csv(tmp_path / "o" / "contact_path.csv", keep_default_na=False, na_values=[""])
    s = pd.read_csv(tmp_path / "o" / "summary.csv").iloc[0]
    ok = t["status"] == "converged"
    assert (t.loc[ok, "ellipse_semi_major_mm"] > 12.5).all()
    assert t.loc[ok, "edge_contact"].str.contains("pinion_face").all()
    inner = t[ok].iloc[1:-1]  # (the first and last contacts are on a tip circle, which cuts the axis at them)
    z, mz = inner["z_mm"], inner["ellipse_major_z"]
    ends = np.sort(np.column_stack([z + inner["ellipse_major_from_mm"] * mz, z + inner["ellipse_major_to_mm"] * mz]))
    np.testing.assert_allclose(ends, np.tile([-12.5, 12.5], (len(inner), 1)), atol=1e-9)
    assert (t.loc[ok, "ellipse_area_on_flank_mm2"] < t.loc[ok, "ellipse_area_mm2"]).all()
    assert s["edge_contact_positions"] == ok.sum()


def test_contact_on_a_tip_keeps_half_the_ellipse_and_inside_nothing_is_cut():
    """At the engagement limits the contact is on a tip circle: the tip plane through the contact
    point halves the ellipse (area to the polygon's resolution, the clipped share of pi a b); in the
    middle of the path the ellipse of the example's small elastic approach is whole."""
    from gearrep.cli.analysis import tca_tables

    t = tca_tables(check(spur()))["contact_path"]
    first, last, mid = t.iloc[0], t.iloc[-1], t.iloc[len(t) // 2]
    assert first["edge_contact"] == "gear_tip" and last["edge_contact"] == "pinion_tip"
    for row in (first, last):
        assert row["ellipse_area_on_flank_mm2"] == pytest.approx(0.5 * row["ellipse_area_mm2"], rel=0.02)
    assert mid["edge_contact"] == "" and mid["ellipse_area_on_flank_mm2"] == pytest.approx(mid["ellipse_area_mm2"])
    assert mid["ellipse_major_from_mm"] == -mid["ellipse_semi_major_mm"]


def test_import_gearrep_exposes_the_names_a_library_user_needs_with_units():
    import subprocess
    import sys

    code = "import gearrep, sys; assert 'gearrep.tca' not in sys.modules; print(sorted(gearrep.__all__))"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr  # importing gearrep stays light: the names load on first use
    import gearrep

    for name in ("GearPair", "InvoluteGearData", "meshing_cycle", "principal_curvatures", "tca", "curvature"):
        assert name in gearrep.__all__
    for name in gearrep.__all__[1:]:
        doc = getattr(gearrep, name).__doc__ or ""
        assert any(u in doc for u in ("rad", "mm", "1/length", "[length")), name
    assert gearrep.GearPair is __import__("gearrep.tca", fromlist=["GearPair"]).GearPair


def test_a_pointed_tooth_names_the_profile_shift_with_the_library_limit():
    from gearrep.settings import SettingError
    from gearrep.surfaces.involute import InvoluteGearData

    with pytest.raises(SettingError, match=r"design\.pinion\.profile_shift: got 1\.5; allowed: below 1\.351 ") as e:
        check(spur(**{"pinion.profile_shift": 1.5}), contact=False)
    limit = float(str(e.value).split("below ")[1].split()[0])
    InvoluteGearData(23, 3.0, np.radians(20), 25.0, x=limit - 1e-3)  # the library builds it
    with pytest.raises(ValueError, match="pointed"):
        InvoluteGearData(23, 3.0, np.radians(20), 25.0, x=limit + 1e-3)


def test_profile_shifts_that_need_another_centre_distance_name_d_e_with_its_range():
    """The design's centre distance is r_p1 + r_p2; a positive shift raises the pinion's root above
    where the gear tip reaches: the refusal gives the d_E_mm range that meshes."""
    from gearrep.settings import SettingError

    with pytest.raises(SettingError, match=r"design\.misalignment\.d_E_mm: got 0\.0; allowed: 2\.68 < d_E_mm < ") as e:
        check(spur(**{"pinion.profile_shift": 1.2}))
    assert "tip interference" in str(e.value)
    lo = float(str(e.value).split("allowed: ")[1].split(" <")[0])
    check(spur(**{"pinion.profile_shift": 1.2, "misalignment.d_E_mm": lo + 0.05}))


def test_the_sweep_benchmark_is_a_1000_design_sweep_of_the_example_kind():
    from gearrep.cli.bench import GRID
    from gearrep.cli.sweep import resolve_sweep

    raw = yaml.safe_load((EXAMPLES / "sweep_crowned_spur.yaml").read_text())
    spec = resolve_sweep({**raw, "grid": GRID}, load_yaml(EXAMPLES / raw["design"]))
    assert spec["n_points"] == 1000 and spec["phi1_points"] == 1001
    assert "gearrep.cli.bench" in (ROOT / "Makefile").read_text().split("\nbench:")[1].split("\n\n")[0]
