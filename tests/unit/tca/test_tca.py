"""Tooth contact analysis of cylindrical pairs: conventional (thesis eq 26-32) and reduced (eq 33-44)
formulations, per-row Newton solves and the derivatives of the normal."""

import time

import numpy as np
import pytest
from _gear_pairs import ALPHA, C1, helical_pair, spur_pair
from _numerics import assert_rounding_close, assert_same_solve

from gearrep.solve import Status
from gearrep.surface import Surface
from gearrep.surfaces.involute import (
    InvoluteGearData,
    ParabolicCrowning,
    mating_flanks,
    standard_centre_distance,
)
from gearrep.tca import (
    ContactPoints,
    GearPair,
    Misalignment,
    default_start,
    newton_rows,
    normal_derivatives,
    reduced_unknowns,
    solve_contact,
    trace_path,
    transmission_error,
)
from gearrep.units import ARCMIN, ARCSEC

D = np.radians


def pitch_angle(pair, v1=0.0):
    """phi1 at which the transverse section v1 of member 1 is in contact at the pitch point: the tooth
    is centred on x, its flank crosses the pitch circle at +pi/(2 N1), and the helix turns the
    section by hand v1 tan(beta)/r_p."""
    f = pair.flank1
    return -np.pi / (2 * pair.n1) - float(f.twist(v1)[0])


PHI_SPUR = np.linspace(-0.12, 0.06, 13)  # inside the engagement interval of the 52/72 pair


# ---------------------------------------------------------------------------------------------
# aligned conjugate pairs: TE = 0, contact on the line / plane of action
# ---------------------------------------------------------------------------------------------
def test_aligned_spur_zero_te_on_line_of_action():
    pair, g1, g2 = spur_pair()
    P = np.array([g1.r_p, 0.0, 0.0])  # pitch point
    d = np.array([np.sin(ALPHA), np.cos(ALPHA), 0.0])  # line of action (outward normal of flank 1)
    for v1 in (-4.0, 0.0, 5.0):
        red = solve_contact(pair, PHI_SPUR, v1=v1)
        assert np.all(red.status == Status.CONVERGED)
        assert np.max(np.abs(red.te_arcsec)) < 1e-9
        rel = red.position - P
        assert np.max(np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0])) < 1e-10  # distance to the line
        assert np.max(np.abs(red.normal - d)) < 1e-12
        assert np.allclose(red.position[:, 2], v1, atol=1e-12) and np.allclose(red.v2, v1, atol=1e-12)
        conv = solve_contact(pair, PHI_SPUR, v1=v1, formulation="conventional")
        assert np.all(conv.status == Status.CONVERGED)
        assert np.max(np.abs(conv.te_arcsec)) < 1e-8  # residual tol 1e-12 mm -> ~1e-14 rad
        assert np.max(np.abs(conv.position - red.position)) < 1e-9
    # the roll relation of conjugate involutes: contact at roll length r_b1 (phi1 + pi/2N1) + r_p1 sin(a)
    s = np.sqrt(red.u1**2 - g1.r_b**2)
    assert np.allclose(s, g1.r_p * np.sin(ALPHA) + g1.r_b * (PHI_SPUR + np.pi / (2 * 52)), atol=1e-10)


def test_aligned_helical_zero_te_in_plane_of_action():
    pair, g1, g2 = helical_pair()
    at, bb = g1.alpha_t, g1.beta_b
    P = np.array([g1.r_p, 0.0, 0.0])
    m = np.array([np.cos(at), -np.sin(at), 0.0])  # normal of the plane of action
    for v1 in (-6.0, 0.0, 6.0):
        phi = pitch_angle(pair, v1) + np.linspace(-0.06, 0.03, 7)
        for form in ("reduced", "conventional"):
            c = solve_contact(pair, phi, v1=v1, formulation=form)
            ok = c.status == Status.CONVERGED
            assert np.all(ok)
            assert np.max(np.abs(c.te_arcsec[ok])) < (1e-9 if form == "reduced" else 1e-8)
            assert np.max(np.abs((c.position[ok] - P) @ m)) < 1e-10  # in the plane of action
            assert np.max(np.abs(c.normal[ok] @ m)) < 1e-12
            assert np.allclose(np.abs(c.normal[ok, 2]), np.sin(bb), atol=1e-12)  # tilted by beta_b


def test_asin_helix_form_is_not_conjugate_for_unequal_gears():
    """Correction 3 in action: with eq (5)/(58) the aligned 40/37 pair has no line contact."""
    pair, _, _ = helical_pair("asin")
    true_pair, _, _ = helical_pair("true")
    for v1 in (-8.0, 8.0):
        phi = pitch_angle(true_pair, v1) + np.array([-0.02, 0.0, 0.02])
        c = solve_contact(pair, phi, v1=v1)
        assert np.all(c.status != Status.CONVERGED)
        assert np.all(c.residual > 1e-5)  # normals cannot be made collinear in that section
        c = solve_contact(true_pair, phi, v1=v1)
        assert np.all(c.status == Status.CONVERGED)


def test_te_sign_convention_eq_14():
    """TE = (phi2 - phi20) - (N1/N2)(phi1 - phi10), phi2 in the driven sense: thinning either member's
    drive flank by c3 makes member 2 lag by exactly c3 / r_b2 (negative TE)."""
    c3 = 0.004
    for kw in (dict(thin1=c3), dict(thin2=c3)):
        pair, g1, g2 = spur_pair(**kw)
        c = solve_contact(pair, PHI_SPUR, v1=0.0)
        assert np.all(c.status == Status.CONVERGED)
        assert np.allclose(c.te, -c3 / g2.r_b, rtol=1e-11, atol=0)
    assert transmission_error(0.3, 0.3 * 52 / 72, 52, 72) == pytest.approx(0.0, abs=1e-16)
    assert transmission_error(0.3, 0.25, 52, 72, phi10=0.1, phi20=0.05) == pytest.approx(0.2 - 52 / 72 * 0.2)


