"""Involute spur/helical flanks (thesis seed 003 eq 1-5, 10-13, 57-58, Table 1) and the corrections."""

import numpy as np
import pytest

from gearrep.surface import fd_derivatives
from gearrep.surfaces.involute import (
    CircularCrowning,
    InvoluteFlank,
    InvoluteGearData,
    LogarithmicCrowning,
    ParabolicCrowning,
    RootRelief,
    TipRelief,
    involute_polar_angle,
    involute_xy,
    mating_flanks,
    standard_centre_distance,
)

D = np.radians


def spur(n=25, m=2.5, b=25.0, **kw):
    return InvoluteGearData(n, m, D(20), b, **kw)


def helical(n=40, m=1.0, b=20.0, beta=14.0, **kw):
    return InvoluteGearData(n, m, D(20), b, helix_angle=D(beta), **kw)


# ---------------------------------------------------------------------------------------------
# analytic derivatives
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("form", ["true", "asin"])
@pytest.mark.parametrize("side", [1, -1])
@pytest.mark.parametrize("crown", [None, "par", "circ", "log"])
def test_analytic_derivatives_match_finite_differences(form, side, crown):
    g = helical(25, 2.5, 25.0)
    cr = {
        None: None,
        "par": ParabolicCrowning(0.003, 1e-3, 2e-3, v0=1.0),
        "circ": CircularCrowning(0.05, 25.0),
        "log": LogarithmicCrowning(0.02, 0.6, 12.5),
    }[crown]
    rel = [TipRelief(g.r_p + 1.0, 1.5, 0.02), RootRelief(g.r_p - 1.0, 1.0, 0.01)]
    f = InvoluteFlank(g, side, -1, crowning=cr, relief=rel, helix_form=form)
    u = np.array([g.r_p - 1.7, g.r_p - 0.4, g.r_p + 0.6, g.r_p + 2.0])
    v = np.array([-9.0, -2.0, 3.0, 10.0])
    a = f.evaluate(u, v)
    b = fd_derivatives(f.position, u, v, 1e-3, 1e-3)
    for name, tol in (("r", 1e-13), ("r_u", 1e-10), ("r_v", 1e-10), ("r_uu", 1e-6), ("r_uv", 1e-6), ("r_vv", 1e-6)):
        assert np.max(np.abs(getattr(a, name) - getattr(b, name))) < tol, name


def test_u_is_radius_and_v_is_axial_coordinate():
    """Eq (35)-(36): u = distance from the axis, v = axial coordinate (needed by the reduced TCA)."""
    g = helical()
    f = InvoluteFlank(g, 1, 1, crowning=ParabolicCrowning(0.01), relief=[TipRelief(g.r_p, 0.5, 0.01)])
    u = np.linspace(f.u_min + 1e-6, f.u_max, 7)[:, None]
    v = np.linspace(f.v_min, f.v_max, 5)[None, :]
    r = f.position(u, v)
    assert np.allclose(np.hypot(r[..., 0], r[..., 1]), u, rtol=0, atol=1e-13)
    assert np.array_equal(r[..., 2], np.broadcast_to(v, r.shape[:2]))


def test_thesis_eq_3_4_is_the_involute_polar_angle():
    """acos((r_b/u)(cos t + t sin t)) of eq (4) equals inv(u) = tan(a) - a, cos(a) = r_b/u."""
    rb = 29.3655
    u = np.linspace(rb, 1.3 * rb, 50)
    t = np.sqrt(u**2 / rb**2 - 1.0)
    eq4 = np.arccos(np.clip(rb / u * (np.cos(t) + t * np.sin(t)), -1, 1))
    assert np.allclose(eq4, involute_polar_angle(u, rb), atol=1e-7)  # acos loses digits near 0
    a = np.arccos(rb / u)
    assert np.allclose(involute_polar_angle(u, rb), np.tan(a) - a, atol=1e-15)
    # the side = -1 flank with c = 0 is eq (3)-(4)
    f = InvoluteFlank(spur(), -1)
    assert np.allclose(f.polar_angle(u[1:], 0.0) + f.c, involute_polar_angle(u[1:], f.r_b), atol=1e-15)


