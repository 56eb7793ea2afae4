"""Checks on the hand-digitised numbers of seed 000 (data/published/*_000_*.csv).

Spot values below were typed from seeds/000_4d213f6321cd1ae7.txt, not copied from the CSVs.
"""

import pandas as pd
import pytest
from conftest import PUBLISHED_DIR as PUB

from gearrep.published import CLAIM_COLUMNS, PARAM_COLUMNS, VALUE_COLUMNS
from gearrep.units import KNOWN_UNITS as UNITS

L1_KEYS = {
    f"l1_mm={v}"
    for v in ["4.381", "4.979", "5.576", "6.173", "6.770", "7.368", "7.965", "8.562", "9.159", "9.757", "10.354"]
}
PHI1_KEYS = {f"phi1_deg={v}" for v in range(-10, 11, 2)}
Q4 = {"k_s", "e_s_x", "e_s_y", "e_s_z", "k_q", "e_q_x", "e_q_y", "e_q_z"}
Q5 = {"phi2", "l_p", "Z_p", "l_g", "Z_g", "KE"}
T4 = ["T4.3", "T4.4"]
T5 = ["T5.3", "T5.4", "T5.7", "T5.8", "T5.9"]


def load(name):
    return pd.read_csv(PUB / name, dtype=str, keep_default_na=False)


@pytest.fixture(scope="module")
def values():
    return {t: load(f"values_000_{t}.csv") for t in T4 + T5 + ["text"]}


def cell(df, row, q, col="printed"):
    hit = df[(df["row"] == row) & (df["quantity"] == q)]
    assert len(hit) == 1, (row, q)
    return hit.iloc[0][col]


@pytest.mark.parametrize("t", T4 + T5 + ["text"])
def test_value_file_format(values, t):
    df = values[t]
    assert list(df.columns) == VALUE_COLUMNS
    assert (df["seed"] == "000").all()
    assert set(df["unit"]) <= UNITS
    assert set(df["precision_kind"]) <= {"decimals", "sig"}
    assert set(df["rounding"]) <= {"round", "truncate"}
    df["line"].astype(int)
    for _, r in df.iterrows():
        assert float(r["value"]) == float(r["printed"]), r["id"]
        assert r["id"] == f"000-{t}-{r['row'].split(';')[0].replace('_mm=', '=').replace('_deg=', '=')}-{r['quantity']}"
        if r["precision_kind"] == "decimals":
            assert len(r["printed"].split(".")[1]) == int(r["precision"]), r["id"]
        else:
            mant = r["printed"].upper().split("E")[0].lstrip("-+").replace(".", "").lstrip("0")
            assert len(mant) == int(r["precision"]), r["id"]


def test_ids_unique_over_all_files(values):
    ids = pd.concat([v["id"] for v in values.values()] + [load("claims_000.csv")["id"]])
    assert ids.is_unique


@pytest.mark.parametrize("t", T4)
def test_curvature_tables_shape(values, t):
    df = values[t]
    assert len(df) == 88
    assert set(df["row"]) == L1_KEYS
    assert set(df["quantity"]) == Q4
    assert df.groupby("row").size().eq(8).all()
    assert (df["rounding"] == "round").all()
    assert set(df.loc[df["quantity"].isin({"k_s", "k_q"}), "unit"]) == {"per_mm"}
    assert set(df.loc[~df["quantity"].isin({"k_s", "k_q"}), "unit"]) == {"1"}


def test_T43_spot_values(values):
    df = values["T4.3"]
    assert cell(df, "l1_mm=4.381", "k_s") == "0.008067"
    assert cell(df, "l1_mm=4.381", "k_q") == "0.058372"
    assert cell(df, "l1_mm=4.381", "e_q_y") == "-0.493"
    assert cell(df, "l1_mm=10.354", "k_s") == "0.009304"
    assert cell(df, "l1_mm=10.354", "k_q") == "1.465754"
    assert cell(df, "l1_mm=10.354", "e_q_x") == "0.998"
    assert cell(df, "l1_mm=4.381", "k_s", "line") == "366"
    # elliptic (Sigma_2R): k_s and k_q of the same sign in every row
    ks = df[df.quantity == "k_s"].set_index("row")["value"].astype(float)
    kq = df[df.quantity == "k_q"].set_index("row")["value"].astype(float)
    assert ((ks * kq) > 0).all()