def test_thesis_pitch_point_example():
    """Sec. 6.1: spur 25/25, m = 2.5, b = 25, a_p = 1e-4 1/mm: u1 = 31.103, u2 = 31.402,
    v1 = v2 = 12.5 (= mid-face, our v = 0). We find the angle at which u1 = 31.103 and check u2."""
    g = InvoluteGearData(25, 2.5, ALPHA, 25.0)
    f1, f2 = mating_flanks(g, g, crowning1=ParabolicCrowning(1e-4))
    pair = GearPair(f1, f2, 25, 25, standard_centre_distance(g, g))
    s1 = np.sqrt(31.103**2 - g.r_b**2)
    phi1 = -np.pi / 50 + (s1 - g.r_p * np.sin(ALPHA)) / g.r_b
    c = solve_contact(pair, phi1)
    assert c.status[0] == Status.CONVERGED
    assert c.u1[0] == pytest.approx(31.103, abs=1e-9)
    assert c.u2[0] == pytest.approx(31.402, abs=1.5e-3)  # printed to 3 decimals; u1 rounding propagates
    assert abs(c.v1[0]) < 1e-9 and abs(c.v2[0]) < 1e-9
    assert abs(c.te_arcsec[0]) < 1e-9


# ---------------------------------------------------------------------------------------------
# crowned pinion under a shaft-angle error: closed-form first-order estimate
# ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize("dg, rtol", [(1 * ARCMIN, 1e-5), (3 * ARCMIN, 3e-5), (6 * ARCMIN, 1e-4)])
def test_crowned_pinion_misalignment_closed_form(dg, rtol):
    """Closed-form estimate (leading order in the misalignment angle).

    Spur pair, pinion crowned delta(z) = c z^2 (material removed along the normal, z = axial
    coordinate from mid-face), gear unmodified; the outward normal of the pinion flank along the
    line of action is n = (sin a, cos a, 0). Misalignment rotates the gear about an axis through its
    centre O2 = (a, 0, 0). The gear flank is a cylinder along its axis, so what matters is its
    section by the plane z = const:

    * out-of-plane error dd (rotation about x_f, the centre line): a gear point (x, y0, z0) goes to
      y = y0 cos dd - z0 sin dd, z = y0 sin dd + z0 cos dd; at fixed z the section is the original
      profile shifted by -z tan dd in y and stretched by 1/cos dd in y. Along n this moves the gear
      flank by  g(z) = -z tan(dd) cos(a) + y (1/cos dd - 1) cos(a).
    * in-plane error dg (rotation about y_f): likewise at fixed z the section is shifted by
      z tan dg in x and stretched by 1/cos dg in x - a:  g(z) = z tan(dg) sin(a) - (a - x)(1/cos dg - 1) sin(a).

    The gap between the flanks along n at the nominal gear angle is c z^2 + g(z); turning the gear
    forward by dphi2 opens it by r_b2 dphi2 (involute). Contact is where the gap is smallest:
        z* = +tan(dd) cos(a) / (2c)            (out-of-plane)
        z* = -tan(dg) sin(a) / (2c)            (in-plane)
    and the gear must lead by minus that minimum gap, so (eq 14 sign: TE > 0 = gear leads)
        TE = [tan^2(dd) cos^2(a) / (4c) - y (1/cos dd - 1) cos(a)] / r_b2      (out-of-plane)
        TE = [tan^2(dg) sin^2(a) / (4c) + (a - x)(1/cos dg - 1) sin(a)] / r_b2  (in-plane)
    with (x, y) the contact point. The shift is O(dd) and the TE offset O(dd^2); the neglected terms
    are one order higher (tilt of the normals, crowning slope at z*), so the relative error should
    grow about linearly with the angle, which the tolerances reflect.
    """
    crown = ParabolicCrowning(C1)
    for kind in ("out-of-plane", "in-plane"):
        mis = Misalignment(d_gamma_out=dg) if kind == "out-of-plane" else Misalignment(d_gamma_in=dg)
        pair, g1, g2 = spur_pair(crown1=crown, mis=mis)
        a = pair.centre_distance
        c = solve_contact(pair, PHI_SPUR)
        assert np.all(c.status == Status.CONVERGED)
        x, y = c.position[:, 0], c.position[:, 1]
        if kind == "out-of-plane":
            z_cf = np.tan(dg) * np.cos(ALPHA) / (2 * C1)
            te_cf = (
                np.tan(dg) ** 2 * np.cos(ALPHA) ** 2 / (4 * C1) - y * (1 / np.cos(dg) - 1) * np.cos(ALPHA)
            ) / g2.r_b
        else:
            z_cf = -np.tan(dg) * np.sin(ALPHA) / (2 * C1)
            te_cf = (
                np.tan(dg) ** 2 * np.sin(ALPHA) ** 2 / (4 * C1) + (a - x) * (1 / np.cos(dg) - 1) * np.sin(ALPHA)
            ) / g2.r_b
        assert np.allclose(c.position[:, 2], z_cf, rtol=rtol, atol=0)
        assert np.allclose(c.v1, z_cf, rtol=rtol, atol=0)
        assert np.allclose(c.te, te_cf, rtol=rtol, atol=0)
        assert np.all(c.te > 0)
        if dg == 3 * ARCMIN:
            print(
                f"\n{kind} 3': shift {c.v1[6]:.6f} mm (closed form {z_cf:.6f}), "
                f"TE {c.te_arcsec[6]:.6f} arcsec (closed form {te_cf[6] / ARCSEC:.6f})"
            )


