"""The TCA equations by components (structure of arrays, or Python floats for one point): the
reduced formulation's back-substitution (eq 37-44) and the conventional system (eq 26-32), with
their analytic Jacobians, as the solves of :mod:`gearrep.tca._formulations` evaluate them."""

from __future__ import annotations

import math

import numpy as np

from ..frames import rotate_z
from ..surface import add3, cross, cross3, cross3_sparse, dot3
from ._bevel import spherical_unknowns
from ._pair import GearPair, _wrap

__all__ = ["normal_derivatives", "reduced_system"]


def normal_derivatives(P, sign):
    """Unit normal sign * (r_u x r_v)/|.| of a :class:`~gearrep.surface.SurfacePoint` and its u- and
    v-derivatives (n_u = (N_u - n (n . N_u))/|N|, likewise n_v).

    Parameters
    ----------
    P : gearrep.surface.SurfacePoint
        A surface point with its first and second derivatives.
    sign : int
        +1 or -1 (e.g. the flank's ``outward_sign``).

    Returns
    -------
    tuple of numpy.ndarray
        (n, n_u, n_v), each (..., 3) [n unitless; n_u, n_v per unit of u, v].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Sphere
    >>> from gearrep.tca import normal_derivatives
    >>> n, n_u, n_v = normal_derivatives(Sphere(R=2.0).evaluate(0.0, 0.0), 1)
    >>> np.round(n, 12).tolist(), np.round(n_u, 12).tolist()  # n_u = r_u / R on a sphere
    ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    """
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
    :meth:`~gearrep.surface.Surface.evaluate_components`; returns (n, n_u, n_v), each a 3-tuple
    (:func:`_unit_normal3` followed by :func:`_normal_partials3`)."""
    n, L = _unit_normal3(P, sign)
    return (n, *_normal_partials3(P, sign, n, L))


def _products(P):
    """The cross product and sum :func:`_normal_derivatives3` uses for the vectors of ``P``: on
    arrays the cross products skip the float components 0.0 and 1.0
    (:func:`~gearrep.surface.cross3_sparse`); one point on floats: the plain forms."""
    if type(P[1][0]) is float:  # one point on floats: every component is a float
        return cross3, _add3_plain
    return cross3_sparse, add3


def _unit_normal3(P, sign):
    """The signed unit normal sign * N/|N|, N = r_u x r_v, of the vectors ``P`` (see
    :func:`_normal_derivatives3`) and |N|: what a residual needs. ``sign`` -1 swaps the operands
    of the cross product (which negates N exactly), so the signed normal comes without a negation
    pass."""
    cr, _ = _products(P)
    N0, N1, N2 = cr(P[1], P[2]) if sign == 1 else cr(P[2], P[1])
    L = _sqrt(N0 * N0 + N1 * N1 + N2 * N2)
    return (N0 / L, N1 / L, N2 / L), L


def _normal_partials3(P, sign, n, L):
    """The u- and v-derivatives (n_u, n_v) of the signed unit normal ``n`` = :func:`_unit_normal3`
    (with its ``L``): n_u = (N_u - n (n . N_u))/|N|, likewise n_v; what a Jacobian needs (the
    operands of every cross product swapped for ``sign`` -1, as there)."""
    _, ru, rv, ruu, ruv, rvv = P
    cr, add = _products(P)
    if sign == 1:
        dNu, dNv = add(cr(ruu, rv), cr(ru, ruv)), add(cr(ruv, rv), cr(ru, rvv))
    else:
        dNu, dNv = add(cr(rv, ruu), cr(ruv, ru)), add(cr(rv, ruv), cr(rvv, ru))
    pu, pv = dot3(n, dNu), dot3(n, dNv)
    dnu = ((dNu[0] - n[0] * pu) / L, (dNu[1] - n[1] * pu) / L, (dNu[2] - n[2] * pu) / L)
    dnv = ((dNv[0] - n[0] * pv) / L, (dNv[1] - n[1] * pv) / L, (dNv[2] - n[2] * pv) / L)
    return dnu, dnv


def _add3_plain(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _stack3(v, n):
    """(n, 3) array of a vector given by components (floats broadcast)."""
    if type(v[0]) is float and type(v[1]) is float and type(v[2]) is float and n == 1:
        return np.array([v])
    out = np.empty((n, 3))
    out[:, 0], out[:, 1], out[:, 2] = v
    return out


def _reduced3(pair: GearPair, u1, v1, phi1, c1, s1, derivs=True, v_column=True, P1=None):
    """The reduced formulation's explicit back-substitution (eq 37-44) in structure-of-arrays form.

    ``c1``, ``s1`` = cos, sin of ``phi1`` (computed once per solve by the caller). Returns a dict
    of components: u2, v2, phi2 (arrays), r, n1, n2 (3-tuples) and, with ``derivs``, the
    derivatives with respect to u1 (suffix _u) and, with ``v_column``, v1 (suffix _v):
    du2, dv2, dphi2 (arrays), dr, dn1, dn2 (3-tuples). ``derivs="lazy"``: the derivatives are not
    computed; the dict's entry "derivs" is a function that returns them (the same values) when called.
    Callers set ``np.errstate`` (off the flanks the arrays hold NaN/inf). A spherical member 2
    (bevel pairs, ``flank2.spherical``): the cylindrical back-substitution on the pair's axial view,
    then (rho2, z2) -> (u2, v2) by :func:`gearrep.tca._bevel.spherical_unknowns` (derivatives
    computed at once). ``P1``: member 1's flank already evaluated at (u1, v1) by components, if
    the caller has it."""
    if getattr(pair.flank2, "spherical", False):
        view = pair.axial_view
        P1 = P1 if view.flank1 is pair.flank1 else None
        K = _reduced3(view, u1, v1, phi1, c1, s1, derivs=bool(derivs), v_column=v_column, P1=P1)
        return spherical_unknowns(K, bool(derivs), v_column)
    g = pair._soa
    if P1 is None:
        P1 = pair.flank1.evaluate_components(u1, v1)
    n1l, L1 = _unit_normal3(P1, pair.sign1)
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
    n2l, L2 = _unit_normal3(P2, pair.sign2)
    n2 = g["A2"](rotate_z(c2, s2, n2l))
    out = dict(u2=u2, v2=v2, phi2=phi2, r=r, n1=n1, n2=n2)
    if not derivs:
        return out

    def derivatives():  # a dict of its own: the function refers to no dict holding it (no cycle)
        d = {}
        dn1u, dn1v = _normal_partials3(P1, pair.sign1, n1l, L1)
        dn2u, dn2v = _normal_partials3(P2, pair.sign2, n2l, L2)
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
            dn2l = (dn2u[0] * du2 + dn2v[0] * dv2, dn2u[1] * du2 + dn2v[1] * dv2, dn2u[2] * du2 + dn2v[2] * dv2)
            dn2 = g["A2"](rotate_z(c2, s2, dn2l))
            d["dr" + j] = dr
            d["dn1" + j] = rotate_z(c1, s1, dnj)
            d["du2" + j], d["dv2" + j], d["dphi2" + j] = du2, dv2, dphi2
            d["dn2" + j] = (dn2[0] + w2xn2[0] * dphi2, dn2[1] + w2xn2[1] * dphi2, dn2[2] + w2xn2[2] * dphi2)
        return d

    if derivs == "lazy":
        out["derivs"] = derivatives
    else:
        out.update(derivatives())
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


def _cross_kept(a, b, first0, last2):
    """The two components of a x b (vectors by components) that :func:`_keep3` keeps; where every
    row drops the same component (Python bools) only those two are computed (the same values)."""
    if type(first0) is not bool:
        return _keep3(cross3(a, b), first0, last2)
    a0, a1, a2 = a
    b0, b1, b2 = b
    c1 = a2 * b0 - a0 * b2 if (first0 or last2) else None
    return (c1 if first0 else a1 * b2 - a2 * b1), (c1 if last2 else a0 * b1 - a1 * b0)


def _pack(F_comps, J_cols, n, one):
    """F (n, m) from its m components and J (n, m, len(J_cols)) from its columns (each m
    components; None: no J); ``one``: every entry a float (one point), packed by one np.array call;
    ``one="lists"``: F as a list and J as a list of rows (the form of ``newton(floats=...)``).
    ``J_cols`` a function: J is a lazy Jacobian for :func:`gearrep.solve.newton`, a function of the
    rows wanted that packs the columns ``J_cols()`` when called (see :func:`_lazy_jacobian`)."""
    if callable(J_cols):
        return _pack(F_comps, None, n, one)[0], _lazy_jacobian(J_cols, n, one)
    if one == "lists":
        return list(F_comps), (None if J_cols is None else [list(row) for row in zip(*J_cols)])
    if one:
        m = len(F_comps)
        F = np.array(F_comps, dtype=float).reshape(1, m)
        return F, (None if J_cols is None else _pack_jacobian_one(J_cols, m))
    # filled component by component into (m, n) and (m, k, n) arrays (contiguous writes, one pass
    # each) and handed out as their transposed views (n, m) and (n, m, k): the same values
    Ft = np.empty((len(F_comps), n))
    for i, c in enumerate(F_comps):
        Ft[i] = c
    if J_cols is None:
        return Ft.T, None
    return Ft.T, _pack_jacobian(J_cols, len(F_comps), n)


def _pack_jacobian_one(J_cols, m):
    """J (1, m, k) of ``_pack`` for one point from its k columns of m floats each."""
    flat = [col[i] for i in range(m) for col in J_cols]  # row-major
    return np.array(flat, dtype=float).reshape(1, m, len(J_cols))


def _pack_jacobian(J_cols, m, n):
    """J (n, m, k) of ``_pack`` from its k columns of m components each (arrays)."""
    Jt = np.empty((m, len(J_cols), n))
    for k, col in enumerate(J_cols):
        for i, c in enumerate(col):
            Jt[i, k] = c
    return Jt.transpose(2, 0, 1)


def _lazy_jacobian(columns, n, one):
    """The Jacobian of an evaluation as a function ``J(rows=None)`` (see
    :func:`gearrep.solve.newton`, which calls it at most once): the columns are computed by
    ``columns()`` when it is called and packed as :func:`_pack` does, only the rows ``rows``
    (indices into the evaluated rows; None: all) where given (a list of rows for one point:
    ``rows`` is ignored there)."""

    def J(rows=None):
        cols = columns()
        m = len(cols[0])
        if one == "lists":
            return [list(row) for row in zip(*cols)]
        if one:
            return _pack_jacobian_one(cols, m)
        if rows is not None:  # the components of these rows (1-D gathers), then packed
            cols = [[c if np.ndim(c) == 0 else c[rows] for c in col] for col in cols]
        return _pack_jacobian(cols, m, n if rows is None else len(rows))

    return J


def _reduced_FJ3(pair, u1, v1, phi1, c1, s1, first0, last2, derivs=True, v_column=True, lists=False, P1=None):
    """(F (n, 2), J (n, 2, 1 or 2), kernel dict) of the reduced system by components (``lists``:
    one point on floats, F and J as lists, see :func:`_pack`); ``derivs="lazy"``: J is a lazy
    Jacobian (:func:`_lazy_jacobian`), its derivatives computed only when it is called."""
    K = _reduced3(pair, u1, v1, phi1, c1, s1, derivs=derivs, v_column=v_column, P1=P1)
    n1, n2 = K["n1"], K["n2"]
    f = _cross_kept(n1, n2, first0, last2)
    one = "lists" if lists else type(u1) is float
    n = 1 if one else np.size(u1)
    if not derivs:
        return (*_pack(f, None, n, one), K)

    def columns():
        if "derivs" in K:
            K.update(K.pop("derivs")())
        J_cols = []
        for j in ("_u", "_v") if v_column else ("_u",):
            a, b = _cross_kept(K["dn1" + j], n2, first0, last2), _cross_kept(n1, K["dn2" + j], first0, last2)
            J_cols.append((a[0] + b[0], a[1] + b[1]))
        return J_cols

    return (*_pack(f, columns if derivs == "lazy" else columns(), n, one), K)


def reduced_system(pair, u1, v1, phi1, drop, derivs=True):
    """The reduced formulation (eq 33-44) at member 1's (u1, v1) and angles phi1 (arrays (n,),
    [rad]): (F (n, 2), J (n, 2, 2) or None without ``derivs``, K), F the two components of
    n_f1 x n_f2 kept when the component ``drop`` (n,) (0, 1 or 2) is dropped, J its Jacobian in
    (u1, v1), K the kernel's record: member 2's explicit unknowns ``u2``, ``v2``, ``phi2``, the
    point ``r`` and the normals ``n1``, ``n2`` by components.

    Parameters
    ----------
    pair : GearPair
        The pair (member 2 in explicit cylindrical form).
    u1, v1 : (n,) array_like
        Flank parameters of member 1 [length].
    phi1 : (n,) array_like
        Angles of member 1 [rad].
    drop : (n,) array_like of int
        The component of n_f1 x n_f2 left out, per row.
    derivs : bool, optional
        Also the Jacobian.

    Returns
    -------
    tuple
        (F (n, 2), J (n, 2, 2) or None, K dict of the kernel's record).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, solve_contact
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # 1/mm
    >>> pair = GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_E=0.01))
    >>> from gearrep.tca import reduced_system
    >>> c = solve_contact(pair, [0.0])
    >>> F, J, K = reduced_system(pair, c.u1, c.v1, c.phi1, np.array([1]))
    >>> bool(np.abs(F).max() < 1e-12), J.shape, round(float(K["u2"][0] - c.u2[0]), 9)
    (True, (1, 2, 2), 0.0)
    """
    u1, v1, phi1 = (np.asarray(a, float) for a in (u1, v1, phi1))
    drop = np.asarray(drop)
    with np.errstate(invalid="ignore", divide="ignore"):
        return _reduced_FJ3(pair, u1, v1, phi1, np.cos(phi1), np.sin(phi1), drop == 0, drop == 2, derivs=derivs)


def _conventional_FJ3(pair, x, c1, s1, drop, first0, last2, cols, derivs=True, keep=None, lists=False, P1=None):
    """(F (n, 5 or 6), J (n, m, len(cols))) of the conventional system by components; ``x``: the
    five unknowns (u1, v1, u2, v2, phi2) as columns (arrays, or floats for one point); ``cols``:
    the free ones; ``drop`` None keeps all three normal components (six equations); ``keep``: a dict
    that receives r (member 1's point), n1 and n2 (outward normals) by components; ``lists``: one
    point on floats, F and J as lists (see :func:`_pack`); ``derivs="lazy"``: J is a lazy Jacobian
    (:func:`_lazy_jacobian`), the normals' derivatives computed only when it is called; ``P1``:
    member 1's flank already evaluated at (u1, v1) by components, if the caller has it."""
    g = pair._soa
    u1, v1, u2, v2, phi2 = x
    if P1 is None:
        P1 = pair.flank1.evaluate_components(u1, v1)
    P2 = pair.flank2.evaluate_components(u2, v2)
    n2l, L2 = _unit_normal3(P2, pair.sign2)
    n1l, L1 = _unit_normal3(P1, pair.sign1)
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
    one = "lists" if lists else type(u1) is float
    n = 1 if one else np.size(u1)
    ns = (n1[0] + n2[0], n1[1] + n2[1], n1[2] + n2[2])
    F = [r1[0] - (O2[0] + rel2[0]), r1[1] - (O2[1] + rel2[1]), r1[2] - (O2[2] + rel2[2])]
    F += ns if drop is None else _keep3(ns, first0, last2)
    if not derivs:
        return _pack(F, None, n, one)

    def columns():
        dn2u, dn2v = _normal_partials3(P2, pair.sign2, n2l, L2)
        dn1u, dn1v = _normal_partials3(P1, pair.sign1, n1l, L1)
        J_cols = []
        for col in cols:
            if col == 0:
                jr, jn = rotate_z(c1, s1, P1[1]), rotate_z(c1, s1, dn1u)
            elif col == 1:
                jr, jn = rotate_z(c1, s1, P1[2]), rotate_z(c1, s1, dn1v)
            elif col == 2:
                jr, jn = R2(P2[1]), R2(dn2u)
                jr = (-jr[0], -jr[1], -jr[2])
            elif col == 3:
                jr, jn = R2(P2[2]), R2(dn2v)
                jr = (-jr[0], -jr[1], -jr[2])
            else:
                jr = cross3(g["w2"], rel2)
                jr = (-jr[0], -jr[1], -jr[2])
                jn = cross3(g["w2"], n2)
            J_cols.append(jr + (jn if drop is None else _keep3(jn, first0, last2)))
        return J_cols

    return _pack(F, columns if derivs == "lazy" else columns(), n, one)


def _conventional_FJ(pair, x, phi1, drop, derivs=True):
    """:func:`_conventional_FJ3` of (n, 5) unknowns ``x`` at ``phi1``; ``drop``: None (six
    equations), one component for every row (0, 1 or 2: picked without a per-row selection) or
    one per row."""
    x = np.asarray(x, float)
    phi1 = np.broadcast_to(np.asarray(phi1, float), (len(x),))
    c1, s1 = np.cos(phi1), np.sin(phi1)
    d = None if drop is None else np.asarray(drop)
    if d is not None and d.ndim == 0:
        f0, l2 = bool(d == 0), bool(d == 2)
    else:
        f0 = None if d is None else d == 0
        l2 = None if d is None else d == 2
    with np.errstate(invalid="ignore", divide="ignore"):
        return _conventional_FJ3(
            pair, tuple(x[:, i] for i in range(5)), c1, s1, d, f0, l2, (0, 1, 2, 3, 4), derivs=derivs
        )