# ---------------------------------------------------------------------------------------------
# corrections to the thesis, with evidence
# ---------------------------------------------------------------------------------------------
def test_correction_1_y_component_of_eq_1():
    rb = 10.0
    t = np.linspace(0, 1.2, 13)
    good = involute_xy(t, rb)
    bad = involute_xy(t, rb, corrected=False)
    # eq (2): the point at roll angle t has radius u = r_b sqrt(1 + t^2)
    assert np.allclose(np.hypot(*good.T), rb * np.sqrt(1 + t**2), atol=1e-12)
    assert np.isclose(np.hypot(*bad[0]), np.sqrt(2) * rb)  # printed form starts off the base circle
    assert np.max(np.abs(np.hypot(*bad.T) - rb * np.sqrt(1 + t**2))) > 1.0
    # the thesis's own pitch-point example (sec. 6.1: 25/25 teeth, m = 2.5, 20 deg) is consistent
    # with a true involute: u1 and u2 are the radii of one point of the line of action
    g = spur()
    a = standard_centre_distance(g, g)
    u1, u2 = 31.103, 31.402
    s = np.sqrt(u1**2 - g.r_b**2) + np.sqrt(u2**2 - g.r_b**2)
    # printed to 3 decimals: |ds| <= 0.0005 (u1/s1 + u2/s2) ~ 0.003
    assert abs(s - a * np.sin(D(20))) < 0.003


def test_correction_2_tip_diameter_of_table_1():
    from gearrep.meshing import contact_ratio_closed_form

    g1, g2 = InvoluteGearData(52, 1.0, D(20), 11.42), InvoluteGearData(72, 1.0, D(20), 11.42)
    a = standard_centre_distance(g1, g2)
    assert np.isclose(g1.r_a, 0.5 * (52 + 2)) and np.isclose(g2.r_a, 0.5 * (72 + 2))
    good = contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, a, g1.base_pitch)
    assert 1.7 < good < 1.9
    # printed: d_a = d_b + 2m -> tip inside the pitch circle and a negative contact ratio
    ra1_p, ra2_p = g1.r_b + 1.0, g2.r_b + 1.0
    assert ra1_p < g1.r_p
    bad = (np.sqrt(ra1_p**2 - g1.r_b**2) + np.sqrt(ra2_p**2 - g2.r_b**2) - a * np.sin(D(20))) / g1.base_pitch
    assert bad < 0


def test_correction_3_eq_5_is_not_a_helicoid():
    g = helical()  # thesis Table 2 gear: 40 teeth, m = 1, 20 deg, 14 deg helix
    true = InvoluteFlank(g, 1, 1)
    thes = InvoluteFlank(g, 1, 1, helix_form="asin")
    # helix angle at the pitch cylinder: true helicoid gives beta, eq (5) gives atan(sin b / cos a_t)
    assert np.isclose(true.helix_angle_at(g.r_p), D(14), atol=1e-15)
    bt = thes.helix_angle_at(g.r_p)
    assert np.isclose(bt, np.arctan(np.sin(D(14)) / np.cos(g.alpha_t)), atol=1e-15)
    assert np.degrees(bt) - 14.0 > 0.45
    # constant lead: the twist is linear in v for the helicoid, not for eq (5)
    v = np.linspace(-10, 10, 21)
    for f, linear in ((true, True), (thes, False)):
        tw = f.polar_angle(g.r_p, v) - f.polar_angle(g.r_p, 0.0)
        dev = np.max(np.abs(tw - v * (tw[-1] - tw[0]) / 20.0))
        assert (dev < 1e-15) if linear else (dev > 1e-6)
    # eq (5) is undefined beyond |v| = r_b / sin(beta)
    with np.errstate(invalid="ignore"):
        assert np.isnan(thes.polar_angle(g.r_p, 1.01 * g.r_b / np.sin(D(14))))
    # the thesis's Table 2 centre distance 39.67 implies a NORMAL module: (40+37) m_n / (2 cos 14)
    assert np.isclose(standard_centre_distance(g, helical(37)), 39.67, atol=0.01)


