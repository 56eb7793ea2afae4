"""The two TCA formulations (conventional eq 26-32, reduced eq 33-44) with analytic Jacobians,
Newton with per-row data, and the public solves (see :mod:`gearrep.tca`)."""

from __future__ import annotations

import math

import numpy as np

from ..frames import rotate_z
from ..solve import SolveResult, Status, _rows_all_finite, newton
from ..surface import add3, cross, cross3, cross3_sparse, dot3
from ._pair import ContactPoints, GearPair, _wrap, transmission_error

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


# one-point solves run the same kernels on Python floats (a numpy call on a 1-element array costs
# as much as on thousands of elements); these pick the math or the numpy function by the argument
def _sqrt(x):
    return math.sqrt(x) if type(x) is float else np.sqrt(x)


def _atan2(y, x):
    return math.atan2(y, x) if type(x) is float and type(y) is float else np.arctan2(y, x)


def _cos_sin(x):
    return (math.cos(x), math.sin(x)) if type(x) is float else (np.cos(x), np.sin(x))


def _wrap_any(x):
    """:func:`_wrap` for arrays or floats (round half to even in both)."""
    return x - 2.0 * math.pi * round(x / (2.0 * math.pi)) if type(x) is float else _wrap(x)


#: a one-point kernel on floats raises these where the array kernel gives inf/NaN; the caller then
#: repeats it on arrays, so that both give the same statuses
_SCALAR_ERRORS = (ArithmeticError, ValueError)


def _normal_derivatives3(P, sign):
    """:func:`normal_derivatives` in structure-of-arrays form: ``P`` = the six vectors of
    :meth:`~gearrep.surface.Surface.evaluate_components`; returns (n, n_u, n_v), each a 3-tuple.
    ``sign`` -1 swaps the operands of every cross product (which negates N and its derivatives
    exactly), so the signed normal and its derivatives come without a negation pass. On arrays
    the cross products skip the float components 0.0 and 1.0 (:func:`~gearrep.surface.cross3_sparse`)."""
    _, ru, rv, ruu, ruv, rvv = P
    if type(ru[0]) is float:  # one point on floats: every component is a float
        cr, add = cross3, _add3_plain
    else:
        cr, add = cross3_sparse, add3
    if sign == 1:
        N, dNu, dNv = cr(ru, rv), add(cr(ruu, rv), cr(ru, ruv)), add(cr(ruv, rv), cr(ru, rvv))
    else:
        N, dNu, dNv = cr(rv, ru), add(cr(rv, ruu), cr(ruv, ru)), add(cr(rv, ruv), cr(rvv, ru))
    N0, N1, N2 = N
    L = _sqrt(N0 * N0 + N1 * N1 + N2 * N2)
    n = (N0 / L, N1 / L, N2 / L)
    pu, pv = dot3(n, dNu), dot3(n, dNv)
    dnu = ((dNu[0] - n[0] * pu) / L, (dNu[1] - n[1] * pu) / L, (dNu[2] - n[2] * pu) / L)
    dnv = ((dNv[0] - n[0] * pv) / L, (dNv[1] - n[1] * pv) / L, (dNv[2] - n[2] * pv) / L)
    return n, dnu, dnv


