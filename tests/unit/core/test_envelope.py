"""gearrep.envelope: one- and two-parameter envelopes against closed forms, singular points."""

import numpy as np
import pytest
from _envelope_cases import (
    HOB,
    TORUS,
    Cylinder,
    Plane,
    ellipsoid_motion,
    hob_case,
    principal_wrt,
    torus_motion,
)
from _numerics import assert_rounding_close

from gearrep.envelope import (
    ChainMotion,
    Envelope,
    FunctionMotion,
    fixed,
    rack_generation_motion,
    rotation,
    singular_points,
    translation,
)
from gearrep.solve import Status, newton
from gearrep.surface import fd_derivatives
from gearrep.surfaces.rack import StraightRackCutter
from gearrep.units import DEG


def inv(a):
    return np.tan(a) - a


def involute_case(N=20, mn=3.0, alpha_n=20 * DEG, beta=15 * DEG, y0=0.3, side=1):
    r_p = mn * N / (2 * np.cos(beta))
    rack = StraightRackCutter(alpha_n, beta, y0=y0, side=side)
    env = Envelope(rack, rack_generation_motion(r_p), free=("u", "v"))
    alpha_t = np.arctan(np.tan(alpha_n) / np.cos(beta))
    return env, r_p, alpha_t, r_p * np.cos(alpha_t)


# ---- motions -------------------------------------------------------------------------------
def test_chain_motion_derivatives_match_finite_differences():
    mot = ChainMotion(
        [
            rotation((0, 0, 1), [0.05, 0.0]),
            rotation((1, 0.2, 0), [0.0, 1.0], point=(60, 110, 0)),
            translation((1, 0, 0), [0.0, 3.0], offset=60),
            fixed(np.diag([1.0, -1.0, -1.0, 1.0])),
            rotation((0, 0, 1), [1.0, 0.7]),
        ],
        names=("theta", "psi"),
    )
    m = np.array([[0.3, -0.1], [2.0, 0.05]])
    M, dM, d2M = mot.matrices(m)
    fd = FunctionMotion(lambda x: mot.matrices(x)[0], 2, ("theta", "psi"), fd_step=1e-3)
    _, dMf, d2Mf = fd.matrices(m)
    np.testing.assert_allclose(dM, dMf, atol=1e-9)
    np.testing.assert_allclose(d2M, d2Mf, atol=1e-7)
    R = M[..., :3, :3]
    np.testing.assert_allclose(R @ np.swapaxes(R, -1, -2), np.broadcast_to(np.eye(3), R.shape), atol=1e-14)
    assert M.shape == (2, 4, 4) and dM.shape == (2, 2, 4, 4) and d2M.shape == (2, 2, 2, 4, 4)


def _first_factor(kind):
    """A chain's first factor of each kind of step: a constant, one moving with both parameters,
    one moving with one."""
    return {
        "constant": rotation((1, 0, 0), [0.0, 0.0], offset=0.4),
        "both": rotation((0, 1, 0), [0.5, -0.3]),
        "one": translation((0, 0, 2.0), [0.0, 1.0]),
    }[kind]


@pytest.mark.parametrize("first", ["constant", "both", "one"])
def test_chain_motion_steps(first):
    """Every kind of step of ChainMotion.matrices (a factor with all-zero coefficients is a constant,
    one moving with a single parameter adds only its row and column, one moving with both the full
    product rule), first in the chain or after others: the derivatives match finite differences,
    and a constant factor gives the same matrices, bit for bit, as the fixed factor of its matrix."""
    head = _first_factor(first)
    rest = [
        rotation((0, 0, 1), [0.05, 0.0]),
        translation((1, 0, 0), [0.0, 0.0], offset=60),
        rotation((1, 0.2, 0), [0.0, 1.0], point=(60, 110, 0)),
        rotation((0, 1, 1), [0.0, 0.0], offset=-0.7, point=(1.0, 2.0, 3.0)),
        rotation((0, 0, 1), [1.0, 0.7]),
    ]
    mot = ChainMotion([head, *rest], names=("theta", "psi"))
    m = np.array([[0.3, -0.1], [2.0, 0.05], [-1.0, 0.4]])
    M, dM, d2M = mot.matrices(m)
    fd = FunctionMotion(lambda x: mot.matrices(x)[0], 2, ("theta", "psi"), fd_step=1e-3)
    _, dMf, d2Mf = fd.matrices(m)
    np.testing.assert_allclose(dM, dMf, atol=1e-8)
    np.testing.assert_allclose(d2M, d2Mf, atol=1e-6)
    const = [f for f in [head, *rest] if not f.coeffs.any()]
    as_fixed = [fixed(f.evaluate(np.array([f.offset]))[0][0]) if not f.coeffs.any() else f for f in [head, *rest]]
    assert len(const) >= 2
    for a, b in zip(mot.matrices(m), ChainMotion(as_fixed, names=("theta", "psi")).matrices(m)):
        np.testing.assert_array_equal(a, b)
    for i in range(len(m)):  # one point alone: the same matrices
        for a, b in zip(mot.matrices(m[i]), (M[i], dM[i], d2M[i])):
            np.testing.assert_array_equal(a, b)


