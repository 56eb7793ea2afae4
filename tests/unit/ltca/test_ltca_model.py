"""Loaded tooth contact analysis (gearrep.ltca): closed forms (ISO 6336, Hertz, Weber), the contact
solver's optimality conditions, edge contact, the coupling of the nodes, load balance, symmetry,
grid convergence, the unloaded and rigid-tooth limits, families."""

import itertools

import numpy as np
import pytest
from _gear_pairs import C1, helical_pair, spur_pair

from gearrep.ellipse import effective_modulus
from gearrep.ltca import (
    STEEL,
    SUPPORTED,
    Material,
    ToothCompliance,
    cantilever_plate_ratio,
    cycle_positions,
    half_space_segment_mm2_per_N,
    initial_separations,
    iso,
    loaded_contact,
    plate_kernel,
    solve_contact_loads,
    weber_contact_approach_mm,
)
from gearrep.ltca._compliance import HERTZ_STRIP_OFFSET, contact_half_width_mm
from gearrep.ltca._families import RACK_TIP_RADIUS, rack_fillet_half_angle
from gearrep.replications.ltca.checks import PRESSURE_RTOL
from gearrep.solve import Status
from gearrep.surfaces.catt import assemble
from gearrep.surfaces.involute import ParabolicCrowning, mating_flanks, standard_centre_distance
from gearrep.tca import GearPair, Misalignment, contact_hertz, solve_contact

SEC4 = dict(z1=19, z2=31, module=8.0, R_T=500.0, face_width=80.0)
TOOL = dict(pressure_angle_deg=20.0, addendum=1.0, clearance=0.25)


def crowned_misaligned_pair():
    """Thesis sec. 6.2 pair with the crowned pinion and a 3 arc-min out-of-plane shaft error."""
    return spur_pair(crown1=ParabolicCrowning(C1), mis=Misalignment(d_gamma_out=np.radians(3 / 60)))


def pitch(pair):
    return cycle_positions(pair, 3)[[1]]


# ---------------------------------------------------------------------------------------------
# closed forms
# ---------------------------------------------------------------------------------------------
def test_iso_factors_printed_values():
    """ISO 6336-2 prints Z_E = 189.8 sqrt(MPa) for steel on steel (checked to its printed precision);
    Z_H = sqrt(2 / (sin(a) cos(a))) = 2.4946 for alpha = 20 deg, beta = 0, x = 0."""
    assert iso.elasticity_factor(206000.0, 0.3) == pytest.approx(189.8, abs=0.05)
    a = np.radians(20.0)
    assert iso.zone_factor(a) == pytest.approx(np.sqrt(2.0 / (np.sin(a) * np.cos(a))), rel=1e-14)
    assert iso.q_prime(20, 40) == pytest.approx(0.04723 + 0.15551 / 20 + 0.25791 / 40, rel=1e-15)
    with pytest.raises(ValueError, match="z_n1"):
        iso.q_prime(0, 40)


def test_half_space_kernel_over_a_line_is_webers_approach():
    """Boussinesq's displacement relative to depth h, integrated over an infinite line with the Hertz
    strip's lateral offset (b/2) exp(-1/2), is Weber's line-contact approach to O((b/h)^2)."""
    w, k, h1, h2 = 100.0, 0.05, 2.0, 3.0
    Es = float(effective_modulus(206000.0, 0.3, 206000.0, 0.3))
    b = float(contact_half_width_mm(w, k, Es))
    X = 1e6
    kern = w * sum(half_space_segment_mm2_per_N(-X, X, HERTZ_STRIP_OFFSET * b, h, STEEL) for h in (h1, h2))
    weber = float(weber_contact_approach_mm(w, k, h1, h2, STEEL, STEEL))
    assert kern == pytest.approx(weber, rel=(b / min(h1, h2)) ** 2)