def _add3_plain(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _stack3(v, n):
    """(n, 3) array of a vector given by components (floats broadcast)."""
    if type(v[0]) is float and type(v[1]) is float and type(v[2]) is float and n == 1:
        return np.array([v])
    out = np.empty((n, 3))
    out[:, 0], out[:, 1], out[:, 2] = v
    return out


def _reduced3(pair: GearPair, u1, v1, phi1, c1, s1, derivs=True, v_column=True):
    """The reduced formulation's explicit back-substitution (eq 37-44) in structure-of-arrays form.

    ``c1``, ``s1`` = cos, sin of ``phi1`` (computed once per solve by the caller). Returns a dict
    of components: u2, v2, phi2 (arrays), r, n1, n2 (3-tuples) and, with ``derivs``, the
    derivatives with respect to u1 (suffix _u) and, with ``v_column``, v1 (suffix _v):
    du2, dv2, dphi2 (arrays), dr, dn1, dn2 (3-tuples). Callers set ``np.errstate`` (off the flanks
    the arrays hold NaN/inf). A spherical member 2 (bevel pairs, ``flank2.spherical``): the
    cylindrical back-substitution on the pair's axial view, then (rho2, z2) -> (u2, v2) by
    :func:`gearrep.tca._bevel.spherical_unknowns`."""
    if getattr(pair.flank2, "spherical", False):
        from ._bevel import spherical_unknowns

        K = _reduced3(pair.axial_view, u1, v1, phi1, c1, s1, derivs=derivs, v_column=v_column)
        return spherical_unknowns(K, derivs, v_column)
    g = pair._soa
    P1 = pair.flank1.evaluate_components(u1, v1)
    n1l, dn1u, dn1v = _normal_derivatives3(P1, pair.sign1)
    r = rotate_z(c1, s1, P1[0])
    n1 = rotate_z(c1, s1, n1l)
    s = g["Q"](g["minus_O2"](r))  # member-2 axis frame, before Rz(-phi2)
    sx, sy, v2 = s
    rho2 = sx * sx + sy * sy
    u2 = _sqrt(rho2)
    th = _atan2(sy, sx)
    P2 = pair.flank2.evaluate_components(u2, v2)
    r2 = P2[0]
    ang2 = _atan2(r2[1], r2[0])
    ref = pair.ratio * phi1
    phi2 = ref + _wrap_any(ang2 - th - ref)
    c2, s2 = _cos_sin(pair.phase2 - phi2)
    n2l, dn2u, dn2v = _normal_derivatives3(P2, pair.sign2)
    n2 = g["A2"](rotate_z(c2, s2, n2l))
    out = dict(u2=u2, v2=v2, phi2=phi2, r=r, n1=n1, n2=n2)
    if not derivs:
        return out
    q2 = r2[0] * r2[0] + r2[1] * r2[1]
    ang_u = (r2[0] * P2[1][1] - r2[1] * P2[1][0]) / q2
    ang_v = (r2[0] * P2[2][1] - r2[1] * P2[2][0]) / q2
    w2xn2 = cross3(g["w2"], n2)
    for j, rj, dnj in (("_u", P1[1], dn1u), ("_v", P1[2], dn1v)):
        if j == "_v" and not v_column:
            break
        dr = rotate_z(c1, s1, rj)
        ds = g["Q"](dr)
        du2 = (sx * ds[0] + sy * ds[1]) / u2
        dth = (sx * ds[1] - sy * ds[0]) / rho2
        dv2 = ds[2]
        dphi2 = ang_u * du2 + ang_v * dv2 - dth
        dn2l = tuple(a * du2 + b * dv2 for a, b in zip(dn2u, dn2v))
        dn2 = g["A2"](rotate_z(c2, s2, dn2l))
        out["dr" + j] = dr
        out["dn1" + j] = rotate_z(c1, s1, dnj)
        out["du2" + j], out["dv2" + j], out["dphi2" + j] = du2, dv2, dphi2
        out["dn2" + j] = tuple(a + b * dphi2 for a, b in zip(dn2, w2xn2))
    return out


def _reduced_kernel(pair: GearPair, u1, v1, phi1, *, derivs=True):
    """Explicit back-substitution of the reduced formulation (eq 37-44) and derivatives w.r.t. (u1, v1).

    Returns a dict with u2, v2, phi2, r (contact point), n1, n2 (outward normals in S_f, (n, 3))
    and, with ``derivs``, their derivatives d_* of shape (n, 2[, 3]) w.r.t. (u1, v1) (a spherical
    member 2 as in :func:`_reduced3`).
    """
    u1, v1, phi1 = (np.asarray(a, float) for a in (u1, v1, phi1))
    n = np.broadcast_shapes(u1.shape, v1.shape, phi1.shape)[0]
    K = None
    if n == 1 and not derivs:  # one point: on floats (see _SCALAR_ERRORS)
        f = tuple(float(a.reshape(-1)[0]) for a in (u1, v1, phi1))
        try:
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                K1 = _reduced3(pair, f[0], f[1], f[2], *_cos_sin(f[2]), derivs=False)
            K = {
                k: (np.array([v]) if k in ("u2", "v2", "phi2") else tuple(np.array([x]) for x in v))
                for k, v in K1.items()
            }
        except _SCALAR_ERRORS:
            K = None
    if K is None:
        with np.errstate(invalid="ignore", divide="ignore"):
            K = _reduced3(pair, u1, v1, phi1, np.cos(phi1), np.sin(phi1), derivs=derivs)
    out = {k: K[k] for k in ("u2", "v2", "phi2")}
    out.update({k: _stack3(K[k], n) for k in ("r", "n1", "n2")})
    if derivs:
        for k in ("dr", "dn1", "dn2"):
            out[k] = np.stack([_stack3(K[k + "_u"], n), _stack3(K[k + "_v"], n)], axis=-2)
        for k in ("du2", "dv2", "dphi2"):
            out[k] = np.stack(np.broadcast_arrays(K[k + "_u"], K[k + "_v"]), axis=-1)
    return out


def _keep(vec, drop):
    """Two components of (..., 3) ``vec`` (or (..., k, 3)) other than ``drop`` (per row)."""
    drop = np.asarray(drop).astype(int)
    idx = np.array([[1, 2], [0, 2], [0, 1]])[drop]  # (n, 2)
    if vec.ndim == 2:
        return np.take_along_axis(vec, idx, axis=-1)
    return np.take_along_axis(vec, idx[:, None, :], axis=-1)


def _keep3(v, first0, last2):
    """The two components of a vector by components other than the dropped one (per row):
    (v1 if drop = 0 else v0, v1 if drop = 2 else v2); ``first0`` = (drop == 0), ``last2`` = (drop == 2)."""
    if type(first0) is bool:
        return (v[1] if first0 else v[0]), (v[1] if last2 else v[2])
    return np.where(first0, v[1], v[0]), np.where(last2, v[1], v[2])


def _pack(F_comps, J_cols, n, one):
    """F (n, m) from its m components and J (n, m, len(J_cols)) from its columns (each m
    components; None: no J); ``one``: every entry a float (one point), packed by one np.array call."""
    if one:
        m = len(F_comps)
        F = np.array(F_comps, dtype=float).reshape(1, m)
        if J_cols is None:
            return F, None
        flat = [col[i] for i in range(m) for col in J_cols]  # row-major
        return F, np.array(flat, dtype=float).reshape(1, m, len(J_cols))
    # filled component by component into (m, n) and (m, k, n) arrays (contiguous writes, one pass
    # each) and handed out as their transposed views (n, m) and (n, m, k): the same values
    Ft = np.empty((len(F_comps), n))
    for i, c in enumerate(F_comps):
        Ft[i] = c
    if J_cols is None:
        return Ft.T, None
    Jt = np.empty((len(F_comps), len(J_cols), n))
    for k, col in enumerate(J_cols):
        for i, c in enumerate(col):
            Jt[i, k] = c
    return Ft.T, Jt.transpose(2, 0, 1)


def _reduced_FJ3(pair, u1, v1, phi1, c1, s1, first0, last2, derivs=True, v_column=True):
    """(F (n, 2), J (n, 2, 1 or 2), kernel dict) of the reduced system by components."""
    K = _reduced3(pair, u1, v1, phi1, c1, s1, derivs=derivs, v_column=v_column)
    n1, n2 = K["n1"], K["n2"]
    f = _keep3(cross3(n1, n2), first0, last2)
    one = type(u1) is float
    n = 1 if one else np.size(f[0])
    if not derivs:
        return (*_pack(f, None, n, one), K)
    J_cols = []
    for j in ("_u", "_v") if v_column else ("_u",):
        a, b = cross3(K["dn1" + j], n2), cross3(n1, K["dn2" + j])
        J_cols.append(_keep3((a[0] + b[0], a[1] + b[1], a[2] + b[2]), first0, last2))
    return (*_pack(f, J_cols, n, one), K)


def _reduced_FJ(pair, u1, v1, phi1, drop, derivs=True):
    u1, v1, phi1 = (np.asarray(a, float) for a in (u1, v1, phi1))
    drop = np.asarray(drop)
    with np.errstate(invalid="ignore", divide="ignore"):
        return _reduced_FJ3(pair, u1, v1, phi1, np.cos(phi1), np.sin(phi1), drop == 0, drop == 2, derivs=derivs)


def _conventional_FJ3(pair, x, c1, s1, drop, first0, last2, cols, derivs=True, keep=None):
    """(F (n, 5 or 6), J (n, m, len(cols))) of the conventional system by components; ``x``: the
    five unknowns (u1, v1, u2, v2, phi2) as columns (arrays, or floats for one point); ``cols``:
    the free ones; ``drop`` None keeps all three normal components (six equations); ``keep``: a dict
    that receives r (member 1's point), n1 and n2 (outward normals) by components."""
    g = pair._soa
    u1, v1, u2, v2, phi2 = x
    P1 = pair.flank1.evaluate_components(u1, v1)
    P2 = pair.flank2.evaluate_components(u2, v2)
    n2l, dn2u, dn2v = _normal_derivatives3(P2, pair.sign2)
    n1l, dn1u, dn1v = _normal_derivatives3(P1, pair.sign1)
    c2, s2 = _cos_sin(pair.phase2 - phi2)

    def R2(v):
        return g["A2"](rotate_z(c2, s2, v))

    r1 = rotate_z(c1, s1, P1[0])
    rel2 = R2(P2[0])
    n1 = rotate_z(c1, s1, n1l)
    n2 = R2(n2l)
    if keep is not None:
        keep.update(r=r1, n1=n1, n2=n2)
    O2 = g["O2"]
    one = type(u1) is float
    n = 1 if one else np.size(u1)
    ns = tuple(a + b for a, b in zip(n1, n2))
    F = [r1[i] - (O2[i] + rel2[i]) for i in range(3)] + list(ns if drop is None else _keep3(ns, first0, last2))
    if not derivs:
        return _pack(F, None, n, one)
    J_cols = []
    for col in cols:
        if col == 0:
            jr, jn = rotate_z(c1, s1, P1[1]), rotate_z(c1, s1, dn1u)
        elif col == 1:
            jr, jn = rotate_z(c1, s1, P1[2]), rotate_z(c1, s1, dn1v)
        elif col == 2:
            jr, jn = R2(P2[1]), R2(dn2u)
            jr = tuple(-a for a in jr)
        elif col == 3:
            jr, jn = R2(P2[2]), R2(dn2v)
            jr = tuple(-a for a in jr)
        else:
            jr = tuple(-a for a in cross3(g["w2"], rel2))
            jn = cross3(g["w2"], n2)
        J_cols.append(tuple(jr) + tuple(jn if drop is None else _keep3(jn, first0, last2)))
    return _pack(F, J_cols, n, one)


def _conventional_FJ(pair, x, phi1, drop, derivs=True):
    x = np.asarray(x, float)
    phi1 = np.broadcast_to(np.asarray(phi1, float), (len(x),))
    c1, s1 = np.cos(phi1), np.sin(phi1)
    d = None if drop is None else np.asarray(drop)
    f0 = None if d is None else d == 0
    l2 = None if d is None else d == 2
    with np.errstate(invalid="ignore", divide="ignore"):
        return _conventional_FJ3(
            pair, tuple(x[:, i] for i in range(5)), c1, s1, d, f0, l2, (0, 1, 2, 3, 4), derivs=derivs
        )


def conventional_system(pair: GearPair, phi1: float, drop: int | None):
    """(F, J) callables of the conventional TCA (eq 26-32, eq 27 corrected to n_f1 + n_f2 = 0) at a
    fixed ``phi1`` for x = (u1, v1, u2, v2, phi2) (n, 5), as :func:`gearrep.solve.newton` takes them.

    F = [r_f1 - r_f2, components of n_f1 + n_f2] with outward unit normals; ``drop`` = 0, 1 or 2
    leaves that normal component out (five equations), None keeps all three (six equations, least
    squares). The one implementation behind :func:`solve_contact` (``formulation="conventional"``).
    """
    return _conventional_callables(pair, phi1, drop)[:2]


def _conventional_callables(pair: GearPair, phi1: float, drop: int | None):
    """(F, J, FJ) of :func:`conventional_system`; FJ(x) = (F(x), J(x)) from one evaluation (the
    residual by the same expressions as F alone), for ``newton(fun_jac=...)``."""
    if drop is not None and drop not in (0, 1, 2):
        raise ValueError(f"drop must be None or one of 0, 1, 2, got {drop!r}")

    def rows(x):
        x = np.atleast_2d(x)
        return x, None if drop is None else np.full(len(x), drop)

    def FJ(x, derivs=True):
        x, d = rows(x)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return _conventional_FJ(pair, x, phi1, d, derivs=derivs)

    return (lambda x: FJ(x, derivs=False)[0]), (lambda x: FJ(x)[1]), FJ


# ----------------------------------------------------------------------------------------------
# newton with frozen per-row parameters
# ----------------------------------------------------------------------------------------------
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
    if not np.isfinite(phi1).all():
        raise ValueError("phi1 must be finite")
    if len(phi1) == n and len(start) == n:
        return phi1.copy(), start.copy()
    return np.broadcast_to(phi1, (n,)).copy(), np.broadcast_to(start, (n, width)).copy()


def _largest_normal_component(pair, u1, v1, c1, s1) -> np.ndarray:
    """Per row the index (as float) of the largest component of member 1's unit normal in S_f at
    (u1, v1) turned by (cos, sin) = (c1, s1); 0 where it is not finite (the solve reports those)."""
    if len(u1) == 1:  # one point: on floats (numpy scalars where the family has no float path)
        try:
            with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
                P = pair.flank1.evaluate_components(float(u1[0]), float(v1[0]))
                N = rotate_z(float(c1[0]), float(s1[0]), cross3(P[1], P[2]))
                L = math.sqrt(dot3(N, N))
                a = [abs(x / L) for x in N]
            if all(math.isfinite(x) for x in a):  # else as arrays (NaN counts as 0 there)
                return np.array([float(a.index(max(a)))])
        except _SCALAR_ERRORS:
            pass
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):  # a non-finite start ends as DIVERGED
        P = pair.flank1.evaluate_components(u1, v1)
        N = rotate_z(c1, s1, cross3(P[1], P[2]))
        L = np.sqrt(dot3(N, N))
        a = np.abs(np.stack(np.broadcast_arrays(*(x / L for x in N)), axis=-1))
        return np.argmax(np.nan_to_num(a, nan=0.0), axis=-1).astype(float)


