"""gearrep.surfaces.novikov: closed-form rack-generated flanks (seed 002 eq 2.2.6-2.3.6) against the
library's envelope solve and EnvelopeSurface derivatives; the pair's TCA is tested in
tests/unit/tca/test_novikov.py."""

import numpy as np
import pytest
from _numerics import assert_rounding_close, assert_same_solve, solve_bound

from gearrep import frames
from gearrep.surface import fd_derivatives
from gearrep.surfaces.novikov import RackGeneratedFlank, pitch_radius
from gearrep.units import DEG


@pytest.mark.parametrize("side, beta", [(-1, 19.948 * DEG), (1, 19.948 * DEG), (-1, -19.948 * DEG), (1, -10 * DEG)])
def test_closed_form_matches_envelope(side, beta):
    f = RackGeneratedFlank(0.425 if side < 0 else 0.394, 25 * DEG, 0.18126, beta, 1.81 if side < 0 else 8.19, side)
    u = np.array([-0.12, 0.0, 0.07, 0.15])
    th = np.array([0.5, -1.0, 2.0, 0.0])
    rec = f.solve(u, th)
    assert np.all(rec.converged)
    e = f.evaluate(u, th)
    np.testing.assert_allclose(e.r, rec.point, atol=1e-12)
    phi = f.rolling_angle(u, th)[0]
    np.testing.assert_allclose(phi, rec.param("phi"), atol=1e-13)
    # meshing equation satisfied exactly at the closed-form angle
    q = np.column_stack([u, th, phi])
    assert np.max(np.abs(f.envelope.meshing(q))) < 1e-13
    es = f._surface.evaluate(u, th)  # EnvelopeSurface: analytic first, FD-tangential second derivatives
    for a, b in ((e.r_u, es.r_u), (e.r_v, es.r_v)):
        np.testing.assert_allclose(a, b, atol=1e-13)
    fd = fd_derivatives(f.position, u, th, 1e-3, 1e-3)
    for a, b in ((e.r_uu, fd.r_uu), (e.r_uv, fd.r_uv), (e.r_vv, fd.r_vv)):
        np.testing.assert_allclose(a, b, atol=1e-7)


def test_bad_input():
    with pytest.raises(ValueError, match="outward_sign"):
        RackGeneratedFlank(0.4, 25 * DEG, 0.18, 0.3, 2.0, -1, outward_sign=0)
    with pytest.raises(ValueError, match="u_range"):
        RackGeneratedFlank(0.4, 25 * DEG, 0.18, 0.3, 2.0, -1, u_range=(1.0, -1.0))
    with pytest.raises(ValueError, match="P_n"):
        pitch_radius(17, 0.0, 0.3)
    with pytest.raises(ValueError, match="N"):
        pitch_radius(1.5, 5.0, 0.3)
    assert pitch_radius(17, 5.0, np.arccos(0.94)) == pytest.approx(17 / 9.4)


@pytest.mark.parametrize("feed, hand", [("translation", "opposite"), ("translation", "same"), ("rotation", "opposite")])
def test_unplunged_worm_grinds_the_rack_generated_pinion(feed, hand):
    """Without plunging the worm's and pinion's racks coincide, so the two-parameter envelope is the
    rack-generated pinion (module doc of WormGeneratedPinion), for either feed and worm hand;
    plunging removes material away from l = 0."""
    from gearrep.solve import newton
    from gearrep.surfaces.worm_ground import WormGeneratedPinion

    an, Pn, beta = 25 * DEG, 5.0, -np.arccos(0.94)
    l, rp, a = np.cos(an) / Pn, pitch_radius(17, Pn, beta), Pn / (2 * 5.88)
    pin = RackGeneratedFlank(a, an, l, beta, rp, -1)
    psi, ll = np.meshgrid(np.linspace(-0.2, 0.2, 3), np.linspace(-0.8, 0.8, 3))
    for a_pl, lo, hi in ((0.0, 0.0, 1e-12), (0.00139, 1e-5, 2e-3)):
        w = WormGeneratedPinion(a, an, l, beta, rp, Pn, 3.82, a_pl, feed=feed, worm_hand=hand)
        rec = w.solve(psi.ravel(), ll.ravel())
        assert np.all(rec.converged)

        def F(x, idx, pts=rec.point):
            return pin.evaluate(x[:, 0], x[:, 1]).r - pts[idx]

        x0 = np.column_stack([np.zeros(len(rec.point)), rec.point[:, 2] / np.cos(beta)])
        # foot of the normal from the ground point on the rack-generated pinion: F parallel to its normal
        # (two components of F x n vanish), then the gap is |F . n|
        res = newton(
            lambda x, idx: np.cross(F(x, idx), pin.evaluate(x[:, 0], x[:, 1]).normal)[:, :2], x0, tol=1e-13, rows=True
        )
        assert np.all(res.converged)
        gap = np.abs(np.einsum("na,na->n", F(res.x, np.arange(len(x0))), pin.evaluate(res.x[:, 0], res.x[:, 1]).normal))
        mid = np.abs(ll.ravel()) < 1e-12
        assert np.all(gap[mid] <= 1e-12)
        assert np.all(gap[~mid] >= lo) and np.all(gap <= hi)