def test_cantilever_plate_ratio_limits():
    """R(0) = 1 (the beam), R ~ 6 / ((1 - nu)(3 + nu) q^3) for large q (a semi-infinite plate's free
    edge, derived in the docstring), decreasing; the kernel P is odd with P(inf) = 1/2."""
    nu = 0.3
    q = np.array([1e-6, 0.5, 1.0, 2.0, 5.0, 40.0])
    R = cantilever_plate_ratio(q, nu)
    assert R[0] == pytest.approx(1.0, abs=1e-9) and np.all(np.diff(R) < 0)
    assert R[-1] == pytest.approx(6.0 / ((1 - nu) * (3 + nu) * 40.0**3), rel=1e-3)
    u = np.array([0.3, 1.0, 3.0, 30.0])
    P = plate_kernel(u, nu)
    assert np.allclose(plate_kernel(-u, nu), -P, rtol=0, atol=0)
    assert np.all(np.diff(P) > 0) and P[-1] == 0.5 and P[-2] == pytest.approx(0.5, abs=1e-2)


# ---------------------------------------------------------------------------------------------
# the contact solver
# ---------------------------------------------------------------------------------------------
def _brute_force(C, s, h, M):
    """The QP's solution by enumerating working sets (the one whose loads are >= 0 and gaps >= 0)."""
    n = s.size
    for k in range(1, n + 1):
        for P in itertools.combinations(range(n), k):
            P = list(P)
            A = np.zeros((k + 1, k + 1))
            A[:k, :k] = C[np.ix_(P, P)]
            A[:k, k] = -h[P]
            A[k, :k] = h[P]
            x = np.linalg.solve(A, np.concatenate([-s[P], [M]]))
            F = np.zeros(n)
            F[P] = x[:k]
            gaps = s + C @ F - x[k] * h
            if np.all(x[:k] >= 0) and np.all(gaps >= -1e-12):
                return F, x[k]
    raise AssertionError("no solution found")


def test_active_set_solver_optimality_and_brute_force():
    rng = np.random.default_rng(7)
    for _ in range(25):
        n = int(rng.integers(2, 8))
        B = rng.normal(size=(n, n))
        C = B @ B.T / n + np.diag(rng.uniform(0.5, 2.0, n))  # symmetric positive definite
        s = rng.uniform(0.0, 2.0, n) * (rng.uniform(size=n) < 0.7)
        h = rng.uniform(0.5, 2.0, n)
        M = float(rng.uniform(0.5, 5.0))
        sol = solve_contact_loads(C, s, h, M)
        assert sol.status == Status.CONVERGED
        F = sol.loads_N
        # KKT: loads >= 0, gaps >= 0, complementarity, balance; scale-relative tolerances of a
        # well-conditioned dense solve (condition numbers here < 1e3)
        scale = max(np.max(np.abs(s)), np.max(C) * M / np.min(h))
        assert np.all(F >= 0)
        assert np.all(sol.gaps_mm >= -1e-11 * scale)
        assert np.max(np.abs(F * sol.gaps_mm)) <= 1e-10 * scale * M / np.min(h)
        assert abs(h @ F - M) <= 1e-12 * M
        Fb, tb = _brute_force(C, s, h, M)
        assert np.allclose(F, Fb, rtol=1e-9, atol=1e-10 * M / np.min(h))
        assert sol.rotation == pytest.approx(tb, rel=1e-9)


def test_solver_refuses_bad_input():
    with pytest.raises(ValueError, match="moment arms"):
        solve_contact_loads(np.eye(2), [0.0, 0.0], [1.0, -1.0], 1.0)
    with pytest.raises(ValueError, match="moment"):
        solve_contact_loads(np.eye(2), [0.0, 0.0], [1.0, 1.0], 0.0)