@pytest.mark.numerics
@pytest.mark.parametrize("first", ["constant", "both", "one"])
def test_chain_motion_twists_are_the_matrices_derivatives(first):
    """ChainMotion.twists (the factors' twists carried into the tool frame, gearrep.motion's module
    doc) against the same quantities from its matrices (Motion.twists: M^-1 dM and M^-1 d2M applied to
    points): every kind of step, a fixed first factor, one and two parameters; the two routes round
    differently (a few ulps of the largest entry)."""
    from gearrep.motion import Motion

    head = _first_factor(first)
    rest = [
        fixed(np.diag([1.0, -1.0, -1.0, 1.0])),
        rotation((0, 0, 1), [0.05, 0.0]),
        translation((1, 0, 0), [0.0, 0.0], offset=60),
        rotation((1, 0.2, 0), [0.0, 1.0], point=(60, 110, 0)),
        rotation((0, 0, 1), [1.0, 0.7]),
    ]
    rng = np.random.default_rng(8)
    for mot in (ChainMotion([head, *rest], names=("theta", "psi")), rack_generation_motion(30.0, 1), hob_case()[1]):
        m = rng.uniform(-1.0, 1.0, (6, mot.n_params))
        r = rng.uniform(-50.0, 50.0, (6, 3))
        a, b = mot.twists(m), Motion.twists(mot, m)
        for x, y in ((a.M, b.M), (a.omega, b.omega), (a.v, b.v), (a.second(r), b.second(r))):
            assert x.shape == y.shape
            assert_rounding_close(x, y)
    fixed_only = ChainMotion([fixed(np.eye(4)), translation((1, 0, 0), [0.0], offset=2.0)])
    t = fixed_only.twists(np.zeros((2, 1)))
    assert np.all(t.omega == 0) and np.all(t.v == 0) and np.all(t.second(np.ones((2, 3))) == 0)
    assert t.M[0, 0, 3] == 2.0


@pytest.mark.parametrize("member_side", [-1, 1])
def test_rack_meshing_equals_seed002_eq_2_3_6(member_side):
    """n . v^(1c) = +-[(r_p phi - y_c) N_x + x_c N_y] / |N| (seed 002 eq 2.2.9 / 2.3.6)."""
    r_p = 7.0
    rack = StraightRackCutter(25 * DEG, 19.948 * DEG, y0=0.1)
    env = Envelope(rack, rack_generation_motion(r_p, member_side))
    rng = np.random.default_rng(1)
    q = rng.uniform(-1, 1, (20, 3))
    p = rack.evaluate(q[:, 0], q[:, 1])
    N = np.cross(p.r_u, p.r_v)
    f = ((r_p * q[:, 2] - p.r[:, 1]) * N[:, 0] + p.r[:, 0] * N[:, 1]) / np.linalg.norm(N, axis=1)
    np.testing.assert_allclose(env.meshing(q)[:, 0], -member_side * f, atol=1e-14)
    # the pitch point of the rack (x_c = 0, y_c = r_p phi) is carried to (member_side * -r_p, 0)
    M, _, _ = rack_generation_motion(r_p, member_side).matrices(np.array([0.4]))
    P = M @ np.array([0.0, r_p * 0.4, 0.0, 1.0])
    np.testing.assert_allclose(np.hypot(P[0], P[1]), r_p, rtol=1e-15)


