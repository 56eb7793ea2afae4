"""gearrep.curvature_relations: generating/generated curvature relations (GGAT ch. 8; seed 000
eq 4.6-4.39) against closed forms and against direct differential geometry of the envelope."""

import numpy as np
import pytest
from _envelope_cases import (
    TORUS,
    Cylinder,
    Plane,
    ellipsoid_curvatures,
    ellipsoid_motion,
    hob_case,
    principal_wrt,
    torus_motion,
)

from gearrep.curvature_relations import (
    _two_parameter_b_coefficients_printed,
    generated_curvatures,
    litvin_one_parameter,
    two_parameter_b_coefficients,
    two_parameter_principal_curvatures,
    two_parameter_system,
)
from gearrep.envelope import Envelope, rack_generation_motion, singular_points
from gearrep.surface import Surface
from gearrep.surfaces.rack import ParabolicRackCutter, StraightRackCutter, vertex_pitch_distance
from gearrep.units import DEG


def rack_envelope(rack, r_p, member_side=-1):
    return Envelope(rack, rack_generation_motion(r_p, member_side), free=("u", "v"))


class PositionOnly(Surface):
    """Wraps a surface's position so that evaluate() uses the base class's finite differences
    (an independent check of the envelope's own derivatives)."""

    def __init__(self, surf, fd_step):
        self.surf, self.fd_step = surf, fd_step

    def position(self, u, v):
        return self.surf.position(u, v)


def assert_direct(env, rec, gc, guess, fd_step, rtol_analytic, rtol_fd, fd_pure=None):
    """Relations vs gearrep.curvature on the generated surface (analytic-normal derivatives of
    EnvelopeSurface, and pure finite differences of its solved positions with steps ``fd_pure``:
    these must be larger, since the solved positions carry the Newton tolerance's noise)."""
    a = rec.params[:, env.free[0]]
    b = rec.params[:, env.free[1]]
    surf = env.surface(guess, fd_step=fd_step)
    scale = np.max(np.abs([gc.k1, gc.k2]))
    pure = PositionOnly(surf, fd_pure or fd_step)
    for s, rtol in ((surf, rtol_analytic), (pure, rtol_fd)):
        k1, k2 = principal_wrt(s.evaluate(a, b), gc.normal)
        np.testing.assert_allclose(k1, gc.k1, rtol=rtol, atol=rtol * scale)
        np.testing.assert_allclose(k2, gc.k2, rtol=rtol, atol=rtol * scale)


# ---- one-parameter enveloping ------------------------------------------------------------------
def test_involute_helicoid_closed_form():
    N, mn, an, beta = 20, 3.0, 20 * DEG, 15 * DEG
    r_p = mn * N / (2 * np.cos(beta))
    env = rack_envelope(StraightRackCutter(an, beta, y0=0.3), r_p)
    u, th = np.meshgrid(np.linspace(-2.5, 3.0, 6), np.linspace(-10, 10, 3))
    rec = env.solve(u, th, guess=0.0)
    gc = generated_curvatures(env, rec.params)
    alpha_t = np.arctan(np.tan(an) / np.cos(beta))
    r_b = r_p * np.cos(alpha_t)
    beta_b = np.arctan(np.tan(beta) * np.cos(alpha_t))
    rho = np.hypot(rec.point[:, 0], rec.point[:, 1])
    k_closed = np.cos(beta_b) / np.sqrt(rho**2 - r_b**2)
    np.testing.assert_allclose(gc.k2, -k_closed, rtol=1e-12)
    np.testing.assert_allclose(gc.k1, 0.0, atol=1e-12 * k_closed.max())
    # curved direction is transverse (normal to the gear axis), the straight one is the
    # generatrix, tangent to the base helix: angle beta_b with the axis
    np.testing.assert_allclose(gc.e2[:, 2], 0.0, atol=1e-12)
    np.testing.assert_allclose(np.abs(gc.e1[:, 2]), np.cos(beta_b), rtol=1e-12)
    # the rack plane has k_f = k_h = 0; a_13, a_23 and a_33 are Litvin's coefficients
    np.testing.assert_allclose(gc.k_f, 0.0, atol=1e-15)
    assert gc.A.shape == (rec.params.shape[0], 3, 3)
    np.testing.assert_allclose(np.linalg.svd(gc.A, compute_uv=False)[:, 1:], 0.0, atol=1e-12)  # rank 1


