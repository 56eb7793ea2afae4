"""Numerical stress tests of the GENERATED gears: the curvilinear-tooth gear
cut by the ZA hob (two-parameter envelope, :mod:`gearrep.surfaces.hob`), the CATT gear
(:mod:`gearrep.surfaces.catt`) and the 9-unknown TCA of seed 000 ch. 5
(:mod:`gearrep.replications.hobcut_tca`).

Cases: tooth-trace radius R_c (hob) and cutter radius R_T (CATT) from 50 mm to 50 000 mm and the
straight limit; near-singular Jacobians (the mid-face singularity of the (theta, psi)
parameterisation of the envelope, Litvin's limiting line near the face ends, the almost-line
contact of the ideal R_cp = R_cg = 110 mm pair). For each: the solver returns a converged point
that is verified independently (closed form, spur limit, a re-solve from another start, the
surface itself) or a status that says why not; no NaN in a converged result. The condition
numbers seen are recorded (``record_conditions``, printed at the end of ``make stress``).
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import PUBLISHED_DIR, assert_honest

from gearrep import published, tca
from gearrep.curvature import principal_curvatures
from gearrep.envelope import Envelope
from gearrep.replications import hobcut_curvature as tc
from gearrep.replications import hobcut_tca as tca_rep
from gearrep.replications import ma2021 as catt_rep
from gearrep.replications.hobcut_tca import studies as ts
from gearrep.solve import Status
from gearrep.surfaces import catt as catt_surf
from gearrep.surfaces.catt import (
    CATTFlank,
    CATTGearData,
    middle_section_curvatures,
    pitch_thickness_closed_form,
    tooth_thickness,
)
from gearrep.surfaces.hob import GeneratedGear
from gearrep.tca import solve_contact
from gearrep.units import ARCSEC

pytestmark = pytest.mark.stress

KNOWN = {int(s) for s in Status}
RC_SWEEP_MM = [float(r) for r in tc.SETTINGS["rc_sweep_mm"].value]  # 50 .. 50 000 mm (hobcut_curvature setting)
L_END_MM = tc.params_from_published(published.load(PUBLISHED_DIR)).l1_end_mm  # last row of Tables 4.2-4.5
TCA_GEARS = tca_rep.params_from_published(published.load(PUBLISHED_DIR)).gears  # the Table 5.1 pair and hob
CATT_PRM = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}
CATT_TCA_TOL = 1e-10  # Newton tolerance of the CATT TCA here (tighter than the workflow's ma2021.tol 1e-8)


def _full(request) -> bool:
    m = request.config.getoption("-m") or ""
    return "slow" in m


# ---------------------------------------------------------------------------------------------
# helpers
# ---------------------------------------------------------------------------------------------
def meshing_condition(g: GeneratedGear, rec) -> np.ndarray:
    """2-norm condition of the meshing Jacobian in the solved (phi, theta) at the returned
    parameters (the solver's own ``condition`` is NaN where the start already solved)."""
    env = g.envelope()
    q = rec.params
    out = np.full(len(q), np.nan)
    ok = np.all(np.isfinite(q), axis=1)
    if ok.any():
        J = env.meshing_jacobian(q[ok])[:, :, list(env.solved)]
        out[ok] = np.linalg.cond(J)
    return out


def assert_honest_envelope(g: GeneratedGear, rec):
    """Statuses known; converged points finite, below the tolerance by an independent evaluation
    of the meshing equations, and the family point at those parameters."""
    assert set(np.unique(rec.status)) <= KNOWN
    ok = rec.converged
    for name in ("params", "point", "normal", "tangents"):
        assert np.all(np.isfinite(getattr(rec, name)[ok])), name
    assert np.all(np.isfinite(rec.residual[ok]))
    env = g.envelope()
    tol = g.effective_tol
    assert np.all(rec.residual[ok] < tol)
    if ok.any():
        f = np.linalg.norm(env.meshing(rec.params[ok]), axis=-1)
        assert np.all(f < tol), f.max()
        np.testing.assert_allclose(env.family(rec.params[ok]), rec.point[ok], atol=1e-9)
        # inside the generated tooth band (radial r_p +- 2.5 m): WRONG_ROOT otherwise (GeneratedGear.verify)
        r = np.hypot(rec.point[ok, 0], rec.point[ok, 1])
        assert np.all(np.abs(r - g.pitch_radius_mm) <= 2.5 * g.hob.module_mm)


def assert_finite_curvatures(c):
    ok = c.result.converged
    for name in ("k_s", "k_q", "e_s", "e_q", "point", "normal"):
        assert np.all(np.isfinite(getattr(c, name)[ok])), name


@pytest.fixture(scope="module")
def l_rows():
    """Tip (r = 33 mm), pitch (r = 30 mm) and last (l = 10.354) rows of Tables 4.2-4.5."""
    g = GeneratedGear.flank("R")
    res = g.l_at_radius(np.array([33.0, 30.0]))
    assert np.all(res.status == Status.CONVERGED)
    return np.array([res.x[0, 0], res.x[1, 0], L_END_MM])


# ---------------------------------------------------------------------------------------------
# 1. hob-generated curvilinear gear: R_c from 50 mm to 50 000 mm and the straight limit
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("flank", ["R", "L"])
def test_hob_trace_radius_sweep_mid_face(flank, l_rows, record_conditions):
    """Mid-face rows at every R_c of the hobcut_curvature sweep and R_c = inf (axial feed). The
    mid-face transverse profile does not depend on the trace: every converged point equals the
    spur-limit point, and a re-solve from another start (spur solution + 0.02 rad in phi and theta)
    finds the same point; k_q equals the spur k_q, k_s is finite and R_c k_s settles as R_c grows
    (its successive differences shrink); the spur limit has k_s = 0."""
    spur = GeneratedGear.flank(flank, R_c_mm=np.inf)
    cs = spur.curvatures(l_rows)
    assert_honest_envelope(spur, cs.result)
    assert np.all(cs.result.converged)
    np.testing.assert_allclose(cs.k_s, 0.0, atol=1e-13)
    conds = [meshing_condition(spur, cs.result)]
    rks = []
    for Rc in RC_SWEEP_MM:
        g = GeneratedGear.flank(flank, R_c_mm=Rc)
        c = g.curvatures(l_rows)
        assert_honest_envelope(g, c.result)
        assert_finite_curvatures(c)
        assert np.all(c.result.converged), (Rc, c.result.status)
        np.testing.assert_allclose(c.point, cs.point, atol=1e-9)
        other = g.solve(l_rows, 0.0, guess=cs.result.params[:, [1, 2]] + 0.02)
        assert_honest_envelope(g, other)
        assert np.all(other.converged)
        np.testing.assert_allclose(other.point, c.result.point, atol=1e-9)
        # k_q: the mid-face profile curvature, independent of the trace (tests/unit/surfaces/test_hob.py)
        np.testing.assert_allclose(c.k_q, cs.k_q, rtol=1e-9)
        assert np.all(c.k_s != 0)
        rks.append(Rc * c.k_s)
        conds.append(meshing_condition(g, c.result))
    rks = np.array(rks)
    steps = np.abs(np.diff(rks, axis=0))  # successive differences of R_c k_s along the sweep
    big = np.array(RC_SWEEP_MM[1:]) >= 200
    # shrinking, up to the rounding floor of R_c k_s (|k_s| rounding ~1e-15 /mm times R_c <= 5e4 mm);
    # at the pitch row R_c k_s does not depend on R_c at all (differences are rounding only)
    assert np.all(np.diff(steps[big], axis=0) <= 1e-10), steps
    assert np.all(np.abs(rks[-1] - rks[-2]) < 1e-3)  # 20 000 -> 50 000 mm: R_c k_s has settled
    record_conditions(np.concatenate(conds), f"mid-face, R_c 50..5e4, inf, Sigma_2{flank}")


@pytest.mark.parametrize("flank", ["R", "L"])
def test_hob_trace_radius_sweep_off_mid_face(flank, l_rows, record_conditions):
    """Points 10 mm off mid-face (psi = asin(10 / R_c); psi = 10 mm of axial feed in the spur limit).
    As R_c grows they tend to the spur points at Z_f = 10 mm with the 1/R_c law of the swivel's
    lever arm: (Z_f - 10) R_c and |p - p_spur| R_c are constant to 5 % for R_c >= 1000 mm."""
    spur = GeneratedGear.flank(flank, R_c_mm=np.inf)
    ps_spur, _, rs = spur.points(l_rows, 10.0)
    assert_honest_envelope(spur, rs)
    assert np.all(rs.converged)
    np.testing.assert_allclose(ps_spur[:, 2], 10.0, atol=1e-9)
    dz, dp, conds = [], [], [meshing_condition(spur, rs)]
    for Rc in RC_SWEEP_MM:
        g = GeneratedGear.flank(flank, R_c_mm=Rc)
        c = g.curvatures(l_rows, np.arcsin(10.0 / Rc))
        assert_honest_envelope(g, c.result)
        assert_finite_curvatures(c)
        assert np.all(c.result.converged), (Rc, c.result.status)
        dz.append((c.point[:, 2] - 10.0) * Rc)
        dp.append(np.linalg.norm(c.point - ps_spur, axis=1) * Rc)
        conds.append(c.result.solve.condition)
        conds.append(meshing_condition(g, c.result))
    far = np.array(RC_SWEEP_MM) >= 1000
    for arr in (np.array(dz)[far], np.array(dp)[far]):
        # a(R_c) = (deviation) R_c = c1 + c2 / R_c + ...: its successive differences shrink (up to the
        # rounding floor ~1e-12 mm x R_c <= 5e4 mm) and it stays within a factor 2 of a(1000 mm)
        steps = np.abs(np.diff(arr, axis=0))
        assert np.all(np.diff(steps, axis=0) <= 1e-7), arr
        assert np.all(np.abs(arr) <= 2 * np.abs(arr[0]) + 1e-7), arr
    record_conditions(np.concatenate(conds), f"Sigma_2{flank}, Z_f ~ 10 mm, R_c 50..5e4, inf")


@pytest.mark.slow
@pytest.mark.parametrize("flank", ["R", "L"])
def test_hob_trace_radius_sweep_full_face(flank, record_conditions):
    """11 rows x 9 sections across the 40 mm face at every R_c (and inf): each point converges or
    is flagged; converged points are confirmed by a re-solve at a 100 times tighter tolerance
    started from a perturbed guess (points agree to 1e-9 mm where both converge); curvatures
    finite where converged."""
    ls = np.linspace(4.3814841, L_END_MM, 11)
    conds = []
    for Rc in RC_SWEEP_MM + [np.inf]:
        g = GeneratedGear.flank(flank, R_c_mm=Rc)
        zs = np.linspace(-20.0, 20.0, 9)
        ps = zs if np.isinf(Rc) else np.arcsin(zs / Rc)
        L, PS = np.meshgrid(ls, ps, indexing="ij")
        c = g.curvatures(L.ravel(), PS.ravel())
        assert_honest_envelope(g, c.result)
        assert_finite_curvatures(c)
        assert c.result.converged.mean() > 0.9
        tight = GeneratedGear.flank(flank, R_c_mm=Rc, tol=g.tol / 100)
        ok = c.result.converged
        rec2 = tight.solve(L.ravel()[ok], PS.ravel()[ok], guess=c.result.params[ok][:, [1, 2]] + 1e-3)
        assert set(np.unique(rec2.status)) <= KNOWN
        both = rec2.converged
        np.testing.assert_allclose(rec2.point[both], c.result.point[ok][both], atol=1e-9)
        conds += [c.result.solve.condition, meshing_condition(g, c.result)]
    record_conditions(np.concatenate(conds), f"Sigma_2{flank}, 11 x 9 over the face")


# ---------------------------------------------------------------------------------------------
# 2. CATT gear: cutter radius R_T from 50 mm to 50 000 mm and the straight limit
# ---------------------------------------------------------------------------------------------
def catt_gear(RT, z=19):
    return CATTGearData(z, 4.0, RT, 40.0)


def _section_condition(f: CATTFlank, x):
    """Condition of d(z, radius)/d(theta, phi) at the solved parameters (the Jacobian of solve_point)."""
    P = f.evaluate(x[:, 0], x[:, 1])
    rad = np.hypot(P.r[:, 0], P.r[:, 1])
    J = np.empty((len(x), 2, 2))
    J[:, 0, 0], J[:, 0, 1] = P.r_u[:, 2], P.r_v[:, 2]
    J[:, 1, 0] = (P.r[:, 0] * P.r_u[:, 0] + P.r[:, 1] * P.r_u[:, 1]) / rad
    J[:, 1, 1] = (P.r[:, 0] * P.r_v[:, 0] + P.r[:, 1] * P.r_v[:, 1]) / rad
    return np.linalg.cond(J)


@pytest.mark.parametrize("side", [1, -1])
def test_catt_cutter_radius_sweep_flank_points(side, record_conditions):
    """Flank points at sections z = -16, 0, 16 mm and 5 radii form..tip for R_T = 50..50 000 mm:
    converged points reproduce their targets (z, radius) on the surface; on the middle section
    theta = 0, phi = the closed form and the principal curvatures equal the closed forms (involute
    profile, cutter cone along the axis); the pitch tooth thickness equals its closed form. The
    straight limit R_T = inf is refused with a ValueError naming R_T."""
    conds = []
    for RT in RC_SWEEP_MM:
        g = catt_gear(RT)
        f = CATTFlank(g, side)
        radii = np.linspace(g.r_form + 0.1, g.r_a, 5)
        Z, R = np.meshgrid([-16.0, 0.0, 16.0], radii, indexing="ij")
        res = f.solve_point(Z.ravel(), R.ravel())
        assert set(np.unique(res.status)) <= KNOWN
        assert np.all(res.converged), (RT, res.status)
        assert np.all(np.isfinite(res.x)) and np.all(res.residual < 1e-11)
        p = f.position(res.x[:, 0], res.x[:, 1])
        np.testing.assert_allclose(p[:, 2], Z.ravel(), atol=1e-10)
        np.testing.assert_allclose(np.hypot(p[:, 0], p[:, 1]), R.ravel(), atol=1e-10)
        mid = Z.ravel() == 0.0
        np.testing.assert_allclose(res.x[mid, 0], 0.0, atol=1e-12)
        np.testing.assert_allclose(res.x[mid, 1], f.middle_section_phi(R.ravel()[mid]), atol=1e-12)
        pc = principal_curvatures(f.evaluate(res.x[mid, 0], res.x[mid, 1]))
        kp, ka, _, _ = middle_section_curvatures(g, side, R.ravel()[mid])
        s = np.sign(np.sum(pc.normal * f.outward_normal(res.x[mid, 0], res.x[mid, 1]), -1))[:, None]
        np.testing.assert_allclose(np.sort(s * np.c_[pc.k1, pc.k2], 1), np.sort(np.c_[kp, ka], 1), rtol=1e-8)
        th, rmax = tooth_thickness(g, [-16.0, 0.0, 16.0])
        assert rmax < 1e-10
        np.testing.assert_allclose(th, pitch_thickness_closed_form(g, [-16.0, 0.0, 16.0]), atol=1e-9)
        conds.append(_section_condition(f, res.x))
    with pytest.raises(ValueError, match="R_T"):
        catt_gear(np.inf)
    record_conditions(np.concatenate(conds), f"side {side}, R_T 50..5e4 (solve_point)")


def _catt_mesh(RT, pair_id):
    design = {"name": "stress", "group": "stress", "z1": 19, "z2": 31, "module": 4.0, "R_T": RT, "face_width": 40.0}
    return catt_surf.assemble(design, pair_id, CATT_PRM)


def _check_catt_tca(mesh, phi1, cp):
    """Honest CATT TCA: statuses known; converged points finite, with TE = 0 (aligned ideal pair)
    within the Newton tolerance carried to an angle by the pinion base radius (x2 margin for the
    two members), on the middle section within the first-order error bound condition x tol of
    the ill-conditioned axial direction, at the closed-form middle-section radius of the pinion."""
    assert_honest(cp, tol=CATT_TCA_TOL)
    ok = cp.converged
    te_bound = 2 * CATT_TCA_TOL / mesh.g1.r_b / ARCSEC
    assert np.all(np.abs(cp.te_arcsec[ok]) < te_bound), np.abs(cp.te_arcsec[ok]).max()
    assert np.all(np.abs(cp.position[ok, 2]) <= cp.condition[ok] * CATT_TCA_TOL)
    r1, _ = catt_rep.contact_radii(mesh, phi1)
    p1 = mesh.f1.position(cp.u1[ok], cp.v1[ok])
    dr = np.hypot(p1[:, 0], p1[:, 1]) - r1[ok]
    # off the middle section the radius changes only to second order in the axial offset z:
    # |dr| <= z^2 / rho_blade + the tolerance (the blade circle radius rho >= R_T - pi m / 4)
    zb = np.abs(cp.position[ok, 2])
    assert np.all(np.abs(dr) <= zb**2 / (mesh.g1.R_T - mesh.g1.q) + 10 * CATT_TCA_TOL), np.abs(dr).max()
    return ok


@pytest.mark.parametrize("pair_id", ["A", "B"])
def test_catt_tca_cutter_radius_sweep_and_straight_limit(pair_id, record_conditions):
    """TCA of the aligned CATT pair (19/31 teeth, m = 4, B = 40) over its real meshing cycle for
    R_T = 50..50 000 mm and towards the straight limit (1e5, 1e6, 1e7 mm): the contact stays on
    the middle section with TE = 0 while the Jacobian condition grows like R_T^2 (the lengthwise
    curvature difference ~ pi m / (2 R_T^2) is all that fixes the axial position). Every point
    is verified or flagged: up to 5e4 mm all converge; at 1e7 mm the solver reports SINGULAR."""
    per_rt = {}
    for RT in RC_SWEEP_MM + [1e5, 1e6, 1e7]:
        mesh = _catt_mesh(RT, pair_id)
        lim = catt_surf.path_limits(mesh)
        phi1 = np.linspace(lim["phi1_lo"], lim["phi1_hi"], 7)
        cp = catt_surf.solve_cycle(mesh, phi1, {"start_offset_mm": 5.0, "tol": CATT_TCA_TOL, "maxiter": 50})
        ok = _check_catt_tca(mesh, phi1, cp)
        if RT <= 5e4:
            assert np.all(ok), (RT, cp.status)
        per_rt[RT] = cp
        record_conditions(cp.condition, f"R_T={RT:g}, pair {pair_id}")
    assert not np.any(per_rt[1e7].converged)
    assert set(np.unique(per_rt[1e7].status)) <= {
        Status.SINGULAR,
        Status.NOT_CONVERGED,
        Status.DIVERGED,
        Status.OFF_FLANK,
    }
    # condition ~ R_T^2: a factor ~100 per decade between 1e3 and 1e6 mm
    c = {RT: np.median(per_rt[RT].condition) for RT in (1000.0, 10000.0, 1e5, 1e6)}
    ratios = np.array([c[10000.0] / c[1000.0], c[1e5] / c[10000.0], c[1e6] / c[1e5]])
    assert np.all((ratios > 50) & (ratios < 200)), ratios


@pytest.mark.slow
@pytest.mark.parametrize("pair_id", ["A", "B"])
def test_catt_tca_random_starts(pair_id, record_conditions):
    """Random starts (axial offsets up to +-15 mm on both members, roll +-0.02 rad, phi2 +-0.01 rad)
    at three positions of the cycle for R_T = 50, 500, 5000, 50 000 mm: converged points pass the
    same verification (one contact, on the middle section, TE = 0); the rest are flagged."""
    rng = np.random.default_rng(7)
    n = 200
    for RT in (50.0, 500.0, 5000.0, 50000.0):
        mesh = _catt_mesh(RT, pair_id)
        lim = catt_surf.path_limits(mesh)
        for phi in np.linspace(lim["phi1_lo"], lim["phi1_hi"], 5)[1:-1]:
            phi1 = np.full(n, phi)
            start = catt_surf.starts(mesh, phi1, 0.0)
            start[:, 0] += rng.uniform(-15, 15, n) / mesh.f1.rho0
            start[:, 2] += rng.uniform(-15, 15, n) / mesh.f2.rho0
            start[:, [1, 3]] += rng.uniform(-0.02, 0.02, (n, 2))
            start[:, 4] += rng.uniform(-0.01, 0.01, n)
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                cp = solve_contact(mesh.gear_pair, phi1, start, formulation="conventional", tol=CATT_TCA_TOL)
            ok = _check_catt_tca(mesh, phi1, cp)
            assert ok.sum() > 0
            record_conditions(cp.condition, f"R_T={RT:g} random starts, pair {pair_id}")


# ---------------------------------------------------------------------------------------------
# 3a. near-singular Jacobians of the two-parameter envelope
# ---------------------------------------------------------------------------------------------
def test_envelope_mid_face_singular_parameterisation(record_conditions):
    """The meshing Jacobian in (theta, psi) is singular at mid-face (hob module doc): solving for
    (theta, psi) at given (l, phi) from starts near the mid-face root either flags the point or
    returns a point that IS on the generated surface (re-solved in the library's (l, psi)
    parameterisation at the psi found: same point). The library's (l, psi) parameterisation is
    regular there: psi -> 0 from 1e-1 to 1e-12 converges with a bounded condition and the
    curvatures are continuous at psi = 0 (at least first order)."""
    g = GeneratedGear.flank("R", R_c_mm=110.0)
    ls = np.linspace(5.0, 10.0, 5)
    rec0 = g.solve(ls, 0.0)
    assert np.all(rec0.converged)
    q = rec0.params
    env = g.envelope()
    cond_tp = np.linalg.cond(env.meshing_jacobian(q)[:, :, [2, 3]])  # (theta, psi) at the mid-face root
    assert np.all(cond_tp > 1e12)  # singular to rounding
    record_conditions(cond_tp, "J(theta, psi) at mid-face roots")
    env2 = Envelope(g.thread(), g.motion(), free=("u", "v"), tol=g.effective_tol, maxiter=g.maxiter)
    rng = np.random.default_rng(1)
    n = 40
    Q = np.repeat(q, n, 0)
    guess = Q[:, [2, 3]] + rng.normal(0.0, 0.02, (len(Q), 2))
    guess[::n] = Q[::n, [2, 3]]  # one exact start per row (singular Jacobian at the start)
    r2 = env2.solve(Q[:, 0], Q[:, 1], guess=guess)
    assert set(np.unique(r2.status)) <= KNOWN
    ok = r2.converged
    assert np.all(np.isfinite(r2.params[ok])) and np.all(np.isfinite(r2.point[ok]))
    assert np.all(np.linalg.norm(env2.meshing(r2.params[ok]), axis=-1) < g.effective_tol)
    if ok.any():
        back = g.solve(r2.params[ok, 0], r2.params[ok, 3], guess=r2.params[ok][:, [1, 2]])
        assert np.all(back.converged)
        np.testing.assert_allclose(back.point, r2.point[ok], atol=1e-8)
    record_conditions(r2.solve.condition, "(l, phi) free, (theta, psi) solved, near mid-face")
    # the library's parameterisation through psi = 0
    ps = np.r_[0.0, np.logspace(-12, -1, 12), -np.logspace(-12, -1, 12)]
    c = g.curvatures(np.full(ps.size, 7.0), ps)
    assert_honest_envelope(g, c.result)
    assert_finite_curvatures(c)
    assert np.all(c.result.converged)
    mc = meshing_condition(g, c.result)
    assert np.all(mc < 1e5)
    record_conditions(mc, "(l, psi) free, psi = 0, +-1e-12 .. 1e-1")
    for k in (c.k_s, c.k_q):
        d = np.abs(k[1:] - k[0])
        assert np.all(d <= np.abs(ps[1:]) / 0.1 * np.max(d[np.abs(ps[1:]) == 0.1]) + 1e-14)


@pytest.mark.parametrize("flank", ["R", "L"])
def test_envelope_limiting_line_near_face_ends(flank, record_conditions):
    """At the face ends (Z_f ~ +-20 mm, R_c = 110 mm) Litvin's limiting line crosses the last rows
    (hobcut_curvature ``undercut``): across it the determinant of Litvin's matrix changes sign once,
    the singular measure is smallest next to the change, and the curvature is largest there (it
    passes through infinity on the line). The meshing solve stays regular: every point converges
    with finite values (points beyond the line are envelope points the hob removes)."""
    g = GeneratedGear.flank(flank, R_c_mm=110.0)
    pe = np.arcsin(20.0 / 110.0)
    ls = np.linspace(9.6, 11.2, 33)
    conds = []
    for ps in (pe, -pe):
        c = g.curvatures(ls, ps)
        rec = c.result
        assert_honest_envelope(g, rec)
        assert_finite_curvatures(c)
        assert np.all(rec.converged)
        ch = np.flatnonzero(np.diff(np.sign(rec.litvin_det)) != 0)
        assert len(ch) == 1
        i = ch[0]
        assert np.argmin(rec.singular_measure) in (i, i + 1)
        kmax = np.maximum(np.abs(c.k_s), np.abs(c.k_q))
        assert np.argmax(kmax) in (i, i + 1)
        conds += [rec.solve.condition, meshing_condition(g, rec)]
        record_conditions(rec.singular_measure, f"Sigma_2{flank} psi={ps:+.3f}: Litvin measure (not a condition)")
    record_conditions(np.concatenate(conds), f"Sigma_2{flank}, across the limiting line")


# ---------------------------------------------------------------------------------------------
# 3b. the almost-line contact of the ideal R_cp = R_cg = 110 mm pair (seed 000 Table 5.2/5.3)
# ---------------------------------------------------------------------------------------------
def _outward_f(flank: tca.EnvelopeFlank, rot, x4):
    """Outward (out of the tooth) unit normal in S_f of a member at its parameters x4 (n, 4)."""
    r, _, n, _, _, _ = tca.envelope_member_geometry(flank, x4)
    R = flank.gear.to_tooth_frame  # tooth frame: the tooth centred on X (GeneratedGear.outward)
    rm, nm = r @ R.T, n @ R.T
    s = np.sign(np.sum(GeneratedGear.outward(rm, nm) * nm, -1))
    return s[:, None] * np.einsum("nab,nb->na", rot, n)


def _gap_at(pair, at, conf):
    """First-order normal gap (mm; < 0 = interference) at the tangency point of root ``at`` when the
    gear is at the phi2' of root ``conf`` (same phi1'): the rigid turn of the gear moves its flank
    by (phi2'_conf - phi2'_at) e_z x (r - O_g), measured along the pinion's outward normal."""
    n_out = _outward_f(pair.pinion, pair.pinion_rotation(at.phi1), at.x[:, :4])
    arm = np.cross([0.0, 0.0, 1.0], at.r_f - pair.gear_origin)
    return (conf.phi2 - at.phi2) * np.sum(arm * n_out, -1)


@pytest.fixture(scope="module")
def line_contact_roots():
    """The ideal 110/110 pair at phi1' = 0: the library's route (continuation from 110/113) and
    200 starts spread over the face (psi_p, psi_g, l_p, l_g perturbed)."""
    pair, sol = tca.hobbed_continue_to(TCA_GEARS, 110.0, 110.0, tca.HobbedAssembly())
    ref = tca.hobbed_ideal_start(tca.hobbed_pair(TCA_GEARS, 110.0, 113.0))
    rng = np.random.default_rng(0)
    n = 200
    x0 = np.repeat(ref.x, n, 0)
    x0[:, 3] += rng.uniform(-0.1, 0.1, n)
    x0[:, 7] += rng.uniform(-0.05, 0.05, n)
    x0[:, 0] += rng.normal(0.0, 0.3, n)
    x0[:, 4] += rng.normal(0.0, 0.3, n)
    roots = tca.solve_envelope_points(pair, np.zeros(n), x0)
    return pair, sol, roots


def _assert_honest_ke(r: tca.EnvelopeContactPath, tol=1e-11):
    assert set(np.unique(r.solve.status)) <= KNOWN
    ok = r.converged
    for name in ("x", "r_f", "n_p", "n_g", "Z_p", "Z_g", "radius_p", "radius_g", "cond"):
        assert np.all(np.isfinite(getattr(r, name)[ok])), name
    assert np.all(r.solve.residual[ok] < tol)
    # a true contact: opposite or equal normals (full cross product small, not only the two rows kept)
    assert np.all(np.linalg.norm(np.cross(r.n_p[ok], r.n_g[ok]), axis=1) < 1e-9)
    return ok


def test_line_contact_110_110_roots_are_tangencies(line_contact_roots, record_conditions):
    """Every converged root of the 9-unknown system for the ideal 110/110 pair is a genuine
    tangency (residual, full normal cross product, finite), the Jacobian condition (~2e6, vs
    ~1.6e4 for 110/113) reports the ill-conditioning, and the library's continuation lands on the
    mid-face pitch point (Z_p = 0). The roots are isolated (three: Z_p = 0 and a symmetric pair),
    not a continuum: the contact is almost, not exactly, a line."""
    pair, sol, roots = line_contact_roots
    assert np.all(_assert_honest_ke(sol))
    # the library returns the physical contact (hobcut_tca.physical_contact), one of the symmetric
    # pair Z_p = +-1.0967 mm, not the mid-face root a bare continuation lands on
    assert sol.n_tangencies[0] == 3 and abs(abs(sol.Z_p[0]) - 1.0967) < 1e-3
    ok = _assert_honest_ke(roots)
    assert ok.mean() > 0.9
    z = roots.Z_p[ok]
    centres = np.unique(np.round(z, 3))
    assert len(centres) <= 3 and np.any(np.abs(centres) < 1e-3)
    # orientation sanity of the gap test below: the members' outward normals are opposite at a contact
    n_p = _outward_f(pair.pinion, pair.pinion_rotation(sol.phi1), sol.x[:, :4])
    n_g = _outward_f(pair.gear, pair.gear_rotation(sol.phi2), sol.x[:, 4:8])
    np.testing.assert_allclose(n_p, -n_g, atol=1e-9)
    record_conditions(sol.cond, "110/110 continuation from 110/113")
    record_conditions(roots.cond, "110/110, 200 starts over the face")
    record_conditions(
        tca.hobbed_ideal_start(tca.hobbed_pair(TCA_GEARS, 110.0, 113.0)).cond, "110/113 ideal (reference)"
    )


def test_line_contact_110_110_returned_root_is_the_physical_contact(line_contact_roots):
    """Correct behaviour: the root the library returns has no interference at any other tangency of
    the same position (first-order normal gap >= -1e-9 mm, far below the paint thickness), i.e. its
    phi2' (hence KE) is the physical one within half a printed KE unit (0.0005 arcsec)."""
    pair, sol, roots = line_contact_roots
    ok = _assert_honest_ke(roots)
    others = roots.take(np.flatnonzero(ok))
    gap = _gap_at(pair, others, sol)
    assert np.all(gap >= -1e-9), gap.min()
    # the library's first-order gap (used to judge Table 5.2) agrees with this independent one
    np.testing.assert_allclose(tca.envelope_turn_gap(pair, others, sol.phi2), gap, rtol=1e-9, atol=1e-15)
    # the physical phi2' is the smallest of the tangencies (no interference at the others); the
    # interfering mid-face root is 0.001 arcsec away by nature, so it cannot be within 0.0005 of sol
    assert abs(others.phi2.min() - sol.phi2[0]) / ARCSEC < 0.0005


@pytest.mark.slow
def test_line_contact_110_110_along_the_path(record_conditions):
    """The ideal 110/110 path over phi1' = -10..10 deg (Table 5.2 range) from the library's route,
    then every point re-solved from 50 starts spread over the face: each start converges to a
    genuine tangency or is flagged; the condition numbers stay ~1e6 along the path."""
    case = {
        "R_cp_mm": 110.0,
        "R_cg_mm": 110.0,
        "dgamma_h_arcmin": 0.0,
        "dgamma_v_arcmin": 0.0,
        "dC_mm": 0.0,
        "dZ_mm": 0.0,
    }
    phi1 = np.radians(np.arange(-10.0, 10.1, 2.0))
    pair, path = ts.compute_case(TCA_GEARS, case, phi1)
    ok = _assert_honest_ke(path)
    assert np.all(ok)
    record_conditions(path.cond, "110/110 path -10..10 deg")
    rng = np.random.default_rng(2)
    n = 50
    x0 = np.repeat(path.x, n, 0)
    x0[:, 3] += rng.uniform(-0.1, 0.1, len(x0))
    x0[:, 7] += rng.uniform(-0.05, 0.05, len(x0))
    r = tca.solve_envelope_points(pair, np.repeat(phi1, n), x0)
    _assert_honest_ke(r)
    record_conditions(r.cond, "110/110 path, 50 starts per point")