def test_diagonal_compliance_path_agrees_with_the_dense_one():
    """Independent points (a diagonal C, given as its diagonal) are solved in closed form per working
    set; the dense path on the same problem gives the same loads to the solve's rounding (dense
    solves of condition < 1e3 here)."""
    rng = np.random.default_rng(11)
    for _ in range(20):
        n = int(rng.integers(1, 30))
        c = rng.uniform(0.5, 2.0, n)
        s = rng.uniform(0.0, 1.0, n) * (rng.uniform(size=n) < 0.6)
        h = rng.uniform(0.5, 2.0, n)
        a, b = solve_contact_loads(c, s, h, 3.0), solve_contact_loads(np.diag(c), s, h, 3.0)
        assert a.status == b.status == Status.CONVERGED
        assert np.allclose(a.loads_N, b.loads_N, rtol=1e-10, atol=1e-12 * 3.0 / h.min())
        assert a.rotation == pytest.approx(b.rotation, rel=1e-10)


# ---------------------------------------------------------------------------------------------
# geometry from the surfaces, edge contact
# ---------------------------------------------------------------------------------------------
def test_section_contacts_of_the_aligned_spur_pair():
    """Line contact: every node of a tooth pair touching inside the flanks touches at once (zero
    separation, TE = 0), the moment arms are the base radii and the relative curvature across the
    line at the pitch point is 1/(r_p1 sin a) + 1/(r_p2 sin a)."""
    pair, g1, g2 = spur_pair()
    phi = cycle_positions(pair)
    sep = initial_separations(pair, phi, n_nodes=8)
    inner = sep.kind == 1
    assert np.all(np.isin(inner.sum(axis=2), (0, 8)))  # whole pairs
    assert np.all(np.abs(sep.gap_mm[inner]) < 1e-12) and np.all(np.abs(sep.te_rigid_rad) < 1e-12)
    assert np.allclose(sep.arm1_mm[inner], g1.r_b, rtol=1e-12) and np.allclose(sep.arm2_mm[inner], g2.r_b, rtol=1e-12)
    i, k = len(phi) // 2, int(np.flatnonzero(sep.pairs == 0)[0])
    s = np.sin(g1.alpha_t)
    assert sep.k_rel_per_mm[i, k] == pytest.approx(np.full(8, 1 / (g1.r_p * s) + 1 / (g2.r_p * s)), rel=1e-9)


@pytest.mark.numerics
def test_tip_edge_separation_is_the_distance_to_the_mating_flank():
    """At the pitch position of the unmodified 52/72 pair the neighbouring pairs' contacts lie beyond
    a tip (single-contact zone): their first touch is a tip edge (member 1's for the pair leaving,
    member 2's for the pair entering), open by its distance to the mating flank. Reference: that
    distance by sampling the mating profile at 2e5 points (spacing 1e-5 mm: its error is second
    order, < 1e-9 mm), against the first-order separation (relative error of order the TE
    difference, 1e-4)."""
    pair, g1, g2 = spur_pair()
    sep = initial_separations(pair, pitch(pair), n_nodes=3)
    k0 = int(np.flatnonzero(sep.pairs == 0)[0])
    assert sep.kind[0, k0 - 1, 1] == 2 and sep.kind[0, k0 + 1, 1] == 3
    p1 = 2 * np.pi / pair.n1
    for k, edge in ((-1, "tip1"), (1, "tip2")):
        pe = pitch(pair)[0] - k * p1
        if edge == "tip1":
            P, _ = pair.member1(np.array([g1.r_a]), np.array([0.0]), np.array([pe]))
            u = np.linspace(pair.lower2[0], pair.upper2[0], 200001)
            Q, N = pair.member2(u, 0 * u, np.full_like(u, pair.ratio * pe))
        else:
            P, _ = pair.member2(np.array([g2.r_a]), np.array([0.0]), np.array([pair.ratio * pe]))
            u = np.linspace(pair.lower1[0], pair.upper1[0], 200001)
            Q, N = pair.member1(u, 0 * u, np.full_like(u, pe))
        j = np.argmin(np.linalg.norm(Q - P, axis=1))
        dist = abs(float(np.dot(P[0] - Q[j], N[j])))
        assert sep.gap_mm[0, k0 + k, 1] == pytest.approx(dist, rel=1e-3)