def _screw_parameter(flank):
    """p of a helicoid from its normals: n . (e_z x r + p e_z) = 0 (p > 0: right hand)."""
    e = flank.evaluate(np.array([0.0, 0.05]), np.array([0.1, 0.3]))
    p = -np.sum(np.cross([0.0, 0.0, 1.0], e.r) * e.normal, -1) / e.normal[:, 2]
    assert p[0] == pytest.approx(p[1], rel=1e-9)
    return p[0]


def test_worm_hand_and_crossing_angle():
    """The worm of the pinion's hand meshes with the pinion's rack at 90 - beta + lambda_w between the
    axes, the opposite-hand worm at 90 - beta - lambda_w (the value printed as seed 002 eq 5.2.1);
    the worm's screw parameter is r_pw tan(lambda_w) in magnitude."""
    from gearrep.surfaces.worm_ground import WormGeneratedPinion

    an, Pn, beta = 25 * DEG, 5.0, -np.arccos(0.94)  # left-hand pinion
    l, rp, a = np.cos(an) / Pn, pitch_radius(17, Pn, beta), Pn / (2 * 5.88)
    assert _screw_parameter(RackGeneratedFlank(a, an, l, beta, rp, -1)) < 0  # left hand
    lam = np.arcsin(1 / (2 * Pn * 3.82))
    for hand, sign, angle in (("same", -1, np.pi / 2 - abs(beta) + lam), ("opposite", 1, np.pi / 2 - abs(beta) - lam)):
        w = WormGeneratedPinion(a, an, l, beta, rp, Pn, 3.82, 0.0, worm_hand=hand)
        p = _screw_parameter(w.worm)
        assert np.sign(p) == sign and abs(p) == pytest.approx(3.82 * np.tan(lam), rel=1e-9)
        between_axes = np.pi / 2 - abs(np.pi / 2 - abs(w.delta) % np.pi)
        assert between_axes == pytest.approx(angle, abs=1e-12)


@pytest.mark.parametrize("feed", ["translation", "rotation"])
def test_worm_motion_derivatives(feed):
    """The worm -> pinion motion's exact dM and d2M (product rule over shared products) equal the
    finite-difference derivatives of its M (FunctionMotion, 4th order); batched and single points
    give the same matrices."""
    from gearrep.envelope import FunctionMotion
    from gearrep.surfaces.worm_ground import WormGeneratedPinion

    an, Pn, beta = 25 * DEG, 5.0, -np.arccos(0.94)
    l, rp, a = np.cos(an) / Pn, pitch_radius(17, Pn, beta), Pn / (2 * 5.88)
    w = WormGeneratedPinion(a, an, l, beta, rp, Pn, 3.82, 0.00139, feed=feed)
    m = np.array([[0.1, -0.8], [-0.3, 0.5], [0.0, 1.7]])
    M, dM, d2M = w.motion.matrices(m)
    assert (M.shape, dM.shape, d2M.shape) == ((3, 4, 4), (3, 2, 4, 4), (3, 2, 2, 4, 4))
    A, (B, _, _), C, D = w._factors(m)
    np.testing.assert_array_equal(M, A[0] @ B @ C @ D[0])
    fdM, fdd, fdd2 = FunctionMotion(lambda mm: w.motion.matrices(mm)[0], n_params=2, names=("psi", "l")).matrices(m)
    np.testing.assert_array_equal(fdM, M)
    np.testing.assert_allclose(dM, fdd, atol=1e-9)
    np.testing.assert_allclose(d2M, fdd2, atol=1e-6)
    for i in range(3):
        for got, want in zip(w.motion.matrices(m[i]), (M[i], dM[i], d2M[i])):
            np.testing.assert_array_equal(got, want)


