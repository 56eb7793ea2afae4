"""gearrep.curvature against closed forms (plane, sphere, cylinder, torus, helicoid, involute
helicoid), with analytic derivatives and with the finite-difference default of gearrep.surface;
the batched 2x2 eigen-solver and the shape matrix.

Accuracy achieved (documented here and asserted below):
* analytic derivatives: principal curvatures to ~1e-15 relative (asserted 1e-12);
* 4th-order finite differences (h = 1e-3 in parameter units, O(1) surfaces): ~1e-9 of the
  largest |k| (asserted 1e-8 * max(|k1|, |k2|) absolute; a zero curvature cannot be met
  "relatively"), directions to ~1e-9 rad. The FD rounding error grows like
  eps |r| / (h |r_u|)^2, so points far from the origin (|r| >> curvature radius, or >> 1 in
  parameter units) lose accuracy: choose the origin near the surface or a larger fd_step.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gearrep import curvature as cv
from gearrep.surface import SurfacePoint, unit
from gearrep.surfaces.analytic import (
    Cylinder,
    Helicoid,
    InvoluteHelicoid,
    Plane,
    Sphere,
    Torus,
    finite_difference_version,
)

TOL = {"analytic": 1e-12, "fd": 1e-8}


def _surf(s, mode):
    return s if mode == "analytic" else finite_difference_version(s)


def _check_against_exact(s, u, v, mode, check_dirs=True):
    p = _surf(s, mode).evaluate(u, v)
    pc = cv.principal_curvatures(p)
    k1, k2, e1, e2 = s.exact_principal(u, v)
    scale = np.maximum(np.maximum(np.abs(k1), np.abs(k2)), 1e-300)
    tol = TOL[mode]
    assert np.all(np.abs(pc.k1 - k1) <= tol * scale)
    assert np.all(np.abs(pc.k2 - k2) <= tol * scale)
    assert np.all(pc.k1 >= pc.k2)
    # orthonormal, right-handed frame (e1, e2, n)
    np.testing.assert_allclose(np.linalg.norm(pc.e1, axis=-1), 1.0, atol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(pc.e2, axis=-1), 1.0, atol=1e-14)
    np.testing.assert_allclose(np.cross(pc.e1, pc.e2), pc.normal, atol=1e-14)
    np.testing.assert_allclose(np.sum(pc.e1 * pc.normal, -1), 0.0, atol=1e-14)
    if check_dirs:  # a direction is a line: compare up to sign
        np.testing.assert_allclose(np.abs(np.sum(pc.e1 * e1, -1)), 1.0, atol=10 * tol)
        np.testing.assert_allclose(np.abs(np.sum(pc.e2 * e2, -1)), 1.0, atol=10 * tol)
    return pc


MODES = ["analytic", "fd"]


@pytest.mark.parametrize("mode", MODES)
def test_plane_zero_and_umbilic_direction(mode):
    s = Plane(origin=(1, 2, 3), a=(1.0, 0.2, 0.0), b=(0.3, 1.0, 0.5))
    u, v = np.linspace(-1, 1, 5), np.linspace(0, 2, 5)
    pc = cv.principal_curvatures(_surf(s, mode).evaluate(u, v))
    # FD rounding: absolute error ~ eps |r| / (h |r_u|)^2 ~ 1e-9 here (|r| ~ 4, h = 1e-3)
    tol = 1e-14 if mode == "analytic" else 1e-8
    assert np.all(np.abs(pc.k1) < tol) and np.all(np.abs(pc.k2) < tol)
    if mode == "analytic":  # exactly umbilic: e1 = unit(r_u)
        np.testing.assert_allclose(pc.e1, np.broadcast_to(unit(s.a), pc.e1.shape), atol=1e-15)


@pytest.mark.parametrize("mode", MODES)
def test_sphere_outward_and_inward(mode):
    R = 2.5
    s = Sphere(R)
    u, v = np.meshgrid(np.linspace(-3, 3, 4), np.linspace(-1.2, 1.2, 3))
    p = _surf(s, mode).evaluate(u, v)
    pc = _check_against_exact(s, u, v, mode, check_dirs=False)
    np.testing.assert_allclose(pc.k1, -1 / R, rtol=TOL[mode])
    # umbilic: e1 = unit(r_u) (contract)
    np.testing.assert_allclose(pc.e1, unit(p.r_u), atol=1e-12)
    # contract example: inward normal gives k = +1/R
    pin = cv.principal_curvatures(p.flipped())
    np.testing.assert_allclose(pin.k1, 1 / R, rtol=TOL[mode])
    np.testing.assert_allclose(pin.k2, 1 / R, rtol=TOL[mode])
    np.testing.assert_allclose(np.sum(pin.normal * p.r, -1), -R, rtol=1e-12)


@pytest.mark.parametrize("mode", MODES)
def test_cylinder(mode):
    s = Cylinder(0.8)
    u, v = np.linspace(-3, 3, 7), np.linspace(-2, 2, 7)
    _check_against_exact(s, u, v, mode)


@pytest.mark.parametrize("mode", MODES)
def test_torus_equators_and_generic(mode):
    c, a = 3.0, 1.0
    s = Torus(c, a)
    u = np.array([0.3, 0.3, 1.1, -2.0, 0.0])
    v = np.array([0.0, np.pi, 0.7, 2.3, -1.0])
    pc = _check_against_exact(s, u, v, mode)
    tol = TOL[mode]
    assert abs(pc.k1[0] - (-1 / (c + a))) <= tol * 1.0  # outer equator, elliptic
    assert abs(pc.k2[0] - (-1 / a)) <= tol
    assert abs(pc.k1[1] - 1 / (c - a)) <= tol  # inner equator, hyperbolic
    assert abs(pc.k2[1] - (-1 / a)) <= tol
    K = cv.gaussian_curvature(_surf(s, mode).evaluate(u, v))
    np.testing.assert_allclose(K, np.cos(v) / (a * (c + a * np.cos(v))), atol=10 * tol)


@pytest.mark.parametrize("mode", MODES)
def test_helicoid_minimal(mode):
    cc = 0.7
    s = Helicoid(cc)
    rho, th = np.meshgrid(np.array([0.0, 0.4, 1.3, 2.5]), np.array([-1.0, 0.4, 2.0]))
    pc = _check_against_exact(s, rho, th, mode)
    np.testing.assert_allclose(pc.k1, cc / (rho**2 + cc**2), rtol=TOL[mode])
    np.testing.assert_allclose(pc.k2, -cc / (rho**2 + cc**2), rtol=TOL[mode])
    H = cv.mean_curvature(_surf(s, mode).evaluate(rho, th))
    assert np.all(np.abs(H) < TOL[mode] * cc / (rho**2 + cc**2))
    # negative screw parameter: same magnitudes, mirrored directions
    _check_against_exact(Helicoid(-cc), rho, th, mode)


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("p_screw", [0.6, -1.7])
def test_involute_helicoid(mode, p_screw):
    rb = 1.3
    s = InvoluteHelicoid(rb, p_screw)
    u = np.array([0.2, 0.8, 1.5, -0.9])
    v = np.array([0.0, 0.3, -1.0, 2.0])
    pc = _check_against_exact(s, u, v, mode)
    knz = p_screw / (rb * np.abs(u))
    kz = np.where(p_screw > 0, pc.k2, pc.k1)
    kk = np.where(p_screw > 0, pc.k1, pc.k2)
    assert np.all(np.abs(kz) <= TOL[mode] * np.abs(knz))
    np.testing.assert_allclose(kk, knz, rtol=TOL[mode])
    # zero curvature along the straight generator r_u
    p = _surf(s, mode).evaluate(u, v)
    ezero = np.where(p_screw > 0, pc.e2.T, pc.e1.T).T
    np.testing.assert_allclose(np.abs(np.sum(ezero * unit(p.r_u), -1)), 1.0, atol=1e-9)
    # gear form: k = cos(beta_b)/rho_t, tan(beta_b) = rb/|p|, rho_t = transverse radius of
    # curvature of the involute = |u| sin(beta_b) (transverse projection of the generator)
    beta_b = np.arctan2(rb, abs(p_screw))
    rho_t = np.abs(u) * np.sin(beta_b)
    np.testing.assert_allclose(np.abs(knz), np.cos(beta_b) / rho_t, rtol=1e-13)


def test_fundamental_forms_sphere():
    R = 1.7
    s = Sphere(R)
    u, v = np.array([0.2, 1.0]), np.array([0.3, -0.6])
    f = cv.fundamental_forms(s.evaluate(u, v))
    np.testing.assert_allclose(f.E, R**2 * np.cos(v) ** 2, rtol=1e-14)
    np.testing.assert_allclose(f.F, 0.0, atol=1e-14)
    np.testing.assert_allclose(f.G, R**2, rtol=1e-14)
    np.testing.assert_allclose(f.L, -R * np.cos(v) ** 2, rtol=1e-14)
    np.testing.assert_allclose(f.M, 0.0, atol=1e-14)
    np.testing.assert_allclose(f.N, -R, rtol=1e-14)


def test_normal_curvature_euler_and_II_over_I():
    s = Torus(3.0, 1.2)
    u, v = np.full(50, 0.4), np.full(50, 0.9)
    p = s.evaluate(u, v)
    pc = cv.principal_curvatures(p)
    rng = np.random.default_rng(1)
    du, dv = rng.normal(size=50), rng.normal(size=50)
    d = du[:, None] * p.r_u + dv[:, None] * p.r_v
    f = cv.fundamental_forms(p)
    ii_i = (f.L * du**2 + 2 * f.M * du * dv + f.N * dv**2) / (f.E * du**2 + 2 * f.F * du * dv + f.G * dv**2)
    kn = cv.normal_curvature(p, d + 0.37 * p.normal)  # normal component ignored
    np.testing.assert_allclose(kn, ii_i, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(cv.euler_normal_curvature(pc, d), ii_i, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(cv.normal_curvature(p, pc.e1), pc.k1, rtol=1e-13)
    np.testing.assert_allclose(cv.normal_curvature(p, pc.e2), pc.k2, rtol=1e-13)
    # extrema of k_n are the principal curvatures
    assert np.all(kn <= pc.k1 + 1e-14) and np.all(kn >= pc.k2 - 1e-14)


def test_gaussian_mean_match_principal_generic_param():
    # non-orthogonal parametrisation: a torus point reparametrised by u' = u + 0.7 v
    s = Torus(2.0, 0.5)

    class Skew(Torus):
        def position(self, u, v):
            return s.position(u - 0.7 * v, v)

    from gearrep.surface import fd_derivatives

    u, v = np.array([0.1, 2.0]), np.array([0.5, 2.5])
    p = fd_derivatives(Skew(2.0, 0.5).position, u, v)
    pc = cv.principal_curvatures(p)
    k1, k2, _, _ = s.exact_principal(u - 0.7 * v, v)
    np.testing.assert_allclose(pc.k1, k1, atol=1e-8 * 2)
    np.testing.assert_allclose(pc.k2, k2, atol=1e-8 * 2)
    np.testing.assert_allclose(cv.gaussian_curvature(p), pc.k1 * pc.k2, rtol=1e-10)
    np.testing.assert_allclose(cv.mean_curvature(p), 0.5 * (pc.k1 + pc.k2), rtol=1e-10)
    np.testing.assert_allclose(pc.gaussian, pc.k1 * pc.k2)


def test_with_opposite_normal_matches_flipped_parametrisation():
    s = Torus(3.0, 1.0)
    u, v = np.array([0.3, 1.0, -0.5]), np.array([0.6, np.pi, 2.0])
    p = s.evaluate(u, v)
    pc = cv.principal_curvatures(p)
    op = cv.with_opposite_normal(pc)
    fl = cv.principal_curvatures(p.flipped())
    np.testing.assert_allclose(op.k1, fl.k1, atol=1e-14)
    np.testing.assert_allclose(op.k2, fl.k2, atol=1e-14)
    np.testing.assert_allclose(op.normal, fl.normal, atol=1e-14)
    np.testing.assert_allclose(np.abs(np.sum(op.e1 * fl.e1, -1)), 1.0, atol=1e-14)
    np.testing.assert_allclose(np.cross(op.e1, op.e2), op.normal, atol=1e-14)
    # involution
    back = cv.with_opposite_normal(op)
    for a, b in zip(back, pc):
        np.testing.assert_array_equal(a, b)


def test_batch_shapes():
    s = Helicoid(1.0)
    u, v = np.meshgrid(np.linspace(0, 1, 5), np.linspace(0, 1, 4))
    pc = cv.principal_curvatures(s.evaluate(u, v))
    assert pc.k1.shape == (4, 5) and pc.e1.shape == (4, 5, 3) and pc.normal.shape == (4, 5, 3)
    pc0 = cv.principal_curvatures(s.evaluate(0.3, 0.2))
    assert pc0.k1.shape == () and pc0.e1.shape == (3,)


# ---------------------------------------------------------------- relative curvature


def _transform_point(p: SurfacePoint, R, t):
    """Rigidly move a surface point (derivatives rotate, the position also translates)."""
    rot = lambda x: x @ R.T  # noqa: E731
    return SurfacePoint(rot(p.r) + t, rot(p.r_u), rot(p.r_v), rot(p.r_uu), rot(p.r_uv), rot(p.r_vv))


def _rx(g):
    c, s = np.cos(g), np.sin(g)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


@pytest.mark.parametrize("gamma", [0.0, 0.3, np.pi / 4, np.pi / 2, 2.0])
def test_relative_crossed_cylinders(gamma):
    R1, R2 = 1.5, 0.6
    c1 = Cylinder(R1)
    p1 = c1.evaluate(0.0, 0.2)  # point (R1, 0, 0.2), outward normal +x
    c2 = Cylinder(R2)
    p2 = _transform_point(c2.evaluate(np.pi, 0.0), _rx(gamma), np.array([R1 + R2, 0.0, 0.2]))
    np.testing.assert_allclose(p2.r, p1.r, atol=1e-14)
    np.testing.assert_allclose(p2.normal, -p1.normal, atol=1e-14)
    pc1 = cv.principal_curvatures(p1)
    pc2 = cv.with_opposite_normal(cv.principal_curvatures(p2))  # common normal +x
    with pytest.raises(ValueError, match="normal"):
        cv.relative_curvature(pc1, cv.principal_curvatures(p2))
    rel = cv.relative_curvature(pc1, pc2)
    # closed form (Hertz crossed cylinders): both relative curvatures negative with n = +x
    s = 1 / R1 + 1 / R2
    root = np.sqrt(1 / R1**2 + 1 / R2**2 + 2 * np.cos(2 * gamma) / (R1 * R2))
    np.testing.assert_allclose(rel.k1, -(s - root) / 2, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(rel.k2, -(s + root) / 2, rtol=1e-12)
    # independent: brute-force extrema of k1_n - k2_n over tangent directions
    th = np.linspace(0, np.pi, 200001)
    t1, t2 = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0])
    d = np.cos(th)[:, None] * t1 + np.sin(th)[:, None] * t2
    kr = cv.normal_curvature(p1, d) - (-cv.normal_curvature(p2, d))
    assert abs(kr.max() - rel.k1) < 1e-9 and abs(kr.min() - rel.k2) < 1e-9
    np.testing.assert_allclose(abs(np.dot(d[np.argmax(kr)], rel.e1)), 1.0, atol=1e-9)
    # directions and frame
    np.testing.assert_allclose(cv.normal_curvature(p1, rel.e1) + cv.normal_curvature(p2, rel.e1), rel.k1, atol=1e-12)
    np.testing.assert_allclose(np.cross(rel.e1, rel.e2), rel.normal, atol=1e-14)
    # sigma is the true angle between e_I(1), e_I(2) (mod pi)
    np.testing.assert_allclose(
        np.cos(2 * rel.sigma), np.cos(2 * cv.signed_angle(pc1.e1, pc2.e1, pc1.normal)), atol=1e-14
    )


def test_relative_two_spheres_isotropic():
    R1, R2 = 2.0, 0.5
    p1 = Sphere(R1).evaluate(0.4, 0.3)
    n = p1.normal
    # sphere 2 outside sphere 1, touching at p1.r: its centre is p1.r + R2 n
    # point of sphere 2 whose outward normal is -n (antipodal parameters), moved to touch p1
    p2 = Sphere(R2).evaluate(0.4 + np.pi, -0.3)
    p2 = _transform_point(p2, np.eye(3), p1.r - p2.r)
    np.testing.assert_allclose(p2.r, p1.r, atol=1e-15)
    np.testing.assert_allclose(p2.normal, -n, atol=1e-14)
    pc1 = cv.principal_curvatures(p1)
    pc2 = cv.with_opposite_normal(cv.principal_curvatures(p2))
    rel = cv.relative_curvature(pc1, pc2)
    # w.r.t. n (outward of sphere 1): kappa1 = -1/R1, kappa2 = +1/R2 (inward for sphere 2)
    np.testing.assert_allclose(rel.k1, -(1 / R1 + 1 / R2), rtol=1e-13)
    np.testing.assert_allclose(rel.k2, -(1 / R1 + 1 / R2), rtol=1e-13)
    assert rel.alpha == 0.0
    np.testing.assert_allclose(rel.e1, pc1.e1, atol=1e-15)


def test_relative_principal_matches_litvin_formulas():
    rng = np.random.default_rng(7)
    kI1, kII1, kI2, kII2 = rng.normal(size=(4, 200)) * 3
    sigma = rng.uniform(-np.pi, np.pi, 200)
    k1, k2, alpha = cv.relative_principal_curvatures(kI1, kII1, kI2, kII2, sigma)
    kS1, kS2, g1, g2 = kI1 + kII1, kI2 + kII2, kI1 - kII1, kI2 - kII2
    Rr = np.sqrt(g1**2 - 2 * g1 * g2 * np.cos(2 * sigma) + g2**2)
    A = 0.25 * (kS1 - kS2 - Rr)  # seed 002 eq 2.6.4
    B = 0.25 * (kS1 - kS2 + Rr)  # seed 002 eq 2.6.5
    np.testing.assert_allclose(k1, 2 * B, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(k2, 2 * A, rtol=1e-12, atol=1e-12)
    # seed 002 eq 2.6.1 and 2.6.2 (alpha measured in the sense of sigma: sin 2alpha sign flips)
    np.testing.assert_allclose(np.cos(2 * alpha), (g1 - g2 * np.cos(2 * sigma)) / Rr, atol=1e-11)
    np.testing.assert_allclose(np.sin(2 * alpha), -g2 * np.sin(2 * sigma) / Rr, atol=1e-11)


@settings(max_examples=60, deadline=None)
@given(st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5), st.floats(-3.2, 3.2))
def test_relative_principal_brute_force(a1, b1, a2, b2, sigma):
    kI1, kII1, kI2, kII2 = a1, b1, a2, b2
    k1, k2, alpha = cv.relative_principal_curvatures(kI1, kII1, kI2, kII2, sigma)
    q = np.linspace(-np.pi / 2, np.pi / 2, 20001)
    kr = kI1 * np.cos(q) ** 2 + kII1 * np.sin(q) ** 2 - kI2 * np.cos(q - sigma) ** 2 - kII2 * np.sin(q - sigma) ** 2
    assert abs(kr.max() - k1) < 1e-6 * (1 + abs(k1)) and abs(kr.min() - k2) < 1e-6 * (1 + abs(k2))
    at_alpha = (
        kI1 * np.cos(alpha) ** 2
        + kII1 * np.sin(alpha) ** 2
        - kI2 * np.cos(alpha - sigma) ** 2
        - kII2 * np.sin(alpha - sigma) ** 2
    )
    assert abs(at_alpha - k1) < 1e-9 * (1 + abs(k1))


def test_relative_small_difference_accuracy():
    # longitudinal relative curvature a tiny difference of nearly equal curvatures (seed 004)
    kI1, kII1 = 0.05, 1e-3
    kI2, kII2 = 0.049, 1e-3 - 1e-9
    k1, k2, alpha = cv.relative_principal_curvatures(kI1, kII1, kI2, kII2, 0.0)
    assert k1 == pytest.approx(1e-3, rel=1e-12)
    assert k2 == pytest.approx(1e-9, rel=1e-6)


def test_second_form_in_basis_is_shape_matrix_and_rotates_with_the_basis():
    # skewed torus parametrisation (F != 0), analytic derivatives via the chain rule
    s = Torus(3.0, 1.2)
    u, v = np.array([0.4, 1.3, -2.0]), np.array([0.9, -0.3, 2.2])
    q = s.evaluate(u, v)
    p = SurfacePoint(
        q.r, q.r_u, q.r_u * 0.6 + q.r_v, q.r_uu, q.r_uu * 0.6 + q.r_uv, q.r_uu * 0.36 + 2 * 0.6 * q.r_uv + q.r_vv
    )  # v' = v, u = u' + 0.6 v'
    t1, t2, n, S11, S12, S22 = cv.shape_matrix(p)
    K = cv.second_form_in_basis(p, n, t1, t2)
    assert K.shape == (3, 2, 2)
    np.testing.assert_allclose(K[..., 0, 0], S11, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(K[..., 0, 1], S12, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(K[..., 1, 0], S12, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(K[..., 1, 1], S22, rtol=1e-13, atol=1e-15)
    # any orthonormal basis: II(e, e) is the normal curvature, eigenvalues the principal curvatures
    a = np.array([0.2, -1.0, 2.5])[:, None]
    e1, e2 = np.cos(a) * t1 + np.sin(a) * t2, -np.sin(a) * t1 + np.cos(a) * t2
    K = cv.second_form_in_basis(p, n, e1, e2)
    np.testing.assert_allclose(K[..., 0, 0], cv.normal_curvature(p, e1), rtol=1e-12)
    np.testing.assert_allclose(K[..., 1, 1], cv.normal_curvature(p, e2), rtol=1e-12)
    pc = cv.principal_curvatures(p)
    w = np.linalg.eigvalsh(K)
    np.testing.assert_allclose(w[:, 1], pc.k1, rtol=1e-12)
    np.testing.assert_allclose(w[:, 0], pc.k2, rtol=1e-12)
    k1, k2, _, _ = s.exact_principal(u, v)
    np.testing.assert_allclose(np.sort(w, axis=1), np.sort(np.stack([k1, k2], -1), axis=1), rtol=1e-12)
    # the opposite normal flips the form
    np.testing.assert_allclose(cv.second_form_in_basis(p, -n, e1, e2), -K, rtol=0, atol=0)


def test_sym2_eig_matches_numpy_eigh():
    rng = np.random.default_rng(1)
    a, b, c = rng.normal(size=(3, 500)) * 10.0 ** rng.uniform(-6, 6, size=(3, 500))
    lam1, lam2, theta = cv.sym2_eig(a, b, c)
    M = np.stack([np.stack([a, b], -1), np.stack([b, c], -1)], -2)
    w = np.linalg.eigvalsh(M)
    scale = np.abs(w).max(axis=1)
    np.testing.assert_allclose(lam1, w[:, 1], rtol=0, atol=1e-13 * scale.max())
    assert np.all(np.abs(lam1 - w[:, 1]) <= 1e-12 * scale)
    assert np.all(np.abs(lam2 - w[:, 0]) <= 1e-12 * scale)
    e = np.stack([np.cos(theta), np.sin(theta)], -1)
    Me = np.einsum("nij,nj->ni", M, e)
    assert np.all(np.linalg.norm(Me - lam1[:, None] * e, axis=1) <= 1e-10 * scale)
    assert np.all((theta > -np.pi / 2 - 1e-15) & (theta <= np.pi / 2 + 1e-15))


def test_sym2_eig_small_eigenvalue_without_cancellation_and_umbilic():
    # [[1, 1e-8], [1e-8, 1e-16 + 1e-16]]: det = 1e-16 exactly representable -> small eigenvalue 1e-16
    lam1, lam2, _ = cv.sym2_eig(1.0, 1e-8, 2e-16)
    assert lam2 == pytest.approx(1e-16, rel=1e-8)
    l1, l2, th = cv.sym2_eig(np.array([2.0, -3.0]), np.array([0.0, 0.0]), np.array([2.0, -3.0]))
    np.testing.assert_array_equal(l1, l2)
    np.testing.assert_array_equal(th, 0.0)


@pytest.mark.parametrize("surface, expected", [(Sphere(R=4.0), (-0.25, -0.25)), (Cylinder(R=2.0), (0.0, -0.5))])
def test_shape_matrix_eigenvalues_are_principal_curvatures(surface, expected):
    u, v = np.array([0.3, 1.1]), np.array([0.2, -0.4])
    t1, t2, n, S11, S12, S22 = cv.shape_matrix(surface.evaluate(u, v))
    np.testing.assert_allclose(np.einsum("...i,...i", t1, t2), 0.0, atol=1e-15)
    np.testing.assert_allclose(np.einsum("...i,...i", t1, n), 0.0, atol=1e-15)
    k1, k2, _ = cv.sym2_eig(S11, S12, S22)
    got = np.sort(np.stack([k1, k2]), axis=0)
    np.testing.assert_allclose(got, np.sort(np.array(expected))[:, None] * np.ones(2), rtol=1e-12, atol=1e-14)
