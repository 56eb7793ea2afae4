"""gearrep.surfaces.rack: straight and parabolic (seed 002 sec. 2.1-2.3) rack-cutter surfaces."""

import numpy as np
import pytest
from _envelope_cases import principal

from gearrep.surface import fd_derivatives
from gearrep.surfaces.rack import ParabolicRackCutter, StraightRackCutter, vertex_pitch_distance
from gearrep.units import DEG

RACKS = [
    StraightRackCutter(20 * DEG),
    StraightRackCutter(25 * DEG, beta=-15 * DEG, y0=0.4, side=-1),
    ParabolicRackCutter(0.425, 25 * DEG, vertex_pitch_distance(25 * DEG, 5.0), beta=19.948 * DEG),
    ParabolicRackCutter(-0.3, 20 * DEG, 0.3, beta=10 * DEG, y0=-0.2, side=-1),
]


@pytest.mark.parametrize("rack", RACKS)
def test_analytic_derivatives_match_finite_differences(rack):
    u, th = np.meshgrid(np.linspace(-0.6, 0.6, 5), np.linspace(-2.0, 2.0, 3))
    p = rack.evaluate(u, th)
    q = fd_derivatives(rack.position, u, th)
    # FD rounding: ~eps |r| / h for first, ~eps |r| / h^2 (~1e-9 here) for second derivatives
    for name, tol in (("r", 1e-15), ("r_u", 1e-11), ("r_v", 1e-11), ("r_uu", 1e-8), ("r_uv", 1e-8), ("r_vv", 1e-8)):
        np.testing.assert_allclose(getattr(p, name), getattr(q, name), atol=tol, err_msg=name)
    assert p.r.shape == u.shape + (3,)


def test_straight_rack_geometry():
    an, beta, y0 = 20 * DEG, 15 * DEG, 0.3
    rack = StraightRackCutter(an, beta, y0=y0, side=1)
    u, th = np.linspace(-1, 1, 7), np.linspace(-2, 2, 7)
    p = rack.evaluate(u, th)
    # height = u cos(alpha_n); theta is the displacement along the tooth direction
    np.testing.assert_allclose(p.r[:, 0], u * np.cos(an), atol=1e-15)
    np.testing.assert_allclose(p.r @ rack.t, th, atol=1e-15)
    # profile crosses the pitch line at y_b = y0
    np.testing.assert_allclose(rack.position(0.0, 0.0) @ rack.e_yb, y0, atol=1e-15)
    # transverse section (z_c = const) is straight with tan(alpha_t) = tan(alpha_n)/cos(beta)
    alpha_t = np.arctan(np.tan(an) / np.cos(beta))
    # along a curve with dz = 0: r_u du + t dth, dth = -(r_u)_z / t_z du
    d = p.r_u - p.r_v * (p.r_u[:, 2] / rack.t[2])[:, None]
    np.testing.assert_allclose(d[:, 1] / d[:, 0], np.tan(alpha_t), rtol=1e-14)
    # normal N = side sin(a) e_x - cos(a) e_yb; the rack is a plane: zero curvature
    N = np.cross(p.r_u, p.r_v)
    np.testing.assert_allclose(N, np.sin(an) * rack.e_x - np.cos(an) * rack.e_yb + 0 * N, atol=1e-15)
    k1, k2, *_ = principal(p)
    np.testing.assert_allclose([k1, k2], 0.0, atol=1e-15)


def test_parabolic_rack_seed002_construction():
    """seed 002 eq 2.2.1-2.2.5, 2.5.1-2.5.2, 2.7: vertex Q at |QP| = l on the normal through P,
    profile curvature 2a at Q, principal curvatures 0 (generatrix) and 2a (profile)."""
    an, Pn, a, beta, y0 = 25 * DEG, 5.0, 0.425, 19.948 * DEG, 0.1
    l = vertex_pitch_distance(an, Pn)
    assert l == pytest.approx(np.cos(an) / Pn, rel=1e-15)
    rack = ParabolicRackCutter(a, an, l, beta=beta, y0=y0)
    p = rack.evaluate(0.0, 0.0)
    P = y0 * rack.e_yb  # pitch point of this normal section (theta = 0)
    np.testing.assert_allclose(np.linalg.norm(p.r - P), l, rtol=1e-14)
    n = p.normal
    np.testing.assert_allclose(np.linalg.norm(np.cross(P - p.r, n)), 0.0, atol=1e-15)  # normal through P
    # tangent at Q inclined at alpha_n to the tooth height x_c
    np.testing.assert_allclose(p.r_u[0], np.cos(an), rtol=1e-14)
    assert p.r[0] == pytest.approx(l * np.sin(an), rel=1e-14)
    np.testing.assert_allclose(abs(rack.profile_curvature(0.0)), 2 * a, rtol=1e-14)
    k1, k2, e1, e2, _ = principal(p)
    ks = np.sort([k1, k2])
    np.testing.assert_allclose(np.abs(ks[np.argmax(np.abs(ks))]), 2 * a, rtol=1e-12)
    np.testing.assert_allclose(ks[np.argmin(np.abs(ks))], 0.0, atol=1e-14)
    # the zero-curvature direction is the generatrix (tooth direction)
    e0 = e1 if abs(k1) < abs(k2) else e2
    np.testing.assert_allclose(abs(e0 @ rack.t), 1.0, rtol=1e-12)
    # curvature along the profile: x_a = u, y_a = a u^2 in the (tangent, normal) frame at Q
    u = np.linspace(-0.5, 0.5, 11)
    r = rack.position(u, 0.0) - p.r
    xb, yb = r[:, 0], r @ rack.e_yb  # normal-section coordinates relative to Q
    np.testing.assert_allclose(xb * rack.tangent_q[0] + yb * rack.tangent_q[1], u, atol=1e-14)
    np.testing.assert_allclose(xb * rack.normal_q[0] + yb * rack.normal_q[1], a * u**2, atol=1e-14)
    np.testing.assert_allclose(r @ rack.t, 0.0, atol=1e-15)  # theta = 0 is one normal section