def test_worm_options_are_checked():
    from gearrep.surfaces.worm_ground import WormGeneratedPinion

    args = (0.425, 25 * DEG, 0.18, -0.35, 1.8, 5.0, 3.82, 0.001)
    with pytest.raises(ValueError, match="feed"):
        WormGeneratedPinion(*args, feed="screw")
    with pytest.raises(ValueError, match="worm_hand"):
        WormGeneratedPinion(*args, worm_hand="left")


def test_normal_part_surface_matches_envelope_surface():
    """NormalPartSurface: same r, r_u, r_v as EnvelopeSurface and the same normal components of the
    second derivatives (hence the same unit-normal derivatives and curvatures)."""
    from gearrep.curvature import principal_curvatures
    from gearrep.surfaces.worm_ground import WormGeneratedPinion

    an, Pn, beta = 25 * DEG, 5.0, -np.arccos(0.94)
    w = WormGeneratedPinion(Pn / (2 * 5.88), an, np.cos(an) / Pn, beta, pitch_radius(17, Pn, beta), Pn, 3.82, 0.00139)
    psi, ll = np.array([-0.1, 0.0, 0.15]), np.array([0.5, -0.7, 1.2])
    full, light = w.evaluate(psi, ll), w.light().evaluate(psi, ll)
    # r_u of the envelope surface against central differences of the position (translation feed)
    h = 1e-6
    np.testing.assert_allclose((w.position(psi + h, ll) - w.position(psi - h, ll)) / (2 * h), full.r_u, atol=1e-7)
    for a, b in ((full.r, light.r), (full.r_u, light.r_u), (full.r_v, light.r_v)):
        np.testing.assert_allclose(a, b, atol=1e-12)
    n = full.normal
    for a, b in ((full.r_uu, light.r_uu), (full.r_uv, light.r_uv), (full.r_vv, light.r_vv)):
        np.testing.assert_allclose(np.sum(a * n, -1), np.sum(b * n, -1), rtol=1e-7, atol=1e-9)
    pf, pl = principal_curvatures(full), principal_curvatures(light)
    np.testing.assert_allclose([pf.k1, pf.k2], [pl.k1, pl.k2], rtol=1e-7, atol=1e-9)
    assert w.light().outward_sign == w.outward_sign


def _plunged_worm(feed="translation", hand="opposite"):
    from gearrep.surfaces.worm_ground import WormGeneratedPinion

    an, Pn, beta = 25 * DEG, 5.0, -np.arccos(0.94)
    a, l, rp = Pn / (2 * 5.88), np.cos(an) / Pn, pitch_radius(17, Pn, beta)
    return WormGeneratedPinion(a, an, l, beta, rp, Pn, 3.82, 0.00139, feed=feed, worm_hand=hand)


def _reduction_bound(w, psi, ll, value):
    """Largest difference of a value of the worm-ground pinion between two solves of its equations of
    meshing, each to a residual below the envelope's tol: the solved parameters differ by at most
    ||J_S^-1|| 2 tol (J_S the meshing Jacobian in them, at the envelope solve's root), the point by
    that times its tangents' size, a derivative by as much relative to its own size
    (tests/_numerics.solve_bound)."""
    rec = w.solve(psi, ll)
    assert rec.converged.all()
    J = w.envelope.meshing_jacobian(rec.params)[:, :, list(w.envelope.solved)]
    tool = w.worm.evaluate(rec.params[:, 0], rec.params[:, 1])
    size = np.maximum(np.linalg.norm(tool.r_u, axis=-1), np.linalg.norm(tool.r_v, axis=-1))
    sensitivity = np.linalg.norm(np.linalg.inv(J), ord=2, axis=(1, 2)) * (1.0 + size)
    return solve_bound(w.envelope.tol, sensitivity[:, None], np.abs(value).max(axis=-1, keepdims=True))


