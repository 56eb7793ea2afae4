"""The hob-cut pair of gearrep.tca (hobbed_*: the TCA of a pair cut by one ZA hob): bad input is
refused at the public entry points with a ValueError naming the argument, before any solve; the
pinion-angle grid and the pair's geometry. (Results: tests/replication/test_hobcut_tca.py and the
hobbed_curvilinear tests of tests/unit/cli/test_cli.py; the pair design: tests/unit/surfaces/test_hob.py.)"""

from __future__ import annotations

import numpy as np
import pytest

from gearrep import tca
from gearrep.surfaces.hob import PairDesign, za_hob


@pytest.fixture(scope="module")
def design():
    return PairDesign(20, 40, 40.0, za_hob(3.0, 20.0, 30.0))


def test_pair_geometry(design):
    pair = tca.hobbed_pair(design, 110.0, 113.0, tca.HobbedAssembly(dC=0.5, dZ=-0.2))
    assert pair.ratio == 0.5 and pair.face_width_mm == 40.0
    assert pair.centre_distance == pytest.approx(30.0 + 60.0 + 0.5, abs=1e-12)
    np.testing.assert_array_equal(pair.gear_origin, [pair.centre_distance, 0.0, -0.2])
    phi = np.array([0.2, -0.4])
    for rot in (pair.pinion_rotation, pair.gear_rotation):  # the derivative is the difference quotient
        fd = (rot(phi + 1e-6) - rot(phi - 1e-6)) / 2e-6
        np.testing.assert_allclose(rot(phi, deriv=True), fd, atol=1e-9)
    assert tca.HobbedAssembly(1e-3, 0.0, 1.0, 0.0).scaled(0.5) == tca.HobbedAssembly(5e-4, 0.0, 0.5, 0.0)


def test_phi1_grid():
    g = np.degrees(tca.hobbed_phi1_grid(-10.0, 10.0, 2.0))
    assert len(g) == 11 and g[5] == 0.0
    np.testing.assert_allclose(g, np.arange(-10.0, 10.1, 2.0), atol=1e-12)
    assert np.count_nonzero(tca.hobbed_phi1_grid(-0.3, 0.3, 0.1) == 0.0) == 1  # 0 exactly, not -3e-17
    with pytest.raises(ValueError, match="step_deg"):
        tca.hobbed_phi1_grid(-10.0, 10.0, 0.0)
    with pytest.raises(ValueError, match="end_deg"):
        tca.hobbed_phi1_grid(-10.0, float("nan"), 2.0)


def test_bad_input_names_the_argument(design):
    pair = tca.hobbed_pair(design, 110.0, 113.0)
    refusals = [
        ("dgamma_v", lambda: tca.HobbedAssembly(dgamma_v=0.02)),
        ("dC", lambda: tca.HobbedAssembly(dC=float("inf"))),
        ("design", lambda: tca.hobbed_pair(object(), 110.0, 113.0)),
        ("R_cp_mm", lambda: tca.hobbed_pair(design, 10.0, 113.0)),
        ("R_cg_mm", lambda: tca.hobbed_pair(design, 110.0, 15.0)),
        ("assembly", lambda: tca.hobbed_pair(design, 110.0, 113.0, (0.0, 0.0, 0.0, 0.0))),
        ("pair", lambda: tca.hobbed_ideal_start(object())),
        ("tol", lambda: tca.hobbed_ideal_start(pair, tol=0.0)),
        ("steps", lambda: tca.hobbed_continue_to(design, 110.0, 113.0, tca.HobbedAssembly(), steps=0)),
        ("assembly", lambda: tca.hobbed_continue_to(design, 110.0, 113.0, None)),
        ("R_gap_mm", lambda: tca.hobbed_continue_to(design, 110.0, 113.0, tca.HobbedAssembly(), R_gap_mm=-1.0)),
        ("tol", lambda: tca.hobbed_continue_to(design, 110.0, 113.0, tca.HobbedAssembly(), tol=1.0)),
        ("pair", lambda: tca.hobbed_physical_contact(None, None)),
        ("ratio", lambda: tca.ke_table(None, 0.0)),
        ("member", lambda: tca.hobbed_tip_crossing(pair, None, "wheel", 33.0, 10.0, 1e-11)),
        ("ra", lambda: tca.hobbed_tip_crossing(pair, None, "gear", -1.0, 10.0, 1e-11)),
        ("delta_mm", lambda: tca.hobbed_elastic_ellipses(pair, None, 0.0)),
    ]
    for name, call in refusals:
        with pytest.raises(ValueError, match=name):
            call()
