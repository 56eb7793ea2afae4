"""Check records: tolerances from printed precision, truncation, statuses, scorecard, not-computed
records, validation of check tables and their CSV round trip."""

import math

import numpy as np
import pandas as pd
import pytest

from gearrep import checks


def row(printed, rounding="round", **kw):
    d = {
        "id": "x",
        "seed": "000",
        "source": "Table",
        "row": "k=1",
        "quantity": "q",
        "unit": "mm",
        "printed": printed,
        "value": float(printed),
        "rounding": rounding,
    }
    d.update(kw)
    return pd.Series(d)


def test_rounded_decimals_half_unit():
    lo, hi, basis = checks.printed_interval("0.0125")
    assert lo == pytest.approx(0.01245) and hi == pytest.approx(0.01255)
    assert checks.compare_value(row("0.0125"), 0.012549)["status"] == "reproduced"
    assert checks.compare_value(row("0.0125"), 0.012551)["status"] == "deviates"


def test_significant_digits():
    lo, hi, _ = checks.printed_interval("1.881729E-4")
    assert hi - lo == pytest.approx(1e-10)
    assert checks.compare_value(row("1.881729E-4"), 1.8817294e-4)["status"] == "reproduced"
    assert checks.compare_value(row("1.881729E-4"), 1.8817296e-4)["status"] == "deviates"


def test_truncation_toward_zero():
    # phi_2' = -4.99893 prints as -4.998 when truncated (seed 000 Table 5.3)
    r = row("-4.998", rounding="truncate")
    assert checks.compare_value(r, -4.99893)["status"] == "reproduced"
    assert checks.compare_value(r, -4.9975)["status"] == "deviates"  # would print -4.997
    assert checks.compare_value(r, -4.99901)["status"] == "deviates"  # would print -4.999
    rp = row("4.998", rounding="truncate")
    assert checks.compare_value(rp, 4.9989)["status"] == "reproduced"
    assert checks.compare_value(rp, 4.9979)["status"] == "deviates"


def test_extra_tolerance_needs_reason():
    with pytest.raises(ValueError, match="reason"):
        checks.compare_value(row("1.00"), 1.2, extra_tol=0.3)
    rec = checks.compare_value(row("1.00"), 1.2, extra_tol=0.3, extra_basis="key rounded")
    assert rec["status"] == "reproduced" and "key rounded" in rec["tolerance_basis"]


def test_nonfinite_is_deviation_not_pass():
    rec = checks.compare_value(row("1.00"), np.nan)
    assert rec["status"] == "deviates" and "no finite" in rec["note"]


def test_check_values_rejects_unknown_ids():
    pub = pd.DataFrame([row("1.00")])
    with pytest.raises(KeyError):
        checks.check_values(pub, pd.DataFrame({"id": ["typo"], "computed": [1.0]}))
    out = checks.check_values(pub, pd.DataFrame({"id": ["x"], "computed": [1.004]}))
    assert list(out.columns) == checks.CHECK_COLUMNS and out["status"].iloc[0] == "reproduced"


def test_scorecard_fills_not_computed_and_rejects_strays():
    values = pd.DataFrame([row("1.00", id="a"), row("2.00", id="b")])
    claims = pd.DataFrame(
        [
            {
                "id": "c",
                "seed": "000",
                "source": "text",
                "kind": "trend",
                "statement": "s",
                "parameters": "",
                "confirm_if": "y",
                "refute_if": "n",
            }
        ]
    )
    done = checks.check_values(values, pd.DataFrame({"id": ["a"], "computed": [1.0]}))
    card = checks.scorecard({"rep": done}, values, claims)
    assert dict(zip(card["id"], card["status"])) == {"a": "reproduced", "b": "not-computed", "c": "not-computed"}
    with pytest.raises(ValueError):
        checks.scorecard({"rep": done.assign(id="zzz")}, values, claims)
    s = checks.summary(card)
    assert s.loc[0, "total"] == 3 and s.loc[0, "not-computed"] == 2


def test_qualitative_needs_evidence():
    claim = pd.Series(
        {"id": "c", "seed": "004", "source": "Fig 12", "kind": "trend", "parameters": "", "confirm_if": "S grows"}
    )
    with pytest.raises(ValueError):
        checks.qualitative(claim, True, "")
    assert checks.qualitative(claim, False, "S falls 3 %")["status"] == "qualitative-fails"


def test_status_vocabulary_results_and_inputs():
    # one place: every status is a result status or an input status, never both
    assert checks.STATUSES == checks.RESULT_STATUSES + checks.INPUT_STATUSES
    assert not set(checks.RESULT_STATUSES) & set(checks.INPUT_STATUSES)
    assert checks.INPUT == "input" and checks.INPUT in checks.STATUSES
    assert len(set(checks.STATUSES)) == len(checks.STATUSES)
    bad = pd.DataFrame([{c: "" for c in checks.CHECK_COLUMNS} | {"id": "x", "seed": "003", "status": "inputs"}])
    with pytest.raises(ValueError, match="unknown statuses"):
        checks.validate_checks(bad)


def _values(ids):
    return pd.DataFrame(
        [
            {"id": i, "seed": "003", "source": "T", "row": f"k={n}", "quantity": "q", "unit": "mm", "value": 1.5}
            for n, i in enumerate(ids)
        ]
    )