def test_T44_spot_values(values):
    df = values["T4.4"]
    assert cell(df, "l1_mm=4.381", "k_s") == "1.881729E-4"
    assert cell(df, "l1_mm=4.381", "k_s", "precision_kind") == "sig"
    assert cell(df, "l1_mm=4.381", "k_s", "precision") == "7"
    assert cell(df, "l1_mm=10.354", "k_s") == "1.876682E-4"
    assert cell(df, "l1_mm=10.354", "k_q") == "-1.465754"
    # shifted cells of l.385 read correctly
    assert cell(df, "l1_mm=5.576", "e_s_z") == "1.000"
    assert cell(df, "l1_mm=5.576", "k_q") == "-0.072231"
    assert cell(df, "l1_mm=5.576", "k_q", "line") == "385"
    # sign glitch kept as printed, and documented
    assert cell(df, "l1_mm=7.368", "e_s_z") == "-1.000"
    assert cell(df, "l1_mm=7.368", "e_s_z", "notes") != ""
    # hyperbolic (Sigma_2L); |k_q| equals Table 4.3 row by row
    ks = df[df.quantity == "k_s"].set_index("row")["value"].astype(float)
    kq = df[df.quantity == "k_q"].set_index("row")["value"].astype(float)
    assert ((ks * kq) < 0).all()
    kq3 = values["T4.3"].query("quantity == 'k_q'").set_index("row")["value"].astype(float)
    assert (kq.abs().sort_index() == kq3.sort_index()).all()


@pytest.mark.parametrize("t", T5)
def test_ke_tables_shape(values, t):
    df = values[t]
    assert len(df) == 66
    assert set(df["row"]) == PHI1_KEYS
    assert set(df["quantity"]) == Q5
    assert df.groupby("row").size().eq(6).all()
    phi2 = df[df.quantity == "phi2"]
    assert (phi2["rounding"] == "truncate").all() and (phi2["unit"] == "deg").all()
    assert (df[df.quantity != "phi2"]["rounding"] == "round").all()
    assert set(df[df.quantity == "KE"]["unit"]) == {"arcsec"}
    assert (df["precision"] == "3").all()


@pytest.mark.parametrize("t", T5)
def test_phi2_is_truncated_ratio_plus_ke(values, t):
    df = values[t]
    for row in PHI1_KEYS:
        phi1 = float(row.split("=")[1])
        ke = float(cell(df, row, "KE"))
        exact = 0.5 * phi1 + ke / 3600.0  # T_p/T_g = 20/40
        trunc = int(exact * 1000) / 1000  # int() chops toward zero
        assert float(cell(df, row, "phi2")) == pytest.approx(trunc, abs=1e-9), (t, row)
    assert cell(df, "phi1_deg=0", "KE") == "0.000"


# (table, first-row [phi2, l_p, Z_p, l_g, Z_g, KE], last-row [...]) typed from the seed
KE_SPOTS = {
    "T5.3": (
        ["-4.998", "4.460", "10.672", "9.322", "10.667", "3.859"],
        ["5.000", "8.024", "9.660", "5.760", "9.663", "0.601"],
    ),
    "T5.4": (
        ["-4.998", "4.319", "3.727", "9.456", "3.721", "4.203"],
        ["5.000", "7.889", "3.376", "5.889", "3.378", "0.270"],
    ),
    "T5.7": (
        ["-4.998", "4.321", "-3.771", "9.454", "3.871", "4.200"],
        ["5.000", "7.890", "-3.415", "5.887", "3.515", "0.273"],
    ),
    "T5.8": (
        ["-4.998", "4.270", "4.792", "9.297", "4.758", "4.104"],
        ["5.000", "7.839", "4.335", "5.730", "4.312", "0.410"],
    ),
    "T5.9": (
        ["-4.998", "4.239", "0.393", "9.325", "-0.259", "4.180"],
        ["5.000", "7.809", "0.356", "5.757", "-0.233", "0.337"],
    ),
}


@pytest.mark.parametrize("t", T5)
def test_ke_spot_values(values, t):
    df = values[t]
    first, last = KE_SPOTS[t]
    qs = ["phi2", "l_p", "Z_p", "l_g", "Z_g", "KE"]
    for q, p in zip(qs, first):
        assert cell(df, "phi1_deg=-10", q) == p, (t, q)
    for q, p in zip(qs, last):
        assert cell(df, "phi1_deg=10", q) == p, (t, q)
    assert cell(values["T5.3"], "phi1_deg=8", "phi2") == "4.000"
    assert cell(values["T5.4"], "phi1_deg=8", "phi2") == "3.999"