def test_vectorised_shapes():
    rack = ParabolicRackCutter(0.4, 25 * DEG, 0.2, beta=0.3)
    u = np.zeros((2, 3, 4))
    assert rack.position(u, 1.0).shape == (2, 3, 4, 3)
    p = rack.evaluate(u, np.ones(4))
    assert p.r_uu.shape == (2, 3, 4, 3) and p.r_vv.shape == (2, 3, 4, 3)


@pytest.mark.parametrize(
    "make, match",
    [
        (lambda: StraightRackCutter(0.0), "alpha_n"),
        (lambda: StraightRackCutter(np.pi / 2), "alpha_n"),
        (lambda: StraightRackCutter(0.3, beta=np.pi / 2), "beta"),
        (lambda: StraightRackCutter(0.3, side=0), "side"),
        (lambda: StraightRackCutter(0.3, y0=np.nan), "y0"),
        (lambda: ParabolicRackCutter(np.inf, 0.3, 0.1), "a"),
        (lambda: ParabolicRackCutter(0.4, 0.3, np.nan), "l"),
        (lambda: vertex_pitch_distance(0.4, 0.0), "P_n"),
        (lambda: vertex_pitch_distance(2.0, 5.0), "alpha_n"),
    ],
)
def test_validation(make, match):
    with pytest.raises(ValueError, match=match):
        make()


def test_circular_arc_profile():
    """The arc is the osculating circle of the parabola a = 1/(2 rho) at Q (same point, tangent and
    curvature), parameterised by arc length; its pitch crossing matches the base formula (which
    ignores third derivatives) where the normal is not parallel to the pitch line, and is constant
    for an arc centred on the pitch line (l = rho)."""
    from gearrep.surfaces.rack import CircularArcRackCutter, RackCutter

    an, rho, l = 27 * DEG, 0.23, 0.18
    arc, par = CircularArcRackCutter(rho, an, l, beta=0.3), ParabolicRackCutter(1 / (2 * rho), an, l, beta=0.3)
    pa, pp = arc.profile(np.array([0.0])), par.profile(np.array([0.0]))
    np.testing.assert_allclose(np.ravel(pa), np.ravel(pp), atol=1e-15)
    u = np.linspace(-0.3, 0.3, 7)
    x, y, x1, y1, x2, y2 = arc.profile(u)
    np.testing.assert_allclose(np.hypot(x - arc.centre[0], y - arc.centre[1]), rho, atol=1e-15)
    np.testing.assert_allclose(np.hypot(x1, y1), 1.0, atol=1e-15)  # arc length
    np.testing.assert_allclose(arc.profile_curvature(u), np.full(u.shape, arc.profile_curvature(0.0)), atol=1e-12)
    # y_P: where the normal line meets x = 0, by intersecting it directly
    yp = y - x * (-x1) / y1
    np.testing.assert_allclose(arc.pitch_crossing(u)[0], yp, atol=1e-13)
    h = 1e-5
    d1 = (arc.pitch_crossing(u + h)[0] - arc.pitch_crossing(u - h)[0]) / (2 * h)
    d2 = (arc.pitch_crossing(u + h)[1] - arc.pitch_crossing(u - h)[1]) / (2 * h)
    np.testing.assert_allclose(arc.pitch_crossing(u)[1], d1, rtol=1e-5)
    np.testing.assert_allclose(arc.pitch_crossing(u)[2], d2, rtol=1e-5)
    np.testing.assert_allclose(RackCutter.pitch_crossing(par, u)[0], par.pitch_crossing(u)[0])
    centred = CircularArcRackCutter(0.2, an, 0.2)
    assert centred.centre[0] == 0.0
    u0 = -0.2 * an  # the arc's crossing with the pitch line (zero pressure angle)
    assert centred.profile(np.array([u0]))[0][0] == pytest.approx(0.0, abs=1e-15)
    np.testing.assert_allclose(centred.pitch_crossing(np.array([u0, 0.0, 0.1]))[0], centred.centre[1], atol=0)
    with pytest.raises(ValueError, match="rho"):
        CircularArcRackCutter(0.0, an, 0.2)
    with pytest.raises(ValueError, match="rho"):
        CircularArcRackCutter(np.inf, an, 0.2)
    with pytest.raises(ValueError, match="l"):
        CircularArcRackCutter(0.2, an, np.nan)
    with pytest.raises(ValueError, match="alpha_n"):
        CircularArcRackCutter(0.2, 0.0, 0.2)
