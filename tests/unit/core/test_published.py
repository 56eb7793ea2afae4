"""The digitised published data: format, precision fields, agreement with the seed texts, and
parameter tables."""

import re

import numpy as np
import pandas as pd
import pytest
from conftest import PUBLISHED_DIR

from gearrep import published as pub


def test_loads_and_has_every_seed(published):
    assert len(published.values) > 0
    assert set(published.values["seed"]) | set(published.claims["seed"]) <= set(pub.SEEDS)


def test_ids_unique(published):
    ids = pd.concat([published.values["id"], published.claims["id"]])
    assert not ids.duplicated().any()


def test_precision_field_matches_printed_digits(published):
    for _, r in published.values.iterrows():
        assert pub.printed_precision(r["printed"]) == (r["precision_kind"], r["precision"]), r["id"]


def test_units_known(published):
    from gearrep.units import KNOWN_UNITS

    assert set(published.values["unit"]) <= KNOWN_UNITS
    assert set(published.params["unit"]) <= KNOWN_UNITS


def _variants(printed: str):
    """Ways a number can appear in OCR text: as printed, without leading zero or plus sign,
    with E/e, with a LaTeX-style minus or a space after the sign."""
    s = printed.strip()
    yield s
    words = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"]
    if s.isdigit() and int(s) < len(words):
        yield words[int(s)]  # small integers written as words
    yield s.lstrip("+")
    if s.startswith("-"):
        yield "−" + s[1:]
        yield "- " + s[1:]
    if s.startswith(("0.", "-0.")):
        yield s.replace("0.", ".", 1)
    if "E" in s or "e" in s:
        yield s.replace("E", "e")
        yield s.replace("e", "E")
        m = re.match(r"^([+-]?[\d.]+)[eE]([+-]?)0*(\d+)$", s)
        if m:
            yield f"{m.group(1)}E{m.group(2)}{m.group(3)}"
            yield f"{m.group(1)}e{m.group(2)}{m.group(3)}"


@pytest.mark.parametrize("table", ["values", "params"])
def test_printed_numbers_stand_on_their_line(published, seed_lines, table):
    """Every printed number occurs on the seed line it cites (+-1 line for wrapped OCR lines),
    unless its note records an OCR correction."""
    df = getattr(published, table)
    missing = []
    for _, r in df.iterrows():
        if not str(r["printed"]).strip():
            continue
        lines = seed_lines[r["seed"]]
        ln = int(r["line"])
        assert 1 <= ln <= len(lines), (r.get("id", r["parameter"]), ln)
        window = " ".join(lines[max(ln - 2, 0) : ln + 1])
        window_nospace = window.replace(" ", "")
        found = any(v in window or v.replace(" ", "") in window_nospace for v in _variants(r["printed"]))
        if not found and "ocr" not in str(r["notes"]).lower():
            missing.append((r["file"], r.get("id", r.get("parameter")), r["printed"], ln))
    assert not missing, f"{len(missing)} printed numbers not found on their line: {missing[:15]}"


def test_claims_cite_existing_lines(published, seed_lines):
    for _, r in published.claims.iterrows():
        assert 1 <= r["line"] <= len(seed_lines[r["seed"]]), r["id"]
        assert r["confirm_if"].strip() and r["refute_if"].strip(), r["id"]


def test_printed_precision_parsing():
    assert pub.printed_precision("0.008067") == ("decimals", 6)
    assert pub.printed_precision("-4.998") == ("decimals", 3)
    assert pub.printed_precision("1.881729E-4") == ("sig", 7)
    assert pub.printed_precision("27") == ("decimals", 0)
    assert pub.printed_precision("1e-10") == ("sig", 1)
    with pytest.raises(pub.PublishedDataError):
        pub.printed_precision("12a")


def test_bad_file_is_rejected_with_its_name(tmp_path):
    cols = ",".join(pub.VALUE_COLUMNS)
    (tmp_path / "values_bad.csv").write_text(
        cols + "\n000-x-k=1-q,000,Table 1,1,k=1,q,0.0125,0.0125,per_mm,decimals,3,round,\n"
    )
    with pytest.raises(pub.PublishedDataError, match="values_bad.csv.*implies decimals=4"):
        pub.load(tmp_path)


def test_parse_row():
    assert pub.parse_row("l1_mm=4.381;side=L") == {"l1_mm": "4.381", "side": "L"}
    with pytest.raises(pub.PublishedDataError):
        pub.parse_row("nonsense")


