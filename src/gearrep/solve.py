"""Vectorised damped Newton solver that reports, never guesses.

Every solve returns a :class:`SolveResult` with the solution, the residual norm, the number of
iterations and a status for each of many independent problems solved at once (a batch of
starting points or meshing positions). A caller decides what to do with an unconverged point;
the solver never hands one back looking like a converged one.

The step is the least-squares Newton step (private module ``_newton_steps``): by SVD, so that
square (n equations, n unknowns) and over-determined systems (more equations than unknowns, e.g.
the vector equations of tooth contact) are handled alike and a rank-deficient Jacobian is detected
from its singular values instead of being inverted; 2 x 2 systems take a closed form, and with
``inverse_square`` larger square ones Gauss-Jordan elimination (up to 6 x 6; LAPACK's inverse
above), each with a bound of the condition that sends the rows it cannot clear of singularity to
the SVD.

Each algorithm (the Newton iteration, the 2 x 2 closed form, Gauss-Jordan elimination) exists in
two forms: on arrays for a batch, and on Python floats for one problem, which :func:`newton` takes
for a batch of one row and for the last active row of a batch. On one row numpy's cost per call
exceeds the arithmetic: with the batch form, a single-point contact solve of the README pair
(crowned spur 52/72) costs 1117 instead of 589 reference-kernel elements (reduced) and 1356
instead of 688 (conventional, measured in one interleaved run). Both forms do the same operations
in the same order (Gauss-Jordan bit for bit: +, -, x, / and abs only), so one problem gets the
record its row gets in a batch (tests/unit/core/test_solve.py).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from enum import IntEnum

import numpy as np

from ._newton_steps import step_batch, step_floats
from .inputs import check_integer, check_positive, real_or_nan

__all__ = [
    "Status",
    "STATUS_NAMES",
    "status_names",
    "SolveResult",
    "numeric_jacobian",
    "newton",
    "finite_rows",
]


class Status(IntEnum):
    """Outcome of one solve: the code stored per row in :attr:`SolveResult.status`.

    Examples
    --------
    >>> from gearrep.solve import Status
    >>> int(Status.OFF_FLANK), Status(3).name
    (2, 'SINGULAR')
    """

    CONVERGED = 0  #: residual below tolerance (and inside the bounds, when bounds are given)
    NOT_CONVERGED = 1  #: iteration limit reached, or the line search could not reduce the residual
    OFF_FLANK = 2  #: converged, but the root lies outside the parameter domain (the tooth flank)
    SINGULAR = 3  #: Jacobian rank-deficient at the iterate (relative singular value < rcond)
    WRONG_ROOT = 4  #: converged to a root other than a verified reference (set by callers)
    DIVERGED = 5  #: the iterate or residual became non-finite


#: status code -> lower-case name (``0: "converged"``, ...), as tables write the status
STATUS_NAMES = {s.value: s.name.lower() for s in Status}

#: the codes as ints for the one-row loop (an IntEnum member looked up on its class is slow there)
_S_CONVERGED, _S_NOT_CONVERGED, _S_OFF_FLANK, _S_SINGULAR, _S_DIVERGED = (
    int(s) for s in (Status.CONVERGED, Status.NOT_CONVERGED, Status.OFF_FLANK, Status.SINGULAR, Status.DIVERGED)
)


def status_names(status) -> np.ndarray:
    """Array of lower-case status names (``converged``, ``off_flank``, ...) for status codes.

    Parameters
    ----------
    status : int or array_like of int
        :class:`Status` codes.

    Returns
    -------
    numpy.ndarray
        Object array of the names, of the shape of ``status``.

    Examples
    --------
    >>> from gearrep.solve import status_names
    >>> status_names([0, 2, 5]).tolist()
    ['converged', 'off_flank', 'diverged']
    """
    status = np.asarray(status)
    out = np.empty(status.shape, dtype=object)
    for code, name in STATUS_NAMES.items():
        out[status == code] = name
    return out


@dataclass(frozen=True)
class SolveResult:
    """Result of a batch of solves.

    Attributes
    ----------
    x : (n, k) solutions (last iterate where not converged)
    residual : (n,) Euclidean norm of the residual at ``x``
    iterations : (n,) Newton iterations taken
    status : (n,) :class:`Status` codes
    condition : (n,) 2-norm condition number s_max/s_min of the Jacobian at the last iteration
        (inf where it was exactly singular, NaN where no iteration was taken); with
        ``newton(inverse_square=True)``, for square systems larger than 2 x 2, the Frobenius
        condition number ||J||_F ||J^-1||_F instead (an upper bound, at most k times the 2-norm
        one), except in rows the SVD examined as nearly singular

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.solve import newton
    >>> a = np.array([4.0, -1.0])  # x^2 = 4 and x^2 = -1, one problem per row
    >>> r = newton(lambda x, i: x**2 - a[i, None], [[1.0], [1.0]], rows=True)
    >>> r.status_name.tolist(), bool(r.converged[0]), round(float(r.x[0, 0]), 12)
    (['converged', 'not_converged'], True, 2.0)
    >>> len(r), r.with_status([True, False], 4).status_name.tolist()
    (2, ['wrong_root', 'not_converged'])
    """

    x: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    status: np.ndarray
    condition: np.ndarray | None = None

    @property
    def converged(self) -> np.ndarray:
        """Boolean mask of points with status CONVERGED."""
        return self.status == Status.CONVERGED

    @property
    def status_name(self) -> np.ndarray:
        """Lower-case status name of each point (:func:`status_names` of ``status``)."""
        return status_names(self.status)

    def with_status(self, mask, status: Status) -> SolveResult:
        """Copy with ``status`` set where ``mask`` holds (e.g. WRONG_ROOT after verification).

        Parameters
        ----------
        mask : (n,) array_like of bool
            The points to mark.
        status : Status
            The status they get.

        Returns
        -------
        SolveResult
            The same solutions, residuals, iterations and conditions; the new statuses.
        """
        st = self.status.copy()
        st[np.asarray(mask, dtype=bool)] = int(status)
        return SolveResult(self.x, self.residual, self.iterations, st, self.condition)

    def __len__(self) -> int:
        return len(self.status)


def numeric_jacobian(fun: Callable, x: np.ndarray, f0: np.ndarray | None = None, rel_step=1e-7):
    """Central-difference Jacobian of a batched function.

    Step ``h = rel_step * max(1, abs(x_j))``; the truncation error is O(h^2) and the rounding
    error O(eps / h), so 1e-7 gives about 8-9 correct digits for smooth, O(1)-scaled functions.

    Parameters
    ----------
    fun : callable
        Maps a batch of points (n, k) to residuals (n, m), row by row.
    x : (n, k) array_like
        The points (in the unknowns' own units).
    f0 : (n, m) array_like, optional
        ``fun(x)``, unused (central differences do not need it); accepted so callers can pass it.
    rel_step : float, optional
        Step relative to ``max(1, abs(x_j))``.

    Returns
    -------
    (n, m, k) numpy.ndarray
        The Jacobians, ``J[i, a, j] = d fun_a / d x_j`` at row ``i``.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.solve import numeric_jacobian
    >>> J = numeric_jacobian(lambda x: np.stack([x[:, 0] * x[:, 1], np.sin(x[:, 0])], -1), [[1.0, 2.0]])
    >>> J.shape, np.round(J, 6).tolist()
    ((1, 2, 2), [[[2.0, 1.0], [0.540302, 0.0]]])
    """
    x = np.asarray(x, dtype=float)
    n, k = x.shape
    cols = []
    for j in range(k):
        h = rel_step * np.maximum(1.0, np.abs(x[:, j]))
        xp = x.copy()
        xm = x.copy()
        xp[:, j] += h
        xm[:, j] -= h
        cols.append((fun(xp) - fun(xm)) / (2.0 * h)[:, None])
    return np.stack(cols, axis=-1)


def _row_norms(F):
    """Euclidean norms of the rows of F (what ``np.linalg.norm(F, axis=1)`` computes, without its
    Python overhead): the squares summed column by column, left to right (the order numpy's
    reduction of a short row takes), which avoids a reduction over a short axis."""
    if F.shape[1] >= 8:  # from 8 columns numpy sums a row pairwise: left to it
        return np.sqrt(np.add.reduce(F * F, axis=1))
    c = F[:, 0]
    acc = c * c
    for j in range(1, F.shape[1]):
        c = F[:, j]
        acc += c * c
    return np.sqrt(acc)


def _norm_floats(F) -> float:
    """:func:`_row_norms` of one row given as a list of floats, as a Python float (the same sum,
    left to right, and the correctly rounded square root of both)."""
    if len(F) >= 8:
        return float(_row_norms(np.array([F], dtype=float))[0])
    acc = F[0] * F[0]
    for v in F[1:]:
        acc += v * v
    return math.sqrt(acc)  # a sum of squares: never negative (NaN stays NaN)


def _all_finite(a) -> bool:
    """Whether every entry of a small array is finite (on Python floats: no numpy reduction)."""
    return all(map(math.isfinite, a.ravel().tolist()))


def finite_rows(a) -> np.ndarray:
    """Per row (first axis) of the array ``a``, whether every entry is finite (one pass when all are).

    Parameters
    ----------
    a : numpy.ndarray
        An array of at least one dimension.

    Returns
    -------
    (len(a),) numpy.ndarray of bool
        True where every entry of the row is finite.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.solve import finite_rows
    >>> finite_rows(np.array([[1.0, 2.0], [np.nan, 0.0], [0.0, np.inf]])).tolist()
    [True, False, False]
    """
    if len(a) == 1:
        return np.array([_all_finite(a)])
    fin = np.isfinite(a)
    if fin.all():
        return np.ones(len(a), dtype=bool)
    return fin.reshape(len(a), -1).all(axis=1)


def _matrix_finite(J) -> bool:
    """Whether every entry of a matrix given as a list of rows of floats is finite: a finite sum
    proves it (an inf or NaN entry makes the sum inf or NaN); otherwise each entry is tested."""
    return math.isfinite(sum(map(sum, J))) or all(math.isfinite(v) for row in J for v in row)


# -- the Newton iteration --------------------------------------------------------------------


def _dense(J):
    """A Jacobian as returned: a lazy one (a function, see :func:`newton`) formed for every row."""
    return J() if callable(J) else J


def _one_point_evaluator(fun, fun_jac, floats, k):
    """evaluate(x, derivs) -> (F, J or None) of one problem at the point ``x`` (a list of k
    floats) as lists (J as rows, with ``derivs``): by ``floats`` where given and it evaluates,
    else by the array callables on a batch of one."""

    def evaluate(xl, derivs):
        if floats is not None:
            out = floats(xl, derivs)
            if out is not None:
                return out
        xa = np.array([xl], dtype=float)
        if derivs:
            Fa, Ja = fun_jac(xa)
            Ja = _dense(Ja)
            Fa = np.asarray(Fa, dtype=float).reshape(-1)
            return Fa.tolist(), np.asarray(Ja, dtype=float).reshape(len(Fa), k).tolist()
        return np.asarray(fun(xa), dtype=float).reshape(-1).tolist(), None

    return evaluate


def _newton_one(fun, x, jac, fun_jac, floats, opts: _BatchOptions) -> SolveResult:
    """:func:`newton` for a batch of one (``x`` of shape (1, k)), without keep_inside: the same
    arithmetic (steps as :func:`step_batch`, residual norms as :func:`_row_norms`, the same Armijo
    test and statuses) on Python floats, the iterate, residual and Jacobian as lists (on one row
    numpy's per-call cost exceeds the arithmetic; tests/unit/core/test_solve.py). ``floats`` (optional)
    evaluates on lists; where it returns None the array callables evaluate."""
    k = x.shape[1]
    use_fj = fun_jac is not None
    evaluate = _one_point_evaluator(fun, fun_jac, floats, k)
    xl = x[0].tolist()
    F, J = evaluate(xl, use_fj)
    m = len(F)
    if m < k:
        raise ValueError(f"fun returns {m} equations for {k} unknowns; need m >= k")
    tol, rcond = opts.tol, opts.rcond
    res = _norm_floats(F)
    iters, cond = 0, math.nan
    finite = math.isfinite(res)
    status = _S_CONVERGED if res < tol else (_S_NOT_CONVERGED if finite else _S_DIVERGED)
    done = res < tol or not finite
    for _ in range(opts.maxiter):
        if done:
            break
        if J is None:
            xa = np.array([xl], dtype=float)
            Ja = _dense(jac(xa)) if jac is not None else numeric_jacobian(fun, xa, np.array([F], dtype=float))
            J = np.asarray(Ja, dtype=float).reshape(m, k).tolist()
        elif callable(J):  # a lazy Jacobian of the floats evaluation (lists)
            J = J()
        bad_j = not _matrix_finite(J)
        if bad_j:
            J = [[0.0] * k for _ in range(m)]
        d, singular, cond = step_floats(J, F, rcond, opts.inverse_square)
        singular = singular or bad_j
        if bad_j:
            cond = math.nan
        iters += 1
        lam = 1.0
        x_new = [a + b for a, b in zip(xl, d)]
        F_new, J_new = evaluate(x_new, use_fj)
        r_new = _norm_floats(F_new)
        stalled = False
        if opts.damped:
            r_old = res
            need = not (r_new <= (1.0 - 1e-4 * lam) * r_old)
            for _h in range(opts.max_halvings):
                if not need:
                    break
                lam *= 0.5
                xt = [a + lam * b for a, b in zip(xl, d)]
                Ft, _ = evaluate(xt, False)
                x_new, F_new, r_new, J_new = xt, Ft, _norm_floats(Ft), None
                need = not (r_new <= (1.0 - 1e-4 * lam) * r_old)
            if need:  # no decrease found: keep the old iterate and stop
                x_new, F_new, r_new, J_new, stalled = xl, F, r_old, None, True
        xl, F, res, J = x_new, F_new, r_new, J_new
        nonfinite = not math.isfinite(r_new) or not all(map(math.isfinite, x_new))
        conv = r_new < tol and not nonfinite
        if conv:
            status = _S_CONVERGED
        elif nonfinite:
            status = _S_DIVERGED
        elif singular:
            status = _S_SINGULAR
        done = conv or nonfinite or singular or stalled
    # the batch's test on floats (the same IEEE operations)
    inside = all(
        a >= b - 1e-12 * (1 + abs(b)) and a <= c + 1e-12 * (1 + abs(c))
        for a, b, c in zip(xl, opts.lo.tolist(), opts.hi.tolist())
    )
    if status == _S_CONVERGED and not inside:
        status = _S_OFF_FLANK
    return SolveResult(
        x=np.array([xl], dtype=float),
        residual=np.array([res]),
        iterations=np.array([iters]),
        status=np.array([int(status)]),
        condition=np.array([cond]),
    )


def _check_bounds(lower, upper, k):
    """(lo, hi) (k,) arrays of the bounds (+-inf where None); ValueError if lo > hi somewhere."""
    lo, hi = (
        np.full(k, sign * np.inf)
        if b is None
        else (
            b
            if type(b) is np.ndarray and b.shape == (k,) and b.dtype == float
            else np.broadcast_to(np.asarray(b, float), (k,))
        )
        for b, sign in ((lower, -1), (upper, 1))
    )
    lo_f, hi_f = lo.tolist(), hi.tolist()  # k is small: on floats
    if any(a != a for a in lo_f) or any(b != b for b in hi_f):
        raise ValueError(f"lower and upper must not be NaN (use -inf or inf for no bound), got {lower!r}, {upper!r}")
    if any(a > b for a, b in zip(lo_f, hi_f)):
        raise ValueError("lower bound exceeds upper bound")
    return lo, hi


def _bind_rows(fun, jac, fun_jac, n):
    """For ``rows=True``: the callables with the active row indices bound (read from the returned
    box's ``"i"``, which the solver sets before each call)."""
    box = {"i": np.arange(n)}
    _fun, _jac, _fj = fun, jac, fun_jac

    def fun(xx):
        return _fun(xx, box["i"])

    jac = None if _jac is None else (lambda xx: _jac(xx, box["i"]))
    if _fj is not None:

        def fun_jac(xx):
            return _fj(xx, box["i"])

    return fun, jac, fun_jac, box


def newton(
    fun: Callable,
    x0,
    jac: Callable | None = None,
    *,
    tol: float = 1e-12,
    maxiter: int = 50,
    damped: bool = True,
    max_halvings: int = 12,
    lower=None,
    upper=None,
    keep_inside: bool = False,
    rcond: float = 1e-13,
    rows: bool = False,
    fun_jac: Callable | None = None,
    inverse_square: bool = False,
    floats: Callable | None = None,
) -> SolveResult:
    """Solve ``fun(x) = 0`` for a batch of independent problems.

    Parameters
    ----------
    fun : callable
        (n, k) -> (n, m), m >= k; rows are independent problems (residuals in the unit of the
        equations, e.g. mm for the contact equations of TCA).
    x0 : (n, k) or (k,) array_like
        Starting points (in the unknowns' units: rad for angles, the design's length unit).
    jac : callable, optional
        (n, k) -> (n, m, k); central differences when omitted (it may return a lazy Jacobian as
        ``fun_jac`` may; it is formed for every row at once).
    tol : float, optional
        Convergence when the Euclidean residual norm is below ``tol`` (unit of the residual).
    maxiter : int, optional
        Iteration limit (an integer >= 1).
    damped : bool, optional
        Armijo backtracking on the residual norm (step halved up to ``max_halvings``
        times); with ``damped=False`` the full Newton step is always taken (plain Newton).
    max_halvings : int, optional
        Halvings of the step the line search tries (an integer >= 0).
    lower, upper : (k,) array_like, optional
        Bounds of the parameter domain (use +-inf for none). A converged root outside them gets
        status OFF_FLANK.
    keep_inside : bool, optional
        Project every iterate onto the bounds (the "domain-kept" variant).
    rcond : float, optional
        Relative singular-value threshold below which the Jacobian counts as singular, in [0, 1).
    rows : bool, optional
        If True, ``fun`` and ``jac`` are called as ``fun(x, idx)`` with ``idx`` the indices
        (into the batch, increasing) of the rows of ``x``: the solver passes only the active rows,
        so per-problem data (e.g. fixed parameters) can be looked up by ``idx``.
    fun_jac : callable, optional
        x -> (F, J), called like ``fun``: residual and Jacobian in one
        evaluation, used at the start and at every full Newton step instead of ``fun`` followed by
        ``jac`` at the next iteration (the work they share is done once; the Jacobian of a row
        whose step the line search shortened is computed afresh). F must equal ``fun(x)``. J may
        be lazy: a function ``J(rows=None)`` returning the Jacobians of the evaluated rows ``rows``
        (indices into them, increasing; None: all), which the solver calls at most once, at the
        next step, for the rows that step (a row's last evaluation, at its root, then costs no
        Jacobian).
    inverse_square : bool, optional
        Square systems larger than 2 x 2 take their step and inverse from Gauss-Jordan
        elimination over the batch (LAPACK's inverse above 6 x 6; :func:`step_square`: a
        Frobenius-norm bound clears most rows of singularity, the SVD
        examines the rest), several times cheaper than the SVD of every row; ``condition`` is then
        the Frobenius condition number (see :class:`SolveResult`). The TCA solves use it.
    floats : callable, optional
        (x, derivs) -> (F, J) or None, with ``fun_jac``: the same
        evaluation for ONE problem on Python floats (x a list of k floats; F a list of m floats,
        J a list of m rows of k floats with ``derivs``, or a function of no argument returning
        it when needed, else None), used when the batch has one
        row (a numpy call on one row costs more than its arithmetic). Its values must equal those
        of ``fun_jac``/``fun``; where it returns None these evaluate instead.

    Returns
    -------
    SolveResult
        Solution, residual, iterations, status and condition per row; ``status`` is CONVERGED only
        for a finite root with residual < tol that lies inside the bounds.

    Raises
    ------
    ValueError
        Before any iteration, if ``tol`` is not a finite number > 0, ``rcond`` is outside [0, 1),
        ``maxiter`` or ``max_halvings`` is not an integer in range, a bound is NaN or ``lower``
        exceeds ``upper``; and if ``fun`` returns fewer equations than unknowns.

    Examples
    --------
    Two circles cut by a line, solved from two starts at once; the second root lies outside the
    bounds, so its row is not called converged:

    >>> import numpy as np
    >>> from gearrep.solve import newton
    >>> def fun(x):
    ...     return np.stack([x[:, 0] ** 2 + x[:, 1] ** 2 - 1.0, x[:, 0] - x[:, 1]], -1)
    >>> r = newton(fun, [[0.5, 0.6], [-0.5, -0.6]], lower=[0.0, 0.0], upper=[1.0, 1.0])
    >>> np.round(r.x, 9).tolist(), r.status_name.tolist()
    ([[0.707106781, 0.707106781], [-0.707106781, -0.707106781]], ['converged', 'off_flank'])
    >>> bool(r.residual.max() < 1e-12), r.iterations.tolist()
    (True, [4, 4])
    """
    check_positive("tol", tol)
    if isinstance(rcond, bool) or not (0.0 <= real_or_nan(rcond) < 1.0):
        raise ValueError(f"rcond must be in [0, 1) (relative singular-value threshold), got {rcond!r}")
    maxiter = check_integer("maxiter", maxiter)
    max_halvings = check_integer("max_halvings", max_halvings, 0)
    x = np.atleast_2d(np.array(x0, dtype=float))
    n, k = x.shape
    lo, hi = _check_bounds(lower, upper, k)
    if keep_inside:
        x = np.clip(x, lo, hi)
    box = {"i": None}
    if rows:
        fun, jac, fun_jac, box = _bind_rows(fun, jac, fun_jac, n)
    opts = _BatchOptions(tol, maxiter, damped, max_halvings, lo, hi, rcond, inverse_square, keep_inside)
    if n == 1 and not keep_inside:  # one problem: the same steps on floats with scalar bookkeeping
        return _newton_one(fun, x, jac, fun_jac, floats if fun_jac is not None else None, opts)
    return _newton_batch(fun, jac, fun_jac, x, box, opts)


@dataclass(slots=True)  # not frozen: a frozen dataclass's __init__ costs about 1 us more per call
class _BatchOptions:
    tol: float
    maxiter: int
    damped: bool
    max_halvings: int
    lo: np.ndarray
    hi: np.ndarray
    rcond: float
    inverse_square: bool
    keep_inside: bool


class _BatchState:
    """Iterates, residuals and bookkeeping of a batch solve (:func:`_newton_batch`)."""

    def __init__(self, fun, fun_jac, x, opts: _BatchOptions):
        n, k = x.shape
        self.x, self.k = x, k
        self.Jc = self.fresh = self.pending = None
        if fun_jac is not None:
            F, Jc = fun_jac(x)
            # a copy: the store is written to, and F may be the caller's array (or a read-only one)
            self.F = np.array(F, dtype=float).reshape(n, -1)
            self.fresh = np.ones(n, dtype=bool)  # Jc (or the pending lazy one) holds the Jacobian at x
            self.own_jc = False  # Jc may be the caller's array: copied before a partial write
        else:
            self.F = np.array(fun(x), dtype=float).reshape(n, -1)
        self.m = self.F.shape[1]
        if self.m < k:
            raise ValueError(f"fun returns {self.m} equations for {k} unknowns; need m >= k")
        if fun_jac is not None:
            self.keep_jacobians(np.arange(n), Jc)
        self.res = _row_norms(self.F)
        self.iters = np.zeros(n, dtype=int)
        self.status = np.full(n, int(Status.NOT_CONVERGED), dtype=int)
        finite = np.isfinite(self.res)
        self.status[~finite] = int(Status.DIVERGED)
        self.status[self.res < opts.tol] = int(Status.CONVERGED)  # a start that already solves the system
        self.done = (self.res < opts.tol) | ~finite
        self.stalled = np.zeros(n, dtype=bool)
        self.cond = np.full(n, np.nan)

    def keep_jacobians(self, act, J):
        """Keep the Jacobians ``J`` of the rows ``act`` (fresh at the new iterates); all rows:
        ``J`` replaces the store without a copy. A lazy ``J`` (see :func:`newton`) is kept pending,
        formed by the next step for the rows it takes (:func:`_batch_step`)."""
        if callable(J):
            self.pending = (J, act)
            self.fresh[act] = True
            return
        self.pending = None
        J = np.asarray(J, dtype=float).reshape(act.size, self.m, self.k)
        n = len(self.fresh)
        if act.size == n:
            self.Jc, self.own_jc = J, False
        elif self.Jc is None:  # after lazy ones: a store of every row
            self.Jc, self.own_jc = np.full((n, self.m, self.k), np.nan), True
            self.Jc[act] = J
        else:
            if not self.own_jc:
                self.Jc, self.own_jc = self.Jc.copy(), True
            self.Jc[act] = J
        self.fresh[act] = True


def _batch_step(S: _BatchState, act, sel, jac, fun, box, opts: _BatchOptions):
    """Jacobian of the active rows (reusing the fresh ones of ``fun_jac``) and their Newton step;
    records the condition and counts the iteration. Returns (d, singular)."""
    xa, Fa = S.x[sel], S.F[sel]
    if S.pending is not None:  # a lazy Jacobian of the last evaluation: formed for these rows only
        lazy, evaluated = S.pending
        S.pending = None
        stale = np.flatnonzero(~S.fresh[sel])
        Ja = lazy(None if act.size == evaluated.size else np.searchsorted(evaluated, act))
        Ja = np.asarray(Ja, dtype=float).reshape(act.size, S.m, S.k)
        if stale.size:
            Ja = np.array(Ja)  # written to: the caller's array may be read-only
            box["i"] = act[stale]
            Ja[stale] = np.asarray(_dense(jac(xa[stale])), dtype=float).reshape(stale.size, S.m, S.k)
            box["i"] = act
    elif S.Jc is not None:
        stale = np.flatnonzero(~S.fresh[sel])
        Ja = S.Jc[act] if stale.size else S.Jc[sel]  # a view only where it is not written to
        if stale.size:
            box["i"] = act[stale]
            Ja[stale] = np.asarray(_dense(jac(xa[stale])), dtype=float).reshape(stale.size, S.m, S.k)
            box["i"] = act
    else:
        Ja = _dense(jac(xa)) if jac is not None else numeric_jacobian(fun, xa, Fa)
    Ja = np.asarray(Ja, dtype=float).reshape(act.size, S.m, S.k)
    good_j = finite_rows(Ja)
    bad_j = ~good_j
    if bad_j.any():
        Ja = np.where(bad_j[:, None, None], 0.0, Ja)
    if act.size == 1:  # the last active row: its step on floats, as a solve of one problem
        d1, sing1, cond = step_floats(Ja[0].tolist(), Fa[0].tolist(), opts.rcond, opts.inverse_square)
        d, singular = np.array([d1]), np.array([sing1])
    else:
        d, singular, sv = step_batch(Ja, Fa, opts.rcond, opts.inverse_square)
        with np.errstate(divide="ignore", invalid="ignore"):
            cond = sv[:, 0] / sv[:, -1]
    singular |= bad_j
    S.cond[sel] = np.where(bad_j, np.nan, cond)
    S.iters[sel] += 1
    return d, singular


def _line_search(S: _BatchState, act, sel, d, x_new, F_new, r_new, fun, box, opts: _BatchOptions):
    """Armijo backtracking of the active rows whose full step did not decrease the residual enough
    (step halved up to ``max_halvings`` times); rows without a decrease keep their old iterate and
    are marked stalled. Updates x_new, F_new, r_new in place."""
    xa, Fa = S.x[sel], S.F[sel]
    lam = np.ones(act.size)
    r_old = S.res[sel]
    need = ~(r_new <= (1.0 - 1e-4 * lam) * r_old)
    for _h in range(opts.max_halvings):
        if not need.any():
            break
        idx = need.nonzero()[0]
        lam[idx] *= 0.5
        xt = xa[idx] + lam[idx, None] * d[idx]
        if opts.keep_inside:
            xt = np.clip(xt, opts.lo, opts.hi)
        box["i"] = act[idx]
        Ft = np.asarray(fun(xt), dtype=float).reshape(idx.size, -1)
        box["i"] = act
        rt = _row_norms(Ft)
        x_new[idx], F_new[idx], r_new[idx] = xt, Ft, rt
        if S.fresh is not None:
            S.fresh[act[idx]] = False
        need[idx] = ~(rt <= (1.0 - 1e-4 * lam[idx]) * r_old[idx])
    # no decrease found: keep the old iterate and stop this point
    stall = need
    if stall.any():
        x_new[stall], F_new[stall], r_new[stall] = xa[stall], Fa[stall], r_old[stall]
        S.stalled[act[stall]] = True


def _newton_batch(fun, jac, fun_jac, x, box, opts: _BatchOptions) -> SolveResult:
    """:func:`newton` for a batch (rows bound by :func:`_bind_rows` read ``box["i"]``). Where every
    row is still active the rows are addressed by a slice (views, no gathers)."""
    S = _BatchState(fun, fun_jac, x, opts)
    n = len(x)
    if fun_jac is not None and jac is None:
        jac = lambda xx: fun_jac(xx)[1]  # noqa: E731
    for _ in range(opts.maxiter):
        act = (~S.done).nonzero()[0]
        if act.size == 0:
            break
        sel = slice(None) if act.size == n else act
        box["i"] = act
        d, singular = _batch_step(S, act, sel, jac, fun, box, opts)
        x_new = S.x[sel] + d
        if opts.keep_inside:
            x_new = np.clip(x_new, opts.lo, opts.hi)
        if fun_jac is not None:
            F_new, J_new = fun_jac(x_new)
            F_new = np.asarray(F_new, dtype=float).reshape(act.size, -1)
            S.keep_jacobians(act, J_new)
        else:
            F_new = np.asarray(fun(x_new), dtype=float).reshape(act.size, -1)
        if opts.damped and not F_new.flags.writeable:
            F_new = F_new.copy()  # the line search writes to it (it may be a read-only array of the caller's)
        r_new = _row_norms(F_new)
        if opts.damped:
            _line_search(S, act, sel, d, x_new, F_new, r_new, fun, box, opts)
        if act.size == n:  # every row: the new arrays replace the old (no copy)
            S.x, S.res = x_new, r_new
            S.F[sel] = F_new
        else:
            S.x[sel], S.F[sel], S.res[sel] = x_new, F_new, r_new
        nonfinite = ~(np.isfinite(r_new) & finite_rows(x_new))
        conv = (r_new < opts.tol) & ~nonfinite
        sing_stop = singular & ~conv
        S.status[act[conv]] = int(Status.CONVERGED)
        S.status[act[nonfinite]] = int(Status.DIVERGED)
        S.status[act[sing_stop & ~nonfinite]] = int(Status.SINGULAR)
        S.done[act[conv | nonfinite | sing_stop]] = True
        S.done[S.stalled] = True
    lo, hi = opts.lo, opts.hi
    inside = np.all((S.x >= lo - 1e-12 * (1 + np.abs(lo))) & (S.x <= hi + 1e-12 * (1 + np.abs(hi))), axis=1)
    S.status[(S.status == Status.CONVERGED) & ~inside] = int(Status.OFF_FLANK)
    return SolveResult(x=S.x, residual=S.res, iterations=S.iters, status=S.status, condition=S.cond)
