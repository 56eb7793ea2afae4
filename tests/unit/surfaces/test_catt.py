"""CATT flank of seed 004 (gearrep.surfaces.catt) against independent computations.

* eq (6) as printed (u from its fourth line) = the closed form (C) used by the library;
* a direct numerical envelope: the cutter family r(u, theta, phi) carried by the transforms of
  eq (1)-(4), the equation of meshing n . dr/dphi = 0 solved for u by Newton with complex-step
  derivatives (no use of the closed form), gives the same surface;
* analytic derivatives = 4th-order finite differences; middle-section principal curvatures = the
  closed forms (involute profile, blade-cone axial curvature) and gearrep.curvature;
* straight-trace limit: R_T -> infinity gives the involute spur flank of gearrep.surfaces.involute,
  off the middle section with the predicted 1/R_T^2 (transverse pressure angle) deviation;
* eq (28)-(29) are eq (6) in a turned-over frame; tooth thickness = its closed form;
* bad input raises ValueError naming the parameter; the turn-over is a half turn about x.
"""

from __future__ import annotations

import numpy as np
import pytest
from _numerics import assert_rounding_close

from gearrep import curvature
from gearrep.solve import newton
from gearrep.surface import fd_derivatives
from gearrep.surfaces.catt import (
    CATTFlank,
    CATTGearData,
    eq28_profile,
    eq29_profile,
    middle_section_curvatures,
    pitch_thickness_closed_form,
    tooth_thickness,
)
from gearrep.surfaces.involute import InvoluteFlank, InvoluteGearData, involute_polar_angle

GEAR = CATTGearData(19, 8.0, 500.0, 80.0)


def grid(f, n=7):
    th = np.linspace(-0.07, 0.07, n)[:, None]
    ph0 = -f.side * GEAR.q / GEAR.r_p
    ph = np.linspace(ph0 - 0.15, ph0 + 0.15, n)[None, :]
    return np.broadcast_arrays(th, ph)


@pytest.mark.parametrize("side", [1, -1])
def test_eq6_literal_equals_closed_form(side):
    f = CATTFlank(GEAR, side)
    T, P = grid(f)
    np.testing.assert_allclose(f.position(T, P), f.position_eq6(T, P), atol=1e-10)


@pytest.mark.parametrize("side", [1, -1])
def test_numerical_envelope_equals_closed_form(side):
    """Solve n . v = 0 of the cutter family for u numerically, with derivatives of the transforms
    of eq (1)-(4) taken by the complex step (no use of the closed form).

    Why the complex step: central differences of coordinates of size ~500 mm with h = 1e-6 carry a
    rounding error ~eps * 500 / h ~ 1e-7 into n . v (measured 1.8e-7 at the exact u), a floor above
    the solver tolerance 1e-9, so Newton stalled at the right u but reported not_converged. The
    complex step gives the derivatives to rounding (the meshing function is linear in u, so the
    start u = 0 is not the problem)."""
    f = CATTFlank(GEAR, side)
    T, P = (x.ravel() for x in grid(f, 5))
    h = 1e-30

    def d(fun, k, X):
        Xc = [x.astype(complex) for x in X]
        Xc[k] = Xc[k] + 1j * h
        return fun(*Xc).imag / h

    def meshing(X):
        args = (X[:, 0], X[:, 1], X[:, 2])
        r_u = d(f.position_by_transforms, 0, args)
        r_t = d(f.position_by_transforms, 1, args)
        v = d(f.position_by_transforms, 2, args)
        n = np.cross(r_u, r_t)
        n /= np.linalg.norm(n, axis=-1, keepdims=True)
        return np.column_stack([np.sum(n * v, axis=-1), np.zeros(len(X)), np.zeros(len(X))])

    def jac(X):
        J = np.zeros((len(X), 3, 3))
        dd = 1e-4
        Xp, Xm = X.copy(), X.copy()
        Xp[:, 0] += dd
        Xm[:, 0] -= dd
        J[:, 0, 0] = (meshing(Xp)[:, 0] - meshing(Xm)[:, 0]) / (2 * dd)
        J[:, 1, 1] = J[:, 2, 2] = 1.0
        return J

    # the complex-step transforms reproduce the real ones (complex and real cos/sin round differently)
    assert_rounding_close(f.position_by_transforms(T.astype(complex), T, P).real, f.position_by_transforms(T, T, P))
    res = newton(meshing, np.column_stack([np.zeros_like(T), T, P]), jac, tol=1e-9, maxiter=40)
    assert np.all(res.converged)
    u = res.x[:, 0]
    np.testing.assert_allclose(f.position_by_transforms(u, T, P), f.position(T, P), atol=1e-6)
    np.testing.assert_allclose(u, f.blade_u(T, P), atol=1e-6)
    # and the library's analytic meshing residual vanishes on the closed form
    assert np.max(np.abs(f.meshing_residual(f.blade_u(T, P), T, P))) < 1e-10


