"""The TCA of the Novikov-Wildhaber pair of seed 002 (rack-generated flanks of
gearrep.surfaces.novikov): the offset start under a crossing error, and one-point solves on floats
(the flanks: tests/unit/surfaces/test_novikov.py)."""

import numpy as np
import pytest
from _numerics import assert_rounding_close, solve_bound

from gearrep.units import DEG


def _novikov_pair(misalignment=None):
    """The seed-002 profile-crowned pair's proportions (17/77 teeth, P_n = 5/in, alpha_n = 25 deg,
    rho_c = 5.88/P_n, rho_t = 6.35/P_n, left hand), flanks from the racks."""
    from gearrep.surfaces.novikov import member_flank
    from gearrep.tca import GearPair

    an, Pn, beta = 25 * DEG, 5.0, 0.3481660212729610
    l = np.cos(an) / Pn
    f1 = member_flank(17, Pn, Pn / (2 * 5.88), an, l, -beta, "pinion")
    f2 = member_flank(77, Pn, Pn / (2 * 6.35), an, l, -beta, "gear")
    return GearPair(f1, f2, 17, 77, f1.r_p + f2.r_p, misalignment=misalignment, phase2=0.0)


def test_offset_start_reaches_the_same_contacts_in_a_few_iterations():
    """Under a 3 arcmin crossing error the aligned contact is 0.125 in across the profile from the
    misaligned one and the damped solve creeps (about 30 iterations); moved by the offset solved at
    one angle, the starts lead to the same roots in at most 4 full steps."""
    from gearrep.surfaces.novikov import aligned_start
    from gearrep.tca import Misalignment, offset_start, solve_contact
    from gearrep.units import ARCMIN

    pair = _novikov_pair(Misalignment(d_gamma_out=3 * ARCMIN))
    per = 2 * np.pi / pair.n1
    phi = np.linspace(-per, per, 41)
    kw = dict(formulation="conventional", tol=1e-12, maxiter=50)
    before = solve_contact(pair, phi, aligned_start(pair, phi), **kw)
    start = offset_start(pair, phi, aligned_start, tol=1e-12, maxiter=50)
    after = solve_contact(pair, phi, start, **kw)
    assert before.converged.all() and after.converged.all()
    assert after.iterations.max() <= 4
    # same roots: residual 1e-12 with Jacobian condition numbers ~5e4 leaves ~1e-11 in the unknowns
    x0, x1 = before.unknowns("conventional"), after.unknowns("conventional")
    assert np.abs(x0 - x1).max() < 1e-9
    assert np.abs(before.te_arcsec - after.te_arcsec).max() < 1e-6


def test_offset_start_keeps_the_nominal_start_where_it_cannot_help():
    from gearrep.surfaces.novikov import aligned_start
    from gearrep.tca import Misalignment, offset_start

    pair = _novikov_pair(Misalignment(d_gamma_out=3 * DEG / 60))
    one = offset_start(pair, [0.01], aligned_start)
    assert np.array_equal(one, aligned_start(pair, [0.01]))  # one angle: the reference would be the solve
    phi = np.array([-0.05, 0.0, 0.05])
    failed = offset_start(pair, phi, aligned_start, maxiter=1)  # the reference does not converge
    assert np.array_equal(failed, aligned_start(pair, phi))
    with pytest.raises(ValueError, match="nominal must return"):
        offset_start(pair, phi, lambda p, ph: aligned_start(p, ph)[:, :2])
    with pytest.raises(ValueError, match="formulation"):
        offset_start(pair, phi, aligned_start, formulation="fast")