# ---- one-parameter: involute helicoid ---------------------------------------------------------
@pytest.mark.parametrize("beta, side", [(0.0, 1), (15 * DEG, 1), (-25 * DEG, -1)])
def test_straight_rack_generates_involute_helicoid(beta, side):
    env, r_p, alpha_t, r_b = involute_case(beta=beta, side=side)
    u, th = np.meshgrid(np.linspace(-3.0, 3.0, 7), np.linspace(-20, 20, 5))
    rec = env.solve(u, th, guess=0.0)
    assert np.all(rec.converged) and np.all(rec.residual < 1e-12)
    assert np.all(rec.iterations <= 2)  # the meshing equation is affine in phi: one Newton step
    X = rec.point
    rho, Th, Z = np.hypot(X[:, 0], X[:, 1]), np.arctan2(X[:, 1], X[:, 0]), X[:, 2]
    # closed form: polar angle = (y0/cos(beta) + Z tan(beta)) / r_p + side (inv(a_rho) - inv(a_t))
    # (the profile's pitch point touches the pitch circle when r_p phi = y_c(pitch) at that Z)
    a_rho = np.arccos(r_b / rho)
    Th_c = (0.3 / np.cos(beta) + Z * np.tan(beta)) / r_p + side * (inv(a_rho) - inv(alpha_t))
    assert np.max(np.abs(rho * (Th - Th_c))) < 1e-10  # mm
    # the generated point carries the tool normal; it is normal to the involute helicoid
    tang = rec.tangents
    np.testing.assert_allclose(np.einsum("na,nfa->nf", rec.normal, tang), 0.0, atol=1e-12)
    # sanity on the closed form itself: the other flank's formula is far off
    assert np.max(np.abs(rho * (Th - Th_c + 2 * side * (inv(a_rho) - inv(alpha_t))))) > 1e-3


def test_generated_surface_curvatures_closed_form():
    """Involute helicoid: principal curvatures 0 (generatrix) and cos(beta_b)/sqrt(r^2 - r_b^2)
    in the transverse direction (transverse involute curvature 1/rho_t with Meusnier's factor
    cos(beta_b), the angle between the surface normal and the transverse plane)."""
    beta = 15 * DEG
    env, r_p, alpha_t, r_b = involute_case(beta=beta)
    beta_b = np.arctan(np.tan(beta) * np.cos(alpha_t))
    surf = env.surface(guess=0.0)
    u, th = np.meshgrid(np.linspace(-2.5, 3.0, 6), np.linspace(-10, 10, 3))
    p = surf.evaluate(u, th)
    rec = surf.solve(u, th)
    np.testing.assert_allclose(p.r.reshape(-1, 3), rec.point, atol=1e-12)
    rho = np.hypot(rec.point[:, 0], rec.point[:, 1])
    k_closed = np.cos(beta_b) / np.sqrt(rho**2 - r_b**2)
    k1, k2 = principal_wrt(p, rec.normal.reshape(p.r.shape))
    k1, k2 = k1.reshape(-1), k2.reshape(-1)
    # the tool normal points away from the involute's centre of curvature (convex): k = -1/rho
    np.testing.assert_allclose(k2, -k_closed, rtol=1e-8)
    np.testing.assert_allclose(k1, 0.0, atol=1e-8 * k_closed.max())


def test_envelope_surface_derivatives_match_finite_differences():
    env, *_ = involute_case(beta=20 * DEG)
    surf = env.surface(guess=0.0, fd_step=(1e-3, 1e-3))
    u, th = np.linspace(-2, 2, 5), np.linspace(-5, 5, 5)
    p = surf.evaluate(u, th)
    q = fd_derivatives(surf.position, u, th, 1e-2, 1e-2)
    for name, tol in (("r", 1e-13), ("r_u", 1e-9), ("r_v", 1e-9), ("r_uu", 1e-7), ("r_uv", 1e-7), ("r_vv", 1e-7)):
        np.testing.assert_allclose(getattr(p, name), getattr(q, name), atol=tol, err_msg=name)


