"""Spherical-involute straight and spiral bevel flanks (thesis seed 003 eq 6-9, 45-51) and the
bevel TCA (intersecting axes, eq 47-48) in both formulations."""

import numpy as np
import pytest

from gearrep.curvature import principal_curvatures
from gearrep.surface import AxialForm, fd_derivatives
from gearrep.surfaces.bevel import (
    BevelGearData,
    SphericalInvoluteFlank,
    mating_bevel_flanks,
    relief_from_length,
    spherical_involute_azimuth,
    spherical_involute_eq48,
)
from gearrep.surfaces.involute import CircularCrowning, LogarithmicCrowning, ParabolicCrowning
from gearrep.tca import BevelMisalignment, BevelPair, reduced_unknowns, solve_contact

D = np.radians


def straight(n1=39, n2=32):
    return BevelGearData(n1, n2, 2.5, D(20), 14.0), BevelGearData(n2, n1, 2.5, D(20), 14.0)


def spiral():
    g = BevelGearData(17, 17, 1.0, D(20), 4.8, spiral_angle=D(35))
    return g, g


def _crowns(g):
    rm = g.mean_cone_distance
    return {
        None: None,
        "par": ParabolicCrowning(0.02, v0=rm),
        "circ": CircularCrowning(0.05, g.face_width, v0=rm),
        "log": LogarithmicCrowning(0.01, 0.9, 0.5 * g.face_width, v0=rm),
    }


def _grid(f, n=7, margin=1e-3):
    u = np.linspace(f.u_min + margin * (f.u_max - f.u_min), f.u_max, n)
    v = np.linspace(f.v_min, f.v_max, n)
    return np.meshgrid(u, v)


def test_table5_cone_angles():
    # Table 5 prints the face cones 52.90 / 41.64 deg and, as "base cones", the root cones 47.79 / 36.53 deg
    g1, g2 = straight()
    assert np.degrees(g1.face_cone_angle) == pytest.approx(52.90, abs=0.005)
    assert np.degrees(g2.face_cone_angle) == pytest.approx(41.64, abs=0.005)
    assert np.degrees(g1.root_cone_angle) == pytest.approx(47.79, abs=0.005)
    assert np.degrees(g2.root_cone_angle) == pytest.approx(36.53, abs=0.005)
    # the true base cones (sin a_b = sin delta_p cos alpha) differ from the printed values
    assert np.degrees(g1.base_cone_angle) == pytest.approx(46.590, abs=1e-3)
    assert np.degrees(g2.base_cone_angle) == pytest.approx(36.588, abs=1e-3)
    assert g1.outer_cone_distance == pytest.approx(g2.outer_cone_distance, rel=1e-14)


@pytest.mark.parametrize("case", ["straight", "spiral"])
@pytest.mark.parametrize("crown", [None, "par", "circ", "log"])
@pytest.mark.parametrize("side", [1, -1])
def test_every_point_on_its_sphere_and_derivatives(case, crown, side):
    g, _ = straight() if case == "straight" else spiral()
    f = SphericalInvoluteFlank(g, side, 1, crowning=_crowns(g)[crown], relief=[relief_from_length(g, 0.16, 0.08)])
    u, v = _grid(f, margin=0.05)  # away from the cusp at the base cone (r_uu ~ 1/sin(sigma))
    P = f.evaluate(u, v)
    assert np.max(np.abs(np.linalg.norm(P.r, axis=-1) - v)) < 1e-12 * g.outer_cone_distance
    # analytic first derivatives against 4th-order differences; second ones against differences
    # of the analytic first ones
    Q = fd_derivatives(f.position, u, v, 1e-5, 1e-4)
    for name in ("r_u", "r_v"):
        a, b = getattr(P, name), getattr(Q, name)
        assert np.max(np.abs(a - b)) < 1e-8 * np.max(np.abs(a))
    _second_derivatives_match_differences(f, P, u, v)


def _second_derivatives_match_differences(surface, P, u, v, h=1e-6):
    """``P`` = surface.evaluate(u, v): its second derivatives against central differences of the
    analytic first ones."""
    A, B = surface.evaluate(u + h, v), surface.evaluate(u - h, v)
    C, E = surface.evaluate(u, v + h), surface.evaluate(u, v - h)
    for got, want in (
        (P.r_uu, (A.r_u - B.r_u) / (2 * h)),
        (P.r_uv, (C.r_u - E.r_u) / (2 * h)),
        (P.r_vv, (C.r_v - E.r_v) / (2 * h)),
    ):
        assert np.max(np.abs(got - want)) < 1e-6 * (1 + np.max(np.abs(got)))


