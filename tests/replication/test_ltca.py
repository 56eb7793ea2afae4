"""The validation of gearrep.ltca (a validation study, seed gearrep.checks.VALIDATION) with the test
settings (study_settings: declared values, config/config.yaml, config/test.yaml).

Every record keeps the status on file in expected_ltca.csv (with its reason); the records have the
study's own ids, none a published one, and every tolerance a stated basis."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from conftest import study_settings

from gearrep import checks as C
from gearrep.replications import ltca

#: statuses and values of the studies: run again by the portability passes (tests/README.md)
pytestmark = pytest.mark.numerics

EXPECTED = pd.read_csv(Path(__file__).with_name("expected_ltca.csv"))


@pytest.fixture(scope="module")
def tables(published):
    design = ltca.params_from_published(published)
    out = ltca.run(study_settings("ltca"), design)
    return {k: pd.read_csv(io.StringIO(v.to_csv(index=False))) for k, v in out.items()}


@pytest.fixture(scope="module")
def records(tables, published):
    return C.validate_checks(ltca.checks(tables, published)["checks"])


def test_records_are_the_expected_ones(records, published):
    assert set(records["id"]) == set(EXPECTED["id"])
    assert (records["seed"] == C.VALIDATION).all()
    assert not set(records["id"]) & (set(published.values["id"]) | set(published.claims["id"]))
    assert (records["tolerance_basis"].str.len() > 20).all() and (EXPECTED["reason"].str.len() > 10).all()


@pytest.mark.parametrize("cid", EXPECTED["id"].tolist())
def test_expected_status(records, cid):
    exp = EXPECTED.set_index("id").loc[cid]
    got = records.set_index("id").loc[cid]
    assert got["status"] == exp["status"], f"{cid}: {got['status']} != {exp['status']} ({exp['reason']})\n{got['note']}"


def test_tables_hold_what_the_records_read(tables):
    st = tables["iso_stiffness"]
    np.testing.assert_allclose(st["single_ratio"], st["c_single_N_per_mm_um"] / st["c_ref_iso_N_per_mm_um"], rtol=1e-15)
    np.testing.assert_allclose(
        st["c_ref_iso_N_per_mm_um"], st["c_th_iso_N_per_mm_um"] * st["basic_rack_factor"], rtol=1e-15
    )
    assert (tables["balance"]["n_failed"] == 0).all()
    assert (tables["convergence"]["n_failed"] == 0).all()
    c = tables["cycle"]
    assert set(c["case"]) == {"readme_pair", "unmodified"} and (c["status"] == 0).all()
    assert (tables["pressure_map"]["pressure_MPa"].dropna() >= 0).all()
