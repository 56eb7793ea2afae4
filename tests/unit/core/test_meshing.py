"""Meshing cycle: engagement limits, contact ratio (seed 000 eq 5.13 corrected), TE envelope."""

import numpy as np
import pytest

from gearrep.meshing import (
    contact_ratio,
    contact_ratio_closed_form,
    engagement_limits,
    meshing_cycle,
)
from gearrep.solve import Status
from gearrep.surfaces.involute import (
    InvoluteGearData,
    ParabolicCrowning,
    TipRelief,
    mating_flanks,
    standard_centre_distance,
)
from gearrep.tca import GearPair, Misalignment, solve_contact
from gearrep.units import ARCSEC

D = np.radians


def make_pair(n1, n2, m=1.0, b=10.0, beta=0.0, alpha=20.0, d_E=0.0, **kw):
    g1 = InvoluteGearData(n1, m, D(alpha), b, helix_angle=D(beta))
    g2 = InvoluteGearData(n2, m, D(alpha), b, helix_angle=D(beta))
    f1, f2 = mating_flanks(g1, g2, **kw)
    a = standard_centre_distance(g1, g2) + d_E
    return GearPair(f1, f2, n1, n2, a), g1, g2


def closed_form(pair, g1, g2):
    return contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, pair.centre_distance, g1.base_pitch)


@pytest.mark.parametrize(
    "n1, n2, m, alpha", [(52, 72, 1.0, 20.0), (25, 25, 2.5, 20.0), (20, 40, 3.0, 20.0), (17, 77, 2.0, 25.0)]
)
def test_spur_contact_ratio_equals_closed_form(n1, n2, m, alpha):
    """(sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2) - a sin(alpha)) / (pi m cos(alpha)) to 1e-6."""
    pair, g1, g2 = make_pair(n1, n2, m=m, alpha=alpha)
    b, e = engagement_limits(pair, -np.pi / (2 * n1), v1=0.0)
    assert (b.boundary, e.boundary) == ("u2_max", "u1_max")  # gear tip at the start, pinion tip at the end
    mc = contact_ratio(b.phi1, e.phi1, n1)
    a, ra1, rb1, ra2, rb2 = pair.centre_distance, g1.r_a, g1.r_b, g2.r_a, g2.r_b
    ref = (np.sqrt(ra1**2 - rb1**2) + np.sqrt(ra2**2 - rb2**2) - a * np.sin(D(alpha))) / (np.pi * m * np.cos(D(alpha)))
    assert abs(mc - ref) < 1e-6
    assert abs(mc - closed_form(pair, g1, g2)) < 1e-6
    # the limits are contacts on the tips
    assert b.contact.u2[0] == pytest.approx(g2.r_a, abs=1e-9) and e.contact.u1[0] == pytest.approx(g1.r_a, abs=1e-9)
    assert b.contact.status[0] == Status.CONVERGED and e.contact.status[0] == Status.CONVERGED


def test_printed_eq_5_13_divides_by_a_full_turn():
    """Eq (5.13) as printed, (phi_1E - phi_1B)/360 deg, is the corrected value divided by N1: for the
    seed-000 example (T_p = 20, m_c = 1.62) it would give 0.081."""
    pair, g1, g2 = make_pair(20, 40, m=3.0)
    b, e = engagement_limits(pair, -np.pi / 40, v1=0.0)
    corrected = contact_ratio(b.phi1, e.phi1, 20)
    printed = (e.phi1 - b.phi1) / (2 * np.pi)
    assert printed == pytest.approx(corrected / 20)
    assert 1.5 < corrected < 1.7 and printed < 0.1