def test_correction_4_modification_is_a_normal_offset():
    """A uniform thinning c3 moves the spur flank by exactly c3 along its normal (rotation by c3/r_b)."""
    g = spur()
    c3 = 0.01
    f0 = InvoluteFlank(g, 1)
    f1 = InvoluteFlank(g, 1, crowning=ParabolicCrowning(0.0, 0.0, c3))
    u = np.linspace(f0.u_min + 0.3, f0.u_max, 9)
    p = f1.position(u, 0.0)
    q = p + c3 * f1.outward_normal(u, 0.0)  # back out along the outward normal by c3
    rq = np.hypot(q[:, 0], q[:, 1])
    assert np.allclose(np.arctan2(q[:, 1], q[:, 0]), f0.polar_angle(rq, 0.0), atol=1e-14)
    # for the helical flank the 3-D normal offset is c3 cos(beta_b)
    gh = helical(25, 2.5, 25.0)
    h0, h1 = InvoluteFlank(gh, 1, 1), InvoluteFlank(gh, 1, 1, crowning=ParabolicCrowning(0.0, 0.0, c3))
    p = h1.position(gh.r_p, 2.0)
    q = p + c3 * np.cos(gh.beta_b) * h1.outward_normal(gh.r_p, 2.0)
    assert np.isclose(np.arctan2(q[1], q[0]), h0.polar_angle(np.hypot(q[0], q[1]), q[2]), atol=1e-13)


# ---------------------------------------------------------------------------------------------
# modifications (eq 10-13)
# ---------------------------------------------------------------------------------------------
def test_crowning_functions():
    b = 20.0
    par = ParabolicCrowning(0.0227)
    d, d1, d2 = par(np.array([-10.0, 0.0, 10.0]))
    assert np.allclose(d, [2.27, 0, 2.27]) and np.allclose(d2, 0.0454)
    circ = CircularCrowning(2.398, b)
    assert np.isclose(circ.radius, (4 * 2.398**2 + b**2) / (8 * 2.398))
    d, d1, d2 = circ(np.array([-10.0, 0.0, 10.0]))
    assert np.allclose(d, [2.398, 0.0, 2.398], atol=1e-13) and d1[1] == 0 and np.isclose(d2[1], 1 / circ.radius)
    log = LogarithmicCrowning(2.515, 0.6, b / 2)
    d, d1, d2 = log(np.array([-10.0, 0.0, 10.0]))
    assert np.allclose(d, [2.515 * np.log(1 / 0.4), 0, 2.515 * np.log(1 / 0.4)])
    for cr in (par, circ, log, ParabolicCrowning(0.01, 0.002, 0.1, 1.0)):
        v = np.linspace(-9, 9, 7)
        h = 1e-5
        dp, dm = cr(v + h)[0], cr(v - h)[0]
        assert np.allclose(cr(v)[1], (dp - dm) / (2 * h), atol=1e-7)
        assert np.allclose(cr(v)[2], (cr(v + h)[1] - cr(v - h)[1]) / (2 * h), atol=1e-6)


def test_tip_and_root_relief_eq_13():
    tr = TipRelief(30.0, 0.6, 0.4)
    d, d1, d2 = tr(np.array([29.0, 30.0, 30.3, 30.6]))
    assert np.allclose(d, [0, 0, 0.1, 0.4]) and np.allclose(d1[:2], 0) and np.allclose(d2[2:], 2 * 0.4 / 0.36)
    rr = RootRelief(28.0, 0.4, 0.4)
    d, d1, _ = rr(np.array([27.6, 27.8, 28.0, 29.0]))
    assert np.allclose(d, [0.4, 0.1, 0, 0]) and d1[0] < 0


def test_outward_normal_points_out_of_the_tooth():
    for g in (spur(), helical()):
        for side in (1, -1):
            f = InvoluteFlank(g, side, 1)
            u = np.linspace(f.u_min + 0.2, f.u_max, 5)
            v = np.linspace(-5, 5, 5)
            p = f.position(u, v)
            q = p + 1e-4 * f.outward_normal(u, v)
            rq = np.hypot(q[:, 0], q[:, 1])
            beyond = side * (np.arctan2(q[:, 1], q[:, 0]) - f.polar_angle(rq, q[:, 2]))
            assert np.all(beyond > 0)  # farther from the tooth centre than the flank: outside


