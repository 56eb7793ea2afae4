"""gearrep.benchmark: timing records, Pareto fronts and the knee against hand-worked cases; the load
average."""

import math

import numpy as np
import pytest

from gearrep import benchmark as B


def test_time_call_counts_calls_and_reports_median():
    calls = []
    res, t = B.time_call(lambda: calls.append(1) or len(calls), repeats=4, warmup=2)
    assert res == 6 and len(calls) == 6
    assert t.repeats == 4 and 0 <= t.min_s <= t.median_s


@pytest.mark.parametrize("kw, name", [({"repeats": 0}, "repeats"), ({"warmup": -1}, "warmup")])
def test_time_call_rejects_bad_counts(kw, name):
    with pytest.raises(ValueError, match=name):
        B.time_call(lambda: None, **kw)


def test_pareto_front_by_hand():
    t = np.array([1.0, 2.0, 2.0, 3.0, 0.5, np.nan])
    e = np.array([1e-3, 1e-6, 1e-5, 1e-6, 1e-1, 0.0])
    # (2, 1e-5) is dominated by (2, 1e-6); (3, 1e-6) by (2, 1e-6); NaN time never on the front
    assert B.pareto_front(t, e).tolist() == [True, True, False, False, True, False]


def test_knee_is_the_corner_of_an_L_shaped_front():
    # error falls fast up to t = 1, then barely: the knee is t = 1
    t = np.array([0.1, 0.3, 1.0, 3.0, 10.0])
    e = np.array([1e-1, 1e-4, 1e-10, 5e-11, 3e-11])
    assert B.knee(t, e) == 2


def test_knee_with_error_target_takes_fastest_meeting_it():
    t = np.array([0.1, 0.3, 1.0, 3.0])
    e = np.array([1e-1, 1e-4, 1e-10, 5e-11])
    assert B.knee(t, e, error_target=1e-3) == 1
    assert B.knee(t, e, error_target=1e-20) == B.knee(t, e)  # unmet: the knee
    with pytest.raises(ValueError, match="error_target"):
        B.knee(t, e, error_target=0.0)


def test_knee_needs_a_finite_point():
    with pytest.raises(ValueError, match="finite"):
        B.knee([np.nan], [1.0])


def _partial_e(n):
    return sum(1.0 / math.factorial(k) for k in range(n))


def test_sweep_measures_error_against_the_reference():
    # the error of a truncated series for e is known exactly
    out = B.sweep(
        lambda s: _partial_e(s["n"]),
        [{"n": n} for n in (2, 4, 8, 16)],
        {"n": 30},
        lambda r, ref: abs(r - ref),
        repeats=2,
    )
    assert list(out.columns) == ["n", "time_s", "time_min_s", "error", "load_1min", "pareto", "knee"]
    np.testing.assert_allclose(out["error"], [abs(_partial_e(n) - math.e) for n in (2, 4, 8, 16)], atol=1e-15)
    assert out["knee"].sum() == 1
    with pytest.raises(ValueError, match="knobs"):
        B.sweep(lambda s: 0.0, [{"n": 1}, {"m": 2}], {"n": 3}, lambda r, ref: 0.0)


def test_reference_kernel_and_interleaved_timing():
    y = B.reference_kernel(7)
    assert y.shape == (7,) and np.all(np.isfinite(y))
    assert B.REFERENCE_SIN_COS == 20 and B.REFERENCE_MULTIPLY_ADDS == 300
    calls = []
    t = B.time_interleaved({"a": lambda: calls.append("a"), "b": lambda: calls.append("b")}, repeats=3, warmup=1)
    assert calls == ["a", "b"] * 4 and set(t) == {"a", "b"} and all(v >= 0 for v in t.values())
    for bad in ({"repeats": 0}, {"warmup": -1}):
        with pytest.raises(ValueError, match=next(iter(bad))):
            B.time_interleaved({"a": lambda: None}, **bad)
    with pytest.raises(ValueError, match="n must be"):
        B.reference_kernel(0)


def test_scipy_baseline_finds_the_same_contacts():
    from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
    from gearrep.tca import GearPair, Misalignment, default_start, solve_contact

    g1, g2 = InvoluteGearData(52, 1.0, np.radians(20), 11.42), InvoluteGearData(72, 1.0, np.radians(20), 11.42)
    f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(0.002857))
    pair = GearPair(f1, f2, 52, 72, standard_centre_distance(g1, g2), misalignment=Misalignment(d_gamma_out=1e-3))
    phi = np.array([-0.05, -0.03, 0.0])
    for form in ("reduced", "conventional"):
        start = default_start(pair, phi, form)
        x, ok = B.scipy_root_solves(pair, phi, start, form)
        c = solve_contact(pair, phi, start, formulation=form)
        assert ok.all() and c.converged.all()
        np.testing.assert_allclose(x, c.unknowns(form), atol=1e-9)
    r = B.tca_throughput(
        pair, phi, default_start(pair, phi, "reduced"), formulation="reduced", n_single=2, repeats=1, scipy_points=2
    )
    assert r["converged_fraction_vectorised"] == 1.0 and r["scipy_success_fraction"] == 1.0
    assert r["vectorised_elements_per_solve"] > 0 and r["scipy_over_single"] > 0
    with pytest.raises(ValueError, match="n_single"):
        B.tca_throughput(pair, phi, default_start(pair, phi, "reduced"), formulation="reduced", n_single=5)


def test_throughput_of_a_family_with_its_own_solve():
    """A family with its own contact solve (``solve=``) is timed the same way; the row holds the
    vectorised solve's mean Newton iterations (from ``iterations`` or ``solve.iterations``)."""
    from types import SimpleNamespace

    from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
    from gearrep.tca import GearPair, Misalignment, default_start, solve_contact

    g1, g2 = InvoluteGearData(52, 1.0, np.radians(20), 11.42), InvoluteGearData(72, 1.0, np.radians(20), 11.42)
    f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(0.002857))
    pair = GearPair(f1, f2, 52, 72, standard_centre_distance(g1, g2), misalignment=Misalignment(d_gamma_out=1e-3))
    phi = np.array([-0.05, -0.03, 0.0])
    start = default_start(pair, phi, "reduced")
    calls = []

    def own(ph, st):  # a result shaped like gearrep.tca.EnvelopeContactPath (iterations in .solve)
        calls.append(len(ph))
        c = solve_contact(pair, ph, st, formulation="reduced")
        return SimpleNamespace(converged=c.converged, solve=SimpleNamespace(iterations=c.iterations))

    r = B.tca_throughput(pair, phi, start, formulation="own", n_single=2, repeats=1, solve=own)
    assert 3 in calls and 1 in calls  # the vectorised call and the single-point calls went to it
    assert r["converged_fraction_single"] == 1.0 and r["formulation"] == "own"
    assert r["mean_iterations"] == solve_contact(pair, phi, start, formulation="reduced").iterations.mean()
    with pytest.raises(ValueError, match="scipy_points"):
        B.tca_throughput(pair, phi, start, formulation="own", n_single=2, scipy_points=1, solve=own)


def test_load_average_is_a_nonnegative_number_or_nan():
    la = B.load_average()
    assert isinstance(la, float) and (math.isnan(la) or la >= 0.0)
