"""gearrep.surfaces.hob: ZA hob thread (seed 000 eq 4.40-4.48), the generated curvilinear gear
(two-parameter envelope) and the pair design (one hob, the two gears it cuts); the hob-cut pair's
TCA is tested in tests/unit/tca/test_hobbed.py."""

import numpy as np
import pytest
from _envelope_cases import HOB, ArchimedeanThread, hob_case

from gearrep.curvature import principal_curvatures
from gearrep.curvature_relations import generated_curvatures
from gearrep.envelope import Envelope
from gearrep.surface import RotatedSurface, fd_derivatives
from gearrep.surfaces.hob import FLANK_SIDE, GeneratedGear, HobThread, PairDesign, ZAHob, za_hob

L_GRID = np.linspace(4.3814841, 10.354, 5)


def test_hob_constants_table_5_1():
    h = ZAHob()
    assert np.degrees(h.lead_angle_rad) == pytest.approx(2.866, abs=5e-4)  # Table 5.1 prints 2.866 deg
    assert h.apex_radius_mm == pytest.approx(23.52641, abs=5e-6)  # reconstruction of docs/reading-notes.md 000-C
    assert h.lead_per_rad_mm == pytest.approx(3.0 / (2 * np.cos(h.lead_angle_rad)), rel=1e-15)
    assert h.beta_rad == 0.0 and ZAHob(variant="printed").beta_rad == h.lead_angle_rad


@pytest.mark.parametrize("variant", ["axial", "printed"])
@pytest.mark.parametrize("side", [1, -1])
def test_thread_derivatives_match_finite_differences(variant, side):
    t = ZAHob(variant=variant).thread(side)
    l, p = np.meshgrid(np.linspace(3.0, 11.0, 4), np.linspace(2.5, 3.8, 3))
    a = t.evaluate(l, p)
    d = fd_derivatives(t.position, l, p, 1e-3, 1e-3)
    # 4th-order differences with h = 1e-3 on |r| ~ 30 mm: rounding ~ eps |r| / h (first
    # derivatives) and ~ eps |r| / h^2 ~ 1e-8 (second derivatives), truncation ~ h^4
    for name, tol in (("r", 0.0), ("r_u", 1e-9), ("r_v", 1e-9), ("r_uu", 1e-7), ("r_uv", 1e-7), ("r_vv", 1e-7)):
        np.testing.assert_allclose(getattr(a, name), getattr(d, name), atol=tol, rtol=0, err_msg=name)
    assert np.all(a.r_uu == 0.0)  # eq 4.46


def test_axial_variant_is_the_straight_axial_line():
    """The axial variant equals the reference Archimedean thread of the test cases (alpha -> side
    alpha), and its axial sections are straight lines at alpha_n."""
    h = ZAHob()
    l, p = np.meshgrid(np.linspace(3.0, 11.0, 4), np.linspace(2.5, 3.8, 3))
    for side in (1, -1):
        ref = ArchimedeanThread(h.apex_radius_mm, side * h.pressure_angle_rad, h.lead_per_rad_mm)
        a, b = h.thread(side).evaluate(l, p), ref.evaluate(l, p)
        for name in ("r", "r_u", "r_v", "r_uv", "r_vv"):
            np.testing.assert_allclose(getattr(a, name), getattr(b, name), atol=1e-13)
    # the printed variant differs from it (tilted profile line) by l sin(alpha) sin(beta)-sized terms
    d = ZAHob(variant="printed").thread(1).position(10.0, 3.0) - h.thread(1).position(10.0, 3.0)
    assert 0.1 < np.linalg.norm(d) < 0.3


def test_thread_principal_curvatures():
    """The axial variant's profile is straight: the principal curvature along the profile
    direction r_l is 0 only if r_l is principal; in any case K <= 0 (a ruled surface)."""
    pc = ZAHob().thread(1).principal(np.array([4.0, 8.0]), np.array([3.0, 3.1]))
    assert np.all(pc.k1 * pc.k2 <= 1e-15)
    np.testing.assert_allclose(np.cross(pc.e1, pc.e2), pc.normal, atol=1e-14)


def test_tip_row_and_tooth_symmetry():
    g = GeneratedGear.flank("R")
    lt = g.l_at_radius(33.0)
    assert lt.status[0] == 0 and lt.x[0, 0] == pytest.approx(4.38148, abs=5e-6)  # docs/reading-notes.md 000-C: 4.38148
    pR, nR, recR = GeneratedGear.flank("R").points(L_GRID, 0.0)
    pL, nL, recL = GeneratedGear.flank("L").points(L_GRID, 0.0)
    assert np.all(recR.converged) and np.all(recL.converged)
    # tooth frame: the tooth is symmetric about X_f; R on +Y_f, L on -Y_f, mid-face Z_f = 0
    np.testing.assert_allclose(pR[:, :2], pL[:, :2] * [1, -1], atol=1e-10)
    assert np.all(pR[:, 1] > 0) and np.all(np.abs(pR[:, 2]) < 1e-12)
    # tooth half-thickness angle at the tip of a standard 20-tooth, m = 3, 20 deg involute: 1.80 deg
    assert np.degrees(np.arctan2(pR[0, 1], pR[0, 0])) == pytest.approx(1.80, abs=0.01)