@pytest.mark.numerics
@pytest.mark.parametrize("feed, hand", [("translation", "opposite"), ("translation", "same"), ("rotation", "opposite")])
def test_reduced_worm_surface_against_the_envelope_solve(feed, hand):
    """The worm-ground pinion by the one-dimensional reduction of its equations of meshing
    (:class:`ReducedWormSurface`, what ``light()`` returns) against the two-parameter envelope solve
    with Litvin's curvature relations (:class:`NormalPartSurface`, the evaluation it replaces): the
    same point, tangents and normal parts of the second derivatives over the flank, for either feed
    and worm hand with plunging, within the solves' accuracy; one point on floats and points
    started from the last evaluation (warm start) give the same values."""
    from gearrep.surfaces.novikov import NormalPartSurface
    from gearrep.surfaces.worm_ground import ReducedWormSurface

    w = _plunged_worm(feed, hand)
    psi, ll = (x.ravel() for x in np.meshgrid(np.linspace(-0.3, 0.3, 9), np.linspace(-1.5, 1.5, 9)))
    red = w.light()
    assert isinstance(red, ReducedWormSurface) and red.outward_sign == w.outward_sign
    new, ref = red.evaluate(psi, ll), NormalPartSurface(w).evaluate(psi, ll)
    names = ("r", "r_u", "r_v", "r_uu", "r_uv", "r_vv")
    for name in names:
        x, y = getattr(new, name), getattr(ref, name)
        assert np.all(np.abs(x - y) <= _reduction_bound(w, psi, ll, y)), name
    _, done, it = red.solve_reduced(psi, ll)  # from the linear start about the flank's middle
    assert done.all() and it.max() <= 12
    # the points moved by a small step start from the last evaluation's prediction: fewer iterations
    moved, step = (psi + 1e-3, ll - 2e-3), red._warm_start(psi + 1e-3, ll - 2e-3, False)
    _, done, it_warm = red.solve_reduced(*moved, step)
    assert done.all() and it_warm.max() <= 2
    again, fresh = red.evaluate(*moved), ReducedWormSurface(w).evaluate(*moved)
    for name in names:
        y = getattr(fresh, name)
        assert np.all(np.abs(getattr(again, name) - y) <= _reduction_bound(w, *moved, y)), name
    for i in (0, 40, 80):
        one = red.evaluate_components(float(psi[i]), float(ll[i]))
        assert all(type(c) is float for vec in one for c in vec)
        for vec, name in zip(one, names):
            y = getattr(new, name)[i : i + 1]
            assert np.all(np.abs(np.array(vec) - y) <= _reduction_bound(w, psi[i : i + 1], ll[i : i + 1], y)), name


@pytest.mark.numerics
def test_worm_ground_contacts_by_the_reduction(published):
    """The contact solve of the seed-002 worm-ground pair (3 arcmin crossing error) with the pinion
    evaluated by the one-dimensional reduction finds the contacts it found with the two-parameter
    envelope solve: the same statuses, iterations within one, values within the solver's bound."""
    from conftest import study_settings

    from gearrep.replications import litvin2000
    from gearrep.replications.litvin2000.geometry import make_worm_pair, worm_start
    from gearrep.surfaces.novikov import NormalPartSurface
    from gearrep.tca import ContactPoints, GearPair, Misalignment, solve_contact
    from gearrep.units import ARCMIN

    s = study_settings("litvin2000")
    d = litvin2000.params_from_published(published)
    pair = make_worm_pair(d, s, misalignment=Misalignment(d_gamma_out=s["misalignment_arcmin"] * ARCMIN))
    before = GearPair(
        NormalPartSurface(pair.flank1.base),
        pair.flank2,
        pair.n1,
        pair.n2,
        pair.centre_distance,
        misalignment=pair.misalignment,
        phase2=0.0,
    )
    per = 2 * np.pi / pair.n1
    phi = np.linspace(-0.5 * per, 0.5 * per, 21)
    kw = dict(formulation="conventional", tol=s["tol"], maxiter=s["maxiter"])
    a = solve_contact(pair, phi, worm_start(pair, phi), **kw)
    b = solve_contact(before, phi, worm_start(pair, phi), **kw)
    assert a.converged.all()
    assert_same_solve(a, b, s["tol"], [*ContactPoints.ARRAYS, "condition"])