def test_nonstandard_centre_distance_and_helical_transverse_section():
    # centre distance increased: working pressure angle alpha_w, cos(alpha_w) = (rb1 + rb2)/a
    pair, g1, g2 = make_pair(30, 45, m=2.0, d_E=0.3)
    b, e = engagement_limits(pair, -np.pi / 60, v1=0.0)
    assert abs(contact_ratio(b.phi1, e.phi1, 30) - closed_form(pair, g1, g2)) < 1e-6
    # helical pair, line contact, transverse section v1 = 0: the transverse contact ratio eps_alpha
    pair, g1, g2 = make_pair(40, 37, b=20.0, beta=14.0)
    b, e = engagement_limits(pair, -np.pi / 80, v1=0.0)
    assert abs(contact_ratio(b.phi1, e.phi1, 40) - closed_form(pair, g1, g2)) < 1e-6


def test_aligned_conjugate_cycle_has_indeterminate_transfer():
    pair, g1, g2 = make_pair(52, 72, b=11.42)
    cyc = meshing_cycle(pair, -np.pi / 104, v1=0.0, n_points=21)
    assert abs(cyc.contact_ratio - closed_form(pair, g1, g2)) < 1e-6
    assert cyc.transfer_kind == "indeterminate" and np.isnan(cyc.transfer_out)
    assert np.max(np.abs(cyc.te)) / ARCSEC < 1e-9


def test_tip_relief_transfer_points_and_te_envelope():
    """Equal gears with equal tip relief: TE curves of neighbouring pairs cross at the transfer point;
    the real cycle is one angular pitch between transfer points and the envelope is continuous."""
    g = InvoluteGearData(25, 2.5, D(20), 25.0)
    rel = [TipRelief(g.r_p + 0.5, g.r_a - g.r_p - 0.5, 0.01)]
    f1, f2 = mating_flanks(g, g, relief1=rel, relief2=rel)
    pair = GearPair(f1, f2, 25, 25, standard_centre_distance(g, g))
    p1 = 2 * np.pi / 25
    cyc = meshing_cycle(pair, -np.pi / 50, v1=0.0, n_points=41)
    assert cyc.transfer_kind == "crossing"
    assert cyc.transfer_out - cyc.transfer_in == pytest.approx(p1, abs=1e-15)
    # at the transfer point the outgoing and incoming pairs have the same TE
    c = solve_contact(pair, [cyc.transfer_out, cyc.transfer_out - p1], v1=0.0)
    assert np.all(c.converged) and abs(c.te[0] - c.te[1]) < 1e-13
    # symmetric pair: the TE of one pair is symmetric about the pitch-point position up to the
    # phi1 <-> phi2 swap, so the transfer is within 1e-3 pitch of the symmetric estimate
    assert abs(cyc.transfer_out - (-np.pi / 50 + p1 / 2)) < 1e-3 * p1
    # envelope: continuous, the outgoing pair at the start, pair 0 in the middle
    assert np.max(np.abs(np.diff(cyc.te))) < 0.2 * np.ptp(cyc.te)
    assert cyc.pair_index[len(cyc.phi1) // 2] == 0
    assert np.all(cyc.te <= 1e-15)  # relief only removes material: member 2 lags
    # peak-to-peak is bounded by the relief at the tip, amount / r_b
    assert 0 < cyc.te_peak_to_peak < 0.01 / g.r_b
    print(
        f"\ntip-relief TE over the real cycle: peak-to-peak {cyc.te_peak_to_peak / ARCSEC:.4f} arcsec, "
        f"contact ratio {cyc.contact_ratio:.6f}"
    )


def test_crowned_misaligned_cycle_transfers_at_engagement_or_exit():
    """A crowned pinion with an in-plane error: TE is nearly constant with a small slope, so one pair
    leads over the whole overlap and the transfer happens at an engagement limit (TE jumps)."""
    pair, g1, g2 = make_pair(52, 72, b=11.42, crowning1=ParabolicCrowning(0.002857))
    pair = pair.with_misalignment(Misalignment(d_gamma_in=D(0.05)))
    cyc = meshing_cycle(pair, -np.pi / 104, n_points=21)
    assert cyc.transfer_kind in ("at_engagement", "at_exit")
    assert abs(cyc.contact_ratio - closed_form(pair, g1, g2)) < 1e-3  # point contact at z* ~ 0.1 mm
    assert np.all(np.isfinite(cyc.te)) and np.all(cyc.te > 0)


def test_validation():
    pair, g1, g2 = make_pair(20, 30)
    with pytest.raises(ValueError, match="n1"):
        contact_ratio(0.0, 1.0, 0)
    with pytest.raises(ValueError, match="centre_distance"):
        contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, 1.0, g1.base_pitch)
    with pytest.raises(ValueError, match="r_b1"):
        contact_ratio_closed_form(1.0, -1.0, 1.0, 1.0, 3.0, 1.0)
    with pytest.raises(ValueError, match="n_points"):
        meshing_cycle(pair, v1=0.0, n_points=3)
    with pytest.raises(ValueError, match="step"):
        engagement_limits(pair, v1=0.0, step=-1.0)
    with pytest.raises(ValueError, match="no contact"):
        engagement_limits(pair, 1.0, v1=0.0)


