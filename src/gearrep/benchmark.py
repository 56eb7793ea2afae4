"""Run time against error: repeated timing, accuracy sweeps, Pareto fronts and the knee setting.

Used by the ``bench`` workflow target (``workflow/rules/bench.smk``). Pure functions: the caller
passes the computation and the settings; nothing here reads files or the config.

* :func:`time_call`: median wall time of repeated calls (``time.perf_counter``), with the machine
  load (1-minute load average) recorded beside it, so that a timing taken on a busy machine can be
  recognised as such.
* :func:`sweep`: runs a computation for every setting of its accuracy knobs, and measures the
  error of each against a reference result computed in the same process at the most accurate
  setting (the caller supplies the reference setting and the error metric).
* :func:`pareto_front`: the settings that no other setting beats in both time and error.
* :func:`reference_kernel`: a fixed numpy computation (per element 20 sin/cos and 300
  multiply-adds) that run times are expressed in, so that a throughput figure measured on one
  machine under some load can be compared with one measured elsewhere; :func:`time_interleaved`
  times several computations and the reference kernel in turns (best of several rounds), so that
  a change of load during the run hits all of them alike.
* :func:`tca_throughput`: contact solves of one gear pair vectorised, one point per call, and
  with ``scipy.optimize.root`` point by point (:func:`scipy_root_solves`, the baseline a user
  would write), each in reference-kernel elements per solve, measured in one interleaved run.
* :func:`knee`: the setting chosen as default: on the Pareto front, in log10(time)-log10(error)
  coordinates scaled to the unit square, the point farthest below the chord joining the fastest
  and the most accurate front points (the "knee": past it, extra time buys little accuracy).
  With ``error_target`` it is instead the fastest front point whose error meets the target (the
  target being a stated fraction of the tightest published tolerance, say), falling back to the
  knee when no point meets it.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from .tca import check_formulation, conventional_system, reduced_unknowns, solve_contact

__all__ = [
    "ERROR_FLOOR",
    "Timing",
    "load_average",
    "time_call",
    "REFERENCE_SIN_COS",
    "REFERENCE_MULTIPLY_ADDS",
    "reference_kernel",
    "time_interleaved",
    "THROUGHPUT_TARGETS",
    "FAMILY_TARGETS",
    "scipy_root_solves",
    "tca_throughput",
    "sweep",
    "pareto_front",
    "knee",
]

#: error floor used in log coordinates (an exact result has error 0)
ERROR_FLOOR = 1e-300


@dataclass(frozen=True)
class Timing:
    """Wall times of ``repeats`` calls: median and minimum in seconds, and the 1-min load average."""

    median_s: float
    min_s: float
    repeats: int
    load_1min: float


def load_average() -> float:
    """The 1-minute load average of the machine (NaN where the OS does not report it)."""
    try:
        return float(os.getloadavg()[0])
    except (AttributeError, OSError):
        return float("nan")


def time_call(fn: Callable[[], Any], *, repeats: int = 5, warmup: int = 1) -> tuple[Any, Timing]:
    """Call ``fn()`` ``warmup`` times untimed, then ``repeats`` times timed; return the last result
    and its :class:`Timing` (median, min). ``repeats`` >= 1, ``warmup`` >= 0."""
    if not isinstance(repeats, (int, np.integer)) or repeats < 1:
        raise ValueError(f"repeats must be an integer >= 1, got {repeats!r}")
    if not isinstance(warmup, (int, np.integer)) or warmup < 0:
        raise ValueError(f"warmup must be an integer >= 0, got {warmup!r}")
    result = None
    for _ in range(warmup):
        result = fn()
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return result, Timing(float(np.median(times)), float(np.min(times)), int(repeats), load_average())


#: per element of :func:`reference_kernel`: transcendental calls and multiply-adds
REFERENCE_SIN_COS = 20
REFERENCE_MULTIPLY_ADDS = 300


def reference_kernel(n: int) -> np.ndarray:
    """The fixed reference computation on ``n`` elements: 10 rounds of (one sine, one cosine, then
    15 times y <- y * a + s and y <- y * b + c), i.e. 20 sin/cos and 300 multiply-adds per element,
    with numpy in place on float64 arrays (each multiply-add two array passes). Returns y (bounded,
    so that no overflow or denormal slows it down)."""
    if not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"n must be an integer >= 1, got {n!r}")
    y = np.linspace(0.1, 1.0, int(n))
    s = np.empty_like(y)
    c = np.empty_like(y)
    for _ in range(REFERENCE_SIN_COS // 2):
        np.sin(y, out=s)
        np.cos(y, out=c)
        for _ in range(REFERENCE_MULTIPLY_ADDS // 20):
            y *= 0.5
            y += s
            y *= 0.5
            y += c
    return y


def time_interleaved(
    fns: dict[str, Callable[[], Any]],
    *,
    repeats: int = 5,
    warmup: int = 1,
    clock: Callable[[], float] = time.perf_counter,
) -> dict[str, float]:
    """Best (minimum) time in seconds of each computation in ``fns`` over ``repeats`` rounds; in
    every round each is called once, in the given order, so that all see the same load.
    ``warmup`` untimed rounds first. ``clock``: wall time (default) or e.g. ``time.process_time``
    (CPU time of this process, which other processes on a shared machine do not inflate)."""
    if not isinstance(repeats, (int, np.integer)) or repeats < 1:
        raise ValueError(f"repeats must be an integer >= 1, got {repeats!r}")
    if not isinstance(warmup, (int, np.integer)) or warmup < 0:
        raise ValueError(f"warmup must be an integer >= 0, got {warmup!r}")
    if not fns:
        raise ValueError("fns must hold at least one computation")
    for _ in range(warmup):
        for fn in fns.values():
            fn()
    best = {k: np.inf for k in fns}
    for _ in range(repeats):
        for k, fn in fns.items():
            t0 = clock()
            fn()
            best[k] = min(best[k], clock() - t0)
    return {k: float(v) for k, v in best.items()}


#: throughput targets in reference-kernel elements per solve (vectorised) or per call (single
#: point), for the crowned 52/72 spur pair of docs/library.md
THROUGHPUT_TARGETS = {"reduced": 6.0, "conventional": 12.0, "single": 1000.0}

#: targets of every gear family in reference-kernel elements per vectorised solve and per
#: single-point call, by the kind of tooth surface: "analytic" (closed-form surfaces: involute,
#: bevel, CATT, rack-generated Novikov-Wildhaber) or "generated" (a tool's envelope solved where
#: it is evaluated: worm- and disk-ground Novikov pinions, hob-cut flanks); a benchmark fails a
#: family above 1.5 times its targets
FAMILY_TARGETS = {
    "analytic": {"vectorised": 30.0, "single": 3000.0},
    "generated": {"vectorised": 150.0, "single": 10000.0},
}


def scipy_root_solves(pair, phi1, start, formulation: str = "reduced", *, tol: float = 1e-12):
    """The same contact solves with ``scipy.optimize.root`` (MINPACK hybrid method), one point per
    call, as a user of the public API would write them: the conventional system from
    :func:`gearrep.tca.conventional_system` (its analytic Jacobian, the dropped normal component
    the largest at the start), the reduced one as two components of n_f1 x n_f2 with member 2
    back-substituted by :func:`gearrep.tca.reduced_unknowns` (finite-difference Jacobian).
    Returns (x (n, 2 or 5), success (n,) bool)."""
    from scipy.optimize import root

    check_formulation(formulation)
    phi1 = np.atleast_1d(np.asarray(phi1, float))
    start = np.atleast_2d(np.asarray(start, float))
    if len(start) != len(phi1):
        raise ValueError(f"start has {len(start)} rows for {len(phi1)} angles")
    xs, ok = [], []
    for p, x0 in zip(phi1, start):
        _, n1 = pair.member1(x0[:1], x0[1:2], np.array([p]))
        drop = int(np.argmax(np.abs(n1[0])))
        if formulation == "conventional":
            F, J = conventional_system(pair, p, drop)
            r = root(lambda x: F(x)[0], x0, jac=lambda x: J(x)[0], method="hybr", tol=tol)
        else:
            keep = [i for i in range(3) if i != drop]

            def fun(x, p=p, keep=keep):
                u2, v2, phi2 = reduced_unknowns(pair, x[:1], x[1:2], np.array([p]))
                _, a = pair.member1(x[:1], x[1:2], np.array([p]))
                _, b = pair.member2(u2, v2, phi2)
                return np.cross(a[0], b[0])[keep]

            r = root(fun, x0, method="hybr", tol=tol)
        xs.append(r.x)
        ok.append(bool(r.success))
    return np.array(xs), np.array(ok)


def _iterations(result) -> np.ndarray:
    """Newton iterations per row of a contact solve's result (``iterations`` or ``solve.iterations``)."""
    it = getattr(result, "iterations", None)
    return np.asarray(result.solve.iterations if it is None else it)


