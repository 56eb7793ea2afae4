"""Hostile inputs to the library: inconsistent designs are refused with a
ValueError naming the key, the value and the allowed range, instead of confident numbers or
numpy errors, and no numpy warning escapes the public calls."""

import warnings

import numpy as np
import pytest

from gearrep.meshing import engagement_limits, meshing_cycle, pair_te_curves
from gearrep.surfaces.involute import (
    InvoluteFlank,
    InvoluteGearData,
    ParabolicCrowning,
    mating_flanks,
    standard_centre_distance,
)
from gearrep.tca import (
    GearPair,
    default_start,
    guard_reduced_starts,
    line_of_action_start,
    line_of_action_starts,
    robust_start,
    solve_contact,
    solve_conventional,
    solve_variant,
    trace_path,
    transverse_stage,
)

ALPHA = np.radians(20.0)
CROWN = ParabolicCrowning(0.003)  # point contact: the meshing cycle needs no v1


def _gears(n1=20, n2=40, **kw1):
    return InvoluteGearData(n1, 1.0, ALPHA, 10.0, **kw1), InvoluteGearData(n2, 1.0, ALPHA, 10.0)


def _pair(n1=20, n2=40, crowning1=CROWN):
    g1, g2 = _gears(n1, n2)
    f1, f2 = mating_flanks(g1, g2, crowning1=crowning1)
    return GearPair(f1, f2, n1, n2, standard_centre_distance(g1, g2))