def test_gear_data_and_bounds():
    g = helical(37)
    assert np.isclose(g.alpha_t, np.arctan(np.tan(D(20)) / np.cos(D(14))))
    assert np.isclose(g.r_b, g.r_p * np.cos(g.alpha_t))
    assert np.isclose(np.tan(g.beta_b), np.tan(D(14)) * np.cos(g.alpha_t))
    f = InvoluteFlank(g)
    assert np.allclose(f.lower, [max(g.r_b, g.r_f), -10]) and np.allclose(f.upper, [g.r_a, 10])
    assert f.contains(g.r_p, 0.0) and not f.contains(g.r_a + 0.1, 0.0) and not f.contains(g.r_p, 10.5)
    # base circle above the root circle for few teeth: u_min = r_b
    g20 = InvoluteGearData(20, 3.0, D(20), 10)
    assert InvoluteFlank(g20).u_min == pytest.approx(g20.r_b)
    # zero-backlash standard teeth: half the pitch at the pitch circle
    assert np.isclose(g.tooth_thickness, np.pi * g.transverse_module / 2)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(n_teeth=2), "n_teeth"),
        (dict(module=0.0), "module"),
        (dict(pressure_angle=2.0), "pressure_angle"),
        (dict(face_width=-1.0), "face_width"),
        (dict(helix_angle=-0.1), "helix_angle"),
    ],
)
def test_gear_data_validation(kwargs, name):
    base = dict(n_teeth=20, module=1.0, pressure_angle=D(20), face_width=10.0)
    base.update(kwargs)
    with pytest.raises(ValueError, match=name):
        InvoluteGearData(**base)


def test_flank_and_modification_validation():
    g = spur()
    with pytest.raises(ValueError, match="side"):
        InvoluteFlank(g, 0)
    with pytest.raises(ValueError, match="hand"):
        InvoluteFlank(g, 1, 2)
    with pytest.raises(ValueError, match="helix_form"):
        InvoluteFlank(g, helix_form="approx")
    with pytest.raises(ValueError, match="u_min"):
        InvoluteFlank(g, u_min=g.r_b - 1)
    with pytest.raises(ValueError, match="u_max"):
        InvoluteFlank(g, u_max=g.r_b)
    with pytest.raises(ValueError, match="relief"):
        InvoluteFlank(g, relief=[ParabolicCrowning(0.1)])
    with pytest.raises(ValueError, match="a2"):
        LogarithmicCrowning(1.0, 1.0, 5.0)
    with pytest.raises(ValueError, match="crown"):
        CircularCrowning(6.0, 10.0)
    with pytest.raises(ValueError, match="length"):
        TipRelief(30.0, 0.0, 0.1)
    with pytest.raises(ValueError, match="module"):
        mating_flanks(spur(m=2.5), spur(m=2.0))
    with pytest.raises(ValueError, match="r_b"):
        involute_polar_angle(30.0, -1.0)


def test_mating_flanks_have_opposite_hands():
    f1, f2 = mating_flanks(helical(40), helical(37), hand1=1)
    assert (f1.hand, f2.hand) == (1, -1) and f1.side == f2.side == 1
    with np.errstate(invalid="ignore"):
        assert np.isnan(f1.position(f1.r_b * 0.9, 0.0)).any()  # inside the base circle: no involute


@pytest.mark.parametrize("cls", [TipRelief, RootRelief])
def test_a_relief_too_short_for_its_curvature_is_refused(cls):
    """L**2 underflows (or amount / L**2 overflows): refused, naming the length, instead of a
    division by zero at the first point."""
    with pytest.raises(ValueError, match=r"^length: got 1e-300"):
        cls(20.0, 1e-300, 0.5)
    with pytest.raises(ValueError, match=r"^length: got 1e-160"):
        cls(20.0, 1e-160, 0.5)
    u = 20.0005 if cls is TipRelief else 19.9995  # inside a 1 um relief of 5 mm: a finite curvature
    assert cls(20.0, 1e-3, 5.0)(u)[2] == pytest.approx(2 * 5.0 / 1e-3**2, rel=1e-12)