def default_start(pair: GearPair, phi1, formulation: str = "reduced") -> np.ndarray:
    """Starting point at the middle of the flanks, phi2 = (N1/N2) phi1 (the thesis's choice of u2, v2)."""
    phi1 = _angles(phi1)
    mid1, mid2 = pair._mid_flanks
    if formulation == "reduced":
        return np.tile(mid1, (len(phi1), 1))
    return np.column_stack([np.tile(mid1, (len(phi1), 1)), np.tile(mid2, (len(phi1), 1)), pair.ratio * phi1])


class _Record:
    """The contact geometry the kernel evaluations gave (u2, v2, phi2 of the reduced form; point r
    and normals n1, n2 of both), kept with the unknowns they were evaluated at, so that the contact
    record of a row whose final iterate was the last point evaluated is not computed a second time
    (:meth:`at`; rows whose final iterate differs, e.g. a stalled line search, are). Evaluations are
    only listed while solving (``rows`` None: all rows); :meth:`at` takes each row's last one."""

    def __init__(self, n: int, k: int):
        self.n, self.k = n, k
        self.entries = []

    def store(self, rows, x, K):
        self.entries.append((rows, x, K))

    def at(self, x):
        """(mask of the rows recorded at exactly ``x``, the record: ``x``, ``scalars`` and
        ``vectors`` (n, 3) of each row's last evaluation)."""
        n = self.n
        if self.entries and self.entries[-1][0] is None:  # the last evaluation covered every row
            _, xe, K = self.entries[-1]
            self.x = xe
            self.scalars = {key: np.array(K[key], dtype=float).reshape(n) for key in ("u2", "v2", "phi2") if key in K}
            self.vectors = {key: _stack3(K[key], n) for key in ("r", "n1", "n2")}
            self.entries = []
            return (self.x == x).all(axis=1), self
        self.x = np.full((n, self.k), np.nan)
        self.scalars = {key: np.full(n, np.nan) for key in ("u2", "v2", "phi2")}
        self.vectors = {key: np.full((n, 3), np.nan) for key in ("r", "n1", "n2")}
        filled = np.zeros(n, dtype=bool)
        for rows, xe, K in reversed(self.entries):
            rows = np.arange(n) if rows is None else rows
            new = ~filled[rows]
            if not new.any():
                continue
            r = rows[new]
            filled[r] = True
            self.x[r] = xe[new]
            for key, arr in self.scalars.items():
                if key in K:
                    arr[r] = np.broadcast_to(K[key], new.shape)[new]
            for key, arr in self.vectors.items():
                for i in range(3):
                    arr[r, i] = np.broadcast_to(K[key][i], new.shape)[new]
            if filled.all():
                break
        self.entries = []
        return (self.x == x).all(axis=1), self


