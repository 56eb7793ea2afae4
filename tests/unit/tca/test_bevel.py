"""The bevel TCA (gearrep.tca.BevelPair: intersecting axes, thesis seed 003 eq 47-48) of the
spherical-involute straight and spiral bevel flanks in both formulations, and bad input at every
step of building a bevel pair (the flanks: tests/unit/surfaces/test_bevel.py)."""

import numpy as np
import pytest
from _gear_pairs import spiral_bevel as spiral
from _gear_pairs import straight_bevel as straight
from _numerics import assert_same_solve

from gearrep.solve import Status
from gearrep.surface import AxialForm
from gearrep.surfaces.bevel import BevelGearData, SphericalInvoluteFlank, mating_bevel_flanks
from gearrep.surfaces.involute import ParabolicCrowning
from gearrep.tca import BevelMisalignment, BevelPair, ContactPoints, default_start, reduced_unknowns, solve_contact

D = np.radians


def _pair(case, crowning=None, mis=None):
    g1, g2 = straight() if case == "straight" else spiral()
    f1, f2 = mating_bevel_flanks(g1, g2, crowning1=crowning)
    return BevelPair(f1, f2, g1.n_teeth, g2.n_teeth, misalignment=mis), g1


@pytest.mark.parametrize("case", ["straight", "spiral"])
def test_aligned_unmodified_pair_line_contact_zero_te(case):
    pair, g1 = _pair(case)
    phi = np.linspace(-0.06, 0.06, 7) if case == "straight" else np.linspace(-0.02, 0.02, 5)
    us = []
    # the spiral pair's contact line crosses the face obliquely: near phi1 = 0 it leaves the inner half
    v_lo = g1.mean_cone_distance - (0.4 if case == "straight" else 0.1) * g1.face_width
    for v1 in np.linspace(v_lo, g1.outer_cone_distance - 0.05, 4):
        c = solve_contact(pair, phi, np.array([[g1.pitch_cone_angle, v1]]), v1=v1, tol=1e-13)
        assert np.all(c.converged)
        assert np.max(np.abs(c.te_arcsec)) < 1e-6
        us.append(c.u1)
        # the apex-centred explicit relations: common apex -> v2 = v1 and eq (45) (spherical cosine rule)
        np.testing.assert_allclose(c.v2, v1, rtol=1e-13)
        az = np.arctan2(c.position[:, 1], c.position[:, 0])
        cos_u2 = np.cos(pair.shaft_angle) * np.cos(c.u1) + np.sin(pair.shaft_angle) * np.sin(c.u1) * np.cos(az)
        np.testing.assert_allclose(np.cos(c.u2), cos_u2, atol=1e-13)
    if case == "straight":  # the contact line is a generatrix through the apex: same u1 at every v1
        assert np.ptp(np.array(us), axis=0).max() < 1e-10


@pytest.mark.parametrize("case", ["straight", "spiral"])
def test_both_formulations_agree_under_misalignment(case):
    g1 = (straight() if case == "straight" else spiral())[0]
    mis = BevelMisalignment(d_A=0.02 * g1.module, d_E=0.04 * g1.module, d_G=-0.02 * g1.module, d_gamma=D(0.2))
    pair, _ = _pair(case, ParabolicCrowning(0.01 / g1.module, v0=g1.mean_cone_distance), mis)
    phi = np.linspace(-0.04, 0.04, 5)
    r = solve_contact(pair, phi, np.array([[g1.pitch_cone_angle, g1.mean_cone_distance]]), tol=1e-13)
    assert np.all(r.converged)
    x0 = np.column_stack([r.u1, r.v1, r.u2, r.v2, r.phi2]) + 1e-3
    c = solve_contact(pair, phi, x0, formulation="conventional", tol=1e-13)
    assert np.all(c.converged)
    np.testing.assert_allclose(c.unknowns(), r.unknowns("conventional"), atol=1e-9)
    u2, v2, phi2 = reduced_unknowns(pair, r.u1, r.v1, phi)
    p2, n2 = pair.member2(u2, v2, phi2)
    np.testing.assert_allclose(p2, r.position, atol=1e-11)
    np.testing.assert_allclose(n2, -r.normal, atol=1e-9)