def test_tip_edges_carry_load_when_the_teeth_deflect():
    """Unmodified 52/72 pair at the pitch position: its neighbours' tip edges are open by 1.8-2.7 um.
    At 1 N m the teeth deflect far less and one pair carries the load; at 50 N m (about 13 um) the
    tip edges close and take load (edge contact found, not assumed away)."""
    pair, _, _ = spur_pair()
    small, large = (loaded_contact(pair, T, pitch(pair), n_nodes=5) for T in (1.0, 50.0))
    assert small.pairs_loaded[0] == 1 and small.tip_edge_load_N[0] == 0.0
    assert large.pairs_loaded[0] == 3 and 0.2 < large.tip_edge_load_N[0] / large.normal_load_N[0] < 0.8
    assert np.isfinite(large.tip_edge_pressure_MPa[0]) and large.tip_edge_pressure_MPa[0] > large.max_pressure_MPa[0]


def test_face_end_of_a_tilted_mate_is_a_node():
    """With the gear's axis tilted out of plane, off the pitch point the contact line leaves the gear's
    face before the pinion's face end: there the end node sits where the tangency reaches the gear's
    face end (kind 4, its member-2 face coordinate on the face end to the solve's tolerance)."""
    pair, _, _ = spur_pair(mis=Misalignment(d_gamma_out=np.radians(0.05)))
    sep = initial_separations(pair, cycle_positions(pair, 5), n_nodes=5)
    at_end = sep.kind[..., [0, -1]] == 4
    assert np.any(at_end)
    i, k, e = np.argwhere(at_end)[0]
    v2 = sep.contacts.v2[np.ravel_multi_index((i, k, 0 if e == 0 else 4), sep.shape)]
    assert min(abs(v2 - pair.lower2[1]), abs(v2 - pair.upper2[1])) < 1e-9


def test_weber_load_geometry_closed_form():
    """The load angle read from the surface normal equals the involute's alpha_F = alpha_c - theta_c
    (pressure angle at the contact radius less the half tooth angle there)."""
    pair, g1, _ = spur_pair()
    t = ToothCompliance(pair.flank1, STEEL)
    r = np.linspace(g1.r_b * 1.01, g1.r_a, 7)
    alpha, _, _, theta = t.load_geometry(r)
    assert np.allclose(alpha, np.arccos(g1.r_b / r) - theta, atol=1e-12)
    lam = t.compliance(r)
    assert np.all(lam > 0) and np.all(np.diff(lam) > 0)  # the tooth softens toward the tip
    assert sum(t.terms(r).values()) == pytest.approx(lam, rel=1e-14)


# ---------------------------------------------------------------------------------------------
# validation against closed forms
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("n1, n2, m", [(52, 72, 1.0), (20, 40, 2.0)])
def test_pitch_point_pressure_matches_iso_6336_2(n1, n2, m):
    """One tooth pair carries the load at the pitch point: the nodes model a uniform line contact,
    whose pressure is ISO 6336-2's sigma_H0 (Z_eps = 1) up to the coupling's truncation at the face
    ends (the validation study's PRESSURE_RTOL, with its reason)."""
    b = 10.0 * m
    pair, g1, g2 = spur_pair(n1, n2, m, b=b)
    T = 40.0 * m**2
    r = loaded_contact(pair, T, pitch(pair), pairs=[0])
    assert r.status[0] == Status.CONVERGED and r.pairs_loaded[0] == 1
    Ft = 2000.0 * T / (2.0 * g1.r_p)
    sigma = iso.pitch_point_stress_MPa(
        Ft, 2 * g1.r_p, b, n2 / n1, iso.zone_factor(g1.alpha_t), iso.elasticity_factor(206000, 0.3)
    )
    assert r.max_pressure_MPa[0] == pytest.approx(sigma, rel=PRESSURE_RTOL)