@pytest.mark.parametrize("case", ["straight", "spiral"])
def test_profile_is_a_spherical_involute(case):
    """The great circle normal to the profile (the curve v = const on the sphere |r| = v) at a point
    is tangent to the base cone: its plane, spanned by r and the in-sphere normal r x r_u, has the
    normal unit(r_u), which makes the angle 90 deg - a_b with the axis. On the straight flank the
    flank normal n is that in-sphere normal (r x n is along r_u)."""
    g, _ = straight() if case == "straight" else spiral()
    f = SphericalInvoluteFlank(g, 1, 1)
    u, v = _grid(f, 9)
    P = f.evaluate(u, v)
    m = P.r_u / np.linalg.norm(P.r_u, axis=-1, keepdims=True)
    assert np.max(np.abs(np.abs(m[..., 2]) - np.sin(f.a_b))) < 1e-13
    if case == "straight":
        k = np.cross(P.r, P.normal) / np.linalg.norm(P.r, axis=-1, keepdims=True)
        assert np.max(np.abs(np.abs(k[..., 2]) - np.sin(f.a_b))) < 1e-13


def test_eq48_is_the_same_spherical_involute():
    """Eq (48)-(50) (generating angle beta, cone distance R) give the involute leaving the base cone
    at azimuth 0 whose azimuth is I(u) at the polar angle u of eq (49)."""
    g, _ = straight()
    a_b = g.base_cone_angle
    beta = np.linspace(0.0, 0.4, 9)
    pts = spherical_involute_eq48(beta, 50.0, a_b)
    u = np.arccos(pts[:, 2] / 50.0)
    np.testing.assert_allclose(np.cos(u), np.cos(a_b) * np.cos(beta * np.sin(a_b)), atol=1e-15)  # eq 49 (Napier)
    np.testing.assert_allclose(np.arctan2(pts[:, 1], pts[:, 0]), spherical_involute_azimuth(u, a_b), atol=1e-14)
    # with the spiral turn of eq (51) the points turn rigidly about the axis
    q = spherical_involute_eq48(beta, 50.0, a_b, theta=0.3)
    np.testing.assert_allclose(np.arctan2(q[:, 1], q[:, 0]), spherical_involute_azimuth(u, a_b) + 0.3, atol=1e-14)
    assert np.isnan(spherical_involute_azimuth(0.9 * a_b, a_b))


def test_spiral_angle_on_the_base_cone():
    """Eq (51): the base-cone curve of the profile crosses the generatrices at the spiral angle."""
    g, _ = spiral()
    f = SphericalInvoluteFlank(g, 1, 1)
    v = np.linspace(f.v_min, f.v_max, 5)
    _, t1, _ = f.twist(v)
    np.testing.assert_allclose(np.abs(v * np.sin(f.a_b) * t1), np.tan(g.spiral_angle), rtol=1e-14)


def test_closed_form_curvature_at_the_pitch_point():
    """The straight flank is a cone (a generatrix is a straight line: curvature 0); across it the
    normal curvature is the geodesic curvature of the spherical involute on the sphere of radius v,
    cot(sigma)/v, with cos(sigma) = cos(delta_p)/cos(a_b) (the osculating circle is centred at the
    tangency point on the base cone)."""
    g, _ = straight()
    f = SphericalInvoluteFlank(g, 1, 1)
    v = np.array([g.mean_cone_distance, g.outer_cone_distance])
    pc = principal_curvatures(f.evaluate(np.full(2, g.pitch_cone_angle), v))
    k = np.stack([pc[0], pc[1]], axis=-1)
    sig = np.arccos(np.cos(g.pitch_cone_angle) / np.cos(g.base_cone_angle))
    np.testing.assert_allclose(np.min(np.abs(k), axis=-1), 0.0, atol=1e-12)
    np.testing.assert_allclose(np.max(np.abs(k), axis=-1), 1.0 / (np.tan(sig) * v), rtol=1e-10)


def test_axial_form_is_the_same_surface():
    g, _ = spiral()
    f = SphericalInvoluteFlank(g, 1, 1, crowning=ParabolicCrowning(0.02, v0=g.mean_cone_distance))
    u, v = _grid(f)
    a = AxialForm(f)
    P, Q = f.evaluate(u, v), a.evaluate(v * np.sin(u), v * np.cos(u))
    np.testing.assert_allclose(Q.r, P.r, atol=1e-13)
    np.testing.assert_allclose(Q.normal, P.normal, atol=1e-12)
    R = fd_derivatives(a.position, v * np.sin(u), v * np.cos(u), 1e-5, 1e-5)
    for name in ("r_u", "r_v"):
        assert np.max(np.abs(getattr(Q, name) - getattr(R, name))) < 1e-8
    # the chain rule's second derivatives against differences of its analytic first ones
    rho, z = v * np.sin(u), v * np.cos(u)
    _second_derivatives_match_differences(a, Q, rho, z)
    # by components (structure of arrays, what the TCA kernels read): the same numbers
    for vec, comps in zip((Q.r, Q.r_u, Q.r_v, Q.r_uu, Q.r_uv, Q.r_vv), a.evaluate_components(rho, z)):
        np.testing.assert_array_equal(np.stack(np.broadcast_arrays(*comps), axis=-1), vec)


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