def test_reduced_worm_surface_falls_back_to_the_envelope_solve():
    """Rows the reduction does not solve (here: no Newton iteration allowed) are evaluated by the
    two-parameter envelope solve; one point on floats raises ValueError (the contact solve then
    evaluates it on arrays); bad settings are refused."""
    from gearrep.surfaces.novikov import NormalPartSurface
    from gearrep.surfaces.worm_ground import ReducedWormSurface

    w = _plunged_worm()
    psi, ll = np.array([0.05, -0.2, 0.1]), np.array([0.3, 1.1, -0.9])
    stuck = ReducedWormSurface(w, maxiter=0)
    got, ref = stuck.evaluate(psi, ll), NormalPartSurface(w).evaluate(psi, ll)
    for name in ("r", "r_u", "r_v", "r_uu", "r_uv", "r_vv"):
        np.testing.assert_array_equal(getattr(got, name), getattr(ref, name))
    with pytest.raises(ValueError, match="reduced worm-pinion solve failed"):
        stuck.evaluate_components(0.05, 0.3)
    with pytest.raises(ValueError, match="tol"):
        ReducedWormSurface(w, tol=0.0)
    with pytest.raises(ValueError, match="WormGeneratedPinion"):
        ReducedWormSurface(NormalPartSurface(w))


def _straight_rack_member(N=17, beta=0.35):
    """A member generated by a straight rack (parabola coefficient 0): an involute helicoid."""
    an, Pn = 25 * DEG, 5.0
    f = RackGeneratedFlank(0.0, an, np.cos(an) / Pn, beta, pitch_radius(N, Pn, beta), -1)
    alpha_t = np.arctan(np.tan(an) / np.cos(beta))
    return f, Pn, alpha_t


@pytest.mark.parametrize("beta", [0.35, -0.35])
def test_undercut_limit_of_a_straight_rack(beta):
    """Straight rack profile: Litvin's limiting line lies at x = -r_p sin^2(alpha_t) (either hand)."""
    from gearrep.surfaces.novikov import undercut_limit

    f, Pn, alpha_t = _straight_rack_member(beta=beta)
    u, x_b = undercut_limit(f, -1.0 / Pn)
    assert x_b == pytest.approx(-f.r_p * np.sin(alpha_t) ** 2, rel=1e-9)
    assert f.rack.profile(np.array([u]))[0][0] == pytest.approx(x_b, abs=1e-14)


def test_pointing_limit_of_an_involute_member():
    """Straight rack: at the radius pointing_limit returns, the involute tooth thickness
    s(R) = R (s_p / r_p + 2 (inv alpha_t - inv alpha_R)) equals the requested top land."""
    from gearrep.surfaces.novikov import pointing_limit, transverse_point

    f, Pn, alpha_t = _straight_rack_member()
    p_n = np.pi / Pn
    u, x_b, R = pointing_limit(f, p_n, 0.5 * p_n, 0.3 / Pn, 3.0 / Pn)
    assert transverse_point(f, u)[0][0] == pytest.approx(R, rel=1e-12) and x_b > 0
    inv = lambda a: np.tan(a) - a  # noqa: E731
    r_b = f.r_p * np.cos(alpha_t)
    s_p = 0.5 * p_n / np.cos(f.rack.beta)
    s_R = R * (s_p / f.r_p + 2 * (inv(alpha_t) - inv(np.arccos(r_b / R))))
    assert s_R == pytest.approx(0.3 / Pn, rel=1e-9)
    # a thinner rack tooth (thicker member tooth) points later; an unreachable top land gives NaN
    assert pointing_limit(f, p_n, 0.4 * p_n, 0.3 / Pn, 3.0 / Pn)[1] > x_b
    assert np.isnan(pointing_limit(f, p_n, 0.5 * p_n, 0.3 / Pn, 0.1 / Pn)[0])
    with pytest.raises(ValueError, match="rack_tooth_n"):
        pointing_limit(f, p_n, 1.2 * p_n, 0.3 / Pn, 3.0 / Pn)
    with pytest.raises(ValueError, match="top_land"):
        pointing_limit(f, p_n, 0.5 * p_n, -0.1, 3.0 / Pn)
    with pytest.raises(ValueError, match="u_max"):
        pointing_limit(f, p_n, 0.5 * p_n, 0.3 / Pn, -3.0 / Pn)