# ---------------------------------------------------------------------------------------------
# the two formulations agree; jacobians agree
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("case", ["spur", "helical"])
def test_conventional_and_reduced_agree(case):
    mis = Misalignment(d_gamma_in=D(0.05), d_gamma_out=-D(0.03), d_E=0.05, d_H=0.01, d_Z=0.2)
    if case == "spur":
        pair, _, _ = spur_pair(crown1=ParabolicCrowning(C1), mis=mis)
        phi = PHI_SPUR
    else:
        pair, _, _ = helical_pair(crown1=ParabolicCrowning(0.0227), mis=mis)
        phi = np.linspace(-0.05, 0.05, 9)
    red = solve_contact(pair, phi)
    conv = solve_contact(
        pair, phi, red.unknowns("conventional") + [0.3, -0.5, -0.3, 0.4, 0.01], formulation="conventional"
    )
    both = (red.status == Status.CONVERGED) & (conv.status == Status.CONVERGED)
    assert both.sum() >= len(phi) - 2
    assert np.max(np.abs(red.position[both] - conv.position[both])) < 1e-9
    for name in ("u1", "v1", "u2", "v2"):
        assert np.max(np.abs(getattr(red, name)[both] - getattr(conv, name)[both])) < 1e-9, name
    assert np.max(np.abs(red.phi2[both] - conv.phi2[both])) < 1e-10
    assert np.max(np.abs(red.normal[both] - conv.normal[both])) < 1e-10


def test_numeric_and_analytic_jacobians_find_the_same_root():
    pair, _, _ = spur_pair(crown1=ParabolicCrowning(C1), mis=Misalignment(d_gamma_in=D(0.1)))
    for form in ("reduced", "conventional"):
        a = solve_contact(pair, PHI_SPUR, formulation=form)
        n = solve_contact(pair, PHI_SPUR, formulation=form, jacobian="numeric")
        assert np.all(a.converged) and np.all(n.converged)
        assert np.max(np.abs(a.position - n.position)) < 1e-9
        assert np.max(np.abs(a.phi2 - n.phi2)) < 1e-11


# ---------------------------------------------------------------------------------------------
# robustness: bad starts are flagged, converged points are the true root
# ---------------------------------------------------------------------------------------------
def test_far_starts_are_flagged_not_silent():
    pair, g1, g2 = spur_pair(crown1=ParabolicCrowning(C1), mis=Misalignment(d_gamma_in=D(0.05)))
    f1 = pair.flank1
    ref = solve_contact(pair, 0.0)
    assert ref.status[0] == Status.CONVERGED
    far = np.array(
        [
            [3 * f1.u_max, 0.0],
            [f1.u_max, 60.0],
            [0.5 * g1.r_b, 0.0],
            [f1.u_min, -60.0],
            [1e3, 1e3],
            [-5.0, 0.0],
            [1e6, -1e6],
        ]
    )
    red = solve_contact(pair, 0.0, far)
    conv_start = np.column_stack([far, np.full(len(far), g2.r_p), np.zeros(len(far)), np.full(len(far), 2.0)])
    conv = solve_contact(pair, 0.0, conv_start, formulation="conventional")
    for c in (red, conv):
        ok = c.status == Status.CONVERGED
        # every point is either flagged or the verified root inside the flanks
        assert np.all(np.abs(c.u1[ok] - ref.u1[0]) < 1e-8) and np.all(np.abs(c.v1[ok] - ref.v1[0]) < 1e-8)
        assert np.sum(~ok) >= 4
        assert set(np.unique(c.status[~ok])) <= {
            Status.NOT_CONVERGED,
            Status.OFF_FLANK,
            Status.SINGULAR,
            Status.WRONG_ROOT,
            Status.DIVERGED,
        }
    # a position outside the engagement interval: the contact exists but off the flank
    for form in ("reduced", "conventional"):
        c = solve_contact(pair, [0.25, -0.3], formulation=form)
        assert np.all(c.status == Status.OFF_FLANK)


def test_random_starts_converge_only_to_the_true_root():
    """Protocol (cf. thesis Table 10): 2000 starts uniform over the flank of member 1 at phi1 = 0;
    conventional: u2, v2 at the middle of flank 2 and phi2 uniform in nominal +- 0.5 rad. A start
    counts as converged only if status CONVERGED (residual < 1e-12, inside both flanks, normals
    opposite); every such point must be the reference root."""
    pair, _, _ = spur_pair(crown1=ParabolicCrowning(C1), mis=Misalignment(d_gamma_in=D(0.05)))
    f1, f2 = pair.flank1, pair.flank2
    ref = solve_contact(pair, 0.0)
    rng = np.random.default_rng(3)
    n = 2000
    st = np.column_stack([rng.uniform(f1.u_min, f1.u_max, n), rng.uniform(f1.v_min, f1.v_max, n)])
    red = solve_contact(pair, 0.0, st)
    cst = np.column_stack([st, np.full(n, 0.5 * (f2.u_min + f2.u_max)), np.zeros(n), rng.uniform(-0.5, 0.5, n)])
    conv = solve_contact(pair, 0.0, cst, formulation="conventional")
    for c in (red, conv):
        ok = c.converged
        assert np.max(np.abs(c.u1[ok] - ref.u1[0])) < 1e-9 and np.max(np.abs(c.v1[ok] - ref.v1[0])) < 1e-9
        assert np.max(np.abs(c.phi2[ok] - ref.phi2[0])) < 1e-12
    print(
        f"\nconvergence from {n} random starts: reduced {red.converged.mean():.2%} "
        f"({red.iterations[red.converged].mean():.2f} it), conventional {conv.converged.mean():.2%} "
        f"({conv.iterations[conv.converged].mean():.2f} it)"
    )
    assert red.converged.mean() > 0.99


