"""Loaded tooth contact analysis (gearrep.ltca): closed forms (ISO 6336-1/-2, Hertz), the contact
solver's optimality conditions, load balance, symmetry, strip convergence and the unloaded limit."""

import itertools

import numpy as np
import pytest
from test_tca import C1, helical_pair, spur_pair

from gearrep.ltca import (
    STEEL,
    Material,
    ToothCompliance,
    cycle_positions,
    initial_separations,
    iso,
    loaded_contact,
    solve_contact_loads,
)
from gearrep.meshing import contact_ratio_closed_form
from gearrep.solve import Status
from gearrep.surfaces.involute import ParabolicCrowning, mating_flanks, standard_centre_distance
from gearrep.tca import GearPair, Misalignment, solve_contact


def crowned_misaligned_pair():
    """Thesis sec. 6.2 pair with the crowned pinion and a 3 arc-min out-of-plane shaft error."""
    return spur_pair(crown1=ParabolicCrowning(C1), mis=Misalignment(d_gamma_out=np.radians(3 / 60)))


# ---------------------------------------------------------------------------------------------
# ISO closed forms
# ---------------------------------------------------------------------------------------------
def test_iso_factors_printed_values():
    """ISO 6336-2 prints Z_E = 189.8 sqrt(MPa) for steel on steel (checked to its printed precision);
    Z_H = sqrt(2 / (sin(a) cos(a))) = 2.4946 for alpha = 20 deg, beta = 0, x = 0."""
    assert iso.elasticity_factor(206000.0, 0.3) == pytest.approx(189.8, abs=0.05)
    a = np.radians(20.0)
    assert iso.zone_factor(a) == pytest.approx(np.sqrt(2.0 / (np.sin(a) * np.cos(a))), rel=1e-14)
    # q' with x = 0: C1 + C2/z1 + C3/z2
    assert iso.q_prime(20, 40) == pytest.approx(0.04723 + 0.15551 / 20 + 0.25791 / 40, rel=1e-15)
    with pytest.raises(ValueError, match="z_n1"):
        iso.q_prime(0, 40)


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


# ---------------------------------------------------------------------------------------------
# geometry from the surfaces
# ---------------------------------------------------------------------------------------------
def test_section_contacts_of_the_aligned_spur_pair():
    """Line contact: every strip of a tooth pair in mesh touches at once (zero separation, TE = 0),
    the moment arms are the base radii and the relative curvature across the line at the pitch point
    is 1/(r_p1 sin a) + 1/(r_p2 sin a)."""
    pair, g1, g2 = spur_pair()
    phi = cycle_positions(pair)
    sep = initial_separations(pair, phi, n_nodes=8)
    ok = sep.in_contact
    assert np.all(np.isin(ok.sum(axis=2), (0, 8)))  # whole pairs in contact
    assert np.all(np.abs(sep.gap_mm[ok]) < 1e-12) and np.all(np.abs(sep.te_rigid_rad) < 1e-12)
    assert np.allclose(sep.arm1_mm[ok], g1.r_b, rtol=1e-12) and np.allclose(sep.arm2_mm[ok], g2.r_b, rtol=1e-12)
    i, k = len(phi) // 2, int(np.flatnonzero(sep.pairs == 0)[0])
    s = np.sin(g1.alpha_t)
    assert sep.k_rel_per_mm[i, k] == pytest.approx(np.full(8, 1 / (g1.r_p * s) + 1 / (g2.r_p * s)), rel=1e-9)


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


# ---------------------------------------------------------------------------------------------
# validation against closed forms
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("n1, n2, m", [(52, 72, 1.0), (20, 40, 2.0)])
def test_pitch_point_pressure_matches_iso_6336_2(n1, n2, m):
    """One tooth pair carries the load at the pitch point (single-contact zone of these pairs): the
    strip model's pressure is the Hertz line contact of the computed load per strip, and the load is
    uniform over the face for the aligned pair, so ISO 6336-2's sigma_H0 (Z_eps = 1) is reproduced up to
    the solves' tolerances (1e-10): checked to 1e-6."""
    b = 10.0 * m
    pair, g1, g2 = spur_pair(n1, n2, m, b=b)
    T = 40.0 * m**2
    r = loaded_contact(pair, T)
    i = len(r.phi1_rad) // 2
    assert r.status[i] == Status.CONVERGED and r.pairs_loaded[i] == 1
    Ft = 2000.0 * T / (2.0 * g1.r_p)
    sigma = iso.pitch_point_stress_MPa(
        Ft, 2 * g1.r_p, b, n2 / n1, iso.zone_factor(g1.alpha_t), iso.elasticity_factor(206000, 0.3)
    )
    assert r.max_pressure_MPa[i] == pytest.approx(sigma, rel=1e-6)


#: designs (z1, z2, m) of the stiffness table: standard basic rack, x = 0, b = 10 m, F_t/b = 300 N/mm
STIFFNESS_DESIGNS = [(20, 40, 2.0), (30, 30, 3.0), (52, 72, 1.0), (25, 60, 4.0)]


