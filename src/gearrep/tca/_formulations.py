"""The two TCA formulations (conventional eq 26-32, reduced eq 33-44) with analytic Jacobians,
Newton with per-row data, and the public solves (see :mod:`gearrep.tca`)."""

from __future__ import annotations

import numpy as np

from ..solve import SolveResult, Status, newton
from ..surface import cross
from ._pair import ContactPoints, GearPair, _mv, _wrap, transmission_error

__all__ = [
    "normal_derivatives",
    "conventional_system",
    "newton_rows",
    "default_start",
    "solve_contact",
    "reduced_unknowns",
    "trace_path",
]


def normal_derivatives(P, sign):
    """Unit normal sign * (r_u x r_v)/|.| of a :class:`~gearrep.surface.SurfacePoint` and its u- and
    v-derivatives (n_u = (N_u - n (n . N_u))/|N|, likewise n_v)."""
    N = cross(P.r_u, P.r_v)
    L = np.linalg.norm(N, axis=-1, keepdims=True)
    n = N / L
    dNu = cross(P.r_uu, P.r_v) + cross(P.r_u, P.r_uv)
    dNv = cross(P.r_uv, P.r_v) + cross(P.r_u, P.r_vv)
    dnu = (dNu - n * np.sum(n * dNu, axis=-1, keepdims=True)) / L
    dnv = (dNv - n * np.sum(n * dNv, axis=-1, keepdims=True)) / L
    return sign * n, sign * dnu, sign * dnv