def test_choice_of_normal_components_decides_conditioning():
    """Conventional system, crowned spur pair (normal ~ (sin a, cos a, ~0)): keeping the x and y
    components of n1 + n2 (dropping the ~0 z component) leaves n_z fixed only through n_z^2, so the
    5x5 Jacobian is nearly singular and the sign-flipped false roots n1z = +n2z appear (flagged
    WRONG_ROOT). Dropping the largest component (default) is well conditioned."""
    from gearrep.tca._kernels import _conventional_FJ

    pair, _, _ = spur_pair(crown1=ParabolicCrowning(C1), mis=Misalignment(d_gamma_in=D(0.05)))
    ref = solve_contact(pair, 0.0)
    x = ref.unknowns("conventional")
    ratio = {}
    for d in (1, 2):
        s = np.linalg.svd(_conventional_FJ(pair, x, ref.phi1, np.array([d]))[1][0], compute_uv=False)
        ratio[d] = s[-1] / s[0]
    assert ratio[1] > 1e-5 and ratio[2] < 1e-7
    rng = np.random.default_rng(0)
    st = default_start(pair, np.zeros(200), "conventional") + rng.normal(0, [0.5, 1.0, 0.5, 1.0, 0.02], (200, 5))
    auto = solve_contact(pair, 0.0, st, formulation="conventional")
    xy = solve_contact(pair, 0.0, st, formulation="conventional", drop=2)
    assert np.all(auto.converged)
    assert np.sum(xy.status == Status.WRONG_ROOT) > 10
    ok = xy.converged
    assert np.max(np.abs(xy.v1[ok] - ref.v1[0])) < 1e-6  # the rest is right, but less accurate
    # eq (27) as printed: the raw normals r_u x r_v of two alike-parameterised flanks are opposite at
    # the contact, so n1 - n2 = 0 has no solution there; with outward normals n1 + n2 = 0 holds
    P1 = pair.flank1.evaluate(ref.u1, ref.v1)
    P2 = pair.flank2.evaluate(ref.u2, ref.v2)
    raw1 = np.einsum("nij,nj->ni", pair.R1(ref.phi1), P1.normal)
    raw2 = np.einsum("nij,nj->ni", pair.R2(ref.phi2), P2.normal)
    assert np.allclose(raw1 + raw2, 0, atol=1e-12) and np.linalg.norm(raw1 - raw2) > 1.99


def test_line_contact_needs_fixed_v1():
    """Conjugate (unmodified, aligned) pair with v1 free: the contact is not isolated; the solver
    reports it (SINGULAR / NOT_CONVERGED) instead of returning an arbitrary point."""
    pair, _, _ = spur_pair()
    c = solve_contact(pair, PHI_SPUR)
    assert np.all(c.status != Status.CONVERGED)


# ---------------------------------------------------------------------------------------------
# the reduced formulation's explicit relations (eq 37-44)
# ---------------------------------------------------------------------------------------------
def test_reduced_explicit_relations_and_phi2_sign_rule():
    mis = Misalignment(d_gamma_in=D(0.1), d_gamma_out=D(0.07), d_E=0.1, d_Z=0.3)
    pair, _, _ = helical_pair(crown1=ParabolicCrowning(0.01), mis=mis)
    f1 = pair.flank1
    rng = np.random.default_rng(7)
    u1 = rng.uniform(f1.u_min + 0.1, f1.u_max, 200)
    v1 = rng.uniform(-8, 8, 200)
    phi1 = rng.uniform(-0.3, 0.3, 200)
    u2, v2, phi2 = reduced_unknowns(pair, u1, v1, phi1)
    r1, _ = pair.member1(u1, v1, phi1)
    r2, _ = pair.member2(u2, v2, phi2)
    assert np.max(np.abs(r1 - r2)) < 1e-12  # eq (38): a common point by construction
    # eq (41)-(44) with the sign rule: phi2 = sign((p2 x q2) . w2) acos(p2 . q2 / |q2|^2), evaluated
    # in member 2's axis frame (w2 = -z there)
    f2 = pair.flank2
    from gearrep.frames import rot_z

    p = np.einsum("ij,nj->ni", rot_z(pair.phase2), f2.position(u2, v2))
    q = (r1 - pair.O2) @ pair.A2  # A2^T (r - O2)
    p[:, 2] = q[:, 2] = 0.0
    w = np.array([0.0, 0.0, -1.0])
    sign = np.sign(np.cross(p, q) @ w)
    eq43 = sign * np.arccos(np.clip(np.sum(p * q, axis=1) / np.sum(q * q, axis=1), -1, 1))
    diff = (eq43 - phi2 + np.pi) % (2 * np.pi) - np.pi
    assert np.max(np.abs(diff)) < 1e-7  # acos is only good to ~sqrt(eps)
    # the acos form cannot resolve a small angle: cos(1e-9) == 1 in double precision
    assert np.arccos(np.cos(1e-9)) == 0.0 and np.arctan2(np.sin(1e-9), np.cos(1e-9)) == pytest.approx(1e-9)


def test_trace_path_by_continuation():
    pair, _, _ = spur_pair(crown1=ParabolicCrowning(C1), mis=Misalignment(d_gamma_out=D(0.05)))
    phi = np.linspace(-0.13, 0.07, 41)
    path = trace_path(pair, phi)
    assert np.all(path.status == Status.CONVERGED)
    assert np.all(np.diff(path.u1) > 0)  # contact climbs the pinion flank
    assert np.mean(path.iterations) <= 3.0
    same = solve_contact(pair, phi)
    assert np.max(np.abs(same.position - path.position)) < 1e-9
    conv = trace_path(pair, phi, default_start(pair, phi[:1], "conventional")[0], formulation="conventional")
    assert np.all(conv.converged) and np.max(np.abs(conv.position - path.position)) < 1e-9


# ---------------------------------------------------------------------------------------------
# performance
# ---------------------------------------------------------------------------------------------
def test_10000_aligned_spur_solves():
    pair, _, _ = spur_pair()
    rng = np.random.default_rng(0)
    phi = rng.uniform(-0.12, 0.06, 10_000)
    v1 = rng.uniform(-5.0, 5.0, 10_000)
    c = solve_contact(pair, phi, v1=v1)
    assert np.all(c.status == Status.CONVERGED) and np.max(np.abs(c.te_arcsec)) < 1e-9