def test_single_pair_stiffness_is_the_inverse_of_its_compliance():
    """One tooth pair, uniform load: the stiffness from the loaded TE equals 1 / (tooth compliance of
    both members + Weber's secant approach) per face width, to the O((b/h)^2) to which the coupled
    contact deformation sums to Weber's approach."""
    pair, g1, g2 = spur_pair(30, 30, 3.0, b=30.0)
    r = loaded_contact(pair, 300.0, pitch(pair), pairs=[0], n_nodes=5)
    c = r.separations.contacts
    j = int(np.flatnonzero(r.separations.in_contact.ravel())[2])
    t1, t2 = ToothCompliance(pair.flank1), ToothCompliance(pair.flank2)
    lam = t1.compliance(np.array([c.u1[j]]))[0] + t2.compliance(np.array([c.u2[j]]))[0]
    w = r.normal_load_N[0] / 30.0
    h1, h2 = t1.load_geometry(np.array([c.u1[j]]))[2][0], t2.load_geometry(np.array([c.u2[j]]))[2][0]
    weber = float(weber_contact_approach_mm(w, r.separations.k_rel_per_mm[0, 0, 2], h1, h2, STEEL, STEEL))
    b = float(r.half_width_mm[0, 0, 2])
    assert r.mesh_stiffness_N_per_mm_um[0] == pytest.approx(1e-3 / (lam + weber / w), rel=(b / min(h1, h2)) ** 2)


def test_rigid_teeth_give_hertz_point_contact():
    """Tooth compliance left out, crowned aligned pair, one tooth pair, a load so small that the
    ellipse (a = 0.2 mm, b = 0.02 mm) is slender and short against the tooth's depth h = 0.8 mm: the
    coupled nodes give Hertz's p0 within the slender-strip error (b/a)^2 ln(a/b) plus the depth
    reference's (a/h)^2 / 8 (3 %); independent strips (no coupling) are further off."""
    pair, _, _ = spur_pair(crown1=ParabolicCrowning(C1))
    phi = pitch(pair)
    r = loaded_contact(pair, 0.05, phi, pairs=[0], tooth_bending=False, n_nodes=41, maxiter=300)
    h = contact_hertz(pair, solve_contact(pair, phi), r.normal_load_N[0], 206000.0, 0.3)
    a, b = float(h.a[0]), float(h.b[0])
    bound = (b / a) ** 2 * np.log(a / b) + (a / 0.8) ** 2 / 8
    assert r.max_pressure_MPa[0] == pytest.approx(float(h.p0[0]), rel=bound)


# ---------------------------------------------------------------------------------------------
# balance, symmetry, convergence, unloaded limit
# ---------------------------------------------------------------------------------------------
def test_loads_balance_the_torque():
    """Sum of F_j h_j = torque at every position (to 1e-9 relative); where no tip edge carries load
    the force lines are on the plane of action, so the loads sum to the normal load T / r_b1."""
    pair, g1, _ = spur_pair()
    r = loaded_contact(pair, 50.0, n_nodes=5)
    assert np.all(r.converged)
    assert np.all(r.moment_residual <= 1e-9)
    flank = r.tip_edge_load_N == 0
    assert np.any(flank) and np.allclose(r.normal_load_N[flank], 50e3 / g1.r_b, rtol=1e-9, atol=0)
    assert np.allclose(np.nansum(r.pair_load_N, axis=1), r.normal_load_N, rtol=1e-12)


def test_symmetric_pair_is_symmetric_about_the_pitch_point():
    """Two equal gears: the position phi_p + d mirrors phi_p - d (the members swap roles), so the
    loaded TE, the maximum pressure and the pair loads agree to the solves' tolerance."""
    pair, _, _ = spur_pair(30, 30, 2.0, b=20.0)
    phi_p = -np.pi / 60
    d = np.linspace(0.0, np.pi / 30, 6)
    a, b = loaded_contact(pair, 40.0, phi_p + d, n_nodes=5), loaded_contact(pair, 40.0, phi_p - d, n_nodes=5)
    assert np.allclose(a.lte_urad, b.lte_urad, rtol=1e-8, atol=1e-8 * np.max(np.abs(a.lte_urad)))
    assert np.allclose(a.max_pressure_MPa, b.max_pressure_MPa, rtol=1e-8)
    assert np.allclose(np.sort(a.pair_load_N, axis=1), np.sort(b.pair_load_N, axis=1), rtol=1e-8, atol=1e-9)