# ---- singular points (undercutting) ----------------------------------------------------------
@pytest.mark.parametrize("beta", [0.0, 20 * DEG])
def test_undercut_limit_of_small_pinion(beta):
    """10-tooth, 20 deg, m = 1: the rack's limiting line is at x_c = -r_p sin^2(alpha_t) (the
    line of action meets the base circle), and the singular point lies on the base circle."""
    env, r_p, alpha_t, r_b = involute_case(N=10, mn=1.0, alpha_n=20 * DEG, beta=beta, y0=0.0)
    th = np.array([0.0, 1.5, -3.0])
    # phi of the contact shifts by theta sin(beta) / r_p along a helical rack tooth
    sp = singular_points(env, "v", th, guess=np.c_[np.full(3, -0.6), -0.4 + th * np.sin(beta) / r_p])
    assert np.all(sp.converged)
    x_c = sp.param("u") * np.cos(20 * DEG)
    np.testing.assert_allclose(x_c, -r_p * np.sin(alpha_t) ** 2, rtol=1e-10)
    np.testing.assert_allclose(np.hypot(sp.point[:, 0], sp.point[:, 1]), r_b, rtol=1e-10)
    assert np.all(sp.singular)
    # the limit is undercut for a 1-module addendum: r_p sin^2 alpha_t < m
    assert r_p * np.sin(alpha_t) ** 2 < 1.0
    # along a profile, Litvin's determinant changes sign exactly at the limit; the generated
    # surface's tangent vectors there become parallel
    u_lim = sp.param("u")[0]
    rec = env.solve(u_lim + np.array([-0.2, -1e-3, 1e-3, 0.2]), 0.0, guess=0.0)
    d = rec.litvin_det
    assert d[0] * d[3] < 0 and d[1] * d[2] < 0 and d[0] * d[1] > 0
    assert rec.singular_measure[1] < 1e-2 * rec.singular_measure[3]
    area = np.linalg.norm(np.cross(rec.tangents[:, 0], rec.tangents[:, 1]), axis=-1)  # |r_u x r_theta|
    assert area[1] < 1e-2 * area[3] and area[2] < 1e-2 * area[0]
    # on both sides of the limit the generated points lie outside the base circle: rack points
    # deeper than the limit generate the second branch of the involute beyond its cusp (undercut)
    r = np.hypot(rec.point[:, 0], rec.point[:, 1])
    assert np.all(r > r_b) and r[0] > r[1] and r[3] > r[2]