def test_one_point_on_floats_gives_the_array_values():
    """A rack-generated flank evaluated at one point given as Python floats computes on floats
    (the single-point TCA's path) and gives the array path's values (cos/sin of the rolling angle
    by math instead of numpy: rounding only); a one-point contact solve gives its batch row."""
    from gearrep.surfaces.novikov import aligned_start
    from gearrep.tca import Misalignment, offset_start, solve_contact

    pair = _novikov_pair(Misalignment(d_gamma_out=3 * DEG / 60))
    for f in (pair.flank1, pair.flank2):
        for u, th in ((0.1, 0.3), (-0.12, -0.7), (0.0, 0.0)):
            A = f.evaluate_components(np.array([u]), np.array([th]))
            B = f.evaluate_components(u, th)
            assert all(type(c) is float for vec in B for c in vec)
            for va, vb in zip(A, B):
                assert_rounding_close(np.concatenate([np.ravel(c) for c in va]), vb)
        yp = f.rack.pitch_crossing(0.05)
        assert all(type(c) is float for c in yp)
        assert_rounding_close(yp, [c[0] for c in f.rack.pitch_crossing(np.array([0.05]))])
    phi = np.linspace(-0.2, 0.2, 5)
    start = offset_start(pair, phi, aligned_start)
    kw = dict(formulation="conventional", tol=1e-12, maxiter=50)
    batch = solve_contact(pair, phi, start, **kw).unknowns("conventional")
    for i in range(len(phi)):
        one = solve_contact(pair, phi[i : i + 1], start[i : i + 1], **kw)
        assert one.converged[0]
        # both converged to 1e-12 residual (condition ~5e4): the same root to 1e-9
        assert np.abs(one.unknowns("conventional")[0] - batch[i]).max() < 1e-9


def test_polynomial_offset_start_for_a_ground_pinion(published):
    """The disk-ground pinion of seed 002 under the 3 arcmin crossing error: its aligned start
    drifts from the contact along the path (0.8 in along the tooth at the ends of a pitch), so a
    constant offset leaves most of the drift; the offset polynomial in the angle (order 1, 2) leads
    to the same roots in fewer iterations."""
    from conftest import study_settings

    from gearrep.replications import litvin2000
    from gearrep.replications.litvin2000.geometry import disk_start, make_disk_pair
    from gearrep.tca import Misalignment, offset_start, solve_contact
    from gearrep.units import ARCMIN

    s = study_settings("litvin2000")
    d = litvin2000.params_from_published(published)
    mis = Misalignment(d_gamma_out=s["misalignment_arcmin"] * ARCMIN)
    pair = make_disk_pair(d, s, float(np.mean(s["disk_E_d_bracket_in"])), misalignment=mis)
    per = 2 * np.pi / pair.n1
    phi = np.linspace(-0.5 * per, 0.5 * per, 21)
    kw = dict(formulation="conventional", tol=s["tol"], maxiter=s["maxiter"])
    c = [
        solve_contact(pair, phi, offset_start(pair, phi, disk_start, order=k, tol=s["tol"], maxiter=s["maxiter"]), **kw)
        for k in (0, 1, 2)
    ]
    assert all(ck.converged.all() for ck in c)
    assert c[1].iterations.mean() < 0.6 * c[0].iterations.mean() and c[1].iterations.max() <= 6
    assert c[2].iterations.mean() < c[1].iterations.mean() and c[2].iterations.max() <= 5
    # the same roots: both residuals below tol, within the solver's bound (condition x 2 tol)
    x0 = c[0].unknowns("conventional")
    for ck in c[1:]:
        bound = solve_bound(s["tol"], np.fmax(c[0].condition, ck.condition)[:, None], x0)
        assert np.all(np.abs(x0 - ck.unknowns("conventional")) <= bound)
    # one angle more than the polynomial needs: the references are three of the four angles
    assert np.all(np.isfinite(offset_start(pair, phi[:4], disk_start, order=2)))
    assert np.array_equal(offset_start(pair, phi[:3], disk_start, order=2), disk_start(pair, phi[:3]))
    with pytest.raises(ValueError, match="order"):
        offset_start(pair, phi, disk_start, order=4)
