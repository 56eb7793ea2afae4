"""Comparisons of floating-point results that hold on any machine (see tests/README.md).

Two code paths that compute the same quantity (one point on Python floats and the same point in a
numpy batch, a batch in blocks and whole, two machines' SIMD kernels) agree to the accuracy of the
computation, not bit for bit. These helpers state that accuracy once:

* a converged Newton solve stops at a residual norm below ``tol``; two converged solves of one
  system differ by at most about ``condition * (r_a + r_b)`` relative to the solution's scale
  (``condition`` = s_max / s_min of the Jacobian, recorded by the solver), plus a few ulps of each
  value's own rounding;
* the last iterate of a solve that did not converge is not a result (the library reports its
  status; its numbers may be anything on another machine), so only the status is compared there.

``nudged`` is the portability check's perturbation of a test design (``GEARREP_PERTURB_ULPS``, the
same switch that moves the published design data, ``gearrep.published.PERTURB_ENV``).
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from gearrep import published
from gearrep.solve import Status

EPS = float(np.finfo(float).eps)
#: ulps of rounding allowed on each value beyond the solver bound (a value formed by a few
#: operations from the solved unknowns: positions, normals, TE)
ROUNDING_ULPS = 64


def nudged(value: float) -> float:
    """A test design's length or angle as the portability check sees it: moved by a few ulps when
    ``GEARREP_PERTURB_ULPS`` is set, unchanged otherwise."""
    return published.perturbed_value(value, published.perturb_ulps_from_env())


def solve_bound(tol: float, condition, scale) -> np.ndarray:
    """Largest difference two converged solves of one system may show in a value of magnitude
    ``scale``: ``condition * 2 * tol`` (both residuals below ``tol``) plus ``ROUNDING_ULPS`` ulps,
    relative to ``max(1, |scale|)`` (unknowns and values of order 1 to 100 in mm and rad)."""
    c = np.nan_to_num(np.asarray(condition, dtype=float), nan=1.0, posinf=1e16)
    return (np.maximum(c, 1.0) * 2.0 * tol + ROUNDING_ULPS * EPS) * np.maximum(1.0, np.abs(scale))


def assert_same_solve(a, b, tol: float, fields, rows_a=None, rows_b=None, what: str = "") -> None:
    """Two solves of the same systems (records with ``status``, ``iterations``, ``condition`` and
    the array ``fields``): statuses equal (exact), and in the rows both converged the iterations
    within one step of each other, every field within :func:`solve_bound`, the condition numbers
    within 1e-6 relative (a diagnostic: its relative change is about condition x the difference of
    the iterates, far below that). ``rows_a``/``rows_b`` select and align rows (default: all)."""

    def take(rec, name, rows):
        x = np.asarray(getattr(rec, name))
        return x if rows is None else x[rows]

    sa, sb = take(a, "status", rows_a), take(b, "status", rows_b)
    np.testing.assert_array_equal(sa, sb, err_msg=f"{what} status")  # exact: codes
    ok = sa == Status.CONVERGED
    cond = np.fmax(take(a, "condition", rows_a), take(b, "condition", rows_b))[ok]
    ia, ib = take(a, "iterations", rows_a)[ok], take(b, "iterations", rows_b)[ok]
    assert np.all(np.abs(ia.astype(int) - ib.astype(int)) <= 1), f"{what} iterations {ia} vs {ib}"
    for f in fields:
        if f in ("status", "iterations", "condition"):
            continue
        x, y = take(a, f, rows_a)[ok], take(b, f, rows_b)[ok]
        bound = solve_bound(tol, cond.reshape(cond.shape + (1,) * (np.ndim(y) - 1)), y)
        bad = ~(np.abs(x - y) <= bound)
        assert not bad.any(), f"{what} {f}: {x[bad][:3]} vs {y[bad][:3]} (bound {bound[bad][:3]})"
    ca, cb = take(a, "condition", rows_a)[ok], take(b, "condition", rows_b)[ok]
    np.testing.assert_allclose(ca, cb, rtol=1e-6, err_msg=f"{what} condition")


def assert_rounding_close(a, b, ulps: int = ROUNDING_ULPS, err_msg: str = "") -> None:
    """``a`` and ``b`` are one formula evaluated by two routes that round differently (Python's
    ``math`` on floats against numpy's SIMD kernels, complex against real functions, one product
    of matrices against another order of it): equal within ``ulps`` units in the last place of the
    largest magnitude compared (a sum's rounding error scales with its largest term), at least 1."""
    a, b = np.asarray(a), np.asarray(b)
    kind = np.result_type(a, b, float)
    a, b = a.astype(kind), b.astype(kind)
    scale = max(1.0, float(np.nanmax(np.abs(b))) if np.size(b) else 1.0)
    np.testing.assert_allclose(a, b, rtol=0, atol=ulps * EPS * scale, err_msg=err_msg)


#: relative agreement asked of a computed value and its accepted reference
#: (tests/data/scorecard_reference.csv): the workflow's solves stop at residuals of 1e-12 in systems
#: whose condition numbers reach about 1e4 where no check states more, so 1e-8 relative is what the
#: computation resolves, on any machine and for inputs moved by a few ulps (the largest change such
#: a nudge makes, 1.4e-9 relative, is a percentage formed from two TE areas)
RTOL_REFERENCE = 1e-8
#: how a check states an ill-conditioned value: "Jacobian condition [up to | here is] 1.21e+07"
_CONDITION = re.compile(r"Jacobian condition (?:up to |here is )?(\d+(?:\.\d*)?(?:e[+-]?\d+)?)")


def stated_condition(note: str) -> float:
    """The largest Jacobian condition number a check's note states (1 when it states none)."""
    found = [float(c) for c in _CONDITION.findall(note)]
    return max([1.0, *found])


def reference_mismatches(ref, new) -> list[tuple]:
    """Rows of the scorecard ``new`` whose computed value differs from the reference ``ref`` by
    more than ``RTOL_REFERENCE`` relative plus the value's absolute resolution
    (``gearrep.checks.resolution`` of its unit), times the Jacobian condition number the row's
    check states for an ill-conditioned value (resolved only to that). Run times are not compared;
    NaN matches NaN. Frames of strings indexed by id, in the same order."""
    import pandas as pd

    from gearrep.checks import resolution

    timed = ref["quantity"].str.contains("time|second", case=False)
    ref, new = ref.loc[~timed], new.loc[~timed]
    x = pd.to_numeric(ref["computed"], errors="coerce")
    y = pd.to_numeric(new["computed"], errors="coerce")
    cond = ref["note"].map(stated_condition)
    scale = pd.concat([x.abs(), y.abs()], axis=1).max(axis=1)
    allowed = (RTOL_REFERENCE * scale + ref["unit"].map(resolution)) * cond
    close = ((x - y).abs() <= allowed) | (x.isna() & y.isna())
    return [(i, x[i], y[i], allowed[i]) for i in x.index[~close]]


#: a test that checks the design is read exactly as printed cannot hold on inputs the portability
#: pass moves on purpose; it runs in the default pass
reads_printed_design = pytest.mark.skipif(
    published.perturb_ulps_from_env() > 0,
    reason="compares the design with the printed numbers exactly; GEARREP_PERTURB_ULPS moves them by a few ulps",
)
