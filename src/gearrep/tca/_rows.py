"""Newton solves of independent problems that each carry their own fixed data (the rows of a
batch of contact solves: phi1, a fixed v1, the dropped component)."""

from __future__ import annotations

import numpy as np

from ..solve import SolveResult, newton

__all__ = ["newton_rows"]


def newton_rows(
    F,
    FJ,
    x0,
    params,
    *,
    lower=None,
    upper=None,
    jacobian="analytic",
    tol=1e-12,
    maxiter=50,
    damped=True,
    inverse_square=False,
) -> SolveResult:
    """:func:`gearrep.solve.newton` for problems with per-row data ``params`` (n, q).

    ``F(x, p) -> (n, m)``; ``FJ(x, p) -> (F, J)`` with J (n, m, k) (analytic; ignored when
    ``jacobian="numeric"``, which differentiates F by central differences; its F must equal
    ``F(x, p)``: the solver takes the residual at each full step from it, ``fun_jac`` of
    :func:`gearrep.solve.newton`). Each row's parameters follow it through the solve
    (``newton(..., rows=True)``). ``inverse_square``: as :func:`gearrep.solve.newton` (the
    contact solves of :func:`solve_contact` use it).

    Parameters
    ----------
    F, FJ : callable
        Residual, and residual with Jacobian, of ``(x, p)``.
    x0 : (n, k) array_like
        Starts.
    params : (n, q) array_like
        Per-row data.
    lower, upper : (k,) array_like, optional
        Bounds, as :func:`gearrep.solve.newton`.
    jacobian : {"analytic", "numeric"}, optional
        Use ``FJ``, or central differences of ``F``.
    tol, maxiter, damped, inverse_square : optional
        As :func:`gearrep.solve.newton`.

    Returns
    -------
    gearrep.solve.SolveResult
        One record per row.

    Raises
    ------
    ValueError
        If ``params`` has not one row per start, or ``jacobian`` is unknown.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.tca import newton_rows
    >>> F = lambda x, p: x * x - p  # x^2 = p, one p per row
    >>> FJ = lambda x, p: (x * x - p, 2.0 * x[:, :, None])
    >>> r = newton_rows(F, FJ, [[1.0], [1.0]], [[4.0], [9.0]])
    >>> np.round(r.x[:, 0], 12).tolist()
    [2.0, 3.0]
    """
    x0 = np.atleast_2d(np.asarray(x0, float))
    params = np.atleast_2d(np.asarray(params, float))
    n = x0.shape[0]
    if params.shape[0] != n:
        raise ValueError(f"params has {params.shape[0]} rows for {n} starts")
    if jacobian not in ("analytic", "numeric"):
        raise ValueError(f"jacobian must be 'analytic' or 'numeric', got {jacobian!r}")

    def fun(x, idx):
        return F(x, params[idx])

    def jac(x, idx):
        return FJ(x, params[idx])[1]

    def fun_jac(x, idx):
        return FJ(x, params[idx])

    analytic = jacobian == "analytic"
    return newton(
        fun,
        x0,
        jac if analytic else None,
        tol=tol,
        maxiter=maxiter,
        damped=damped,
        lower=lower,
        upper=upper,
        rows=True,
        fun_jac=fun_jac if analytic else None,
        inverse_square=inverse_square,
    )