@pytest.mark.bench
def test_performance_10000_aligned_spur_solves():
    """Timed (bench marker, not in the default run): 10,000 reduced solves in under a second."""
    pair, _, _ = spur_pair()
    rng = np.random.default_rng(0)
    phi = rng.uniform(-0.12, 0.06, 10_000)
    v1 = rng.uniform(-5.0, 5.0, 10_000)
    solve_contact(pair, phi[:100], v1=v1[:100])  # warm-up
    best = np.inf
    for _ in range(3):
        t0 = time.perf_counter()
        c = solve_contact(pair, phi, v1=v1)
        best = min(best, time.perf_counter() - t0)
    assert np.all(c.status == Status.CONVERGED)
    print(
        f"\n10,000 aligned spur contact solves (reduced, analytic Jacobian): {best:.3f} s "
        f"({c.iterations.mean():.2f} iterations on average)"
    )
    assert best < 1.0


@pytest.mark.bench
@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_throughput_in_reference_kernel_elements(formulation):
    """Throughput targets on the README pair (crowned 52/72 spur, 0.05 deg out-of-plane), in elements
    of the reference kernel timed in the same run (gearrep.benchmark): at most 6 (reduced) or 12
    (conventional) per vectorised solve and 1000 per single-point call; fails above 1.5 x target."""
    from gearrep import benchmark

    pair, _, _ = spur_pair(crown1=ParabolicCrowning(0.002857), mis=Misalignment(d_gamma_out=D(0.05)))
    rng = np.random.default_rng(7)
    phi = -np.pi / 104 + rng.uniform(-0.4, 0.4, 20_000) * 2 * np.pi / 52
    r = benchmark.tca_throughput(pair, phi, default_start(pair, phi, formulation), formulation=formulation, n_single=50)
    assert r["converged_fraction_vectorised"] == 1.0 and r["converged_fraction_single"] == 1.0
    print(
        f"\n{formulation}: {r['vectorised_elements_per_solve']:.1f} reference elements per solve, "
        f"{r['single_elements_per_call']:.0f} per single-point call "
        f"(load {r['load_1min_before']:.1f}-{r['load_1min_after']:.1f})"
    )
    targets = benchmark.THROUGHPUT_TARGETS
    assert r["vectorised_elements_per_solve"] <= 1.5 * targets[formulation]
    assert r["single_elements_per_call"] <= 1.5 * targets["single"]


# ---------------------------------------------------------------------------------------------
# validation
# ---------------------------------------------------------------------------------------------
@pytest.mark.numerics
@pytest.mark.parametrize("fixed", [False, True])
@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_one_point_solve_gives_its_batch_row(formulation, fixed):
    """A solve of one point (its kernel, Newton steps and contact record on Python floats) returns
    what the same point gets in a batch (numpy arrays): the same status, dtypes and, where it
    converged, every field within the solver's accuracy (tests/_numerics.py: the two paths round
    differently, by machine), for converging, wrong-root, non-converging and singular starts on a
    crowned misaligned spur pair and a helical pair."""
    rng = np.random.default_rng(3)
    pairs = [
        spur_pair(crown1=ParabolicCrowning(0.002857), mis=Misalignment(d_gamma_out=D(0.05)))[0],
        helical_pair()[0],
    ]
    fields = [*ContactPoints.ARRAYS, "condition"]
    statuses = set()
    for pair in pairs:
        phi = -np.pi / 104 + rng.uniform(-0.6, 0.6, 60) * 2 * np.pi / 52
        start = default_start(pair, phi, formulation) + rng.normal(0.0, 0.3, (60, 2 if formulation == "reduced" else 5))
        v1 = rng.uniform(-3.0, 3.0, 60) if fixed else None
        kw = dict(formulation=formulation, phi10=0.01, phi20=-0.002)
        batch = solve_contact(pair, phi, start, v1=v1, **kw)
        statuses |= set(batch.status.tolist())
        for i in range(len(phi)):
            one = solve_contact(pair, phi[i : i + 1], start[i : i + 1], v1=None if v1 is None else v1[i : i + 1], **kw)
            for f in fields:
                assert np.asarray(getattr(one, f)[0]).dtype == np.asarray(getattr(batch, f)[i]).dtype, (i, f)
            assert_same_solve(one, batch, 1e-12, fields, [0], [i], what=f"point {i}")
    assert len(statuses) >= 2  # more than one outcome is exercised


@pytest.mark.numerics
@pytest.mark.parametrize("v_column", [True, False])
def test_a_lazy_jacobian_of_the_kernels_equals_the_eager_one(v_column):
    """The kernels' lazy Jacobians (a row's last evaluation forms none) give bit for bit the eager
    Jacobians (the same operations on the same numbers), for every row, a subset of rows and one
    point on floats, reduced and conventional, with the same residuals; the one point on floats
    (Python's math) gives its row of the arrays (numpy's kernels) within rounding."""
    from gearrep.tca._kernels import _conventional_FJ3, _reduced_FJ3

    rng = np.random.default_rng(5)
    pair = helical_pair()[0]
    n = 200
    phi = -np.pi / 104 + rng.uniform(-0.6, 0.6, n) * 2 * np.pi / 52
    x = default_start(pair, phi, "conventional") + rng.normal(0.0, 0.2, (n, 5))
    c1, s1 = np.cos(phi), np.sin(phi)
    drop = rng.integers(0, 3, n)
    first0, last2 = drop == 0, drop == 2
    rows = np.sort(rng.choice(n, 37, replace=False))
    cols = (0, 1, 2, 3, 4) if v_column else (0, 2, 3, 4)

    def red(derivs, i=None):
        if i is None:
            return _reduced_FJ3(pair, x[:, 0], x[:, 1], phi, c1, s1, first0, last2, derivs, v_column)[:2]
        f = [float(a) for a in (x[i, 0], x[i, 1], phi[i], c1[i], s1[i])]
        return _reduced_FJ3(pair, *f, bool(first0[i]), bool(last2[i]), derivs, v_column, lists=True)[:2]

    def conv(derivs, i=None):
        if i is None:
            return _conventional_FJ3(pair, tuple(x.T), c1, s1, 5, first0, last2, cols, derivs)
        x5 = x[i].tolist()
        fl = (float(c1[i]), float(s1[i]), 5, bool(first0[i]), bool(last2[i]))
        return _conventional_FJ3(pair, x5, *fl, cols, derivs, lists=True)

    with np.errstate(invalid="ignore", divide="ignore"):
        for kernel in (red, conv):
            F, J = kernel(True)
            Fl, Jl = kernel("lazy")
            np.testing.assert_array_equal(F, Fl)
            np.testing.assert_array_equal(Jl(), J)
            np.testing.assert_array_equal(kernel("lazy")[1](rows), J[rows])
            for i in (0, 17):
                F1, J1 = kernel(True, i)
                F1l, J1l = kernel("lazy", i)
                assert F1 == F1l and J1l() == J1
                assert_rounding_close(np.array(J1), J[i], ulps=256, err_msg=f"row {i}: floats against arrays")