def test_source_lines(values):
    first_lines = {"T4.3": 366, "T4.4": 383, "T5.3": 633, "T5.4": 666, "T5.7": 691, "T5.8": 721, "T5.9": 739}
    for t, ln in first_lines.items():
        lines = values[t]["line"].astype(int)
        assert lines.min() == ln and lines.max() == ln + 10, t


def test_text_values(values):
    df = values["text"]
    assert len(df) == 5
    assert cell(df, "example=5.1", "contact_ratio") == "1.62"
    assert cell(df, "example=5.1", "contact_ratio", "line") == "606"
    assert cell(df, "alpha_n_deg=20;R_c_mm=110", "a_over_b") == "43.2"
    assert cell(df, "alpha_n_deg=25;R_c_mm=110", "a_over_b") == "42.3"
    assert cell(df, "alpha_n_deg=25;R_c_mm=110", "a_over_b", "line") == "624"


def test_params_table5_1():
    df = load("params_000_table5_1.csv")
    assert list(df.columns) == PARAM_COLUMNS
    assert set(df["unit"]) <= UNITS
    p = df.set_index(["example", "parameter"])["printed"]
    assert p[("5.1", "N_gear")] == "40" and p[("5.1", "N_pinion")] == "20"
    assert p[("5.1", "hob_lead_angle")] == "2.866"
    assert p[("5.1", "hob_outside_diameter")] == "67.5"
    assert p[("5.1", "gear_outside_diameter")] == "126"
    assert p[("5.1", "pinion_pitch_radius")] == "30"
    assert p[("5.1", "R_cp")] == "110" and p[("5.1", "R_cg")] == "110"
    assert p[("5.3", "paint_thickness")] == "0.00632"
    assert p[("4.1", "R_c")] == "110" and p[("4.2", "R_c")] == "5000"
    assert (
        df.loc[
            df.parameter.str.startswith(("hob_", "gear_", "pinion_", "N_", "R_c")) & (df.source == "Table 5.1"), "line"
        ]
        .astype(int)
        .between(611, 618)
        .all()
    )


def test_params_examples():
    df = load("params_000_examples.csv")
    assert list(df.columns) == PARAM_COLUMNS
    assert len(df) == 54
    assert set(df["example"]) == {f"5.{i}" for i in range(1, 10)}
    assert df.groupby("example").size().eq(6).all()
    # implied-but-not-printed parameters have an empty value and a note saying "implied 0"
    implied = df[df["printed"] == ""]
    assert (implied["value"] == "").all()
    assert implied["notes"].str.contains("implied 0").all()
    v = df.set_index(["example", "parameter"])["value"].replace("", "0").astype(float)
    for ex in [f"5.{i}" for i in range(1, 10)]:
        assert v[(ex, "R_cp")] == 110
        assert v[(ex, "R_cg")] == (110 if ex in ("5.1", "5.2") else 113)
    expect = {
        "5.2": {"dgamma_h": 3},
        "5.4": {"dgamma_h": 3},
        "5.5": {"dgamma_v": 3},
        "5.6": {"dC": 0.2},
        "5.7": {"dZ": 0.1},
        "5.8": {"dgamma_h": 3, "dgamma_v": 3, "dC": 0.2},
        "5.9": {"dgamma_h": 3, "dgamma_v": 3, "dC": 0.2, "dZ": 0.1},
    }
    for ex in [f"5.{i}" for i in range(1, 10)]:
        for par in ["dgamma_h", "dgamma_v", "dC", "dZ"]:
            assert v[(ex, par)] == expect.get(ex, {}).get(par, 0.0), (ex, par)


def test_claims():
    df = load("claims_000.csv")
    assert list(df.columns) == CLAIM_COLUMNS
    assert set(df["kind"]) == {"missing-table", "trend", "approximate"}
    missing = df[df.kind == "missing-table"]
    assert set(missing["source"].str.extract(r"(Table \d\.\d)")[0]) == {
        "Table 4.2",
        "Table 4.5",
        "Table 5.2",
        "Table 5.5",
        "Table 5.6",
    }
    assert (df[["statement", "confirm_if", "refute_if"]] != "").all().all()
    df["line"].astype(int)
    approx_lines = set(df.loc[df.kind == "approximate", "line"].astype(int))
    assert {606, 624, 649, 657, 684, 713, 753, 757} <= approx_lines