def _check_solve_inputs(pair: GearPair, phi1, start, formulation, v1, jacobian, drop):
    """Validated (phi1 (n,), start (n, width) with a fixed v1 written into its column 1, fixed);
    ValueError naming the argument otherwise (before any work)."""
    if formulation not in ("reduced", "conventional"):
        raise ValueError(f"formulation must be 'reduced' or 'conventional', got {formulation!r}")
    if jacobian not in ("analytic", "numeric"):
        raise ValueError(f"jacobian must be 'analytic' or 'numeric', got {jacobian!r}")
    if drop is not None and drop not in (0, 1, 2):
        raise ValueError(f"drop must be None or one of 0, 1, 2, got {drop!r}")
    if formulation == "reduced" and not (
        getattr(pair.flank2, "cylindrical", False) or getattr(pair.flank2, "spherical", False)
    ):
        raise ValueError(
            "the reduced formulation needs flank2 in cylindrical or spherical form "
            "(flank2.cylindrical = True or flank2.spherical = True)"
        )
    width = 2 if formulation == "reduced" else 5
    phi1 = _angles(phi1)
    if start is None:
        start = default_start(pair, phi1, formulation)
    phi1, start = _prep(phi1, start, width)
    fixed = v1 is not None
    if fixed:
        v1a = _face_coordinates(v1, len(phi1))
        if not np.isfinite(v1a).all():
            raise ValueError("v1 must be finite")
        start[:, 1] = v1a
    return phi1, start, fixed