def _throughput_inputs(phi1, start, n_single, scipy_points, solve):
    """(phi1, start) as float arrays after the checks of :func:`tca_throughput` (ValueError naming
    the argument)."""
    if solve is not None and scipy_points:
        raise ValueError("scipy_points must be 0 with a solve of the family's own")
    phi1 = np.asarray(phi1, float)
    start = np.asarray(start, float)
    n = len(phi1)
    if n < 1 or len(start) != n:
        raise ValueError(f"phi1 and start must have the same length >= 1, got {n} and {len(start)}")
    if not isinstance(n_single, (int, np.integer)) or not 1 <= n_single <= n:
        raise ValueError(f"n_single must be an integer in [1, {n}], got {n_single!r}")
    if not isinstance(scipy_points, (int, np.integer)) or not 0 <= scipy_points <= n:
        raise ValueError(f"scipy_points must be an integer in [0, {n}], got {scipy_points!r}")
    return phi1, start


def tca_throughput(
    pair,
    phi1,
    start,
    *,
    formulation: str,
    n_single: int,
    repeats: int = 5,
    solve_kwargs: dict | None = None,
    scipy_points: int = 0,
    solve: Callable[[np.ndarray, np.ndarray], Any] | None = None,
) -> dict:
    """Contact solves of ``pair`` at the angles ``phi1`` from ``start`` (one row per angle), timed in
    ONE interleaved run (:func:`time_interleaved`, best of ``repeats``, CPU time of the process:
    on a shared machine the load of other processes stretches wall times unevenly, the short
    reference kernel finding a quiet moment more often than a long solve) with the reference kernel
    on as many elements as there are angles (at least 10 000): vectorised (one :func:`gearrep.tca.solve_contact`
    call), single point (``n_single`` calls of one point each) and, with ``scipy_points`` > 0,
    :func:`scipy_root_solves` on that many points. Returns seconds and reference elements per
    solve (per call for the single points; CPU seconds), the converged fractions, the mean Newton
    iterations of the vectorised solve, and the machine load before and after. ``solve(phi1, start)``
    replaces :func:`gearrep.tca.solve_contact` for a family with its own contact solve (e.g.
    :func:`gearrep.tca.solve_envelope_points`); its result has ``converged`` and ``iterations`` or
    ``solve.iterations`` (``solve_kwargs`` and ``scipy_points`` are then unused)."""
    phi1, start = _throughput_inputs(phi1, start, n_single, scipy_points, solve)
    n = len(phi1)
    kw = dict(solve_kwargs or {})
    own = solve

    def one(i):
        if own is not None:
            return own(phi1[i : i + 1], start[i : i + 1])
        return solve_contact(
            pair,
            phi1[i : i + 1],
            start[i : i + 1],
            formulation=formulation,
            **{k: (v[i : i + 1] if isinstance(v, np.ndarray) else v) for k, v in kw.items()},
        )

    def batch():
        if own is not None:
            return own(phi1, start)
        return solve_contact(pair, phi1, start, formulation=formulation, **kw)

    out = {}
    n_ref = max(n, 10_000)  # enough elements that the kernel's own per-call overhead does not count
    fns = {
        "reference": lambda: reference_kernel(n_ref),
        "vectorised": lambda: out.__setitem__("vec", batch()),
        "single": lambda: out.__setitem__("single", [one(i) for i in range(n_single)]),
    }
    if scipy_points:
        fns["scipy"] = lambda: out.__setitem__(
            "scipy", scipy_root_solves(pair, phi1[:scipy_points], start[:scipy_points], formulation)
        )
    load0 = load_average()
    t = time_interleaved(fns, repeats=repeats, clock=time.process_time)
    ref = t["reference"] / n_ref
    row = {
        "formulation": formulation,
        "n_vectorised": n,
        "n_single": int(n_single),
        "reference_s_per_element": ref,
        "vectorised_s_per_solve": t["vectorised"] / n,
        "vectorised_elements_per_solve": t["vectorised"] / n / ref,
        "single_s_per_call": t["single"] / n_single,
        "single_elements_per_call": t["single"] / n_single / ref,
        "converged_fraction_vectorised": float(np.mean(out["vec"].converged)),
        "converged_fraction_single": float(np.mean([c.converged[0] for c in out["single"]])),
        "mean_iterations": float(np.mean(_iterations(out["vec"]))),
        "load_1min_before": load0,
        "load_1min_after": load_average(),
    }
    if scipy_points:
        xs, ok = out["scipy"]
        mine = out["vec"].unknowns(formulation)[:scipy_points]
        both = ok & out["vec"].converged[:scipy_points]
        row.update(
            scipy_points=int(scipy_points),
            scipy_s_per_solve=t["scipy"] / scipy_points,
            scipy_elements_per_solve=t["scipy"] / scipy_points / ref,
            scipy_over_vectorised=(t["scipy"] / scipy_points) / (t["vectorised"] / n),
            scipy_over_single=(t["scipy"] / scipy_points) / (t["single"] / n_single),
            scipy_success_fraction=float(np.mean(ok)),
            scipy_max_abs_difference=float(np.max(np.abs(xs[both] - mine[both]))) if both.any() else float("nan"),
        )
    return row