@pytest.fixture(autouse=True)
def _numpy_warnings_are_errors():
    """Every call in this module runs with warnings as errors: none may escape the public API."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


# ---------------------------------------------------------------------------------------------
# tooth numbers that disagree with the flanks
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("key, n1, n2, flank_n", [("n1", 10, 40, 20), ("n2", 20, 41, 40)])
def test_gear_pair_refuses_a_tooth_number_its_flank_disagrees_with(key, n1, n2, flank_n):
    """Today n1=10 with a 20-tooth flank gives a TE of 26 325 arcsec instead of an error."""
    g1, g2 = _gears()
    f1, f2 = mating_flanks(g1, g2, crowning1=CROWN)
    with pytest.raises(ValueError, match=rf"{key} = {n1 if key == 'n1' else n2}\b.*{flank_n}"):
        GearPair(f1, f2, n1, n2, standard_centre_distance(g1, g2))


def test_gear_pair_accepts_flanks_without_a_tooth_number():
    """Surfaces that carry no gear data (e.g. generated flanks) keep being accepted as before."""

    class Bare:
        pass

    pair = GearPair(Bare(), Bare(), 10, 40, 30.0)
    assert (pair.n1, pair.n2) == (10, 40)


# ---------------------------------------------------------------------------------------------
# impossible tooth thickness
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("thinning", [1.6, 2.0, 10.0])
def test_thinning_beyond_the_tooth_thickness_is_refused(thinning):
    """Today thinning = 2 mm on a 1.571 mm tooth gives contact ratio 1.635 and TE 0."""
    with pytest.raises(ValueError, match=rf"thinning = {thinning}.*must be < [0-9.]+ mm"):
        InvoluteGearData(20, 1.0, ALPHA, 10.0, thinning=thinning)


def test_thinning_that_points_the_tooth_below_its_tip_is_refused():
    """1.2 mm off a 1.571 mm tooth: still positive at the pitch circle, but the two flanks cross
    below the tip circle (a pointed tooth), which the flank model cannot represent."""
    with pytest.raises(ValueError, match=r"thinning = 1.2 .*pointed"):
        InvoluteGearData(20, 1.0, ALPHA, 10.0, thinning=1.2)


def test_a_realistic_backlash_thinning_is_accepted():
    g = InvoluteGearData(20, 1.0, ALPHA, 10.0, thinning=0.05)
    assert g.tooth_thickness == pytest.approx(0.5 * np.pi - 0.05)


# ---------------------------------------------------------------------------------------------
# empty and 2-D angle arrays
# ---------------------------------------------------------------------------------------------
BAD_ANGLES = {"empty": [], "2-D": np.zeros((2, 3)), "empty 2-D": np.zeros((0, 2))}


@pytest.mark.parametrize("bad", BAD_ANGLES.values(), ids=BAD_ANGLES.keys())
@pytest.mark.parametrize("call", [solve_contact, trace_path, default_start, line_of_action_starts])
def test_angle_arrays_must_be_non_empty_and_1d(call, bad):
    with pytest.raises(ValueError, match=r"phi1 must be a scalar or a non-empty 1-D array .*shape"):
        call(_pair(), bad)


@pytest.mark.parametrize("bad", [np.zeros((2, 2)), [], np.array([0.0, 0.1]), np.nan])
@pytest.mark.parametrize("call", [meshing_cycle, engagement_limits])
def test_phi1_start_must_be_one_finite_angle(call, bad):
    with pytest.raises(ValueError, match=r"phi1_start must be one finite angle"):
        call(_pair(), bad)


@pytest.mark.parametrize("bad", [np.zeros((2, 3)), [], np.nan])
def test_line_of_action_start_takes_one_finite_angle(bad):
    with pytest.raises(ValueError, match=r"phi1 must be one finite angle"):
        line_of_action_start(_pair(), bad)


@pytest.mark.parametrize("call", [solve_contact, trace_path])
@pytest.mark.parametrize("v1", [np.zeros((2, 2)), [0.0, 1.0, 2.0]])
def test_fixed_v1_must_match_the_angles(call, v1):
    """Today: 'input operand has more dimensions than allowed by the axis remapping'."""
    with pytest.raises(ValueError, match=r"v1 must be a scalar or a 1-D array of length 1 or 2"):
        call(_pair(crowning1=None), [0.0, 0.01], v1=v1)


@pytest.mark.parametrize("v1", [np.zeros((2, 2)), [0.0, 1.0], np.inf])
@pytest.mark.parametrize("call", [meshing_cycle, engagement_limits])
def test_meshing_v1_is_one_finite_coordinate(call, v1):
    with pytest.raises(ValueError, match=r"v1 must be None \(point contact\) or one finite face-width"):
        call(_pair(crowning1=None), v1=v1)


# ---------------------------------------------------------------------------------------------
# line contact: the message says what to do
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("call", [meshing_cycle, engagement_limits])
def test_line_contact_pair_is_told_to_pass_v1(call):
    with pytest.raises(ValueError, match=r"line contact.*pass v1="):
        call(_pair(crowning1=None))


def test_line_contact_pair_with_v1_runs():
    cycle = meshing_cycle(_pair(crowning1=None), v1=0.0, n_points=9)
    assert 1.5 < cycle.contact_ratio < 1.8


# ---------------------------------------------------------------------------------------------
# undercut flanks
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("n1", [8, 12, 17])
@pytest.mark.parametrize("call", [meshing_cycle, engagement_limits])
def test_undercut_pinion_names_undercut_and_the_limit(call, n1):
    """20 deg, h_a = 1, x = 0: the generating rack undercuts below 2 / sin^2(20 deg) = 17.1 teeth.
    Today: a numpy RuntimeWarning, then 'could not locate the flank boundary'."""
    with pytest.raises(ValueError, match=rf"flank1.*n_teeth = {n1}.*undercut.*17\.1.*18"):
        call(_pair(n1, 2 * n1))


def test_the_undercut_limit_follows_profile_shift_and_pressure_angle():
    from gearrep.surfaces.involute import undercut_limit

    assert undercut_limit(InvoluteGearData(20, 1.0, ALPHA, 10.0)) == pytest.approx(2 / np.sin(ALPHA) ** 2)
    assert undercut_limit(InvoluteGearData(20, 1.0, ALPHA, 10.0, x=0.5)) == pytest.approx(1 / np.sin(ALPHA) ** 2)
    assert undercut_limit(InvoluteGearData(20, 1.0, np.radians(25), 10.0)) < 12
    # a profile-shifted 12-tooth pinion is no longer undercut and meshes
    g1 = InvoluteGearData(12, 1.0, ALPHA, 10.0, x=0.4)
    g2 = InvoluteGearData(24, 1.0, ALPHA, 10.0, x=-0.4)
    f1, f2 = mating_flanks(g1, g2, crowning1=CROWN)
    cycle = meshing_cycle(GearPair(f1, f2, 12, 24, standard_centre_distance(g1, g2)), n_points=9)
    assert cycle.contact_ratio > 1.0


# ---------------------------------------------------------------------------------------------
# valid calls stay quiet (warnings are errors in this module)
# ---------------------------------------------------------------------------------------------
def test_valid_public_calls_emit_no_numpy_warning():
    pair = _pair()
    c = solve_contact(pair, np.linspace(-0.1, 0.1, 7))
    assert c.converged.any()
    assert len(trace_path(pair, np.linspace(-0.05, 0.05, 5))) == 5
    cycle = meshing_cycle(pair, n_points=9)
    assert np.isfinite(cycle.te_peak_to_peak)
    flank = InvoluteFlank(_gears()[0])
    assert np.all(np.isfinite(flank.position(np.linspace(flank.u_min, flank.u_max, 5), 0.0)))


@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
@pytest.mark.parametrize("u1", [np.inf, -np.inf, np.nan, 1e300])
def test_a_non_finite_or_huge_start_is_reported_diverged_without_warnings(formulation, u1):
    """Today an infinite start lets 'invalid value encountered in cos' escape (and 1e300 an overflow)."""
    pair = _pair()
    start = np.array([[u1, 0.0]]) if formulation == "reduced" else np.array([[u1, 0.0, 20.0, 0.0, 0.0]])
    c = solve_contact(pair, 0.0, start, formulation=formulation)
    assert c.status_name.tolist() == ["diverged"]
    assert trace_path(pair, [0.0, 0.01], start[0], formulation=formulation).status_name.tolist() == ["diverged"] * 2


# ---------------------------------------------------------------------------------------------
# secondary TCA entry points and the meshing cycle's grid size
# ---------------------------------------------------------------------------------------------
STARTS_UV = [
    ("u1 2-D", np.zeros((2, 2)), np.zeros(2), r"u1 and v1 must be non-empty 1-D arrays .*shapes \(2, 2\) and \(2,\)"),
    ("lengths differ", np.full(3, 10.5), np.zeros(2), r"u1 and v1 must be .*shapes \(3,\) and \(2,\)"),
    ("empty", np.zeros(0), np.zeros(0), r"u1 and v1 must be non-empty"),
]


@pytest.mark.parametrize("u1, v1, msg", [s[1:] for s in STARTS_UV], ids=[s[0] for s in STARTS_UV])
@pytest.mark.parametrize("call", [robust_start, transverse_stage, guard_reduced_starts])
def test_start_stages_refuse_mismatched_start_arrays(call, u1, v1, msg):
    with pytest.raises(ValueError, match=msg):
        call(_pair(), 0.0, u1, v1)


@pytest.mark.parametrize(
    "phi1, msg",
    [(np.zeros(3), r"phi1 must be one angle or one per start \(length 2\)"), (np.nan, "phi1 must be finite")],
)
@pytest.mark.parametrize("call", [robust_start, transverse_stage, guard_reduced_starts])
def test_start_stages_refuse_bad_angles(call, phi1, msg):
    with pytest.raises(ValueError, match=msg):
        call(_pair(), phi1, np.full(2, 10.5), np.zeros(2))


@pytest.mark.parametrize(
    "call, kw, msg",
    [
        (transverse_stage, {"tol": 0.0}, r"tol must be a finite number > 0, got 0.0"),
        (transverse_stage, {"maxiter": 2.5}, r"maxiter must be an integer >= 1, got 2.5"),
        (guard_reduced_starts, {"n_bisect": 0}, r"n_bisect must be an integer >= 1, got 0"),
    ],
)
def test_start_stages_refuse_bad_solver_knobs(call, kw, msg):
    with pytest.raises(ValueError, match=msg):
        call(_pair(), 0.0, np.full(2, 10.5), np.zeros(2), **kw)


@pytest.mark.parametrize("call", [solve_variant, solve_conventional])
@pytest.mark.parametrize(
    "starts, msg",
    [
        (np.zeros((3, 2)), r"must be an \(n, 5\) array of starts .*shape \(3, 2\)"),
        (np.zeros(5), r"must be an \(n, 5\) array of starts .*shape \(5,\)"),
        (np.zeros((0, 5)), r"must be an \(n, 5\) array of starts .*shape \(0, 5\)"),
    ],
)
def test_conventional_entry_points_refuse_start_shapes(call, starts, msg):
    with pytest.raises(ValueError, match=msg):
        call(_pair(), 0.0, starts, "plain") if call is solve_variant else call(_pair(), 0.0, starts)


@pytest.mark.parametrize("call", [solve_variant, solve_conventional])
@pytest.mark.parametrize("phi1", [np.array([0.0, 0.1]), np.nan, np.zeros((1, 1))])
def test_conventional_entry_points_take_one_finite_angle(call, phi1):
    starts = np.tile([10.5, 0.0, 20.5, 0.0, 0.0], (2, 1))
    with pytest.raises(ValueError, match=r"phi1 must be one finite angle"):
        call(_pair(), phi1, starts, "plain") if call is solve_variant else call(_pair(), phi1, starts)


def test_solve_variant_names_the_variants():
    with pytest.raises(ValueError, match=r"variant must be one of .*'reduced_robust'.*got 'newton'"):
        solve_variant(_pair(), 0.0, np.tile([10.5, 0.0, 20.5, 0.0, 0.0], (2, 1)), "newton")


@pytest.mark.parametrize(
    "kw, msg",
    [
        ({"maxiter": 0}, r"maxiter must be an integer >= 1, got 0"),
        ({"tol": -1.0}, r"tol must be a finite number > 0"),
        ({"margin": 0.7}, r"margin must be in \[0, 0.5\)"),
    ],
)
def test_solve_conventional_refuses_bad_knobs(kw, msg):
    with pytest.raises(ValueError, match=msg):
        solve_conventional(_pair(), 0.0, np.tile([10.5, 0.0, 20.5, 0.0, 0.0], (2, 1)), **kw)


@pytest.mark.parametrize("n_points", [5.5, 4, "81", True])
def test_meshing_cycle_takes_an_integer_grid_size(n_points):
    with pytest.raises(ValueError, match=rf"n_points must be an integer >= 5, got {n_points!r}"):
        meshing_cycle(_pair(), n_points=n_points)


@pytest.mark.parametrize(
    "phi1, te, at, msg",
    [
        (np.zeros((2, 3)), np.zeros((2, 3)), np.zeros(2), r"phi1 and te must be 1-D arrays of the same length"),
        (np.linspace(0, 1, 4), np.zeros(3), np.zeros(2), r"shapes \(4,\) and \(3,\)"),
        (np.linspace(0, 1, 4), np.zeros(4), np.zeros((2, 2)), r"at must be a scalar or a 1-D array"),
    ],
)
def test_pair_te_curves_refuses_mismatched_shapes(phi1, te, at, msg):
    with pytest.raises(ValueError, match=msg):
        pair_te_curves(phi1, te, 0.1, at)


@pytest.mark.parametrize(
    "kw, msg",
    [
        ({"maxiter": 2.5}, r"maxiter must be an integer >= 1, got 2.5"),
        ({"maxiter": True}, r"maxiter must be an integer >= 1, got True"),
        ({"maxiter": "50"}, r"maxiter must be an integer >= 1, got '50'"),
        ({"max_halvings": -1}, r"max_halvings must be an integer >= 0, got -1"),
        ({"max_halvings": 2.5}, r"max_halvings must be an integer >= 0, got 2.5"),
    ],
)
def test_newton_refuses_iteration_counts_that_are_not_integers(kw, msg):
    """A fractional iteration limit was truncated (maxiter=2.5 ran 2 iterations) and a negative
    number of step halvings turned the damped solve into plain Newton, both silently."""
    from gearrep.solve import newton

    with pytest.raises(ValueError, match=msg):
        newton(lambda x: x - 1.0, np.zeros((2, 1)), lambda x: np.ones((len(x), 1, 1)), **kw)


def test_newton_takes_numpy_integers():
    from gearrep.solve import Status, newton

    r = newton(lambda x: x - 1.0, np.zeros((2, 1)), lambda x: np.ones((len(x), 1, 1)), maxiter=np.int64(3))
    assert (r.status == Status.CONVERGED).all()


@pytest.mark.parametrize("formulation", ["reduced", "conventional"])
def test_solve_contact_refuses_a_fractional_iteration_limit(formulation):
    with pytest.raises(ValueError, match=r"maxiter must be an integer >= 1, got 2.5"):
        solve_contact(_pair(), np.zeros(2), formulation=formulation, maxiter=2.5)


def test_default_start_names_the_formulations():
    """default_start gave conventional starts for any name but 'reduced'."""
    with pytest.raises(ValueError, match=r"formulation must be 'reduced' or 'conventional', got 'Reduced'"):
        default_start(_pair(), np.zeros(2), "Reduced")


def test_envelope_and_hob_gear_refuse_a_fractional_iteration_limit():
    from gearrep.envelope import Envelope
    from gearrep.surfaces.hob import GeneratedGear

    gear = GeneratedGear()
    with pytest.raises(ValueError, match=r"maxiter must be an integer >= 1, got 2.5"):
        Envelope(gear.thread(), gear.motion(), free=("u", "psi"), maxiter=2.5)
    with pytest.raises(ValueError, match=r"maxiter must be an integer >= 1, got 2.5"):
        GeneratedGear(maxiter=2.5)


def test_newton_refuses_an_infinite_tolerance():
    """tol=inf called every start converged at once (status CONVERGED, no iteration)."""
    from gearrep.solve import newton

    with pytest.raises(ValueError, match=r"tol must be a finite number > 0, got inf"):
        newton(lambda x: x - 1.0, np.zeros((2, 1)), lambda x: np.ones((len(x), 1, 1)), tol=np.inf)
    with pytest.raises(ValueError, match=r"tol must be a number in \(0, 0.001\].*got inf"):
        solve_contact(_pair(), np.zeros(2), tol=np.inf)


def test_ellipse_and_hertz_take_one_value_per_contact_point():
    """A per-point elastic approach or load is taken row by row also when some points did not
    converge (it was broadcast against the converged rows only: a numpy shape error), and any other
    length is refused naming the argument."""
    from gearrep.tca import contact_ellipse, contact_hertz

    pair = _pair()
    phi = np.array([-0.02, 0.0, 3.0, 0.02])  # the third is not a contact of this flank pair
    c = solve_contact(pair, phi)
    assert not c.converged[2] and c.converged[[0, 1, 3]].all()
    delta = np.array([0.002, 0.004, 0.006, 0.008])
    per_point = contact_ellipse(pair, c, delta)
    for i in (0, 1, 3):
        assert per_point.a[i] == contact_ellipse(pair, c, delta[i]).a[i]
    assert np.isnan(per_point.a[2])
    load = np.array([500.0, 1000.0, 1500.0, 2000.0])
    h = contact_hertz(pair, c, load, 2.06e5, 0.3)
    for i in (0, 1, 3):
        assert h.p0[i] == contact_hertz(pair, c, load[i], 2.06e5, 0.3).p0[i]
    with pytest.raises(ValueError, match=r"delta must be a scalar or one value per contact point \(length 4\)"):
        contact_ellipse(pair, c, np.full(3, 0.002))
    with pytest.raises(ValueError, match=r"load_N must be a scalar or one value per contact point \(length 4\)"):
        contact_hertz(pair, c, np.ones((2, 2)), 2.06e5, 0.3)


def test_contact_ellipse_of_a_line_contact_is_not_elliptic():
    """An unmodified aligned spur pair touches along a line: its relative curvature across the
    line is a rounding-made ~1e-34 1/mm, which gave an 'ellipse' of semi-axis ~5e15 mm flagged
    elliptic (contact_hertz already called those points singular)."""
    from gearrep.tca import contact_ellipse, contact_hertz

    pair = _pair(crowning1=None)
    c = solve_contact(pair, np.array([0.0, 0.01]), v1=0.0)
    assert c.converged.all()
    assert not contact_ellipse(pair, c, 0.005).elliptic.any()
    assert (contact_hertz(pair, c, 1000.0, 2.06e5, 0.3).status == 3).all()  # SINGULAR
    assert contact_ellipse(_pair(), solve_contact(_pair(), np.array([0.0, 0.01])), 0.005).elliptic.all()


@pytest.mark.parametrize(
    "phi1, kw, msg",
    [
        (np.linspace(0.2, -0.2, 11), {}, r"phi1 must increase strictly along the grid"),
        (np.r_[np.linspace(-0.2, 0.0, 6), np.linspace(0.0, 0.2, 6)], {}, r"phi1 must increase strictly"),
        (np.linspace(-0.2, 0.2, 11), {"tol": -1.0}, r"tol must be a finite number >= 0 \[rad\], got -1.0"),
        (np.linspace(-0.2, 0.2, 11), {"tol": np.nan}, r"tol must be a finite number >= 0 \[rad\], got nan"),
        (np.linspace(-0.2, 0.2, 11), {"pairs": [0.5]}, r"pairs must be one or more integers .*got \[0.5\]"),
        (np.linspace(-0.2, 0.2, 11), {"pairs": []}, r"pairs must be one or more integers .*got \[\]"),
    ],
)
def test_pair_te_curves_refuses_grids_it_would_misread(phi1, kw, msg):
    """np.interp needs increasing angles: a reversed grid gave a TE 14 times too large, and a
    negative or NaN tol called every pair disengaged (-inf), all silently."""
    from gearrep.meshing import sampled_cycle

    te = 1e-6 * phi1**2
    with pytest.raises(ValueError, match=msg):
        pair_te_curves(phi1, te, 0.3, [0.05], **({"pairs": [0]} | kw))
    if not kw:
        with pytest.raises(ValueError, match=msg):
            sampled_cycle(phi1, te, 0.3, 11)


@pytest.mark.parametrize(
    "kw, msg",
    [
        ({"thinning": -5.0}, r"thinning = -5.0 mm makes the tooth at least as thick as the circular pitch"),
        ({"h_a": 0.0}, r"h_a \(addendum coefficient\) must be > 0, got 0.0"),
        ({"h_f": -2.0}, r"h_f \(dedendum coefficient\) must be > -h_a = -1.0, got -2.0"),
        ({"h_f": 50.0}, r"h_f = 50.0 puts the root circle at r_f = -40.0 mm; allowed range: h_f < 10.0"),
    ],
)
def test_involute_gear_data_has_lower_bounds_too(kw, msg):
    """A tooth thicker than the circular pitch, no addendum, or a root below the axis were
    accepted (a meshing cycle then reported a contact ratio for teeth that cannot exist)."""
    with pytest.raises(ValueError, match=msg):
        InvoluteGearData(20, 1.0, ALPHA, 10.0, **kw)


@pytest.mark.parametrize("call", [solve_contact, trace_path])
@pytest.mark.parametrize(
    "kw, msg",
    [
        (
            {"tol": 0.1},
            r"tol must be a number in \(0, 0.001\] \(a larger one calls an untouched start converged\), got 0.1",
        ),
        ({"tol": 1e300}, r"tol must be a number in \(0, 0.001\]"),
        ({"tol": True}, r"tol must be a number in \(0, 0.001\]"),
        ({"phi10": np.nan}, r"phi10 \(TE reference angle\) must be one finite number \[rad\], got nan"),
        ({"phi20": np.inf}, r"phi20 \(TE reference angle\) must be one finite number \[rad\], got inf"),
        ({"phi10": np.zeros(3)}, r"phi10 \(TE reference angle\) must be one finite number"),
        ({"formulation": "Reduced"}, r"formulation must be 'reduced' or 'conventional', got 'Reduced'"),
    ],
)
def test_contact_solves_refuse_knobs_that_make_their_answer_meaningless(call, kw, msg):
    """tol=1.0 reported the middle of the flank as a converged contact after 0 iterations (TE -99
    arcsec where the contact gives 0.36); a NaN or infinite TE reference made every TE NaN or -inf
    with status converged."""
    with pytest.raises(ValueError, match=msg):
        call(_pair(), np.array([0.0, 0.02]), **kw)


def test_the_largest_tolerance_still_solves():
    c = solve_contact(_pair(), np.array([0.0, 0.02]), tol=1e-3)
    assert c.converged.all() and (c.iterations >= 1).all()


@pytest.mark.parametrize(
    "make, msg",
    [
        (lambda: InvoluteGearData(20, 1.0, ALPHA, "10"), r"face_width must be a finite number, got '10'"),
        (lambda: InvoluteGearData(20, True, ALPHA, 10.0), r"module must be a finite number, got True"),
        (lambda: ParabolicCrowning("0.003"), r"c1 must be a finite number, got '0.003'"),
        (lambda: __import__("gearrep.tca", fromlist=["Misalignment"]).Misalignment(d_E="0.1"), r"d_E must be a finite"),
        (
            lambda: __import__("gearrep.tca", fromlist=["BevelMisalignment"]).BevelMisalignment(d_A="0.1"),
            r"d_A must be a finite number, got '0.1'",
        ),
    ],
)
def test_numbers_given_as_strings_or_bools_are_refused_where_they_are_given(make, msg):
    """A numeric string passed the checks (float('10') works) and was stored as a string, to fail
    far away ("unsupported operand type(s) for +: 'float' and 'str'" in a later solve)."""
    with pytest.raises(ValueError, match=msg):
        make()


@pytest.mark.parametrize(
    "a, pb, msg",
    [
        (40.0, None, r"no path of contact: at centre_distance = 40.0 the tip circles do not reach across"),
        (np.nan, None, r"centre_distance must be finite and > 0 \[mm\], got nan"),
        (30.0, np.inf, r"base_pitch must be finite and > 0 \[mm\], got inf"),
    ],
)
def test_closed_form_contact_ratio_has_no_negative_values(a, pb, msg):
    """Gears too far apart gave a contact ratio of -4.5, NaN inputs NaN and an infinite base pitch 0."""
    from gearrep.meshing import contact_ratio_closed_form

    g1, g2 = _gears()
    pb = g1.base_pitch if pb is None else pb
    assert contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, 30.0, g1.base_pitch) > 1.0
    with pytest.raises(ValueError, match=msg):
        contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, a, pb)


@pytest.mark.parametrize(
    "kw, msg",
    [
        ({"phase2": np.nan}, r"phase2 must be finite, got nan"),
        ({"phase2": np.inf}, r"phase2 must be finite, got inf"),
        ({"shaft_angle": "0"}, r"shaft_angle must be a finite number, got '0'"),
        ({"n1": np.nan}, r"n1 must be a positive integer, got nan"),
        ({"n1": None}, r"n1 must be a positive integer, got None"),
        ({"n1": True}, r"n1 must be a positive integer, got True"),
    ],
)
def test_gear_pair_checks_every_argument(kw, msg):
    """phase2=nan built a pair whose first solve failed on "M must be one finite 3x3 matrix" (an
    internal matrix, not the argument); n1=nan or None gave raw conversion errors."""
    g1, g2 = _gears()
    f1, f2 = mating_flanks(g1, g2, crowning1=CROWN)
    args = {"n1": 20, "n2": 40} | kw
    extra = {k: v for k, v in kw.items() if k not in ("n1", "n2")}
    with pytest.raises(ValueError, match=msg):
        GearPair(f1, f2, args["n1"], args["n2"], standard_centre_distance(g1, g2), **extra)


def test_bevel_flanks_need_the_bevel_pair_and_line_of_action_starts_need_involutes():
    """Both failed with AttributeErrors about internals ('axial_view', 'alpha_t')."""
    from gearrep.surfaces.bevel import BevelGearData, mating_bevel_flanks
    from gearrep.tca import BevelPair

    f1, f2 = mating_bevel_flanks(BevelGearData(39, 32, 2.5, ALPHA, 14.0), BevelGearData(32, 39, 2.5, ALPHA, 14.0))
    with pytest.raises(ValueError, match=r"bevel \(spherical\) flanks mesh on intersecting axes.*BevelPair"):
        GearPair(f1, f2, 39, 32, 50.0)
    bevel = BevelPair(f1, f2, 39, 32)
    for call, phi in ((line_of_action_start, 0.0), (line_of_action_starts, [0.0])):
        with pytest.raises(ValueError, match=r"line-of-action starts need member 1 to be a cylindrical involute"):
            call(bevel, phi)
    with pytest.raises(ValueError, match=r"phi1 must be finite"):
        line_of_action_starts(_pair(), [np.nan])


@pytest.mark.parametrize("margin", [0.7, np.nan, -0.1])
def test_flank_boxes_refuse_a_margin_that_inverts_the_box(margin):
    from gearrep.tca import flank_boxes

    with pytest.raises(ValueError, match=r"margin must be in \[0, 0.5\) \(fraction of the flank height\)"):
        flank_boxes(_pair(), margin)


@pytest.mark.parametrize(
    "kw, msg",
    [
        ({"lower": [np.nan]}, r"lower and upper must not be NaN \(use -inf or inf for no bound\)"),
        ({"upper": np.nan}, r"lower and upper must not be NaN"),
        ({"rcond": np.nan}, r"rcond must be in \[0, 1\) \(relative singular-value threshold\), got nan"),
        ({"rcond": 1.5}, r"rcond must be in \[0, 1\)"),
    ],
)
def test_newton_refuses_nan_bounds_and_thresholds(kw, msg):
    """A NaN bound reported the root of x - 1 as off_flank, a NaN rcond as singular."""
    from gearrep.solve import newton

    with pytest.raises(ValueError, match=msg):
        newton(lambda x: x - 1.0, np.zeros((1, 1)), lambda x: np.ones((len(x), 1, 1)), **kw)