class _Rows:
    """Per-row data of a contact solve (phi1, cos, sin, the dropped normal component as the masks
    drop == 0 and drop == 2, a fixed v1) as contiguous arrays, gathered for the active rows
    (``idx``; no gather while all rows are active), and for one row as Python floats."""

    def __init__(self, phi1, c1, s1, drop, v1):
        self.n = len(phi1)
        self.cols = {"phi1": phi1, "c1": c1, "s1": s1, "first0": drop == 0, "last2": drop == 2, "v1": v1}
        self.one = None
        if self.n == 1:
            self.one = {k: (bool(v[0]) if v.dtype == bool else float(v[0])) for k, v in self.cols.items()}

    def take(self, idx):
        if len(idx) == self.n:
            return self.cols
        return {k: v[idx] for k, v in self.cols.items()}


def _reduced_FJ_rows(pair, data: _Rows, fixed, record):
    """FJ(x, idx, derivs) of the reduced system for ``newton(rows=True)`` (see :func:`solve_contact`)."""
    v_column = not fixed

    def FJ(x, idx, derivs=True):
        out = None
        if len(x) == 1 and data.one is not None:  # one point: the kernel on floats (see _SCALAR_ERRORS)
            q = data.one
            x0 = x[0].tolist()
            try:
                out = _reduced_FJ3(
                    pair,
                    x0[0],
                    q["v1"] if fixed else x0[1],
                    q["phi1"],
                    q["c1"],
                    q["s1"],
                    q["first0"],
                    q["last2"],
                    derivs=derivs,
                    v_column=v_column,
                )
            except _SCALAR_ERRORS:
                pass
        if out is None:
            p = data.take(idx)
            v1 = p["v1"] if fixed else x[:, 1]
            out = _reduced_FJ3(
                pair, x[:, 0], v1, p["phi1"], p["c1"], p["s1"], p["first0"], p["last2"], derivs, v_column
            )
        record.store(None if len(idx) == data.n else idx, x, out[2])
        return out[:2]

    return FJ