def sweep(
    run: Callable[[dict], Any],
    settings: list[dict],
    reference: dict,
    error: Callable[[Any, Any], float],
    *,
    repeats: int = 3,
) -> pd.DataFrame:
    """Time ``run(setting)`` for each setting and measure ``error(result, reference_result)``.

    run : computation of one setting (a dict of knob values)
    settings : the knob settings to sweep (each a dict with the same keys)
    reference : the high-accuracy setting; its result is computed first, in the same process
    error : non-negative error of a result against the reference result (a float; NaN if failed)
    Returns one row per setting: the knob columns, ``time_s`` (median), ``time_min_s``, ``error``,
    ``load_1min``, ``pareto`` (on the front) and ``knee`` (the chosen default).
    """
    if not settings:
        raise ValueError("settings must hold at least one knob setting")
    keys = list(settings[0])
    for s in settings:
        if list(s) != keys:
            raise ValueError(f"settings must all have the knobs {keys}, got {list(s)}")
    ref = run(dict(reference))
    rows = []
    for s in settings:
        res, t = time_call(lambda s=s: run(dict(s)), repeats=repeats, warmup=0)
        err = float(error(res, ref))
        if not (np.isnan(err) or err >= 0):
            raise ValueError(f"error must be non-negative or NaN, got {err} for setting {s}")
        rows.append({**s, "time_s": t.median_s, "time_min_s": t.min_s, "error": err, "load_1min": t.load_1min})
    out = pd.DataFrame(rows)
    out["pareto"] = pareto_front(out["time_s"].to_numpy(), out["error"].to_numpy())
    k = knee(out["time_s"].to_numpy(), out["error"].to_numpy())
    out["knee"] = np.arange(len(out)) == k
    return out