@pytest.mark.numerics
@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_a_large_batch_solved_in_blocks_gives_the_same_points(formulation, monkeypatch):
    """A batch above the block size is solved in equal blocks (arrays that fit a core's cache) with
    the statuses of one batch and, where converged, every field within the solver's accuracy (the
    same kernels on arrays of other lengths: SIMD loops may round a row differently by its place):
    random starts (several statuses), a fixed v1, an explicit dropped component."""
    import gearrep.tca._formulations as tf

    pair = helical_pair()[0]
    rng = np.random.default_rng(9)
    n = 901
    phi = -np.pi / 104 + rng.uniform(-0.6, 0.6, n) * 2 * np.pi / 52
    start = default_start(pair, phi, formulation) + rng.normal(0.0, 0.3, (n, 2 if formulation == "reduced" else 5))
    fields = [*ContactPoints.ARRAYS, "condition"]
    statuses = set()
    for kw in ({}, {"v1": rng.uniform(-3.0, 3.0, n)}, {"drop": 0, "phi10": 0.01}):
        kw["maxiter"] = 12
        whole = solve_contact(pair, phi, start, formulation=formulation, **kw)
        monkeypatch.setattr(tf, "_BLOCK_ROWS", 300)
        blocks = solve_contact(pair, phi, start, formulation=formulation, **kw)
        monkeypatch.setattr(tf, "_BLOCK_ROWS", 20_000)
        assert_same_solve(blocks, whole, 1e-12, fields, what=str(kw))
        statuses |= set(whole.status.tolist())
    assert len(statuses) >= 2


@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_the_flank_evaluation_that_picks_the_dropped_component_is_the_first_iterates(formulation, monkeypatch):
    """Member 1's flank evaluated at the starts to pick the dropped component serves the
    solve's first evaluation: a solve that picks it evaluates the flank as often as one given the
    same component, with every field equal bit for bit (free and fixed v1); the evaluation is
    handed out once, and only for exactly the starts' (u1, v1)."""
    from gearrep.tca._formulations import _Rows

    pair = spur_pair(crown1=ParabolicCrowning(0.002857), mis=Misalignment(d_gamma_out=D(0.05)))[0]
    phi = np.linspace(-0.05, 0.05, 400)
    start = default_start(pair, phi, formulation)
    start[::5] += 0.3
    flank = pair.flank1
    calls = []

    def counted(u, v, evaluate=flank.evaluate_components):
        calls.append(np.size(u))
        return evaluate(u, v)

    monkeypatch.setattr(flank, "evaluate_components", counted)
    for kw in ({}, {"v1": start[:, 1] - 0.2}):
        calls[:] = []
        picked = solve_contact(pair, phi, start, formulation=formulation, **kw)
        n_picked, calls[:] = len(calls), []
        given = solve_contact(pair, phi, start, formulation=formulation, drop=1, **kw)  # the spur pair's pick
        assert n_picked == len(calls) > 2
        for f in [*ContactPoints.ARRAYS, "condition"]:
            np.testing.assert_array_equal(getattr(picked, f), getattr(given, f), err_msg=f)
    u, v = np.array([1.0, 2.0]), np.array([3.0, 4.0])

    def rows():
        return _Rows(phi[:2], phi[:2], phi[:2], np.ones(2), np.full(2, np.nan), (u, v, "P"))

    r = rows()
    assert r.start_flank1(u.copy(), v.copy()) == "P" and r.start_flank1(u, v) is None  # once
    assert rows().start_flank1(u, v + 1e-15) is None and rows().start_flank1(u[:1], v[:1]) is None


@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_a_solve_leaves_no_reference_cycle(formulation):
    """A contact solve (batch and one point) frees its evaluations by reference counting: no
    reference cycle (a lazy Jacobian referring to the dict that holds it, say) keeps the kernel's
    arrays alive until the cyclic garbage collector runs."""
    import gc

    pair = spur_pair(crown1=ParabolicCrowning(0.002857), mis=Misalignment(d_gamma_out=D(0.05)))[0]
    phi = np.linspace(-0.05, 0.05, 300)
    start = default_start(pair, phi, formulation)
    start[::7] += 0.4  # rows converging at different steps, some by a shortened step
    solve_contact(pair, phi, start, formulation=formulation)
    gc.collect()
    gc.disable()
    try:
        solve_contact(pair, phi, start, formulation=formulation)
        solve_contact(pair, phi[:1], start[:1], formulation=formulation)
        assert gc.collect() == 0
    finally:
        gc.enable()


