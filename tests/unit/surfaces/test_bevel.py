"""Spherical-involute straight and spiral bevel flanks (thesis seed 003 eq 6-9, 45-51); the bevel TCA
is tested in tests/unit/tca/test_bevel.py."""

import numpy as np
import pytest
from _gear_pairs import spiral_bevel as spiral
from _gear_pairs import straight_bevel as straight
from _numerics import assert_rounding_close

from gearrep.curvature import principal_curvatures
from gearrep.surface import AxialForm, fd_derivatives
from gearrep.surfaces.bevel import (
    SphericalInvoluteFlank,
    relief_from_length,
    spherical_involute_azimuth,
    spherical_involute_eq48,
)
from gearrep.surfaces.involute import CircularCrowning, LogarithmicCrowning, ParabolicCrowning

D = np.radians


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


@pytest.mark.numerics
@pytest.mark.parametrize("crown", [None, "par", "circ", "log"])
def test_one_point_on_floats_gives_the_array_values(crown):
    """A bevel flank (and its axial form) evaluated at one point given as Python floats computes on
    floats (the single-point TCA's path) and gives the array path's values within rounding (math's
    sine and cosine against numpy's), with tip and root relief on and off the point; inside the base
    cone the floats raise ValueError where the arrays give NaN."""
    for g in (straight()[0], spiral()[0]):
        rel = [relief_from_length(g, 0.16, 0.08), relief_from_length(g, 0.16, 0.05, root=True)]
        f = SphericalInvoluteFlank(g, -1, -1, crowning=_crowns(g)[crown], relief=rel)
        a = AxialForm(f)
        for su, sv in ((0.02, 0.3), (0.5, 0.5), (0.97, 0.9)):
            u, v = f.u_min + su * (f.u_max - f.u_min), f.v_min + sv * (f.v_max - f.v_min)
            for surf, (p, q) in ((f, (u, v)), (a, (v * np.sin(u), v * np.cos(u)))):
                one = surf.evaluate_components(float(p), float(q))
                assert all(type(c) is float for vec in one for c in vec)
                arr = surf.evaluate_components(np.array([p]), np.array([q]))
                for vo, va in zip(one, arr):
                    assert_rounding_close(
                        np.array(vo), np.concatenate([np.ravel(np.broadcast_to(c, (1,))) for c in va])
                    )
        with pytest.raises(ValueError, match="base cone"):
            f.evaluate_components(0.5 * f.a_b, float(f.v_max))
        assert np.isnan(f.evaluate_components(np.array([0.5 * f.a_b]), np.array([f.v_max]))[0][0]).all()