# ---------------------------------------------------------------------------------------------
# upper envelope of sampled per-tooth TE curves (pair_te_curves, upper_envelope, handover_jump)
# ---------------------------------------------------------------------------------------------
def test_envelope_of_parabolic_pair_curves_hands_over_at_the_crossing():
    """Identical parabolic TE curves -c (phi - k p)^2 over an engagement longer than one pitch: the
    envelope is the leading parabola, its hand-over at +-p/2 is a crossing (no jump) and its
    minimum -c (p/2)^2 is reached there."""
    from gearrep.meshing import handover_jump, pair_te_curves, upper_envelope

    p, c = 2 * np.pi / 20, 3.0
    phi = np.linspace(-0.8 * p, 0.8 * p, 401)
    te = -c * phi**2
    at = np.linspace(-0.5 * p, 0.5 * p, 101)
    curves = pair_te_curves(phi, te, p, at)
    assert curves.shape == (5, 101) and np.isneginf(curves[0]).all()  # pair k = -2 is never engaged here
    env, lead = upper_envelope(curves)
    np.testing.assert_allclose(env, -c * at**2, atol=c * (phi[1] - phi[0]) ** 2)
    assert set(lead[1:-1]) == {2} and handover_jump(curves, lead, env) == 0.0
    # cubic interpolation of the same samples is exact for a parabola
    env3, _ = upper_envelope(pair_te_curves(phi, te, p, at, interpolation="cubic"))
    np.testing.assert_allclose(env3, -c * at**2, atol=1e-14)


def test_envelope_jumps_where_a_linear_curve_leaves_its_flank():
    """A TE linear along the path (sawtooth): the envelope jumps by slope x pitch at the hand-over;
    outside every engagement interval the envelope is NaN (a gap: no pair in contact)."""
    from gearrep.meshing import handover_jump, pair_te_curves, upper_envelope

    p, s = 0.1, 2e-4
    phi = np.linspace(-0.6 * p, 0.6 * p, 121)
    curves = pair_te_curves(phi, s * phi, p, np.linspace(-0.5 * p, 0.5 * p, 51))
    env, lead = upper_envelope(curves)
    assert np.all(np.isfinite(env))
    assert handover_jump(curves, lead, env) == pytest.approx(s * p, rel=0.05)
    short = np.where(np.abs(phi) <= 0.3 * p, s * phi, np.nan)  # engagement shorter than one pitch
    env_gap, _ = upper_envelope(pair_te_curves(phi, short, p, np.linspace(-0.5 * p, 0.5 * p, 51)))
    assert np.isnan(env_gap).any() and np.isfinite(env_gap).any()
    # the same gap from an engagement mask (e.g. contact inside the face width) on the full samples
    masked = pair_te_curves(
        phi, s * phi, p, np.linspace(-0.5 * p, 0.5 * p, 51), engaged=lambda q: np.abs(q) <= 0.3 * p + 1e-12
    )
    env_mask, _ = upper_envelope(masked)
    np.testing.assert_array_equal(np.isnan(env_mask), np.isnan(env_gap))
    with pytest.raises(ValueError, match="pitch"):
        pair_te_curves(phi, s * phi, -1.0, phi)
    with pytest.raises(ValueError, match="interpolation"):
        pair_te_curves(phi, s * phi, p, phi, interpolation="spline")