@pytest.mark.parametrize("side", [1, -1])
def test_analytic_derivatives_match_fd(side):
    f = CATTFlank(GEAR, side)
    T, P = (x.ravel() for x in grid(f, 4))
    a = f.evaluate(T, P)
    d = fd_derivatives(f.position, T, P, 1e-3, 1e-4)
    for name in ("r_u", "r_v", "r_uu", "r_uv", "r_vv"):
        x, y = getattr(a, name), getattr(d, name)
        scale = np.max(np.abs(x))
        assert np.max(np.abs(x - y)) < 1e-6 * scale, name


@pytest.mark.parametrize("side", [1, -1])
def test_middle_section_curvatures_closed_form(side):
    f = CATTFlank(GEAR, side)
    radii = np.linspace(GEAR.r_form + 0.5, GEAR.r_a, 7)
    phi = f.middle_section_phi(radii)
    p = f.evaluate(np.zeros_like(phi), phi)
    np.testing.assert_allclose(np.hypot(p.r[:, 0], p.r[:, 1]), radii, rtol=1e-13)
    assert np.max(np.abs(p.r[:, 2])) < 1e-12
    pc = curvature.principal_curvatures(p)
    kp, ka, _, _ = middle_section_curvatures(GEAR, side, radii)
    got = np.sort(np.column_stack([pc.k1, pc.k2]), axis=1)
    exp = np.sort(np.column_stack([kp, ka]), axis=1)
    np.testing.assert_allclose(got, exp, rtol=1e-9)
    # convex (s = +1) / concave (s = -1) along the face width w.r.t. the outward normal
    assert np.all(np.sign(ka) == -side)


@pytest.mark.parametrize("z_mm", [0.0, 30.0])
def test_straight_trace_limit_is_involute_spur(z_mm):
    """R_T -> infinity: the transverse profile tends to the involute of r_b = R cos(alpha) (exactly
    involute in the middle section). Off the middle section the tooth trace of the generating rack
    is inclined by beta = asin(z / rho) (rho = R_T - pi m/4, the inside blade at the pitch line), so
    the section is, to leading order, the involute of transverse pressure angle
    tan(alpha_t) = tan(alpha) / cos(beta), as on a helical gear: the deviation from the spur
    involute is that predicted one and falls like beta^2 ~ 1/R_T^2 (a factor 100 per decade)."""
    inv = InvoluteGearData(19, 8.0, np.radians(20.0), 80.0)
    devs = []
    for RT in (1e3, 1e4, 1e5):
        g = CATTGearData(19, 8.0, RT, 80.0)
        radii = np.linspace(g.r_form + 0.5, g.r_a, 9)
        f = CATTFlank(g, 1)
        pts, res = f.section_profile(z_mm, radii)
        assert np.all(res.converged)
        psi_c = np.unwrap(np.arctan2(pts[:, 1], pts[:, 0]))
        best = np.inf
        for side in (1, -1):
            q = InvoluteFlank(inv, side).position(radii, np.full_like(radii, z_mm))
            psi_i = np.unwrap(np.arctan2(q[:, 1], q[:, 0]))
            for sgn in (1, -1):  # the two frames may be mirrored
                d = sgn * psi_c - psi_i
                best = min(best, float(np.max(np.abs(d - d.mean())) * inv.r_b))
        devs.append(best)
        # predicted deviation: involute of base radius R cos(alpha_t) against R cos(alpha)
        beta = np.arcsin(z_mm / (RT - g.q))
        alpha_t = np.arctan(np.tan(g.pressure_angle) / np.cos(beta))
        dp = involute_polar_angle(radii, g.r_p * np.cos(alpha_t)) - involute_polar_angle(radii, g.r_b)
        pred = float(np.max(np.abs(dp - dp.mean())) * g.r_b)
        if z_mm == 0.0:
            assert pred == 0.0
        else:
            assert best == pytest.approx(pred, rel=2e-3)
        # the tooth is as thick as the involute spur tooth in the limit
        t, _ = tooth_thickness(g, [z_mm])
        assert t[0] == pytest.approx(inv.tooth_thickness, abs=2 * 8.0 * z_mm**2 / RT**2 + 1e-9)
    if z_mm == 0.0:
        assert max(devs) < 1e-10
    else:
        assert devs[2] < 1e-6
        assert devs[1] / devs[2] == pytest.approx(100.0, rel=0.01)
        assert devs[0] / devs[1] == pytest.approx(100.0, rel=0.02)


