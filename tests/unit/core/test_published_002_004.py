"""Digitised published data of seeds 002 (NASA CR-2000-209415) and 004 (Ma et al. 2021).

Checks the CSVs in data/published/ written for these two seeds: row counts, key sets, the
README format (precision re-derived from the printed string, units, unique ids) and spot values
typed by hand from the seed text. When the seed OCR files are present (../shared/seeds), every
printed string is also looked up on the line it cites.
"""

from __future__ import annotations

import math
import re

import pandas as pd
import pytest
from _published_format import printed_precision as _precision
from _published_format import read_text_csv as _read
from conftest import seeds_dir

from gearrep.published import CLAIM_COLUMNS, PARAM_COLUMNS, VALUE_COLUMNS
from gearrep.units import KNOWN_UNITS as UNITS

SEED_DIR = seeds_dir()
SEED_FILES = {"002": "002_f0171829ee188968.txt", "004": "004_de0fa252fc3e91a7.txt"}


VALUE_COUNTS = {
    "values_002_S2.5.csv": 4,
    "values_002_S2.7.csv": 1,
    "values_002_S3.3.csv": 2,
    "values_002_S5.5.csv": 10,
    "values_002_T6.2.1.csv": 8,
    "values_002_T6.2.2.csv": 9,
    "values_002_T6.2.3.csv": 6,
    "values_002_T6.2.4.csv": 9,
}
PARAM_COUNTS = {
    "params_002_S1.csv": 5,
    "params_002_S2.4.csv": 5,
    "params_002_S2.5.csv": 7,
    "params_002_S2.6.csv": 8,
    "params_002_S2.7.csv": 4,
    "params_002_S2.8.csv": 2,
    "params_002_S3.csv": 7,
    "params_002_S5.3.csv": 1,
    "params_002_S5.4.csv": 9,
    "params_002_S5.5.csv": 2,
    "params_002_T6.2.csv": 28,
    "params_004_examples.csv": 122,
}
CLAIM_COUNTS = {"claims_002.csv": 26, "claims_004.csv": 24}

#: params whose printed number is written as a word in the seed ("zero", "one zone", "two zones")
WORD_NUMBERS = {("params_004_examples.csv", "phi1_at_pitch_point"), ("params_002_T6.2.csv", "meshing_zones")}


def _values(name: str) -> pd.DataFrame:
    return _read(name).set_index("id")


# ----------------------------------------------------------------------------- structure