def test_disk_ground_pinion():
    """Appendices A-B: at the grinding line the pinion normal meets the disk axis over the whole
    rack-parameter range, on one branch (Newton from one start over the range once landed on roots
    thousands of radians away below u = -0.23 in, and under inputs moved by a few ulps did not
    converge there), the line passes through Q in the plane z = 0, and without plunging the swept
    line lies on the helicoid."""
    from gearrep.surfaces.novikov import DiskGroundPinion

    an, Pn, beta = 25 * DEG, 5.0, -np.arccos(0.94)
    pin = RackGeneratedFlank(0.425, an, np.cos(an) / Pn, beta, pitch_radius(17, Pn, beta), -1)
    p_n = np.pi / Pn
    disk = DiskGroundPinion(pin, 17, p_n, 0.5 * p_n, 6.0, 0.001)
    u = np.linspace(-0.45, 0.45, 1801)
    th = disk._line_theta(u, 0.0)
    r, n = disk._rn(u, th)
    dist = np.abs(np.einsum("na,na->n", r - disk._A, np.cross(n, disk._d))) / np.linalg.norm(
        np.cross(n, disk._d), axis=1
    )
    assert np.all(dist < 1e-10)  # the normal line meets the disk axis
    assert np.max(np.abs(np.diff(th))) < 0.5  # one branch: no jump to another root
    np.testing.assert_allclose(disk.line(u), r, atol=1e-11)  # spline of the line
    assert abs(disk.line(np.array([0.0]))[0, 2]) < 1e-12  # Q at z = 0
    flat = DiskGroundPinion(pin, 17, p_n, 0.5 * p_n, 6.0, 0.0)
    uu, psi = np.array([0.1, -0.1, 0.05]), np.array([0.3, -0.2, 0.1])
    x = flat.position(uu, psi)
    # the helicoid point of the same rack profile parameter at the same z (z is linear in theta)
    theta = (x[:, 2] + pin.rack.profile(uu)[1] * np.sin(beta)) / np.cos(beta)
    np.testing.assert_allclose(pin.evaluate(uu, theta).r, x, atol=1e-10)
    plunged = disk.position(uu, psi)
    assert np.all(np.linalg.norm(plunged - x, axis=1) > 1e-6)  # the plunge moves the swept points
    # pointwise position: the finite differences in one call give the per-offset values
    assert disk.pointwise
    e, f = disk.fd_evaluate(uu, psi), fd_derivatives(disk.position, uu, psi, *disk.fd_step)
    for name in ("r", "r_u", "r_v", "r_uu", "r_uv", "r_vv"):
        np.testing.assert_array_equal(getattr(e, name), getattr(f, name), err_msg=name)
    with pytest.raises(ValueError, match="E_d"):
        DiskGroundPinion(pin, 17, p_n, 0.5 * p_n, 1.0, 0.0)
    with pytest.raises(ValueError, match="a_pd"):
        DiskGroundPinion(pin, 17, p_n, 0.5 * p_n, 6.0, -1.0)