def test_eq29_and_eq28_are_eq6_turned_over():
    ph = np.linspace(-0.2, 0.2, 9)
    for upper, side in ((True, -1), (False, 1)):
        x, y = eq29_profile(GEAR, upper, ph)
        p = CATTFlank(GEAR, side).position(0 * ph, ph)
        np.testing.assert_allclose(np.column_stack([x, -y]), p[:, :2], atol=1e-10)
    f = CATTFlank(GEAR, -1)
    b = 20.0
    th = np.linspace(0.9, 1.1, 5) * np.arcsin(b / f.rho0)
    x, y, phi1, _ = eq28_profile(GEAR, True, b, th)
    p = f.position(th, phi1)
    # eq (28) upper at offset b is eq (6) lower at z = -b with y -> -y
    np.testing.assert_allclose(p[:, 2], -b, atol=1e-10)
    np.testing.assert_allclose(np.column_stack([x, -y]), p[:, :2], atol=1e-9)


def test_tooth_thickness_closed_form():
    z = np.array([0.0, 15.0, 30.0, 39.0])
    t, res = tooth_thickness(GEAR, z)
    assert res < 1e-9
    np.testing.assert_allclose(t, pitch_thickness_closed_form(GEAR, z), atol=1e-9)
    assert t[0] == pytest.approx(np.pi * GEAR.module / 2, abs=1e-12)
    assert np.all(np.diff(t) < 0)


@pytest.mark.parametrize(
    "kw,name",
    [
        ({"n_teeth": 2.5}, "n_teeth"),
        ({"module": -1.0}, "module"),
        ({"R_T": 30.0}, "R_T"),
        ({"face_width": 0.0}, "face_width"),
        ({"pressure_angle": 1.2}, "pressure_angle"),
    ],
)
def test_bad_input(kw, name):
    args = {"n_teeth": 19, "module": 8.0, "R_T": 500.0, "face_width": 80.0, **kw}
    with pytest.raises(ValueError, match=name):
        CATTGearData(**args)
    with pytest.raises(ValueError, match="side"):
        CATTFlank(GEAR, 0)