def test_printed_input_records_and_scorecard_counts_them_apart():
    values = _values(["amount1", "amount2", "te", "gap"])
    inputs = checks.printed_input(values.iloc[:2], "crowning amount chosen by the author; used as printed")
    assert list(inputs.columns) == checks.CHECK_COLUMNS
    assert (inputs["status"] == "input").all() and inputs["computed"].isna().all()
    assert (inputs["published"] == 1.5).all() and inputs["note"].str.contains("used as printed").all()
    with pytest.raises(ValueError, match="note"):
        checks.printed_input(values.iloc[:1], "")
    claims = pd.DataFrame([{"id": "c", "seed": "003", "source": "T", "kind": "trend", "statement": "s"}])
    with pytest.raises(ValueError, match="claims"):
        checks.printed_input(claims, "x")
    done = pd.concat(
        [
            inputs,
            checks.check_values(
                values.assign(printed="1.5", rounding="round").iloc[2:3],
                pd.DataFrame({"id": ["te"], "computed": [1.5]}),
            ),
        ],
        ignore_index=True,
    )
    card = checks.scorecard({"rep": done}, values, claims.iloc[:0])
    s = checks.summary(card).iloc[0]
    assert (s["input"], s["reproduced"], s["not-computed"]) == (2, 1, 1)
    # results exclude the printed inputs; the total keeps every published row
    assert s["results"] == 2 and s["total"] == 4
    assert list(checks.summary(card).columns) == ["seed", *checks.STATUSES, "results", "total"]


def test_values_below_the_resolution_are_recorded_as_zero():
    """A computed value below 1e-12 in the library's internal unit (a residual or vector component
    that is zero in exact arithmetic) is written as 0 (no -0.0, no rounding noise that differs by
    machine); a widening below it is dropped; larger values are kept as computed."""
    from gearrep.checks import compare_value, resolution
    from gearrep.units import ARCSEC

    assert resolution("mm") == 1e-12 and resolution("arcsec") == pytest.approx(1e-12 / ARCSEC, rel=1e-15)
    row = pd.Series({"id": "x", "seed": "000", "source": "T", "row": "r", "quantity": "e_z", "unit": "1"})
    row = pd.concat([row, pd.Series({"printed": "0.000", "value": 0.0, "rounding": "round"})])
    for noise in (-1.003e-15, 8.7e-16, -0.0):
        rec = compare_value(row, noise, extra_tol=6e-15, extra_basis="noise")
        assert rec["computed"] == 0.0 and math.copysign(1.0, rec["computed"]) == 1.0
        assert rec["status"] == "reproduced" and "plus" not in rec["tolerance_basis"]
    assert compare_value(row, 2e-12)["computed"] == 2e-12
    assert compare_value(row, 2e-4, extra_tol=1e-3, extra_basis="key")["tolerance"] == pytest.approx(1.5e-3)


def _two_printed_values():
    return pd.DataFrame(
        {
            "id": ["x-1", "x-2"],
            "seed": ["000", "000"],
            "source": ["Table 1"] * 2,
            "row": ["a=1", "a=2"],
            "quantity": ["k", "k"],
            "unit": ["per_mm"] * 2,
            "value": ["0.5", "-1.25"],
        }
    )


def test_not_computed_records_values_and_claims():
    rec = checks.not_computed(_two_printed_values(), "needs a bevel surface")
    assert list(rec.columns) == checks.CHECK_COLUMNS
    assert list(rec["status"]) == ["not-computed"] * 2
    assert list(rec["published"]) == [0.5, -1.25] and rec["computed"].isna().all()
    assert (rec["note"] == "needs a bevel surface").all()
    claims = pd.DataFrame(
        {
            "id": ["c-1"],
            "seed": ["004"],
            "source": ["sec 4"],
            "kind": ["trend"],
            "statement": ["S grows"],
            "parameters": ["R_T=300"],
        }
    )
    rc = checks.not_computed(claims, "later")
    assert rc.loc[0, "row"] == "R_T=300" and rc.loc[0, "quantity"] == "trend" and math.isnan(rc.loc[0, "published"])
    checks.validate_checks(pd.concat([rec, rc], ignore_index=True))


def test_validate_checks_rejects_bad_tables():
    rec = checks.not_computed(_two_printed_values(), "r")
    with pytest.raises(ValueError, match="lacks columns"):
        checks.validate_checks(rec.drop(columns=["status"]))
    bad = rec.copy()
    bad.loc[0, "status"] = "ok"
    with pytest.raises(ValueError, match="unknown statuses"):
        checks.validate_checks(bad)
    with pytest.raises(ValueError, match="duplicate check ids"):
        checks.validate_checks(pd.concat([rec, rec.iloc[:1]]))


def test_check_csv_round_trip_keeps_seed_text_and_bad_seeds_are_rejected(tmp_path):
    rec = checks.not_computed(_two_printed_values(), "r")
    f = tmp_path / "c.csv"
    rec.to_csv(f, index=False)
    back = pd.read_csv(f, dtype=checks.TEXT_COLUMNS, keep_default_na=False, na_values=[""])
    assert list(back["seed"]) == ["000", "000"]
    checks.validate_checks(back)
    with pytest.raises(ValueError, match="three-digit string"):
        checks.validate_checks(pd.read_csv(f, keep_default_na=False, na_values=[""]))