@pytest.mark.parametrize("name,count", sorted(VALUE_COUNTS.items()))
def test_value_file_format(name, count):
    df = _read(name)
    assert list(df.columns) == VALUE_COLUMNS
    assert len(df) == count
    assert df["id"].is_unique
    assert set(df["unit"]) <= UNITS
    assert set(df["rounding"]) == {"round"}
    for _, r in df.iterrows():
        assert re.fullmatch(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?", r["printed"]), r["id"]
        assert _precision(r["printed"]) == (r["precision_kind"], int(r["precision"])), r["id"]
        assert math.isclose(float(r["printed"]), float(r["value"]), rel_tol=1e-12), r["id"]
        assert r["id"] == f"{r['seed']}-{name[len('values_002_') : -4]}-{r['row']}-{r['quantity']}"
        for part in r["row"].split(";"):
            assert re.fullmatch(r"[A-Za-z0-9_]+=[^=;]+", part), (r["id"], part)


@pytest.mark.parametrize("name,count", sorted(PARAM_COUNTS.items()))
def test_param_file_format(name, count):
    df = _read(name)
    assert list(df.columns) == PARAM_COLUMNS
    assert len(df) == count
    assert not df.duplicated(["example", "parameter"]).any()
    assert set(df["unit"]) <= UNITS
    for _, r in df.iterrows():
        assert math.isclose(float(r["printed"]), float(r["value"]), rel_tol=1e-12), (name, r["parameter"])


@pytest.mark.parametrize("name,count", sorted(CLAIM_COUNTS.items()))
def test_claim_file_format(name, count):
    df = _read(name)
    assert list(df.columns) == CLAIM_COLUMNS
    assert len(df) == count
    assert df["id"].is_unique
    assert set(df["kind"]) <= {"trend", "approximate", "missing-table"}
    for col in ("statement", "confirm_if", "refute_if"):
        assert (df[col].str.strip() != "").all(), col
    assert all(i.startswith(f"{s}-") for i, s in zip(df["id"], df["seed"]))


def test_ids_unique_across_files():
    ids = pd.concat([_read(n)["id"] for n in [*VALUE_COUNTS, *CLAIM_COUNTS]])
    assert ids.is_unique


def test_gearrep_loader_accepts_files():
    published = pytest.importorskip("gearrep.published")
    for names, cols, check in (
        (VALUE_COUNTS, published.VALUE_COLUMNS, published.validate_values),
        (PARAM_COUNTS, published.PARAM_COLUMNS, published.validate_params),
        (CLAIM_COUNTS, published.CLAIM_COLUMNS, published.validate_claims),
    ):
        frames = [_read(n)[cols].assign(file=n) for n in names]
        check(pd.concat(frames, ignore_index=True))


@pytest.mark.skipif(not SEED_DIR.is_dir(), reason="seed OCR files not available")
def test_printed_strings_on_cited_lines():
    lines = {s: (SEED_DIR / f).read_text(encoding="utf-8").split("\n") for s, f in SEED_FILES.items()}
    for name in [*VALUE_COUNTS, *PARAM_COUNTS]:
        for _, r in _read(name).iterrows():
            key = r["id"] if "id" in r else r["parameter"]
            if (name, r.get("parameter")) in WORD_NUMBERS:
                continue
            assert r["printed"] in lines[r["seed"]][int(r["line"]) - 1], (name, key, r["line"])
    for name in CLAIM_COUNTS:
        for _, r in _read(name).iterrows():
            assert 1 <= int(r["line"]) <= len(lines[r["seed"]]), r["id"]


# ----------------------------------------------------------------------------- key sets


def test_key_sets_002():
    s25 = _read("values_002_S2.5.csv")
    assert set(zip(s25["row"], s25["quantity"])) == {
        ("member=1", "kappa_I"),
        ("member=1", "kappa_II"),
        ("member=2", "kappa_I"),
        ("member=2", "kappa_II"),
    }
    s55 = _read("values_002_S5.5.csv")
    assert set(s55["row"]) == {
        f"crowning=profile;tool={t};misalignment={m}"
        for t in ("disk", "worm")
        for m in ("dgamma_3arcmin", "dlambda_3arcmin")
    } | {
        f"crowning={c};misalignment={m}"
        for c in ("disk", "worm")
        for m in ("none", "dgamma_3arcmin", "dlambda_3arcmin")
    }
    assert set(_read("values_002_T6.2.1.csv")["row"]) == {
        "version=1",
        "version=2;zone=pinion_addendum",
        "version=2;zone=pinion_dedendum",
        "version=3",
    }
    for name, quantities in (
        ("values_002_T6.2.2.csv", {"ha_Pn", "hd_Pn", "h_Pn"}),
        ("values_002_T6.2.3.csv", {"delta_alpha", "delta_1"}),
        ("values_002_T6.2.4.csv", {"major_axis_2a", "minor_axis_2b", "area_F1"}),
    ):
        df = _read(name)
        assert set(zip(df["row"], df["quantity"])) == {(f"version={v}", q) for v in (1, 2, 3) for q in quantities}
    t62 = _read("params_002_T6.2.csv")
    assert set(t62["example"]) == {"version1", "version2", "version3"}
    assert set(_read("params_002_S5.4.csv")["parameter"]) == {
        "N1",
        "N2",
        "normal_pressure_angle",
        "normal_diametral_pitch",
        "a_c",
        "a_t",
        "helix_angle",
        "a_pl",
        "r_pw",
    }


def test_key_sets_004():
    p = _read("params_004_examples.csv")
    examples = set(p["example"])
    assert {f"fig12_module_sweep_m{m}" for m in (4, 8, 12, 16)} <= examples
    assert {f"fig13_RT_sweep_z2_{z}_RT{r}" for z in (29, 89) for r in (300, 400, 500, 600, 800)} <= examples
    assert {f"fig15_z2_sweep_z2_{z}" for z in (29, 49, 69, 89, 109)} <= examples
    assert {
        "sec4_3d_model",
        "sec4_fea",
        "sec4_meshing_test",
        "figs12-15_common",
        "fig14_thickness_sections",
    } <= examples
    assert len(examples) == 4 + 10 + 5 + 5
    for ex in examples:
        if ex.startswith(("fig12", "fig13", "fig15")):
            assert set(p.loc[p["example"] == ex, "parameter"]) == {
                "z1",
                "z2",
                "module",
                "tooth_line_radius",
                "face_width",
            }
    c = _read("claims_004.csv")
    for fig in ("F12", "F13", "F15"):
        assert f"004-{fig}-cliff_near_top" in set(c["id"])
    assert c["id"].str.contains("F14-").sum() == 3


# ----------------------------------------------------------------------------- spot values


def test_spot_values_002():
    v = pd.concat([_values(n) for n in VALUE_COUNTS])
    spot = {
        "002-S2.5-member=1-kappa_I": ("0.0125", 4, "per_in", 373),
        "002-S2.5-member=1-kappa_II": ("1.5605", 4, "per_in", 373),
        "002-S2.5-member=2-kappa_I": ("0.0083", 4, "per_in", 373),
        "002-S2.5-member=2-kappa_II": ("0.5940", 4, "per_in", 373),
        "002-S5.5-crowning=profile;tool=worm;misalignment=dlambda_3arcmin-TE_max": ("40.48", 2, "arcsec", 1013),
        "002-S5.5-crowning=disk;misalignment=none-TE_max": ("11.54", 2, "arcsec", 1011),
        "002-S5.5-crowning=disk;misalignment=dgamma_3arcmin-TE_max": ("11.66", 2, "arcsec", 1011),
        "002-S5.5-crowning=disk;misalignment=dlambda_3arcmin-TE_max": ("10.11", 2, "arcsec", 1011),
        "002-S5.5-crowning=worm;misalignment=none-TE_max": ("7.21", 2, "arcsec", 1013),
        "002-S5.5-crowning=worm;misalignment=dgamma_3arcmin-TE_max": ("8.33", 2, "arcsec", 1013),
        "002-S5.5-crowning=worm;misalignment=dlambda_3arcmin-TE_max": ("5.41", 2, "arcsec", 1013),
        "002-T6.2.1-version=2;zone=pinion_dedendum-rho_pinion": (".258", 3, "in", 1157),
        "002-T6.2.1-version=3-rho_gear": ("1.270", 3, "in", 1158),
        "002-T6.2.2-version=1-ha_Pn": ("0.00", 2, "1", 1172),
        "002-T6.2.3-version=1-delta_alpha": ("19.50", 2, "deg", 1197),
        "002-T6.2.3-version=3-delta_1": ("0.038", 3, "1", 1199),
        "002-T6.2.4-version=3-major_axis_2a": ("1.034", 3, "in", 1210),
        "002-T6.2.4-version=2-area_F1": (".012", 3, "in2", 1209),
        "002-S2.7-design=recommended-rho_t_over_rho_c": ("1.08", 2, "1", 440),
    }
    for id_, (printed, prec, unit, line) in spot.items():
        r = v.loc[id_]
        assert (r["printed"], int(r["precision"]), r["unit"], int(r["line"])) == (printed, prec, unit, line), id_
    # internal consistency of the printed tables
    for ver in (1, 2, 3):
        t2 = v.loc[[f"002-T6.2.2-version={ver}-{q}" for q in ("ha_Pn", "hd_Pn", "h_Pn")], "value"].astype(float)
        assert t2.iloc[0] + t2.iloc[1] == pytest.approx(t2.iloc[2], abs=1e-9)
        a2, b2, area = (
            float(v.loc[f"002-T6.2.4-version={ver}-{q}", "value"])
            for q in ("major_axis_2a", "minor_axis_2b", "area_F1")
        )
        assert math.pi * a2 * b2 / 4 == pytest.approx(area, abs=0.0005 + 1e-9)


def test_spot_params_002():
    p = pd.concat([_read(n).assign(file=n) for n in PARAM_COUNTS if n.startswith("params_002")])
    get = lambda f, ex, par: p[(p.file == f) & (p.example == ex) & (p.parameter == par)].iloc[0]
    assert get("params_002_S2.5.csv", "S2.5_example", "helix_angle")["printed"] == "19.548"
    assert get("params_002_S5.4.csv", "S5.4_example", "helix_angle")["printed"] == "19.95"
    assert float(get("params_002_S5.4.csv", "S5.4_example", "a_pl")["value"]) == 0.00139
    assert float(get("params_002_S5.4.csv", "S5.4_example", "r_pw")["value"]) == 3.82
    assert get("params_002_S2.6.csv", "S2.6_ellipse", "elastic_approach")["printed"] == "0.0025"
    assert get("params_002_T6.2.csv", "version3", "elastic_approach")["printed"] == "0.00025"
    assert float(get("params_002_T6.2.csv", "version1", "normal_pressure_angle")["value"]) == 27
    assert float(get("params_002_T6.2.csv", "version3", "normal_pressure_angle")["value"]) == 25
    e = get("params_002_T6.2.csv", "version3", "center_distance")
    assert (float(e["value"]), e["unit"]) == (10.0, "in")
    # the helix-angle check recorded in the notes: cos(beta) = (N1 + N2) / (2 P_n E)
    assert math.degrees(math.acos((17 + 77) / (2 * 5 * 10))) == pytest.approx(19.95, abs=0.005)


def test_spot_params_004():
    p = _read("params_004_examples.csv")
    val = lambda ex, par: float(p[(p.example == ex) & (p.parameter == par)]["value"].iloc[0])
    assert [
        val("sec4_3d_model", k) for k in ("z1", "z2", "module", "face_width", "tooth_line_radius", "pressure_angle")
    ] == [19, 31, 8, 80, 500, 20]
    assert val("figs12-15_common", "elastic_approach") == 0.00632
    assert (val("figs12-15_common", "phi1_min"), val("figs12-15_common", "phi1_max")) == (-14.5, 14.5)
    assert val("fig12_module_sweep_m16", "module") == 16
    assert val("fig13_RT_sweep_z2_89_RT800", "tooth_line_radius") == 800
    assert val("fig13_RT_sweep_z2_89_RT800", "z2") == 89
    assert val("fig15_z2_sweep_z2_109", "z2") == 109
    assert val("fig14_thickness_sections", "section_offset_B45") == 45
    assert val("sec4_meshing_test", "face_width_driving") == 85


def test_spot_claims():
    c2 = _read("claims_002.csv").set_index("id")
    assert c2.loc["002-S2.5-helix_angle_typo", "kind"] == "approximate"
    assert int(c2.loc["002-T6.2.4-area_ratio_v1_v2", "line"]) == 1212
    c4 = _read("claims_004.csv").set_index("id")
    assert int(c4.loc["004-F13-area_grows_with_RT", "line"]) == 268
    assert "S(300) < S(400) < S(500) < S(600) < S(800)" in c4.loc["004-F13-area_grows_with_RT", "confirm_if"]