def test_handover_gap_is_zero_at_a_crossing_and_the_step_at_an_edge():
    from gearrep.meshing import handover_gap, handover_jump, upper_envelope

    x = np.linspace(-1.0, 1.0, 9)
    # two steep curves crossing between grid points: continuous transmitted TE
    cross = np.stack([-5.0 * (x - 0.05), 5.0 * (x - 0.05)])
    env, lead = upper_envelope(cross)
    assert handover_jump(cross, lead, env) > 0.1  # grid-limited difference, not a jump
    assert handover_gap(cross, lead, env) == 0.0
    # pair b enters above pair a (a still engaged): a step of the envelope
    edge = np.stack([np.zeros_like(x), np.where(x > 0.1, 1.0, -np.inf)])
    env, lead = upper_envelope(edge)
    assert handover_gap(edge, lead, env) == pytest.approx(1.0)
    # no hand-over
    env, lead = upper_envelope(np.stack([x, x - 1.0]))
    assert handover_gap(np.stack([x, x - 1.0]), lead, env) == 0.0


def test_sampled_cycle_is_the_envelope_of_the_pairs_over_one_pitch():
    """sampled_cycle (the TE over one cycle of the thesis's cylindrical and bevel studies): the
    envelope of the parabolic pairs is continuous with its extreme -c (p/2)^2 at the hand-over;
    a sawtooth steps by slope x pitch (a jump by either measure); fewer than two samples give NaN."""
    from gearrep.meshing import handover_jump, pair_te_curves, sampled_cycle, upper_envelope

    p, c = 2 * np.pi / 20, 3.0
    phi = np.linspace(-0.8 * p, 0.8 * p, 401)
    cyc = sampled_cycle(phi, -c * phi**2, p, 101)
    at = np.linspace(-0.5 * p, 0.5 * p, 101)
    np.testing.assert_array_equal(cyc.phi1, at)
    env, lead = upper_envelope(pair_te_curves(phi, -c * phi**2, p, at))
    np.testing.assert_array_equal(cyc.te, env)
    assert cyc.jump == handover_jump(pair_te_curves(phi, -c * phi**2, p, at), lead, env) == 0.0
    assert cyc.continuous(jump_tol_arcsec=0.01) and cyc.jump_arcsec == 0.0
    assert cyc.te_extreme == pytest.approx(-c * (0.5 * p) ** 2, rel=1e-3)
    assert cyc.te_peak_to_peak == pytest.approx(c * (0.5 * p) ** 2, rel=1e-3)

    s = 2e-4
    saw = np.linspace(-0.6 * 0.1, 0.6 * 0.1, 121)
    for how in ("jump", "gap"):
        step = sampled_cycle(saw, s * saw, 0.1, 51, handover=how)
        assert step.jump == pytest.approx(s * 0.1, rel=0.05) and not step.continuous(0.01)
        assert step.jump_arcsec == pytest.approx(step.jump / ARCSEC)

    none = sampled_cycle(phi, np.where(phi == phi[0], 1.0, np.nan), p, 11)
    assert np.isnan(none.te).all() and np.isnan(none.jump) and np.isnan(none.jump_arcsec)
    assert np.isnan(none.te_extreme) and np.isnan(none.te_peak_to_peak) and not none.continuous(1e9)
    with pytest.raises(ValueError, match="handover"):
        sampled_cycle(phi, -c * phi**2, p, 11, handover="step")
    with pytest.raises(ValueError, match="n_points"):
        sampled_cycle(phi, -c * phi**2, p, 1)
    with pytest.raises(ValueError, match="pitch"):
        sampled_cycle(phi, -c * phi**2, 0.0, 11)