@pytest.mark.slow
def test_node_convergence_of_a_localized_contact():
    """Crowned, misaligned pair: halving the node spacing (21 -> 41 nodes) moves the maximum pressure,
    loaded TE and mesh stiffness by less than 1 % (the declared accuracy; the validation study
    records the README pair's)."""
    pair, _, _ = crowned_misaligned_pair()
    phi = np.linspace(-0.08, 0.0, 5)
    a, b = (loaded_contact(pair, 50.0, phi, n_nodes=n) for n in (21, 41))
    for q in ("max_pressure_MPa", "lte_urad", "mesh_stiffness_N_per_mm_um"):
        x, y = getattr(a, q), getattr(b, q)
        assert np.max(np.abs(x - y) / np.abs(y)) < 0.01, q


def test_unloaded_tca_is_recovered():
    """The rigid TE of the nodes equals the TCA's point-contact TE (of the leading tooth pair) up to
    the node spacing: the pinion's crown c1 w^2 leaves the nearest node at most c1 (dz/2)^2 open, i.e.
    a TE deficit of at most c1 (dz/2)^2 / r_b2 (dz the leading pair's spacing). As the torque goes to 0
    the elastic TE vanishes at least as Hertz's point-contact approach (F^(2/3)): at 2e-8 of the
    load below (2e-8)^(2/3) = 7e-6 of its value."""
    pair, _, g2 = crowned_misaligned_pair()
    phi = np.linspace(-0.08, 0.0, 5)
    full = loaded_contact(pair, 50.0, phi, n_nodes=11)
    tiny = loaded_contact(pair, 1e-6, phi, n_nodes=11)
    p1 = 2 * np.pi / pair.n1
    tcas = [solve_contact(pair, phi - k * p1) for k in (-1, 0, 1)]
    assert np.all(tcas[1].converged)
    te_tca = np.max([np.where(c.converged, c.te, -np.inf) for c in tcas], axis=0)
    sep = full.separations
    lead = np.nanargmax(np.where(sep.in_contact, sep.te_rad, -np.inf).reshape(phi.size, -1), axis=1)
    dz = np.diff(sep.z_mm, axis=-1)[np.arange(phi.size), lead // sep.shape[2], 0]
    deficit = te_tca - full.te_unloaded_rad
    assert np.all(deficit >= -1e-13) and np.all(deficit <= C1 * (dz / 2) ** 2 / g2.r_b + 1e-13)
    e_full = np.abs(full.te_loaded_rad - full.te_unloaded_rad)
    e_tiny = np.abs(tiny.te_loaded_rad - tiny.te_unloaded_rad)
    assert np.all(e_tiny < (2e-8) ** (2 / 3) * e_full)


def test_non_converged_position_is_nan_with_status():
    pair, _, _ = crowned_misaligned_pair()
    r = loaded_contact(pair, 50.0, np.array([-0.04]), n_nodes=11, maxiter=1)
    assert r.status[0] == Status.NOT_CONVERGED
    assert np.isnan(r.lte_urad[0]) and np.isnan(r.max_pressure_MPa[0]) and np.isnan(r.mesh_stiffness_N_per_um[0])
    assert np.isnan(r.summary().max_contact_pressure_MPa) and r.summary().n_failed == 1


def test_pressure_map_carries_the_node_loads():
    """The semi-elliptic map of each node integrates (across the line) to its load per length."""
    pair, _, _ = crowned_misaligned_pair()
    r = loaded_contact(pair, 50.0, np.array([-0.04]), n_nodes=11)
    pm = r.pressure_map(0, n_across=2001)
    integral = np.trapezoid(np.nan_to_num(pm.pressure_MPa), pm.across_mm, axis=-1)
    w = np.nan_to_num(r.node_load_N[0]) / r.separations.line_length_mm[0]
    big = np.nan_to_num(w) > 0.05 * np.nanmax(w)
    assert np.allclose(integral[big], w[big], rtol=2e-3)  # trapezoid error at the ellipse's ends
    assert pm.z_mm.shape == r.separations.z_mm[0].shape


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(torque_Nm=-1.0), "torque_Nm"),
        (dict(driving="wheel"), "driving"),
        (dict(materials=Material(206000.0, 0.3), n_nodes=1), "n_nodes"),
        (dict(edge_radius_mm=0.0), "edge_radius_mm"),
    ],
)
def test_bad_input_is_refused(kwargs, match):
    pair, _, _ = spur_pair()
    kw = dict(torque_Nm=10.0)
    kw.update(kwargs)
    with pytest.raises(ValueError, match=match):
        loaded_contact(pair, **kw)
    with pytest.raises(ValueError, match="poisson"):
        Material(206000.0, 0.7)