@pytest.mark.parametrize("a, side, member_side", [(0.425, 1, -1), (0.394, 1, 1), (-0.3, -1, -1)])
def test_parabolic_rack_relations_vs_direct(a, side, member_side):
    an, Pn, beta = 25 * DEG, 5.0, 19.948 * DEG
    r_p = 17 / (2 * Pn * np.cos(beta))
    rack = ParabolicRackCutter(a, an, vertex_pitch_distance(an, Pn), beta=beta, side=side)
    env = rack_envelope(rack, r_p, member_side)
    u, th = np.meshgrid(np.linspace(-0.15, 0.15, 3), np.linspace(-1.0, 1.0, 3))
    rec = env.solve(u, th, guess=0.0)
    assert np.all(rec.converged)
    gc = generated_curvatures(env, rec.params)
    assert np.all(np.abs(gc.k_h) > 0.1)  # a curved tool: the K_1 terms matter
    assert_direct(env, rec, gc, 0.0, (1e-3, 1e-3), 1e-9, 1e-7)
    # GGAT ch. 8 closed formulas (tan 2 sigma, k_s + k_q, k_s - k_q) give the same answer
    A = gc.A
    ks, kq, sig = litvin_one_parameter(gc.k_f, gc.k_h, A[:, 0, 2], A[:, 1, 2], A[:, 2, 2])
    np.testing.assert_allclose([ks, kq], [gc.k1, gc.k2], rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(sig, gc.sigma, atol=1e-13)
    np.testing.assert_allclose(ks + kq, gc.k_f + gc.k_h + (A[:, 0, 2] ** 2 + A[:, 1, 2] ** 2) / A[:, 2, 2], rtol=1e-13)
    # e1 = cos(sigma) e_f + sin(sigma) e_h, orthonormal frame with the common normal
    e1 = np.cos(gc.sigma)[:, None] * gc.e_f + np.sin(gc.sigma)[:, None] * gc.e_h
    np.testing.assert_allclose(e1, gc.e1, atol=1e-14)
    np.testing.assert_allclose(np.cross(gc.e1, gc.e2), gc.normal, atol=1e-14)


def test_seed002_sec_2_5_principal_curvatures():
    """Seed 002 sec. 2.5 example: printed kappa_I(1) = 0.0125, kappa_II(1) = 1.5605,
    kappa_I(2) = 0.0083, kappa_II(2) = 0.5940 (1/in). Reproduced (4 decimals, gear kappa_II to
    1.1e-4) with a_i = 1/(2 rho_i), rho_c = 5.88/P_n, rho_t = 6.35/P_n (seed 002 eq 2.7.2, 2.7.4;
    the printed a_c = 0.425, a_t = 0.394 are these rounded) and beta = arccos(94/100) = 19.948 deg
    (centre distance 10 in), NOT the printed 19.548 deg. The pinion is elliptic and the gear
    hyperbolic (opposite signs: the printed "both positive" lost a sign)."""
    an, Pn = 25 * DEG, 5.0
    l = vertex_pitch_distance(an, Pn)

    def curv(N, a, beta, member_side):
        r_p = N / (2 * Pn * np.cos(beta))
        env = rack_envelope(ParabolicRackCutter(a, an, l, beta=beta), r_p, member_side)
        rec = env.solve(0.0, 0.0, guess=0.0)  # point Q (u = 0)
        gc = generated_curvatures(env, rec.params)
        return gc.k1[0], gc.k2[0]

    beta = np.arccos(0.94)
    p1, p2 = curv(17, Pn / (2 * 5.88), beta, -1)
    g1, g2 = curv(77, Pn / (2 * 6.35), beta, +1)
    pin = np.sort(np.abs([p1, p2]))
    gear = np.sort(np.abs([g1, g2]))
    np.testing.assert_allclose(pin, [0.0125, 1.5605], atol=6e-5)
    np.testing.assert_allclose(gear, [0.0083, 0.5940], atol=1.5e-4)
    assert p1 * p2 > 0 and g1 * g2 < 0
    # the printed helix angle 19.548 deg misses the pinion's kappa_II by 4e-3
    q1, q2 = curv(17, Pn / (2 * 5.88), 19.548 * DEG, -1)
    assert abs(max(abs(q1), abs(q2)) - 1.5605) > 3e-3


def test_a33_vanishes_at_singular_points():
    """E (GGAT a_33) is zero exactly at Litvin's limiting line (module doc)."""
    r_p = 5.0
    env = rack_envelope(StraightRackCutter(20 * DEG), r_p)
    sp = singular_points(env, "v", [0.0], guess=[-0.6, -0.3])
    gc = generated_curvatures(env, sp.params)
    rec = env.solve(np.array([-1.0, 1.0]), 0.0, guess=0.0)
    scale = np.max(np.abs(generated_curvatures(env, rec.params).E))
    assert abs(gc.E[0, 0, 0]) < 1e-9 * scale
    assert not np.isfinite(gc.k2[0]) or abs(gc.k2[0]) > 1e6  # curvature blows up at the cusp


# ---- two-parameter enveloping --------------------------------------------------------------
def test_two_parameter_torus_closed_form():
    R0, r0, rho, gamma = TORUS["R0"], TORUS["r0"], TORUS["rho"], TORUS["gamma"]
    env = Envelope(Cylinder(rho), torus_motion(**TORUS), free=("theta", "psi"))
    th, ps = np.meshgrid(np.linspace(-0.5, 2.5, 3), np.linspace(-1.2, 1.2, 4))
    rec = env.solve(th, ps, guess=[0.1, 0.2])
    gc = generated_curvatures(env, rec.params)
    p = rec.param("psi")
    kmer = np.full(p.shape, -1.0 / (r0 + rho))
    kpar = -np.cos(p) / (R0 + (r0 + rho) * np.cos(p))
    np.testing.assert_allclose(gc.k1, kpar, rtol=1e-12)  # the parallel is the flatter direction
    np.testing.assert_allclose(gc.k2, kmer, rtol=1e-12)
    # tool: k_f = 0 along the cylinder axis, k_h = -1/rho; the parallel circle is at -gamma
    np.testing.assert_allclose(gc.k_f, 0.0, atol=1e-15)
    np.testing.assert_allclose(gc.k_h, -1.0 / rho, rtol=1e-14)
    np.testing.assert_allclose(gc.sigma, -gamma, atol=1e-12)
    np.testing.assert_allclose(np.linalg.svd(gc.A, compute_uv=False)[:, 2:], 0.0, atol=1e-12)  # rank 2
    assert_direct(env, rec, gc, [0.1, 0.2], (1e-3, 1e-3), 1e-10, 1e-7)


def test_two_parameter_ellipsoid_closed_form():
    axes = np.array([3.0, 2.0, 1.2])
    env = Envelope(Plane(), ellipsoid_motion(axes), free=("theta", "psi"))
    th, ps = np.meshgrid(np.linspace(-2, 2, 4), np.linspace(0.3, 1.2, 3))
    rec = env.solve(th, ps, guess=[0.0, 0.0])
    gc = generated_curvatures(env, rec.params)
    kc1, kc2 = ellipsoid_curvatures(rec.point, axes)
    # motion derivatives by finite differences (FunctionMotion): ~1e-9 relative
    np.testing.assert_allclose(gc.k1, kc1, rtol=1e-8)
    np.testing.assert_allclose(gc.k2, kc2, rtol=1e-8)


def test_two_parameter_hob_vs_direct():
    """Seed 000 set-up (free (l, psi), solved (phi, theta)), across the mid-face psi = 0."""
    tool, motion = hob_case()
    env = Envelope(tool, motion, free=("u", "psi"))
    l, ps = np.meshgrid(np.linspace(4.4, 10.3, 3), np.array([-0.1, 0.0, 0.1]))
    rec = env.solve(l, ps, guess=[np.pi, 0.0])
    assert np.all(rec.converged)
    gc = generated_curvatures(env, rec.params)
    assert_direct(env, rec, gc, [np.pi, 0.0], (1e-3, 1e-4), 1e-9, 1e-7, fd_pure=(1e-2, 1e-3))
    # e_1, e_2 orthonormal and tangent
    np.testing.assert_allclose(np.einsum("na,na->n", gc.e1, gc.normal), 0.0, atol=1e-14)
    np.testing.assert_allclose(np.cross(gc.e1, gc.e2), gc.normal, atol=1e-14)


def test_seed000_equations_4_33_to_4_39():
    tool, motion = hob_case()
    env = Envelope(tool, motion, free=("u", "psi"))
    rec = env.solve(np.linspace(4.4, 10.3, 4), np.array([-0.1, 0.0, 0.05, 0.1]), guess=[np.pi, 0.0])
    gc = generated_curvatures(env, rec.params)
    b = two_parameter_system(env, rec.params)
    assert np.all(np.isnan(b[:, :2, :2])) and np.all(np.isfinite(b[:, 2:, :]))
    b11, b12, b22 = two_parameter_b_coefficients(b)
    # B = K_2 - K_1 in (e_f, e_h)
    np.testing.assert_allclose(
        np.stack([b11, b12, b22], -1), np.stack([gc.A[:, 0, 0], gc.A[:, 0, 1], gc.A[:, 1, 1]], -1), rtol=1e-12
    )
    # rank 2 of the completed 4 x 4 matrix (eq 4.33) and the determinant conditions 4.34-4.36
    bb = b.copy()
    bb[:, 0, 0], bb[:, 0, 1], bb[:, 1, 0], bb[:, 1, 1] = b11, b12, b12, b22
    s = np.linalg.svd(bb, compute_uv=False)
    assert np.all(s[:, 2] < 1e-12 * s[:, 0])

    def det3(x11, rows, cols):
        m = bb[:, rows][:, :, cols].copy()
        m[:, 0, 0] = x11
        return np.linalg.det(m)

    d434 = det3(b11, [0, 2, 3], [0, 2, 3])
    scale = np.abs(np.linalg.det(bb[:, 2:, 2:])) * np.abs(b11)
    assert np.all(np.abs(d434) < 1e-10 * scale)
    # printed 4.37-4.39: every numerator has the wrong sign -> B_printed = -B
    p11, p12, p22 = _two_parameter_b_coefficients_printed(b)
    np.testing.assert_allclose([p11, p12, p22], [-b11, -b12, -b22], rtol=1e-12)
    assert np.all(np.abs(det3(p11, [0, 2, 3], [0, 2, 3])) > 1e-3 * scale)
    # k_s, k_q, sigma (4.24-4.26): same pair as the direct geometry, e_s the one nearest e_f
    ks, kq, sig = two_parameter_principal_curvatures(b11, b12, b22, gc.k_f, gc.k_h)
    np.testing.assert_allclose(np.sort(np.c_[ks, kq], axis=1), np.c_[gc.k2, gc.k1], rtol=1e-12)
    assert np.all(np.abs(sig) <= np.pi / 4 + 1e-15)
    np.testing.assert_allclose(
        np.abs(np.sin(sig)), np.abs(np.sin(np.where(ks >= kq, gc.sigma, gc.sigma - np.pi / 2))), atol=1e-12
    )
    # with the printed signs the curvatures are wrong
    ks_p, kq_p, _ = two_parameter_principal_curvatures(p11, p12, p22, gc.k_f, gc.k_h)
    assert np.max(np.abs(np.sort(np.c_[ks_p, kq_p], axis=1) - np.c_[gc.k2, gc.k1])) > 1e-2


def test_seed000_principal_curvatures_b12_zero_limit():
    ks, kq, sig = two_parameter_principal_curvatures(0.3, 0.0, -0.2, 0.1, -0.5)
    assert sig == 0.0 and ks == pytest.approx(0.4) and kq == pytest.approx(-0.7)
    ks, kq, sig = two_parameter_principal_curvatures(0.3, 1e-30, -0.2, 0.1, -0.5)
    assert ks == pytest.approx(0.4) and kq == pytest.approx(-0.7)


def test_validation():
    env = rack_envelope(StraightRackCutter(20 * DEG), 10.0)
    with pytest.raises(ValueError, match="q must"):
        generated_curvatures(env, np.zeros((2, 4)))
    with pytest.raises(ValueError, match="k = 2"):
        two_parameter_system(env, np.zeros((2, 3)))
    with pytest.raises(ValueError, match="b must"):
        two_parameter_b_coefficients(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="b_33"):
        two_parameter_b_coefficients(np.zeros((4, 4)))
    with pytest.raises(ValueError, match="a33"):
        litvin_one_parameter(0.0, 0.0, 1.0, 1.0, 0.0)
