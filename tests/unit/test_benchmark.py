"""gearrep.benchmark: timing records, Pareto fronts and the knee against hand-worked cases."""

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