#: the ``drop`` argument of :func:`_conventional_FJ3` for five equations (any value but None; the
#: dropped component itself comes as the masks first0, last2)
_FIVE = 5


def _conventional_FJ_rows(pair, data: _Rows, free, record):
    """FJ(x, idx, derivs) of the conventional system for ``newton(rows=True)`` (free columns
    ``free`` of the five unknowns; a fixed v1 from the row data)."""
    cols = tuple(free)

    def FJ(x, idx, derivs=True):
        p = data.take(idx)
        full = _expand(x, free, p["v1"])
        keep = {}
        out = None
        if len(x) == 1 and data.one is not None:  # one point: the kernel on floats (see _SCALAR_ERRORS)
            q = data.one
            try:
                out = _conventional_FJ3(
                    pair, tuple(full[0].tolist()), q["c1"], q["s1"], _FIVE, q["first0"], q["last2"], cols, derivs, keep
                )
            except _SCALAR_ERRORS:
                pass
        if out is None:
            x5 = tuple(full[:, i] for i in range(5))
            out = _conventional_FJ3(pair, x5, p["c1"], p["s1"], _FIVE, p["first0"], p["last2"], cols, derivs, keep)
        record.store(None if len(idx) == data.n else idx, x, keep)
        return out

    return FJ