@pytest.mark.numerics
def test_disk_ground_pinion_analytic_derivatives():
    """The disk-ground pinion's analytic derivatives (the spline's cubic pieces carried by the
    screw motion and the plunge) against scipy's derivatives of the same spline and against the
    finite differences of its position that the surface used before; one point on floats gives
    the array values."""
    from gearrep.surfaces.novikov import DiskGroundPinion

    an, Pn, beta = 25 * DEG, 5.0, -np.arccos(0.94)
    pin = RackGeneratedFlank(0.425, an, np.cos(an) / Pn, beta, pitch_radius(17, Pn, beta), -1)
    p_n = np.pi / Pn
    disk = DiskGroundPinion(pin, 17, p_n, 0.5 * p_n, 6.0, 0.001)
    # u over the working part of the grinding line (towards u = -0.24 its derivatives grow
    # a hundredfold, and below it the line's solve is on another branch), three of them on knots
    rng = np.random.default_rng(5)
    u, psi = rng.uniform(-0.15, 0.4, 40), rng.uniform(-0.6, 0.6, 40)
    u[:3] = disk._line.x[[600, 900, 1700]]
    for k, L in enumerate(disk._line_derivs(u)):  # the same cubic pieces: rounding only
        assert_rounding_close(np.stack(L, axis=-1), disk._line(u, k))
    a, f = disk.evaluate(u, psi), disk.fd_evaluate(u, psi)
    # along u the surface is the line turned by Rz(phi_s) Rz(-psi): r_u, r_uu from scipy's L', L''
    turn = np.einsum("ab,nbc->nac", frames.rot_z(disk.phi_s), frames.rot_z(-psi))
    for name, k in (("r_u", 1), ("r_uu", 2)):
        assert_rounding_close(getattr(a, name), np.einsum("nab,nb->na", turn, disk._line(u, k)), err_msg=name)
    np.testing.assert_allclose(a.r, f.r, rtol=0, atol=1e-14)
    # the psi-derivatives against fourth-order differences with h = 1e-4 (smooth in psi): rounding
    # eps |r| / h ~ 1e-11 in the first derivatives, eps |r| / h^2 ~ 1e-7 in the second, relative
    # to each vector's largest entry (along u the differences straddle the spline's knots, where its
    # third derivative jumps: r_uu is checked above instead)
    for name, rtol in (("r_u", 1e-9), ("r_v", 1e-9), ("r_uv", 1e-6), ("r_vv", 1e-6)):
        x, y = getattr(a, name), getattr(f, name)
        assert np.abs(x - y).max() <= rtol * np.abs(y).max(), name
    for i in range(3):
        one = disk.evaluate_components(float(u[i]), float(psi[i]))
        assert all(type(c) is float for vec in one for c in vec)
        for vec, name in zip(one, ("r", "r_u", "r_v", "r_uu", "r_uv", "r_vv")):
            assert_rounding_close(np.array(vec), getattr(a, name)[i])


@pytest.mark.parametrize("rho, l", [(0.2, 0.2), (0.23, 0.18), (-0.258, -0.23)])
def test_circular_arc_flank_matches_envelope(rho, l):
    """Circular-arc racks (seed 002 sec. 6.2): the closed-form rolling angle solves the meshing
    equation, the closed-form point is the envelope solve's, and the analytic second derivatives
    match finite differences (arc centred on the pitch line included)."""
    beta = np.arccos(0.94)
    f = RackGeneratedFlank(1 / (2 * rho), 27 * DEG, l, beta, pitch_radius(17, 5.0, beta), -1, profile="circular_arc")
    u = np.array([-0.08, 0.0, 0.05, 0.1])
    th = np.array([0.5, -1.0, 2.0, 0.0])
    phi = f.rolling_angle(u, th)[0]
    assert np.max(np.abs(f.envelope.meshing(np.column_stack([u, th, phi])))) < 1e-13
    rec = f.solve(u, th)
    assert np.all(rec.converged)
    e = f.evaluate(u, th)
    np.testing.assert_allclose(e.r, rec.point, atol=1e-12)
    fd = fd_derivatives(f.position, u, th, 1e-4, 1e-3)
    for a, b in ((e.r_u, fd.r_u), (e.r_uu, fd.r_uu), (e.r_uv, fd.r_uv), (e.r_vv, fd.r_vv)):
        np.testing.assert_allclose(a, b, atol=1e-6)
    assert f.profile_angle(0.1) == pytest.approx(0.1 / rho)


def test_circular_arc_flank_bad_input():
    with pytest.raises(ValueError, match="profile"):
        RackGeneratedFlank(0.4, 25 * DEG, 0.18, 0.3, 2.0, -1, profile="ellipse")
    with pytest.raises(ValueError, match="a must be finite and nonzero"):
        RackGeneratedFlank(0.0, 25 * DEG, 0.18, 0.3, 2.0, -1, profile="circular_arc")


