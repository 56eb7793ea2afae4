"""The contact problem of the load distribution, solved by a primal active-set method.

Problem (Conry & Seireg, "A mathematical programming technique for the evaluation of load
distribution and optimal modifications for gear systems", J. Eng. Ind. 95 (1973) 1115-1122): at
the candidate contact points j, with initial separations s_j >= 0 [mm], a symmetric positive
definite compliance matrix C [mm/N], moment arms h_j > 0 [mm] of the normal loads about the driving
axis and the applied moment M [N mm], find loads F_j and the rigid rotation theta of the driving
member such that

    gap_j = s_j + (C F)_j - theta h_j >= 0,   F_j >= 0,   F_j gap_j = 0,   sum_j h_j F_j = M.

These are the KKT conditions of the convex quadratic programme
min 1/2 F^T C F + s^T F subject to F >= 0 and h^T F = M (theta is the multiplier of the equality),
which has one solution for C positive definite. The solver is the primal active-set method of
Nocedal & Wright, "Numerical Optimization", 2nd ed., Algorithm 16.3, started from the whole load
on the point of smallest s_j / h_j (a feasible point): each iteration solves the
equality-constrained problem on the working set, steps back to feasibility where a load would turn
negative (dropping that point), and adds the point with the most negative gap once the loads are
positive; it ends when every gap is >= -tol_gap and every load >= 0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..inputs import check_positive
from ..solve import Status

__all__ = ["ContactLoads", "solve_contact_loads", "solve_checked"]


@dataclass(frozen=True)
class ContactLoads:
    """Solution of the contact problem.

    Parameters
    ----------
    loads_N : numpy.ndarray
        (n,) loads F_j >= 0 [N].
    rotation : float
        theta, the driving member's rotation that closes the gaps [rad].
    gaps_mm : numpy.ndarray
        (n,) deformed gaps [mm] (0 where loaded).
    moment_residual : float
        |h.F - M| / M.
    complementarity : float
        max_j F_j gap_j / (M max h) (relative; 0 at the exact solution).
    iterations : int
        Working-set changes.
    status : int
        :class:`gearrep.solve.Status` (NOT_CONVERGED at the iteration limit, SINGULAR if a
        working-set system could not be solved).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.ltca import solve_contact_loads
    >>> loads = solve_contact_loads(np.array([1e-5, 1e-5]), [0.0, 0.002], [30.0, 30.0], 3000.0)  # mm/N, mm, mm, N mm
    >>> loads.loads_N.tolist(), np.round(loads.gaps_mm, 9).tolist(), loads.status  # N, mm
    ([100.0, 0.0], [0.0, 0.001], 0)
    """

    loads_N: np.ndarray
    rotation: float
    gaps_mm: np.ndarray
    moment_residual: float
    complementarity: float
    iterations: int
    status: int


def _check(C, s, h, moment):
    s = np.asarray(s, dtype=float)
    h = np.asarray(h, dtype=float)
    C = np.asarray(C, dtype=float)
    n = s.size
    if s.ndim != 1 or n == 0:
        raise ValueError(f"separations must be a non-empty 1-D array [mm], got shape {s.shape}")
    if h.shape != s.shape or C.shape not in ((n, n), (n,)):
        raise ValueError(f"arms must have shape {s.shape} and C shape {(n, n)} or {(n,)}, got {h.shape} and {C.shape}")
    if not (np.all(np.isfinite(s)) and np.all(np.isfinite(C)) and np.all(np.isfinite(h))):
        raise ValueError("separations, arms and compliance must be finite")
    if np.any(h <= 0):
        raise ValueError(f"moment arms must be > 0 [mm], got min {h.min()!r}")
    if C.ndim == 1 and np.any(C <= 0):
        raise ValueError(f"a diagonal compliance must be > 0 [mm/N], got min {C.min()!r}")
    check_positive("moment", moment)
    return C, s, h


def _working_set_solve(C, s, h, moment, P):
    """Loads on the working set P and theta from [C_PP -h_P; h_P^T 0] [F_P; theta] = [-s_P; M]; for a
    diagonal C (given as its diagonal) in closed form: F_P = (theta h_P - s_P) / c_P with
    theta = (M + sum h s / c) / sum h^2 / c."""
    if C.ndim == 1:
        c, hP, sP = C[P], h[P], s[P]
        theta = (moment + float(np.sum(hP * sP / c))) / float(np.sum(hP * hP / c))
        return (theta * hP - sP) / c, theta
    # the bordered system by its Schur complement: C_PP [a, b] = [h_P, s_P], theta = (M + h.b) / (h.a)
    hP = h[P]
    ab = np.linalg.solve(C[P][:, P], np.column_stack([hP, s[P]]))
    theta = (moment + float(hP @ ab[:, 1])) / float(hP @ ab[:, 0])
    return theta * ab[:, 0] - ab[:, 1], theta


def _apply(C, F, P=None):
    """C F (or the columns P of C times F[P]) for a full or diagonal C."""
    if C.ndim == 1:
        return C * F
    return C @ F if P is None else C[:, P] @ F[P]


def solve_contact_loads(
    C, s, h, moment, *, tol: float = 1e-12, maxiter: int | None = None, working=None
) -> ContactLoads:
    """Loads of the contact problem of the module docstring (units: mm, N, N mm).

    ``C`` is the (n, n) compliance matrix or, for independent points, its diagonal (n,).
    ``tol`` scales the gap test (a gap >= -tol max(s, |C| F scale) counts as open) and the load test;
    ``maxiter`` defaults to 3 n + 10 working-set changes; ``working`` an initial guess of the loaded
    points (indices; default those of smallest s/h), used only if it gives non-negative loads (else
    the whole load on the point of smallest s/h, a feasible start).

    Parameters
    ----------
    C : array_like
        (n, n) compliance matrix, or its diagonal (n,) [mm/N], positive definite.
    s : array_like
        (n,) initial separations [mm], >= 0.
    h : array_like
        (n,) moment arms [mm], > 0.
    moment : float
        Applied moment M [N mm], > 0.
    tol : float, optional
        Relative tolerance of the gap and load tests.
    maxiter : int, optional
        Working-set changes at most.
    working : array_like of int, optional
        Initial loaded points.

    Returns
    -------
    ContactLoads
        The loads, gaps and the solve record.

    Raises
    ------
    ValueError
        If the shapes or values are out of range.

    Examples
    --------
    Two equal springs, the second one 0.1 um farther away: both carry load, the nearer more.

    >>> import numpy as np
    >>> from gearrep.ltca import solve_contact_loads
    >>> r = solve_contact_loads(np.array([1e-5, 1e-5]), [0.0, 1e-4], [30.0, 30.0], 3000.0)  # mm/N, mm, mm, N mm
    >>> np.round(r.loads_N, 9).tolist(), r.status  # N
    ([55.0, 45.0], 0)
    """
    C, s, h = _check(C, s, h, moment)
    return solve_checked(C, s, h, float(moment), tol=tol, maxiter=maxiter, working=working)


def solve_checked(C, s, h, moment: float, *, tol: float = 1e-12, maxiter=None, working=None) -> ContactLoads:
    """:func:`solve_contact_loads` on inputs already checked (float arrays of the right shapes:
    the loaded analysis checks its problems once, when it builds them)."""
    n = s.size
    maxiter = 3 * n + 10 if maxiter is None else int(maxiter)
    F = np.zeros(n)
    start = None
    if working is None:  # the points of smallest separation (all of them for line contact)
        working = np.flatnonzero(s / h <= np.min(s / h) + tol * max(float(np.max(np.abs(s))), 1e-300) / np.max(h))
    known = None  # the working-set solution of the start, not solved twice
    if len(working):
        P0 = np.unique(np.asarray(working, dtype=int))
        try:
            FP, th0 = _working_set_solve(C, s, h, moment, P0)
        except np.linalg.LinAlgError:
            FP = None
        if FP is not None and np.all(FP >= 0):
            start = P0
            F[P0] = FP
            known = (FP, th0)
    if start is None:
        j = int(np.argmin(s / h))
        start = np.array([j])
        F[j] = moment / h[j]
    inP = np.zeros(n, dtype=bool)
    inP[start] = True
    theta = np.nan
    cmax = float(np.max(C)) if C.ndim == 1 else float(np.max(np.diag(C)))
    scale = max(float(np.max(np.abs(s))), cmax * moment / float(np.min(h)))
    status = int(Status.NOT_CONVERGED)
    it = 0
    for it in range(1, maxiter + 1):  # noqa: B007 (the count is reported)
        Pa = np.flatnonzero(inP)
        try:
            FP, theta = _working_set_solve(C, s, h, moment, Pa) if known is None else known
        except np.linalg.LinAlgError:
            status = int(Status.SINGULAR)
            break
        known = None
        if np.all(FP >= 0):
            F[:] = 0.0
            F[Pa] = FP
            gaps = s + _apply(C, F, Pa) - theta * h
            gaps[inP] = np.inf
            j = int(np.argmin(gaps))
            if gaps[j] >= -tol * scale:
                status = int(Status.CONVERGED)
                break
            inP[j] = True
            continue
        # step from the feasible F toward FP until the first load reaches zero; drop it
        cur = F[Pa]
        neg = FP < 0
        alpha = np.min(cur[neg] / (cur[neg] - FP[neg]))
        F[:] = 0.0
        F[Pa] = cur + alpha * (FP - cur)
        F[F <= tol * moment / float(np.max(h))] = 0.0
        inP = F > 0.0
        if not np.any(inP):  # numerical corner: restart from the smallest separation
            j = int(np.argmin(s / h))
            inP[j], F[j] = True, moment / h[j]
    gaps = s + _apply(C, F) - theta * h
    mres = abs(float(h @ F) - moment) / moment
    comp = float(np.max(np.abs(F * gaps))) / (moment / float(np.min(h)) * scale) if n else 0.0
    if status == int(Status.CONVERGED) and not np.isfinite(theta):
        status = int(Status.DIVERGED)
    return ContactLoads(F, float(theta), gaps, mres, comp, it, status)