def test_helical_pair_balance_and_driving_member():
    """Helical pair: the torque balances at every position and, where no tip edge carries load, the
    loads sum to T / (r_b1 cos(beta_b)). Driving from the gear with the torque T N2/N1 loads the same
    flanks with the same loads and loaded TE where every force line is on the plane of action (involute
    arms are in the ratio r_b2 / r_b1): at 1 N m, where no tip edge closes (a tip edge's force line is
    off the plane of action, and the two torques are then not in the ratio of the tooth numbers)."""
    pair, g1, _ = helical_pair()
    r = loaded_contact(pair, 30.0, cycle_positions(pair, 5), n_nodes=7)
    assert np.all(r.converged) and np.all(r.pairs_loaded >= 2) and np.all(r.moment_residual <= 1e-9)
    flank = r.tip_edge_load_N == 0
    assert np.allclose(r.normal_load_N[flank], 30e3 / (g1.r_b * np.cos(g1.beta_b)), rtol=1e-9, atol=0)
    pair, _, _ = spur_pair()
    phi = pitch(pair)[0] + 2 * np.pi / pair.n1 * np.array([-0.4, 0.0, 0.4])  # double, single, double contact
    a = loaded_contact(pair, 1.0, phi, n_nodes=5)
    b = loaded_contact(pair, 1.0 * 72 / 52, phi, driving="gear", n_nodes=5)
    assert np.all(a.tip_edge_load_N == 0) and np.all(b.tip_edge_load_N == 0)
    assert np.allclose(a.pair_load_N, b.pair_load_N, rtol=1e-8, atol=1e-8 * np.max(a.pair_load_N))
    assert np.allclose(a.lte_urad, b.lte_urad, rtol=1e-8, atol=1e-8 * np.max(np.abs(a.lte_urad)))


def test_flanks_driven_by_decreasing_angle_mirror_the_other_side():
    """``side=-1`` flanks are the mirror image (y -> -y) of ``side=+1`` ones: member 1 drives them
    turning by decreasing phi1, the position phi1 mirrors -phi1, the loads and pressures are equal
    and the loaded TE changes sign (to the solves' tolerance)."""
    a_pair, g1, g2 = spur_pair()
    f1, f2 = mating_flanks(g1, g2, side=-1)
    b_pair = GearPair(f1, f2, 52, 72, standard_centre_distance(g1, g2))
    a = loaded_contact(a_pair, 50.0, cycle_positions(a_pair, 5), n_nodes=5)
    b = loaded_contact(b_pair, 50.0, cycle_positions(b_pair, 5), n_nodes=5)
    assert b.separations.sense == -1 and a.separations.sense == 1
    assert np.allclose(b.phi1_rad, -a.phi1_rad[::-1], rtol=0, atol=1e-15)
    assert np.allclose(b.max_pressure_MPa, a.max_pressure_MPa[::-1], rtol=1e-8)
    assert np.allclose(np.sort(b.pair_load_N, axis=1), np.sort(a.pair_load_N[::-1], axis=1), rtol=1e-8, atol=1e-8)
    scale = np.max(np.abs(a.lte_urad))
    assert np.allclose(b.lte_urad, -a.lte_urad[::-1], rtol=1e-8, atol=1e-8 * scale)