def test_errata_file_is_well_formed():
    from conftest import ROOT

    errata = pd.read_csv(ROOT / "data" / "errata.csv", dtype=str, keep_default_na=False)
    assert list(errata.columns) == ["seed", "location", "printed", "correction", "evidence"]
    assert set(errata["seed"]) <= set(pub.SEEDS)
    assert (errata["evidence"].str.len() > 20).all(), "every erratum needs its evidence"


def test_errata_evidence_points_at_tests_that_exist():
    """An erratum's evidence that names a test file (and test) must name one that exists, so the
    evidence cannot silently rot when tests are renamed."""
    import re

    from conftest import ROOT

    errata = pd.read_csv(ROOT / "data" / "errata.csv", dtype=str, keep_default_na=False)
    refs = {m for ev in errata["evidence"] for m in re.findall(r"tests/[\w/]+\.py(?:::\w+)?", ev)}
    assert refs, "the errata cite no tests at all"
    for ref in sorted(refs):
        path, _, name = ref.partition("::")
        f = ROOT / path
        assert f.is_file(), f"{ref}: no such file"
        if name:
            assert re.search(rf"^def {name}\(", f.read_text(), flags=re.M), f"{ref}: no such test"


def test_values_by_keys_every_row_in_order():
    """One pass over a params or values frame: each key's values in row order (a repeated key
    keeps all of them, for the caller to refuse)."""
    frame = pd.DataFrame(
        {"file": ["a", "a", "b", "a"], "parameter": ["x", "y", "x", "x"], "value": [1.0, 2.0, 3.0, float("nan")]}
    )
    got = pub.values_by(frame, ["file", "parameter"])
    assert list(got) == [("a", "x"), ("a", "y"), ("b", "x")]
    assert got[("a", "y")] == [2.0] and got[("b", "x")] == [3.0]
    assert got[("a", "x")][0] == 1.0 and got[("a", "x")][1] != got[("a", "x")][1]  # NaN


def test_perturbed_params_move_lengths_and_angles_by_a_few_ulps(published, monkeypatch):
    """The portability check's switch: every length, angle and curvature moves by 1 to k ulps (the
    same way in every process, equal values alike), counts, ratios, zeros and NaN stay; a bad
    value of the environment variable is refused naming it."""
    import math

    p = published.params
    q = pub.perturbed_params(p, 4)
    a, b = p["value"].to_numpy(), q["value"].to_numpy()
    moved = p["unit"].isin(pub.PERTURBED_UNITS).to_numpy() & (a != 0) & np.isfinite(a)
    assert moved.sum() > 100 and np.all(b[moved] != a[moved])
    ulps = np.abs(b[moved] - a[moved]) / np.spacing(np.abs(a[moved]))
    assert np.all((ulps >= 0.5) & (ulps <= 8.0))  # 1-4 ulps (an ulp halves across a power of 2)
    np.testing.assert_array_equal(b[~moved], a[~moved])  # exact: the same numbers, unmoved
    assert pub.perturbed_value(110.0, 4) == pub.perturbed_value(110.0, 4) != 110.0
    assert pub.perturbed_value(0.0, 4) == 0.0 and math.isnan(pub.perturbed_value(math.nan, 4))
    assert pub.perturbed_value(3.5, 0) == 3.5
    with pytest.raises(ValueError, match="ulps"):
        pub.perturbed_value(1.0, -1)
    monkeypatch.setenv(pub.PERTURB_ENV, "4")
    assert pub.perturb_ulps_from_env() == 4
    loaded = pub.load(PUBLISHED_DIR)
    np.testing.assert_array_equal(loaded.params["value"].to_numpy(), b)  # exact: the same perturbation
    monkeypatch.setenv(pub.PERTURB_ENV, "few")
    with pytest.raises(ValueError, match="GEARREP_PERTURB_ULPS='few'"):
        pub.load(PUBLISHED_DIR)


def test_param_table_selects_file_and_example():
    params = pd.DataFrame(
        {
            "file": ["p_a.csv", "p_a.csv", "p_a.csv", "p_b.csv"],
            "example": ["e1", "e1", "e2", "e1"],
            "parameter": ["m", "z", "m", "m"],
            "value": [2.5, 25.0, 3.0, 1.0],
        }
    )
    assert pub.param_table(params, "p_a.csv", "e1") == {"m": 2.5, "z": 25.0}
    assert pub.param_table(params, "p_b.csv") == {"m": 1.0}
    with pytest.raises(KeyError, match="example='e9'"):
        pub.param_table(params, "p_a.csv", "e9")