def test_bad_input():
    with pytest.raises(ValueError, match="n_teeth"):
        BevelGearData(2, 30, 1.0, D(20), 4.0)
    with pytest.raises(ValueError, match="spiral_angle"):
        BevelGearData(17, 17, 1.0, D(20), 4.0, spiral_angle=D(95))
    with pytest.raises(ValueError, match="face_width"):
        BevelGearData(17, 17, 1.0, D(20), 40.0)
    g1, g2 = straight()
    with pytest.raises(ValueError, match="side"):
        SphericalInvoluteFlank(g1, 0)
    with pytest.raises(ValueError, match="mate_teeth"):
        mating_bevel_flanks(g1, g1)
    f1, f2 = mating_bevel_flanks(g1, g2)
    with pytest.raises(ValueError, match="shaft_angle"):
        BevelPair(f1, f2, 39, 32, shaft_angle=0.0)
    with pytest.raises(ValueError, match="n2"):
        BevelPair(f1, f2, 39, 31)
    with pytest.raises(ValueError, match="d_gamma"):
        BevelMisalignment(d_gamma=1.0)
    with pytest.raises(ValueError, match="spherical"):
        AxialForm(object())


def test_relative_curvature_of_the_crowned_straight_pair_closed_form():
    """At a contact of the aligned straight pair with a parabolic lead crown c1 on gear 1 the relative
    curvatures are the two profile curvatures (cot(sigma_i) / v, both flanks convex) and, along the
    generatrix, 2 c1 (to the order of the crown's curvature of its own, ~1e-3 relative)."""
    from gearrep.curvature import relative_curvature
    from gearrep.tca import contact_curvatures

    c1 = 0.002
    pair, g1 = _pair("straight", ParabolicCrowning(c1, v0=straight()[0].mean_cone_distance))
    g2 = straight()[1]
    c = solve_contact(
        pair, np.array([-0.03, 0.0, 0.03]), np.array([[g1.pitch_cone_angle, g1.mean_cone_distance]]), tol=1e-13
    )
    assert np.all(c.converged)
    np.testing.assert_allclose(c.v1, g1.mean_cone_distance, atol=1e-9)  # the crown centres the contact
    rel = relative_curvature(*contact_curvatures(pair, c))
    s1 = np.arccos(np.cos(c.u1) / np.cos(g1.base_cone_angle))
    s2 = np.arccos(np.cos(c.u2) / np.cos(g2.base_cone_angle))
    k_profile = (1 / np.tan(s1) + 1 / np.tan(s2)) / c.v1
    k = np.sort(np.abs(np.stack([rel.k1, rel.k2], axis=-1)), axis=-1)
    np.testing.assert_allclose(k[:, 1], k_profile, rtol=1e-6)
    np.testing.assert_allclose(k[:, 0], 2 * c1, rtol=2e-3)


@pytest.mark.numerics
@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_one_point_bevel_solve_gives_its_batch_row(formulation):
    """A solve of one point of a misaligned crowned bevel pair (kernels on Python floats) returns
    what the point gets in a batch: the same status and, where it converged, every field within the
    solver's accuracy (tests/_numerics.py), from starts scattered about the pitch-cone contact."""
    rng = np.random.default_rng(11)
    fields = [*ContactPoints.ARRAYS, "condition"]
    statuses = set()
    for case in ("straight", "spiral"):
        g1 = (straight() if case == "straight" else spiral())[0]
        mis = BevelMisalignment(d_A=0.02 * g1.module, d_E=0.04 * g1.module, d_gamma=D(0.2))
        pair, _ = _pair(case, ParabolicCrowning(0.01 / g1.module, v0=g1.mean_cone_distance), mis)
        phi = -np.pi / (2 * pair.n1) + rng.uniform(-0.3, 0.3, 30) * 2 * np.pi / pair.n1
        start = default_start(pair, phi, formulation)
        start = start + rng.normal(0.0, 0.02, start.shape) * np.abs(start).max(axis=0)
        batch = solve_contact(pair, phi, start, formulation=formulation, tol=1e-12)
        statuses |= set(batch.status.tolist())
        for i in range(len(phi)):
            one = solve_contact(pair, phi[i : i + 1], start[i : i + 1], formulation=formulation, tol=1e-12)
            assert_same_solve(one, batch, 1e-12, fields, [0], [i], what=f"{case} point {i}")
    assert Status.CONVERGED in statuses