def _expand(x, free, v1):
    """The full unknowns (n, width) from the free columns ``x``; column 1 = the fixed ``v1``
    where v1 is not among the free ones."""
    width = 2 if len(free) <= 2 else 5
    if len(free) == width:
        return x
    full = np.empty((x.shape[0], width))
    full[:, free] = x
    full[:, 1] = v1
    return full


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
    phi1, start, fixed = _check_solve_inputs(pair, phi1, start, formulation, v1, jacobian, drop)
    n = len(phi1)
    c1, s1 = np.cos(phi1), np.sin(phi1)
    # dropped normal component: the largest of member 1's normal at the start
    if drop is None:
        drop = _largest_normal_component(pair, start[:, 0], start[:, 1], c1, s1)
    else:
        drop = np.full(n, float(drop))
    reduced = formulation == "reduced"
    free = ([0] if fixed else [0, 1]) if reduced else ([0, 2, 3, 4] if fixed else [0, 1, 2, 3, 4])
    lo, hi = pair._free_bounds(tuple(free))
    x0 = start[:, : len(free)] if free == list(range(len(free))) else start[:, free]  # a view where contiguous
    data = _Rows(phi1, c1, s1, drop, start[:, 1] if fixed else np.full(n, np.nan))
    record = _Record(n, len(free))
    FJ = _reduced_FJ_rows(pair, data, fixed, record) if reduced else _conventional_FJ_rows(pair, data, free, record)
    analytic = jacobian == "analytic"
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):  # non-finite iterates end as DIVERGED
        res = newton(
            lambda x, idx: FJ(x, idx, derivs=False)[0],
            x0,
            (lambda x, idx: FJ(x, idx)[1]) if analytic else None,
            tol=tol,
            maxiter=maxiter,
            damped=damped,
            lower=lo,
            upper=hi,
            rows=True,
            fun_jac=FJ if analytic else None,
            inverse_square=True,
        )
    sol = _expand(res.x, free, data.cols["v1"])
    return _finish(pair, formulation, sol, phi1, res, phi10, phi20, record.at(res.x))


