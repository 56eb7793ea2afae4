"""gearrep.replications._params: the shared checks of replication parameter dicts."""

import pytest

from gearrep.replications import _params

DEFAULTS = {"tol": 1e-12, "n": 5, "nested": {"a": 1}}


def test_merge_overlays_copies_and_refuses_unknown_keys():
    p = _params.merge("demo", DEFAULTS, {"n": 7}, {"tol": 1e-9})
    assert p == {"tol": 1e-9, "n": 7, "nested": {"a": 1}}
    p["nested"]["a"] = 2
    assert DEFAULTS["nested"]["a"] == 1  # defaults are not shared with the result
    assert _params.merge("demo", DEFAULTS, {"design": 1}, passthrough=("design",))["design"] == 1
    with pytest.raises(ValueError, match=r"demo params: unknown key 'nn'.*allowed \['n', 'nested', 'tol'\]"):
        _params.merge("demo", DEFAULTS, {"nn": 1})
    with pytest.raises(ValueError, match="must be a dict"):
        _params.merge("demo", DEFAULTS, [("n", 1)])


def test_number_positive_counts():
    assert _params.number({"x": "2.5"}, "x", 0, 3) == 2.5
    assert _params.number({"k": 4.0}, "k", 1, 10, integer=True) == 4
    for bad in ({"x": 4}, {"x": float("nan")}, {"x": "a"}):
        with pytest.raises(ValueError, match=r"x must be a number in \[0, 3\]"):
            _params.number(bad, "x", 0, 3)
    with pytest.raises(ValueError, match="k must be an integer"):
        _params.number({"k": 4.5}, "k", 1, 10, integer=True)
    _params.positive("demo", {"a": 1e-9}, ["a"])
    with pytest.raises(ValueError, match="demo params: a must be > 0"):
        _params.positive("demo", {"a": 0.0}, ["a"])
    _params.counts("demo", {"n": 3}, ["n"])
    with pytest.raises(ValueError, match="demo params: n must be a positive integer"):
        _params.counts("demo", {"n": 2.5}, ["n"])