def _reduced_kernel(pair: GearPair, u1, v1, phi1, *, derivs=True):
    """Explicit back-substitution of the reduced formulation (eq 37-44) and derivatives w.r.t. (u1, v1).

    Returns a dict with u2, v2, phi2, r (contact point), n1, n2 (outward normals in S_f) and, with
    ``derivs``, their derivatives d_* of shape (n, 2[, 3]) w.r.t. (u1, v1). A spherical member 2
    (bevel pairs, ``flank2.spherical``) goes through :func:`gearrep.tca._bevel.spherical_kernel`.
    """
    if getattr(pair.flank2, "spherical", False):
        from ._bevel import spherical_kernel

        return spherical_kernel(pair, u1, v1, phi1, derivs=derivs)
    P1 = pair.flank1.evaluate(u1, v1)
    R1 = pair.R1(phi1)
    r = _mv(R1, P1.r)
    n1l, dn1u, dn1v = normal_derivatives(P1, pair.sign1)
    n1 = _mv(R1, n1l)
    s = _mv(pair._Q, r - pair.O2)  # member-2 axis frame, before Rz(-phi2)
    v2 = s[..., 2]
    rho2 = s[..., 0] ** 2 + s[..., 1] ** 2
    u2 = np.sqrt(rho2)
    th = np.arctan2(s[..., 1], s[..., 0])
    with np.errstate(invalid="ignore", divide="ignore"):
        P2 = pair.flank2.evaluate(u2, v2)
    ang2 = np.arctan2(P2.r[..., 1], P2.r[..., 0])
    ref = pair.ratio * np.asarray(phi1, float)
    phi2 = ref + _wrap(ang2 - th - ref)
    R2 = pair.R2(phi2)
    with np.errstate(invalid="ignore", divide="ignore"):
        n2l, dn2u, dn2v = normal_derivatives(P2, pair.sign2)
    n2 = _mv(R2, n2l)
    out = dict(u2=u2, v2=v2, phi2=phi2, r=r, n1=n1, n2=n2, P1=P1, P2=P2)
    if not derivs:
        return out
    # derivatives with respect to (u1, v1): stack directions on axis -2
    dr = _mv(R1[..., None, :, :], np.stack([P1.r_u, P1.r_v], axis=-2))  # (n,2,3)
    dn1 = _mv(R1[..., None, :, :], np.stack([dn1u, dn1v], axis=-2))
    ds = _mv(pair._Q, dr)
    sx, sy = s[..., 0, None], s[..., 1, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        du2 = (sx * ds[..., 0] + sy * ds[..., 1]) / u2[..., None]
        dth = (sx * ds[..., 1] - sy * ds[..., 0]) / rho2[..., None]
        dv2 = ds[..., 2]
        r2 = P2.r
        q2 = r2[..., 0] ** 2 + r2[..., 1] ** 2
        ang_u = (r2[..., 0] * P2.r_u[..., 1] - r2[..., 1] * P2.r_u[..., 0]) / q2
        ang_v = (r2[..., 0] * P2.r_v[..., 1] - r2[..., 1] * P2.r_v[..., 0]) / q2
        dphi2 = ang_u[..., None] * du2 + ang_v[..., None] * dv2 - dth
        dn2l = dn2u[..., None, :] * du2[..., None] + dn2v[..., None, :] * dv2[..., None]
        dn2 = _mv(R2[..., None, :, :], dn2l) + cross(pair.w2, n2)[..., None, :] * dphi2[..., None]
    out.update(dr=dr, dn1=dn1, du2=du2, dv2=dv2, dphi2=dphi2, dn2=dn2)
    return out


def _keep(vec, drop):
    """Two components of (..., 3) ``vec`` (or (..., k, 3)) other than ``drop`` (per row)."""
    drop = np.asarray(drop).astype(int)
    idx = np.array([[1, 2], [0, 2], [0, 1]])[drop]  # (n, 2)
    if vec.ndim == 2:
        return np.take_along_axis(vec, idx, axis=-1)
    return np.take_along_axis(vec, idx[:, None, :], axis=-1)


def _reduced_FJ(pair, u1, v1, phi1, drop, derivs=True):
    K = _reduced_kernel(pair, u1, v1, phi1, derivs=derivs)
    c = cross(K["n1"], K["n2"])
    F = _keep(c, drop)
    if not derivs:
        return F, None, K
    dc = cross(K["dn1"], K["n2"][..., None, :]) + cross(K["n1"][..., None, :], K["dn2"])  # (n,2,3)
    J = np.swapaxes(_keep(dc, drop), -1, -2)  # (n, 2 eq, 2 unknowns)
    return F, J, K


def _conventional_FJ(pair, x, phi1, drop, derivs=True):
    u1, v1, u2, v2, phi2 = (x[:, i] for i in range(5))
    P1 = pair.flank1.evaluate(u1, v1)
    R1 = pair.R1(phi1)
    with np.errstate(invalid="ignore", divide="ignore"):
        P2 = pair.flank2.evaluate(u2, v2)
        n2l, dn2u, dn2v = normal_derivatives(P2, pair.sign2)
    n1l, dn1u, dn1v = normal_derivatives(P1, pair.sign1)
    R2 = pair.R2(phi2)
    r1 = _mv(R1, P1.r)
    rel2 = _mv(R2, P2.r)
    n1 = _mv(R1, n1l)
    n2 = _mv(R2, n2l)
    F = np.concatenate([r1 - (pair.O2 + rel2), n1 + n2 if drop is None else _keep(n1 + n2, drop)], axis=-1)
    if not derivs:
        return F, None
    cols_r = [_mv(R1, P1.r_u), _mv(R1, P1.r_v), -_mv(R2, P2.r_u), -_mv(R2, P2.r_v), -cross(pair.w2, rel2)]
    cols_n = [_mv(R1, dn1u), _mv(R1, dn1v), _mv(R2, dn2u), _mv(R2, dn2v), cross(pair.w2, n2)]
    Jr = np.stack(cols_r, axis=-1)  # (n,3,5)
    Jn = np.stack(cols_n, axis=-2)  # (n,5,3)
    J = np.concatenate([Jr, np.swapaxes(Jn if drop is None else _keep(Jn, drop), -1, -2)], axis=-2)
    return F, J


def conventional_system(pair: GearPair, phi1: float, drop: int | None):
    """(F, J) callables of the conventional TCA (eq 26-32, eq 27 corrected to n_f1 + n_f2 = 0) at a
    fixed ``phi1`` for x = (u1, v1, u2, v2, phi2) (n, 5), as :func:`gearrep.solve.newton` takes them.

    F = [r_f1 - r_f2, components of n_f1 + n_f2] with outward unit normals; ``drop`` = 0, 1 or 2
    leaves that normal component out (five equations), None keeps all three (six equations, least
    squares). The one implementation behind :func:`solve_contact` (``formulation="conventional"``).
    """
    if drop is not None and drop not in (0, 1, 2):
        raise ValueError(f"drop must be None or one of 0, 1, 2, got {drop!r}")

    def rows(x):
        x = np.atleast_2d(x)
        return x, None if drop is None else np.full(len(x), drop)

    def F(x):
        x, d = rows(x)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return _conventional_FJ(pair, x, phi1, d, derivs=False)[0]

    def J(x):
        x, d = rows(x)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return _conventional_FJ(pair, x, phi1, d)[1]

    return F, J


# ----------------------------------------------------------------------------------------------
# newton with frozen per-row parameters
# ----------------------------------------------------------------------------------------------
def newton_rows(
    F, FJ, x0, params, *, lower=None, upper=None, jacobian="analytic", tol=1e-12, maxiter=50, damped=True
) -> SolveResult:
    """:func:`gearrep.solve.newton` for problems with per-row data ``params`` (n, q).

    ``F(x, p) -> (n, m)``; ``FJ(x, p) -> (F, J)`` with J (n, m, k) (analytic; ignored when
    ``jacobian="numeric"``, which differentiates F by central differences). Each row's
    parameters follow it through the solve (``newton(..., rows=True)``).
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

    return newton(
        fun,
        x0,
        jac if jacobian == "analytic" else None,
        tol=tol,
        maxiter=maxiter,
        damped=damped,
        lower=lower,
        upper=upper,
        rows=True,
    )


# ----------------------------------------------------------------------------------------------
# public solves
# ----------------------------------------------------------------------------------------------
def _angles(phi1, name: str = "phi1") -> np.ndarray:
    """``phi1`` as a non-empty 1-D float array [rad]; a scalar becomes length 1."""
    a = np.asarray(phi1, dtype=float)
    if a.ndim > 1 or a.size == 0:
        raise ValueError(f"{name} must be a scalar or a non-empty 1-D array of angles [rad], got shape {a.shape}")
    return np.atleast_1d(a)


def _face_coordinates(v1, n: int) -> np.ndarray:
    """Fixed face-width coordinates ``v1`` (scalar, length 1 or length ``n``) as an (n,) array."""
    a = np.asarray(v1, dtype=float)
    if a.ndim > 1 or (a.ndim == 1 and len(a) not in (1, n)):
        raise ValueError(f"v1 must be a scalar or a 1-D array of length 1 or {n} (one per phi1), got shape {a.shape}")
    return np.broadcast_to(a, (n,)).copy()


def _prep(phi1, start, width):
    start = np.atleast_2d(np.asarray(start, dtype=float))
    phi1 = _angles(phi1)
    if start.shape[-1] != width:
        raise ValueError(f"start must have {width} columns, got shape {start.shape}")
    n = max(len(phi1), len(start))
    if len(phi1) not in (1, n) or len(start) not in (1, n):
        raise ValueError(f"phi1 ({len(phi1)}) and start ({len(start)}) must have equal length or length 1")
    if not np.all(np.isfinite(phi1)):
        raise ValueError("phi1 must be finite")
    return np.broadcast_to(phi1, (n,)).copy(), np.broadcast_to(start, (n, width)).copy()


def default_start(pair: GearPair, phi1, formulation: str = "reduced") -> np.ndarray:
    """Starting point at the middle of the flanks, phi2 = (N1/N2) phi1 (the thesis's choice of u2, v2)."""
    phi1 = _angles(phi1)
    mid1 = np.where(np.isfinite(pair.lower1 + pair.upper1), 0.5 * (pair.lower1 + pair.upper1), 0.0)
    if formulation == "reduced":
        return np.tile(mid1, (len(phi1), 1))
    mid2 = np.where(np.isfinite(pair.lower2 + pair.upper2), 0.5 * (pair.lower2 + pair.upper2), 0.0)
    return np.column_stack([np.tile(mid1, (len(phi1), 1)), np.tile(mid2, (len(phi1), 1)), pair.ratio * phi1])


def solve_contact(
    pair: GearPair,
    phi1,
    start=None,
    *,
    formulation: str = "reduced",
    v1=None,
    jacobian: str = "analytic",
    tol: float = 1e-12,
    maxiter: int = 50,
    damped: bool = True,
    phi10: float = 0.0,
    phi20: float = 0.0,
    drop=None,
) -> ContactPoints:
    """Contact points of ``pair`` at member-1 angles ``phi1`` (vectorised over starts and angles).

    Parameters
    ----------
    phi1 : (n,) or scalar, rad
    start : (n, 2) (u1, v1) for ``formulation="reduced"`` (eq 33-44) or (n, 5) (u1, v1, u2, v2, phi2)
        for ``"conventional"`` (eq 26-32); default :func:`default_start`
    v1 : None (point contact: v1 unknown) or scalar/(n,) fixed face-width coordinate of member 1
        (line contact; the v1 column of ``start`` is then ignored)
    jacobian : "analytic" or "numeric" (central differences)
    tol, maxiter, damped : passed to :func:`gearrep.solve.newton`
    phi10, phi20 : TE reference (eq 14)
    drop : None (default: the component j = argmax |n_f1,j| at the start, per row) or 0, 1, 2 - the
        component of n_f1 + n_f2 (conventional) or n_f1 x n_f2 (reduced) left out of the system.
        Other choices than the default can make the Jacobian singular (see module docstring).

    Returns
    -------
    ContactPoints; status CONVERGED only for a verified root inside both flanks.
    """
    if formulation not in ("reduced", "conventional"):
        raise ValueError(f"formulation must be 'reduced' or 'conventional', got {formulation!r}")
    width = 2 if formulation == "reduced" else 5
    phi1 = _angles(phi1)
    if start is None:
        start = default_start(pair, phi1, formulation)
    phi1, start = _prep(phi1, start, width)
    n = len(phi1)
    fixed = v1 is not None
    if fixed:
        v1a = _face_coordinates(v1, n)
        if not np.all(np.isfinite(v1a)):
            raise ValueError("v1 must be finite")
        start[:, 1] = v1a
    if formulation == "reduced" and not (
        getattr(pair.flank2, "cylindrical", False) or getattr(pair.flank2, "spherical", False)
    ):
        raise ValueError(
            "the reduced formulation needs flank2 in cylindrical or spherical form "
            "(flank2.cylindrical = True or flank2.spherical = True)"
        )

    # dropped normal component: the largest of member 1's normal at the start
    if drop is None:
        with np.errstate(invalid="ignore", over="ignore"):  # a non-finite start ends as status DIVERGED
            _, n1s = pair.member1(start[:, 0], start[:, 1], phi1)
            drop = np.argmax(np.nan_to_num(np.abs(n1s), nan=0.0), axis=-1).astype(float)
    else:
        if drop not in (0, 1, 2):
            raise ValueError(f"drop must be None or one of 0, 1, 2, got {drop!r}")
        drop = np.full(n, float(drop))

    free = (
        [0]
        if (fixed and formulation == "reduced")
        else ([0, 1] if formulation == "reduced" else ([0, 2, 3, 4] if fixed else [0, 1, 2, 3, 4]))
    )
    lo_all = np.concatenate([pair.lower1, pair.lower2, [-np.inf]])
    hi_all = np.concatenate([pair.upper1, pair.upper2, [np.inf]])

    def expand(x, p):
        full = np.empty((x.shape[0], width))
        full[:, free] = x
        if fixed:
            full[:, 1] = p[:, 2]
        return full

    if formulation == "reduced":

        def FJ(x, p):
            full = expand(x, p)
            Fv, J, _ = _reduced_FJ(pair, full[:, 0], full[:, 1], p[:, 0], p[:, 1])
            return Fv, J[:, :, free]

        def Fonly(x, p):
            full = expand(x, p)
            return _reduced_FJ(pair, full[:, 0], full[:, 1], p[:, 0], p[:, 1], derivs=False)[0]
    else:

        def FJ(x, p):
            Fv, J = _conventional_FJ(pair, expand(x, p), p[:, 0], p[:, 1])
            return Fv, J[:, :, free]

        def Fonly(x, p):
            return _conventional_FJ(pair, expand(x, p), p[:, 0], p[:, 1], derivs=False)[0]

    params = np.column_stack([phi1, drop] + ([start[:, 1]] if fixed else []))
    with np.errstate(invalid="ignore", over="ignore"):  # non-finite iterates end as status DIVERGED
        res = newton_rows(
            Fonly,
            FJ,
            start[:, free],
            params,
            lower=lo_all[free],
            upper=hi_all[free],
            jacobian=jacobian,
            tol=tol,
            maxiter=maxiter,
            damped=damped,
        )
    sol = expand(res.x, params)
    return _finish(pair, formulation, sol, phi1, res, phi10, phi20)


def _finish(pair, formulation, sol, phi1, res, phi10, phi20) -> ContactPoints:
    status = res.status.copy()
    u1, v1 = sol[:, 0], sol[:, 1]
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        if formulation == "reduced":
            K = _reduced_kernel(pair, u1, v1, phi1, derivs=False)
            u2, v2, phi2, r, n1, n2 = K["u2"], K["v2"], K["phi2"], K["r"], K["n1"], K["n2"]
        else:
            u2, v2, phi2 = sol[:, 2], sol[:, 3], sol[:, 4]
            ref = pair.ratio * phi1
            phi2 = ref + _wrap(phi2 - ref)
            r, n1 = pair.member1(u1, v1, phi1)
            r2, n2 = pair.member2(u2, v2, phi2)
        opposite = np.sum(n1 * n2, axis=-1) < 0
        if formulation == "conventional":
            opposite &= np.linalg.norm(n1 + n2, axis=-1) < 1e-6
    solved = (status == Status.CONVERGED) | (status == Status.OFF_FLANK)
    status[solved & ~opposite] = int(Status.WRONG_ROOT)
    tol2 = 1e-12 * (1 + np.abs(np.concatenate([pair.lower2, pair.upper2])))
    inside2 = (
        (u2 >= pair.lower2[0] - tol2[0])
        & (u2 <= pair.upper2[0] + tol2[2])
        & (v2 >= pair.lower2[1] - tol2[1])
        & (v2 <= pair.upper2[1] + tol2[3])
    )
    status[(status == Status.CONVERGED) & ~inside2] = int(Status.OFF_FLANK)
    te = transmission_error(phi1, phi2, pair.n1, pair.n2, phi10, phi20)
    return ContactPoints(
        u1=u1,
        v1=v1,
        u2=u2,
        v2=v2,
        phi1=phi1,
        phi2=phi2,
        position=r,
        normal=n1,
        te=te,
        residual=res.residual,
        iterations=res.iterations,
        status=status,
        formulation=formulation,
        condition=res.condition,
    )


def reduced_unknowns(pair: GearPair, u1, v1, phi1):
    """(u2, v2, phi2) from (u1, v1, phi1) by the explicit relations of the reduced formulation (eq 39-44)."""
    u1, v1, phi1 = np.broadcast_arrays(*(np.asarray(a, float) for a in (u1, v1, phi1)))
    shape = u1.shape
    K = _reduced_kernel(pair, u1.ravel(), v1.ravel(), phi1.ravel(), derivs=False)
    return K["u2"].reshape(shape), K["v2"].reshape(shape), K["phi2"].reshape(shape)


def trace_path(
    pair: GearPair,
    phi1,
    start=None,
    *,
    formulation: str = "reduced",
    v1=None,
    jacobian: str = "analytic",
    tol: float = 1e-12,
    maxiter: int = 50,
    phi10: float = 0.0,
    phi20: float = 0.0,
    predictor: bool = True,
) -> ContactPoints:
    """Path of contact over the angles ``phi1`` (in order) by continuation (Litvin & Fuentes ch. 9).

    Each position starts from the previous converged solution (linearly extrapolated from the last
    two when ``predictor``); ``start`` (one row, as for :func:`solve_contact`) is used for the first
    position. A failed position does not seed the next one. Returns ContactPoints in the order
    of ``phi1``.
    """
    phi1 = _angles(phi1)
    width = 2 if formulation == "reduced" else 5
    x = default_start(pair, phi1[:1], formulation)[0] if start is None else np.asarray(start, float).reshape(-1)
    if x.shape != (width,):
        raise ValueError(f"start must have {width} entries, got shape {x.shape}")
    v1a = None if v1 is None else _face_coordinates(v1, len(phi1))
    out, hist = [], []  # hist: (phi1, solution) of converged points
    for i, p in enumerate(phi1):
        guess = x
        if predictor and len(hist) >= 2 and hist[-1][0] != hist[-2][0]:
            (pa, xa), (pb, xb) = hist[-2], hist[-1]
            guess = xb + (xb - xa) * (p - pb) / (pb - pa)
        elif hist:
            guess = hist[-1][1]
        c = solve_contact(
            pair,
            p,
            guess[None, :],
            formulation=formulation,
            v1=None if v1a is None else v1a[i],
            jacobian=jacobian,
            tol=tol,
            maxiter=maxiter,
            phi10=phi10,
            phi20=phi20,
        )
        if c.status[0] != Status.CONVERGED and len(hist) >= 1 and predictor:
            c2 = solve_contact(
                pair,
                p,
                hist[-1][1][None, :],
                formulation=formulation,
                v1=None if v1a is None else v1a[i],
                jacobian=jacobian,
                tol=tol,
                maxiter=maxiter,
                phi10=phi10,
                phi20=phi20,
            )
            if c2.status[0] == Status.CONVERGED:
                c = c2
        out.append(c)
        if c.status[0] == Status.CONVERGED:
            hist.append((p, c.unknowns(formulation)[0]))
    return ContactPoints.concatenate(out)