def test_the_dropped_component_is_the_first_largest_of_the_normal():
    """The default dropped component per row is argmax |n_f1| (the first on ties; 0 where the
    normal is not finite), as the stacked array computes it."""
    from gearrep.surface import cross3, dot3
    from gearrep.tca._formulations import _largest_normal_component

    pair = helical_pair()[0]
    rng = np.random.default_rng(2)
    n = 500
    u1 = rng.uniform(pair.flank1.u_min, pair.flank1.u_max, n)
    v1 = rng.uniform(pair.flank1.v_min, pair.flank1.v_max, n)
    u1[:5] = np.nan
    phi = rng.uniform(-np.pi, np.pi, n)
    phi[10:60] = np.round(phi[10:60] / (np.pi / 2)) * (np.pi / 2)  # normals along axes: ties of zeros
    c1, s1 = np.cos(phi), np.sin(phi)
    with np.errstate(invalid="ignore"):
        P = pair.flank1.evaluate_components(u1, v1)
        N0, N1, N2 = cross3(P[1], P[2])
        N = (c1 * N0 - s1 * N1, s1 * N0 + c1 * N1, np.broadcast_to(N2, u1.shape))
        L = np.sqrt(dot3(N, N))
        a = np.abs(np.stack([np.broadcast_to(x / L, (n,)) for x in N], axis=-1))
    expected = np.argmax(np.nan_to_num(a, nan=0.0), axis=-1).astype(float)
    got = _largest_normal_component(pair, u1, v1, c1, s1)
    np.testing.assert_array_equal(got, expected)
    assert set(got[:5]) == {0.0} and len(set(got)) >= 2
    for i in (7, 20):
        np.testing.assert_array_equal(
            _largest_normal_component(pair, u1[i : i + 1], v1[i : i + 1], c1[i : i + 1], s1[i : i + 1]), expected[i]
        )


def test_input_validation():
    pair, g1, g2 = spur_pair()
    with pytest.raises(ValueError, match="formulation"):
        solve_contact(pair, 0.0, formulation="litvin")
    with pytest.raises(ValueError, match="start"):
        solve_contact(pair, 0.0, np.zeros((1, 3)))
    with pytest.raises(ValueError, match="phi1"):
        solve_contact(pair, np.nan)
    with pytest.raises(ValueError, match="jacobian"):
        solve_contact(pair, 0.0, jacobian="exact")
    with pytest.raises(ValueError, match="centre_distance"):
        GearPair(pair.flank1, pair.flank2, 52, 72, -1.0)
    with pytest.raises(ValueError, match="n1"):
        GearPair(pair.flank1, pair.flank2, 0, 72, 62.0)
    with pytest.raises(ValueError, match="d_gamma_in"):
        Misalignment(d_gamma_in=1.0)
    with pytest.raises(ValueError, match="n2"):
        transmission_error(0.0, 0.0, 52, 0)

    class Plane(Surface):
        def position(self, u, v):
            u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
            return np.stack([u, v, np.zeros_like(u)], axis=-1)

    with pytest.raises(ValueError, match="cylindrical"):
        solve_contact(GearPair(pair.flank1, Plane(), 52, 72, 62.0), 0.0)


def test_contact_curvatures_and_ellipse_of_a_crowned_spur_pair():
    """Aligned 52/72 pair, pinion crowned delta = c1 v^2 (a normal offset): at every contact point
    (v1 = 0) the relative curvature is 1/rho1 + 1/rho2 across the profile (involute radii of
    curvature rho = sqrt(u^2 - r_b^2)) and 2 c1 along the face, so a = sqrt(2 delta / (2 c1)) along
    z and b = sqrt(2 delta / (1/rho1 + 1/rho2))."""
    from gearrep.curvature import relative_curvature
    from gearrep.tca import contact_curvatures, contact_ellipse

    pair, g1, g2 = spur_pair(crown1=ParabolicCrowning(C1))
    c = solve_contact(pair, np.linspace(-0.1, 0.05, 7))
    assert np.all(c.converged) and np.allclose(c.v1, 0.0, atol=1e-9)
    p1, p2 = contact_curvatures(pair, c)
    np.testing.assert_allclose(p1.normal, c.normal, atol=1e-12)
    np.testing.assert_allclose(p2.normal, c.normal, atol=1e-9)
    rel = relative_curvature(p1, p2)
    rho1, rho2 = np.sqrt(c.u1**2 - g1.r_b**2), np.sqrt(c.u2**2 - g2.r_b**2)
    k_profile = 1 / rho1 + 1 / rho2
    np.testing.assert_allclose(
        np.sort(np.abs([rel.k1, rel.k2]), axis=0), np.sort([np.full(7, 2 * C1), k_profile], axis=0), rtol=1e-7
    )
    delta = 0.00632
    el = contact_ellipse(pair, c, delta)
    assert np.all(el.elliptic)
    assert np.all(rel.k1 < 0) and np.all(rel.k2 < 0)  # convex on convex, seen from member 1 (outward normal)
    np.testing.assert_allclose(el.a, np.sqrt(2 * delta / (2 * C1)), rtol=1e-7)
    np.testing.assert_allclose(el.b, np.sqrt(2 * delta / k_profile), rtol=1e-7)
    np.testing.assert_allclose(np.abs(el.major_axis[:, 2]), 1.0, atol=1e-9)  # along the face
    bad = solve_contact(pair, [0.3])  # off the flank: not converged -> NaN, not a number
    assert not bad.converged[0] and np.isnan(contact_ellipse(pair, bad, delta).a[0])