# ---- two-parameter envelopes --------------------------------------------------------------------
def test_two_parameter_torus_from_cylinder():
    R0, r0, rho = TORUS["R0"], TORUS["r0"], TORUS["rho"]
    env = Envelope(Cylinder(rho), torus_motion(**TORUS), free=("theta", "psi"))
    th, ps = np.meshgrid(np.linspace(-0.5, 2.5, 4), np.linspace(-1.2, 1.2, 5))
    rec = env.solve(th, ps, guess=[0.1, 0.2])
    assert np.all(rec.converged)
    X = rec.point
    rc = np.hypot(X[:, 0], X[:, 1]) - R0
    np.testing.assert_allclose(np.hypot(rc, X[:, 2]), r0 + rho, rtol=1e-14)
    # position: p(theta, psi) + rho n, with the tool contact point fixed at (u, v) = (0, 0)
    t, p = rec.param("theta"), rec.param("psi")
    Xc = np.stack(
        [(R0 + (r0 + rho) * np.cos(p)) * np.cos(t), (R0 + (r0 + rho) * np.cos(p)) * np.sin(t), (r0 + rho) * np.sin(p)],
        -1,
    )
    np.testing.assert_allclose(X, Xc, atol=1e-12)
    np.testing.assert_allclose(rec.params[:, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(
        rec.normal, (Xc - np.stack([R0 * np.cos(t), R0 * np.sin(t), 0 * t], -1)) / (r0 + rho), atol=1e-13
    )
    # generated surface curvatures by direct differential geometry vs closed form
    surf = env.surface([0.1, 0.2])
    sp = surf.evaluate(t, p)
    k1, k2 = principal_wrt(sp, rec.normal)
    kmer = -1.0 / (r0 + rho)
    kpar = -np.cos(p) / (R0 + (r0 + rho) * np.cos(p))
    np.testing.assert_allclose(k1, np.maximum(kmer, kpar), rtol=1e-10)
    np.testing.assert_allclose(k2, np.minimum(kmer, kpar), rtol=1e-10)


@pytest.mark.parametrize(
    "free, grid",
    [
        (("theta", "psi"), (np.linspace(-2, 2, 4), np.linspace(0.3, 1.2, 3))),
        (("v", "psi"), (np.linspace(-0.4, 0.4, 3), np.linspace(0.3, 1.2, 3))),
    ],
)
def test_two_parameter_ellipsoid_from_plane(free, grid):
    axes = np.array([3.0, 2.0, 1.2])
    env = Envelope(Plane(), ellipsoid_motion(axes), free=free)
    a, b = np.meshgrid(*grid)
    rec = env.solve(a, b, guess=[0.0, 0.0])
    assert np.all(rec.converged)
    X = rec.point
    np.testing.assert_allclose(np.sum(X**2 / axes**2, -1), 1.0, atol=1e-13)
    np.testing.assert_allclose(np.cross(rec.normal, X / axes**2), 0.0, atol=1e-11)  # normal = grad


def test_two_parameter_hob_parameterised_by_l_psi():
    """Seed 000 set-up: with free (l, psi) the solve for (phi, theta) is regular across the
    mid-face psi = 0, where the Jacobian of the meshing equations in (theta, psi) is singular."""
    tool, motion = hob_case()
    env = Envelope(tool, motion, free=("u", "psi"))
    l, ps = np.meshgrid(np.linspace(4.4, 10.3, 4), np.array([-0.1, 0.0, 0.1]))
    rec = env.solve(l, ps, guess=[np.pi, 0.0])
    assert np.all(rec.converged) and not np.any(rec.singular)
    J = env.meshing_jacobian(rec.params)
    s_tp = np.linalg.svd(J[:, :, 2:], compute_uv=False)
    s_pt = np.linalg.svd(J[:, :, 1:3], compute_uv=False)
    mid = rec.param("psi") == 0.0
    assert np.all(s_tp[mid, 1] < 1e-12 * s_tp[mid, 0])  # (theta, psi): singular at mid-face
    assert np.all(s_pt[:, 1] > 1e-3 * s_pt[:, 0])  # (phi, theta): regular
    # the working profile lies about the 20-tooth gear's pitch circle (r = 30 mm, tip 33)
    r = np.hypot(rec.point[:, 0], rec.point[:, 1])
    assert np.all((r > 27.5) & (r < 33.5))
    assert HOB["N"] == 20


def test_status_is_reported_not_hidden():
    # (u, psi) cannot parameterise the plane/ellipsoid family: f_psi does not depend on (v, theta)
    env = Envelope(Plane(), ellipsoid_motion(), free=("u", "psi"))
    rec = env.solve(np.array([0.2, 0.3]), np.array([0.5, 0.6]), guess=[0.0, 0.0])
    assert not np.any(rec.converged)
    # bounds on the solved parameter give OFF_FLANK
    env1, *_ = involute_case()
    rec = Envelope(env1.tool, env1.motion, lower=[-0.01], upper=[0.01]).solve([0.0, 3.0], 0.0, guess=0.0)
    assert rec.status[0] == Status.CONVERGED and rec.status[1] == Status.OFF_FLANK

    # a tool that returns NaN (a point off its domain): DIVERGED, not an exception
    class Bad(Plane):
        def evaluate(self, u, v):
            p = super().evaluate(u, v)
            return type(p)(p.r * np.nan, p.r_u, p.r_v, p.r_uu, p.r_uv, p.r_vv)

    rec = Envelope(Bad(), ellipsoid_motion(), free=("theta", "psi")).solve(0.1, 0.5, guess=[0.0, 0.0])
    assert rec.status[0] == Status.DIVERGED and not rec.singular[0]
    # EnvelopeSurface.position gives NaN for failed solves
    surf = env.surface([0.0, 0.0])
    assert np.all(np.isnan(surf.position(0.2, 0.5)))


def test_newton_rows_and_initial_root():
    """Support added to gearrep.solve.newton for this module: rows=True passes the batch indices
    of the active rows; a starting point that is already a root counts as converged."""
    c = np.array([1.0, 2.0, 3.0])
    seen = []

    def fun(x, idx):
        seen.append(idx.copy())
        return x**2 - c[idx, None]

    r = newton(fun, np.array([[1.0], [1.0], [1.0]]), rows=True)
    assert np.all(r.converged) and r.iterations[0] == 0
    np.testing.assert_allclose(r.x[:, 0], np.sqrt(c), rtol=1e-14)
    assert any(len(s) < 3 for s in seen)


def test_validation():
    env, *_ = involute_case()
    with pytest.raises(ValueError, match="free"):
        Envelope(env.tool, env.motion, free=("u", "u"))
    with pytest.raises(ValueError, match="free"):
        Envelope(env.tool, env.motion, free=("u", "psi"))
    with pytest.raises(ValueError, match="tool"):
        Envelope(object(), env.motion)
    with pytest.raises(ValueError, match="r_p"):
        rack_generation_motion(-1.0)
    with pytest.raises(ValueError, match="member_side"):
        rack_generation_motion(1.0, member_side=0)
    with pytest.raises(ValueError, match="guess"):
        env.solve(0.0, 0.0)
    with pytest.raises(ValueError, match="q must"):
        env.meshing(np.zeros((3, 4)))
    with pytest.raises(ValueError, match="coeffs"):
        ChainMotion([rotation((0, 0, 1), [1.0, 2.0])], names=("phi",))
    with pytest.raises(ValueError, match="axis"):
        rotation((0, 0, 0))
    with pytest.raises(ValueError, match="n_params"):
        FunctionMotion(lambda m: None, 3)
    with pytest.raises(ValueError, match="finite"):
        env.solve(np.nan, 0.0, guess=0.0)
    with pytest.raises(ValueError, match="guess"):
        env.solve(0.0, 0.0, guess=[0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="guess"):
        singular_points(env, "v", [0.0, 1.0], guess=[1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="fixed_name"):
        singular_points(env, "psi", [0.0], guess=[1.0, 2.0])
    with pytest.raises(ValueError, match="lower"):
        Envelope(env.tool, env.motion, lower=[0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="m must"):
        torus_motion(**TORUS).matrices(np.zeros((2, 3)))


def test_local_geometry_passes_nonfinite_rows_through():
    from gearrep.envelope import local_geometry

    env, _, _, _ = involute_case()
    q = np.array([[0.5, 0.1, 0.2], [np.nan, 0.1, 0.2]])
    loc = local_geometry(env.tool, env.motion, q)
    np.testing.assert_array_equal(loc.f[0], env.local(q[:1]).f[0])
    assert not np.all(np.isfinite(loc.f[1]))
    with pytest.raises(ValueError, match="finite"):
        env.local(q)


def test_recent_local_geometries_are_reused_read_only():
    """The local geometry of one of the last few small batches is returned again for the same tool,
    motion and q (values equal to a fresh evaluation, arrays read-only); another q, tool or motion,
    or a q changed in place after the call, is evaluated anew."""
    import gearrep.envelope as E

    r_p = 7.0
    rack = StraightRackCutter(25 * DEG, 19.948 * DEG, y0=0.1)
    mot = rack_generation_motion(r_p, -1)
    q = np.random.default_rng(3).uniform(-1, 1, (5, 3))
    a = E.local_geometry(rack, mot, q)
    fresh = E._local_geometry(rack, mot, q.copy())
    assert E.local_geometry(rack, mot, q.copy()) is a
    for f in ("M", "N", "n", "w", "f", "J", "T", "H"):
        np.testing.assert_array_equal(getattr(a, f), getattr(fresh, f))
        assert not getattr(a, f).flags.writeable
    assert not a.tool.r.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        a.f[0] = 0.0
    q[0, 0] += 1e-9  # changed in place: a new key
    assert E.local_geometry(rack, mot, q) is not a
    assert E.local_geometry(rack, rack_generation_motion(r_p, -1), q.copy()) is not E.local_geometry(rack, mot, q)


@pytest.mark.numerics
def test_a_batch_of_recent_rows_is_gathered_from_them():
    """A batch whose rows the last evaluations hold (bit for bit) in part is assembled from their
    rows and evaluated only at the others: the same values as a fresh evaluation (gathered rows
    exactly their sources', the rest within rounding of the batch they are evaluated in); a gathered
    batch is found again whole, but its rows are not offered to later batches; the member-frame
    quantities of a local geometry are its tool-frame ones turned by M."""
    import gearrep.envelope as E

    tool, mot = hob_case()[:2]
    rng = np.random.default_rng(12)
    q1, q2, q3 = (
        np.column_stack([rng.uniform(3, 6, 7), rng.uniform(-1, 1, 7), rng.uniform(2, 4, 7), rng.uniform(-0.1, 0.1, 7)])
        for _ in range(3)
    )
    E._RECENT.clear()
    a, b = E.local_geometry(tool, mot, q1), E.local_geometry(tool, mot, q2)
    mixed = np.concatenate([q2[:3], q1[4:], q3[:2]])  # rows of both, and two new ones
    got = E.local_geometry(tool, mot, mixed)
    fresh = E._local_geometry(tool, mot, mixed)
    for f in ("M", "N", "n", "w", "omega", "Xr", "f", "J", "T", "H", "n_q"):
        x, y = getattr(got, f), getattr(fresh, f)
        np.testing.assert_array_equal(x[:3], getattr(b, f)[:3])
        np.testing.assert_array_equal(x[3:6], getattr(a, f)[4:])
        assert_rounding_close(x, y, err_msg=f)
        assert not x.flags.writeable
    np.testing.assert_array_equal(got.tool.r[:3], b.tool.r[:3])
    assert E.local_geometry(tool, mot, mixed.copy()) is got
    assert E._RECENT[0][5] is E._GATHERED
    R = got.M[:, :3, :3]
    r, T, n, dn = got.in_member_frame
    assert_rounding_close(r, np.einsum("nab,nb->na", R, got.tool.r) + got.M[:, :3, 3])
    assert_rounding_close(T, np.einsum("nab,nqb->nqa", R, got.T))
    assert_rounding_close(n, np.einsum("nab,nb->na", R, got.n))
    assert_rounding_close(dn, np.einsum("nab,nqb->nqa", R, got.n_q))
    assert not r.flags.writeable


def test_newton_does_not_write_to_the_callers_arrays():
    """newton keeps its own copies of the residuals: a fun_jac that returns read-only arrays (as the
    reused local geometries are) is solved, damped and not, with the same result as writeable ones."""

    def fun_jac(x, frozen):
        F = np.column_stack([x[:, 0] ** 3 - 2.0, x[:, 1] - 0.5 * x[:, 0]])
        J = np.zeros((len(x), 2, 2))
        J[:, 0, 0], J[:, 1, 0], J[:, 1, 1] = 3 * x[:, 0] ** 2, -0.5, 1.0
        if frozen:
            F.flags.writeable = J.flags.writeable = False
        return F, J

    x0 = np.array([[3.0, 0.0], [0.2, 1.0], [-4.0, 2.0]])
    for damped in (True, False):
        a = newton(lambda x: fun_jac(x, True)[0], x0, fun_jac=lambda x: fun_jac(x, True), damped=damped, tol=1e-13)
        b = newton(lambda x: fun_jac(x, False)[0], x0, fun_jac=lambda x: fun_jac(x, False), damped=damped, tol=1e-13)
        np.testing.assert_array_equal(a.x, b.x)
        np.testing.assert_array_equal(a.status, b.status)
        assert (a.status == Status.CONVERGED).any()


def test_meshing_functions_are_the_callers_own_arrays():
    """Envelope.meshing and meshing_jacobian return writeable copies even where the local geometry
    is reused (read-only)."""
    r_p = 7.0
    rack = StraightRackCutter(25 * DEG, 19.948 * DEG, y0=0.1)
    env = Envelope(rack, rack_generation_motion(r_p, -1))
    q = np.random.default_rng(4).uniform(-1, 1, (3, 3))
    for _ in range(2):
        f, J = env.meshing(q), env.meshing_jacobian(q)
        assert f.flags.writeable and J.flags.writeable
        f[:] = 0.0
        J[:] = 0.0
    np.testing.assert_array_equal(env.meshing(q), env.local(q).f)