def stiffness_table():
    """Computed single-pair and mean mesh stiffness against ISO 6336-1's c'_th and c_gamma_alpha."""
    rows = []
    for z1, z2, m in STIFFNESS_DESIGNS:
        pair, g1, g2 = spur_pair(z1, z2, m, b=10.0 * m)
        T = 300.0 * 10.0 * m * g1.r_p / 1000.0  # F_t / b = 300 N/mm
        s = loaded_contact(pair, T).summary()
        eps = float(contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, pair.centre_distance, g1.base_pitch))
        c_th = iso.single_stiffness_theoretical(z1, z2)
        rows.append(
            (
                s.single_pair_stiffness_max_N_per_mm_um / c_th,
                s.mesh_stiffness_mean_N_per_mm_um / iso.mesh_stiffness_c_gamma_alpha(c_th, eps),
            )
        )
    return np.array(rows)


def test_stiffness_against_iso_6336_1():
    """Band: ISO's c'_th (1/q') is a fit to theoretical values, and ISO itself multiplies it by
    C_M = 0.8 for real solid disc gears; the gear-body (foundation) term here depends on the bore
    (h_f = r_f/r_bore from 1.4 to 3.3 changes a tooth's compliance by about 35 %). So the computed
    single and mean stiffness must lie in [0.6, 1.0] c'_th (0.8 x 0.75 ... 1), and the ratio must vary
    by less than 10 % over the designs (ISO's dependence on the tooth numbers is reproduced)."""
    ratios = stiffness_table()
    assert np.all((ratios >= 0.6) & (ratios <= 1.0)), ratios
    for col in ratios.T:
        assert col.max() / col.min() < 1.10, ratios


# ---------------------------------------------------------------------------------------------
# balance, symmetry, convergence, unloaded limit
# ---------------------------------------------------------------------------------------------
def test_loads_balance_the_torque():
    """Sum of F_j h_j = torque at every position (to 1e-9 relative); for the involute pair the arm is
    the base radius, so the loads sum to the normal load T / r_b1."""
    pair, g1, _ = spur_pair()
    r = loaded_contact(pair, 50.0)
    assert np.all(r.converged)
    assert np.all(r.moment_residual <= 1e-9)
    assert np.allclose(r.normal_load_N, 50e3 / g1.r_b, rtol=1e-9, atol=0)
    assert np.allclose(np.nansum(r.pair_load_N, axis=1), r.normal_load_N, rtol=1e-12)
    s = r.summary()
    assert s.n_failed == 0 and s.load_share_max == pytest.approx(1.0, abs=1e-12)


def test_symmetric_pair_is_symmetric_about_the_pitch_point():
    """Two equal gears: the position phi_p + d mirrors phi_p - d (the members swap roles), so the
    loaded TE, the maximum pressure and the pair loads agree to the solves' tolerance."""
    pair, _, _ = spur_pair(30, 30, 2.0, b=20.0)
    phi_p = -np.pi / 60
    d = np.linspace(0.0, np.pi / 30, 6)
    a, b = loaded_contact(pair, 40.0, phi_p + d), loaded_contact(pair, 40.0, phi_p - d)
    assert np.allclose(a.lte_urad, b.lte_urad, rtol=1e-8, atol=1e-8 * np.max(np.abs(a.lte_urad)))
    assert np.allclose(a.max_pressure_MPa, b.max_pressure_MPa, rtol=1e-8)
    assert np.allclose(np.sort(a.pair_load_N, axis=1), np.sort(b.pair_load_N, axis=1), rtol=1e-8, atol=1e-9)


def test_strip_convergence_of_a_localized_contact():
    """Crowned, misaligned pair: halving the strip width (40 -> 80 strips) moves the maximum pressure,
    loaded TE and mesh stiffness by less than 1 % (the strip model's discretisation error)."""
    pair, _, _ = crowned_misaligned_pair()
    phi = np.linspace(-0.08, 0.0, 5)
    a, b = (loaded_contact(pair, 50.0, phi, n_nodes=n) for n in (40, 80))
    for q in ("max_pressure_MPa", "lte_urad", "mesh_stiffness_N_per_mm_um"):
        x, y = getattr(a, q), getattr(b, q)
        assert np.max(np.abs(x - y) / np.abs(y)) < 0.01, q


def test_unloaded_tca_is_recovered():
    """The rigid TE of the strips equals the TCA's point-contact TE (of the leading tooth pair) up to
    the strip spacing: the
    pinion's crowning c1 w^2 leaves the nearest strip at most c1 (dv/2)^2 open, i.e. a TE deficit of at
    most c1 (dv/2)^2 / r_b2. As the torque goes to 0 the loaded TE tends to it (the elastic part is
    linear in the torque up to Hertz's logarithm: at 2e-8 of the load it is below 1e-6 of its value)."""
    pair, _, g2 = crowned_misaligned_pair()
    phi = np.linspace(-0.08, 0.0, 5)
    n = 40
    full = loaded_contact(pair, 50.0, phi, n_nodes=n)
    tiny = loaded_contact(pair, 1e-6, phi, n_nodes=n)
    p1 = 2 * np.pi / pair.n1
    pairs = [solve_contact(pair, phi - k * p1) for k in (-1, 0, 1)]  # tooth pairs k (gearrep.meshing)
    assert np.all(pairs[1].converged)
    te_tca = np.max([np.where(c.converged, c.te, -np.inf) for c in pairs], axis=0)  # the leading pair
    dv = pair.flank1.gear.face_width / n
    deficit = te_tca - full.te_unloaded_rad
    assert np.all(deficit >= -1e-13) and np.all(deficit <= C1 * (dv / 2) ** 2 / g2.r_b + 1e-13)
    e_full = np.abs(full.te_loaded_rad - full.te_unloaded_rad)
    e_tiny = np.abs(tiny.te_loaded_rad - tiny.te_unloaded_rad)
    assert np.all(e_tiny < 1e-6 * e_full)