def test_addendum_limit():
    """addendum_limit: Litvin's line for a straight and a parabolic rack (the undercut_limit value),
    the pitch line for an arc centred on it (zero pressure angle), the arc's lowest point for a
    convex tip arc; bad input names the argument."""
    from gearrep.surfaces.novikov import addendum_limit, undercut_limit

    f, Pn, alpha_t = _straight_rack_member()
    u, x_b, kind = addendum_limit(f, -3.0 / Pn)
    assert kind == "singular" and x_b == pytest.approx(-f.r_p * np.sin(alpha_t) ** 2, rel=1e-9)
    beta = np.arccos(0.94)
    rp = pitch_radius(17, 5.0, beta)
    par = RackGeneratedFlank(5.0 / (2 * 5.88), 25 * DEG, np.cos(25 * DEG) / 5.0, beta, rp, -1)
    assert addendum_limit(par, -0.6)[1] == pytest.approx(undercut_limit(par, -0.2)[1], abs=1e-12)
    arc = RackGeneratedFlank(1 / 0.4, 27 * DEG, 0.2, beta, rp, -1, profile="circular_arc")
    u, x_b, kind = addendum_limit(arc, -np.pi * 0.2)
    assert kind == "zero_pressure_angle" and abs(x_b) < 1e-14
    assert u == pytest.approx(-0.2 * 27 * DEG, abs=1e-12)  # the tangent turns by alpha_n from Q
    tip = RackGeneratedFlank(-1 / 0.516, 27 * DEG, -0.23, beta, rp, -1, profile="circular_arc")
    u, x_b, kind = addendum_limit(tip, -np.pi * 0.258)
    assert kind == "profile_end" and x_b == pytest.approx(tip.rack.centre[0] - 0.258, abs=1e-12)
    assert np.isnan(addendum_limit(tip, -0.05)[0])  # nothing before u_end
    with pytest.raises(ValueError, match="u_end"):
        addendum_limit(tip, 0.0)
    with pytest.raises(ValueError, match="n"):
        addendum_limit(tip, -0.3, n=3)


def test_pointing_limit_with_q_below_the_pitch_line():
    """A straight profile offset to the other side of P (l < 0) is the same rack shifted along the
    pitch line: the pointing height (measured from where the profile crosses the line) is equal,
    also when the crossing is far from Q (P_n = 1)."""
    from gearrep.surfaces.novikov import pointing_limit

    an, Pn, beta = 25 * DEG, 1.0, 0.35
    rp = pitch_radius(17, Pn, beta)
    p_n = np.pi / Pn
    res = [
        pointing_limit(RackGeneratedFlank(0.0, an, l, beta, rp, -1), p_n, 0.5 * p_n, 0.3 / Pn, 3.0 / Pn)
        for l in (np.cos(an) / Pn, -np.cos(an) / Pn)
    ]
    assert res[1][1] == pytest.approx(res[0][1], abs=1e-10) and res[1][2] == pytest.approx(res[0][2], abs=1e-10)


def test_member_flank_and_aligned_start_refuse_bad_input_naming_the_argument():
    from gearrep.surfaces.novikov import aligned_start, member_flank
    from gearrep.tca import GearPair, solve_contact

    an, Pn, beta = 25 * DEG, 5.0, 15 * DEG
    l = np.cos(an) / Pn
    with pytest.raises(ValueError, match="member"):
        member_flank(20, Pn, 0.4, an, l, beta, "wheel")
    with pytest.raises(ValueError, match="N \\(tooth number\\)"):
        member_flank(0, Pn, 0.4, an, l, beta, "pinion")
    with pytest.raises(ValueError, match="beta_rack"):
        member_flank(20, Pn, 0.4, an, l, beta, "pinion", beta_rack=2.0)
    f1 = member_flank(20, Pn, 0.42, an, l, -beta, "pinion")
    f2 = member_flank(40, Pn, 0.39, an, l, -beta, "gear")
    pair = GearPair(f1, f2, 20, 40, f1.r_p + f2.r_p, phase2=0.0)
    with pytest.raises(ValueError, match="pair must"):
        aligned_start(object(), 0.0)
    with pytest.raises(ValueError, match="phi1"):
        aligned_start(pair, np.nan)
    phi = np.array([-0.05, 0.0, 0.05])
    c = solve_contact(pair, phi, aligned_start(pair, phi), formulation="conventional", tol=1e-12, maxiter=30)
    assert c.converged.all()