def pareto_front(time_s, error) -> np.ndarray:
    """Boolean mask of the non-dominated points: no other point is at least as fast AND at least
    as accurate, and strictly better in one. Points with a NaN error are never on the front."""
    t = np.asarray(time_s, float)
    e = np.asarray(error, float)
    if t.shape != e.shape or t.ndim != 1:
        raise ValueError("time_s and error must be 1-D arrays of the same length")
    ok = np.isfinite(t) & np.isfinite(e)
    mask = np.zeros(t.shape, bool)
    for i in np.flatnonzero(ok):
        better_eq = ok & (t <= t[i]) & (e <= e[i])
        strictly = better_eq & ((t < t[i]) | (e < e[i]))
        mask[i] = not strictly.any()
    return mask


def knee(time_s, error, *, error_target: float | None = None) -> int:
    """Index of the chosen default setting (see the module docstring). Raises ValueError if no
    point has a finite time and error."""
    t = np.asarray(time_s, float)
    e = np.asarray(error, float)
    front = np.flatnonzero(pareto_front(t, e))
    if front.size == 0:
        raise ValueError("no setting has a finite time and error")
    if error_target is not None:
        if not error_target > 0:
            raise ValueError(f"error_target must be > 0, got {error_target}")
        good = front[e[front] <= error_target]
        if good.size:
            return int(good[np.argmin(t[good])])
    if front.size <= 2:
        return int(front[np.argmin(e[front])])  # two points: nothing to trade, take the accurate one
    x = np.log10(t[front])
    y = np.log10(np.maximum(e[front], ERROR_FLOOR))
    xs = (x - x.min()) / max(np.ptp(x), 1e-300)
    ys = (y - y.min()) / max(np.ptp(y), 1e-300)
    a, b = np.argmin(xs), np.argmin(ys)  # fastest, most accurate
    d = np.array([xs[b] - xs[a], ys[b] - ys[a]])
    # signed distance below the chord from the fastest to the most accurate point
    dist = (d[0] * (ys - ys[a]) - d[1] * (xs - xs[a])) / max(np.hypot(*d), 1e-300)
    return int(front[np.argmin(dist)]) if np.min(dist) < 0 else int(front[b])