def test_convex_and_concave_flanks():
    """Seed 000 sec 4.5: Sigma_2R elliptic (k_s k_q > 0), Sigma_2L hyperbolic; e_s along Z_f at
    mid-face, e_q in the X_f-Y_f plane; only k_s depends on R_c."""
    out = {}
    for name in "RL":
        for Rc in (110.0, 5000.0):
            c = GeneratedGear.flank(name, R_c_mm=Rc).curvatures(L_GRID)
            assert np.all(c.result.converged) and not np.any(c.result.singular)
            np.testing.assert_allclose(c.e_s, np.tile([0, 0, 1.0], (len(L_GRID), 1)), atol=1e-12)
            np.testing.assert_allclose(c.e_q[:, 2], 0.0, atol=1e-12)
            out[name, Rc] = c
        assert np.all(out[name, 110.0].k_s * out[name, 110.0].k_q > 0) == (name == "R")
        np.testing.assert_allclose(out[name, 110.0].k_q, out[name, 5000.0].k_q, rtol=1e-10)
    np.testing.assert_allclose(out["R", 110.0].k_q, -out["L", 110.0].k_q, rtol=1e-10)  # steep near the root
    # |k_s| ~ cos(alpha)/R_c order
    assert np.all(np.abs(out["R", 5000.0].k_s * 5000 - 0.94) < 0.01)


@pytest.mark.parametrize("name", ["R", "L"])
def test_direct_geometry_agrees_with_envelope_relations(name):
    """Curvatures two ways: (a) differential geometry of the generated surface
    r(l, psi); (b) K_2 = K_1 + C E^-1 C^T and the chapter's corrected eq 4.33-4.39 / 4.24-4.26."""
    g = GeneratedGear.flank(name)
    l = np.array([4.5, 7.0, 10.0, 6.0])
    ps = np.array([-0.15, 0.0, 0.15, 0.05])
    c = g.curvatures(l, ps)
    pc = principal_curvatures(g.surface().evaluate(l, ps))
    s = np.sign(np.sum(pc.normal * c.normal, -1))
    direct = np.sort(np.c_[s * pc.k1, s * pc.k2], 1)
    np.testing.assert_allclose(direct, np.sort(np.c_[c.k_s, c.k_q], 1), rtol=1e-7)
    np.testing.assert_allclose(
        np.sort(np.c_[c.k_s_two_parameter, c.k_q_two_parameter], 1), np.sort(np.c_[c.k_s, c.k_q], 1), rtol=1e-10
    )


def test_far_from_mid_face_marches():
    g = GeneratedGear.flank("L", R_c_mm=110.0)
    rec = g.solve(np.array([5.0, 9.0]), np.array([-0.19, 0.19]))
    assert np.all(rec.converged)
    assert np.all(np.abs(rec.point[:, 2]) > 19.0)


def test_hob_case_is_the_other_arc_centre():
    """tests/unit/_envelope_cases.py::hob_case = arc_centre +1, side +1: its k_s is the concave
    flank's (the reason it reproduces k_q but not k_s of Table 4.3)."""
    tool, motion = hob_case()
    env = Envelope(tool, motion, free=("u", "psi"))
    rec = env.solve(L_GRID, 0 * L_GRID, guess=[np.pi, 0.0])
    gc = generated_curvatures(env, rec.params)
    mine = GeneratedGear(side=1, arc_centre=1, R_c_mm=HOB["R_c"]).curvatures(L_GRID)
    np.testing.assert_allclose(np.sort(np.c_[gc.k1, gc.k2], 1), np.sort(np.c_[mine.k_s, mine.k_q], 1), rtol=1e-10)
    conv = GeneratedGear.flank("R").curvatures(L_GRID)
    np.testing.assert_allclose(conv.k_q, mine.k_q, rtol=1e-10)  # near the root k_q is ill-conditioned
    assert np.all(mine.k_s < 0) and np.all(conv.k_s > 0)


