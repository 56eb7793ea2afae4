"""Numerical stress tests of the contact solver on involute pairs.

For each case the solver must return either a converged point that is verified (residual below
tolerance, finite, inside both flanks, equal to an independently obtained reference contact) or
a status that says why not. No NaN in a converged result, no silent wrong root.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import assert_honest

from gearrep.solve import Status
from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
from gearrep.tca import GearPair, Misalignment, solve_contact, trace_path

pytestmark = pytest.mark.stress

ALPHA = np.radians(20.0)
C1 = 0.002857  # thesis sec. 6.2 parabolic crowning coefficient (1/mm)


def pair_of(n1, n2, *, m=1.0, b=11.42, helix_deg=0.0, crown=C1, mis=None, x1=0.0, x2=0.0):
    g1 = InvoluteGearData(n1, m, ALPHA, b, helix_angle=np.radians(helix_deg), x=x1)
    g2 = InvoluteGearData(n2, m, ALPHA, b, helix_angle=np.radians(helix_deg), x=x2)
    f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(crown) if crown else None)
    a = standard_centre_distance(g1, g2)
    return GearPair(f1, f2, n1, n2, a, misalignment=mis), g1, g2


def _box_starts(rng, lo, hi, n, grow=0.5):
    span = hi - lo
    return rng.uniform(lo - grow * span, hi + grow * span, size=(n, len(lo)))


@pytest.mark.parametrize("helix_deg", [0.0, 14.0])
@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_random_starts_over_and_beyond_the_flank(helix_deg, formulation, record_conditions, request):
    n = 4000 if request.config.getoption("-m") and "slow" in request.config.getoption("-m") else 800
    pair, g1, g2 = pair_of(52, 72, helix_deg=helix_deg, mis=Misalignment(d_gamma_in=np.radians(0.05)))
    phi1 = -np.pi / (2 * 52) + 0.01
    ref = solve_contact(pair, phi1)
    assert ref.status[0] == Status.CONVERGED
    rng = np.random.default_rng(11)
    s1 = _box_starts(rng, pair.lower1, pair.upper1, n)
    if formulation == "reduced":
        start = s1
    else:
        s2 = _box_starts(rng, pair.lower2, pair.upper2, n)
        start = np.column_stack([s1, s2, pair.ratio * phi1 + rng.uniform(-np.pi, np.pi, n)])
    c = solve_contact(pair, np.full(n, phi1), start, formulation=formulation)
    assert_honest(c, ref)
    record_conditions(c.condition, f"{formulation}, beta={helix_deg}")
    assert c.converged.sum() > 0


@pytest.mark.parametrize("plane", ["in", "out"])
def test_misalignment_from_1e_7_rad_to_edge_contact(plane, record_conditions):
    """Crowned spur pinion, contact near the pitch point: the shift of the contact along the face
    grows with the misalignment until it leaves the flank, where the point must be OFF_FLANK (never
    a converged point outside [-b/2, b/2])."""
    angles = np.concatenate([np.logspace(-7, -2, 11), [0.02, 0.05, 0.1]])
    shifts, statuses, conds = [], [], []
    for ang in angles:
        mis = Misalignment(d_gamma_in=ang) if plane == "in" else Misalignment(d_gamma_out=ang)
        pair, g1, _ = pair_of(52, 72, mis=mis)
        phi1 = -np.pi / (2 * 52)
        c = solve_contact(pair, np.full(5, phi1), np.column_stack([np.full(5, g1.r_p), np.linspace(-5, 5, 5)]))
        assert_honest(c)
        conds.append(c.condition)
        conv = c.converged
        if conv.any():
            v = c.v1[conv]
            assert np.ptp(v) < 1e-8  # one contact point, whatever the start
            assert np.all(np.abs(v) <= 0.5 * g1.face_width + 1e-12)
            shifts.append(abs(v[0]))
        else:
            shifts.append(np.inf)
        statuses.append(set(np.unique(c.status)))
    shifts = np.array(shifts)
    record_conditions(np.concatenate(conds), f"{plane}-plane, 1e-7 .. 0.1 rad")
    # small misalignments: shift proportional to the angle (first order), then growth to the edge
    small = angles <= 1e-4
    ratio = shifts[small] / angles[small]
    assert np.ptp(ratio) < 1e-3 * ratio.mean()
    edge = ~np.isfinite(shifts)
    assert np.all(np.diff(shifts[~edge]) >= -1e-12)
    assert not np.any(np.diff(edge.astype(int)) < 0), "once off the face, larger angles stay off"
    assert edge[-1], "the largest misalignment should push the contact off the face"
    for st, e in zip(statuses, edge):
        if e:
            assert Status.CONVERGED not in st and st <= {
                Status.OFF_FLANK,
                Status.NOT_CONVERGED,
                Status.SINGULAR,
                Status.WRONG_ROOT,
            }


@pytest.mark.parametrize("n1", [12, 14, 17, 18, 25, 60, 120, 200])
def test_tooth_numbers_near_undercut(n1, record_conditions):
    """Aligned pairs N1 = 12..200 (crowned pinion, point contact) with N2 = 2 N1, solved over and
    beyond the engagement interval. Converged points have TE = 0 and lie mid-face with u1 inside
    the flank (above the base circle); positions past the ends of the flank come back OFF_FLANK."""
    pair, g1, g2 = pair_of(n1, 2 * n1)
    step = 2 * np.pi / n1
    phi1 = np.linspace(-np.pi / (2 * n1) - 2.5 * step, -np.pi / (2 * n1) + 2.5 * step, 81)
    c = solve_contact(pair, phi1)
    assert_honest(c)
    ok = c.converged
    assert ok.sum() >= 5
    assert np.max(np.abs(c.te_arcsec[ok])) < 1e-6
    assert np.max(np.abs(c.v1[ok])) < 1e-8
    assert np.all(c.u1[ok] >= pair.lower1[0] - 1e-12)
    assert np.all(c.u1[ok] > g1.r_b)
    assert np.any(c.status == Status.OFF_FLANK)
    record_conditions(c.condition, f"N1={n1}")


def test_line_contact_with_the_point_solver_is_flagged_or_on_the_line(record_conditions):
    """An aligned, unmodified spur pair has LINE contact, so the 2-unknown point system has a
    one-parameter family of roots (singular Jacobian). Whatever the solver returns as converged
    must lie on the contact line (TE = 0); the rest must be flagged."""
    pair, g1, _ = pair_of(52, 72, crown=0.0)
    rng = np.random.default_rng(3)
    start = _box_starts(rng, pair.lower1, pair.upper1, 400, grow=0.0)
    phi1 = -np.pi / (2 * 52)
    for form in ("reduced", "conventional"):
        s = (
            start
            if form == "reduced"
            else np.column_stack(
                [
                    start,
                    np.full(400, pair.lower2[0] + 0.5 * (pair.upper2[0] - pair.lower2[0])),
                    start[:, 1],
                    np.full(400, pair.ratio * phi1),
                ]
            )
        )
        c = solve_contact(pair, np.full(400, phi1), s, formulation=form)
        assert_honest(c)
        ok = c.converged
        if ok.any():
            assert np.max(np.abs(c.te_arcsec[ok])) < 1e-6
            assert np.ptp(c.u1[ok]) < 1e-8  # one line: same profile point on every section
        record_conditions(c.condition, form)


def test_forced_bad_equation_choice_is_never_a_silent_wrong_root(record_conditions):
    """Dropping the small normal component (n_z of a spur gear) makes the conventional Jacobian
    nearly singular (tca module docstring). Starts near the root: every point is either the
    verified root or flagged."""
    pair, g1, g2 = pair_of(52, 72, mis=Misalignment(d_gamma_in=np.radians(0.05)))
    phi1 = -np.pi / (2 * 52)
    ref = solve_contact(pair, phi1)
    rng = np.random.default_rng(5)
    x0 = ref.unknowns("conventional")[0]
    start = x0 + rng.normal(scale=[0.05, 1.0, 0.05, 1.0, 0.01], size=(500, 5))
    c = solve_contact(pair, np.full(500, phi1), start, formulation="conventional", drop=2)
    assert_honest(c, ref)
    record_conditions(c.condition, "drop=2 (n_z)")
    flagged = ~c.converged
    assert flagged.any()  # the bad choice does cost roots; they are reported, not returned as numbers


@pytest.mark.slow
@pytest.mark.parametrize("n1", range(12, 201, 4))
def test_tooth_number_sweep_full(n1, record_conditions):
    """Full sweep of test_tooth_numbers_near_undercut with profile-shifted pinions as well."""
    for x1 in (0.0, 0.3, -0.2):
        pair, g1, g2 = pair_of(n1, 3 * n1, crown=C1, x1=x1, x2=-x1)
        step = 2 * np.pi / n1
        phi1 = np.linspace(-np.pi / (2 * n1) - step, -np.pi / (2 * n1) + step, 61)
        c = trace_path(pair, phi1)
        assert_honest(c)
        record_conditions(c.condition, f"x1={x1}")