@pytest.mark.parametrize("side", [1, -1])
def test_printed_eq8_10_15_16_are_wrong_corrected_forms_hold(side):
    """Evidence for the errata of seed 004 sec. 3.1 (data/errata.csv), on the flank itself:
    eq (8) divides by |r_theta . r_phi|, which is 0 on the middle section (where the contact lies) and
    is not |r_theta x r_phi| elsewhere; eq (10) F = r_theta . r depends on the origin, while the first
    fundamental form needs F = r_theta . r_phi; eq (15)-(16): with H the mean curvature of eq (14) the
    principal curvatures are H +- sqrt(H^2 - K), roots of x^2 - 2Hx + K = 0."""
    f = CATTFlank(GEAR, side)
    ph0 = f.middle_section_phi(GEAR.r_p)
    th = np.array([0.0, 0.03, 0.06])
    ph = np.full_like(th, ph0) + np.array([0.0, 0.02, -0.03])
    p = f.evaluate(th, ph)
    dot = np.sum(p.r_u * p.r_v, axis=-1)
    cross = np.linalg.norm(np.cross(p.r_u, p.r_v), axis=-1)
    scale = np.linalg.norm(p.r_u, axis=-1) * np.linalg.norm(p.r_v, axis=-1)
    assert abs(dot[0]) < 1e-12 * scale[0]  # printed eq (8): division by zero at the middle section
    assert np.all(np.abs(np.abs(dot[1:]) - cross[1:]) > 0.5 * cross[1:])  # and not the norm elsewhere
    # eq (10): the first fundamental form reproduces |dr|^2 with F = r_theta . r_phi, not with r_theta . r
    d = np.array([2e-5, 3e-5])
    dr = f.position(th + d[0], ph + d[1]) - f.position(th - d[0], ph - d[1])
    E, G = np.sum(p.r_u**2, -1), np.sum(p.r_v**2, -1)
    F_ok, F_printed = dot, np.sum(p.r_u * p.r, axis=-1)
    I_ok = 4 * (E * d[0] ** 2 + 2 * F_ok * d[0] * d[1] + G * d[1] ** 2)
    I_pr = 4 * (E * d[0] ** 2 + 2 * F_printed * d[0] * d[1] + G * d[1] ** 2)
    ds2 = np.sum(dr**2, -1)
    np.testing.assert_allclose(I_ok, ds2, rtol=1e-6)
    # (on the middle section r_theta is axial and r lies in z = 0, so there both F vanish; off it they differ)
    assert np.all(np.abs(I_pr[1:] / ds2[1:] - 1) > 1e-2)
    # eq (13)-(16)
    n = p.normal
    L, M, N = (np.sum(x * n, -1) for x in (p.r_uu, p.r_uv, p.r_vv))
    K = (L * N - M**2) / (E * G - F_ok**2)
    H = (L * G - 2 * M * F_ok + N * E) / (2 * (E * G - F_ok**2))
    pc = curvature.principal_curvatures(p)
    k = np.sort(np.column_stack([pc.k1, pc.k2]), axis=1)
    corrected = np.sort(np.column_stack([H - np.sqrt(H * H - K), H + np.sqrt(H * H - K)]), axis=1)
    np.testing.assert_allclose(corrected, k, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(k.sum(axis=1), 2 * H, rtol=1e-9)  # x^2 - 2Hx + K = 0, not x^2 - Hx + K
    k2_printed = H + np.sqrt(H * H + K)
    assert np.all(np.min(np.abs(k - k2_printed[:, None]), axis=1) > 1e-3 * np.max(np.abs(k), axis=1))
    with np.errstate(invalid="ignore"):
        roots15 = np.column_stack([(H - np.sqrt(H * H - 4 * K)) / 2, (H + np.sqrt(H * H - 4 * K)) / 2])
    assert not np.allclose(np.sort(roots15, axis=1), k, rtol=1e-3)


def test_printed_eq19_needs_R_I_in_its_first_term():
    """Eq (19): k^I - k^II in direction sigma0 is H^I - H^II + R^I cos 2 sigma0 - R^II cos 2(sigma0 - sigma);
    the printed R^II in the first term is wrong whenever R^I != R^II (curvatures of the sec 4 pair's
    flanks at the pitch point, concave gear I and convex pinion II, sigma = 90 deg as in the TCA)."""
    g1, g2 = GEAR, CATTGearData(31, 8.0, 500.0, 80.0)
    kpI, kaI, _, _ = middle_section_curvatures(g2, -1, g2.r_p)
    kpII, kaII, _, _ = middle_section_curvatures(g1, 1, g1.r_p)
    k1I, k2I = max(kpI, kaI), min(kpI, kaI)
    k1II, k2II = max(kpII, kaII), min(kpII, kaII)
    sigma = np.pi / 2
    s0 = np.linspace(0, np.pi, 13)
    direct = (
        k1I * np.cos(s0) ** 2 + k2I * np.sin(s0) ** 2 - k1II * np.cos(s0 - sigma) ** 2 - k2II * np.sin(s0 - sigma) ** 2
    )
    HI, HII, RI, RII = (k1I + k2I) / 2, (k1II + k2II) / 2, (k1I - k2I) / 2, (k1II - k2II) / 2
    corrected = HI - HII + RI * np.cos(2 * s0) - RII * np.cos(2 * (s0 - sigma))
    printed = HI - HII + RII * np.cos(2 * s0) - RII * np.cos(2 * (s0 - sigma))
    np.testing.assert_allclose(corrected, direct, rtol=1e-12, atol=1e-15)
    assert np.max(np.abs(printed - direct)) > 0.1 * np.max(np.abs(direct))


def test_assembled_pair_refuses_bad_input_naming_the_argument():
    from gearrep.surfaces.catt import assemble, path_limits, solve_cycle

    design = {"z1": 21, "z2": 37, "module": 4.0, "R_T": 100.0, "face_width": 30.0}
    prm = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}
    with pytest.raises(ValueError, match="pair_id"):
        assemble(design, "C", prm)
    with pytest.raises(ValueError, match="design is missing the keys \\['R_T'\\]"):
        assemble({k: v for k, v in design.items() if k != "R_T"}, "A", prm)
    with pytest.raises(ValueError, match="prm is missing"):
        assemble(design, "A", {"pressure_angle_deg": 20.0})
    with pytest.raises(ValueError, match="mesh must be"):
        path_limits(design)
    mesh = assemble(design, "B", prm)
    lim = path_limits(mesh)
    assert lim["phi1_lo"] < 0 < lim["phi1_hi"] and 1 < lim["contact_ratio"] < 2
    with pytest.raises(ValueError, match="prm is missing"):
        solve_cycle(mesh, np.array([0.0]), {"tol": 1e-12, "maxiter": 50})
    cp = solve_cycle(mesh, np.array([0.0]), {"start_offset_mm": 2.0, "tol": 1e-12, "maxiter": 50})
    assert cp.converged.all() and abs(cp.position[0, 2]) < 1e-6  # the middle section at the pitch point


def test_catt_turn_over_is_a_half_turn_about_x():
    from gearrep.surfaces.catt import turn_over

    T = turn_over()
    np.testing.assert_array_equal(T @ np.array([1.0, 2.0, 3.0]), [1.0, -2.0, -3.0])
    np.testing.assert_allclose(T @ T, np.eye(3))
    assert np.linalg.det(T) == pytest.approx(1.0)  # a rotation, not a mirror