def test_printed_variant_differs():
    """Eq 4.40 as printed (beta = lead angle in the profile terms) gives other curvatures."""
    a = GeneratedGear.flank("R").curvatures(np.array([5.0, 10.0]))
    p = GeneratedGear(hob=ZAHob(variant="printed"), side=1).curvatures(np.array([5.0, 10.0]))
    assert np.all(p.result.converged)
    # close (docs/reading-notes.md 000-C: within ~1e-4) but beyond the tables' 6 printed decimals
    rel = np.abs(p.k_q / a.k_q - 1)
    assert np.all((rel > 1e-5) & (rel < 1e-3))


def test_surface_frames():
    g = GeneratedGear.flank("R")
    st, sg = g.surface("tooth"), g.surface("generation")
    assert isinstance(st, RotatedSurface)
    np.testing.assert_allclose(st.position(6.0, 0.05), sg.position(6.0, 0.05) @ g.to_tooth_frame.T, atol=1e-12)
    with pytest.raises(ValueError, match="frame"):
        g.surface("other")


def test_validation():
    with pytest.raises(ValueError, match="module_mm"):
        ZAHob(module_mm=-1)
    with pytest.raises(ValueError, match="pressure_angle_rad"):
        ZAHob(pressure_angle_rad=2.0)
    with pytest.raises(ValueError, match="variant"):
        ZAHob(variant="zn")
    with pytest.raises(ValueError, match="pitch_radius_mm"):
        ZAHob(pitch_radius_mm=1.0)
    with pytest.raises(ValueError, match="side"):
        HobThread(ZAHob(), 0)
    with pytest.raises(ValueError, match="R_c_mm"):
        GeneratedGear(R_c_mm=0.0)
    with pytest.raises(ValueError, match="R_c_mm"):
        GeneratedGear(R_c_mm=float("nan"))
    with pytest.raises(ValueError, match="n_teeth"):
        GeneratedGear(n_teeth=2)
    with pytest.raises(ValueError, match="arc_centre"):
        GeneratedGear(arc_centre=0)
    with pytest.raises(ValueError, match="'R' or 'L'"):
        GeneratedGear.flank("X")
    with pytest.raises(ValueError, match="radius_mm"):
        GeneratedGear().l_at_radius(-1.0)
    assert FLANK_SIDE == {"R": 1, "L": -1}


def test_spur_limit():
    """R_c = inf: straight teeth (k_s = 0), the same mid-face profile curvature k_q; R_c k_s
    approaches a finite limit as R_c grows."""
    spur = GeneratedGear.flank("R", R_c_mm=np.inf).curvatures(L_GRID)
    big = GeneratedGear.flank("R", R_c_mm=1e6).curvatures(L_GRID)
    assert np.all(spur.result.converged)
    np.testing.assert_allclose(spur.k_s, 0.0, atol=1e-13)
    np.testing.assert_allclose(spur.k_q, big.k_q, rtol=1e-10)
    p, _, _ = GeneratedGear.flank("R", R_c_mm=np.inf).points(6.0, 5.0)
    assert p[0, 2] == pytest.approx(5.0, abs=1e-9)
    assert np.all(np.abs(big.k_s * 1e6 - 0.94) < 0.01)


def test_wrong_root_is_flagged():
    """A root on a far branch of the meshing equations (start (0, 0): the thread on the far side of
    the hob, ~180 mm from the gear axis) is reported as WRONG_ROOT, not as converged."""
    g = GeneratedGear.flank("R")
    rec = g.solve(np.array([5.0, 8.0]), 0.0, guess=[0.0, 0.0])
    assert np.all(rec.status == 4)  # Status.WRONG_ROOT
    assert np.all(g.solve(np.array([5.0, 8.0]), 0.0).converged)
    assert GeneratedGear(R_c_mm=50.0).effective_tol == g.tol
    assert GeneratedGear(R_c_mm=5000.0).effective_tol == pytest.approx(50 * g.tol)


def test_za_hob_and_pair_design():
    hob = za_hob(3.0, 20.0, 30.0, "printed")
    assert hob == ZAHob(3.0, float(np.radians(20.0)), 30.0, "printed")
    with pytest.raises(ValueError, match="pressure_angle_deg"):
        za_hob(3.0, 95.0, 30.0)
    with pytest.raises(ValueError, match="n_gear"):
        PairDesign(20, 3, 40.0, hob)
    d = PairDesign(20, 40, 40.0, hob)
    pin, gear = d.cut(110.0, 113.0)
    assert (pin.n_teeth, pin.R_c_mm, pin.arc_centre) == (20, 110.0, -1)
    assert (gear.n_teeth, gear.R_c_mm, gear.arc_centre) == (40, 113.0, 1)
    with pytest.raises(ValueError, match="R_cg_mm"):
        d.cut(110.0, -1.0)
    assert d.with_hob(pitch_radius_mm=40.0).hob.pitch_radius_mm == 40.0