# ---------------------------------------------------------------------------------------------
# families
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("flank_pair", ["A", "B"])
def test_catt_pair_localized_contact_and_balance(flank_pair):
    """The CATT pair of seed 004 sec 4: at a moderate torque the contact is localized about the middle
    section (the loaded span inside the face, refined), the torque balances at every position."""
    pair = assemble(SEC4, flank_pair, TOOL).gear_pair
    r = loaded_contact(pair, 300.0, cycle_positions(pair, 3), n_nodes=11, pairs=[-1, 0, 1])
    assert np.all(r.converged) and np.all(r.moment_residual <= 1e-9) and r.passes == 2
    k = int(np.flatnonzero(r.separations.pairs == 0)[0])
    z = r.separations.z_mm[1, k]
    loaded = np.nan_to_num(r.node_load_N[1, k]) > 0
    assert -40.0 < z[loaded].min() < 0.0 < z[loaded].max() < 40.0


def test_unsupported_families_are_refused():
    from gearrep.surfaces.bevel import BevelGearData, mating_bevel_flanks
    from gearrep.tca import BevelPair

    assert set(SUPPORTED) == {"involute", "catt"}
    g1, g2 = (BevelGearData(17, 17, 5.0, np.radians(20), 20.0) for _ in range(2))
    f1, f2 = mating_bevel_flanks(g1, g2)
    with pytest.raises(ValueError, match="supports the families"):
        loaded_contact(BevelPair(f1, f2, 17, 17), 10.0)


@pytest.mark.parametrize("n1, n2, m", [(52, 72, 1.0), (20, 40, 2.0)])
def test_tooth_section_has_the_fillet_of_the_basic_rack(n1, n2, m):
    """The section below the form radius is the envelope of the rack's tip circle (ISO 53 A,
    rho_fP = 0.38 m): its bottom lies on the root circle at half angle pi/z - x_c/r_p (the tip
    circle's centre x_c from the rack tooth's centre line, closed form), it meets the involute at
    the form radius r_Ff where the rack's straight flank ends (continuous to the sampling of the
    envelope, 1e-6 rad), and above r_Ff the section is the involute itself."""
    pair, g, _ = spur_pair(n1, n2, m)
    fl = pair.flank1
    a, rho, r_p, z = g.alpha_t, RACK_TIP_RADIUS * g.module, g.r_p, g.n_teeth
    h_c = (r_p - g.r_f) - rho
    x_c = r_p * (np.pi / z - (fl.polar_angle(np.array([r_p]), np.zeros(1))[0])) - h_c * np.tan(a) - rho / np.cos(a)
    r_Ff = np.hypot(g.r_b, r_p * np.sin(a) - (h_c + rho * np.sin(a)) / np.sin(a))
    theta = rack_fillet_half_angle(fl, np.array([g.r_f, r_Ff * (1 - 1e-9), r_Ff, g.r_p, g.r_a]))
    inv = fl.polar_angle(np.array([r_Ff, g.r_p, g.r_a]), np.zeros(3))
    assert theta[0] == pytest.approx(np.pi / z - x_c / r_p, abs=1e-12)
    assert abs(theta[1] - inv[0]) < 1e-6
    np.testing.assert_allclose(theta[2:], inv, atol=1e-14)
    assert 2 * g.r_f * np.sin(theta[0]) > 2 * g.r_f * np.sin(fl.polar_angle(np.array([g.r_b]), np.zeros(1))[0])


def test_basic_rack_factor():
    """ISO 6336-1's C_B is 1 for h_fP = 1.2 m_n at 20 deg and 0.975 for ISO 53's 1.25 m_n."""
    assert iso.basic_rack_factor(1.2, 20.0) == pytest.approx(1.0, rel=1e-15)
    assert iso.basic_rack_factor(1.25, 20.0) == pytest.approx(0.975, rel=1e-15)
    with pytest.raises(ValueError, match="h_fP_over_mn"):
        iso.basic_rack_factor(-1.0)