def test_contact_hertz_of_a_crowned_spur_pair_against_closed_form():
    """Hertz at the contact points of the crowned 52/72 pair (relative curvatures 2 c1 along the face
    and 1/rho1 + 1/rho2 across, see above): a, b, p_max equal gearrep.ellipse.hertz_contact of those
    closed-form curvatures, and p_max = 3 P / (2 pi a b)."""
    from gearrep.ellipse import hertz_contact, hertz_max_pressure_MPa
    from gearrep.tca import contact_hertz

    pair, g1, g2 = spur_pair(crown1=ParabolicCrowning(C1))
    c = solve_contact(pair, np.linspace(-0.1, 0.05, 5))
    h = contact_hertz(pair, c, 200.0, 206e3, 0.3)
    rho1, rho2 = np.sqrt(c.u1**2 - g1.r_b**2), np.sqrt(c.u2**2 - g2.r_b**2)
    ref = hertz_contact(2 * C1, 1 / rho1 + 1 / rho2, 200.0, 206e3, 0.3)
    assert np.all(h.status == Status.CONVERGED)
    for f in ("a", "b", "p0"):
        np.testing.assert_allclose(getattr(h, f), getattr(ref, f), rtol=1e-6)
    np.testing.assert_allclose(h.p0, hertz_max_pressure_MPa(200.0, h.a, h.b), rtol=1e-14)
    both = solve_contact(pair, [0.0, 0.3])  # second row off the flank: NaN, its own status kept
    hb = contact_hertz(pair, both, 200.0, 206e3, 0.3)
    assert np.isfinite(hb.p0[0]) and np.isnan(hb.p0[1]) and hb.status[1] == both.status[1] != Status.CONVERGED
    line = solve_contact(spur_pair()[0], [0.0], v1=[0.0])  # unmodified: line contact, no ellipse
    hl = contact_hertz(spur_pair()[0], line, 200.0, 206e3, 0.3)
    assert line.converged[0] and np.isnan(hl.p0[0]) and hl.status[0] == Status.SINGULAR


# ---------------------------------------------------------------------------------------------
# start strategies and solver variants (gearrep.tca, used by the seed-003 convergence studies)
# ---------------------------------------------------------------------------------------------
def test_solver_variants_agree_from_seeded_and_robust_starts():
    """From starts near a crowned spur pair's contact, every variant of both formulations that does
    not need a phi2 guess finds the same contact; six equations (least squares) agree with five."""
    from gearrep.tca import (
        CONVENTIONAL_VARIANTS,
        REDUCED_VARIANTS,
        draw_starts,
        seed_from_reduced,
        solve_conventional,
        solve_variant,
    )

    pair, _, _ = spur_pair(crown1=ParabolicCrowning(C1))
    ref = solve_contact(pair, 0.01)
    x_ref = ref.unknowns("conventional")[0]
    starts = draw_starts(pair, 20, np.random.default_rng(3), phi2_window=(x_ref[4] - 0.01, x_ref[4] + 0.01))
    starts[:, 0] = x_ref[0] + 0.05 * (starts[:, 0] - x_ref[0])
    starts[:, 1] = 0.2 * starts[:, 1]
    drop = int(np.argmax(np.abs(ref.normal[0])))
    for v in ("seeded", "robust") + REDUCED_VARIANTS:
        assert v in CONVENTIONAL_VARIANTS + REDUCED_VARIANTS
        x, status, _ = solve_variant(pair, 0.01, starts, v, drop=drop)
        assert np.all(status == Status.CONVERGED), v
        assert np.max(np.abs(x[:, :4] - x_ref[:4])) < 1e-8, v
    six = solve_conventional(pair, 0.01, seed_from_reduced(pair, 0.01, starts[:, 0], starts[:, 1]), equations="six")
    assert np.all(six.status == Status.CONVERGED) and np.max(np.abs(six.x[:, :4] - x_ref[:4])) < 1e-8
    with pytest.raises(ValueError, match="variant"):
        solve_conventional(pair, 0.01, starts, variant="newton")
    with pytest.raises(ValueError, match="equations"):
        solve_conventional(pair, 0.01, starts, equations="four")


def test_newton_rows_solves_each_row_with_its_own_data():
    # x^2 = p0, y = p1 x: roots (sqrt(p0), p1 sqrt(p0)) from positive starts
    p = np.array([[4.0, 1.0], [9.0, -2.0], [2.0, 0.5]])

    def F(x, q):
        return np.column_stack([x[:, 0] ** 2 - q[:, 0], x[:, 1] - q[:, 1] * x[:, 0]])

    def FJ(x, q):
        J = np.zeros((len(x), 2, 2))
        J[:, 0, 0] = 2 * x[:, 0]
        J[:, 1, 0] = -q[:, 1]
        J[:, 1, 1] = 1.0
        return F(x, q), J

    exact = np.column_stack([np.sqrt(p[:, 0]), p[:, 1] * np.sqrt(p[:, 0])])
    for jac in ("analytic", "numeric"):
        res = newton_rows(F, FJ, np.ones((3, 2)), p, jacobian=jac, tol=1e-12)
        assert np.all(res.converged), jac
        np.testing.assert_allclose(res.x, exact, rtol=1e-10)
        assert np.all(res.residual < 1e-12) and np.all(res.iterations >= 1)
    with pytest.raises(ValueError, match="params has 2 rows for 3 starts"):
        newton_rows(F, FJ, np.ones((3, 2)), p[:2])
    with pytest.raises(ValueError, match="jacobian must be"):
        newton_rows(F, FJ, np.ones((3, 2)), p, jacobian="complex")


def test_normal_derivatives_match_finite_differences():
    from gearrep.surfaces.analytic import Torus

    surf = Torus(c=5.0, a=1.5)
    u, v = np.array([0.3, 1.2]), np.array([0.7, -2.0])
    n, n_u, n_v = normal_derivatives(surf.evaluate(u, v), -1)
    h = 1e-6
    for d, (du, dv) in ((n_u, (h, 0.0)), (n_v, (0.0, h))):
        plus = surf.evaluate(u + du, v + dv).normal
        minus = surf.evaluate(u - du, v - dv).normal
        np.testing.assert_allclose(d, -(plus - minus) / (2 * h), atol=1e-8)
    np.testing.assert_allclose(n, -surf.evaluate(u, v).normal, atol=1e-15)
