"""Stress suite (issue 10 item 3): a fast subset runs by default; the full sweeps are marked slow.
Full version: `make stress` (pytest -m stress tests/stress, slow ones included).

Every test records the Jacobian condition numbers it saw (``record_conditions``); the table is
printed at the end of the run."""

from __future__ import annotations

import numpy as np
import pytest

_SEEN: list[tuple[str, int, int, float, float, float]] = []


@pytest.fixture()
def record_conditions(request):
    """Call with (array of condition numbers) to report them under the test's name."""

    def record(cond, label=""):
        c = np.asarray(cond, float)
        n_inf = int(np.sum(np.isposinf(c)))
        c = c[np.isfinite(c)]
        name = request.node.name + (f" [{label}]" if label else "")
        stats = (float(c.min()), float(np.median(c)), float(c.max())) if c.size else (np.nan,) * 3
        _SEEN.append((name, c.size, n_inf, *stats))

    return record


def pytest_terminal_summary(terminalreporter):
    if not _SEEN:
        return
    tr = terminalreporter
    tr.section("Jacobian condition numbers seen (converged and unconverged solves)")
    tr.write_line(f"{'case':70s} {'n':>6s} {'singular':>8s} {'min':>10s} {'median':>10s} {'max':>10s}")
    for name, n, n_inf, lo, med, hi in _SEEN:
        tr.write_line(f"{name[:70]:70s} {n:6d} {n_inf:8d} {lo:10.3g} {med:10.3g} {hi:10.3g}")