def _finish(pair, formulation, sol, phi1, res, phi10, phi20, recorded=None) -> ContactPoints:
    """Contact record of the solved rows; ``recorded`` = (mask, :class:`_Record`): the rows whose
    geometry the solve's last kernel evaluation already gave at exactly these unknowns."""
    u2, v2, phi2, r, n1, n2 = _contact_geometry(pair, formulation, sol, phi1, recorded)
    status = _final_status(pair, formulation, res.status.copy(), r, n1, n2, u2, v2)
    te = transmission_error(phi1, phi2, pair.n1, pair.n2, phi10, phi20)
    return ContactPoints(
        u1=sol[:, 0],
        v1=sol[:, 1],
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


def _contact_geometry(pair, formulation, sol, phi1, recorded):
    """(u2, v2, phi2, r, n1, n2) of the solved rows: from the record where it holds them (see
    :func:`_finish`), else evaluated; a point or normal with a non-finite component is NaN."""
    u1, v1 = sol[:, 0], sol[:, 1]
    n = len(sol)
    hit, rec = recorded if recorded is not None else (np.zeros(n, dtype=bool), None)
    reduced = formulation == "reduced"
    if reduced:
        u2, v2, phi2 = (np.empty(n) for _ in range(3))
    else:
        u2, v2 = sol[:, 2], sol[:, 3]
        ref = pair.ratio * phi1
        phi2 = ref + _wrap(sol[:, 4] - ref)
    if rec is not None and hit.all():  # every row recorded: the record's arrays as they are
        r, n1, n2 = (rec.vectors[key] for key in ("r", "n1", "n2"))
        if reduced:
            u2, v2, phi2 = (rec.scalars[key] for key in ("u2", "v2", "phi2"))
        miss = np.zeros(0, dtype=int)
    else:
        r, n1, n2 = (np.empty((n, 3)) for _ in range(3))
        if rec is not None and hit.any():
            for key, arr in zip(("r", "n1", "n2"), (r, n1, n2)):
                arr[hit] = rec.vectors[key][hit]
            if reduced:
                for key, arr in zip(("u2", "v2", "phi2"), (u2, v2, phi2)):
                    arr[hit] = rec.scalars[key][hit]
        miss = np.flatnonzero(~hit)
    if miss.size:
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            if reduced:
                K = _reduced_kernel(pair, u1[miss], v1[miss], phi1[miss], derivs=False)
                u2[miss], v2[miss], phi2[miss] = K["u2"], K["v2"], K["phi2"]
                r[miss], n1[miss], n2[miss] = K["r"], K["n1"], K["n2"]
            else:
                r[miss], n1[miss] = pair.member1(u1[miss], v1[miss], phi1[miss])
                n2[miss] = pair.member2(u2[miss], v2[miss], phi2[miss])[1]
    for vec in (r, n1):  # a point or normal with a non-finite component is not a vector
        bad = ~_rows_all_finite(vec)
        if bad.any():
            vec[bad] = np.nan
    return u2, v2, phi2, r, n1, n2


#: status codes as ints (an IntEnum member looked up on its class costs more than the test itself)
_CONVERGED, _OFF_FLANK, _WRONG_ROOT = int(Status.CONVERGED), int(Status.OFF_FLANK), int(Status.WRONG_ROOT)


def _final_status(pair, formulation, status, r, n1, n2, u2, v2):
    """The solver's statuses with WRONG_ROOT (normals not opposite; conventional: n1 + n2 not
    ~0) and OFF_FLANK (member 2's parameters outside its flank) set."""
    if len(status) == 1:
        return _final_status_one(pair, formulation, status, n1, n2, u2, v2)
    with np.errstate(invalid="ignore", over="ignore"):
        # the sums written out: numpy sums a row of three the same way, left to right
        opposite = (n1[:, 0] * n2[:, 0] + n1[:, 1] * n2[:, 1] + n1[:, 2] * n2[:, 2]) < 0
        if formulation == "conventional":
            s = n1 + n2
            opposite &= np.sqrt(s[:, 0] * s[:, 0] + s[:, 1] * s[:, 1] + s[:, 2] * s[:, 2]) < 1e-6
    if not opposite.all():
        solved = (status == _CONVERGED) | (status == _OFF_FLANK)
        status[solved & ~opposite] = _WRONG_ROOT
    ulo, uhi, vlo, vhi = pair._flank2_limits
    outside2 = ~((u2 >= ulo) & (u2 <= uhi) & (v2 >= vlo) & (v2 <= vhi))
    if outside2.any():
        status[(status == _CONVERGED) & outside2] = _OFF_FLANK
    return status


def _final_status_one(pair, formulation, status, n1, n2, u2, v2):
    """:func:`_final_status` of one point: the same tests on Python floats (NaN fails them alike)."""
    a, b = n1[0].tolist(), n2[0].tolist()
    opposite = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < 0
    if formulation == "conventional":
        s = [x + y for x, y in zip(a, b)]
        opposite = opposite and math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) < 1e-6
    st = int(status[0])
    if st in (_CONVERGED, _OFF_FLANK) and not opposite:
        st = _WRONG_ROOT
    ulo, uhi, vlo, vhi = pair._flank2_limits
    u, v = float(u2[0]), float(v2[0])
    if st == _CONVERGED and not (u >= ulo and u <= uhi and v >= vlo and v <= vhi):
        st = _OFF_FLANK
    status[0] = st
    return status


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