def test_non_converged_position_is_nan_with_status():
    pair, _, _ = crowned_misaligned_pair()
    r = loaded_contact(pair, 50.0, np.array([-0.04]), n_nodes=20, maxiter=1)
    assert r.status[0] == Status.NOT_CONVERGED
    assert np.isnan(r.lte_urad[0]) and np.isnan(r.max_pressure_MPa[0]) and np.isnan(r.mesh_stiffness_N_per_um[0])
    assert np.isnan(r.summary().max_contact_pressure_MPa)


def test_pressure_map_carries_the_strip_loads():
    """The semi-elliptic map of each strip integrates (across the line) to its load per length."""
    pair, _, _ = crowned_misaligned_pair()
    r = loaded_contact(pair, 50.0, np.array([-0.04]), n_nodes=20)
    pm = r.pressure_map(0, n_across=2001)
    integral = np.trapezoid(np.nan_to_num(pm.pressure_MPa), pm.across_mm, axis=-1)
    w = np.nan_to_num(r.node_load_N[0]) / (pair.flank1.gear.face_width / 20)
    big = w > 0.05 * w.max()
    assert np.allclose(integral[big], w[big], rtol=2e-3)  # trapezoid error at the ellipse's ends


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(torque_Nm=-1.0), "torque_Nm"),
        (dict(driving="wheel"), "driving"),
        (dict(materials=Material(206000.0, 0.3), n_nodes=0), "n_slices"),
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


def test_helical_pair_balance_and_driving_member():
    """Helical pair: the moment arm of the normal load is r_b1 cos(beta_b), so the loads sum to
    T / (r_b1 cos(beta_b)) (1e-9 relative). Driving from the gear with the torque T N2/N1 loads the
    same flanks with the same loads and loaded TE (involute arms are in the ratio r_b2 / r_b1)."""
    pair, g1, _ = helical_pair()
    r = loaded_contact(pair, 30.0, cycle_positions(pair, 9))
    assert np.all(r.converged) and np.all(r.pairs_loaded >= 2)
    assert np.allclose(r.normal_load_N, 30e3 / (g1.r_b * np.cos(g1.beta_b)), rtol=1e-9, atol=0)
    pair, _, _ = spur_pair()
    phi = np.linspace(-0.08, 0.0, 5)
    a, b = loaded_contact(pair, 50.0, phi), loaded_contact(pair, 50.0 * 72 / 52, phi, driving="gear")
    assert np.allclose(a.pair_load_N, b.pair_load_N, rtol=1e-9, atol=1e-9 * np.max(a.pair_load_N))
    assert np.allclose(a.lte_urad, b.lte_urad, rtol=1e-9, atol=1e-9 * np.max(np.abs(a.lte_urad)))


def test_flanks_driven_by_decreasing_angle_mirror_the_other_side():
    """``side=-1`` flanks are the mirror image (y -> -y) of ``side=+1`` ones: member 1 drives them
    turning by decreasing phi1, the position phi1 mirrors -phi1, the loads and pressures are equal
    and the loaded TE changes sign (to the solves' tolerance)."""
    a_pair, g1, g2 = spur_pair()
    f1, f2 = mating_flanks(g1, g2, side=-1)
    b_pair = GearPair(f1, f2, 52, 72, standard_centre_distance(g1, g2))
    a = loaded_contact(a_pair, 50.0, cycle_positions(a_pair, 9))
    b = loaded_contact(b_pair, 50.0, cycle_positions(b_pair, 9))
    assert b.separations.sense == -1 and a.separations.sense == 1
    assert np.allclose(b.phi1_rad, -a.phi1_rad[::-1], rtol=0, atol=1e-15)
    assert np.allclose(b.max_pressure_MPa, a.max_pressure_MPa[::-1], rtol=1e-9)
    assert np.allclose(np.sort(b.pair_load_N, axis=1), np.sort(a.pair_load_N[::-1], axis=1), rtol=1e-9, atol=1e-9)
    scale = np.max(np.abs(a.lte_urad))
    assert np.allclose(b.lte_urad, -a.lte_urad[::-1], rtol=1e-9, atol=1e-9 * scale)
    assert np.allclose(b.mesh_stiffness_N_per_um, a.mesh_stiffness_N_per_um[::-1], rtol=1e-9)
